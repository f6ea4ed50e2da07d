//! ARA*: anytime repairing A*, a quick inflated solution first, then better ones.

use std::ops::ControlFlow;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Successors};
use trailmark_core::path::Path;

use trailmark_core::termination::{Stop, Termination, Watch};

use crate::anytime::{AnytimeResult, EpsilonSchedule, Iteration};
use crate::error::SearchError;
use crate::heuristic::{HeuristicCheck, checked_heuristic};
use crate::index::{Dense, NodeIndex};
use crate::one_shot::edges::EdgeCheck;
use crate::one_shot::key::FKey;
use crate::one_shot::workspace::{Search, ensure};
use crate::stats::SearchStats;

/// ARA* (Likhachev, Gordon and Thrun, 2003) from `start` to `goal`: weighted A* with inflation
/// `epsilon` gives a first path quickly, then the inflation is lowered and the search repaired,
/// reusing what earlier iterations expanded, until ε = 1 (optimal) or `termination` stops it
/// (any of its limits; see [the anytime searches](crate#anytime-searches)). With a consistent
/// heuristic every path found costs at most ε times the optimum; each iteration reports its
/// proven bound.
///
/// Errors when the schedule is invalid ([`EpsilonSchedule::check`]), and, as A* does, with
/// [`SearchError::CostOverflow`] when the goal is unreached but a path whose cost exceeds the
/// largest `f64` was met.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_core::termination::{Stop, Termination};
/// use trailmark_search::{EpsilonSchedule, astar, ara_star};
///
/// let grid = Grid::from_rows(&["........", ".@@@@@@.", "......@.", ".@@@@.@.", "........"])?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(2, 2), Cell::new(7, 4));
/// let h = graph.heuristic(GridHeuristic::Octile, goal);
/// let found = ara_star(&graph, start, goal, h, EpsilonSchedule::new(3.0, 1.0), Termination::unlimited())?;
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
    termination: impl Into<Termination>,
) -> Result<AnytimeResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
    H: FnMut(G::Node) -> Cost,
{
    Search::<Dense>::new()
        .ara_star(graph, start, goal, heuristic, schedule, termination, |_| ControlFlow::Continue(()))
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
        termination: impl Into<Termination>,
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
        let termination = termination.into();
        let mut watch = Watch::start(&termination);
        watch.begin_iteration();
        let (s, t) = (query.start, query.goal);
        // Nodes stamped at or above `first` were reached by this query; `closed_stamp()` marks
        // those expanded in the current iteration.
        let first = query.open;
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
        let h_start = checked_heuristic(start, heuristic(start))?;
        if h_start.is_finite() {
            self.heap.push(s, FKey::new(epsilon * h_start, 0.0));
            stats.pushes += 1;
        }
        let stop = loop {
            let before = stats.expansions;
            let (open, closed) = (self.open_stamp(), self.closed_stamp());
            let mut edges = EdgeCheck::new();
            let mut interrupted = None;
            // ImprovePath: expand while some open node's f is below the goal's (every open node
            // while the goal is unreached, those of infinite f included).
            while let Some((u, key)) = self.heap.peek() {
                if self.nodes.stamp[t] >= first && FKey::new(self.nodes.g[t], self.nodes.g[t]) <= key {
                    break;
                }
                // The expansion count is checked every time; the clock and the condition every 256
                // expansions.
                let why = if stats.expansions.is_multiple_of(256) {
                    watch.set_expansions(stats.expansions);
                    watch.interrupted()
                } else {
                    termination.expansions_spent(stats.expansions).then_some(Stop::ExpansionLimit)
                };
                if why.is_some() {
                    interrupted = why;
                    break;
                }
                self.heap.pop();
                self.nodes.stamp[u] = closed;
                stats.expansions += 1;
                let gu = self.nodes.g[u];
                let mut heuristics = HeuristicCheck::new();
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
                    let Some(hv) = heuristics.accept(next, heuristic(next)) else { return };
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
                heuristics.check()?;
            }
            if let Some(why) = interrupted {
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
                        let node = self.index.node(graph, slot);
                        lowest = lowest.min(self.nodes.g[slot] + checked_heuristic(node, heuristic(node))?);
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
            if let Some(cost) = iteration.cost {
                watch.improved(cost);
            }
            watch.set_expansions(stats.expansions);
            if let Some(why) = watch.next_iteration() {
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
                let node = self.index.node(graph, v);
                let hv = checked_heuristic(node, heuristic(node))?;
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
