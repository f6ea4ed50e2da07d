//! Problem documents from Python: `trailmark.solve` and `trailmark.solve_many`, the documents
//! and results of `cargo xtask solve`, as JSON text (`trailmark/documents.py` turns dicts into
//! it and back).

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, PoisonError, mpsc};

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use trailmark::core::read::MAX_DOCUMENT_BYTES;
use trailmark::solve::ProblemSpec;

use crate::errors::{class_of, error};
use crate::interrupt::{receive, run_stoppable};

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
    run_stoppable(py, move |stop| solve_text(&document, &base_dir, stop))
}

/// A document to solve: its place in the list, its text and the folder its paths are
/// relative to.
type Job = (usize, String, PathBuf);

/// Solves every document of `documents` (an iterator of `count` pairs: its text and the folder
/// its paths are relative to) on `workers` threads (default: one per core, at most
/// `MAX_WORKERS`), without the GIL; Ctrl-C stops every planner and the wait; each result is
/// `(None, json)`, or `(class, message)` for a document that could not be solved. The
/// documents are handed out as the iterator makes them, so that the interpreter writes the
/// next while the first are planned.
#[pyfunction]
#[pyo3(signature = (documents, count, workers=None))]
pub fn solve_many_json(
    py: Python<'_>,
    documents: &Bound<'_, PyAny>,
    count: usize,
    workers: Option<usize>,
) -> PyResult<Vec<(Option<&'static str>, String)>> {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let workers = match workers {
        Some(0) => return Err(PyValueError::new_err("workers must be at least 1")),
        Some(w) => w.min(MAX_WORKERS),
        None => cores,
    }
    .min(count.max(1));
    let stop = Arc::new(AtomicBool::new(false));
    let stopped = |error: PyErr| {
        stop.store(true, Ordering::Relaxed);
        error
    };
    let (job_tx, job_rx) = mpsc::channel::<Job>();
    let job_rx = Arc::new(Mutex::new(job_rx));
    let (tx, rx) = mpsc::channel();
    for _ in 0..workers {
        let (job_rx, stop, tx) = (Arc::clone(&job_rx), Arc::clone(&stop), tx.clone());
        crate::pool::run(move || {
            loop {
                // The lock is held while waiting: the other workers would wait for a job anyway.
                let job = job_rx.lock().unwrap_or_else(PoisonError::into_inner).recv();
                let Ok((i, text, base_dir)) = job else { break };
                if stop.load(Ordering::Relaxed) || tx.send((i, solve_text(&text, &base_dir, &stop))).is_err()
                {
                    break;
                }
            }
        })
        .map_err(|e| stopped(PyRuntimeError::new_err(format!("cannot start a planning thread: {e}"))))?;
    }
    drop(tx);
    let mut results: Vec<(Option<&'static str>, String)> = vec![(None, String::new()); count];
    let mut store = |(i, outcome): (usize, Outcome)| {
        results[i] = match outcome {
            Ok(json) => (None, json),
            Err((class, message)) => (Some(class), message),
        };
    };
    let (mut fed, mut got) = (0, 0);
    for document in documents.try_iter()? {
        let (text, base_dir) = document.and_then(|d| d.extract::<(String, PathBuf)>()).map_err(stopped)?;
        if fed == count {
            return Err(stopped(PyValueError::new_err(format!("more documents than the {count} counted"))));
        }
        job_tx
            .send((fed, text, base_dir))
            .map_err(|_| stopped(PyRuntimeError::new_err("the planning threads ended")))?;
        fed += 1;
        while let Ok(message) = rx.try_recv() {
            store(message);
            got += 1;
        }
        py.check_signals().map_err(stopped)?;
    }
    drop(job_tx);
    receive(py, rx, fed - got, &stop, store)?;
    results.truncate(fed);
    Ok(results)
}
