//! The lifelong planner between a start and a goal that LPA*, D* Lite and AD* wrap: the repair
//! engine with the heuristic part of keys, the endpoints, and the checks of what the user tells.

use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::{SearchError, check_endpoints};
use crate::heuristic::{Heuristic, HeuristicCheck};
use crate::incremental::engine::{RepairEngine, SearchDirection, cost_error, valid_cost};
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
    pub engine: RepairEngine<N, M>,
    heuristic: H,
    pub start: N,
    start_slot: usize,
    pub goal: N,
    goal_slot: usize,
    /// The start when `k_m` was last brought up to date (backward only).
    last: N,
    pub k_m: Cost,
    /// The first invalid heuristic value met since the last report.
    heuristics: HeuristicCheck<N>,
    /// The first node whose heuristic part `h(start, s) + k_m` overflowed since the planner was
    /// made or reset (see [`RepairEngine::overflow`]).
    h_overflow: Option<N>,
}

impl<N, H, M> LifelongPlanner<N, H, M>
where
    N: Copy + Eq + std::hash::Hash + Debug,
    M: Mode,
{
    /// A planner in direction `dir` whose engine treats expanded nodes as `mode` says.
    pub fn new<G>(
        dir: SearchDirection,
        graph: &G,
        start: N,
        goal: N,
        heuristic: H,
        mode: M,
    ) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        check_endpoints(graph, start, goal)?;
        let source = if dir == SearchDirection::Backward { goal } else { start };
        let engine = RepairEngine::new(dir, graph, source, mode)?;
        let (start_slot, goal_slot) = (graph.index_of(start), graph.index_of(goal));
        let mut planner = LifelongPlanner {
            engine,
            heuristic,
            start,
            start_slot,
            goal,
            goal_slot,
            last: start,
            k_m: 0.0,
            heuristics: HeuristicCheck::new(),
            h_overflow: None,
        };
        let source = planner.engine.source;
        {
            let (engine, mut h) = planner.engine_with_heuristic(graph);
            engine.update_vertex(graph, source, &mut h);
        }
        planner.engine.take_call_stats(std::time::Duration::ZERO);
        Ok(planner)
    }

    /// A new query from `start` to `goal` with the planner's memory (see [`RepairEngine::reset`]).
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        check_endpoints(graph, start, goal)?;
        let source = if self.engine.dir == SearchDirection::Backward { goal } else { start };
        self.engine.reset(graph, source)?;
        (self.start, self.goal, self.last) = (start, goal, start);
        (self.start_slot, self.goal_slot) = (graph.index_of(start), graph.index_of(goal));
        self.k_m = 0.0;
        self.heuristics = HeuristicCheck::new();
        self.h_overflow = None;
        let source = self.engine.source;
        {
            let (engine, mut h) = self.engine_with_heuristic(graph);
            engine.update_vertex(graph, source, &mut h);
        }
        self.engine.take_call_stats(std::time::Duration::ZERO);
        Ok(())
    }

    /// The node whose value the search computes: the goal (forward) or the start (backward).
    fn target(&self) -> usize {
        match self.engine.dir {
            SearchDirection::Forward => self.goal_slot,
            SearchDirection::Backward => self.start_slot,
        }
    }

    /// The engine, with the heuristic part of its keys: `h(s, goal)` forward, `h(start, s) + k_m`
    /// backward (bringing `k_m` up to date first if the robot moved). Invalid heuristic values
    /// count as 0 and are remembered.
    ///
    /// Should `k_m` overflow (or a hostile heuristic make it infinite), it starts again from 0
    /// and every queued key is recomputed from the current start, which is what `k_m` exists to
    /// avoid, and exact.
    fn engine_with_heuristic<'a, G>(
        &'a mut self,
        graph: &'a G,
    ) -> (&'a mut RepairEngine<N, M>, impl FnMut(N) -> Cost + 'a)
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let LifelongPlanner { engine, heuristic, start, goal, last, k_m, heuristics, h_overflow, .. } = self;
        let backward = engine.dir == SearchDirection::Backward;
        let mut estimate = move |a: N, b: N| {
            heuristics.accept(if backward { b } else { a }, heuristic.estimate(graph, a, b)).unwrap_or(0.0)
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
            engine.rekey(graph, &mut h);
        }
        (engine, h)
    }

    pub fn compute<G>(
        &mut self,
        graph: &G,
        trace: impl FnMut(Expansion<N>),
    ) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
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
        H: Heuristic<G>,
    {
        let clock = std::time::Instant::now();
        check_endpoints(graph, self.start, self.goal)?;
        self.engine.fit(graph)?;
        let target = self.target();
        let complete = {
            let (engine, mut h) = self.engine_with_heuristic(graph);
            engine.compute(graph, target, &mut h, &mut trace, interrupt)
        };
        let stats = self.engine.take_call_stats(clock.elapsed());
        self.report()?;
        if let Some(node) = self.engine.overflow().or(self.h_overflow) {
            return Err(SearchError::CostOverflow { node });
        }
        Ok((complete, stats))
    }

    /// The first fault since the last report, as an error.
    fn report(&mut self) -> Result<(), SearchError<N>> {
        if let Some(e) = self.engine.take_fault() {
            self.heuristics = HeuristicCheck::new();
            return Err(e);
        }
        self.heuristics.take()
    }

    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        if !graph.contains(to) {
            return Err(SearchError::StartNotInGraph(to));
        }
        self.start_slot = self.engine.slot_of(graph, to)?;
        if to != self.start {
            // Backward, the heuristic part of every key is measured from the start.
            self.engine.keys_changed();
        }
        self.start = to;
        Ok(())
    }

    pub fn update_edges<G>(&mut self, graph: &G, changes: &[EdgeChange<N>]) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.engine.fit(graph)?;
        let slots = changes
            .iter()
            .map(|c| {
                let slots = (self.engine.slot_of(graph, c.from)?, self.engine.slot_of(graph, c.to)?);
                // The repair reads the new cost from the graph and needs no old one (see
                // `RepairEngine::edge_changed`).
                let new = edge_cost(graph, c.from, c.to);
                if !valid_cost(new) {
                    return Err(cost_error(c.from, c.to, new));
                }
                Ok((slots, new))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let backward = self.engine.dir == SearchDirection::Backward;
        {
            let (engine, mut h) = self.engine_with_heuristic(graph);
            for ((from, to), new) in slots {
                let (dependent, support) = if backward { (from, to) } else { (to, from) };
                engine.edge_changed(graph, dependent, support, new, &mut h);
            }
        }
        self.engine.take_call_stats(std::time::Duration::ZERO);
        self.report()
    }

    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<usize, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.engine.fit(graph)?;
        let slots =
            nodes.into_iter().map(|n| self.engine.slot_of(graph, n)).collect::<Result<Vec<_>, _>>()?;
        let told = slots.len();
        {
            let (engine, mut h) = self.engine_with_heuristic(graph);
            for slot in slots {
                engine.refresh(graph, slot, &mut h);
            }
        }
        self.engine.take_call_stats(std::time::Duration::ZERO);
        self.report().map(|()| told)
    }

    pub fn cost(&self) -> Option<Cost> {
        let g = self.engine.g(self.target());
        g.is_finite().then_some(g)
    }

    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.engine.path(graph, self.target(), self.cost()?)
    }

    /// The second node of the path (backward: the robot's next move).
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.cost()?;
        let target = self.target();
        if target == self.engine.source {
            return None;
        }
        self.engine.best_support(graph, target).map(|s| graph.node_at(s))
    }

    pub fn g<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.engine.g(self.engine.slot_of(graph, node)?))
    }

    pub fn rhs<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.engine.rhs(self.engine.slot_of(graph, node)?))
    }

    pub fn queue<G>(&self, graph: &G) -> Vec<(N, Key)>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.engine.queue().into_iter().map(|(s, k)| (graph.node_at(s), k)).collect()
    }
}

/// AD*'s iterations.
impl<N, H> LifelongPlanner<N, H, Anytime>
where
    N: Copy + Eq + std::hash::Hash + Debug,
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
        H: Heuristic<G>,
    {
        self.run(graph, |_| {}, interrupt)
    }

    /// AD*: starts a new iteration at inflation `epsilon` (see [`RepairEngine::next_iteration`]).
    pub fn next_iteration<G>(&mut self, graph: &G, epsilon: f64)
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.engine.set_epsilon(epsilon);
        let (engine, mut h) = self.engine_with_heuristic(graph);
        engine.next_iteration(graph, &mut h);
    }
}
