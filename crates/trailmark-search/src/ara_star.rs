//! ARA*: anytime repairing A*, a quick inflated solution first, then better ones.

use std::ops::ControlFlow;
use std::time::Duration;

use serde::{Deserialize, Serialize};
use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Successors};
use trailmark_core::path::Path;

use crate::astar::MAX_WEIGHT;
use crate::error::SearchError;
use crate::index::{Dense, NodeIndex};
use crate::search::{EdgeCheck, FKey, Search, ensure};
use crate::stats::SearchStats;

/// The most iterations an inflation schedule may ask for.
pub const MAX_ITERATIONS: usize = 10_000;

/// The largest initial inflation an anytime planner accepts: [`MAX_WEIGHT`](crate::MAX_WEIGHT),
/// 1e6, for the same reasons (an inflation is a heuristic weight). An inflation that large makes
/// the first iteration a greedy search; a larger one only brings `ε h` toward overflow.
pub const MAX_EPSILON: f64 = MAX_WEIGHT;

/// How an anytime planner lowers its heuristic inflation: from `initial` down to 1 by `step`
/// per iteration (the last step lands on 1 exactly). [`EpsilonSchedule::check`] says which
/// schedules a planner accepts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EpsilonSchedule {
    /// The first inflation, from 1 to [`MAX_EPSILON`] (3 by default).
    pub initial: f64,
    /// The decrease per iteration, `> 0` (0.5 by default).
    pub step: f64,
}

impl Default for EpsilonSchedule {
    fn default() -> Self {
        EpsilonSchedule { initial: 3.0, step: 0.5 }
    }
}

impl EpsilonSchedule {
    /// A schedule from `initial` down by `step`.
    pub fn new(initial: f64, step: f64) -> Self {
        EpsilonSchedule { initial, step }
    }

    /// Errors ([`SearchError::InvalidEpsilon`]) unless `1 <= initial <= MAX_EPSILON`, `step > 0`
    /// is finite, and the schedule reaches 1 in at most [`MAX_ITERATIONS`] iterations, each of
    /// which lowers the inflation by `step`: a step lost to rounding (`1e20 - 1 == 1e20` in
    /// `f64`) would never arrive.
    pub fn check<N: std::fmt::Debug>(&self) -> Result<(), SearchError<N>> {
        let valid = (1.0..=MAX_EPSILON).contains(&self.initial) && self.step.is_finite() && self.step > 0.0;
        if !valid || self.iterations() > MAX_ITERATIONS {
            return Err(SearchError::InvalidEpsilon { initial: self.initial, step: self.step });
        }
        Ok(())
    }

    /// The number of iterations from `initial` to 1, counted by stepping through the schedule
    /// as a planner does. A schedule longer than [`MAX_ITERATIONS`], or one that does not reach 1
    /// because `initial - step` rounds back to `initial` somewhere on the way, counts as
    /// `MAX_ITERATIONS + 1`; a NaN `initial` counts 1 (it is not above 1).
    pub fn iterations(&self) -> usize {
        let mut epsilon = self.initial;
        let mut count = 1;
        while epsilon > 1.0 {
            count += 1;
            let lower = epsilon - self.step;
            if count > MAX_ITERATIONS || lower.is_nan() || lower >= epsilon {
                return MAX_ITERATIONS + 1;
            }
            epsilon = self.next(epsilon);
        }
        count
    }

    /// The inflation after `epsilon`: lower by `step`, never below 1. Above 1 it is always
    /// strictly lower than `epsilon`, by a unit in the last place at least should `step` be lost
    /// to rounding (a schedule [`check`](Self::check) refuses), so stepping always ends.
    pub fn next(&self, epsilon: f64) -> f64 {
        (epsilon - self.step).min(epsilon.next_down()).max(1.0)
    }
}

/// When an anytime search stops before reaching ε = 1: wall time, expansions, or both.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Budget {
    /// Wall-clock time for the whole search.
    pub time: Option<Duration>,
    /// Expansions for the whole search.
    pub expansions: Option<u64>,
}

impl Budget {
    /// No limit: run until ε = 1.
    pub fn unlimited() -> Self {
        Budget::default()
    }

    /// Whether the budget is spent, `elapsed` and `expansions` into the search.
    pub fn spent(&self, elapsed: Duration, expansions: u64) -> Option<Stop> {
        if self.time.is_some_and(|t| elapsed >= t) {
            return Some(Stop::TimeLimit);
        }
        if self.expansions.is_some_and(|e| expansions >= e) {
            return Some(Stop::ExpansionLimit);
        }
        None
    }
}

/// Why an anytime search stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The last iteration ran at ε = 1: the path is optimal (for an admissible, consistent
    /// heuristic).
    Optimal,
    /// The goal cannot be reached: the search proved it (this is the only stop that does).
    Unreachable,
    /// The time budget ran out. Without a path, nothing is known about the goal.
    TimeLimit,
    /// The expansion budget ran out. Without a path, nothing is known about the goal.
    ExpansionLimit,
    /// The caller's callback asked to stop (or, for [`AdStar::improve_once`](crate::AdStar::improve_once),
    /// the one iteration asked for is done).
    Caller,
}

/// One completed iteration of an anytime search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Iteration {
    /// The inflation this iteration searched with.
    pub epsilon: f64,
    /// The cost of the path after this iteration (`None` while the goal is unreached).
    pub cost: Option<Cost>,
    /// The proven suboptimality bound: the cost is at most `bound x` the optimum.
    /// `min(epsilon, g(goal) / min over open and inconsistent nodes of g + h)`.
    pub bound: f64,
    /// Expansions in this iteration.
    pub expansions: u64,
    /// Time since the search began, at the end of this iteration.
    pub elapsed: Duration,
}

/// What an anytime search returns: the best path found, every iteration, why it stopped.
///
/// A result without a path says the goal is unreachable only when it stopped with
/// [`Stop::Unreachable`]; stopped by a budget or the caller, it proves nothing (see
/// [`AnytimeResult::proved_unreachable`]).
#[derive(Debug, Clone, PartialEq)]
pub struct AnytimeResult<N> {
    /// The best path found (from the last completed iteration), `None` if none was found.
    pub path: Option<Path<N>>,
    /// The iterations completed, in order.
    pub iterations: Vec<Iteration>,
    /// Why the search stopped.
    pub stop: Stop,
    /// Counters over the whole search.
    pub stats: SearchStats,
}

impl<N> AnytimeResult<N> {
    /// The cost of the best path found.
    pub fn cost(&self) -> Option<Cost> {
        self.path.as_ref().map(|p| p.cost)
    }

    /// Whether the search proved that the goal is unreachable: no path, and stopped with
    /// [`Stop::Unreachable`], not by a limit before it could tell.
    pub fn proved_unreachable(&self) -> bool {
        self.path.is_none() && self.stop == Stop::Unreachable
    }

    /// The suboptimality bound proven for that path (`None` without a path).
    pub fn bound(&self) -> Option<f64> {
        self.path.as_ref()?;
        self.iterations.last().map(|i| i.bound)
    }
}

/// ARA* (Likhachev, Gordon and Thrun, 2003) from `start` to `goal`: weighted A* with inflation
/// `epsilon` gives a first path quickly, then the inflation is lowered and the search repaired,
/// reusing what earlier iterations expanded, until ε = 1 (optimal) or the budget runs out. With
/// a consistent heuristic every path found costs at most ε times the optimum; each iteration
/// reports its proven bound.
///
/// Errors when the schedule is invalid ([`EpsilonSchedule::check`]), and, as A* does, with
/// [`SearchError::CostOverflow`] when the goal is unreached but a path whose cost exceeds the
/// largest `f64` was met.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{Budget, EpsilonSchedule, Stop, astar, ara_star};
///
/// let grid = Grid::from_rows(&["........", ".@@@@@@.", "......@.", ".@@@@.@.", "........"])?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(2, 2), Cell::new(7, 4));
/// let h = graph.heuristic(GridHeuristic::Octile, goal);
/// let found = ara_star(&graph, start, goal, h, EpsilonSchedule::new(3.0, 1.0), Budget::unlimited())?;
/// assert_eq!(found.stop, Stop::Optimal);
/// assert_eq!(found.iterations[0].epsilon, 3.0);
/// // Each iteration's cost is within its proven bound of the final, optimal cost.
/// for it in &found.iterations {
///     assert!(it.cost.unwrap() <= it.bound * found.cost().unwrap() + 1e-9);
/// }
/// assert_eq!(found.cost(), astar(&graph, start, goal, h)?.cost());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn ara_star<G, H>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
    heuristic: H,
    schedule: EpsilonSchedule,
    budget: Budget,
) -> Result<AnytimeResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
    H: FnMut(G::Node) -> Cost,
{
    Search::<Dense>::new()
        .ara_star(graph, start, goal, heuristic, schedule, budget, |_| ControlFlow::Continue(()))
}

impl<I> Search<I> {
    /// ARA* with this workspace; see [`ara_star`](crate::ara_star()). `on_iteration` sees each
    /// iteration as it completes (to publish the path, or to stop: return `ControlFlow::Break`).
    #[allow(clippy::too_many_arguments)]
    pub fn ara_star<G, H>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        mut heuristic: H,
        schedule: EpsilonSchedule,
        budget: Budget,
        mut on_iteration: impl FnMut(&Iteration) -> ControlFlow<()>,
    ) -> Result<AnytimeResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
    {
        schedule.check()?;
        self.reserve_generations(schedule.iterations() + 1);
        let query = self.begin(graph, start, goal)?;
        let (s, t) = (query.start, query.goal);
        // Nodes stamped at or above `first` were reached by this query; `closed_stamp()` marks
        // those expanded in the current iteration.
        let first = query.open;
        let mut h = |node| {
            let v = heuristic(node);
            if v >= 0.0 { Ok(v) } else { Err(SearchError::InvalidHeuristic { node, value: v }) }
        };
        let mut epsilon = schedule.initial;
        let mut stats = SearchStats::default();
        let mut iterations = Vec::new();
        let mut incons: Vec<u32> = Vec::new();
        let mut best: Option<Path<G::Node>> = None;
        // The first node whose cost overflowed (a finite `g` plus a finite edge cost gave +inf):
        // left unreached, which is exact when the goal is reached (its path costs less) and an
        // error otherwise. A priority `g + ε h` that overflows is just `+inf`: such nodes come
        // after all others, and are expanded while the goal is unreached.
        let mut overflow = None;
        let h_start = h(start)?;
        if h_start.is_finite() {
            self.heap.push(s, FKey::new(epsilon * h_start, 0.0));
            stats.pushes += 1;
        }
        let stop = loop {
            let before = stats.expansions;
            let (open, closed) = (self.open_stamp(), self.closed_stamp());
            let mut edges = EdgeCheck::new();
            let mut out_of_budget = None;
            // ImprovePath: expand while some open node's f is below the goal's (every open node
            // while the goal is unreached, those of infinite f included).
            while let Some((u, key)) = self.heap.peek() {
                if self.nodes.stamp[t] >= first && FKey::new(self.nodes.g[t], self.nodes.g[t]) <= key {
                    break;
                }
                // The expansion count is checked every time, the clock every 256 expansions.
                let clock =
                    if stats.expansions.is_multiple_of(256) { query.elapsed() } else { Duration::ZERO };
                if let Some(why) = budget.spent(clock, stats.expansions) {
                    out_of_budget = Some(why);
                    break;
                }
                self.heap.pop();
                self.nodes.stamp[u] = closed;
                stats.expansions += 1;
                let gu = self.nodes.g[u];
                let mut bad_h = None;
                let (nodes, heap, index) = (&mut self.nodes, &mut self.heap, &mut self.index);
                index.for_each_successor(graph, u, |v, next, cost| {
                    if !edges.accept(next, cost) {
                        return;
                    }
                    ensure(nodes, v);
                    let gv = gu + cost;
                    let st = nodes.stamp[v];
                    if st >= first && gv >= nodes.g[v] {
                        return;
                    }
                    if gv == f64::INFINITY {
                        overflow.get_or_insert(next);
                        return;
                    }
                    let hv = match h(next) {
                        Ok(hv) => hv,
                        Err(e) => {
                            bad_h.get_or_insert(e);
                            return;
                        }
                    };
                    nodes.g[v] = gv;
                    nodes.parent[v] = u as u32;
                    if st == closed {
                        // Expanded in this iteration: its improvement waits for the next one.
                        incons.push(v as u32);
                    } else {
                        nodes.stamp[v] = open;
                        if hv.is_finite() {
                            heap.push(v, FKey::new(gv + epsilon * hv, gv));
                            stats.pushes += 1;
                        }
                    }
                });
                edges.check(|| self.index.node(graph, u))?;
                if let Some(e) = bad_h {
                    return Err(e);
                }
            }
            if let Some(why) = out_of_budget {
                break why;
            }
            // The iteration is complete: publish its path and bound.
            let reached = self.nodes.stamp[t] >= first;
            let cost = reached.then(|| self.nodes.g[t]);
            if reached {
                // The path along parent links costs at most `g(goal)` (a parent may have improved
                // since); `g(goal)` never rises, but that path may cost more than an earlier one,
                // which is then kept.
                let mut path = self.path_to(graph, t);
                path.cost = path_cost(graph, &path.nodes);
                if best.as_ref().is_none_or(|b| path.cost < b.cost) {
                    best = Some(path);
                }
            }
            let bound = match cost {
                None => f64::INFINITY,
                Some(g_goal) => {
                    let mut lowest = f64::INFINITY;
                    for slot in self.heap.iter().map(|(v, _)| v).chain(incons.iter().map(|&v| v as usize)) {
                        lowest = lowest.min(self.nodes.g[slot] + h(self.index.node(graph, slot))?);
                    }
                    if lowest >= g_goal { 1.0 } else { epsilon.min(g_goal / lowest) }
                }
            };
            let iteration = Iteration {
                epsilon,
                cost: best.as_ref().map(|p| p.cost),
                bound,
                expansions: stats.expansions - before,
                elapsed: query.elapsed(),
            };
            iterations.push(iteration);
            if cost.is_none() {
                if let Some(node) = overflow {
                    return Err(SearchError::CostOverflow { node });
                }
                break Stop::Unreachable;
            }
            if epsilon <= 1.0 || bound <= 1.0 {
                break Stop::Optimal;
            }
            if on_iteration(&iteration).is_break() {
                break Stop::Caller;
            }
            if let Some(why) = budget.spent(query.elapsed(), stats.expansions) {
                break why;
            }
            // Next iteration: lower ε, move the inconsistent nodes into the open list, re-key
            // it, and forget which nodes were closed.
            epsilon = schedule.next(epsilon);
            self.next_generation();
            let open = self.open_stamp();
            let mut items: Vec<usize> = self.heap.iter().map(|(v, _)| v).collect();
            items.extend(incons.drain(..).map(|v| v as usize));
            self.heap.clear();
            for v in items {
                let hv = h(self.index.node(graph, v))?;
                let gv = self.nodes.g[v];
                self.nodes.stamp[v] = open;
                if hv.is_finite() {
                    self.heap.push(v, FKey::new(gv + epsilon * hv, gv));
                }
            }
        };
        if let Some(last) = iterations.last()
            && (stop == Stop::Optimal || stop == Stop::Unreachable)
        {
            let _ = on_iteration(last);
        }
        stats.elapsed = query.elapsed();
        Ok(AnytimeResult { path: best, iterations, stop, stats })
    }
}

/// The cost of walking `nodes` in `graph` (the least of parallel edges at each step).
fn path_cost<G: Successors + ?Sized>(graph: &G, nodes: &[G::Node]) -> Cost {
    nodes
        .windows(2)
        .map(|pair| {
            let mut best = f64::INFINITY;
            graph.for_each_successor(pair[0], |n, c| {
                if n == pair[1] && c < best {
                    best = c;
                }
            });
            best
        })
        .sum()
}
