//! Adaptive A*: A* from the robot at every plan, with a heuristic that learns from the plans
//! before (Koenig and Likhachev, "Adaptive A*", AAMAS 2005), kept consistent when costs fall as
//! well as rise (Generalized Adaptive A*, Sun, Koenig and Yeoh, AAMAS 2008).
//!
//! After a plan that reached the goal at cost `g*`, every node `s` it expanded learns
//! `h(s) = g* - g(s)`: the cost from `s` to the goal is at least that, and the next plan, from
//! wherever the robot then is, is guided by the larger of this and the given heuristic, so it
//! expands fewer nodes. Costs that rise keep the learned values admissible and consistent; where
//! a cost may have fallen (every edge at a node the planner is told of), a learned value that
//! became too large is lowered, and the decrease is carried back to the predecessors that relied
//! on it, cheapest first, before the next plan. Each plan is an A* search with a consistent
//! heuristic: its path costs what A* from scratch finds.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fmt::Debug;
use std::marker::PhantomData;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::heuristic::Heuristic;
use crate::incremental::EdgeChange;
use crate::incremental::path_reuse::PathReuse;
use crate::incremental::planner::edge_cost;
use crate::incremental::repeated_astar::RepeatedAStar;
use crate::incremental::replanner::Replanner;
use crate::incremental::values::grow_zeroed;
use crate::stats::SearchStats;

/// What an [`AdaptivePlanner`] keeps from one plan for the next besides its learned
/// heuristic: nothing more ([`LearnOnly`]: Adaptive A*) or the paths it found too
/// ([`ReusePaths`](crate::ReusePaths): MPGAA*).
pub trait Memory: Clone + Debug + Default {
    /// Whether the paths of earlier plans are kept, and a plan ends where it meets one.
    const REUSES_PATHS: bool;
}

/// Adaptive A*'s memory: the learned heuristic alone.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LearnOnly;

impl Memory for LearnOnly {
    const REUSES_PATHS: bool = false;
}

/// Adaptive A* from a moving start to a fixed goal, behind the [`Replanner`] interface.
///
/// Changes told as edges ([`update_edges`](Replanner::update_edges)) are relaxed one by one;
/// a node told ([`update_nodes`](Replanner::update_nodes)) has every edge in and out looked
/// at. On a grid, telling `GridGraph::edges_affected_by(cell)` is the cheaper of the two.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{AdaptiveAStar, Replanner};
///
/// let mut graph = GridGraph::new(&Grid::new(32, 32)?, Connectivity::Eight);
/// let h = graph.heuristic_between(GridHeuristic::Octile);
/// let mut planner = AdaptiveAStar::new(&graph, Cell::new(0, 0), Cell::new(31, 20), h)?;
/// let first = planner.plan(&graph)?;
/// // A wall appears across the way; the robot has moved one step.
/// for y in 0..25 {
///     graph.set_cost(Cell::new(16, y), f64::INFINITY)?;
///     planner.update_nodes(&graph, &graph.cells_affected_by(Cell::new(16, y)).collect::<Vec<_>>())?;
/// }
/// planner.move_start(&graph, Cell::new(1, 1))?;
/// planner.plan(&graph)?;
/// let fresh = trailmark_search::astar(&graph, Cell::new(1, 1), Cell::new(31, 20), graph.heuristic(GridHeuristic::Octile, Cell::new(31, 20)))?;
/// assert_eq!(planner.cost(), fresh.cost()); // the least cost, as A* from scratch
/// # let _ = first;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type AdaptiveAStar<N, H> = AdaptivePlanner<LearnOnly, N, H>;

/// A planner that runs A* from the robot at every plan with a heuristic learned from the plans
/// before, kept consistent when costs rise and fall; its memory `K` says whether it also reuses
/// earlier paths. [`AdaptiveAStar`] and [`MpgaaStar`](crate::MpgaaStar) are its two kinds.
#[derive(Debug, Clone)]
pub struct AdaptivePlanner<K, N, H> {
    /// A* from scratch: its workspace, heuristic, ends, last path and totals.
    base: RepeatedAStar<N, H>,
    /// The learned heuristic per node index; 0 where nothing was learned. Empty until a plan
    /// finds a path: the first search needs nothing learned, and a planner made for a large
    /// graph then pays for the table only once it has something to keep in it.
    learned: Vec<Cost>,
    /// The indices of the nodes whose edges may have changed since the last plan.
    touched: Vec<usize>,
    /// The edges told changed since the last plan, as (from, to) indices: each is looked at
    /// alone, where a touched node has all its edges looked at.
    changed: Vec<(usize, usize)>,
    /// The open list of the consistency repair: (the bits of a lowered learned value, which
    /// order as the values do for costs not negative, node index), smallest first. A node
    /// lowered again is queued again; an entry whose value is no longer the node's is passed
    /// over. No table as large as the graph: the repair stays near the changes.
    repair: BinaryHeap<Reverse<(u64, usize)>>,
    /// The paths of earlier plans, when they are reused (MPGAA*).
    pub(crate) reuse: Option<PathReuse>,
    /// Where the last plan's search ended on a kept path (its path goes on along it).
    tail: Option<usize>,
    memory: PhantomData<K>,
}

impl<K: Memory, N, H> AdaptivePlanner<K, N, H>
where
    N: Copy + Eq + std::hash::Hash + Debug,
{
    // RepeatedAStar::new's public signature; this builds on it.
    /// A planner from `start` to `goal`, with `heuristic(a, b)` a consistent estimate of the
    /// cost from `a` to `b` (the grid heuristics are). Nothing is searched until
    /// [`plan`](Replanner::plan). Errors when the start or the goal is not a node of the graph.
    pub fn new<G>(graph: &G, start: N, goal: N, heuristic: H) -> Result<Self, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let mut base = RepeatedAStar::new(graph, start, goal, heuristic)?;
        base.search.expanded_log = Some(Vec::new());
        Ok(AdaptivePlanner {
            base,
            learned: Vec::new(),
            touched: Vec::new(),
            changed: Vec::new(),
            repair: BinaryHeap::new(),
            reuse: K::REUSES_PATHS.then(PathReuse::new),
            tail: None,
            memory: PhantomData,
        })
    }

    /// The start.
    pub fn start(&self) -> N {
        self.base.start()
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.base.goal()
    }

    /// The cost of the last plan's path (`None` without one).
    pub fn cost(&self) -> Option<Cost> {
        self.base.cost()
    }

    /// Counters summed over every plan since the planner was made.
    pub fn totals(&self) -> SearchStats {
        self.base.totals()
    }

    /// Bytes held by the search workspace, the learned heuristic and the kept paths.
    pub fn memory_bytes(&self) -> usize {
        self.base.memory_bytes()
            + self.learned.capacity() * 8
            + self.repair.capacity() * std::mem::size_of::<Reverse<(u64, usize)>>()
            + self.reuse.as_ref().map_or(0, PathReuse::memory_bytes)
    }

    /// The heuristic of `node` (index `i`): the larger of the given and the learned one.
    fn h_at<G>(graph: &G, learned: &[Cost], heuristic: &mut H, node: N, i: usize, goal: N) -> Cost
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        heuristic.estimate(graph, node, goal).max(learned.get(i).copied().unwrap_or(0.0))
    }

    /// Lowers the learned value of `x` (index `i`) where an edge out of it makes it too large:
    /// to the least `c + h(v)` over its edges `x -> v`, queueing `x` so that the decrease
    /// reaches its predecessors. A kept step out of `x` whose edge changed is cut.
    ///
    /// As the given heuristic is consistent, `h(x) > c + h(v)` holds exactly when the learned
    /// value of `x` exceeds `c + h(v)`; and `h(v)` needs the given heuristic only where
    /// `c` plus the learned value of `v` already does.
    fn relax_out<G>(&mut self, graph: &G, x: N, i: usize)
    where
        G: Successors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let goal = self.base.goal();
        let relax = x != goal && self.learned[i] != 0.0;
        let mut step = self.reuse.as_ref().and_then(|r| r.next_of(i)).map(|n| (n, false));
        if !relax && step.is_none() {
            return; // the given heuristic is consistent by itself
        }
        let (learned, heuristic, reuse) = (&self.learned, &mut self.base.heuristic, &self.reuse);
        let hx = learned[i];
        let mut best = (f64::INFINITY, i, 0.0);
        graph.for_each_successor_index(i, |j, v, c| {
            if let (Some((n, kept)), Some(reuse)) = (step.as_mut(), reuse) {
                *kept |= *n == j && reuse.step_is(i, c);
            }
            if relax && c + learned[j] < hx.min(best.0) {
                let through = c + Self::h_at(graph, learned, heuristic, v, j, goal);
                if through < best.0 {
                    best = (through, j, c);
                }
            }
        });
        if let (Some((_, false)), Some(reuse)) = (step, self.reuse.as_mut()) {
            reuse.cut(i);
        }
        if relax && hx > best.0 {
            self.lower(i, best);
        }
    }

    /// What [`relax_out`](Self::relax_out) does for the one edge `u -> v` (indices) that changed:
    /// cuts `u`'s kept step if it took this edge and its cost changed, lowers `u`'s learned value
    /// if the edge makes it too large. The edge's cost is read from the graph only when one of
    /// the two may happen.
    fn relax_edge<G>(&mut self, graph: &G, u: usize, v: usize)
    where
        G: Successors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let goal = self.base.goal();
        let x = graph.node_at(u);
        let kept = self.reuse.as_ref().is_some_and(|r| r.next_of(u) == Some(v));
        let lu = self.learned[u];
        // Only a learned value above the estimate at `v` can exceed `c + h(v)`, as `c >= 0`.
        let hv = if x != goal && lu != 0.0 {
            Self::h_at(graph, &self.learned, &mut self.base.heuristic, graph.node_at(v), v, goal)
        } else {
            f64::INFINITY
        };
        if !kept && lu <= hv {
            return;
        }
        let c = edge_cost(graph, x, graph.node_at(v));
        if let Some(reuse) = self.reuse.as_mut()
            && kept
            && !reuse.step_is(u, c)
            && !reuse.step_kept(graph, u)
        {
            reuse.cut(u);
        }
        if lu > c + hv {
            self.lower(u, (c + hv, v, c));
        }
    }

    /// Lowers the learned values of the predecessors of `x` (index `i`) that the edge into `x`
    /// makes too large (`h(p) > c + h(x)`, which for a consistent given heuristic is the learned
    /// value of `p` exceeding `c + h(x)`), queueing each. With `check`, a kept step into `x`
    /// whose edge changed is cut first.
    fn relax_into<G>(&mut self, graph: &G, x: N, i: usize, check: bool)
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let goal = self.base.goal();
        let hx = Self::h_at(graph, &self.learned, &mut self.base.heuristic, x, i, goal);
        let AdaptivePlanner { learned, repair, reuse, .. } = self;
        graph.for_each_predecessor_index(i, |k, p, c| {
            if let Some(reuse) = reuse.as_mut().filter(|_| check)
                && reuse.next_of(k) == Some(i)
                && !reuse.step_is(k, c)
                && !reuse.step_kept(graph, k)
            {
                reuse.cut(k);
            }
            if p != goal && learned[k] > c + hx {
                Self::lower_in(learned, repair, reuse, k, (c + hx, i, c));
            }
        });
    }

    fn lower(&mut self, i: usize, to: (Cost, usize, Cost)) {
        Self::lower_in(&mut self.learned, &mut self.repair, &mut self.reuse, i, to);
    }

    /// Sets the learned value of index `i` to `to.0`, reached over the edge of cost `to.2` to
    /// index `to.1`. It is at least the given heuristic, which is consistent: `h` becomes
    /// exactly `c + h(v)`, and the way to the goal is through that edge.
    fn lower_in(
        learned: &mut [Cost],
        repair: &mut BinaryHeap<Reverse<(u64, usize)>>,
        reuse: &mut Option<PathReuse>,
        i: usize,
        (value, j, c): (Cost, usize, Cost),
    ) {
        learned[i] = value;
        repair.push(Reverse((value.to_bits(), i)));
        if let Some(reuse) = reuse.as_mut() {
            reuse.point(i, j, c);
        }
    }

    /// Room in the learned values and the kept paths for `bound` node indices.
    fn make_room(learned: &mut Vec<Cost>, reuse: &mut Option<PathReuse>, bound: usize) {
        grow_zeroed(learned, bound);
        if let Some(reuse) = reuse.as_mut() {
            reuse.resize(bound);
        }
    }

    /// Lowers the learned values that an edge which became cheaper made too large, and carries
    /// each decrease back to the predecessors that relied on it, smallest first.
    fn restore_consistency<G>(&mut self, graph: &G)
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        if self.learned.is_empty() || (self.touched.is_empty() && self.changed.is_empty()) {
            // Nothing learned and no path kept, or nothing changed: the heuristic is consistent.
            self.touched.clear();
            self.changed.clear();
            return;
        }
        Self::make_room(&mut self.learned, &mut self.reuse, graph.node_bound());
        // Neighbouring changes name the same nodes: each is looked at once.
        self.touched.sort_unstable();
        self.touched.dedup();
        let touched = std::mem::take(&mut self.touched);
        self.repair.clear();
        for &i in &touched {
            // The edges out of x and into x may have become cheaper, or changed under a kept
            // step.
            let x = graph.node_at(i);
            self.relax_out(graph, x, i);
            self.relax_into(graph, x, i, true);
        }
        self.touched = touched;
        self.touched.clear();
        let changed = std::mem::take(&mut self.changed);
        for &(u, v) in &changed {
            self.relax_edge(graph, u, v);
        }
        self.changed = changed;
        self.changed.clear();
        while let Some(Reverse((value, i))) = self.repair.pop() {
            if self.learned[i].to_bits() != value {
                continue; // lowered again since: queued again with that value
            }
            self.relax_into(graph, graph.node_at(i), i, false);
        }
    }
}

// The trait's signatures, as every replanner's; the answers (learning, repair) are Adaptive A*'s own.
impl<G, H, K: Memory> Replanner<G> for AdaptivePlanner<K, G::Node, H>
where
    G: Successors + Predecessors + IndexedGraph + ?Sized,
    H: Heuristic<G>,
{
    fn update_edges(
        &mut self,
        graph: &G,
        changes: &[EdgeChange<G::Node>],
    ) -> Result<(), SearchError<G::Node>> {
        self.base.update_edges(graph, changes)?;
        self.changed.extend(changes.iter().map(|c| (graph.index_of(c.from), graph.index_of(c.to))));
        Ok(())
    }

    fn update_nodes(&mut self, graph: &G, nodes: &[G::Node]) -> Result<(), SearchError<G::Node>> {
        self.base.update_nodes(graph, nodes)?;
        self.touched.extend(nodes.iter().map(|&n| graph.index_of(n)));
        Ok(())
    }

    fn move_start(&mut self, graph: &G, to: G::Node) -> Result<(), SearchError<G::Node>> {
        self.base.move_start(graph, to)
    }

    fn plan(&mut self, graph: &G) -> Result<SearchStats, SearchError<G::Node>> {
        // The repair may cut the kept path the last answer goes on along: a plan that fails
        // leaves no answer behind.
        (self.tail, self.base.path) = (None, None);
        self.restore_consistency(graph);
        let (start, goal) = (self.base.start(), self.base.goal());
        let goal_slot = graph.index_of(goal);
        let (learned, base) = (&self.learned, &mut self.base);
        let heuristic = &mut base.heuristic;
        let h = |n| Self::h_at(graph, learned, heuristic, n, graph.index_of(n), goal);
        let found = match self.reuse.as_mut().filter(|_| !learned.is_empty()) {
            None => base.search.astar(graph, start, goal, h)?,
            Some(reuse) => base
                .search
                .astar_until(graph, start, goal, h, |slot| reuse.reaches_goal(learned, slot, goal_slot))?,
        };
        let stats = found.stats;
        base.totals += stats;
        base.path = found.path.map(|mut path| {
            // Where the search stopped on a kept path, the path goes on along it (read out when
            // asked for), and so does its cost.
            let end = graph.index_of(path.nodes[path.nodes.len() - 1]);
            Self::make_room(&mut self.learned, &mut self.reuse, graph.node_bound());
            if end != goal_slot {
                path.cost += self.learned[end];
                self.tail = Some(end);
            }
            // Every expanded node learns the cost to the goal it is known to be at least.
            let (nodes, best) = (&base.search.nodes, path.cost);
            for &i in base.search.expanded_log.iter().flatten() {
                let i = i as usize;
                if i < self.learned.len() {
                    self.learned[i] = self.learned[i].max(best - nodes.g[i]);
                }
            }
            if let Some(reuse) = self.reuse.as_mut() {
                reuse.lay(graph, &mut self.learned, &path.nodes);
            }
            path
        });
        Ok(stats)
    }

    fn path(&self, graph: &G) -> Option<Path<G::Node>> {
        let mut path = self.base.path(graph)?;
        if let (Some(end), Some(reuse)) = (self.tail, &self.reuse) {
            reuse.extend(graph, &mut path, end, graph.index_of(self.base.goal()));
        }
        Some(path)
    }

    fn cost(&self) -> Option<Cost> {
        AdaptivePlanner::cost(self)
    }

    fn next_step(&self, graph: &G) -> Option<G::Node> {
        let searched = self.base.path.as_ref()?;
        match (searched.nodes.get(1), self.tail, &self.reuse) {
            (Some(&next), _, _) => Some(next),
            (None, Some(end), Some(reuse)) => reuse.next_of(end).map(|n| graph.node_at(n)),
            (None, _, _) => None,
        }
    }

    fn totals(&self) -> SearchStats {
        AdaptivePlanner::totals(self)
    }

    fn memory_bytes(&self) -> usize {
        AdaptivePlanner::memory_bytes(self)
    }
}
