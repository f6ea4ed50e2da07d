//! `trailmark.RobotWorld`: a robot arm (URDF, SRDF, planning group) among a MoveIt scene, read
//! once, then asked about states in batches and planned in as often as wanted.

use std::path::PathBuf;
use std::sync::Arc;

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use trailmark::solve::RobotWorldSpec;

use crate::documents::planner_spec;
use crate::errors::{class_of, error, solve_error};
use crate::interrupt::run_stoppable;
use crate::outcome::{Kind, Parts, parts};

/// A robot world made ready: the checker of its group among the scene.
#[pyclass(module = "trailmark._trailmark", name = "RobotWorld", frozen)]
pub struct RobotWorld {
    world: Arc<trailmark::solve::RobotWorld>,
}

#[pymethods]
impl RobotWorld {
    /// The world of `spec` (a document's `"robot"` world as JSON, its `group` required), its
    /// files read relative to `base_dir`.
    #[staticmethod]
    fn load(py: Python<'_>, spec: &str, base_dir: PathBuf) -> PyResult<Self> {
        let spec: RobotWorldSpec = serde_json::from_str(spec)
            .map_err(|e| error(py, "DocumentError", format!("invalid robot world: {e}")))?;
        let world = py
            .detach(|| trailmark::solve::RobotWorld::load(&spec, &base_dir))
            .map_err(|e| solve_error(py, &e))?;
        Ok(RobotWorld { world: Arc::new(world) })
    }

    /// The group's joints, in the order of states.
    #[getter]
    fn joint_names(&self) -> Vec<String> {
        self.world.checker().group().names.clone()
    }

    /// The group's joint limits, a `float64 (d, 2)` array of `(lower, upper)`.
    fn limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let bounds = &self.world.checker().group().bounds;
        let flat: Vec<f64> = bounds.iter().flat_map(|&(low, high)| [low, high]).collect();
        let limits = Array2::from_shape_vec((bounds.len(), 2), flat)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(limits.into_pyarray(py).into_any())
    }

    /// Whether each row of `states` (`float64 (n, d)`, a value per group joint) is free: a
    /// `bool (n,)` array, computed without the GIL. A row that is not finite, or beyond the
    /// joints' limits, is not free.
    fn are_free<'py>(
        &self,
        py: Python<'py>,
        states: PyReadonlyArray2<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<bool>>> {
        let joints = self.world.checker().group().names.len();
        let array = states.as_array();
        if array.ncols() != joints {
            return Err(error(
                py,
                "DocumentError",
                format!("states have {} columns; the group has {joints} joints", array.ncols()),
            ));
        }
        // Row-major whatever the array's strides, then eight rows at a time without the GIL.
        let flat: Vec<f64> = array.iter().copied().collect();
        let mut free = Vec::with_capacity(array.nrows());
        py.detach(|| self.world.are_free(flat.chunks_exact(joints.max(1)), &mut free));
        free.resize(array.nrows(), false);
        Ok(free.into_pyarray(py))
    }

    /// Whether the straight motion in joint space from `a` to `b` is free (continuous joints
    /// turning the short way), proven as the planners prove theirs.
    fn motion_is_free(&self, py: Python<'_>, a: Vec<f64>, b: Vec<f64>) -> bool {
        py.detach(|| self.world.motion_is_free(&a, &b))
    }

    /// Plans from `start` to `goal` with the sampling planner `planner` (its settings as JSON)
    /// and `seed` on a planning thread; Ctrl-C stops it. The parts of a `Plan`, its path as one
    /// row of joint values per state.
    fn plan_json(
        &self,
        py: Python<'_>,
        start: Vec<f64>,
        goal: Vec<f64>,
        planner: &str,
        seed: u64,
    ) -> PyResult<Parts> {
        let spec = planner_spec(py, planner)?;
        let world = Arc::clone(&self.world);
        let found = run_stoppable(py, move |stop| {
            world
                .plan(&spec, &start, &goal, seed, Some(Arc::clone(stop)))
                .map_err(|e| (class_of(&e), e.to_string()))
        })?;
        parts(py, &found, Kind::Points(self.world.checker().group().names.len()))
    }

    fn __repr__(&self) -> String {
        let group = self.world.checker().group();
        format!("RobotWorld(group {:?} of {} joints)", group.name, group.names.len())
    }
}
