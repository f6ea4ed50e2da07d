//! D* Lite: replanning for a robot that moves while the graph changes.

use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::incremental::lifelong::{Costs, Lifelong};
use crate::incremental::replanner::replanner_by_inherent_methods;

/// D* Lite (Koenig and Likhachev, 2002), the optimized version: a search from the goal back to
/// the robot that repairs only what a change of edge costs or a move of the robot invalidates.
///
/// Keys are `[min(g, rhs) + h(start, s) + k_m; min(g, rhs)]`, where `g` and `rhs` are costs *to
/// the goal*; `k_m` grows by `h(last, start)` when the graph changes after the robot moved, so
/// queued keys stay valid lower bounds without being recomputed. The heuristic `h(a, b)` must
/// be a consistent lower bound on the cost from `a` to `b` (on grids,
/// `GridGraph::heuristic_between`).
///
/// The planner holds no reference to the graph: each call takes the graph as it is now. After
/// changing the graph, tell the planner which edges changed ([`DStarLite::update_edges`]: their
/// endpoints, no old costs) or which nodes had edges change ([`DStarLite::update_nodes`]), then call
/// [`DStarLite::compute_shortest_path`] again. Search state is dense, one slot per node index.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::DStarLite;
///
/// let grid = Grid::from_rows(&["......", "......", "......"])?;
/// let mut graph = GridGraph::new(&grid, Connectivity::Four);
/// let (start, goal) = (Cell::new(0, 1), Cell::new(5, 1));
/// let h = graph.heuristic_between(GridHeuristic::Manhattan);
/// let mut planner = DStarLite::new(&graph, start, goal, h)?;
/// planner.compute_shortest_path(&graph)?;
/// assert_eq!(planner.cost(), Some(5.0));
///
/// // The robot steps right, then sees a wall ahead in rows 0 and 1.
/// let next = planner.next_step(&graph).expect("a path exists");
/// planner.move_start(&graph, next)?;
/// for y in 0..2 {
///     graph.set_cost(Cell::new(3, y), f64::INFINITY)?;
///     planner.update_nodes(&graph, graph.cells_affected_by(Cell::new(3, y)))?;
/// }
/// let stats = planner.compute_shortest_path(&graph)?;
/// assert_eq!(planner.cost(), Some(6.0)); // down to row 2, along it, and back up
/// assert!(stats.expansions > 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type DStarLite<N, H> = Lifelong<CostsToGoal, N, H>;

/// D* Lite's values: costs to the goal, searched from the goal back to the robot.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CostsToGoal;

impl Costs for CostsToGoal {
    const TO_GOAL: bool = true;
}

impl<N, H> DStarLite<N, H>
where
    N: Copy + Eq + Hash + Debug,
{
    // D* Lite's own: its start moves with the robot.
    /// Moves the robot to `to` (usually [`next_step`](Self::next_step)). Cheap: the keys are
    /// adjusted when the graph next changes. Errors when `to` is not a node of the graph.
    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.move_start(graph, to)
    }

    /// The node the robot should move to next; `None` at the goal or when it is unreachable.
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.next_step(graph)
    }

    /// The key modifier `k_m`: the heuristic distances the robot covered, added up at each
    /// change of the graph.
    pub fn key_modifier(&self) -> Cost {
        self.planner.k_m
    }
}

replanner_by_inherent_methods!(DStarLite, plan: compute_shortest_path);
