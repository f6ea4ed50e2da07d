//! Rust errors as Python exceptions: each error enum of trailmark is a subclass of
//! `trailmark.TrailmarkError` of the same name, defined in `trailmark/errors.py` (where Python
//! classes can also derive from `ValueError` or `OSError`).

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyType;
use trailmark::solve::SolveError;

/// The exception of class `name` (a class of `trailmark.errors`) with `message`.
pub fn error(py: Python<'_>, name: &str, message: impl std::fmt::Display) -> PyErr {
    let class = py
        .import("trailmark.errors")
        .and_then(|module| module.getattr(name))
        .and_then(|class| class.cast_into::<PyType>().map_err(PyErr::from));
    match class {
        Ok(class) => PyErr::from_type(class, message.to_string()),
        // Only a broken installation lacks the module: say so rather than lose the message.
        Err(missing) => {
            PyRuntimeError::new_err(format!("{message} (and trailmark.errors.{name}: {missing})"))
        }
    }
}

/// The class of `trailmark.errors` that a solve error raises: the name of its Rust error enum.
pub fn class_of(e: &SolveError) -> &'static str {
    match e {
        SolveError::Map(_) => "ReadError",
        SolveError::RosMap(_) => "MapError",
        SolveError::Grid(_) => "GridError",
        SolveError::Document(_) => "DocumentError",
        SolveError::Search(_) => "SearchError",
        SolveError::Visibility(_) => "VisibilityError",
        SolveError::Trapezoid(_) => "TrapezoidError",
        SolveError::Prm(_) => "PrmError",
        SolveError::Sampler(_) => "SamplerError",
        SolveError::Plan(_) => "PlanError",
        SolveError::Space(_) => "SpaceError",
        SolveError::Curve(_) => "CurveError",
        SolveError::Car(_) => "CarError",
        SolveError::Robot(_) => "RobotError",
        _ => "SolveError",
    }
}

/// A solve error as its Python exception.
pub fn solve_error(py: Python<'_>, e: &SolveError) -> PyErr {
    error(py, class_of(e), e)
}
