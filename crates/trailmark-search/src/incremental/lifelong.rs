//! D* Lite and LPA*: one lifelong planner (Koenig and Likhachev), its values costs to the goal
//! or from the start. [`DStarLite`](crate::DStarLite) and [`LpaStar`](crate::LpaStar) are the
//! two kinds of [`Lifelong`]; each kind's own methods (how the start moves, the next step) are
//! in its file.

use std::fmt::Debug;
use std::hash::Hash;
use std::marker::PhantomData;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::incremental::engine::SearchDirection;
use crate::incremental::planner::LifelongPlanner;

/// What a [`Lifelong`] planner's values are: costs to the goal, searched from the goal back to a
/// moving robot ([`CostsToGoal`](crate::CostsToGoal): D* Lite), or costs from the start
/// ([`CostsFromStart`](crate::CostsFromStart): LPA*).
pub trait Costs: Clone + Debug + Default {
    /// Whether the values are costs to the goal.
    const TO_GOAL: bool;
}

/// The direction a planner whose values are `K` searches in.
fn direction<K: Costs>() -> SearchDirection {
    if K::TO_GOAL { SearchDirection::Backward } else { SearchDirection::Forward }
}

/// A lifelong planner: a search that, after edge costs change, repairs its previous search
/// instead of starting over. Its values `K` say which way it searches; [`DStarLite`](crate::DStarLite)
/// and [`LpaStar`](crate::LpaStar) are its two kinds.
#[derive(Debug, Clone)]
pub struct Lifelong<K, N: Debug, H> {
    pub(crate) planner: LifelongPlanner<N, H>,
    costs: PhantomData<K>,
}

impl<K: Costs, N, H> Lifelong<K, N, H>
where
    N: Copy + Eq + Hash + Debug,
{
    /// A planner from `start` to `goal`, with `heuristic(a, b)` a consistent lower bound on
    /// the cost from `a` to `b`. Nothing is searched until
    /// [`compute_shortest_path`](Self::compute_shortest_path).
    ///
    /// Errors when the start or the goal is not a node of the graph.
    pub fn new<G>(graph: &G, start: N, goal: N, heuristic: H) -> Result<Self, crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        let mode = crate::incremental::mode::Exact;
        let planner = crate::incremental::planner::LifelongPlanner::new(
            direction::<K>(),
            graph,
            start,
            goal,
            heuristic,
            mode,
        )?;
        Ok(Self { planner, costs: PhantomData })
    }

    /// Starts a new query from `start` to `goal`, keeping the planner's memory: a planner
    /// reused for many queries pays, at each reset, for the nodes the previous query touched
    /// rather than for the whole graph. Errors as [`new`](Self::new) does.
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        self.planner.reset(graph, start, goal)
    }

    /// Expands nodes until the cost between the start and the goal is known: the first
    /// search, or the repair after what changed since (edge costs and, for D* Lite, the
    /// start). Returns this call's statistics (expansions, queue insertions, key updates,
    /// time).
    ///
    /// Errors when the start or the goal is no longer a node (it was blocked), or when an
    /// edge cost or a heuristic value met was negative or NaN; the search then treated that
    /// edge as absent (that value as 0), and it stays usable: fix the graph, tell the
    /// planner, call again. Errors with [`SearchError::CostOverflow`](crate::SearchError::CostOverflow)
    /// once a cost or key overflowed (finite costs summing past the largest `f64`), at this
    /// and every later call until [`reset`](Self::reset): such a value is stored as `+inf`,
    /// so "no path" could be false.
    pub fn compute_shortest_path<G>(&mut self, graph: &G) -> Result<crate::SearchStats, crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        self.planner.compute(graph, |_| {})
    }

    /// [`compute_shortest_path`](Self::compute_shortest_path), calling `trace` with each node
    /// expanded and its key, in order.
    pub fn compute_shortest_path_traced<G>(
        &mut self,
        graph: &G,
        trace: impl FnMut(crate::Expansion<N>),
    ) -> Result<crate::SearchStats, crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        self.planner.compute(graph, trace)
    }

    /// Tells the planner that these edges changed cost (the graph already has the new
    /// costs). All are checked before any is applied: a node that names nothing, or a new
    /// cost in the graph that is negative or NaN, is an error and the planner is left as it
    /// was.
    ///
    /// The old cost is not needed: the repair reads each edge's cost from the graph, and
    /// when the edge could have been the best way out of its node before, recomputes that
    /// node's value from all of its edges.
    pub fn update_edges<G>(
        &mut self,
        graph: &G,
        changes: &[crate::EdgeChange<N>],
    ) -> Result<(), crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        self.planner.update_edges(graph, changes)
    }

    /// The cost of a shortest path from the start to the goal as of the last
    /// [`compute_shortest_path`](Self::compute_shortest_path); `None` when the goal is
    /// unreachable or nothing was computed yet.
    pub fn cost(&self) -> Option<Cost> {
        self.planner.cost()
    }

    /// The queued (inconsistent) nodes with their keys, least key first.
    pub fn queue<G>(&self, graph: &G) -> Vec<(N, crate::Key)>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.queue(graph)
    }

    /// Counters summed over every call since the planner was made.
    pub fn totals(&self) -> crate::SearchStats {
        self.planner.engine.totals
    }

    /// Bytes held by the planner's state and queue.
    pub fn memory_bytes(&self) -> usize {
        self.planner.engine.memory_bytes()
    }

    /// Tells the planner that edges at these nodes changed, in whatever way: each node's `rhs`
    /// is recomputed from its current edges: its out-edges for D* Lite (whose values are costs
    /// to the goal), its in-edges for LPA* (costs from the start). Name every node with such an
    /// edge that changed (after `GridGraph::set_cost(cell, ..)`, the cells of
    /// `GridGraph::cells_affected_by(cell)`). Nodes are checked first, as in
    /// [`update_edges`](Self::update_edges).
    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<(), crate::SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: crate::Heuristic<G>,
    {
        self.planner.update_nodes(graph, nodes).map(|_| ())
    }

    /// A shortest path from the start to the goal: for D* Lite following the best successor from
    /// each node, for LPA* traced back from the goal along the best predecessors.
    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.path(graph)
    }

    /// The start: where the path begins (for D* Lite, the robot's current node).
    pub fn start(&self) -> N {
        self.planner.start
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.planner.goal
    }

    /// `g` of `node`, when last expanded (`+inf` if never): its cost to the goal for D* Lite,
    /// from the start for LPA*.
    pub fn g<G>(&self, graph: &G, node: N) -> Result<Cost, crate::SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.g(graph, node)
    }

    /// `rhs` of `node`: for D* Lite `min over successors s of c(node, s) + g(s)` (0 at the goal),
    /// for LPA* `min over predecessors p of g(p) + c(p, node)` (0 at the start).
    pub fn rhs<G>(&self, graph: &G, node: N) -> Result<Cost, crate::SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.rhs(graph, node)
    }
}
