//! MPGAA*: Adaptive A* that also reuses the paths of earlier plans (Multipath Generalized
//! Adaptive A*, Hernández, Baier and Asín, AAAI 2015).

#[cfg(doc)]
use crate::incremental::adaptive_astar::AdaptiveAStar;
use crate::incremental::adaptive_astar::{AdaptivePlanner, Memory};
#[cfg(doc)]
use crate::incremental::replanner::Replanner;

/// MPGAA* from a moving start to a fixed goal, behind the [`Replanner`] interface.
///
/// Each plan is [`AdaptiveAStar`]'s (A* from the robot with the heuristic learned from earlier
/// plans, kept consistent when costs rise and fall), and it also ends at the first node taken
/// off the open list from which an earlier path still leads to the goal at exactly its learned
/// cost. A robot that follows its plan and senses nothing new then plans without expanding a
/// node; when a cost changes, the search stops where it meets the part of the old path that is
/// still good. The path costs what A* from scratch finds.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{MpgaaStar, Replanner, astar};
///
/// let mut graph = GridGraph::new(&Grid::new(32, 32)?, Connectivity::Eight);
/// let (start, goal) = (Cell::new(0, 0), Cell::new(31, 20));
/// let h = graph.heuristic_between(GridHeuristic::Octile);
/// let mut planner = MpgaaStar::new(&graph, start, goal, h)?;
/// planner.plan(&graph)?;
/// // The robot takes the first step of its plan: the next plan follows the same path.
/// let step = planner.next_step(&graph).expect("a path");
/// planner.move_start(&graph, step)?;
/// assert_eq!(planner.plan(&graph)?.expansions, 0);
/// // A wall appears across the way: the next plan searches until it meets the old path.
/// for y in 0..25 {
///     graph.set_cost(Cell::new(16, y), f64::INFINITY)?;
///     planner.update_nodes(&graph, &graph.cells_affected_by(Cell::new(16, y)).collect::<Vec<_>>())?;
/// }
/// planner.plan(&graph)?;
/// let fresh = astar(&graph, step, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
/// assert_eq!(planner.cost(), fresh.cost()); // the least cost, as A* from scratch
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type MpgaaStar<N, H> = AdaptivePlanner<ReusePaths, N, H>;

/// MPGAA*'s memory: the learned heuristic and the paths of earlier plans.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ReusePaths;

impl Memory for ReusePaths {
    const REUSES_PATHS: bool = true;
}
