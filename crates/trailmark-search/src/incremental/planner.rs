//! The lifelong planner between a start and a goal that LPA*, D* Lite and AD* wrap: the repair
//! engine with the heuristic part of keys, the endpoints, and the checks of what the user tells.

use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::incremental::engine::{Direction, RepairEngine, cost_error, valid_cost, valid_estimate};
use crate::incremental::mode::{Anytime, Exact, Mode};
use crate::incremental::{EdgeChange, Expansion, Key};
use crate::stats::SearchStats;

/// The cost of the edge `from -> to` in `graph` now (the least of parallel edges), `+inf` when
/// there is none; an invalid cost is returned as it is, for the caller to reject.
pub(crate) fn edge_cost<G>(graph: &G, from: G::Node, to: G::Node) -> Cost
where
    G: Successors + ?Sized,
{
    let mut cost = f64::INFINITY;
    if graph.contains(from) {
        graph.for_each_successor(from, |n, c| {
            // NaN replaces anything, so that the caller sees (and rejects) it.
            if n == to && (c < cost || c.is_nan()) {
                cost = c;
            }
        });
    }
    cost
}

/// A lifelong planner between a start and a goal: the repair engine, the heuristic, the
/// endpoints and D* Lite's key modifier. [`LpaStar`](crate::LpaStar) and
/// [`DStarLite`](crate::DStarLite) are this, forward and backward; [`AdStar`](crate::AdStar) is
/// this backward in the [`Anytime`] mode.
#[derive(Debug, Clone)]
pub(crate) struct LifelongPlanner<N: Debug, H, M = Exact> {
    pub search: RepairEngine<N, M>,
    heuristic: H,
    pub start: N,
    start_slot: usize,
    pub goal: N,
    goal_slot: usize,
    /// The start when `k_m` was last brought up to date (backward only).
    last: N,
    pub k_m: Cost,
    /// The first invalid heuristic value met since the last report.
    bad_h: Option<(N, Cost)>,
    /// The first node whose heuristic part `h(start, s) + k_m` overflowed since the planner was
    /// made or reset (see [`RepairEngine::overflow`]).
    h_overflow: Option<N>,
}

impl<N, H, M> LifelongPlanner<N, H, M>
where
    N: Copy + Eq + std::hash::Hash + Debug,
    H: FnMut(N, N) -> Cost,
    M: Mode,
{
    /// A planner in direction `dir` whose engine treats expanded nodes as `mode` says.
    pub fn new<G>(
        dir: Direction,
        graph: &G,
        start: N,
        goal: N,
        heuristic: H,
        mode: M,
    ) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        check_endpoints(graph, start, goal)?;
        let source = if dir == Direction::Backward { goal } else { start };
        let search = RepairEngine::new(dir, graph, source, mode)?;
        let (start_slot, goal_slot) = (graph.index_of(start), graph.index_of(goal));
        let mut planner = LifelongPlanner {
            search,
            heuristic,
            start,
            start_slot,
            goal,
            goal_slot,
            last: start,
            k_m: 0.0,
            bad_h: None,
            h_overflow: None,
        };
        let source = planner.search.source;
        {
            let (search, mut h) = planner.keyed(graph);
            search.update_vertex(graph, source, &mut h);
        }
        planner.search.close_call(std::time::Duration::ZERO);
        Ok(planner)
    }

    /// A new query from `start` to `goal` with the planner's memory (see [`RepairEngine::reset`]).
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        check_endpoints(graph, start, goal)?;
        let source = if self.search.dir == Direction::Backward { goal } else { start };
        self.search.reset(graph, source)?;
        (self.start, self.goal, self.last) = (start, goal, start);
        (self.start_slot, self.goal_slot) = (graph.index_of(start), graph.index_of(goal));
        self.k_m = 0.0;
        self.bad_h = None;
        self.h_overflow = None;
        let source = self.search.source;
        {
            let (search, mut h) = self.keyed(graph);
            search.update_vertex(graph, source, &mut h);
        }
        self.search.close_call(std::time::Duration::ZERO);
        Ok(())
    }

    /// The node whose value the search computes: the goal (forward) or the start (backward).
    fn target(&self) -> usize {
        match self.search.dir {
            Direction::Forward => self.goal_slot,
            Direction::Backward => self.start_slot,
        }
    }

    /// The search, with the heuristic part of keys: `h(s, goal)` forward, `h(start, s) + k_m`
    /// backward (bringing `k_m` up to date first if the robot moved). Invalid heuristic values
    /// count as 0 and are remembered.
    ///
    /// Should `k_m` overflow (or a hostile heuristic make it infinite), it starts again from 0
    /// and every queued key is recomputed from the current start, which is what `k_m` exists to
    /// avoid, and exact.
    fn keyed<G>(&mut self, graph: &G) -> (&mut RepairEngine<N, M>, impl FnMut(N) -> Cost + '_)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let LifelongPlanner { search, heuristic, start, goal, last, k_m, bad_h, h_overflow, .. } = self;
        let backward = search.dir == Direction::Backward;
        let mut estimate = move |a: N, b: N| {
            let v = heuristic(a, b);
            if valid_estimate(v) {
                v
            } else {
                bad_h.get_or_insert((if backward { b } else { a }, v));
                0.0
            }
        };
        let mut rekey = false;
        if backward && M::KEY_MODIFIER && *last != *start {
            let moved = *k_m + estimate(*last, *start);
            if moved.is_finite() {
                *k_m = moved;
            } else {
                *k_m = 0.0;
                rekey = true;
            }
            *last = *start;
        }
        let (start, goal, k_m) = (*start, *goal, *k_m);
        let mut h = move |s: N| {
            if backward {
                let v = estimate(start, s);
                let sum = v + k_m;
                if sum == f64::INFINITY && v < f64::INFINITY {
                    h_overflow.get_or_insert(s);
                }
                sum
            } else {
                estimate(s, goal)
            }
        };
        if rekey {
            search.rekey(graph, &mut h);
        }
        (search, h)
    }

    pub fn compute<G>(
        &mut self,
        graph: &G,
        trace: impl FnMut(Expansion<N>),
    ) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.run(graph, trace, &mut |_| false).map(|(_, stats)| stats)
    }

    /// The repair loop from the current start, with its checks, statistics and error report.
    fn run<G>(
        &mut self,
        graph: &G,
        mut trace: impl FnMut(Expansion<N>),
        interrupt: &mut impl FnMut(u64) -> bool,
    ) -> Result<(bool, SearchStats), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let clock = std::time::Instant::now();
        check_endpoints(graph, self.start, self.goal)?;
        self.search.fit(graph)?;
        let target = self.target();
        let complete = {
            let (search, mut h) = self.keyed(graph);
            search.compute(graph, target, &mut h, &mut trace, interrupt)
        };
        let stats = self.search.close_call(clock.elapsed());
        self.report()?;
        if let Some(node) = self.search.overflow().or(self.h_overflow) {
            return Err(SearchError::CostOverflow { node });
        }
        Ok((complete, stats))
    }

    /// The first fault since the last report, as an error.
    fn report(&mut self) -> Result<(), SearchError<N>> {
        if let Some(e) = self.search.take_fault() {
            self.bad_h = None;
            return Err(e);
        }
        match self.bad_h.take() {
            Some((node, value)) => Err(SearchError::InvalidHeuristic { node, value }),
            None => Ok(()),
        }
    }

    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        if !graph.contains(to) {
            return Err(SearchError::StartNotInGraph(to));
        }
        self.start_slot = self.search.slot_of(graph, to)?;
        if to != self.start {
            // Backward, the heuristic part of every key is measured from the start.
            self.search.keys_changed();
        }
        self.start = to;
        Ok(())
    }

    pub fn update_edges<G>(&mut self, graph: &G, changes: &[EdgeChange<N>]) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.fit(graph)?;
        let slots = changes
            .iter()
            .map(|c| {
                let slots = (self.search.slot_of(graph, c.from)?, self.search.slot_of(graph, c.to)?);
                let new = edge_cost(graph, c.from, c.to);
                // The old cost is checked (one that cannot be a cost says the caller is confused)
                // but not used: the repair reads the graph (see `RepairEngine::edge_changed`).
                for cost in [c.old_cost, new] {
                    if !valid_cost(cost) {
                        return Err(cost_error(c.from, c.to, cost));
                    }
                }
                Ok((slots, new))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let backward = self.search.dir == Direction::Backward;
        {
            let (search, mut h) = self.keyed(graph);
            for ((from, to), new) in slots {
                let (dependent, support) = if backward { (from, to) } else { (to, from) };
                search.edge_changed(graph, dependent, support, new, &mut h);
            }
        }
        self.search.close_call(std::time::Duration::ZERO);
        self.report()
    }

    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<usize, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.fit(graph)?;
        let slots =
            nodes.into_iter().map(|n| self.search.slot_of(graph, n)).collect::<Result<Vec<_>, _>>()?;
        let told = slots.len();
        {
            let (search, mut h) = self.keyed(graph);
            for slot in slots {
                search.refresh(graph, slot, &mut h);
            }
        }
        self.search.close_call(std::time::Duration::ZERO);
        self.report().map(|()| told)
    }

    pub fn cost(&self) -> Option<Cost> {
        let g = self.search.g(self.target());
        g.is_finite().then_some(g)
    }

    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.path(graph, self.target(), self.cost()?)
    }

    /// The second node of the path (backward: the robot's next move).
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.cost()?;
        let target = self.target();
        if target == self.search.source {
            return None;
        }
        self.search.best_support(graph, target).map(|s| graph.node_at(s))
    }

    pub fn g<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.search.g(self.search.slot_of(graph, node)?))
    }

    pub fn rhs<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.search.rhs(self.search.slot_of(graph, node)?))
    }

    pub fn queue<G>(&self, graph: &G) -> Vec<(N, Key)>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.search.queue().into_iter().map(|(s, k)| (graph.node_at(s), k)).collect()
    }
}

/// Errors unless both endpoints are nodes of the graph.
pub(crate) fn check_endpoints<G>(graph: &G, start: G::Node, goal: G::Node) -> Result<(), SearchError<G::Node>>
where
    G: IndexedGraph + ?Sized,
{
    if !graph.contains(start) {
        return Err(SearchError::StartNotInGraph(start));
    }
    if !graph.contains(goal) {
        return Err(SearchError::GoalNotInGraph(goal));
    }
    Ok(())
}

/// AD*'s iterations.
impl<N, H> LifelongPlanner<N, H, Anytime>
where
    N: Copy + Eq + std::hash::Hash + Debug,
    H: FnMut(N, N) -> Cost,
{
    /// AD*: one pass of the repair loop at the current inflation, from the current start,
    /// stopped early when `interrupt(expansions)` says so. Returns whether the pass completed,
    /// and the pass's statistics.
    pub fn compute_interruptible<G>(
        &mut self,
        graph: &G,
        interrupt: &mut impl FnMut(u64) -> bool,
    ) -> Result<(bool, SearchStats), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.run(graph, |_| {}, interrupt)
    }

    /// AD*: starts a new iteration at inflation `epsilon` (see [`RepairEngine::next_iteration`]).
    pub fn next_iteration<G>(&mut self, graph: &G, epsilon: f64)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.search.set_epsilon(epsilon);
        let (search, mut h) = self.keyed(graph);
        search.next_iteration(graph, &mut h);
    }
}
