//! The harness's progress: an indicatif bar per section on a terminal, and one line per step
//! otherwise (a CI log keeps what ran when).

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};

/// The progress of one section of the benchmark.
pub struct SectionProgress {
    section: &'static str,
    len: u64,
    done: u64,
    bar: Option<ProgressBar>,
}

impl SectionProgress {
    /// A section of `len` steps.
    pub fn new(section: &'static str, len: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(len as u64);
            let style = ProgressStyle::with_template(
                "{prefix:>10} [{bar:30}] {pos}/{len} {elapsed_precise} {wide_msg}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> ");
            bar.set_style(style);
            bar.set_prefix(section);
            bar
        });
        SectionProgress { section, len: len as u64, done: 0, bar }
    }

    /// Starts the next step, described by `what`.
    pub fn step(&mut self, what: impl AsRef<str>) {
        match &self.bar {
            Some(bar) => {
                bar.set_position(self.done);
                bar.set_message(what.as_ref().to_string());
            }
            None => errln!("[{} {}/{}] {}", self.section, self.done + 1, self.len, what.as_ref()),
        }
        self.done += 1;
    }

    /// A message within the current step (a line of its own without a terminal).
    pub fn note(&self, what: impl AsRef<str>) {
        match &self.bar {
            Some(bar) => bar.set_message(what.as_ref().to_string()),
            None => errln!("[{}] {}", self.section, what.as_ref()),
        }
    }
}

impl Drop for SectionProgress {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
