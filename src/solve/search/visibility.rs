//! The visibility graph of a polygon world searched lazily, in rounds of growing bounds: a
//! document asks one query, so only the nodes its search reaches are swept.

use std::time::{Duration, Instant};

use trailmark_core::geometry::Point;
use trailmark_graph::{LazyVisibilityGraph, Roadmap, VisibilityError};

use super::roadmap::search_roadmap;
use crate::solve::error::SolveError;
use crate::solve::planner::PlannerSpec;
use crate::solve::problem::ProblemSpec;
use crate::solve::result::{ResultStats, SolveResult, Status};

/// Searches `graph` from `start` to `goal` with the problem's planner, one round per bound until
/// a round's path is within its bound (or the unbounded round ends); `blocked` turns a refused
/// end into the document's error. Returns the last round's result, its counters summed over
/// the rounds, and the edges the last round swept (for the picture).
///
/// Only the least-cost searches run in rounds: a bound keeps every path no longer than itself,
/// so their answer within it is the full graph's. The others (breadth- and depth-first, weighted
/// A*, the anytime planners with their limits) search the unbounded lazy graph once: the same
/// graph as the full one, with their limits applying once.
pub(super) fn search_visibility(
    problem: &ProblemSpec,
    graph: &LazyVisibilityGraph,
    (start, goal): (Point, Point),
    built: Duration,
    blocked: impl Fn(VisibilityError) -> SolveError,
) -> Result<(SolveResult, Vec<(Point, Point)>), SolveError> {
    let least_cost = matches!(
        problem.planner,
        PlannerSpec::Dijkstra {}
            | PlannerSpec::AStar { .. }
            | PlannerSpec::LpaStar { .. }
            | PlannerSpec::DStarLite { .. }
            | PlannerSpec::AdaptiveAStar { .. }
            | PlannerSpec::MpgaaStar { .. }
    );
    let mut bound = if least_cost { LazyVisibilityGraph::first_bound(start, goal) } else { f64::INFINITY };
    let mut earlier = ResultStats::default();
    let mut joined = Duration::ZERO;
    loop {
        let clock = Instant::now();
        let bounded = graph.within(start, goal, bound).map_err(&blocked)?;
        let query = bounded.query();
        joined += clock.elapsed();
        let mut result = search_roadmap(problem, &query, built, joined)?;
        // A round stopped by a limit ends the search as it is.
        let next = match result.status {
            Status::Solved | Status::NoPath => bounded.next_bound(result.cost),
            _ => None,
        };
        match next {
            Some(next) => {
                add_counts(&mut earlier, &result.stats);
                bound = next;
            }
            None => {
                add_counts(&mut result.stats, &earlier);
                if let Some(stats) = result.stats.graph.as_mut() {
                    stats.query_time_s = joined.as_secs_f64();
                }
                return Ok((result, bounded.edge_ends()));
            }
        }
    }
}

/// Adds the counters and the search time of `round` to `total`.
fn add_counts(total: &mut ResultStats, round: &ResultStats) {
    let add = |a: Option<u64>, b: Option<u64>| match (a, b) {
        (Some(a), Some(b)) => Some(a + b),
        (a, b) => a.or(b),
    };
    total.expansions = add(total.expansions, round.expansions);
    total.pushes = add(total.pushes, round.pushes);
    total.decreases = add(total.decreases, round.decreases);
    total.reopenings = add(total.reopenings, round.reopenings);
    total.time_s += round.time_s;
}
