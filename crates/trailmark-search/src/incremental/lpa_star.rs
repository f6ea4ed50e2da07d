//! LPA*: shortest paths between a fixed start and goal, repaired as edge costs change.

use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::heuristic::Heuristic;
use crate::incremental::lifelong::{Costs, Lifelong};
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
pub type LpaStar<N, H> = Lifelong<CostsFromStart, N, H>;

/// LPA*'s values: costs from the start.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CostsFromStart;

impl Costs for CostsFromStart {
    const TO_GOAL: bool = false;
}

impl<N, H> LpaStar<N, H>
where
    N: Copy + Eq + Hash + Debug,
{
    // LPA*'s own: a moved start is a new query.
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
}

replanner_by_inherent_methods!(LpaStar, plan: compute_shortest_path);
