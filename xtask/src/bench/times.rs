//! The run's wall times: each section's on the main thread, printed as it ends, and the untimed
//! work that ran beside the sections on a thread of its own; the report's time line, so that the
//! budget of the quick suite can be watched as sections are added.

use std::thread::{Scope, ScopedJoinHandle};
use std::time::Instant;

/// Untimed work under way beside the sections: its name, and its result with its own wall time.
pub struct Beside<'scope, T> {
    name: &'static str,
    handle: ScopedJoinHandle<'scope, (T, f64)>,
}

/// The wall times of a run.
pub struct RunTimes {
    start: Instant,
    /// The load average when the run began (Linux), for reading the times.
    load: Option<String>,
    sections: Vec<(&'static str, f64)>,
    beside: Vec<(&'static str, f64)>,
    /// Seconds the main thread waited for untimed work.
    waited: f64,
}

impl RunTimes {
    /// Starts the clock of the run.
    pub fn start() -> RunTimes {
        let load = std::fs::read_to_string("/proc/loadavg")
            .ok()
            .and_then(|l| l.split_whitespace().next().map(str::to_string));
        RunTimes { start: Instant::now(), load, sections: Vec::new(), beside: Vec::new(), waited: 0.0 }
    }

    /// Runs `section` on this thread, and records and prints its wall time.
    pub fn section<T>(&mut self, name: &'static str, section: impl FnOnce() -> T) -> T {
        let clock = Instant::now();
        let out = section();
        let seconds = clock.elapsed().as_secs_f64();
        errln!("{name}: {seconds:.1} s");
        self.sections.push((name, seconds));
        out
    }

    /// Starts untimed `work` on a thread of `scope`, beside the sections that follow.
    pub fn beside<'scope, T: Send + 'scope>(
        scope: &'scope Scope<'scope, '_>,
        name: &'static str,
        work: impl FnOnce() -> T + Send + 'scope,
    ) -> Beside<'scope, T> {
        let handle = scope.spawn(move || {
            let clock = Instant::now();
            let out = work();
            (out, clock.elapsed().as_secs_f64())
        });
        Beside { name, handle }
    }

    /// Waits for untimed work and records its wall time and the wait.
    pub fn join<T>(&mut self, work: Beside<'_, T>) -> Result<T, String> {
        let clock = Instant::now();
        let joined = work.handle.join();
        self.waited += clock.elapsed().as_secs_f64();
        let (out, seconds) = joined.map_err(|_| format!("{} stopped with a panic", work.name))?;
        errln!("{} (beside the sections): {seconds:.1} s", work.name);
        self.beside.push((work.name, seconds));
        Ok(out)
    }

    /// Seconds since the run began.
    pub fn elapsed(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// The report's time line.
    pub fn markdown(&self, cores: usize) -> String {
        let list = |times: &[(&str, f64)]| -> String {
            let each: Vec<String> = times.iter().map(|(name, s)| format!("{name} {s:.0} s")).collect();
            each.join(", ")
        };
        let load = self.load.as_ref().map_or(String::new(), |l| format!(", load average {l} at the start"));
        let mut s = format!(
            "Run time: {:.0} s on {cores} core(s){load}. Sections: {}",
            self.elapsed(),
            list(&self.sections)
        );
        if !self.beside.is_empty() {
            s.push_str(&format!(
                "; untimed work beside them: {} (waited for: {:.0} s)",
                list(&self.beside),
                self.waited
            ));
        }
        s.push_str(".\n\n");
        s
    }
}
