//! Best-first search: A*, weighted A* and Dijkstra's algorithm.
//!
//! All three expand nodes in order of `f = g + w h` from one open list, an
//! [`IndexedHeap`](crate::IndexedHeap) with decrease-key; ties on `f` go to the larger `g`.
//! The goal test happens when a node is expanded, so the path returned is optimal for A* with an
//! admissible heuristic and for Dijkstra, and within a factor `w` of optimal for weighted A* with
//! a consistent heuristic. "Optimal" here is up to a relative 2^-32 (about 2.3e-10): priorities
//! are compared at that precision, so that values equal in exact arithmetic but rounded
//! differently tie, and the tie rule walks across open areas instead of filling them.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Successors};

use crate::error::SearchError;
use crate::heuristic::HeuristicCheck;
use crate::index::{Dense, NodeIndex};
use crate::limits::MAX_WEIGHT;
use crate::one_shot::SearchResult;
use crate::one_shot::edges::EdgeCheck;
use crate::one_shot::key::FKey;
use crate::one_shot::workspace::{Search, ensure};
use crate::stats::SearchStats;

/// The relative saving below which a closed node is not reopened: rounding, not a cheaper path
/// (a path of a million edges sums to within about 1e-10 of its cost in any order).
const REOPEN_TOLERANCE: f64 = 1e-9;

/// A* from `start` to `goal`: a least-cost path when `heuristic` is admissible (never more than
/// the least cost to the goal). A node whose heuristic is `+inf` is treated as a dead end.
///
/// Closed nodes are reopened when a cheaper path to them appears, so an admissible but
/// inconsistent heuristic still gives a least-cost path; with a consistent heuristic (such as
/// [`GridGraph::heuristic`](https://docs.rs/trailmark-graph)) nothing is ever reopened. A
/// saving below a relative 1e-9 is rounding (one length summed in two orders) and reopens
/// nothing: the path's cost is then within that of the least.
///
/// Costs beyond the largest `f64`: a path found is exact (it costs less than any path whose cost
/// overflowed); when none is found but the search met a path whose cost overflowed, the answer
/// is [`SearchError::CostOverflow`], not "no path". The same holds for [`weighted_astar`] and
/// [`dijkstra`].
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::astar;
///
/// let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let goal = Cell::new(3, 2);
/// let found = astar(&graph, Cell::new(0, 0), goal, graph.heuristic(GridHeuristic::Octile, goal))?;
/// let path = found.path.expect("reachable");
/// assert_eq!(path.cost, 5.0); // around the wall: no diagonal move may clip its corners
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn astar<G, H>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
    heuristic: H,
) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
    H: FnMut(G::Node) -> Cost,
{
    Search::new().astar(graph, start, goal, heuristic)
}

/// Weighted A*: A* with the heuristic multiplied by `weight`, from 1 to [`MAX_WEIGHT`] (other
/// weights are a [`SearchError::InvalidWeight`]). It expands fewer nodes than
/// A*, and with a consistent heuristic its path costs at most `weight` times the least cost.
/// Closed nodes are not reopened (that is what keeps it fast; the bound holds without).
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{astar, weighted_astar};
///
/// let grid = Grid::new(64, 64)?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(0, 0), Cell::new(63, 40));
/// let h = graph.heuristic(GridHeuristic::Octile, goal);
/// let best = astar(&graph, start, goal, h)?;
/// let fast = weighted_astar(&graph, start, goal, h, 2.0)?;
/// assert!(fast.cost().unwrap() <= 2.0 * best.cost().unwrap());
/// assert!(fast.stats.expansions <= best.stats.expansions);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn weighted_astar<G, H>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
    heuristic: H,
    weight: f64,
) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
    H: FnMut(G::Node) -> Cost,
{
    Search::new().weighted_astar(graph, start, goal, heuristic, weight)
}

/// Dijkstra's algorithm from `start` to `goal`: a least-cost path, no heuristic.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::dijkstra;
///
/// let mut grid = Grid::new(3, 1)?;
/// grid.set_cost(Cell::new(1, 0), 3.0)?; // moves cost their length x the mean of the two cell costs
/// let graph = GridGraph::new(&grid, Connectivity::Four);
/// let found = dijkstra(&graph, Cell::new(0, 0), Cell::new(2, 0))?;
/// assert_eq!(found.cost(), Some(4.0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn dijkstra<G>(
    graph: &G,
    start: G::Node,
    goal: G::Node,
) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + IndexedGraph + ?Sized,
{
    Search::<Dense>::new().dijkstra(graph, start, goal)
}

// The public searches as methods: alike signatures (kept, public), one loop (`best_first`) under all.
impl<I> Search<I> {
    /// A* from `start` to `goal` with this workspace; see [`astar`](crate::astar()).
    pub fn astar<G, H>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        heuristic: H,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
    {
        self.best_first(graph, start, Some(goal), heuristic, 1.0, true, |_| false)
    }

    /// Weighted A* from `start` to `goal` with this workspace; see [`weighted_astar`](crate::weighted_astar()).
    pub fn weighted_astar<G, H>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        heuristic: H,
        weight: f64,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
    {
        if !(1.0..=MAX_WEIGHT).contains(&weight) {
            return Err(SearchError::InvalidWeight(weight));
        }
        self.best_first(graph, start, Some(goal), heuristic, weight, false, |_| false)
    }

    /// Dijkstra's algorithm from `start` to `goal` with this workspace; see [`dijkstra`](crate::dijkstra()).
    pub fn dijkstra<G>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
    {
        self.best_first(graph, start, Some(goal), |_| 0.0, 1.0, true, |_| false)
    }

    /// Dijkstra's algorithm from `start` to every reachable node. Afterwards
    /// [`Search::cost_to`] and [`Search::path_to_node`] give the least cost and a least-cost path
    /// to any node. The result has no path. Errors with [`SearchError::CostOverflow`] when the
    /// cost of some reachable node exceeds the largest `f64`.
    ///
    /// ```
    /// use trailmark_core::{Cell, Connectivity, Grid};
    /// use trailmark_graph::GridGraph;
    /// use trailmark_search::Search;
    ///
    /// let graph = GridGraph::new(&Grid::from_rows(&["...", "@@."])?, Connectivity::Four);
    /// let mut search = Search::new();
    /// search.dijkstra_all(&graph, Cell::new(0, 0))?;
    /// assert_eq!(search.cost_to(&graph, Cell::new(2, 1)), Some(3.0));
    /// assert_eq!(search.cost_to(&graph, Cell::new(0, 1)), None); // blocked
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn dijkstra_all<G>(
        &mut self,
        graph: &G,
        start: G::Node,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
    {
        self.best_first(graph, start, None, |_| 0.0, 1.0, true, |_| false)
    }

    /// A* from `start` that also ends at the first node leaving the open list for which
    /// `ends_here(slot)` holds (a node from which a path to the goal is already known, as in
    /// MPGAA*); the path returned leads to that node.
    pub(crate) fn astar_until<G, H, E>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        heuristic: H,
        ends_here: E,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
        E: FnMut(usize) -> bool,
    {
        self.best_first(graph, start, Some(goal), heuristic, 1.0, true, ends_here)
    }

    #[allow(clippy::too_many_arguments)]
    pub(crate) fn best_first<G, H, E>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: Option<G::Node>,
        mut heuristic: H,
        weight: f64,
        reopen: bool,
        mut ends_here: E,
    ) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
    where
        G: Successors + ?Sized,
        I: NodeIndex<G>,
        H: FnMut(G::Node) -> Cost,
        E: FnMut(usize) -> bool,
    {
        let query = self.begin(graph, start, goal.unwrap_or(start))?;
        let (s, t, open, closed) = (query.start, query.goal, query.open, query.closed);
        let goal_slot = if goal.is_some() { t } else { usize::MAX };
        let mut stats = SearchStats::default();
        let mut heuristics = HeuristicCheck::new();
        // The first node whose cost from the start overflowed (a finite `g` plus a finite edge
        // cost gave +inf): it is left unreached, which is exact when a path is found (the path
        // costs less than any overflowing one) and an error otherwise. A priority `g + w h` that
        // overflows is simply `+inf`: such nodes come last, after every finite priority.
        let mut overflow = None;
        match heuristics.accept(start, heuristic(start)) {
            Some(h) if h.is_finite() => {
                self.heap.push(s, FKey::new(weight * h, 0.0));
                stats.pushes += 1;
            }
            _ => {}
        }
        let mut edges = EdgeCheck::new();
        let mut found = None;
        // The open list is the heap plus at most one `held` node: the least-key node generated
        // by the last expansion. It is expanded next without passing through the heap when no
        // heap entry has a smaller key, which on grids is most of the time (moves straight
        // toward the goal keep f constant and raise g). The expansion order is exactly that of
        // the heap alone; only pushes and pops are saved.
        let mut held: Option<(FKey, usize)> = None;
        loop {
            let u = match held.take() {
                Some((key, v)) => match self.heap.peek() {
                    Some((_, top)) if top < key => {
                        self.heap.push_absent(v, key);
                        self.heap.pop().map_or(v, |(u, _)| u)
                    }
                    _ => v,
                },
                None => match self.heap.pop() {
                    Some((u, _)) => u,
                    None => break,
                },
            };
            if u == goal_slot || ends_here(u) {
                found = Some(u);
                break;
            }
            self.nodes.stamp[u] = closed;
            if let Some(log) = self.expanded_log.as_mut() {
                log.push(u as u32);
            }
            stats.expansions += 1;
            let gu = self.nodes.g[u];
            let (nodes, heap) = (&mut self.nodes, &mut self.heap);
            self.index.for_each_successor(graph, u, |v, next, cost| {
                if !edges.accept(next, cost) {
                    return;
                }
                ensure(nodes, v);
                let gv = gu + cost;
                let st = nodes.stamp[v];
                let seen = st >= open;
                // A closed node is reopened only for a real saving: the same length summed in
                // another order can come out smaller by rounding, which saves nothing.
                let rounding = st == closed && gv >= nodes.g[v] * (1.0 - REOPEN_TOLERANCE);
                if seen && (gv >= nodes.g[v] || (st == closed && !reopen) || rounding) {
                    return;
                }
                if gv == f64::INFINITY {
                    overflow.get_or_insert(next);
                    return;
                }
                let Some(h) = heuristics.accept(next, heuristic(next)) else { return };
                nodes.reach(v, gv, u, open);
                if h == f64::INFINITY {
                    // A dead end (an overflowing `w h`, with `h` finite, is not one).
                    return;
                }
                match (seen, st == closed) {
                    (false, _) => stats.pushes += 1,
                    (true, true) => stats.reopenings += 1,
                    (true, false) => stats.decreases += 1,
                }
                let key = FKey::new(gv + weight * h, gv);
                match held {
                    // The held node again (a parallel edge): keep the better key.
                    Some((_, w)) if w == v => held = Some((key, v)),
                    // An open node is in the heap (or, with an infinite heuristic, nowhere, and
                    // `push` then inserts it): its key is lowered there.
                    _ if st == open => {
                        heap.push(v, key);
                    }
                    None => held = Some((key, v)),
                    Some((k, w)) if key < k => {
                        heap.push_absent(w, k);
                        held = Some((key, v));
                    }
                    Some(_) => {
                        heap.push_absent(v, key);
                    }
                }
            });
            edges.check(|| self.index.node(graph, u))?;
            heuristics.check()?;
        }
        heuristics.check()?;
        // Without a path (or, for `dijkstra_all`, with nodes left unreached), an overflow means
        // a reachable node would be reported unreachable.
        if let (None, Some(node)) = (found, overflow) {
            return Err(SearchError::CostOverflow { node });
        }
        Ok(self.finish(graph, &query, found, stats))
    }
}
