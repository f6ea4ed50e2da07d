//! The extension module `trailmark._trailmark` of the Python package `trailmark` (see
//! python/README.md and docs/python.md): the Rust side of each Python function, taking and
//! giving JSON text, NumPy arrays and plain values; `python/trailmark/*.py` shape them into
//! the Python API (dicts, `Plan`, keyword arguments) and its exceptions.

mod callback;
mod documents;
mod errors;
mod grid;
mod interrupt;
mod outcome;
mod pool;
mod replanner;
mod robot;
mod ros_map;

use pyo3::prelude::*;

/// The module's functions and classes.
#[pymodule]
fn _trailmark(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add_function(wrap_pyfunction!(documents::solve_json, module)?)?;
    module.add_function(wrap_pyfunction!(documents::solve_many_json, module)?)?;
    module.add_function(wrap_pyfunction!(callback::plan_boxes_json, module)?)?;
    module.add_class::<grid::Grid>()?;
    module.add_class::<ros_map::RosMap>()?;
    module.add_class::<replanner::Replanner>()?;
    module.add_class::<robot::RobotWorld>()?;
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add("MAX_DOCUMENT_BYTES", trailmark::core::read::MAX_DOCUMENT_BYTES)?;
    module.add("MAX_GRID_CELLS", trailmark::core::grid::Grid::MAX_CELLS)?;
    Ok(())
}
