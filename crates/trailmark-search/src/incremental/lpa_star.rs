//! LPA*: shortest paths between a fixed start and goal, repaired as edge costs change.

use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::incremental::engine::Direction;
use crate::incremental::mode::Exact;
use crate::incremental::planner::LifelongPlanner;
use crate::incremental::{EdgeChange, Expansion, Key};
use crate::stats::SearchStats;

/// Lifelong Planning A* (Koenig, Likhachev and Furcy, 2004): A* that, after edge costs change,
/// repairs its previous search instead of starting over, expanding only the nodes whose cost
/// from the start changed (and their heuristic focus).
///
/// Keys are `[min(g, rhs) + h(s, goal); min(g, rhs)]`, with `g` and `rhs` costs *from the
/// start*. The heuristic `h(a, b)` must be a consistent lower bound on the cost from `a` to `b`
/// (on grids, `GridGraph::heuristic_between`). The start and goal are fixed: a robot that moves
/// makes a new planner (or uses [`DStarLite`](crate::DStarLite), which searches from the goal).
///
/// As with D* Lite, the planner holds no reference to the graph: change the graph, tell the
/// planner ([`LpaStar::update_edges`] or [`LpaStar::update_nodes`]), compute again.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::LpaStar;
///
/// let grid = Grid::from_rows(&[".....", ".....", "....."])?;
/// let mut graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(0, 1), Cell::new(4, 1));
/// let mut planner = LpaStar::new(&graph, start, goal, graph.heuristic_between(GridHeuristic::Octile))?;
/// planner.compute_shortest_path(&graph)?;
/// assert_eq!(planner.cost(), Some(4.0));
///
/// // Block the middle cell: the planner repairs around it.
/// let middle = Cell::new(2, 1);
/// graph.set_cost(middle, f64::INFINITY)?;
/// planner.update_nodes(&graph, graph.cells_affected_by(middle))?;
/// planner.compute_shortest_path(&graph)?;
/// assert_eq!(planner.cost(), Some(2.0 + 2.0 * std::f64::consts::SQRT_2));
/// assert!(!planner.path(&graph).unwrap().nodes.contains(&middle));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct LpaStar<N: Debug, H> {
    planner: LifelongPlanner<N, H>,
}

impl<N, H> LpaStar<N, H>
where
    N: Copy + Eq + Hash + Debug,
    H: FnMut(N, N) -> Cost,
{
    /// A planner from `start` to `goal`, with `heuristic(a, b)` a consistent lower bound on the
    /// cost from `a` to `b`. Nothing is searched until
    /// [`compute_shortest_path`](Self::compute_shortest_path).
    ///
    /// Errors when the start or the goal is not a node of the graph.
    pub fn new<G>(graph: &G, start: N, goal: N, heuristic: H) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        Ok(LpaStar {
            planner: LifelongPlanner::new(Direction::Forward, graph, start, goal, heuristic, Exact)?,
        })
    }

    /// Starts a new query from `start` to `goal`, keeping the planner's memory: a planner
    /// reused for many queries pays, at each reset, for the nodes the previous query touched
    /// rather than for the whole graph. Errors as [`new`](Self::new) does.
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.reset(graph, start, goal)
    }

    /// Expands nodes until the cost to the goal is known: the first search, or the repair
    /// after changes. Returns this call's statistics (expansions, queue insertions,
    /// key updates, time).
    ///
    /// Errors when the start or the goal is no longer a node (it was blocked), or when an edge
    /// cost or a heuristic value met was negative or NaN; the search then treated that edge as
    /// absent (that value as 0), and it stays usable: fix the graph, tell the planner, call again.
    /// Errors with [`SearchError::CostOverflow`] once a cost or key overflowed (finite costs
    /// summing past the largest `f64`), at this and every later call until [`reset`](Self::reset):
    /// such a value is stored as `+inf`, so "no path" could be false.
    pub fn compute_shortest_path<G>(&mut self, graph: &G) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.compute(graph, |_| {})
    }

    /// [`compute_shortest_path`](Self::compute_shortest_path), calling `trace` with each node
    /// expanded and its key, in order.
    pub fn compute_shortest_path_traced<G>(
        &mut self,
        graph: &G,
        trace: impl FnMut(Expansion<N>),
    ) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.compute(graph, trace)
    }

    /// Tells the planner that these edges changed cost (the graph already has the new costs).
    /// All are checked before any is applied: a node that names nothing, or an old cost that is
    /// negative, zero or NaN, is an error and the planner is left as it was.
    ///
    /// The repair does not rely on [`EdgeChange::old_cost`]: it reads each edge's cost from the
    /// graph, and when the edge could have been the best way out of its node before, recomputes
    /// that node's value from all of its edges. A wrong (but valid) old cost therefore costs at
    /// most a little work, never a wrong path cost.
    pub fn update_edges<G>(&mut self, graph: &G, changes: &[EdgeChange<N>]) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.update_edges(graph, changes)
    }

    /// Tells the planner that edges entering these nodes changed, in whatever way: each node's
    /// `rhs` is recomputed from its current in-edges. Name every node with an in-edge that
    /// changed (after `GridGraph::set_cost(cell, ..)`, the cells of
    /// `GridGraph::cells_affected_by(cell)`). Nodes are checked first, as in
    /// [`update_edges`](Self::update_edges).
    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.update_nodes(graph, nodes).map(|_| ())
    }

    /// The cost of a shortest path from the start to the goal as of the last
    /// [`compute_shortest_path`](Self::compute_shortest_path); `None` when the goal is
    /// unreachable or nothing was computed yet.
    pub fn cost(&self) -> Option<Cost> {
        self.planner.cost()
    }

    /// A shortest path from the start to the goal, traced back from the goal along the best
    /// predecessors.
    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.path(graph)
    }

    /// The start.
    pub fn start(&self) -> N {
        self.planner.start
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.planner.goal
    }

    /// `g` of `node`: its cost from the start when last expanded (`+inf` if never).
    pub fn g<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.g(graph, node)
    }

    /// `rhs` of `node`: `min over predecessors p of g(p) + c(p, node)` (0 at the start).
    pub fn rhs<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.rhs(graph, node)
    }

    /// The queued (inconsistent) nodes with their keys, least key first.
    pub fn queue<G>(&self, graph: &G) -> Vec<(N, Key)>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.queue(graph)
    }

    /// Counters summed over every call since the planner was made.
    pub fn totals(&self) -> SearchStats {
        self.planner.search.totals
    }

    /// Bytes held by the planner's state and queue.
    pub fn memory_bytes(&self) -> usize {
        self.planner.search.memory_bytes()
    }
}
