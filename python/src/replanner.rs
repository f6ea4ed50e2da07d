//! `trailmark.Replanner`: an incremental planner (D* Lite, LPA*, MPGAA*, Adaptive A*, AD*, or A*
//! from scratch) kept between plans on a grid whose cell costs change as the robot learns them.

use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use trailmark::core::grid::{Cell, Connectivity};
use trailmark::graph::GridGraph;
use trailmark::search::SearchError;
use trailmark::solve::{ResultStats, SolveError, SolveResult, Status, Waypoint};

use crate::documents::planner_spec;
use crate::errors::{error, solve_error};
use crate::grid::{Grid, cell};
use crate::outcome::{Kind, Parts, parts};

type Boxed = Box<dyn trailmark::search::Replanner<GridGraph>>;

/// A replanner on its own copy of a grid, from the robot's cell to the goal.
// Unsendable: the planner behind `dyn Replanner` is not `Send`; Python keeps it on one thread.
#[pyclass(module = "trailmark._trailmark", name = "Replanner", unsendable)]
pub struct Replanner {
    graph: GridGraph,
    planner: Boxed,
    name: &'static str,
    connectivity: Connectivity,
}

fn searched(py: Python<'_>, e: SearchError<Cell>) -> PyErr {
    solve_error(py, &SolveError::Search(e.map_node(Waypoint::Cell)))
}

#[pymethods]
impl Replanner {
    /// The replanner `planner` (its settings as JSON: a document's `"planner"`) on a copy of
    /// `grid`, from `start` to `goal`.
    #[new]
    fn new(
        py: Python<'_>,
        grid: &Grid,
        start: (i64, i64),
        goal: (i64, i64),
        planner: &str,
    ) -> PyResult<Self> {
        let spec = planner_spec(py, planner)?;
        spec.check_limits().map_err(|e| solve_error(py, &e.into()))?;
        let (start, goal) = (cell(py, "start", start)?, cell(py, "goal", goal)?);
        let prepared = grid.prepared();
        for (which, end) in [("start", start), ("goal", goal)] {
            trailmark::solve::check_grid_end(which, end, prepared.grid())
                .map_err(|e| solve_error(py, &e.into()))?;
        }
        // A copy of its own: the replanner changes its costs.
        let graph = prepared.graph().clone();
        let connectivity = graph.connectivity();
        let kind = spec.grid_heuristic(connectivity).map_err(|e| solve_error(py, &e.into()))?;
        let h = graph.heuristic_between(kind);
        let made = spec.replanner(&graph, start, goal, h).ok_or_else(|| {
            error(
                py,
                "DocumentError",
                format!(
                    "\"{}\" does not replan; the replanners are {}",
                    spec.name(),
                    trailmark::solve::PlannerName::replanner_names()
                ),
            )
        })?;
        let planner = made.map_err(|e| searched(py, e))?;
        Ok(Replanner { graph, planner, name: spec.name(), connectivity })
    }

    /// The planner's document name.
    #[getter]
    fn planner(&self) -> &'static str {
        self.name
    }

    /// Plans (or repairs the last plan) from the robot's cell to the goal; the parts of a `Plan`
    /// with this plan's own statistics.
    fn plan(&mut self, py: Python<'_>) -> PyResult<Parts> {
        let stats = self.planner.plan(&self.graph).map_err(|e| searched(py, e))?;
        let path = self.planner.path(&self.graph);
        let result = SolveResult {
            status: if path.is_some() { Status::Solved } else { Status::NoPath },
            cost: path.as_ref().map(|p| p.cost),
            path: path.map(|p| p.nodes.into_iter().map(Waypoint::Cell).collect()).unwrap_or_default(),
            stats: ResultStats {
                expansions: Some(stats.expansions),
                pushes: Some(stats.pushes),
                decreases: Some(stats.decreases),
                reopenings: Some(stats.reopenings),
                time_s: stats.elapsed.as_secs_f64(),
                ..ResultStats::default()
            },
        };
        parts(py, &result, Kind::Cells)
    }

    /// Sets the costs of `xs[i], ys[i]` to `costs[i]` (`inf`: blocked) and tells the planner
    /// which cells' moves changed; all checked before any is applied.
    fn set_costs(
        &mut self,
        py: Python<'_>,
        xs: PyReadonlyArray1<'_, i64>,
        ys: PyReadonlyArray1<'_, i64>,
        costs: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<()> {
        let (xs, ys, costs) = (xs.as_array(), ys.as_array(), costs.as_array());
        if xs.len() != ys.len() || xs.len() != costs.len() {
            return Err(error(py, "DocumentError", "cells and costs must be as many"));
        }
        let mut changes = Vec::with_capacity(xs.len());
        for ((&x, &y), &c) in xs.iter().zip(ys.iter()).zip(costs.iter()) {
            let at = cell(py, "changed cell", (x, y))?;
            if self.graph.cost(at).is_none() {
                let e = trailmark::core::grid::GridError::OutOfBounds {
                    cell: at,
                    width: self.graph.width(),
                    height: self.graph.height(),
                };
                return Err(solve_error(py, &e.into()));
            }
            if !trailmark::core::grid::is_cell_cost(c) {
                let e = trailmark::core::grid::GridError::InvalidCost { cell: at, cost: c };
                return Err(solve_error(py, &e.into()));
            }
            changes.push((at, c));
        }
        let mut touched = Vec::new();
        for &(at, c) in &changes {
            self.graph.set_cost(at, c).map_err(|e| solve_error(py, &e.into()))?;
            touched.extend(self.graph.cells_affected_by(at));
        }
        touched.sort_unstable_by_key(|c| (c.y, c.x));
        touched.dedup();
        self.planner.update_nodes(&self.graph, &touched).map_err(|e| searched(py, e))
    }

    /// Moves the robot (the plans' start) to `to`.
    fn move_to(&mut self, py: Python<'_>, to: (i64, i64)) -> PyResult<()> {
        let to = cell(py, "robot's cell", to)?;
        self.planner.move_start(&self.graph, to).map_err(|e| searched(py, e))
    }

    /// The next cell of the current path after the robot's, if there is one.
    fn next_step(&self) -> Option<(u32, u32)> {
        self.planner.next_step(&self.graph).map(|c| (c.x, c.y))
    }

    /// The current costs, as `Grid.costs` gives them.
    fn costs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (w, h) = (self.graph.width(), self.graph.height());
        let values: Vec<f64> = (0..h)
            .flat_map(|y| (0..w).map(move |x| Cell::new(x, y)))
            .map(|c| self.graph.cost(c).unwrap_or(f64::INFINITY))
            .collect();
        let array = numpy::ndarray::Array2::from_shape_vec((h as usize, w as usize), values)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(numpy::IntoPyArray::into_pyarray(array, py).into_any())
    }

    /// 4 or 8.
    #[getter]
    fn connectivity(&self) -> u8 {
        u8::from(self.connectivity)
    }
}
