//! A* from scratch at every plan: the baseline every replanner is measured against.

use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::{SearchError, check_endpoints};
use crate::heuristic::Heuristic;
use crate::incremental::EdgeChange;
use crate::incremental::replanner::Replanner;
use crate::one_shot::workspace::Search;
use crate::stats::SearchStats;

/// A* from scratch at every plan, behind the [`Replanner`] interface: what an incremental
/// planner must beat. It keeps one [`Search`] workspace, so a plan costs the nodes it expands,
/// not the size of the graph, and breaks ties toward larger `g` as [`astar`](crate::astar())
/// does. Changes told are only checked: each plan reads the graph afresh.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{RepeatedAStar, Replanner};
///
/// let graph = GridGraph::new(&Grid::from_rows(&["....", ".@@.", "...."])?, Connectivity::Eight);
/// let h = graph.heuristic_between(GridHeuristic::Octile);
/// let mut planner = RepeatedAStar::new(&graph, Cell::new(0, 0), Cell::new(3, 2), h)?;
/// planner.plan(&graph)?;
/// assert_eq!(planner.cost(), Some(5.0));
/// planner.move_start(&graph, Cell::new(0, 1))?;
/// planner.plan(&graph)?;
/// assert_eq!(planner.next_step(&graph), Some(Cell::new(0, 2)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct RepeatedAStar<N, H> {
    pub(crate) search: Search,
    pub(crate) heuristic: H,
    start: N,
    goal: N,
    /// The last plan's path.
    pub(crate) path: Option<Path<N>>,
    pub(crate) totals: SearchStats,
}

impl<N, H> RepeatedAStar<N, H>
where
    N: Copy + Eq + std::hash::Hash + Debug,
{
    // AdaptiveAStar and MpgaaStar take the same public signature and build on this constructor.
    /// A planner from `start` to `goal`, with `heuristic(a, b)` an admissible estimate of the
    /// cost from `a` to `b`. Nothing is searched until [`plan`](Replanner::plan). Errors when
    /// the start or the goal is not a node of the graph.
    pub fn new<G>(graph: &G, start: N, goal: N, heuristic: H) -> Result<Self, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        check_endpoints(graph, start, goal)?;
        Ok(RepeatedAStar {
            search: Search::new(),
            heuristic,
            start,
            goal,
            path: None,
            totals: SearchStats::default(),
        })
    }

    /// The start.
    pub fn start(&self) -> N {
        self.start
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.goal
    }

    /// The cost of the last plan's path (`None` without one).
    pub fn cost(&self) -> Option<Cost> {
        self.path.as_ref().map(|p| p.cost)
    }

    /// Counters summed over every plan since the planner was made.
    pub fn totals(&self) -> SearchStats {
        self.totals
    }

    /// Bytes held by the search workspace.
    pub fn memory_bytes(&self) -> usize {
        self.search.memory_bytes()
    }
}

/// Errors unless every node names a node index of the graph (as the incremental planners
/// check what they are told).
fn check_named<G>(graph: &G, nodes: impl IntoIterator<Item = G::Node>) -> Result<(), SearchError<G::Node>>
where
    G: IndexedGraph + ?Sized,
{
    match nodes.into_iter().find(|&n| graph.checked_index(n).is_none()) {
        Some(n) => Err(SearchError::UnknownNode(n)),
        None => Ok(()),
    }
}

// The trait's signatures, as every replanner's; the answers are A* from scratch's own.
impl<G, H> Replanner<G> for RepeatedAStar<G::Node, H>
where
    G: Successors + Predecessors + IndexedGraph + ?Sized,
    H: Heuristic<G>,
{
    fn update_edges(
        &mut self,
        graph: &G,
        changes: &[EdgeChange<G::Node>],
    ) -> Result<(), SearchError<G::Node>> {
        check_named(graph, changes.iter().flat_map(|c| [c.from, c.to]))
    }

    fn update_nodes(&mut self, graph: &G, nodes: &[G::Node]) -> Result<(), SearchError<G::Node>> {
        check_named(graph, nodes.iter().copied())
    }

    fn move_start(&mut self, graph: &G, to: G::Node) -> Result<(), SearchError<G::Node>> {
        if !graph.contains(to) {
            return Err(SearchError::StartNotInGraph(to));
        }
        self.start = to;
        Ok(())
    }

    fn plan(&mut self, graph: &G) -> Result<SearchStats, SearchError<G::Node>> {
        let (heuristic, goal) = (&mut self.heuristic, self.goal);
        let found = self.search.astar(graph, self.start, goal, |n| heuristic.estimate(graph, n, goal))?;
        let stats = found.stats;
        self.path = found.path;
        self.totals += stats;
        Ok(stats)
    }

    fn path(&self, _graph: &G) -> Option<Path<G::Node>> {
        self.path.clone()
    }

    fn cost(&self) -> Option<Cost> {
        RepeatedAStar::cost(self)
    }

    fn next_step(&self, _graph: &G) -> Option<G::Node> {
        self.path.as_ref().and_then(|p| p.nodes.get(1).copied())
    }

    fn totals(&self) -> SearchStats {
        RepeatedAStar::totals(self)
    }

    fn memory_bytes(&self) -> usize {
        RepeatedAStar::memory_bytes(self)
    }
}
