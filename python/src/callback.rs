//! Sampling planners over the user's own validity: a Python function asked of one state at a
//! time (a `float64 (d,)` array, returning a truth value) or, in the batch form, of every state
//! a motion checks in one call (a `float64 (n, d)` array, returning `n` booleans).

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use trailmark::solve::{MAX_BOX_DIMENSION, ProblemSpec, WorldSpec, solve_boxes_with};
use trailmark::space::SVector;
use trailmark::space::validity::{Batched, Sampled};

use crate::documents::parse;
use crate::errors::{error, solve_error};
use crate::outcome::{Kind, Parts, parts};

/// The user's validity function and the first error it raised (after which it is not called
/// again and the planner is stopped).
struct Callback<'py> {
    function: Bound<'py, PyAny>,
    asarray: Bound<'py, PyAny>,
    failed: RefCell<Option<PyErr>>,
    stop: Arc<AtomicBool>,
    calls: std::cell::Cell<u32>,
}

/// Calls between two moments the GIL is let go, for the interpreter's other threads.
const CALLS_PER_RELEASE: u32 = 64;

impl Callback<'_> {
    /// Whether every state of `states` is valid, in one call in the batch form.
    fn all_valid<const N: usize>(&self, states: &[SVector<f64, N>], batch: bool) -> bool {
        if self.failed.borrow().is_some() {
            return false;
        }
        let py = self.function.py();
        // The plan holds the GIL between calls; now and then it lets the interpreter's other
        // threads run (a compiled function never does).
        self.calls.set(self.calls.get().wrapping_add(1));
        if self.calls.get().is_multiple_of(CALLS_PER_RELEASE) {
            py.detach(|| ());
        }
        // Ctrl-C reaches a planner whose function runs no Python code (a ufunc, a compiled
        // function): the signal is looked for at every call.
        let answer = py
            .check_signals()
            .and_then(|()| if batch { self.ask_batch(py, states) } else { self.ask_each(py, states) });
        answer.unwrap_or_else(|e| {
            self.stop.store(true, Ordering::Relaxed);
            *self.failed.borrow_mut() = Some(e);
            false
        })
    }

    fn ask_each<const N: usize>(&self, py: Python<'_>, states: &[SVector<f64, N>]) -> PyResult<bool> {
        for state in states {
            let array = Array1::from_iter(state.iter().copied()).into_pyarray(py);
            if !truth(py, &self.function.call1((array,))?)? {
                return Ok(false);
            }
        }
        Ok(true)
    }

    fn ask_batch<const N: usize>(&self, py: Python<'_>, states: &[SVector<f64, N>]) -> PyResult<bool> {
        let flat: Vec<f64> = states.iter().flat_map(|s| s.iter().copied()).collect();
        let array = Array2::from_shape_vec((states.len(), N), flat)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?
            .into_pyarray(py);
        let answer = self.function.call1((array,))?;
        let answer = match answer.cast::<PyArray1<bool>>() {
            Ok(answer) => answer.clone(),
            // Integers of 0 and 1 are booleans too; a float (a distance?), a string or NaN is
            // not: what it means is not for trailmark to guess.
            Err(_) => {
                let array = self.asarray.call1((answer,))?;
                let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
                let whole = (kind == "i" || kind == "u")
                    && array.call_method0("min")?.extract::<i64>().is_ok_and(|v| v >= 0)
                    && array.call_method0("max")?.extract::<i64>().is_ok_and(|v| v <= 1);
                if !whole {
                    return Err(wrong_answer(py, states.len(), &format!("values of dtype kind {kind:?}")));
                }
                array
                    .call_method1("astype", ("bool",))?
                    .cast_into::<PyArray1<bool>>()
                    .map_err(|_| wrong_answer(py, states.len(), "not a 1-D array"))?
            }
        };
        if answer.len() != states.len() {
            return Err(wrong_answer(py, states.len(), &format!("{} answers", answer.len())));
        }
        let answer = answer.readonly();
        let answers =
            answer.as_slice().map_or_else(|_| answer.as_array().iter().all(|&v| v), |s| s.iter().all(|&v| v));
        Ok(answers)
    }
}

/// A single state's answer: `True`/`False` (Python's or NumPy's), or the integers 1 and 0.
fn truth(py: Python<'_>, answer: &Bound<'_, PyAny>) -> PyResult<bool> {
    if let Ok(value) = answer.extract::<bool>() {
        return Ok(value);
    }
    match answer.extract::<i64>() {
        Ok(1) => Ok(true),
        Ok(0) => Ok(false),
        _ => Err(error(
            py,
            "CallbackError",
            format!(
                "the validity function returned {}; it must return a boolean (True or False)",
                answer.repr().map_or_else(|_| "a value".to_owned(), |r| r.to_string())
            ),
        )),
    }
}

fn wrong_answer(py: Python<'_>, n: usize, found: &str) -> PyErr {
    error(
        py,
        "CallbackError",
        format!(
            "the batch validity function was given {n} states and returned {found}; it must return one boolean per state (an array of shape ({n},))"
        ),
    )
}

/// Plans the box-world document `document` with its states and motions also checked by the
/// Python function `is_valid`, at `resolution` (a fraction of the space's extent) along
/// motions; the parts of a `Plan`.
#[pyfunction]
pub fn plan_boxes_json(
    py: Python<'_>,
    document: &str,
    is_valid: Bound<'_, PyAny>,
    batch: bool,
    resolution: f64,
) -> PyResult<Parts> {
    let problem = parse(document).map_err(|(class, message)| error(py, class, message))?;
    if !is_valid.is_callable() {
        return Err(pyo3::exceptions::PyTypeError::new_err("is_valid must be callable"));
    }
    let dims = match &problem.world {
        WorldSpec::Boxes(world) => world.bounds.len(),
        _ => return Err(error(py, "DocumentError", "a validity function plans in a box world's bounds")),
    };
    let callback = Callback {
        function: is_valid,
        asarray: py.import("numpy")?.getattr("asarray")?,
        failed: RefCell::new(None),
        stop: Arc::new(AtomicBool::new(false)),
        calls: std::cell::Cell::new(0),
    };
    macro_rules! in_dimensions {
        ($($n:literal)*) => {
            match dims {
                $($n => plan::<$n>(py, &problem, &callback, batch, resolution),)*
                d => Err(error(py, "DocumentError", format!("the box world has {d} axes; from 1 to {MAX_BOX_DIMENSION} are supported"))),
            }
        };
    }
    let planned = in_dimensions!(1 2 3 4 5 6 7 8);
    if let Some(e) = callback.failed.take() {
        return Err(e);
    }
    planned
}

fn plan<const N: usize>(
    py: Python<'_>,
    problem: &ProblemSpec,
    callback: &Callback<'_>,
    batch: bool,
    resolution: f64,
) -> PyResult<Parts> {
    let space_error = |e| solve_error(py, &trailmark::solve::SolveError::Space(e));
    let stop = Some(Arc::clone(&callback.stop));
    let result = if batch {
        let validity =
            Batched::new(|states: &[SVector<f64, N>]| callback.all_valid(states, true), resolution)
                .map_err(space_error)?;
        solve_boxes_with::<N, _>(problem, &validity, stop)
    } else {
        let validity = Sampled::new(
            |state: &SVector<f64, N>| callback.all_valid(std::slice::from_ref(state), false),
            resolution,
        )
        .map_err(space_error)?;
        solve_boxes_with::<N, _>(problem, &validity, stop)
    };
    let result = result.map_err(|e| solve_error(py, &e))?;
    parts(py, &result, Kind::Points(N))
}
