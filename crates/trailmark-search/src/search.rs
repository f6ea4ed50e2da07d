//! The reusable search workspace shared by every algorithm of this crate.
//!
//! A [`Search`] owns the per-node state (cost from the start, parent, a generation stamp) in
//! dense `Vec`s, and the open list. Running many queries through one `Search` reuses that memory:
//! a query only touches the nodes it visits, because a node's state counts only when its stamp
//! matches the current query.
//!
//! State per node slot: 8 bytes of cost, 4 of parent, 2 of stamp, and 4 in the open list's
//! position table: 18 bytes, plus 16 per node currently in the open list.

use std::collections::VecDeque;
use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::Graph;
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::index::{Dense, Hashed, NodeIndex};
use crate::queue::IndexedHeap;
use crate::stats::SearchStats;

/// The most node slots a search supports.
pub const MAX_NODES: usize = u32::MAX as usize - 2;

/// The outcome of a search: a path (or `None` when the goal is unreachable) and statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchResult<N> {
    /// The path found, start first; `None` when no path exists.
    pub path: Option<Path<N>>,
    /// What the search did.
    pub stats: SearchStats,
}

impl<N> SearchResult<N> {
    /// The cost of the path, if one was found.
    pub fn cost(&self) -> Option<Cost> {
        self.path.as_ref().map(|p| p.cost)
    }
}

/// Low mantissa bits that priority comparisons ignore (see [`priority_bits`]).
const IGNORED_BITS: u32 = 20;

/// The bit pattern of a non-negative priority (an `f` value, or the primary part of a lifelong
/// key) rounded to 32 of its 52 mantissa bits, a relative precision of 2^-32 (about 2.3e-10).
///
/// Priorities add edge costs and heuristic values in orders that differ from node to node, so
/// values equal in exact arithmetic differ in their last bits (on an open grid, by about 1e-13
/// after a few hundred moves). Compared bit for bit, such near-ties are ordered by rounding
/// noise, and the tie-breaking rule (larger `g` first), which is what lets A* walk straight
/// across the many cells of equal `f` of an open area, never applies: on an empty 512 x 512
/// grid, A* between far corners then expands a whole parallelogram of cells (128,145 in one
/// measured query) instead of the path's cells. Rounding every priority to 2^-32 makes such
/// near-ties exact ties again. The price is that priorities closer than that are ordered as
/// equal: a search can return a path whose cost exceeds the least by at most a relative 2^-32,
/// far below what costs summed in floating point resolve anyway.
///
/// Rounding is monotone, so the order of priorities that differ by more is unchanged; `+inf`
/// stays `+inf`.
#[inline]
pub(crate) fn priority_bits(value: Cost) -> u64 {
    // `+ 0.0` turns a negative zero into a positive one, whose bits order correctly.
    let bits = (value + 0.0).to_bits();
    (bits + (1 << (IGNORED_BITS - 1))) & !((1 << IGNORED_BITS) - 1)
}

/// The key of a node in a best-first open list: `f = g + w h` (at the precision of
/// [`priority_bits`]), ties broken toward larger `g` (deeper nodes first, which on grids reaches
/// the goal after fewer expansions).
///
/// Stored as one 64-bit integer: the bit pattern of the rounded `f`, whose low
/// [`IGNORED_BITS`] bits are zero, with those bits holding `g` inverted, at a precision of 2^-19
/// of `f`. For
/// non-negative floats the bit pattern orders like the number, so keys compare as integers,
/// without floating-point branches in the heap's inner loop, and a heap entry (key and node)
/// takes 16 bytes, so the four children of a heap node span 64 bytes. Among keys of equal
/// `f`, `g` values closer than `f / 2^19` tie; such ties are broken arbitrarily.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct FKey(u64);

impl FKey {
    /// The key of a node with `f` and `g`, both non-negative and finite, `g <= f`.
    #[inline]
    pub fn new(f: Cost, g: Cost) -> Self {
        debug_assert!(f >= 0.0 && g >= 0.0);
        const DEPTH_BITS: u32 = IGNORED_BITS - 1;
        const SCALE: u64 = (1 << IGNORED_BITS) - 1;
        let rounded = priority_bits(f);
        // `g` in units of 2^-19 of the power of two below `f`: as `g <= f`, under 2^20. The
        // power of two comes from `f`'s exponent bits rather than a division, which is slow;
        // the exponent is clamped so that the scale stays a normal float (tiny `f` only).
        let exponent = (rounded >> 52).max(u64::from(DEPTH_BITS) + 1);
        let scale = f64::from_bits((2 * 1023 + u64::from(DEPTH_BITS) - exponent) << 52);
        // Adding 2^52 puts the integer part of a number below 2^52 in the low mantissa bits
        // (rounded to nearest): cheaper than a float-to-integer conversion.
        let depth = ((g * scale + 4503599627370496.0).to_bits() & ((1 << 52) - 1)).min(SCALE);
        FKey(rounded | (SCALE - depth))
    }
}

/// A generation stamp. Two bytes: the stamps of a 512 x 512 map fit in a core's L2 cache, and
/// the stamp test rejects most successors; every 32,766 queries the stamps are reset.
pub(crate) type Stamp = u16;

/// A query in progress: its start and goal slots, the current generation's stamps, its clock.
pub(crate) struct Query {
    pub start: usize,
    pub goal: usize,
    /// The stamp of a node reached by this query and not expanded.
    pub open: Stamp,
    /// The stamp of a node this query expanded.
    pub closed: Stamp,
    clock: std::time::Instant,
}

impl Query {
    /// Time since the query began.
    pub fn elapsed(&self) -> std::time::Duration {
        self.clock.elapsed()
    }
}

/// Per-slot search state, as parallel arrays: the stamp test that rejects most successors
/// reads 4 bytes a node, so the stamps of a node's neighbourhood share few cache lines
/// (measured 20% faster than one 16-byte record per node on 512 x 512 mazes).
#[derive(Debug, Clone, Default)]
pub(crate) struct Nodes {
    /// Cost from the start, valid when `stamp >= open_stamp()`.
    pub g: Vec<Cost>,
    /// Parent slot on the best known path (the start is its own parent).
    pub parent: Vec<u32>,
    /// `2 x generation` when the node was reached by the current query, `+ 1` once expanded.
    pub stamp: Vec<Stamp>,
}

impl Nodes {
    /// Records that `slot` is reached at cost `g` from `parent`, with `stamp`.
    #[inline]
    pub fn reach(&mut self, slot: usize, g: Cost, parent: usize, stamp: Stamp) {
        self.g[slot] = g;
        self.parent[slot] = parent as u32;
        self.stamp[slot] = stamp;
    }

    #[inline]
    pub fn len(&self) -> usize {
        self.stamp.len()
    }

    pub fn resize(&mut self, len: usize) {
        self.g.resize(len, 0.0);
        self.parent.resize(len, 0);
        self.stamp.resize(len, 0);
    }

    pub fn memory_bytes(&self) -> usize {
        self.g.capacity() * 8
            + self.parent.capacity() * 4
            + self.stamp.capacity() * std::mem::size_of::<Stamp>()
    }
}

/// A reusable search workspace: per-node state in dense vectors, and the open list.
///
/// `I` decides how nodes get their slot in the vectors: [`Dense`] (the default) uses the
/// graph's own indices and needs an [`IndexedGraph`](trailmark_core::graph::IndexedGraph);
/// [`Hashed`] works on any graph.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::Search;
///
/// let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
/// let graph = GridGraph::new(&grid, Connectivity::Eight);
/// let mut search = Search::new();
/// for goal in [Cell::new(3, 0), Cell::new(3, 2)] {
///     let h = graph.heuristic(GridHeuristic::Octile, goal);
///     let found = search.astar(&graph, Cell::new(0, 0), goal, h)?;
///     assert!(found.path.is_some());
/// }
/// // The nodes the last query expanded, e.g. to draw them.
/// assert!(search.expanded(&graph).count() > 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Search<I = Dense> {
    pub(crate) index: I,
    /// Per-slot state.
    pub(crate) nodes: Nodes,
    pub(crate) generation: Stamp,
    pub(crate) heap: IndexedHeap<FKey>,
    pub(crate) fifo: VecDeque<u32>,
    pub(crate) stack: Vec<u32>,
    /// The slot of the last query's start, or `None` before the first query.
    pub(crate) start: Option<u32>,
}

impl Default for Search<Dense> {
    fn default() -> Self {
        Search::with_index(Dense)
    }
}

impl Search<Dense> {
    /// A workspace for graphs with dense indices ([`IndexedGraph`](trailmark_core::graph::IndexedGraph)).
    pub fn new() -> Self {
        Self::default()
    }
}

impl<N> Search<Hashed<N>> {
    /// A workspace for any graph: nodes get their slots through a hash map.
    pub fn hashed() -> Self {
        Search::with_index(Hashed::default())
    }
}

impl<I> Search<I> {
    /// A workspace that numbers nodes with `index`.
    pub fn with_index(index: I) -> Self {
        Search {
            index,
            nodes: Nodes::default(),
            generation: 0,
            heap: IndexedHeap::new(),
            fifo: VecDeque::new(),
            stack: Vec::new(),
            start: None,
        }
    }

    /// Bytes held by the per-node state and the open list (allocated capacity). The hash map of
    /// a [`Hashed`] workspace is not included.
    pub fn memory_bytes(&self) -> usize {
        self.nodes.memory_bytes()
            + self.heap.memory_bytes()
            + self.fifo.capacity() * 4
            + self.stack.capacity() * 4
    }

    #[inline]
    pub(crate) fn open_stamp(&self) -> Stamp {
        2 * self.generation
    }

    #[inline]
    pub(crate) fn closed_stamp(&self) -> Stamp {
        2 * self.generation + 1
    }

    /// Starts a query: validates the endpoints, sizes the state, clears the open lists, moves
    /// to a new generation so that older state is ignored, and reaches the start at cost 0.
    pub(crate) fn begin<G>(
        &mut self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
    ) -> Result<Query, SearchError<G::Node>>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let clock = std::time::Instant::now();
        if !graph.contains(start) {
            return Err(SearchError::StartNotInGraph(start));
        }
        if !graph.contains(goal) {
            return Err(SearchError::GoalNotInGraph(goal));
        }
        let bound = self.index.begin(graph);
        if bound > MAX_NODES {
            return Err(SearchError::TooManyNodes(bound));
        }
        if self.nodes.len() < bound {
            self.nodes.resize(bound);
        }
        self.heap.reserve_items(bound);
        self.heap.clear();
        self.fifo.clear();
        self.stack.clear();
        if self.generation >= Stamp::MAX / 2 - 1 {
            self.nodes.stamp.fill(0);
            self.generation = 0;
        }
        self.generation += 1;
        let s = self.slot(graph, start);
        let t = self.slot(graph, goal);
        self.start = Some(s as u32);
        let (open, closed) = (self.open_stamp(), self.closed_stamp());
        self.nodes.reach(s, 0.0, s, open);
        Ok(Query { start: s, goal: t, open, closed, clock })
    }

    /// Makes room for a query that will use `generations` generations (one per iteration of an
    /// anytime search): clears the stamps now if they would run out during the query.
    pub(crate) fn reserve_generations(&mut self, generations: usize) {
        if usize::from(self.generation) + generations >= usize::from(Stamp::MAX / 2 - 1) {
            self.nodes.stamp.fill(0);
            self.generation = 0;
        }
    }

    /// Moves to the next generation within a query (see [`Search::reserve_generations`]).
    pub(crate) fn next_generation(&mut self) {
        self.generation += 1;
    }

    /// Ends a query: the path to `found`, if any, and the statistics with the elapsed time.
    pub(crate) fn finish<G>(
        &self,
        graph: &G,
        query: &Query,
        found: Option<usize>,
        mut stats: SearchStats,
    ) -> SearchResult<G::Node>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let path = found.map(|t| self.path_to(graph, t));
        stats.elapsed = query.clock.elapsed();
        SearchResult { path, stats }
    }

    /// Errors when the path to `found` costs more than an `f64` holds (for breadth- and
    /// depth-first search, whose path does not depend on costs), naming the first node along it
    /// whose cost overflowed.
    pub(crate) fn check_path_cost<G>(
        &self,
        graph: &G,
        found: Option<usize>,
    ) -> Result<(), SearchError<G::Node>>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let Some(mut s) = found.filter(|&t| self.nodes.g[t] == f64::INFINITY) else { return Ok(()) };
        let mut first = s;
        loop {
            if self.nodes.g[s] == f64::INFINITY {
                first = s;
            }
            let p = self.nodes.parent[s] as usize;
            if p == s {
                break;
            }
            s = p;
        }
        Err(SearchError::CostOverflow { node: self.index.node(graph, first) })
    }

    /// The slot of `node`, with state vectors long enough to hold it.
    #[inline]
    pub(crate) fn slot<G>(&mut self, graph: &G, node: G::Node) -> usize
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let s = self.index.slot(graph, node);
        ensure(&mut self.nodes, s);
        s
    }

    /// The path from the start to `slot` along parent links.
    pub(crate) fn path_to<G>(&self, graph: &G, slot: usize) -> Path<G::Node>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let mut nodes = Vec::new();
        let mut s = slot;
        loop {
            nodes.push(self.index.node(graph, s));
            let p = self.nodes.parent[s] as usize;
            if p == s {
                break;
            }
            s = p;
        }
        nodes.reverse();
        Path { nodes, cost: self.nodes.g[slot] }
    }

    /// The nodes the last query expanded (closed), in slot order. The goal, where the search
    /// stopped on reaching it, is not among them.
    pub fn expanded<'a, G>(&'a self, graph: &'a G) -> impl Iterator<Item = G::Node> + 'a
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let closed = self.closed_stamp();
        self.nodes_with(graph, move |stamp| stamp == closed)
    }

    /// The nodes the last query reached, expanded or not, in slot order.
    pub fn reached<'a, G>(&'a self, graph: &'a G) -> impl Iterator<Item = G::Node> + 'a
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let open = self.open_stamp();
        self.nodes_with(graph, move |stamp| stamp >= open)
    }

    /// The nodes whose stamp passes `test`, none before the first query.
    fn nodes_with<'a, G>(
        &'a self,
        graph: &'a G,
        test: impl Fn(Stamp) -> bool + 'a,
    ) -> impl Iterator<Item = G::Node> + 'a
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let started = self.generation > 0;
        self.nodes
            .stamp
            .iter()
            .enumerate()
            .filter(move |&(_, &stamp)| started && test(stamp))
            .map(move |(s, _)| self.index.node(graph, s))
    }

    /// The cost of the best path the last query found from its start to `node`, if it reached
    /// `node`. After [`Search::dijkstra_all`] this is the least cost to every reachable node.
    pub fn cost_to<G>(&mut self, graph: &G, node: G::Node) -> Option<Cost>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        self.reached_slot(graph, node).map(|s| self.nodes.g[s])
    }

    /// The best path the last query found from its start to `node`, if it reached `node`.
    pub fn path_to_node<G>(&mut self, graph: &G, node: G::Node) -> Option<Path<G::Node>>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        self.reached_slot(graph, node).map(|s| self.path_to(graph, s))
    }

    fn reached_slot<G>(&mut self, graph: &G, node: G::Node) -> Option<usize>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        if self.start.is_none() || !graph.contains(node) {
            return None;
        }
        let s = self.slot(graph, node);
        (self.nodes.stamp[s] >= self.open_stamp()).then_some(s)
    }
}

/// Keeps the first invalid edge cost met inside a successor callback.
pub(crate) struct EdgeCheck<N> {
    bad: Option<(N, Cost)>,
}

impl<N: Copy + Debug> EdgeCheck<N> {
    pub fn new() -> Self {
        EdgeCheck { bad: None }
    }

    /// Whether the edge to `to` should be followed: false for `NO_EDGE`, and for invalid costs
    /// (which are remembered).
    #[inline]
    pub fn accept(&mut self, to: N, cost: Cost) -> bool {
        // One integer comparison: the bit patterns below that of +inf are exactly the
        // non-negative finite numbers (negative numbers and NaN have larger patterns).
        if cost.to_bits() < f64::INFINITY.to_bits() {
            return true;
        }
        self.unusual(to, cost)
    }

    /// The rest of [`EdgeCheck::accept`], out of the hot path: `-0.0` is accepted, `NO_EDGE`
    /// skipped, anything else remembered as invalid.
    #[cold]
    #[inline(never)]
    fn unusual(&mut self, to: N, cost: Cost) -> bool {
        if cost == 0.0 {
            return true;
        }
        if cost != f64::INFINITY && self.bad.is_none() {
            self.bad = Some((to, cost));
        }
        false
    }

    /// An error naming the first invalid edge met, whose tail is `from()`.
    pub fn check(&self, from: impl FnOnce() -> N) -> Result<(), SearchError<N>> {
        match self.bad {
            None => Ok(()),
            Some((to, cost)) => Err(SearchError::InvalidEdgeCost { from: from(), to, cost }),
        }
    }
}

/// Makes `nodes` long enough for `slot` (slots handed out by a [`Hashed`] index grow).
#[inline]
pub(crate) fn ensure(nodes: &mut Nodes, slot: usize) {
    if slot >= nodes.len() {
        grow(nodes, slot + 1);
    }
}

#[cold]
fn grow(nodes: &mut Nodes, len: usize) {
    let len = len.max(nodes.len() * 2).max(64);
    nodes.resize(len);
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Keys order by `f` first (beyond the rounding of priorities), then by larger `g`
        /// (beyond the precision of the depth field).
        #[test]
        fn keys_order_by_f_then_larger_g(
            f1 in 0.0..1e6f64, f2 in 0.0..1e6f64, a in 0.0..=1.0f64, b in 0.0..=1.0f64,
        ) {
            let (g1, g2) = (a * f1, b * f2);
            let (k1, k2) = (FKey::new(f1, g1), FKey::new(f2, g2));
            if f1 < f2 * (1.0 - 1e-9) {
                prop_assert!(k1 < k2, "{f1} before {f2}");
            }
            // The same f, different depths.
            let (d1, d2) = (FKey::new(f1, g1), FKey::new(f1, b * f1));
            if g1 > b * f1 + f1 * 1e-5 {
                prop_assert!(d1 < d2, "g {g1} before {} at f {f1}", b * f1);
            }
        }
    }

    #[test]
    fn extreme_keys_stay_ordered() {
        assert!(FKey::new(0.0, 0.0) < FKey::new(f64::MIN_POSITIVE, 0.0));
        assert!(FKey::new(1e-300, 1e-300) < FKey::new(1e-300, 0.0));
        assert!(FKey::new(1e300, 1e300) < FKey::new(1e300, 1e299));
        assert!(FKey::new(1e300, 0.0) < FKey::new(f64::MAX, f64::MAX));
        // Values equal but for rounding noise tie on f, so the larger g wins.
        let f = 0.1 + 0.2;
        assert!(FKey::new(f, 0.2) < FKey::new(0.3, 0.1));
    }
}
