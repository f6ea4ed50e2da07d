//! Uninformed search: breadth-first search (the path with the fewest moves, whatever the edge
//! costs) and depth-first search (some path, found by always extending the most recently
//! reached node). One loop serves both; only the order of the frontier and where the goal is
//! recognised differ.

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

// The public searches as methods: alike signatures (kept, public), one loop (`uninformed`) under both.
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
        self.uninformed::<G, _, true>(graph, start, Some(goal), |_| false)
    }

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
        self.uninformed::<G, _, false>(graph, start, Some(goal), |_| false)
    }

    /// Breadth-first (a queue) or depth-first (a stack) search. Breadth-first, the goal is
    /// recognised when it is reached: the first path to reach it is a shortest one. Depth-first,
    /// a node may be on the stack several times; its parent is the one that pushed it last,
    /// which is the entry popped first, later entries for a closed node are skipped, and the
    /// goal is recognised when it is popped. `BREADTH_FIRST` is a constant, so each search
    /// compiles to its own loop. A node whose slot `is_goal` accepts ends the search as the goal
    /// does (with no goal, only those).
    pub(crate) fn uninformed<G, E, const BREADTH_FIRST: bool>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: Option<G::Node>,
        mut is_goal: E,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        E: FnMut(usize) -> bool,
    {
        let query = self.begin(graph, start, goal.unwrap_or(start))?;
        let (s, open, closed) = (query.start, query.open, query.closed);
        let t = if goal.is_some() { query.goal } else { usize::MAX };
        let mut ends = |slot: usize| slot == t || is_goal(slot);
        let mut stats = SearchStats { pushes: 1, ..SearchStats::default() };
        if BREADTH_FIRST {
            self.fifo.push_back(s as u32);
        } else {
            self.stack.push(s as u32);
        }
        let mut edges = EdgeCheck::new();
        let mut found = (BREADTH_FIRST && ends(s)).then_some(s);
        while found.is_none() {
            let next = if BREADTH_FIRST { self.fifo.pop_front() } else { self.stack.pop() };
            let Some(u) = next else { break };
            let u = u as usize;
            if !BREADTH_FIRST {
                if self.nodes.stamp[u] == closed {
                    continue;
                }
                if ends(u) {
                    found = Some(u);
                    break;
                }
            }
            self.nodes.stamp[u] = closed;
            stats.expansions += 1;
            let gu = self.nodes.g[u];
            let (nodes, fifo, stack) = (&mut self.nodes, &mut self.fifo, &mut self.stack);
            self.index.for_each_successor(graph, u, |v, next, cost| {
                if (BREADTH_FIRST && found.is_some()) || !edges.accept(next, cost) {
                    return;
                }
                ensure(nodes, v);
                // Breadth-first, a node is reached once; depth-first, until it is expanded.
                let skip = if BREADTH_FIRST { nodes.stamp[v] >= open } else { nodes.stamp[v] == closed };
                if skip {
                    return;
                }
                nodes.reach(v, gu + cost, u, open);
                if BREADTH_FIRST {
                    fifo.push_back(v as u32);
                } else {
                    stack.push(v as u32);
                }
                stats.pushes += 1;
                if BREADTH_FIRST && ends(v) {
                    found = Some(v);
                }
            });
            edges.check(|| self.index.node(graph, u))?;
        }
        self.check_path_cost(graph, found)?;
        Ok(self.finish(graph, &query, found, stats))
    }
}
