//! Grid worlds: a MovingAI map or inline rows, with costs, searched cell to cell.

use std::path::Path;

use trailmark_core::grid::{Cell, Connectivity, CornerCutting, Grid};
use trailmark_core::svg::GridSvg;
use trailmark_graph::GridGraph;
use trailmark_search::Search;

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::PlannerSpec;
use crate::solve::problem::{GridSpec, ProblemSpec};
use crate::solve::result::{SolveResult, Waypoint};
use crate::solve::world::grid::{cell_of, check_grid_end, corner_cutting, load_grid};

/// Solves a grid-world problem.
pub(in crate::solve) fn solve_grid(
    problem: &ProblemSpec,
    world: &GridSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForGrids { field: name }.into());
    }
    let grid = load_grid(world, base_dir)?;
    let start = cell_of("start", &problem.start, &grid)?;
    let goal = cell_of("goal", &problem.goal, &grid)?;
    let result =
        search_grid(&problem.planner, &grid, (world.connectivity, corner_cutting(world)), (start, goal))?;
    if let Some(picture) = picture {
        let cells: Vec<Cell> = result
            .path
            .iter()
            .filter_map(|w| match w {
                Waypoint::Cell(c) => Some(*c),
                Waypoint::Point(_) => None,
            })
            .collect();
        let scale = (800.0 / f64::from(grid.width().max(grid.height()))).clamp(1.0, 24.0);
        let svg = GridSvg::new(&grid).cell_size(scale).path(&cells).start(start).goal(goal);
        *picture = svg.title(format!("{} from {start} to {goal}", problem.planner.name())).to_svg();
    }
    Ok(result)
}

/// Runs the graph search `planner` (any of the registry's graph searches, jump point search and
/// the replanners and anytime searches for one plan) on a grid the caller already holds, moving
/// by `connectivity` and diagonal moves by `rule`, from `start` to `goal`: what a grid world
/// document runs once its grid is loaded, for programs that keep one grid for many queries.
///
/// ```
/// use trailmark::core::grid::{Cell, Connectivity, CornerCutting, Grid};
/// use trailmark::solve::{PlannerSpec, Status, search_grid};
///
/// let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
/// let rule = (Connectivity::Eight, CornerCutting::Forbidden);
/// let ends = (Cell::new(0, 0), Cell::new(3, 2));
/// let found = search_grid(&PlannerSpec::AStar { heuristic: None }, &grid, rule, ends)?;
/// assert_eq!(found.status, Status::Solved);
/// assert_eq!(found.cost, Some(5.0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn search_grid(
    planner: &PlannerSpec,
    grid: &Grid,
    (connectivity, rule): (Connectivity, CornerCutting),
    (start, goal): (Cell, Cell),
) -> Result<SolveResult, SolveError> {
    check_query(planner, grid, (start, goal))?;
    let graph = GridGraph::new(grid, connectivity).with_corner_cutting(rule);
    run(planner, grid, &graph, &mut Search::new(), (start, goal))
}

/// Whether `planner` may search `grid` from `start` to `goal`: a graph search within its
/// limits, between passable cells of the grid.
fn check_query(planner: &PlannerSpec, grid: &Grid, (start, goal): (Cell, Cell)) -> Result<(), SolveError> {
    planner.check_limits()?;
    if planner.sampling().is_some() {
        return Err(DocumentError::NeedsPolygons { planner: planner.name() }.into());
    }
    check_grid_end("start", start, grid)?;
    check_grid_end("goal", goal, grid)?;
    Ok(())
}

/// Runs `planner` on `grid` (for jump point search) or its `graph`, in the workspace `search`.
fn run(
    planner: &PlannerSpec,
    grid: &Grid,
    graph: &GridGraph,
    search: &mut Search,
    (start, goal): (Cell, Cell),
) -> Result<SolveResult, SolveError> {
    let rule = graph.corner_cutting();
    match planner.grid_search(grid, graph.connectivity(), rule, (start, goal)) {
        Some(found) => found,
        None => {
            let h = graph.heuristic_between(planner.grid_heuristic(graph.connectivity())?);
            planner.search_in(search, graph, (start, goal), h, Waypoint::Cell, Some(graph))
        }
    }
}

/// A grid made ready for many searches: its graph built once, as [`search_grid`] would build it
/// for each query; the caller keeps a search workspace ([`Search`]) from query to query too,
/// one per thread (its arrays are then not allocated again). What a program (or another
/// language) that asks many queries of one map keeps.
///
/// ```
/// use trailmark::core::grid::{Cell, Connectivity, CornerCutting, Grid};
/// use trailmark::search::Search;
/// use trailmark::solve::{PlannerSpec, PreparedGrid};
///
/// let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
/// let prepared = PreparedGrid::new(grid, Connectivity::Eight, CornerCutting::Forbidden);
/// let (astar, mut workspace) = (PlannerSpec::AStar { heuristic: None }, Search::new());
/// for x in 0..4 {
///     let found = prepared.search(&mut workspace, &astar, (Cell::new(0, 0), Cell::new(x, 2)))?;
///     assert_eq!(found.cost, Some([2.0, 3.0, 4.0, 5.0][x as usize]));
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct PreparedGrid {
    grid: Grid,
    graph: GridGraph,
}

impl PreparedGrid {
    /// `grid`, moved on by `connectivity` with diagonal moves by `rule`.
    pub fn new(grid: Grid, connectivity: Connectivity, rule: CornerCutting) -> Self {
        let graph = GridGraph::new(&grid, connectivity).with_corner_cutting(rule);
        PreparedGrid { grid, graph }
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Its graph.
    pub fn graph(&self) -> &GridGraph {
        &self.graph
    }

    /// Runs `planner` from `start` to `goal` in the workspace `search`, as [`search_grid`] does.
    pub fn search(
        &self,
        search: &mut Search,
        planner: &PlannerSpec,
        (start, goal): (Cell, Cell),
    ) -> Result<SolveResult, SolveError> {
        check_query(planner, &self.grid, (start, goal))?;
        run(planner, &self.grid, &self.graph, search, (start, goal))
    }
}
