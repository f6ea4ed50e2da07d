//! LPA*: shortest paths between a fixed start and goal, repaired as edge costs change.

use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::heuristic::Heuristic;
use crate::incremental::engine::SearchDirection;
use crate::incremental::planner::{LifelongPlanner, shared_lifelong_methods};
use crate::incremental::replanner::replanner_by_inherent_methods;

/// Lifelong Planning A* (Koenig, Likhachev and Furcy, 2004): A* that, after edge costs change,
/// repairs its previous search instead of starting over, expanding only the nodes whose cost
/// from the start changed (and their heuristic focus).
///
/// Keys are `[min(g, rhs) + h(s, goal); min(g, rhs)]`, with `g` and `rhs` costs *from the
/// start*. The heuristic `h(a, b)` must be a consistent lower bound on the cost from `a` to `b`
/// (on grids, `GridGraph::heuristic_between`). The values are costs from the start, so moving
/// the start ([`move_start`](Self::move_start)) starts over; a robot that moves is better served
/// by [`DStarLite`](crate::DStarLite), which searches from the goal.
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
{
    shared_lifelong_methods!(SearchDirection::Forward);

    // Below, DStarLite's alike methods mean other things (out-edges, costs to the goal): not shared.
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
        H: Heuristic<G>,
    {
        self.planner.update_nodes(graph, nodes).map(|_| ())
    }

    /// A shortest path from the start to the goal, traced back from the goal along the best
    /// predecessors.
    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.path(graph)
    }

    /// Moves the start to `to`. A forward search cannot keep its values when its start moves
    /// (they are costs from the start), so this starts a new query from `to` to the goal, as
    /// [`reset`](Self::reset) does, keeping the planner's memory; the same start changes
    /// nothing. Errors when `to` is not a node of the graph.
    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        if to == self.planner.start {
            return Ok(());
        }
        let goal = self.planner.goal;
        self.planner.reset(graph, to, goal)
    }

    /// The node after the start on the [`path`](Self::path); `None` at the goal or when it is
    /// unreachable.
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.path(graph)?.nodes.get(1).copied()
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
}

replanner_by_inherent_methods!(LpaStar, plan: compute_shortest_path);
