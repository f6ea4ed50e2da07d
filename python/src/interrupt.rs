//! Work that Ctrl-C can stop: the work runs on threads of its own while the interpreter's thread
//! waits without the GIL and looks for signals every few milliseconds, so a long plan never
//! holds the interpreter deaf to Ctrl-C.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, TryRecvError};
use std::time::{Duration, Instant};

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

use crate::errors::error;

/// How often the waiting thread looks for a signal.
const POLL: Duration = Duration::from_millis(20);

/// How long the wait for one plan spins before it sleeps.
const SPIN: Duration = Duration::from_micros(500);

/// Receives from `rx` until `wanted` messages came, checking for signals (Ctrl-C raises
/// `KeyboardInterrupt`) in between; on a signal, sets `stop` for the workers and returns the
/// signal's exception at once (the workers end on their own, their results dropped).
pub fn receive<T: Send>(
    py: Python<'_>,
    mut rx: Receiver<T>,
    wanted: usize,
    stop: &Arc<AtomicBool>,
    mut each: impl FnMut(T),
) -> PyResult<()> {
    let mut got = 0;
    // One plan's result is first waited for by spinning: a sleeping thread takes tens of
    // microseconds to wake, as long as a short plan.
    let mut spin = wanted == 1;
    while got < wanted {
        // The receiver is not `Sync`: it moves to the waiting closure and back.
        let first = std::mem::take(&mut spin);
        let (message, back) = py.detach(move || {
            if first {
                let until = Instant::now() + SPIN;
                while Instant::now() < until {
                    match rx.try_recv() {
                        Ok(message) => return (Ok(message), rx),
                        Err(TryRecvError::Disconnected) => return (Err(RecvTimeoutError::Disconnected), rx),
                        Err(TryRecvError::Empty) => std::hint::spin_loop(),
                    }
                }
            }
            (rx.recv_timeout(POLL), rx)
        });
        rx = back;
        match message {
            Ok(message) => {
                each(message);
                got += 1;
            }
            Err(RecvTimeoutError::Timeout) => {
                if let Err(signal) = py.check_signals() {
                    stop.store(true, Ordering::Relaxed);
                    return Err(signal);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "a planning thread ended without a result",
                ));
            }
        }
    }
    Ok(())
}

/// Runs `job` on a planning thread (`pool`) with a stop flag that Ctrl-C sets, and waits for its
/// answer with signals honoured; an error `(class, message)` is raised as that class of
/// `trailmark.errors`.
pub fn run_stoppable<T: Send + 'static>(
    py: Python<'_>,
    job: impl FnOnce(&Arc<AtomicBool>) -> Result<T, (&'static str, String)> + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = mpsc::channel();
    let stop = Arc::new(AtomicBool::new(false));
    let stopped = Arc::clone(&stop);
    crate::pool::run(move || {
        let _ = tx.send(job(&stopped));
    })
    .map_err(|e| PyRuntimeError::new_err(format!("cannot start a planning thread: {e}")))?;
    let mut outcome = None;
    receive(py, rx, 1, &stop, |o| outcome = Some(o))?;
    match outcome {
        Some(Ok(answer)) => Ok(answer),
        Some(Err((class, message))) => Err(error(py, class, message)),
        None => Err(PyRuntimeError::new_err("no result")),
    }
}
