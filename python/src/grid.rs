//! `trailmark.Grid`: a grid of cell costs held in Rust, from a NumPy array, a MovingAI map or
//! rows of text, searched by any graph search of the registry.

use numpy::ndarray::Array2;
use std::sync::{Mutex, TryLockError};

use numpy::{IntoPyArray, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use trailmark::core::grid::{Cell, Connectivity, CornerCutting, Grid as CoreGrid};
use trailmark::core::movingai;
use trailmark::search::Search;
use trailmark::solve::{DocumentError, PlannerSpec, PreparedGrid, SolveError, SolveResult};

use crate::documents::planner_spec;
use crate::errors::{error, solve_error};
use crate::outcome::{Kind, Parts, parts};

/// A grid of cell costs (`inf`: blocked; a move costs its length times the mean of its two
/// cells' costs), its connectivity and its rule for diagonal moves. Cells are `(x, y)`: `x` the column, `y` the row of the array.
#[pyclass(module = "trailmark._trailmark", name = "Grid", frozen)]
pub struct Grid {
    prepared: PreparedGrid,
    // The workspace kept from query to query; a query that finds it busy (another thread's)
    // searches in one of its own.
    workspace: Mutex<Search>,
}

fn moves(py: Python<'_>, connectivity: u8, corner_cutting: bool) -> PyResult<(Connectivity, CornerCutting)> {
    let connectivity = Connectivity::try_from(connectivity)
        .map_err(|_| error(py, "GridError", format!("connectivity must be 4 or 8, not {connectivity}")))?;
    Ok((connectivity, if corner_cutting { CornerCutting::Allowed } else { CornerCutting::Forbidden }))
}

fn grid_error(py: Python<'_>, e: impl Into<SolveError>) -> PyErr {
    solve_error(py, &e.into())
}

impl Grid {
    /// The grid and its graph.
    pub(crate) fn prepared(&self) -> &PreparedGrid {
        &self.prepared
    }

    fn with(py: Python<'_>, grid: CoreGrid, connectivity: u8, corner_cutting: bool) -> PyResult<Self> {
        let (connectivity, rule) = moves(py, connectivity, corner_cutting)?;
        Ok(Grid {
            prepared: PreparedGrid::new(grid, connectivity, rule),
            workspace: Mutex::new(Search::new()),
        })
    }

    /// Runs `planner` in the kept workspace, or in a new one while another thread uses it (a
    /// query that panicked leaves nothing the next one reads: each starts afresh).
    fn search(&self, planner: &PlannerSpec, ends: (Cell, Cell)) -> Result<SolveResult, SolveError> {
        match self.workspace.try_lock() {
            Ok(mut workspace) => self.prepared.search(&mut workspace, planner, ends),
            Err(TryLockError::Poisoned(poisoned)) => {
                self.prepared.search(&mut poisoned.into_inner(), planner, ends)
            }
            Err(TryLockError::WouldBlock) => self.prepared.search(&mut Search::new(), planner, ends),
        }
    }
}

/// Room for the costs of a `w x h` grid, once its size is checked: a grid too large is a
/// `GridError` and memory that cannot be had a `MemoryError`, before anything is allocated.
fn reserve(py: Python<'_>, w: usize, h: usize) -> PyResult<Vec<f64>> {
    let n = CoreGrid::cell_count(w, h).map_err(|e| grid_error(py, e))?;
    let mut costs = Vec::new();
    costs.try_reserve_exact(n).map_err(|e| pyo3::exceptions::PyMemoryError::new_err(e.to_string()))?;
    Ok(costs)
}

/// `(x, y)` as a cell, or the document error a solve document gets for it.
pub(crate) fn cell(py: Python<'_>, which: &'static str, value: (i64, i64)) -> PyResult<Cell> {
    match (u32::try_from(value.0), u32::try_from(value.1)) {
        (Ok(x), Ok(y)) => Ok(Cell::new(x, y)),
        #[allow(clippy::cast_precision_loss)] // for the message only
        _ => Err(solve_error(
            py,
            &DocumentError::NotACell { which, value: vec![value.0 as f64, value.1 as f64] }.into(),
        )),
    }
}

#[pymethods]
impl Grid {
    /// A grid whose cells are free where `free` is true (each of cost 1) and blocked elsewhere.
    #[staticmethod]
    #[pyo3(signature = (free, connectivity=8, corner_cutting=false))]
    fn from_free(
        py: Python<'_>,
        free: PyReadonlyArray2<'_, bool>,
        connectivity: u8,
        corner_cutting: bool,
    ) -> PyResult<Self> {
        let free = free.as_array();
        let (h, w) = free.dim();
        let mut costs = reserve(py, w, h)?;
        costs.extend(free.iter().map(|&f| if f { 1.0 } else { f64::INFINITY }));
        let grid = CoreGrid::from_costs(w, h, costs).map_err(|e| grid_error(py, e))?;
        Grid::with(py, grid, connectivity, corner_cutting)
    }

    /// A grid of cell costs: each positive and finite, or `inf` for a blocked cell.
    #[staticmethod]
    #[pyo3(signature = (costs, connectivity=8, corner_cutting=false))]
    fn from_costs(
        py: Python<'_>,
        costs: PyReadonlyArray2<'_, f64>,
        connectivity: u8,
        corner_cutting: bool,
    ) -> PyResult<Self> {
        let costs = costs.as_array();
        let (h, w) = costs.dim();
        let grid =
            CoreGrid::from_costs(w, h, costs.iter().copied().collect()).map_err(|e| grid_error(py, e))?;
        Grid::with(py, grid, connectivity, corner_cutting)
    }

    /// The grid of a MovingAI `.map` file (8-connected without corner cutting by default, as
    /// the benchmark's optima are).
    #[staticmethod]
    #[pyo3(signature = (path, connectivity=8, corner_cutting=false))]
    fn from_movingai(
        py: Python<'_>,
        path: std::path::PathBuf,
        connectivity: u8,
        corner_cutting: bool,
    ) -> PyResult<Self> {
        let grid = py.detach(|| movingai::read_map(&path)).map_err(|e| grid_error(py, e))?;
        Grid::with(py, grid, connectivity, corner_cutting)
    }

    /// A grid from rows of text: `.` free, `@` blocked (MovingAI's characters).
    #[staticmethod]
    #[pyo3(signature = (rows, connectivity=8, corner_cutting=false))]
    fn from_rows(
        py: Python<'_>,
        rows: Vec<String>,
        connectivity: u8,
        corner_cutting: bool,
    ) -> PyResult<Self> {
        let grid = CoreGrid::from_rows(&rows).map_err(|e| grid_error(py, e))?;
        Grid::with(py, grid, connectivity, corner_cutting)
    }

    /// Columns.
    #[getter]
    fn width(&self) -> u32 {
        self.prepared.grid().width()
    }

    /// Rows.
    #[getter]
    fn height(&self) -> u32 {
        self.prepared.grid().height()
    }

    /// 4 or 8.
    #[getter]
    fn connectivity(&self) -> u8 {
        u8::from(self.prepared.graph().connectivity())
    }

    /// Whether diagonal moves may cut a blocked cell's corner.
    #[getter]
    fn corner_cutting(&self) -> bool {
        self.prepared.graph().corner_cutting() == CornerCutting::Allowed
    }

    /// Each cell's cost as a `float64 (height, width)` array, `inf` where blocked.
    fn costs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let grid = self.prepared.grid();
        let shape = (grid.height() as usize, grid.width() as usize);
        let costs = Array2::from_shape_vec(shape, grid.costs().to_vec())
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(costs.into_pyarray(py).into_any())
    }

    /// Plans from `start` to `goal` (cells `(x, y)`) with the graph search `planner` and its
    /// settings as JSON (those of a problem document's `"planner"`); the parts of a `Plan`.
    fn plan_json(
        &self,
        py: Python<'_>,
        start: (i64, i64),
        goal: (i64, i64),
        planner: &str,
    ) -> PyResult<Parts> {
        let spec = planner_spec(py, planner)?;
        let ends = (cell(py, "start", start)?, cell(py, "goal", goal)?);
        let found = py.detach(|| self.search(&spec, ends)).map_err(|e| solve_error(py, &e))?;
        parts(py, &found, Kind::Cells)
    }

    fn __repr__(&self) -> String {
        let grid = self.prepared.grid();
        format!(
            "Grid({} x {}, {}-connected, {} passable cells)",
            grid.width(),
            grid.height(),
            u8::from(self.prepared.graph().connectivity()),
            grid.passable_count()
        )
    }

    /// `{"rows": [...], "costs": [...], "connectivity": 4 | 8, "corner_cutting": bool}`: the
    /// grid world of a problem document (costs only where a passable cell's is not 1).
    fn world<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let (grid, graph) = (self.prepared.grid(), self.prepared.graph());
        let world = PyDict::new(py);
        world.set_item("rows", grid.to_rows())?;
        if !grid.is_uniform() || grid.min_cost().is_some_and(|c| c != 1.0) {
            let w = grid.width() as usize;
            let rows: Vec<Vec<f64>> = grid
                .costs()
                .chunks(w)
                .map(|row| row.iter().map(|&c| if c.is_finite() { c } else { 1.0 }).collect())
                .collect();
            world.set_item("costs", rows)?;
        }
        world.set_item("connectivity", u8::from(graph.connectivity()))?;
        world.set_item("corner_cutting", graph.corner_cutting() == CornerCutting::Allowed)?;
        Ok(world)
    }
}
