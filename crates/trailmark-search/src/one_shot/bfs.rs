//! Breadth-first search: the path with the fewest moves, whatever the edge costs.

use trailmark_core::graph::{IndexedGraph, Successors};

use crate::error::SearchError;
use crate::index::{Dense, NodeIndex};
use crate::one_shot::SearchResult;
use crate::one_shot::edges::EdgeCheck;
use crate::one_shot::workspace::{Search, ensure};
use crate::stats::SearchStats;

/// Breadth-first search from `start` to `goal`: a path with the fewest edges. Its reported cost
/// is the sum of the edge costs along it, which need not be the least cost; when that sum exceeds
/// the largest `f64`, the answer is [`SearchError::CostOverflow`](crate::SearchError::CostOverflow).
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::bfs;
///
/// let graph = GridGraph::new(&Grid::new(5, 5)?, Connectivity::Eight);
/// let found = bfs(&graph, Cell::new(0, 0), Cell::new(4, 2))?;
/// assert_eq!(found.path.unwrap().moves(), 4); // Chebyshev distance
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn bfs<G>(graph: &G, start: G::Node, goal: G::Node) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
{
    Search::<Dense>::new().bfs(graph, start, goal)
}

impl<I> Search<I> {
    /// Breadth-first search with this workspace; see [`bfs`](crate::bfs()).
    pub fn bfs<G>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
    {
        let query = self.begin(graph, start, goal)?;
        let (s, t, open, closed) = (query.start, query.goal, query.open, query.closed);
        let mut stats = SearchStats { pushes: 1, ..SearchStats::default() };
        self.fifo.push_back(s as u32);
        let mut edges = EdgeCheck::new();
        // The goal is recognised when it is reached: the first path to reach it is a shortest one.
        let mut found = (s == t).then_some(t);
        while found.is_none() {
            let Some(u) = self.fifo.pop_front() else { break };
            let u = u as usize;
            self.nodes.stamp[u] = closed;
            stats.expansions += 1;
            let gu = self.nodes.g[u];
            let (nodes, fifo) = (&mut self.nodes, &mut self.fifo);
            self.index.for_each_successor(graph, u, |v, next, cost| {
                if found.is_some() || !edges.accept(next, cost) {
                    return;
                }
                ensure(nodes, v);
                if nodes.stamp[v] >= open {
                    return;
                }
                nodes.reach(v, gu + cost, u, open);
                fifo.push_back(v as u32);
                stats.pushes += 1;
                if v == t {
                    found = Some(v);
                }
            });
            edges.check(|| self.index.node(graph, u))?;
        }
        self.check_path_cost(graph, found)?;
        Ok(self.finish(graph, &query, found, stats))
    }
}
