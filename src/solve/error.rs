//! Why a problem could not be solved (as opposed to having no path).

use std::fmt::Debug;

use thiserror::Error;
use trailmark_core::curve::CurveError;
use trailmark_core::grid::{Cell, GridError, GridHeuristic};
use trailmark_core::movingai::ReadError;
use trailmark_graph::trapezoid::TrapezoidError;
use trailmark_graph::visibility::VisibilityError;
use trailmark_map::MapError;
use trailmark_sample::PrmError;
use trailmark_sample::{PlanError, SamplerError, SpaceError};
use trailmark_search::SearchError;

use super::result::Waypoint;

/// The longest `time_limit_s` a problem may give: one day. A limit is where a run stops, so
/// a document cannot ask for a run that outlives the machine.
pub const MAX_TIME_LIMIT_S: f64 = 86_400.0;

/// The most iterations a sampling planner's document may ask for: each iteration may add a
/// state to the tree, so this bounds its memory (about a gigabyte) as well as its time.
pub const MAX_ITERATIONS: u64 = 10_000_000;

/// Why a problem could not be solved (as opposed to having no path): the document is wrong
/// ([`SolveError::Document`]), a file could not be read, or a planner or graph builder refused
/// the world, the ends or its settings.
#[derive(Debug, Error)]
pub enum SolveError {
    /// The map file could not be read or parsed.
    #[error(transparent)]
    Map(#[from] ReadError),
    /// A ROS map could not be loaded, or its costmap settings are wrong.
    #[error(transparent)]
    RosMap(#[from] MapError),
    /// The grid (rows or costs) is invalid.
    #[error("invalid grid: {0}")]
    Grid(#[from] GridError),
    /// The document asks for something that cannot be: a field the planner, graph or space
    /// does not take, a value out of its range, a start or goal that is not a cell, point or
    /// state of the world.
    #[error(transparent)]
    Document(#[from] DocumentError),
    /// The search rejected the query (its nodes named as the waypoints of a result).
    #[error(transparent)]
    Search(SearchError<Waypoint>),
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
    Sampler(#[from] SamplerError),
    /// A sampling planner rejected its settings or the start or goal.
    #[error(transparent)]
    Plan(#[from] PlanError),
    /// The state space could not be made (a turning radius that is not positive).
    #[error(transparent)]
    Space(#[from] SpaceError),
    /// A path could not be smoothed.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// Hybrid A* refused its settings, the footprint or a pose.
    #[error(transparent)]
    Car(trailmark_car::CarError),
    /// A robot world's files could not be read, or its group, start or goal are not the
    /// robot's.
    #[error(transparent)]
    Robot(#[from] trailmark_robot::RobotError),
    /// A roadmap over a box world that could not draw the samples asked for: the free space is
    /// empty or very small.
    #[error("found only {added} of {requested} free samples for the roadmap")]
    SamplingExhausted {
        /// Samples asked for.
        requested: usize,
        /// Samples found.
        added: usize,
    },
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
}

/// What is wrong with a problem document itself.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DocumentError {
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
    /// A start or goal of a planner of poses (a Dubins roadmap, Hybrid A*) that is not a
    /// finite pose.
    #[error("the {which} {value:?} is not a pose: \"{planner}\" expects [x, y, heading]")]
    NotAPose {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
        /// The graph or planner: `"dubins_prm"` or `"hybrid_astar"`.
        planner: &'static str,
    },
    /// A Dubins roadmap without a turning radius.
    #[error("the \"dubins_prm\" graph needs a \"turning_radius\"")]
    NoTurningRadius,
    /// Both `k` and `radius`.
    #[error("give \"k\" (nearest neighbours) or \"radius\" (all within a distance), not both")]
    KAndRadius,
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
    /// `"space": "rn"` over a world that is not of boxes.
    #[error("\"space\": \"rn\" plans in a box world (\"world\": {{\"boxes\": ...}})")]
    RnNeedsBoxes,
    /// A box world whose dimension, region or boxes are not valid.
    #[error("the box world {0}")]
    InvalidBoxes(String),
    /// A start or goal of a sampling planner that is not a finite state of its space.
    #[error("the {which} {value:?} is not a state of the \"{space}\" space: expected {}", match *space { "dubins" | "reeds_shepp" => "[x, y, heading]", "rn" => "one finite coordinate per axis of the box world", "joints" => "one finite value per joint of the robot's group, in its order", _ => "[x, y]" })]
    NotAState {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The value given.
        value: Vec<f64>,
        /// The space.
        space: &'static str,
    },
    /// A sampling planner where a graph is searched (the planners that draw their own states
    /// do not search a roadmap).
    #[error("the \"{planner}\" planner draws its own states; it does not search a graph")]
    NotAGraphSearch {
        /// The planner.
        planner: &'static str,
    },
    /// An any-angle search on a graph without straight lines between its nodes.
    #[error(
        "the \"{planner}\" planner draws straight lines between grid cells: it plans on grid and ROS-map worlds"
    )]
    NeedsLines {
        /// The planner.
        planner: &'static str,
    },
    /// A planner made for grids themselves (jump point search) on a 4-connected grid.
    #[error("the \"{planner}\" planner searches 8-connected grid worlds (\"connectivity\": 8) only")]
    NeedsEightConnectedGrid {
        /// The planner.
        planner: &'static str,
    },
    /// A planner made for grids themselves (jump point search) on a world that is not a grid
    /// (a ROS map's costmap prices its cells; roadmaps have no rows to jump along).
    #[error(
        "the \"{planner}\" planner jumps along the rows of a grid world of uniform cost (\"world\": {{\"grid\": ...}}); it does not search ROS-map worlds, whose costmaps price cells, or roadmaps"
    )]
    NeedsGridWorld {
        /// The planner.
        planner: &'static str,
    },
    /// A start or goal in metres outside a ROS map.
    #[error("the {which} ({x}, {y}) m lies outside the map")]
    OutsideMap {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
    },
    /// A start or goal in metres where the robot cannot be (a lethal, inscribed or unknown
    /// cell of the costmap).
    #[error("the {which} ({x}, {y}) m lies in a cell of cost {cost}: the robot cannot be there")]
    BlockedPoint {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
        /// The cell's cost in the costmap (253 inscribed, 254 lethal, 255 unknown).
        cost: u8,
    },
    /// A field a ROS map sets itself.
    #[error("\"{field}\" does not apply to ROS-map worlds: the map's YAML gives it")]
    NotForRosMaps {
        /// The field.
        field: &'static str,
    },
    /// A world with both a robot radius and a footprint.
    #[error("give \"robot_radius\" or \"footprint\", not both")]
    RadiusAndFootprint,
    /// A footprint that is not a simple polygon, or has too many vertices.
    #[error("the footprint: {0}")]
    Footprint(trailmark_core::footprint::FootprintError),
    /// A graph search where a sampling planner is run.
    #[error("the \"{planner}\" planner searches a graph; it does not sample states")]
    NotASamplingPlanner {
        /// The planner.
        planner: &'static str,
    },
    /// A problem without a start or a goal (only a robot world given a `request` has none).
    #[error("the problem needs a \"{0}\"")]
    NoEnd(&'static str),
    /// A robot world given both a `request` and a start or goal.
    #[error("give \"start\" and \"goal\" or a \"request\", not both")]
    RequestAndEnds,
    /// A `request` in a world that is not a robot's.
    #[error("\"request\" applies to robot worlds only")]
    RequestNeedsRobot,
    /// A robot world without a group: neither the robot nor a request names one.
    #[error("a robot world needs its planning \"group\" (in \"robot\", or named by the \"request\")")]
    NoGroup,
    /// A robot world whose `group` is not the request's.
    #[error("the robot's \"group\" is {world:?} but the request plans for {request:?}")]
    GroupMismatch {
        /// The group the world names.
        world: String,
        /// The group the request names.
        request: String,
    },
    /// A group with more joints than the sampling planners take here.
    #[error("the group has {found} joints; robot worlds plan for groups of 1 to {max}", max = crate::solve::MAX_GROUP_JOINTS)]
    TooManyJoints {
        /// The group's joints.
        found: usize,
    },
    /// A field robot worlds do not take.
    #[error("\"{field}\" does not apply to robot worlds: they are planned in the group's joint space")]
    NotForRobots {
        /// The field.
        field: &'static str,
    },
    /// A graph search on a robot world.
    #[error("the \"{planner}\" planner searches a graph; robot worlds are planned by the sampling planners")]
    RobotNeedsSampling {
        /// The planner.
        planner: &'static str,
    },
    /// A picture asked of a world that is not drawn.
    #[error("{0} worlds cannot be drawn: pictures are of grid, polygon and ROS-map worlds")]
    Undrawable(&'static str),
}
