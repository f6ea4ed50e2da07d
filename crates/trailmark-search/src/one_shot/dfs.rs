//! Depth-first search: some path, found by always extending the most recently reached node.

use trailmark_core::graph::{IndexedGraph, Successors};

use crate::error::SearchError;
use crate::index::{Dense, NodeIndex};
use crate::one_shot::SearchResult;
use crate::one_shot::edges::EdgeCheck;
use crate::one_shot::workspace::{Search, ensure};
use crate::stats::SearchStats;

/// Depth-first search from `start` to `goal`: a path if one exists, usually far from the
/// shortest. Uses an explicit stack, so deep graphs cannot overflow the call stack. A path whose
/// cost exceeds the largest `f64` is a [`SearchError::CostOverflow`](crate::SearchError::CostOverflow).
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::dfs;
///
/// let graph = GridGraph::new(&Grid::from_rows(&["...", "@@.", "..."])?, Connectivity::Four);
/// let path = dfs(&graph, Cell::new(0, 0), Cell::new(0, 2))?.path.unwrap();
/// assert_eq!(path.start(), Some(Cell::new(0, 0)));
/// assert_eq!(path.goal(), Some(Cell::new(0, 2)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn dfs<G>(graph: &G, start: G::Node, goal: G::Node) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
{
    Search::<Dense>::new().dfs(graph, start, goal)
}

impl<I> Search<I> {
    /// Depth-first search with this workspace; see [`dfs`](crate::dfs()).
    pub fn dfs<G>(
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
        self.stack.push(s as u32);
        let mut edges = EdgeCheck::new();
        let mut found = None;
        // A node may be on the stack several times; its parent is the one that pushed it last,
        // which is the entry popped first. Later entries for a closed node are skipped.
        while let Some(u) = self.stack.pop() {
            let u = u as usize;
            if self.nodes.stamp[u] == closed {
                continue;
            }
            if u == t {
                found = Some(u);
                break;
            }
            self.nodes.stamp[u] = closed;
            stats.expansions += 1;
            let gu = self.nodes.g[u];
            let (nodes, stack) = (&mut self.nodes, &mut self.stack);
            self.index.for_each_successor(graph, u, |v, next, cost| {
                if !edges.accept(next, cost) {
                    return;
                }
                ensure(nodes, v);
                if nodes.stamp[v] == closed {
                    return;
                }
                nodes.reach(v, gu + cost, u, open);
                stack.push(v as u32);
                stats.pushes += 1;
            });
            edges.check(|| self.index.node(graph, u))?;
        }
        self.check_path_cost(graph, found)?;
        Ok(self.finish(graph, &query, found, stats))
    }
}
