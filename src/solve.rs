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

// Integer casts of user-derived values are checked conversions here, not silent truncation.
#![deny(clippy::cast_possible_truncation)]

mod box_roadmap;
mod sampling;

pub use sampling::{DEFAULT_ITERATIONS, SHORTCUT_ATTEMPTS};

use std::path::Path;
use std::time::{Duration, Instant};

use thiserror::Error;

use trailmark_core::Cost;
use trailmark_core::curve::CurveError;
use trailmark_core::dubins::DubinsPath;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::grid::{Cell, Grid, GridError, GridHeuristic, is_cell_cost};
use trailmark_core::movingai::{self, ReadError};
use trailmark_core::problem::{
    GraphKind, GraphStats, GridWorld, IterationRecord, PlannerSpec, Problem, ResultStats, SamplerKind,
    SolveResult, Status, Waypoint, World,
};
use trailmark_core::svg::{GridSvg, WorldSvg};
use trailmark_core::termination::Termination;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_graph::prm::{Connection, PlanarSpace, Prm, PrmError, PrmOptions, Sampler};
use trailmark_graph::trapezoid::TrapezoidError;
use trailmark_graph::visibility::{Edges, VisibilityError};
use trailmark_graph::{CornerCutting, GridGraph, Roadmap, RoadmapQuery, Trapezoids, VisibilityGraph};
use trailmark_sample::{Dubins, PlanError, SpaceError, StateSpace};
use trailmark_search::{
    AdStar, AnytimeResult, DStarLite, EpsilonSchedule, LpaStar, Search, SearchError, SearchResult,
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
    /// A time limit that is negative, not a number, or above [`MAX_TIME_LIMIT_S`].
    #[error("\"time_limit_s\" is {0:?}; it must be a number of seconds from 0 to {max}", max = MAX_TIME_LIMIT_S)]
    TimeLimit(f64),
    /// A sampling planner's `max_iterations` above [`MAX_ITERATIONS`].
    #[error("\"max_iterations\" is {0}; a sampling planner runs at most {max} iterations", max = MAX_ITERATIONS)]
    TooManyIterations(u64),
    /// The search rejected the query.
    #[error(transparent)]
    Search(#[from] SearchError<Cell>),
    /// The search of a roadmap rejected the query.
    #[error(transparent)]
    RoadmapSearch(#[from] SearchError<u32>),
    /// A roadmap field in a grid problem.
    #[error("\"{field}\" applies to polygon worlds only")]
    NotForGrids {
        /// The field.
        field: &'static str,
    },
    /// A roadmap parameter the chosen roadmap does not take.
    #[error("\"{field}\" does not apply to the \"{graph}\" graph")]
    NotForGraph {
        /// The field.
        field: &'static str,
        /// The graph.
        graph: &'static str,
    },
    /// A heuristic other than the Euclidean distance on a roadmap.
    #[error("roadmaps are searched with the \"euclidean\" heuristic only, not {heuristic:?}")]
    NotEuclidean {
        /// The heuristic asked for.
        heuristic: GridHeuristic,
    },
    /// A start or goal of a polygon world that is not a finite point.
    #[error("the {which} {value:?} is not a point: the \"{graph}\" graph expects [x, y]")]
    NotAPoint {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
        /// The graph.
        graph: &'static str,
    },
    /// A start or goal of a Dubins roadmap that is not a finite pose.
    #[error("the {which} {value:?} is not a pose: the \"dubins_prm\" graph expects [x, y, heading]")]
    NotAPose {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
    },
    /// A Dubins roadmap without a turning radius.
    #[error("the \"dubins_prm\" graph needs a \"turning_radius\"")]
    NoTurningRadius,
    /// Both `k` and `radius`.
    #[error("give \"k\" (nearest neighbours) or \"radius\" (all within a distance), not both")]
    KAndRadius,
    /// The visibility graph rejected the start or goal.
    #[error(transparent)]
    Visibility(#[from] VisibilityError),
    /// The trapezoidal decomposition rejected the start or goal.
    #[error(transparent)]
    Trapezoid(#[from] TrapezoidError),
    /// The roadmap could not be built or rejected the start or goal.
    #[error(transparent)]
    Prm(#[from] PrmError),
    /// A sampler setting out of its range.
    #[error(transparent)]
    Sampler(#[from] trailmark_sample::SamplerError),
    /// A field the planner does not take.
    #[error("\"{field}\" does not apply to the \"{planner}\" planner")]
    NotForPlanner {
        /// The field.
        field: &'static str,
        /// The planner.
        planner: &'static str,
    },
    /// A field the sampling planner's space does not take.
    #[error("\"{field}\" does not apply to the \"{space}\" space")]
    NotForSpace {
        /// The field.
        field: &'static str,
        /// The space.
        space: &'static str,
    },
    /// A sampling planner on a grid.
    #[error("the \"{planner}\" planner plans over polygon worlds, not grids")]
    NeedsPolygons {
        /// The planner.
        planner: &'static str,
    },
    /// A roadmap over a box world that could not draw the samples asked for: the free space is
    /// empty or very small.
    #[error("found only {added} of {requested} free samples for the roadmap")]
    SamplingExhausted {
        /// Samples asked for.
        requested: usize,
        /// Samples found.
        added: usize,
    },
    /// `"space": "rn"` over a world that is not of boxes.
    #[error("\"space\": \"rn\" plans in a box world (\"world\": {{\"boxes\": ...}})")]
    RnNeedsBoxes,
    /// A box world whose dimension, region or boxes are not valid.
    #[error("the box world {0}")]
    InvalidBoxes(String),
    /// A start or goal of a sampling planner that is not a finite state of its space.
    #[error("the {which} {value:?} is not a state of the \"{space}\" space: expected {}", match *space { "dubins" => "[x, y, heading]", "rn" => "one finite coordinate per axis of the box world", _ => "[x, y]" })]
    NotAState {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
        /// The space.
        space: &'static str,
    },
    /// A sampling planner rejected its settings or the start or goal.
    #[error(transparent)]
    Plan(#[from] PlanError),
    /// The state space could not be made (a turning radius that is not positive).
    #[error(transparent)]
    Space(#[from] SpaceError),
    /// A roadmap's path failed the exact re-check that every roadmap answer passes before it
    /// is reported (a motion that collides, or a cost that is not the path's length): the
    /// world is finer than the roadmap resolves. Reported instead of a wrong path.
    #[error(
        "the \"{graph}\" roadmap's path fails the exact check at segment {segment} ({reason}); the world is finer than this roadmap resolves"
    )]
    PathRejected {
        /// The graph.
        graph: &'static str,
        /// The first segment that failed (segment `i` joins waypoints `i` and `i + 1`).
        segment: usize,
        /// What failed.
        reason: &'static str,
    },
    /// A start or goal that the exact collision test finds free, but that lies closer to an
    /// obstacle than the roadmap's free space resolves (its obstacles are grown by up to 2^-20
    /// of the bounds' larger side for the rounding of polygon operations).
    #[error(
        "the {which} ({x}, {y}) is free, but closer to an obstacle than the \"{graph}\" roadmap resolves in these bounds (about {resolution:e}); shrink the bounds or use a sampling planner"
    )]
    BelowResolution {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
        /// The graph.
        graph: &'static str,
        /// The resolution of the free space, in world units.
        resolution: f64,
    },
    /// A path could not be smoothed.
    #[error(transparent)]
    Curve(#[from] CurveError),
}

/// The longest `time_limit_s` a problem may give: one day. A limit is where a run stops, so
/// a document cannot ask for a run that outlives the machine.
pub const MAX_TIME_LIMIT_S: f64 = 86_400.0;

/// The most iterations a sampling planner's document may ask for: each iteration may add a
/// state to the tree, so this bounds its memory (about a gigabyte) as well as its time.
pub const MAX_ITERATIONS: u64 = 10_000_000;

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
        for (y, row) in (0..h).zip(costs) {
            if row.len() != w as usize {
                return Err(shape(y as usize, row.len()));
            }
            for (x, &c) in (0..w).zip(row) {
                let cell = Cell::new(x, y);
                if grid.is_passable(cell) {
                    grid.set_cost(cell, c)?;
                } else if !(c.is_finite() && is_cell_cost(c)) {
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
    #[allow(clippy::cast_possible_truncation)] // whole numbers within u32, checked above
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
    solve_inner(problem, base_dir.as_ref(), None)
}

/// Solves `problem` as [`solve`] does and draws it: an SVG of the world (the obstacles and, for
/// polygon worlds, their boundary grown by the robot radius), the roadmap that was searched,
/// and the path.
///
/// ```
/// use trailmark::problem::Problem;
/// use trailmark::solve::solve_and_draw;
///
/// let problem: Problem = serde_json::from_str(r#"{
///     "world": {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]]}},
///     "graph": "visibility", "start": [1, 1], "goal": [9, 1], "planner": {"name": "astar"}
/// }"#)?;
/// let (result, svg) = solve_and_draw(&problem, ".")?;
/// assert_eq!(result.cost, Some(2.0 * 58f64.sqrt() + 2.0)); // over the wall's top corners
/// assert!(svg.starts_with("<svg") && svg.contains("<polyline"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_and_draw(
    problem: &Problem,
    base_dir: impl AsRef<Path>,
) -> Result<(SolveResult, String), SolveError> {
    let mut picture = String::new();
    let result = solve_inner(problem, base_dir.as_ref(), Some(&mut picture))?;
    Ok((result, picture))
}

fn solve_inner(
    problem: &Problem,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let time_limit = match &problem.planner {
        PlannerSpec::AraStar { time_limit_s, .. } | PlannerSpec::AdStar { time_limit_s, .. } => *time_limit_s,
        planner => planner.sampling().and_then(|spec| spec.time_limit_s),
    };
    if let Some(t) = time_limit
        && !(0.0..=MAX_TIME_LIMIT_S).contains(&t)
    {
        return Err(SolveError::TimeLimit(t));
    }
    if let Some(n) = problem.planner.sampling().and_then(|spec| spec.max_iterations)
        && n > MAX_ITERATIONS
    {
        return Err(SolveError::TooManyIterations(n));
    }
    if problem.space.is_some() && problem.planner.sampling().is_none() {
        return Err(SolveError::NotForPlanner { field: "space", planner: problem.planner.name() });
    }
    match (&problem.world, problem.planner.sampling()) {
        (World::Grid(_), Some(_)) => Err(SolveError::NeedsPolygons { planner: problem.planner.name() }),
        (World::Grid(world), None) => solve_grid(problem, world, base_dir, picture),
        (World::Polygons(world), Some(spec)) => sampling::solve_sampling(problem, world, spec, picture),
        (World::Polygons(world), None) => solve_polygons(problem, world, picture),
        (World::Boxes(_), Some(_)) if picture.is_some() => {
            Err(SolveError::InvalidBoxes("cannot be drawn: pictures are of grid and polygon worlds".into()))
        }
        (World::Boxes(world), Some(spec)) => sampling::solve_boxes(problem, world, spec),
        (World::Boxes(_), None) if picture.is_some() => {
            Err(SolveError::InvalidBoxes("cannot be drawn: pictures are of grid and polygon worlds".into()))
        }
        (World::Boxes(world), None) => box_roadmap::solve_box_roadmap(problem, world),
    }
}

fn solve_grid(
    problem: &Problem,
    world: &GridWorld,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = roadmap_fields(problem).first() {
        return Err(SolveError::NotForGrids { field: name });
    }
    let grid = load_grid(world, base_dir)?;
    let start = cell_of("start", &problem.start, &grid)?;
    let goal = cell_of("goal", &problem.goal, &grid)?;
    let graph = grid_graph(world, &grid);
    let natural = GridHeuristic::for_connectivity(world.connectivity);
    let (asked, optimal) = heuristic_of(&problem.planner);
    let kind = asked.unwrap_or(natural);
    if optimal && !kind.is_admissible(world.connectivity) {
        return Err(SolveError::Inadmissible { heuristic: kind });
    }
    let h = graph.heuristic_between(kind);
    let result = search(&graph, start, goal, h, &problem.planner, Waypoint::Cell)?;
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

/// The roadmap fields a problem sets, by name.
fn roadmap_fields(problem: &Problem) -> Vec<&'static str> {
    [
        ("graph", problem.graph.is_some()),
        ("samples", problem.samples.is_some()),
        ("k", problem.k.is_some()),
        ("radius", problem.radius.is_some()),
        ("turning_radius", problem.turning_radius.is_some()),
        ("sampler", problem.sampler.is_some()),
    ]
    .into_iter()
    .filter_map(|(name, set)| set.then_some(name))
    .collect()
}

/// The heuristic a planner asks for, and whether the planner promises least cost (so the
/// heuristic must be admissible).
fn heuristic_of(planner: &PlannerSpec) -> (Option<GridHeuristic>, bool) {
    match planner {
        PlannerSpec::Bfs {} | PlannerSpec::Dfs {} | PlannerSpec::Dijkstra {} => (None, true),
        PlannerSpec::Rrt(_) | PlannerSpec::RrtConnect(_) | PlannerSpec::RrtStar(_) => (None, false),
        PlannerSpec::WeightedAStar { heuristic, .. } => (*heuristic, false),
        PlannerSpec::AStar { heuristic }
        | PlannerSpec::LpaStar { heuristic }
        | PlannerSpec::DStarLite { heuristic }
        | PlannerSpec::AraStar { heuristic, .. }
        | PlannerSpec::AdStar { heuristic, .. } => (*heuristic, true),
    }
}

/// Runs `planner` from `start` to `goal` on `graph` with the heuristic `h(a, b)`, and writes
/// each path node as `waypoint(node)`.
fn search<G, H>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
    h: H,
    planner: &PlannerSpec,
    waypoint: impl Fn(G::Node) -> Waypoint,
) -> Result<SolveResult, SearchError<G::Node>>
where
    G: Successors + Predecessors + IndexedGraph,
    H: Fn(G::Node, G::Node) -> Cost + Copy,
{
    let to_goal = |n| h(n, goal);
    let mut search = Search::new();
    let found = match planner {
        PlannerSpec::Bfs {} => search.bfs(graph, start, goal)?,
        PlannerSpec::Dfs {} => search.dfs(graph, start, goal)?,
        PlannerSpec::Dijkstra {} => search.dijkstra(graph, start, goal)?,
        PlannerSpec::AStar { .. } => search.astar(graph, start, goal, to_goal)?,
        PlannerSpec::WeightedAStar { weight, .. } => {
            search.weighted_astar(graph, start, goal, to_goal, *weight)?
        }
        PlannerSpec::LpaStar { .. } => {
            let mut planner = LpaStar::new(graph, start, goal, h)?;
            let stats = planner.compute_shortest_path(graph)?;
            SearchResult { path: planner.path(graph), stats }
        }
        PlannerSpec::DStarLite { .. } => {
            let mut planner = DStarLite::new(graph, start, goal, h)?;
            let stats = planner.compute_shortest_path(graph)?;
            SearchResult { path: planner.path(graph), stats }
        }
        PlannerSpec::AraStar { epsilon, epsilon_step, time_limit_s, max_expansions, .. } => {
            let budget = budget(*time_limit_s, *max_expansions);
            let found = trailmark_search::ara_star(
                graph,
                start,
                goal,
                to_goal,
                schedule(*epsilon, *epsilon_step),
                budget,
            )?;
            return Ok(anytime_result_of(&found, waypoint));
        }
        PlannerSpec::AdStar { epsilon, epsilon_step, time_limit_s, max_expansions, .. } => {
            let mut planner = AdStar::new(graph, start, goal, h, schedule(*epsilon, *epsilon_step))?;
            let found = planner.improve(graph, budget(*time_limit_s, *max_expansions))?;
            return Ok(anytime_result_of(&found, waypoint));
        }
        PlannerSpec::Rrt(_) | PlannerSpec::RrtConnect(_) | PlannerSpec::RrtStar(_) => {
            unreachable!("solve_inner sends sampling planners to sampling::solve_sampling")
        }
    };
    Ok(result_of(&found, waypoint))
}

/// Builds the roadmap a polygon-world problem names, joins its start and goal, and searches it;
/// draws the world, the roadmap and the path into `picture` when one is given.
fn solve_polygons(
    problem: &Problem,
    world: &PolygonWorld,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let kind = problem.graph.unwrap_or(GraphKind::Visibility);
    let sampled = matches!(kind, GraphKind::Prm | GraphKind::DubinsPrm);
    for field in roadmap_fields(problem) {
        let applies = match field {
            "graph" => true,
            "turning_radius" => kind == GraphKind::DubinsPrm,
            _ => sampled,
        };
        if !applies {
            return Err(SolveError::NotForGraph { field, graph: kind.name() });
        }
    }
    let (asked, _) = heuristic_of(&problem.planner);
    if let Some(heuristic) = asked.filter(|&h| h != GridHeuristic::Euclidean) {
        return Err(SolveError::NotEuclidean { heuristic });
    }
    if kind == GraphKind::DubinsPrm {
        return solve_dubins(problem, world, picture);
    }
    let point = |which, value: &[f64]| match *value {
        [x, y] if x.is_finite() && y.is_finite() => Ok(Point::new(x, y)),
        _ => Err(SolveError::NotAPoint { which, value: value.to_vec(), graph: kind.name() }),
    };
    let (start, goal) = (point("start", &problem.start)?, point("goal", &problem.goal)?);
    let checker = world.checker();
    // The free space of the exact roadmaps is conservative by its resolution: a free end
    // refused there is below that resolution, not blocked.
    let refused = |which, at: Point, blocked: SolveError| {
        if checker.point_is_free(at) {
            let (x, y, resolution) = (at.x, at.y, world.resolution());
            SolveError::BelowResolution { which, x, y, graph: kind.name(), resolution }
        } else {
            blocked
        }
    };
    let clock = Instant::now();
    let (result, svg) = match kind {
        GraphKind::Visibility => {
            let graph = VisibilityGraph::with_edges(world.free_space(), Edges::Tangent);
            let built = clock.elapsed();
            let query = graph.query(start, goal).map_err(|e| match e {
                VisibilityError::StartBlocked { .. } => refused("start", start, e.into()),
                VisibilityError::GoalBlocked { .. } => refused("goal", goal, e.into()),
            })?;
            let result = search_roadmap(problem, &query, built, clock.elapsed().saturating_sub(built))?;
            let svg = WorldSvg::new(world).free_space(graph.space()).edges(graph.edge_ends());
            (result, svg.title("Visibility graph (tangent edges) and the shortest path"))
        }
        GraphKind::Trapezoid => {
            let space = world.free_space();
            let graph = Trapezoids::new(&space);
            let built = clock.elapsed();
            let query = graph.query(start, goal).map_err(|e| match e {
                TrapezoidError::StartBlocked { .. } => refused("start", start, e.into()),
                TrapezoidError::GoalBlocked { .. } => refused("goal", goal, e.into()),
            })?;
            let result = search_roadmap(problem, &query, built, clock.elapsed().saturating_sub(built))?;
            let cells = (0..graph.cell_count()).map(|c| graph.cell(c).corners().to_vec());
            let svg = WorldSvg::new(world).free_space(&space).cells(cells).edges(graph.edge_ends());
            (result, svg.title("Trapezoidal cells, their centroids and portal midpoints, and a path"))
        }
        _ => {
            let prm = grow(problem, Prm::new(world.clone(), prm_options(problem)?)?)?;
            let built = clock.elapsed();
            let result = search_roadmap(
                problem,
                &prm.query(start, goal)?,
                built,
                clock.elapsed().saturating_sub(built),
            )?;
            let nodes = (0u32..).take(prm.node_count()).map(|u| prm.position(u));
            let space = world.free_space();
            let svg = WorldSvg::new(world).free_space(&space).edges(prm.edge_ends()).nodes(nodes);
            let title = format!("PRM: {} samples, {} edges, and a path", prm.node_count(), prm.edge_count());
            (result, svg.title(title))
        }
    };
    let path: Vec<Point> = result.path.iter().filter_map(waypoint_point).collect();
    if let Some(cost) = result.cost {
        let rejected = |segment, reason| SolveError::PathRejected { graph: kind.name(), segment, reason };
        if let Some(segment) = checker.first_blocked_segment(&path) {
            return Err(rejected(segment, "the robot collides"));
        }
        let length: f64 = path.windows(2).map(|p| (p[1] - p[0]).norm()).sum();
        if !same_length(cost, length) {
            return Err(rejected(0, "the cost is not the path's length"));
        }
    }
    if let Some(picture) = picture {
        *picture = svg.path(&path).start(start).goal(goal).to_svg();
    }
    Ok(result)
}

/// Whether a reported path cost and the length measured along the path agree, up to the
/// rounding of summing the edges in another order.
fn same_length(cost: f64, length: f64) -> bool {
    (cost - length).abs() <= 1e-9 * cost.abs().max(length.abs()).max(f64::MIN_POSITIVE)
}

/// [`solve_polygons`] on a Dubins roadmap: poses, directed Dubins edges.
fn solve_dubins(
    problem: &Problem,
    world: &PolygonWorld,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let radius = problem.turning_radius.ok_or(SolveError::NoTurningRadius)?;
    let space = Dubins::new(world.bounds(), radius)?;
    let pose = |which, value: &[f64]| {
        space
            .state_from_coordinates(value)
            .ok_or_else(|| SolveError::NotAPose { which, value: value.to_vec() })
    };
    let (start, goal) = (pose("start", &problem.start)?, pose("goal", &problem.goal)?);
    let clock = Instant::now();
    let prm = grow(problem, Prm::with_space(world.clone(), space, prm_options(problem)?)?)?;
    let built = clock.elapsed();
    let result =
        search_roadmap(problem, &prm.query(start, goal)?, built, clock.elapsed().saturating_sub(built))?;
    let poses: Vec<Pose> = states_of(&space, &result);
    if let Some(cost) = result.cost {
        check_dubins(&world.checker(), &poses, radius, cost)?;
    }
    if let Some(picture) = picture {
        let curve = dubins_curve(&poses, radius);
        let title =
            format!("Dubins roadmap: {} poses, turning radius {radius}, and a path", prm.node_count());
        *picture = WorldSvg::new(world)
            .free_space(&world.free_space())
            .poses((0u32..).take(prm.node_count()).map(|u| prm.position(u)))
            .path(&curve)
            .start(Point::from(start.translation.vector))
            .goal(Point::from(goal.translation.vector))
            .title(title)
            .to_svg();
    }
    Ok(result)
}

/// The exact re-check of a Dubins roadmap's path: each shortest Dubins curve between
/// consecutive poses collision-free, and their lengths adding up to `cost`.
fn check_dubins(
    checker: &CollisionChecker,
    poses: &[Pose],
    radius: f64,
    cost: f64,
) -> Result<(), SolveError> {
    let rejected =
        |segment, reason| SolveError::PathRejected { graph: GraphKind::DubinsPrm.name(), segment, reason };
    if let [pose] = poses
        && !checker.point_is_free(Point::from(pose.translation.vector))
    {
        return Err(rejected(0, "the robot collides"));
    }
    let mut length = 0.0;
    for (segment, pair) in poses.windows(2).enumerate() {
        let piece = DubinsPath::shortest(&pair[0], &pair[1], radius)
            .map_err(|_| rejected(segment, "no Dubins curve joins the poses"))?;
        if !checker.dubins_is_free(&piece) {
            return Err(rejected(segment, "the robot collides"));
        }
        length += piece.length();
    }
    if !same_length(cost, length) {
        return Err(rejected(0, "the cost is not the path's length"));
    }
    Ok(())
}

/// The positions along the shortest Dubins curves joining `poses` (a positive, finite turning
/// `radius`), every `radius / 8`.
fn dubins_curve(poses: &[Pose], radius: f64) -> Vec<Point> {
    let mut curve = Vec::new();
    for pair in poses.windows(2) {
        let Ok(piece) = DubinsPath::shortest(&pair[0], &pair[1], radius) else { continue };
        // Every radius / 8, but no more than 10,000 points a piece for a picture.
        let samples = piece.sample((radius / 8.0).max(piece.length() / 1e4)).unwrap_or_default();
        curve.extend(samples.iter().map(|p| Point::from(p.translation.vector)));
    }
    curve
}

/// The states of a result's path in `space` (its waypoints' coordinates).
fn states_of<S: StateSpace>(space: &S, result: &SolveResult) -> Vec<S::State> {
    let state = |w: &Waypoint| match w {
        Waypoint::Point(c) => space.state_from_coordinates(c),
        Waypoint::Cell(_) => None,
    };
    result.path.iter().filter_map(state).collect()
}

/// The point of a waypoint (the position of a pose).
fn waypoint_point(waypoint: &Waypoint) -> Option<Point> {
    match waypoint {
        Waypoint::Point(c) if c.len() >= 2 => Some(Point::new(c[0], c[1])),
        _ => None,
    }
}

/// The PRM options of a problem.
fn prm_options(problem: &Problem) -> Result<PrmOptions, SolveError> {
    let sampler = match problem.sampler.unwrap_or(SamplerKind::Uniform) {
        SamplerKind::Uniform => Sampler::Uniform { seed: problem.seed.unwrap_or(0) },
        SamplerKind::Halton => Sampler::Halton,
    };
    let connection = match (problem.k, problem.radius) {
        (Some(_), Some(_)) => return Err(SolveError::KAndRadius),
        (Some(k), None) => Connection::Nearest { k },
        (None, Some(radius)) => Connection::Radius { radius },
        (None, None) => Connection::PrmStar,
    };
    Ok(PrmOptions { sampler, connection, ..PrmOptions::default() })
}

/// `prm` grown by the problem's number of samples.
fn grow<S: PlanarSpace>(problem: &Problem, mut prm: Prm<S>) -> Result<Prm<S>, SolveError> {
    prm.grow(problem.samples.unwrap_or(DEFAULT_SAMPLES))?;
    Ok(prm)
}

/// The number of samples of a sampled roadmap when the problem gives none.
pub const DEFAULT_SAMPLES: usize = 1000;

/// Searches a roadmap query and reports the roadmap's size and timings with the result.
fn search_roadmap<R>(
    problem: &Problem,
    query: &RoadmapQuery<'_, R>,
    built: Duration,
    joined: Duration,
) -> Result<SolveResult, SolveError>
where
    R: Roadmap,
    R::Position: Coordinates,
{
    let waypoint = |node| Waypoint::Point(query.position(node).coordinates());
    let mut result =
        search(query, query.start(), query.goal(), query.heuristic_between(), &problem.planner, waypoint)?;
    // A sampled roadmap without a path proves nothing: more samples may find one.
    let sampled = matches!(problem.graph, Some(GraphKind::Prm | GraphKind::DubinsPrm));
    if sampled && result.status == Status::NoPath {
        result.status = Status::Stopped;
    }
    let roadmap = query.roadmap();
    result.stats.graph = Some(GraphStats {
        nodes: roadmap.node_count(),
        edges: roadmap.count_edges(),
        build_time_s: built.as_secs_f64(),
        query_time_s: joined.as_secs_f64(),
    });
    Ok(result)
}

/// A roadmap position as the numbers of a result waypoint.
trait Coordinates {
    fn coordinates(&self) -> Vec<f64>;
}

impl Coordinates for Point {
    fn coordinates(&self) -> Vec<f64> {
        vec![self.x, self.y]
    }
}

impl Coordinates for Pose {
    fn coordinates(&self) -> Vec<f64> {
        vec![self.translation.x, self.translation.y, self.rotation.angle()]
    }
}

impl<const N: usize> Coordinates for trailmark_core::geometry::SVector<f64, N> {
    fn coordinates(&self) -> Vec<f64> {
        self.iter().copied().collect()
    }
}

fn schedule(epsilon: Option<f64>, step: Option<f64>) -> EpsilonSchedule {
    let default = EpsilonSchedule::default();
    EpsilonSchedule::new(epsilon.unwrap_or(default.initial), step.unwrap_or(default.step))
}

fn budget(time_limit_s: Option<f64>, max_expansions: Option<u64>) -> Termination {
    // Checked by solve_inner: a limit too large for a Duration has been refused already.
    let time = time_limit_s.and_then(|t| Duration::try_from_secs_f64(t).ok());
    Termination { time_limit: time, max_expansions, ..Termination::default() }
}

/// The result document of an anytime search: the path of its last iteration, every iteration;
/// each path node written as `waypoint(node)`. Without a path the status is
/// [`Status::NoPath`] only when the search proved the goal unreachable
/// ([`Stop::Unreachable`](trailmark_core::termination::Stop::Unreachable)); stopped by a limit first, it is
/// [`Status::Stopped`].
pub fn anytime_result_of<N: Copy>(found: &AnytimeResult<N>, waypoint: impl Fn(N) -> Waypoint) -> SolveResult {
    let mut result = result_of(&SearchResult { path: found.path.clone(), stats: found.stats }, waypoint);
    if found.path.is_none() && !found.proved_unreachable() {
        result.status = Status::Stopped;
    }
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

/// The result document of a search, each path node written as `waypoint(node)`
/// ([`Waypoint::Cell`] for a grid search). The searches of [`SearchResult`] run to their end
/// (they take no limit), so a result without a path is [`Status::NoPath`]: proved unreachable.
pub fn result_of<N: Copy>(found: &SearchResult<N>, waypoint: impl Fn(N) -> Waypoint) -> SolveResult {
    let s = &found.stats;
    SolveResult {
        status: if found.path.is_some() { Status::Solved } else { Status::NoPath },
        cost: found.cost(),
        path: found.path.iter().flat_map(|p| p.nodes.iter().map(|&n| waypoint(n))).collect(),
        stats: ResultStats {
            expansions: Some(s.expansions),
            pushes: Some(s.pushes),
            decreases: Some(s.decreases),
            reopenings: Some(s.reopenings),
            time_s: s.elapsed.as_secs_f64(),
            ..ResultStats::default()
        },
    }
}
