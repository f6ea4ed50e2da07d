//! The problem and result documents of `cargo xtask solve`, as serde types.
//!
//! A problem names a world, a start, a goal and a planner; a result gives the status, the cost,
//! the path and statistics. Later planners extend these types with new variants and optional
//! fields; existing documents keep their meaning.
//!
//! ```
//! use trailmark_core::problem::{PlannerSpec, Problem, World};
//!
//! let json = r#"{
//!     "world": {"grid": {"rows": ["....", ".@@.", "...."], "connectivity": 8}},
//!     "start": [0, 0], "goal": [3, 2],
//!     "planner": {"name": "weighted_astar", "weight": 1.5}
//! }"#;
//! let problem: Problem = serde_json::from_str(json).unwrap();
//! assert_eq!(problem.planner, PlannerSpec::WeightedAStar { weight: 1.5, heuristic: None });
//! let World::Grid(grid) = &problem.world else { unreachable!() };
//! assert_eq!(grid.rows.as_ref().unwrap().len(), 3);
//! ```
//!
//! A polygon world is searched on a roadmap, named by `"graph"` with its parameters beside it:
//!
//! ```
//! use trailmark_core::problem::{GraphKind, Problem, World};
//!
//! let json = r#"{
//!     "world": {"polygons": {"bounds": [0, 0, 10, 10],
//!                            "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]],
//!                            "robot_radius": 0.25}},
//!     "graph": "prm", "samples": 500, "k": 12,
//!     "start": [1, 1], "goal": [9, 1],
//!     "planner": {"name": "astar"}
//! }"#;
//! let problem: Problem = serde_json::from_str(json).unwrap();
//! assert_eq!(problem.graph, Some(GraphKind::Prm));
//! assert_eq!((problem.samples, problem.k), (Some(500), Some(12)));
//! let World::Polygons(world) = &problem.world else { unreachable!() };
//! assert_eq!(world.obstacles().len(), 1);
//! ```

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::grid::{Cell, Connectivity, GridHeuristic};
use crate::smooth::Smoothing;
use crate::world::PolygonWorld;

/// A planning problem: a world, a start, a goal, a planner and a seed; for a polygon world,
/// also the roadmap to search and its parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Problem {
    /// The world to plan in.
    pub world: World,
    /// The start: a cell `[x, y]` of a grid, a point `[x, y]` of a polygon world, or a pose
    /// `[x, y, θ]` (θ in radians) for a Dubins roadmap.
    pub start: Vec<f64>,
    /// The goal, as the start.
    pub goal: Vec<f64>,
    /// The planner and its parameters.
    pub planner: PlannerSpec,
    /// The seed of every random choice (planners and graphs that draw none ignore it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Polygon worlds: the roadmap to build (default: the visibility graph).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub graph: Option<GraphKind>,
    /// Sampled roadmaps: the number of samples (default 1000).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    /// Sampled roadmaps: join each sample to its `k` nearest neighbours (default, without `k`
    /// or `radius`: PRM*'s k = ⌈e(1 + 1/d) ln n⌉).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub k: Option<usize>,
    /// Sampled roadmaps: join each sample to every neighbour within this distance instead.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Dubins roadmaps: the turning radius (required).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub turning_radius: Option<f64>,
    /// Sampled roadmaps: how samples are drawn (default uniform, from `seed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<SamplerKind>,
    /// Sampling planners: the state space (default `r2`; `dubins` needs `turning_radius`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub space: Option<SpaceKind>,
}

impl Problem {
    /// A problem with no seed and no roadmap parameters.
    pub fn new(world: World, start: Vec<f64>, goal: Vec<f64>, planner: PlannerSpec) -> Self {
        Problem {
            world,
            start,
            goal,
            planner,
            seed: None,
            graph: None,
            samples: None,
            k: None,
            radius: None,
            turning_radius: None,
            sampler: None,
            space: None,
        }
    }
}

/// The roadmap a polygon world is searched on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GraphKind {
    /// The visibility graph of the grown obstacles: shortest paths for a disc robot.
    Visibility,
    /// The trapezoidal (vertical) cell decomposition: cell centroids and portal midpoints.
    Trapezoid,
    /// A probabilistic roadmap of straight segments.
    Prm,
    /// A probabilistic roadmap of poses joined by Dubins curves (a car that turns no tighter
    /// than `turning_radius`).
    DubinsPrm,
}

impl GraphKind {
    /// The name used in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            GraphKind::Visibility => "visibility",
            GraphKind::Trapezoid => "trapezoid",
            GraphKind::Prm => "prm",
            GraphKind::DubinsPrm => "dubins_prm",
        }
    }
}

/// How a sampled roadmap draws its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SamplerKind {
    /// Uniform random samples from the problem's seed (default 0).
    Uniform,
    /// The deterministic Halton sequence (bases 2, 3 and 5).
    Halton,
}

/// The state space of a sampling planner: over a polygon world, `r2` or `dubins`; over a box
/// world, `rn`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpaceKind {
    /// Points `[x, y]` joined by straight motions.
    R2,
    /// Poses `[x, y, θ]` of a car joined by shortest Dubins curves of the problem's
    /// `turning_radius`.
    Dubins,
    /// Points of a box world's dimension, joined by straight motions.
    Rn,
}

impl SpaceKind {
    /// The name used in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            SpaceKind::R2 => "r2",
            SpaceKind::Dubins => "dubins",
            SpaceKind::Rn => "rn",
        }
    }
}

/// The settings of a sampling planner (RRT, RRT-Connect, RRT*). Each has a default.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SamplingSpec {
    /// The longest motion added at once (default 0.2 x the space's extent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<f64>,
    /// RRT and RRT*: the probability of steering toward the goal (default 0.05).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_bias: Option<f64>,
    /// Stop after this many iterations (default 10,000 unless `time_limit_s` is given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<u64>,
    /// Stop after this many seconds (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_limit_s: Option<f64>,
    /// Shortcut the path afterwards (default false).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simplify: Option<bool>,
    /// `r2` only: smooth the (simplified) path with `hermite`, `bezier` or `bspline` curves,
    /// reported beside it (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smooth: Option<Smoothing>,
    /// Where samples are drawn (default: uniformly).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<SamplerSpec>,
}

/// Where a sampling planner draws the states it steers toward. In JSON, an object whose
/// `"name"` selects the sampler; the two that look for obstacles take `"std_dev"` (required:
/// the distance between the two states tested, about the width of the passages sought),
/// `"share"` (default 0.5) and `"attempts"` (default 100).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", rename_all = "snake_case", deny_unknown_fields)]
pub enum SamplerSpec {
    /// Uniformly over the space. (A struct variant, so that unknown fields beside its name
    /// are refused as for the others.)
    Uniform {},
    /// The bridge test: free midpoints of two nearby states in collision (narrow passages).
    Bridge {
        /// The partner's standard deviation.
        std_dev: f64,
        /// The probability of a bridge sample rather than a uniform one.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        share: Option<f64>,
        /// Tries before a uniform sample.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        attempts: Option<u32>,
    },
    /// Free states beside states in collision (near obstacles' surfaces).
    Gaussian {
        /// The partner's standard deviation.
        std_dev: f64,
        /// The probability of such a sample rather than a uniform one.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        share: Option<f64>,
        /// Tries before a uniform sample.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        attempts: Option<u32>,
    },
}

impl Default for SamplerSpec {
    fn default() -> Self {
        SamplerSpec::Uniform {}
    }
}

/// The world of a problem. In JSON, an object with one key naming the kind of world.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum World {
    /// A grid: `{"grid": {...}}`.
    Grid(GridWorld),
    /// Polygonal obstacles for a disc robot: `{"polygons": {"bounds": [xmin, ymin, xmax, ymax],
    /// "obstacles": [[[x, y], ...], ...], "robot_radius": r}}`, checked as it is read.
    Polygons(PolygonWorld),
    /// Axis-aligned boxes in any dimension, for the sampling planners in `"space": "rn"`:
    /// `{"boxes": {"bounds": [[lo, hi], ...], "obstacles": [[[lo, ...], [hi, ...]], ...]}}`.
    Boxes(BoxesWorld),
}

/// A world of axis-aligned boxes: the region, one `[lo, hi]` per axis, and the obstacles, each
/// its low and high corners. The dimensions and sides are checked when it is solved.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxesWorld {
    /// `[lo, hi]` per axis.
    pub bounds: Vec<[f64; 2]>,
    /// `[[lo, ...], [hi, ...]]` per box.
    #[serde(default)]
    pub obstacles: Vec<[Vec<f64>; 2]>,
}

/// A grid world: a MovingAI map file or inline rows, with its connectivity and optional costs.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridWorld {
    /// A MovingAI `.map` file (relative paths are relative to the problem file). Exactly one of
    /// `map` and `rows` is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map: Option<PathBuf>,
    /// The rows of the grid in MovingAI characters (`.` passable, `@` blocked, ...).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rows: Option<Vec<String>>,
    /// Optional per-cell costs, one row of numbers per grid row, each positive; a blocked cell
    /// stays blocked whatever its cost.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub costs: Option<Vec<Vec<f64>>>,
    /// 4 or 8 (default 8).
    #[serde(default)]
    pub connectivity: Connectivity,
    /// Whether a diagonal move may pass a blocked orthogonal neighbour (default false, the
    /// MovingAI rule).
    #[serde(default)]
    pub corner_cutting: bool,
}

/// A planner and its parameters. In JSON, an object whose `"name"` selects the planner.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", deny_unknown_fields)]
pub enum PlannerSpec {
    /// Breadth-first search: fewest moves, whatever their costs.
    #[serde(rename = "bfs")]
    Bfs {},
    /// Depth-first search: some path, quickly found, not short.
    #[serde(rename = "dfs")]
    Dfs {},
    /// Dijkstra's algorithm: least cost.
    #[serde(rename = "dijkstra")]
    Dijkstra {},
    /// A*: least cost, guided by an admissible heuristic.
    #[serde(rename = "astar")]
    AStar {
        /// The heuristic (default: octile for 8-connected grids, Manhattan for 4-connected).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// Weighted A*: A* with the heuristic inflated by `weight >= 1`; cost at most `weight` times
    /// the least cost.
    #[serde(rename = "weighted_astar")]
    WeightedAStar {
        /// The inflation factor, at least 1.
        weight: f64,
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// Lifelong Planning A*: the incremental forward search (on a static world, one search).
    #[serde(rename = "lpa_star")]
    LpaStar {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// D* Lite: the incremental backward search (on a static world, one search).
    #[serde(rename = "dstar_lite")]
    DStarLite {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// ARA*: anytime repairing A*, from `epsilon` down to 1 by `epsilon_step`, unless a limit
    /// stops it first.
    #[serde(rename = "ara_star")]
    AraStar {
        /// The initial inflation (default 3).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        epsilon: Option<f64>,
        /// The decrease per iteration (default 0.5).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        epsilon_step: Option<f64>,
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
        /// Stop after this many seconds (default: none).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        time_limit_s: Option<f64>,
        /// Stop after this many expansions (default: none).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        max_expansions: Option<u64>,
    },
    /// AD*: anytime D*, as ARA* but searching backward from the goal.
    #[serde(rename = "ad_star")]
    AdStar {
        /// The initial inflation (default 3).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        epsilon: Option<f64>,
        /// The decrease per iteration (default 0.5).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        epsilon_step: Option<f64>,
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
        /// Stop after this many seconds (default: none).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        time_limit_s: Option<f64>,
        /// Stop after this many expansions (default: none).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        max_expansions: Option<u64>,
    },
    /// RRT over a polygon world: one tree from the start, biased toward the goal.
    #[serde(rename = "rrt")]
    Rrt(SamplingSpec),
    /// RRT-Connect over a polygon world: a tree from each end, grown toward each other.
    #[serde(rename = "rrt_connect")]
    RrtConnect(SamplingSpec),
    /// RRT* over a polygon world: rewiring toward the least cost until its limit.
    #[serde(rename = "rrt_star")]
    RrtStar(SamplingSpec),
}

impl PlannerSpec {
    /// The settings of a sampling planner, `None` for a graph search.
    pub fn sampling(&self) -> Option<&SamplingSpec> {
        match self {
            PlannerSpec::Rrt(spec) | PlannerSpec::RrtConnect(spec) | PlannerSpec::RrtStar(spec) => Some(spec),
            _ => None,
        }
    }

    /// The name used in problem documents (`"astar"`, `"dstar_lite"`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            PlannerSpec::Bfs {} => "bfs",
            PlannerSpec::Dfs {} => "dfs",
            PlannerSpec::Dijkstra {} => "dijkstra",
            PlannerSpec::AStar { .. } => "astar",
            PlannerSpec::WeightedAStar { .. } => "weighted_astar",
            PlannerSpec::LpaStar { .. } => "lpa_star",
            PlannerSpec::DStarLite { .. } => "dstar_lite",
            PlannerSpec::AraStar { .. } => "ara_star",
            PlannerSpec::AdStar { .. } => "ad_star",
            PlannerSpec::Rrt(_) => "rrt",
            PlannerSpec::RrtConnect(_) => "rrt_connect",
            PlannerSpec::RrtStar(_) => "rrt_star",
        }
    }
}

/// One iteration of an anytime planner, in a result.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct IterationRecord {
    /// The inflation of the iteration.
    pub epsilon: f64,
    /// The path cost after it (`null` while the goal is unreached).
    pub cost: Option<f64>,
    /// The proven suboptimality bound of that cost.
    pub bound: f64,
    /// Expansions in the iteration.
    pub expansions: u64,
    /// Seconds from the start of the search to the end of the iteration.
    pub time_s: f64,
}

/// Whether a planner found a path, and what its absence means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// A path was found.
    Solved,
    /// The planner proved that no path exists (a search that ran to its end over a grid or an
    /// exact roadmap: the visibility graph or the trapezoidal cells of the free space, whose
    /// round corners are polygons outside the exact disc, so a gap narrower than about 2% of
    /// the robot radius beyond its width counts as closed).
    NoPath,
    /// A sampling planner stopped at its limit without reaching the goal: the path leads to
    /// the state nearest it (no proof that no path exists).
    Approximate,
    /// A limit stopped the planner before it found a path or proved there is none: an anytime
    /// search out of time or expansions, a sampling planner with nothing to show, a sampled
    /// roadmap (PRM) whose samples do not join the start to the goal. There is no
    /// path in the result, and nothing is known about whether one exists.
    Stopped,
}

/// A point of a result path: a cell `[x, y]` of a grid, or a point of a continuous space.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Waypoint {
    /// A grid cell, `[x, y]`.
    Cell(Cell),
    /// A point or state, `[x, y, ...]`.
    Point(Vec<f64>),
}

/// Statistics of a result. Counters a planner does not keep are omitted.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ResultStats {
    /// Nodes expanded (taken from the open list and their successors generated).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub expansions: Option<u64>,
    /// Nodes inserted into the open list.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pushes: Option<u64>,
    /// Keys lowered in the open list (a shorter path to an open node).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub decreases: Option<u64>,
    /// Closed nodes reopened (a shorter path to an expanded node).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reopenings: Option<u64>,
    /// Wall-clock time of the search alone, in seconds (graph construction excluded).
    pub time_s: f64,
    /// Roadmaps: the graph that was searched and the time it took to build.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub graph: Option<GraphStats>,
    /// Anytime planners: each iteration, in order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub iterations: Option<Vec<IterationRecord>>,
    /// Anytime planners: the proven suboptimality bound of the returned path.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bound: Option<f64>,
    /// Sampling planners: what the run did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampling: Option<SamplingStats>,
}

/// What a sampling planner's run did (`time` fields aside, the same seed gives the same
/// figures).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SamplingStats {
    /// Iterations (samples drawn).
    pub iterations: u64,
    /// States in the start tree and in the goal tree (RRT-Connect; 0 for the others).
    pub tree_sizes: [usize; 2],
    /// State and motion validity checks.
    pub collision_checks: u64,
    /// Seconds to the first solution, `null` without one.
    pub time_to_solution_s: Option<f64>,
    /// Each new best solution: the iteration, the seconds since the start, the cost.
    pub improvements: Vec<ImprovementRecord>,
    /// The distance from the path's last state to the goal (0 when solved).
    pub goal_distance: f64,
    /// The planner's path cost before simplification, `null` without a path.
    pub planned_cost: Option<f64>,
    /// Seconds spent simplifying (0 without).
    pub simplify_time_s: f64,
    /// The smoothed path, when asked for.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smoothed: Option<SmoothedRecord>,
}

/// A new best solution of a sampling planner.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ImprovementRecord {
    /// The iteration that found it.
    pub iteration: u64,
    /// Seconds since the start of the run.
    pub time_s: f64,
    /// Its cost.
    pub cost: f64,
}

/// A smoothed path in a result: Bézier pieces end to end.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SmoothedRecord {
    /// The curves used.
    pub method: Smoothing,
    /// Its length.
    pub length: f64,
    /// Legs or corners left unsmoothed because no curve there was proven free.
    pub kept: usize,
    /// Each piece's control points (two for a straight piece).
    pub pieces: Vec<Vec<[f64; 2]>>,
}

/// The roadmap a polygon-world problem was searched on.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GraphStats {
    /// Nodes of the roadmap (start and goal not counted).
    pub nodes: usize,
    /// Edges of the roadmap (start and goal links not counted); an undirected edge counts once.
    pub edges: usize,
    /// Seconds to build the roadmap.
    pub build_time_s: f64,
    /// Seconds to join the start and the goal to it.
    pub query_time_s: f64,
}

/// The result of solving a problem.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolveResult {
    /// `"solved"`, `"no_path"`, `"approximate"` or `"stopped"` (see [`Status`]).
    pub status: Status,
    /// The path cost, `null` without a path.
    pub cost: Option<f64>,
    /// The path from start to goal, empty without one.
    pub path: Vec<Waypoint>,
    /// What the planner did.
    pub stats: ResultStats,
}

/// The document printed instead of a result when the problem itself is wrong.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ErrorReport {
    /// Always `"error"`.
    pub status: String,
    /// What was wrong and where.
    pub error: String,
}

impl ErrorReport {
    /// A report of `error`.
    pub fn new(error: impl std::fmt::Display) -> Self {
        ErrorReport { status: "error".into(), error: error.to_string() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_planner_and_fields_are_errors() {
        let base = |planner: &str| {
            format!(
                r#"{{"world": {{"grid": {{"rows": [".."]}}}}, "start": [0,0], "goal": [1,0], "planner": {planner}}}"#
            )
        };
        assert!(serde_json::from_str::<Problem>(&base(r#"{"name": "astar"}"#)).is_ok());
        let err = serde_json::from_str::<Problem>(&base(r#"{"name": "teleport"}"#)).unwrap_err().to_string();
        assert!(err.contains("unknown variant `teleport`"), "{err}");
        let err = serde_json::from_str::<Problem>(&base(r#"{"name": "weighted_astar", "wieght": 2}"#))
            .unwrap_err()
            .to_string();
        assert!(err.contains("wieght") || err.contains("weight"), "{err}");
        let err = serde_json::from_str::<Problem>(&base(r#"{"name": "dijkstra", "weight": 2}"#));
        assert!(err.is_err(), "a parameter the planner does not take is an error");
        let err = serde_json::from_str::<Problem>(r#"{"world": {"grid": {}}, "start": [0,0]}"#);
        assert!(err.unwrap_err().to_string().contains("missing field"));
    }

    /// Every sampler refuses a field it does not take, the uniform one included.
    #[test]
    fn samplers_refuse_unknown_fields() {
        let spec =
            |sampler: &str| serde_json::from_str::<SamplingSpec>(&format!(r#"{{"sampler": {sampler}}}"#));
        assert_eq!(spec(r#"{"name": "uniform"}"#).unwrap().sampler, Some(SamplerSpec::Uniform {}));
        for sampler in [
            r#"{"name": "uniform", "std_dev": 2}"#,
            r#"{"name": "uniform", "surprise": true}"#,
            r#"{"name": "bridge", "std_dev": 2, "surprise": true}"#,
            r#"{"name": "gaussian", "std_dev": 2, "surprise": true}"#,
        ] {
            assert!(spec(sampler).is_err(), "{sampler}");
        }
    }

    #[test]
    fn connectivity_is_4_or_8() {
        let w: GridWorld = serde_json::from_str(r#"{"rows": ["."], "connectivity": 4}"#).unwrap();
        assert_eq!(w.connectivity, Connectivity::Four);
        assert!(serde_json::from_str::<GridWorld>(r#"{"connectivity": 6}"#).is_err());
    }

    #[test]
    fn results_serialize_as_documented() {
        let result = SolveResult {
            status: Status::NoPath,
            cost: None,
            path: vec![],
            stats: ResultStats { expansions: Some(3), time_s: 0.5, ..Default::default() },
        };
        let json = serde_json::to_string(&result).unwrap();
        assert_eq!(
            json,
            r#"{"status":"no_path","cost":null,"path":[],"stats":{"expansions":3,"time_s":0.5}}"#
        );
        let cell = serde_json::to_string(&Waypoint::Cell(Cell::new(1, 2))).unwrap();
        assert_eq!(cell, "[1,2]");
        for planner in [
            PlannerSpec::Bfs {},
            PlannerSpec::AStar { heuristic: None },
            PlannerSpec::WeightedAStar { weight: 2.0, heuristic: None },
            PlannerSpec::AdStar {
                epsilon: None,
                epsilon_step: None,
                heuristic: None,
                time_limit_s: None,
                max_expansions: None,
            },
        ] {
            let json = serde_json::to_value(&planner).unwrap();
            assert_eq!(json["name"], planner.name());
        }
        assert_eq!(
            serde_json::to_string(&ErrorReport::new("bad")).unwrap(),
            r#"{"status":"error","error":"bad"}"#
        );
    }
}
