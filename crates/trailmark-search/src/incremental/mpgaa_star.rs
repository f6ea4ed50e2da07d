//! MPGAA*: Adaptive A* that also reuses the paths of earlier plans (Multipath Generalized
//! Adaptive A*, Hernández, Baier and Asín, AAAI 2015).

use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::heuristic::Heuristic;
use crate::incremental::EdgeChange;
use crate::incremental::adaptive_astar::AdaptiveAStar;
use crate::incremental::path_reuse::PathReuse;
use crate::incremental::replanner::Replanner;
use crate::stats::SearchStats;

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
#[derive(Debug, Clone)]
pub struct MpgaaStar<N, H>(AdaptiveAStar<N, H>);

impl<N, H> MpgaaStar<N, H>
where
    N: Copy + Eq + std::hash::Hash + Debug,
{
    // AdaptiveAStar::new's public signature and documentation; it builds on that constructor.
    /// A planner from `start` to `goal`, with `heuristic(a, b)` a consistent estimate of the
    /// cost from `a` to `b` (the grid heuristics are). Nothing is searched until
    /// [`plan`](Replanner::plan). Errors when the start or the goal is not a node of the graph.
    pub fn new<G>(graph: &G, start: N, goal: N, heuristic: H) -> Result<Self, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let mut planner = AdaptiveAStar::new(graph, start, goal, heuristic)?;
        planner.reuse = Some(PathReuse::new());
        Ok(MpgaaStar(planner))
    }

    /// The start.
    pub fn start(&self) -> N {
        self.0.start()
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.0.goal()
    }

    /// The cost of the last plan's path (`None` without one).
    pub fn cost(&self) -> Option<Cost> {
        self.0.cost()
    }

    /// Counters summed over every plan since the planner was made.
    pub fn totals(&self) -> SearchStats {
        self.0.totals()
    }

    /// Bytes held by the search workspace, the learned heuristic and the kept paths.
    pub fn memory_bytes(&self) -> usize {
        self.0.memory_bytes()
    }
}

// The trait's signatures, as every replanner's; each answer is the wrapped AdaptiveAStar's.
impl<G, H> Replanner<G> for MpgaaStar<G::Node, H>
where
    G: Successors + Predecessors + IndexedGraph + ?Sized,
    H: Heuristic<G>,
{
    fn update_edges(
        &mut self,
        graph: &G,
        changes: &[EdgeChange<G::Node>],
    ) -> Result<(), SearchError<G::Node>> {
        self.0.update_edges(graph, changes)
    }

    fn update_nodes(&mut self, graph: &G, nodes: &[G::Node]) -> Result<(), SearchError<G::Node>> {
        self.0.update_nodes(graph, nodes)
    }

    fn move_start(&mut self, graph: &G, to: G::Node) -> Result<(), SearchError<G::Node>> {
        self.0.move_start(graph, to)
    }

    fn plan(&mut self, graph: &G) -> Result<SearchStats, SearchError<G::Node>> {
        self.0.plan(graph)
    }

    fn path(&self, graph: &G) -> Option<Path<G::Node>> {
        self.0.path(graph)
    }

    fn cost(&self) -> Option<Cost> {
        self.0.cost()
    }

    fn next_step(&self, graph: &G) -> Option<G::Node> {
        self.0.next_step(graph)
    }

    fn totals(&self) -> SearchStats {
        self.0.totals()
    }

    fn memory_bytes(&self) -> usize {
        self.0.memory_bytes()
    }
}
