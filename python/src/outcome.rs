//! One plan's result handed to Python: its status, cost, path as a NumPy array and statistics
//! (as JSON, which `trailmark/plan.py` turns into a dict), the parts of `trailmark.Plan`.

use numpy::IntoPyArray;
use numpy::ndarray::Array2;
use pyo3::prelude::*;
use trailmark::solve::{SolveResult, Waypoint};

/// What a path's waypoints are, for the array of an empty path.
#[derive(Clone, Copy)]
pub enum Kind {
    /// Grid cells `(x, y)`: an `int64` array of two columns.
    Cells,
    /// Points of this many coordinates: a `float64` array.
    Points(usize),
}

/// `(status, cost, path, stats_json)`.
pub type Parts = (String, Option<f64>, Py<PyAny>, String);

/// The parts of `result`'s `trailmark.Plan`.
pub fn parts(py: Python<'_>, result: &SolveResult, kind: Kind) -> PyResult<Parts> {
    let status = match serde_json::to_value(result.status) {
        Ok(serde_json::Value::String(name)) => name,
        _ => format!("{:?}", result.status),
    };
    let path = path_array(py, &result.path, kind)?;
    let stats = serde_json::to_string(&result.stats)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    Ok((status, result.cost, path, stats))
}

/// The waypoints as one row each: cells as `int64 (n, 2)` `(x, y)`, points as `float64 (n, d)`.
fn path_array(py: Python<'_>, path: &[Waypoint], kind: Kind) -> PyResult<Py<PyAny>> {
    let cells = match path.first() {
        Some(Waypoint::Cell(_)) => true,
        Some(Waypoint::Point(_)) => false,
        None => matches!(kind, Kind::Cells),
    };
    let mixed = || pyo3::exceptions::PyRuntimeError::new_err("a path of waypoints of different kinds");
    if cells {
        let mut flat = Vec::with_capacity(path.len() * 2);
        for waypoint in path {
            let Waypoint::Cell(cell) = waypoint else { return Err(mixed()) };
            flat.extend([i64::from(cell.x), i64::from(cell.y)]);
        }
        let rows = Array2::from_shape_vec((path.len(), 2), flat).map_err(|_| mixed())?;
        Ok(rows.into_pyarray(py).into_any().unbind())
    } else {
        let dims = match (path.first(), kind) {
            (Some(Waypoint::Point(p)), _) => p.len(),
            (_, Kind::Points(d)) => d,
            _ => 2,
        };
        let mut flat = Vec::with_capacity(path.len() * dims);
        for waypoint in path {
            match waypoint {
                Waypoint::Point(p) if p.len() == dims => flat.extend_from_slice(p),
                _ => return Err(mixed()),
            }
        }
        let rows = Array2::from_shape_vec((path.len(), dims), flat).map_err(|_| mixed())?;
        Ok(rows.into_pyarray(py).into_any().unbind())
    }
}
