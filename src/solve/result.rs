//! The result document of [`solve`](super::solve): the status, the cost, the path and what
//! the planner did, as serde types; and the document printed instead when the problem is wrong.

use serde::{Deserialize, Serialize};
use trailmark_core::geometry::{Point, Pose, SVector};
use trailmark_core::grid::Cell;
use trailmark_core::smooth::Smoothing;
use trailmark_sample::StateSpace;
use trailmark_search::{AnytimeResult, SearchResult};

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
///
/// Printed with `{:?}` as its coordinates in parentheses, as a [`Cell`] is: `(3, 4)`.
#[derive(Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Waypoint {
    /// A grid cell, `[x, y]`.
    Cell(Cell),
    /// A point or state, `[x, y, ...]`.
    Point(Vec<f64>),
}

impl std::fmt::Debug for Waypoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Waypoint::Cell(cell) => write!(f, "{cell:?}"),
            Waypoint::Point(coordinates) => {
                let parts: Vec<String> = coordinates.iter().map(|c| format!("{c:?}")).collect();
                write!(f, "({})", parts.join(", "))
            }
        }
    }
}

/// Statistics of a result. Counters a planner does not keep are omitted.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ResultStats {
    /// Why a planner ended without a path when it proved nothing (`"lattice_exhausted"`,
    /// `"time_limit"`, ...); omitted where a planner does not say.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stop: Option<trailmark_core::termination::Stop>,
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
    /// Car planners (Hybrid A*): the path's length, the part in reverse, the cusps.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub car: Option<CarRecord>,
}

/// A car's path in a result: how far it drives, how much of that in reverse, and where it
/// changes gear.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct CarRecord {
    /// The length driven, forward and in reverse.
    pub length: f64,
    /// The length driven in reverse.
    pub reverse_length: f64,
    /// The poses `[x, y, heading]` where the gear changes.
    pub cusps: Vec<[f64; 3]>,
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
    /// The visibility graph of a polygon world is found lazily: the edges its last round swept.
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

/// The result document of an anytime search: the path of its last iteration, every iteration;
/// each path node written as `waypoint(node)`. Without a path the status is
/// [`Status::NoPath`] only when the search proved the goal unreachable
/// ([`Stop::Unreachable`](trailmark_core::termination::Stop::Unreachable)); stopped by a limit
/// first, it is [`Status::Stopped`].
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

/// A position as the numbers of a result waypoint.
pub(super) trait Coordinates {
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

impl<const N: usize> Coordinates for SVector<f64, N> {
    fn coordinates(&self) -> Vec<f64> {
        self.iter().copied().collect()
    }
}

/// The states of a result's path in `space` (its waypoints' coordinates).
pub(super) fn states_of<S: StateSpace>(space: &S, result: &SolveResult) -> Vec<S::State> {
    let state = |w: &Waypoint| match w {
        Waypoint::Point(c) => space.state_from_coordinates(c),
        Waypoint::Cell(_) => None,
    };
    result.path.iter().filter_map(state).collect()
}

/// Whether a reported path cost and the length measured along the path agree, up to the
/// rounding of summing the edges in another order.
pub(super) fn same_length(cost: f64, length: f64) -> bool {
    (cost - length).abs() <= 1e-9 * cost.abs().max(length.abs()).max(f64::MIN_POSITIVE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::{AnytimeSpec, PlannerSpec};

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
            PlannerSpec::AdStar(AnytimeSpec::default()),
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
