//! Theta*: any-angle paths over a graph whose nodes can also be joined by straight lines (Nash,
//! Daniel, Koenig and Felner, "Theta*: Any-Angle Path Planning on Grids", AAAI 2007).
//!
//! It is A* with one change: when a node `v` is reached from `u`, it also tries the straight
//! line from `u`'s parent to `v`, and keeps whichever is cheaper. Paths then bend only where
//! they must, at the corners of obstacles, instead of following the graph's eight directions.
//! Each line's cost comes from the caller ([`Lines`]: the graph itself, or a closure), so the
//! lines can be priced by the terrain they cross, as Nav2's Theta* does on a costmap; a blocked
//! line is `None`.
//!
//! Theta* is not optimal: its paths are at least as long as the true shortest any-angle path
//! (every segment is a line the caller accepted) and in practice within a few percent of it,
//! and they are never longer than A*'s on the same graph with the same costs when the line
//! costs agree with the edge costs.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Lines, Successors};

use crate::error::SearchError;
use crate::heuristic::HeuristicCheck;
use crate::index::NodeIndex;
use crate::one_shot::SearchResult;
use crate::one_shot::edges::EdgeCheck;
use crate::one_shot::key::FKey;
use crate::one_shot::workspace::{Search, Way, ensure};
use crate::stats::SearchStats;

/// Theta* from `start` to `goal`: an any-angle path whose corners are nodes of `graph`, each
/// segment a straight line that `lines` accepts or an edge. The path's cost is the sum of its
/// segments' costs.
///
/// The heuristic: one admissible for straight lines (on a grid, the Euclidean distance) guides
/// the search toward the straightest paths. One that is only consistent along the graph's edges
/// (the octile distance) overestimates some lines, yet the path still never costs more than the
/// graph's least-cost path (nodes on that path are still expanded at no more than their grid
/// cost), and it expands far fewer nodes where costs vary: on the ROS costmaps of
/// docs/ros-maps.md, 1.2-5.5x faster for paths 0.1-0.5% dearer.
///
/// Lines are checked when a node is taken from the open list, not when it is generated (the
/// order of work of Lazy Theta*, Nash, Koenig and Tovey, AAAI 2010): a node reached through its
/// parent's parent is queued at that parent's cost plus [`Lines::line_lower_bound`]; when it
/// comes out, the line is priced and the node takes the cheaper of it and the best edge that
/// reached it, and goes back into the queue if that costs more than its key said. Nodes are
/// expanded at their exact cost, in order, so with a consistent heuristic the path never costs
/// more than the least-cost path of the graph's edges; one line is priced per node reached
/// instead of one per edge.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{astar, theta_star};
///
/// let grid = Grid::from_rows(&["........", "........", "........"])?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(0, 0), Cell::new(7, 2));
/// let h = graph.heuristic(GridHeuristic::Euclidean, goal);
/// let found = theta_star(&graph, start, goal, h, &graph)?; // the graph prices its own lines
/// let path = found.path.expect("reachable");
/// assert_eq!(path.nodes, [start, goal]); // one straight line
/// assert!((path.cost - 53f64.sqrt()).abs() < 1e-12);
/// let grid_path = astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
/// assert!(path.cost < grid_path.cost().unwrap());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn theta_star<G, H, L>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
    heuristic: H,
    lines: &L,
) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
    H: FnMut(G::Node) -> Cost,
    L: Lines<G::Node> + ?Sized,
{
    Search::new().theta_star(graph, start, goal, heuristic, lines)
}

impl<I> Search<I> {
    /// Theta* from `start` to `goal` with this workspace; see [`theta_star`](crate::theta_star()).
    pub fn theta_star<G, H, L>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        mut heuristic: H,
        lines: &L,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
        L: Lines<G::Node> + ?Sized,
    {
        let query = self.begin(graph, start, goal)?;
        let (s, t, open, closed) = (query.start, query.goal, query.open, query.closed);
        let mut exact = std::mem::take(&mut self.any_angle);
        exact.resize(self.nodes.len());
        exact.start(s);
        exact.ways[s].g = 0.0;
        let mut stats = SearchStats::default();
        let mut heuristics = HeuristicCheck::new();
        let mut overflow = None;
        let mut checks = LineCheck::default();
        if let Some(h) = heuristics.accept(start, heuristic(start)).filter(|h| h.is_finite()) {
            self.heap.push(s, FKey::new(h, 0.0));
            stats.pushes += 1;
        }
        let mut edges = EdgeCheck::new();
        let mut found = None;
        while let Some((u, key)) = self.heap.pop() {
            if !exact.verified[u] {
                // Price the line from the lazily chosen parent; keep the cheaper of it and the
                // best exact way known (an edge, or a line priced before).
                exact.verified[u] = true;
                let p = self.nodes.parent[u] as usize;
                let (pn, un) = (self.index.node(graph, p), self.index.node(graph, u));
                let way = exact.ways[u];
                let (mut g, mut from) = (way.g, way.parent as usize);
                // A line dearer than the way known is of no use: its pricing may stop there.
                let budget = g - self.nodes.g[p];
                if let Some(c) = checks.accept(pn, un, lines.line_cost_within(pn, un, budget))
                    && self.nodes.g[p] + c <= g
                {
                    (g, from) = (self.nodes.g[p] + c, p);
                }
                exact.ways[u] = Way { g, parent: from as u32, priced: p as u32 };
                self.nodes.g[u] = g;
                self.nodes.parent[u] = from as u32;
                checks.check()?;
                // Expand it now if its key still holds, else queue it at its exact key (its
                // heuristic was finite and accepted when it was queued).
                let exact_key = FKey::new(g + heuristic(un), g);
                if exact_key > key && self.heap.peek().is_some_and(|(_, top)| top < exact_key) {
                    self.heap.push(u, exact_key);
                    continue;
                }
            }
            if u == t {
                found = Some(u);
                break;
            }
            self.nodes.stamp[u] = closed;
            stats.expansions += 1;
            let gu = self.nodes.g[u];
            let pu = self.nodes.parent[u] as usize;
            // The line from u's parent: none from the start, which is its own parent.
            let parent = (pu != u).then(|| (pu, self.nodes.g[pu], self.index.node(graph, pu)));
            let (nodes, heap) = (&mut self.nodes, &mut self.heap);
            let exact = &mut exact;
            self.index.for_each_successor(graph, u, |v, next, cost| {
                if !edges.accept(next, cost) {
                    return;
                }
                ensure(nodes, v);
                exact.ensure(v);
                let st = nodes.stamp[v];
                if st == closed {
                    return;
                }
                let seen = st >= open;
                if !seen {
                    exact.start(v);
                }
                let g1 = gu + cost;
                let way = &mut exact.ways[v];
                if g1 < way.g {
                    (way.g, way.parent) = (g1, u as u32);
                }
                // The best candidate: the exact one, or the parent's line at its lower bound.
                let (mut gv, mut from, mut verified) = (way.g, way.parent as usize, true);
                if let Some((pu, gp, pnode)) = parent
                    && way.priced != pu as u32
                {
                    let lazy = gp + lines.line_lower_bound(pnode, next).max(0.0);
                    if lazy <= gv {
                        (gv, from, verified) = (lazy, pu, false);
                    }
                }
                if seen && gv >= nodes.g[v] {
                    return;
                }
                if gv == f64::INFINITY {
                    overflow.get_or_insert(next);
                    return;
                }
                let Some(h) = heuristics.accept(next, heuristic(next)) else { return };
                nodes.reach(v, gv, from, open);
                exact.verified[v] = verified;
                if h == f64::INFINITY {
                    return;
                }
                if seen {
                    stats.decreases += 1
                } else {
                    stats.pushes += 1
                }
                heap.push(v, FKey::new(gv + h, gv));
            });
            edges.check(|| self.index.node(graph, u))?;
            heuristics.check()?;
        }
        self.any_angle = exact;
        heuristics.check()?;
        if let (None, Some(node)) = (found, overflow) {
            return Err(SearchError::CostOverflow { node });
        }
        Ok(self.finish(graph, &query, found, stats))
    }
}

/// Keeps the first invalid line cost met (negative or not a number).
struct LineCheck<N> {
    bad: Option<(N, N, Cost)>,
}

impl<N> Default for LineCheck<N> {
    fn default() -> Self {
        LineCheck { bad: None }
    }
}

impl<N: Copy + std::fmt::Debug> LineCheck<N> {
    /// The line's cost when it can be used: `None` for a blocked line, an infinite cost, or an
    /// invalid one (remembered).
    fn accept(&mut self, from: N, to: N, cost: Option<Cost>) -> Option<Cost> {
        match cost {
            Some(c) if (0.0..f64::INFINITY).contains(&c) => Some(c),
            Some(c) if c.is_nan() || c < 0.0 => {
                self.bad.get_or_insert((from, to, c));
                None
            }
            _ => None,
        }
    }

    fn check(&self) -> Result<(), SearchError<N>> {
        match self.bad {
            None => Ok(()),
            Some((from, to, cost)) => Err(SearchError::InvalidLineCost { from, to, cost }),
        }
    }
}
