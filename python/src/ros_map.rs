//! `trailmark.RosMap`: a ROS map (map_server's YAML and image) made into a Nav2-style costmap
//! once, then searched in metres as often as asked.

use std::path::PathBuf;

use numpy::IntoPyArray;
use numpy::ndarray::Array2;
use pyo3::prelude::*;
use trailmark::solve::{RosMapSpec, RosMapWorld};

use crate::documents::planner_spec;
use crate::errors::{error, solve_error};
use crate::outcome::{Kind, Parts, parts};

/// A ROS map's costmap around the robot and the travel costs searched over it.
#[pyclass(module = "trailmark._trailmark", name = "RosMap", frozen)]
pub struct RosMap {
    world: RosMapWorld,
}

#[pymethods]
impl RosMap {
    /// The map of the world settings `spec` (a document's `"ros_map"` as JSON), its files read
    /// relative to `base_dir`.
    #[staticmethod]
    fn load(py: Python<'_>, spec: &str, base_dir: PathBuf) -> PyResult<Self> {
        let spec: RosMapSpec = serde_json::from_str(spec)
            .map_err(|e| error(py, "DocumentError", format!("invalid ROS map world: {e}")))?;
        let world = py.detach(|| RosMapWorld::load(&spec, &base_dir)).map_err(|e| solve_error(py, &e))?;
        Ok(RosMap { world })
    }

    /// Columns.
    #[getter]
    fn width(&self) -> u32 {
        self.world.costmap().frame().width()
    }

    /// Rows.
    #[getter]
    fn height(&self) -> u32 {
        self.world.costmap().frame().height()
    }

    /// Metres per cell.
    #[getter]
    fn resolution(&self) -> f64 {
        self.world.costmap().frame().resolution()
    }

    /// `(x, y, yaw)` of the map's lower-left corner, in metres and radians.
    #[getter]
    fn origin(&self) -> (f64, f64, f64) {
        let [x, y, yaw] = self.world.costmap().frame().origin();
        (x, y, yaw)
    }

    /// The costmap as a `uint8 (height, width)` array, row 0 at the top as in the map's image:
    /// 0 free to 252, 253 inscribed, 254 lethal, 255 unknown.
    fn costs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let frame = self.world.costmap().frame();
        let shape = (frame.height() as usize, frame.width() as usize);
        let costs = Array2::from_shape_vec(shape, self.world.costmap().costs().to_vec())
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(costs.into_pyarray(py).into_any())
    }

    /// Plans from `start` to `goal` (`(x, y)` in metres) with the graph search `planner` (its
    /// settings as JSON); the parts of a `Plan`, its path in metres.
    fn plan_json(&self, py: Python<'_>, start: Vec<f64>, goal: Vec<f64>, planner: &str) -> PyResult<Parts> {
        let spec = planner_spec(py, planner)?;
        let found = py.detach(|| self.world.search(&spec, &start, &goal)).map_err(|e| solve_error(py, &e))?;
        parts(py, &found, Kind::Points(2))
    }

    fn __repr__(&self) -> String {
        let frame = self.world.costmap().frame();
        format!("RosMap({} x {} cells of {} m)", frame.width(), frame.height(), frame.resolution())
    }
}
