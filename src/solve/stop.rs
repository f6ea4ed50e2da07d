//! Stopping a solve from outside: a flag the caller sets (Ctrl-C in an interpreter, a deadline
//! of its own) that every planner of the document with limits (sampling planners, anytime
//! searches, Hybrid A*) reads as one more limit, stopping as at its time limit. Graph searches
//! end within their graph and do not read it.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use trailmark_core::termination::Termination;

thread_local! {
    /// The flag of the solve running on this thread, while `solve_until` runs it.
    static STOP: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// Runs `solve` with `stop` as the flag of this thread's solve, cleared when it ends (a panic
/// included).
pub(super) fn with_flag<T>(stop: Arc<AtomicBool>, solve: impl FnOnce() -> T) -> T {
    struct Clear;
    impl Drop for Clear {
        fn drop(&mut self) {
            STOP.with(|s| s.borrow_mut().take());
        }
    }
    STOP.with(|s| *s.borrow_mut() = Some(stop));
    let _clear = Clear;
    solve()
}

/// `termination`, also ended by the flag of `solve_until` and by `also` when given.
pub(super) fn stoppable(termination: Termination, also: Option<&Arc<AtomicBool>>) -> Termination {
    let flags: Vec<Arc<AtomicBool>> =
        STOP.with(|s| s.borrow().clone()).into_iter().chain(also.cloned()).collect();
    if flags.is_empty() {
        return termination;
    }
    termination.or_when(move |_| flags.iter().any(|f| f.load(Ordering::Relaxed)))
}
