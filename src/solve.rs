//! Solving a [`Problem`] document: build the world's graph, run the named planner, report.
//!
//! This is the engine of `cargo xtask solve`, usable from Rust as well.
//!
//! ```
//! use trailmark::problem::{Problem, Status};
//! use trailmark::solve::solve;
//!
//! let problem: Problem = serde_json::from_str(r#"{
//!     "world": {"grid": {"rows": ["....", ".@@.", "...."]}},
//!     "start": [0, 0], "goal": [3, 2],
//!     "planner": {"name": "astar"}
//! }"#)?;
//! let result = solve(&problem, ".")?;
//! assert_eq!(result.status, Status::Solved);
//! assert_eq!(result.cost, Some(5.0));
//! assert_eq!(result.path.len(), 6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::path::Path;

use thiserror::Error;

use trailmark_core::grid::{Cell, Grid, GridError, GridHeuristic};
use trailmark_core::movingai::{self, ReadError};
use trailmark_core::problem::{
    GridWorld, IterationRecord, PlannerSpec, Problem, ResultStats, SolveResult, Status, Waypoint, World,
};
use trailmark_graph::{CornerCutting, GridGraph};
use trailmark_search::{
    AdStar, AnytimeResult, Budget, DStarLite, EpsilonSchedule, LpaStar, Search, SearchError, SearchResult,
};

/// Why a problem could not be solved (as opposed to having no path).
#[derive(Debug, Error)]
pub enum SolveError {
    /// The map file could not be read or parsed.
    #[error(transparent)]
    Map(#[from] ReadError),
    /// The grid (rows or costs) is invalid.
    #[error("invalid grid: {0}")]
    Grid(#[from] GridError),
    /// A grid world names neither `map` nor `rows`, or both.
    #[error("a grid world needs exactly one of \"map\" and \"rows\"")]
    GridSource,
    /// The `costs` rows do not match the grid.
    #[error("\"costs\" must have {height} rows of {width} numbers (row {row} has {found})")]
    CostsShape {
        /// The grid width.
        width: u32,
        /// The grid height.
        height: u32,
        /// The first mismatching row (the row count if rows are missing).
        row: usize,
        /// Its length.
        found: usize,
    },
    /// A start or goal is not a pair of whole, non-negative numbers.
    #[error("the {which} {value:?} is not a grid cell: expected [x, y] with whole numbers >= 0")]
    NotACell {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
    },
    /// A start or goal lies outside the map.
    #[error("the {which} {cell} is outside the {width} x {height} map")]
    Outside {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The cell.
        cell: Cell,
        /// The map width.
        width: u32,
        /// The map height.
        height: u32,
    },
    /// A start or goal is a blocked cell.
    #[error("the {which} {cell} is a blocked cell")]
    Blocked {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The cell.
        cell: Cell,
    },
    /// An optimal planner was given a heuristic that may overestimate.
    #[error(
        "the {heuristic:?} heuristic overestimates on an 8-connected grid, so the planner would not be optimal; use \"octile\" or \"euclidean\", or \"weighted_astar\""
    )]
    Inadmissible {
        /// The heuristic asked for.
        heuristic: GridHeuristic,
    },
    /// A time limit that is negative or not a number.
    #[error("\"time_limit_s\" is {0}; it must be a number of seconds >= 0")]
    TimeLimit(f64),
    /// The search rejected the query.
    #[error(transparent)]
    Search(#[from] SearchError<Cell>),
}

/// The grid of a grid world, with relative map paths resolved against `base_dir`.
pub fn load_grid(world: &GridWorld, base_dir: impl AsRef<Path>) -> Result<Grid, SolveError> {
    let mut grid = match (&world.map, &world.rows) {
        (Some(map), None) => movingai::read_map(base_dir.as_ref().join(map))?,
        (None, Some(rows)) => Grid::from_rows(rows)?,
        _ => return Err(SolveError::GridSource),
    };
    if let Some(costs) = &world.costs {
        let (w, h) = (grid.width(), grid.height());
        let shape = |row, found| SolveError::CostsShape { width: w, height: h, row, found };
        if costs.len() != h as usize {
            return Err(shape(costs.len(), costs.len()));
        }
        for (y, row) in costs.iter().enumerate() {
            if row.len() != w as usize {
                return Err(shape(y, row.len()));
            }
            for (x, &c) in row.iter().enumerate() {
                let cell = Cell::new(x as u32, y as u32);
                if grid.is_passable(cell) {
                    grid.set_cost(cell, c)?;
                } else if !(c.is_finite() && c > 0.0) {
                    // Blocked cells stay blocked, but their cost must still be a valid number.
                    return Err(GridError::InvalidCost { cell, cost: c }.into());
                }
            }
        }
    }
    Ok(grid)
}

/// The grid graph of a grid world.
pub fn grid_graph(world: &GridWorld, grid: &Grid) -> GridGraph {
    let rule = if world.corner_cutting { CornerCutting::Allowed } else { CornerCutting::Forbidden };
    GridGraph::new(grid, world.connectivity).with_corner_cutting(rule)
}

fn cell_of(which: &'static str, value: &[f64], grid: &Grid) -> Result<Cell, SolveError> {
    let whole = |v: f64| v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v);
    let [x, y] = value else { return Err(SolveError::NotACell { which, value: value.to_vec() }) };
    if !whole(*x) || !whole(*y) {
        return Err(SolveError::NotACell { which, value: value.to_vec() });
    }
    let cell = Cell::new(*x as u32, *y as u32);
    if !grid.contains(cell) {
        return Err(SolveError::Outside { which, cell, width: grid.width(), height: grid.height() });
    }
    if !grid.is_passable(cell) {
        return Err(SolveError::Blocked { which, cell });
    }
    Ok(cell)
}

/// Solves `problem`; relative file paths in it are resolved against `base_dir`.
pub fn solve(problem: &Problem, base_dir: impl AsRef<Path>) -> Result<SolveResult, SolveError> {
    let World::Grid(world) = &problem.world;
    let grid = load_grid(world, base_dir)?;
    let start = cell_of("start", &problem.start, &grid)?;
    let goal = cell_of("goal", &problem.goal, &grid)?;
    let graph = grid_graph(world, &grid);
    let natural = GridHeuristic::for_connectivity(world.connectivity);
    let mut search = Search::new();
    let found: SearchResult<Cell> = match &problem.planner {
        PlannerSpec::Bfs {} => search.bfs(&graph, start, goal)?,
        PlannerSpec::Dfs {} => search.dfs(&graph, start, goal)?,
        PlannerSpec::Dijkstra {} => search.dijkstra(&graph, start, goal)?,
        PlannerSpec::AStar { heuristic } => {
            let kind = admissible(heuristic, natural, world)?;
            search.astar(&graph, start, goal, graph.heuristic(kind, goal))?
        }
        PlannerSpec::WeightedAStar { weight, heuristic } => {
            let kind = heuristic.unwrap_or(natural);
            search.weighted_astar(&graph, start, goal, graph.heuristic(kind, goal), *weight)?
        }
        PlannerSpec::LpaStar { heuristic } => {
            let h = graph.heuristic_between(admissible(heuristic, natural, world)?);
            let mut planner = LpaStar::new(&graph, start, goal, h)?;
            let stats = planner.compute_shortest_path(&graph)?;
            SearchResult { path: planner.path(&graph), stats }
        }
        PlannerSpec::DStarLite { heuristic } => {
            let h = graph.heuristic_between(admissible(heuristic, natural, world)?);
            let mut planner = DStarLite::new(&graph, start, goal, h)?;
            let stats = planner.compute_shortest_path(&graph)?;
            SearchResult { path: planner.path(&graph), stats }
        }
        PlannerSpec::AraStar { epsilon, epsilon_step, heuristic, time_limit_s, max_expansions } => {
            let kind = admissible(heuristic, natural, world)?;
            let schedule = schedule(*epsilon, *epsilon_step);
            let budget = budget(*time_limit_s, *max_expansions)?;
            let found = trailmark_search::ara_star(
                &graph,
                start,
                goal,
                graph.heuristic(kind, goal),
                schedule,
                budget,
            )?;
            return Ok(anytime_result_of(&found));
        }
        PlannerSpec::AdStar { epsilon, epsilon_step, heuristic, time_limit_s, max_expansions } => {
            let h = graph.heuristic_between(admissible(heuristic, natural, world)?);
            let mut planner = AdStar::new(&graph, start, goal, h, schedule(*epsilon, *epsilon_step))?;
            let found = planner.improve(&graph, budget(*time_limit_s, *max_expansions)?)?;
            return Ok(anytime_result_of(&found));
        }
    };
    Ok(result_of(&found))
}

/// The heuristic asked for (or the natural one), which must be admissible.
fn admissible(
    asked: &Option<GridHeuristic>,
    natural: GridHeuristic,
    world: &GridWorld,
) -> Result<GridHeuristic, SolveError> {
    let kind = asked.unwrap_or(natural);
    if !kind.is_admissible(world.connectivity) {
        return Err(SolveError::Inadmissible { heuristic: kind });
    }
    Ok(kind)
}

fn schedule(epsilon: Option<f64>, step: Option<f64>) -> EpsilonSchedule {
    let default = EpsilonSchedule::default();
    EpsilonSchedule::new(epsilon.unwrap_or(default.initial), step.unwrap_or(default.step))
}

fn budget(time_limit_s: Option<f64>, max_expansions: Option<u64>) -> Result<Budget, SolveError> {
    let time = match time_limit_s {
        None => None,
        Some(t) if t.is_finite() && t >= 0.0 => Some(std::time::Duration::from_secs_f64(t)),
        Some(t) => return Err(SolveError::TimeLimit(t)),
    };
    Ok(Budget { time, expansions: max_expansions })
}

/// The result document of an anytime search: the path of its last iteration, every iteration.
pub fn anytime_result_of(found: &AnytimeResult<Cell>) -> SolveResult {
    let mut result = result_of(&SearchResult { path: found.path.clone(), stats: found.stats });
    result.stats.iterations = Some(
        found
            .iterations
            .iter()
            .map(|it| IterationRecord {
                epsilon: it.epsilon,
                cost: it.cost,
                bound: it.bound,
                expansions: it.expansions,
                time_s: it.elapsed.as_secs_f64(),
            })
            .collect(),
    );
    result.stats.bound = found.bound();
    result
}

/// The result document of a grid search.
pub fn result_of(found: &SearchResult<Cell>) -> SolveResult {
    let s = &found.stats;
    SolveResult {
        status: if found.path.is_some() { Status::Solved } else { Status::NoPath },
        cost: found.cost(),
        path: found.path.iter().flat_map(|p| p.nodes.iter().map(|&c| Waypoint::Cell(c))).collect(),
        stats: ResultStats {
            expansions: Some(s.expansions),
            pushes: Some(s.pushes),
            decreases: Some(s.decreases),
            reopenings: Some(s.reopenings),
            time_s: s.elapsed.as_secs_f64(),
            iterations: None,
            bound: None,
        },
    }
}
