//! Problem documents from Python: `trailmark.solve` and `trailmark.solve_many`, the documents
//! and results of `cargo xtask solve`, as JSON text (`trailmark/documents.py` turns dicts into
//! it and back).

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use trailmark::core::read::MAX_DOCUMENT_BYTES;
use trailmark::solve::ProblemSpec;

use crate::errors::{class_of, error};
use crate::interrupt::receive;

/// The most threads `solve_many` starts, whatever it is asked.
const MAX_WORKERS: usize = 256;

/// A document's result as JSON, or the class of `trailmark.errors` to raise and its message.
pub type Outcome = Result<String, (&'static str, String)>;

/// Solves the document `text` with relative paths resolved against `base_dir`, its planner
/// stopped once `stop` is set; a panic (a bug, never expected) becomes a `SolveError` instead
/// of ending the interpreter.
pub fn solve_text(text: &str, base_dir: &Path, stop: &Arc<AtomicBool>) -> Outcome {
    catch_unwind(AssertUnwindSafe(|| solve_unguarded(text, base_dir, stop))).unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(("SolveError", format!("internal error while planning (please report it): {what}")))
    })
}

fn solve_unguarded(text: &str, base_dir: &Path, stop: &Arc<AtomicBool>) -> Outcome {
    if text.len() as u64 > MAX_DOCUMENT_BYTES {
        return Err(("DocumentError", format!("the document is longer than {MAX_DOCUMENT_BYTES} bytes")));
    }
    let problem = parse(text)?;
    let result = trailmark::solve::solve_until(&problem, base_dir, Arc::clone(stop))
        .map_err(|e| (class_of(&e), e.to_string()))?;
    serde_json::to_string(&result).map_err(|e| ("SolveError", e.to_string()))
}

/// The planner of `planner`, a document's `"planner"` as JSON; a `DocumentError` when it is
/// not one.
pub fn planner_spec(py: Python<'_>, planner: &str) -> PyResult<trailmark::solve::PlannerSpec> {
    serde_json::from_str(planner).map_err(|e| error(py, "DocumentError", format!("invalid planner: {e}")))
}

/// The problem of the document `text`.
pub fn parse(text: &str) -> Result<ProblemSpec, (&'static str, String)> {
    serde_json::from_str(text).map_err(|e| ("DocumentError", format!("invalid problem: {e}")))
}

/// Solves one document on a planning thread (`pool`); Ctrl-C stops the planner and the wait.
#[pyfunction]
pub fn solve_json(py: Python<'_>, document: String, base_dir: PathBuf) -> PyResult<String> {
    let (tx, rx) = mpsc::channel();
    let stop = Arc::new(AtomicBool::new(false));
    let stopped = Arc::clone(&stop);
    crate::pool::run(move || {
        let _ = tx.send(solve_text(&document, &base_dir, &stopped));
    })
    .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start a planning thread: {e}")))?;
    let mut outcome = None;
    receive(py, rx, 1, &stop, |o| outcome = Some(o))?;
    match outcome {
        Some(Ok(json)) => Ok(json),
        Some(Err((class, message))) => Err(error(py, class, message)),
        None => Err(pyo3::exceptions::PyRuntimeError::new_err("no result")),
    }
}

/// Solves every document (its text and the folder its paths are relative to) on `workers`
/// threads (default: one per core, at most `MAX_WORKERS`), without the GIL; Ctrl-C stops every
/// planner and the wait; each result is `(None, json)`, or
/// `(class, message)` for a document that could not be solved.
#[pyfunction]
#[pyo3(signature = (documents, workers=None))]
pub fn solve_many_json(
    py: Python<'_>,
    documents: Vec<(String, PathBuf)>,
    workers: Option<usize>,
) -> PyResult<Vec<(Option<&'static str>, String)>> {
    let n = documents.len();
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let workers = match workers {
        Some(0) => return Err(PyValueError::new_err("workers must be at least 1")),
        Some(w) => w.min(MAX_WORKERS),
        None => cores,
    }
    .min(n.max(1));
    let documents = Arc::new(documents);
    let next = Arc::new(AtomicUsize::new(0));
    let stop = Arc::new(AtomicBool::new(false));
    let (tx, rx) = mpsc::channel();
    for _ in 0..workers {
        let (documents, next, stopped, tx) = (documents.clone(), next.clone(), stop.clone(), tx.clone());
        crate::pool::run(move || {
            while !stopped.load(Ordering::Relaxed) {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some((text, base_dir)) = documents.get(i) else { break };
                if tx.send((i, solve_text(text, base_dir, &stopped))).is_err() {
                    break;
                }
            }
        })
        .map_err(|e| {
            stop.store(true, Ordering::Relaxed);
            pyo3::exceptions::PyRuntimeError::new_err(format!("cannot start a planning thread: {e}"))
        })?;
    }
    drop(tx);
    let mut results: Vec<(Option<&'static str>, String)> = vec![(None, String::new()); n];
    receive(py, rx, n, &stop, |(i, outcome)| {
        results[i] = match outcome {
            Ok(json) => (None, json),
            Err((class, message)) => (Some(class), message),
        };
    })?;
    Ok(results)
}
