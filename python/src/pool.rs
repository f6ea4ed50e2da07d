//! The threads documents are planned on, kept between calls: a new thread for every
//! `trailmark.solve` would start each plan with cold per-thread buffers and allocator arenas
//! (measured: 0.4 ms more per call on a 0.7 ms plan). At most `MAX_IDLE` wait; the others end.
//! A forked child (multiprocessing) inherits the list but not the threads: the list belongs to
//! the process that made it, and a child starts its own.

use std::sync::mpsc::{self, Sender};
use std::sync::{Mutex, PoisonError};

type Job = Box<dyn FnOnce() + Send>;

/// The process the idle threads belong to, and each idle thread's channel.
static IDLE: Mutex<(u32, Vec<Sender<Job>>)> = Mutex::new((0, Vec::new()));

/// The most threads kept waiting: enough for `solve_many` on every core of a large machine.
const MAX_IDLE: usize = 64;

/// The idle channels of this process (a list inherited through `fork` is forgotten: its
/// threads do not exist here, and its channels' ends would never be read).
fn idle() -> std::sync::MutexGuard<'static, (u32, Vec<Sender<Job>>)> {
    let mut idle = IDLE.lock().unwrap_or_else(PoisonError::into_inner);
    let here = std::process::id();
    if idle.0 != here {
        std::mem::forget(std::mem::take(&mut idle.1));
        idle.0 = here;
    }
    idle
}

/// Runs `job` on an idle planning thread, or on a new one when none is idle; the thread waits
/// for the next job once `job` returns. Errors only when no thread can be started.
pub fn run(job: impl FnOnce() + Send + 'static) -> std::io::Result<()> {
    let mut job: Job = Box::new(job);
    loop {
        let Some(worker) = idle().1.pop() else { break };
        // A thread that ended (it cannot, short of a panic outside its jobs) gives the job back.
        match worker.send(job) {
            Ok(()) => return Ok(()),
            Err(mpsc::SendError(returned)) => job = returned,
        }
    }
    let (tx, rx) = mpsc::channel::<Job>();
    tx.send(job).map_err(|_| std::io::Error::other("a new planning thread's channel closed"))?;
    std::thread::Builder::new().name("trailmark-plan".into()).spawn(move || {
        for job in rx {
            job();
            let mut idle = idle();
            if idle.1.len() >= MAX_IDLE {
                return;
            }
            idle.1.push(tx.clone());
        }
    })?;
    Ok(())
}
