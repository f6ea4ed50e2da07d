//! Solving a problem document: read a [`ProblemSpec`], build the world's graph, run the named
//! planner, report a [`SolveResult`].
//!
//! This is the engine of `cargo xtask solve`, usable from Rust as well. The document's schema
//! is here too ([`ProblemSpec`], [`PlannerSpec`], [`WorldSpec`] and the result types), and so
//! is the registry of the planners it runs ([`PlannerSpec`]).
//!
//! ```
//! use trailmark::solve::{ProblemSpec, Status, solve};
//!
//! let problem: ProblemSpec = serde_json::from_str(r#"{
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

mod car;
mod curves;
mod error;
mod planner;
mod problem;
mod registry;
mod replan;
mod result;
mod sampling;
mod search;
mod settings;
mod stop;
mod world;

pub use error::{DocumentError, MAX_ITERATIONS, MAX_TIME_LIMIT_S, SolveError};
pub use planner::PlannerSpec;
pub use problem::{
    ArmCheckerKind, BoxesSpec, GraphKind, GridSpec, ProblemSpec, RobotSpec, RobotWorldSpec, RosMapSpec,
    SamplerKind, SpaceKind, WorldSpec,
};
pub use registry::{Family, PlannerName};
pub use result::{
    CarRecord, ErrorReport, GraphStats, ImprovementRecord, IterationRecord, ResultStats, SamplingStats,
    SmoothedRecord, SolveResult, Status, Waypoint, anytime_result_of, result_of,
};
pub use sampling::boxes::solve_boxes_with;
pub use sampling::robot::SMOOTHING_PASSES;
pub use sampling::{DEFAULT_ITERATIONS, SHORTCUT_ATTEMPTS};
pub use search::grid::{PreparedGrid, search_grid};
pub use search::roadmap::DEFAULT_SAMPLES;
pub use settings::{AnytimeSpec, HybridSpec, SamplerSpec, SamplingSpec};
pub use world::boxes::MAX_BOX_DIMENSION;
pub use world::grid::{check_grid_end, grid_graph, load_grid};
pub use world::robot::{MAX_GROUP_JOINTS, RobotWorld};
pub use world::ros_map::{
    DEFAULT_COST_FACTOR, DEFAULT_COST_SCALING_FACTOR, DEFAULT_INFLATION_RADIUS, DEFAULT_ROBOT_RADIUS,
    MAX_COST_FACTOR, RosMapWorld, ros_costmap, ros_travel_cost,
};

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// Solves `problem`; relative file paths in it are resolved against `base_dir`.
pub fn solve(problem: &ProblemSpec, base_dir: impl AsRef<Path>) -> Result<SolveResult, SolveError> {
    solve_inner(problem, base_dir.as_ref(), None)
}

/// Solves `problem` as [`solve`] does, its planner stopped (its result then
/// `"stopped"`, or the best it has) once `stop` is set, from any thread.
///
/// ```
/// use std::sync::Arc;
/// use std::sync::atomic::AtomicBool;
/// use trailmark::solve::{ProblemSpec, Status, solve_until};
///
/// let problem: ProblemSpec = serde_json::from_str(r#"{
///     "world": {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]]}},
///     "start": [1, 1], "goal": [9, 1], "planner": {"name": "rrt_star", "time_limit_s": 60}
/// }"#)?;
/// let stop = Arc::new(AtomicBool::new(true)); // set before it starts: the planner stops at once
/// let result = solve_until(&problem, ".", stop)?;
/// assert!(result.stats.time_s < 1.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_until(
    problem: &ProblemSpec,
    base_dir: impl AsRef<Path>,
    stop: Arc<AtomicBool>,
) -> Result<SolveResult, SolveError> {
    stop::with_flag(stop, || solve(problem, base_dir))
}

/// Solves `problem` as [`solve`] does and draws it: an SVG of the world (the obstacles and, for
/// polygon worlds, their boundary grown by the robot radius), the roadmap that was searched,
/// and the path.
///
/// ```
/// use trailmark::solve::{ProblemSpec, solve_and_draw};
///
/// let problem: ProblemSpec = serde_json::from_str(r#"{
///     "world": {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]]}},
///     "graph": "visibility", "start": [1, 1], "goal": [9, 1], "planner": {"name": "astar"}
/// }"#)?;
/// let (result, svg) = solve_and_draw(&problem, ".")?;
/// assert_eq!(result.cost, Some(2.0 * 58f64.sqrt() + 2.0)); // over the wall's top corners
/// assert!(svg.starts_with("<svg") && svg.contains("<polyline"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_and_draw(
    problem: &ProblemSpec,
    base_dir: impl AsRef<Path>,
) -> Result<(SolveResult, String), SolveError> {
    let mut picture = String::new();
    let result = solve_inner(problem, base_dir.as_ref(), Some(&mut picture))?;
    Ok((result, picture))
}

fn solve_inner(
    problem: &ProblemSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let planner = &problem.planner;
    planner.check_limits()?;
    if problem.space.is_some() && planner.sampling().is_none() {
        return Err(DocumentError::NotForPlanner { field: "space", planner: planner.name() }.into());
    }
    if problem.request.is_some() && !matches!(problem.world, WorldSpec::Robot(_)) {
        return Err(DocumentError::RequestNeedsRobot.into());
    }
    if problem.request.is_none() {
        for (which, end) in [("start", &problem.start), ("goal", &problem.goal)] {
            if end.is_empty() {
                return Err(DocumentError::NoEnd(which).into());
            }
        }
    }
    if let PlannerSpec::HybridAStar(spec) = planner {
        return car::solve_hybrid_astar(problem, &problem.world, spec, base_dir, picture);
    }
    match (&problem.world, planner.sampling()) {
        (WorldSpec::Grid(_), Some(_)) => Err(DocumentError::NeedsPolygons { planner: planner.name() }.into()),
        (WorldSpec::Grid(world), None) => search::grid::solve_grid(problem, world, base_dir, picture),
        (WorldSpec::Polygons(world), Some(spec)) => sampling::solve_sampling(problem, world, spec, picture),
        (WorldSpec::Polygons(world), None) => search::polygons::solve_polygons(problem, world, picture),
        (WorldSpec::Boxes(_), _) if picture.is_some() => Err(DocumentError::Undrawable("box").into()),
        (WorldSpec::Boxes(world), Some(spec)) => sampling::boxes::solve_boxes(problem, world, spec),
        (WorldSpec::Boxes(world), None) => search::boxes::solve_box_roadmap(problem, world),
        (WorldSpec::RosMap(_), Some(_)) => {
            Err(DocumentError::NeedsPolygons { planner: planner.name() }.into())
        }
        (WorldSpec::RosMap(world), None) => search::ros_map::solve_ros_map(problem, world, base_dir, picture),
        (WorldSpec::Robot(_), _) if picture.is_some() => Err(DocumentError::Undrawable("robot").into()),
        (WorldSpec::Robot(world), Some(spec)) => sampling::robot::solve_robot(problem, world, spec, base_dir),
        (WorldSpec::Robot(_), None) => {
            Err(DocumentError::RobotNeedsSampling { planner: planner.name() }.into())
        }
    }
}
