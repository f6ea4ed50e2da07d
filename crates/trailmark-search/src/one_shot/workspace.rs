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

use trailmark_core::cost::Cost;
use trailmark_core::graph::Graph;
use trailmark_core::path::Path;

use crate::error::{SearchError, check_endpoints};
use crate::index::{Dense, Hashed, NodeIndex};
use crate::limits::MAX_NODES;
use crate::one_shot::SearchResult;
use crate::one_shot::key::FKey;
use crate::queue::IndexedHeap;
use crate::stats::SearchStats;

/// A generation stamp. Two bytes, because the stamp test rejects most successors and small
/// stamps share few cache lines; every 32,766 queries the stamps are reset.
pub(crate) type Stamp = u16;

/// A query in progress: its start and goal slots, the current generation's stamps, its clock.
pub(crate) struct RunningQuery {
    pub start: usize,
    pub goal: usize,
    /// The stamp of a node reached by this query and not expanded.
    pub open: Stamp,
    /// The stamp of a node this query expanded.
    pub closed: Stamp,
    clock: std::time::Instant,
}

impl RunningQuery {
    /// Time since the query began.
    pub fn elapsed(&self) -> std::time::Duration {
        self.clock.elapsed()
    }
}

/// Per-slot search state, as parallel arrays: the stamp test that rejects most successors
/// reads only the stamps, so those of a node's neighbourhood share few cache lines (faster than
/// one record per node; docs/search.md, "Inside").
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

/// Per-node state of an any-angle search beside the workspace's: the best exact way known to
/// each node (an edge, or a line already priced) and whether the node's current parent line has
/// been priced. Valid where the workspace's stamp says the node was reached by this query.
#[derive(Debug, Clone, Default)]
pub(crate) struct AnyAngle {
    /// One record per slot: the fields are read together for every successor.
    pub(crate) ways: Vec<Way>,
    pub(crate) verified: Vec<bool>,
}

/// The best exact way known to a node.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Way {
    pub(crate) g: Cost,
    pub(crate) parent: u32,
    /// The last parent whose line to the node was priced: offering that line again would only
    /// repeat the pricing (parents are closed, so their cost no longer changes).
    pub(crate) priced: u32,
}

impl AnyAngle {
    pub(crate) fn resize(&mut self, len: usize) {
        if self.ways.len() < len {
            self.ways.resize(len, Way { g: f64::INFINITY, parent: 0, priced: 0 });
            self.verified.resize(len, true);
        }
    }

    #[inline]
    pub(crate) fn ensure(&mut self, slot: usize) {
        if slot >= self.ways.len() {
            self.resize((slot + 1).next_power_of_two());
        }
    }

    /// Starts `slot` for a new query: no way known, no line priced.
    #[inline]
    pub(crate) fn start(&mut self, slot: usize) {
        self.ensure(slot);
        self.ways[slot] = Way { g: f64::INFINITY, parent: slot as u32, priced: slot as u32 };
        self.verified[slot] = true;
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        self.ways.capacity() * std::mem::size_of::<Way>() + self.verified.capacity()
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
    /// Theta*'s state beside `nodes` (empty until a Theta* query).
    pub(crate) any_angle: AnyAngle,
    /// When kept, the slots the best-first searches expand, in order (Adaptive A* learns from
    /// them); cleared by each query.
    pub(crate) expanded_log: Option<Vec<u32>>,
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
            any_angle: AnyAngle::default(),
            expanded_log: None,
        }
    }

    /// Bytes held by the per-node state and the open list (allocated capacity). The hash map of
    /// a [`Hashed`] workspace is not included.
    pub fn memory_bytes(&self) -> usize {
        self.nodes.memory_bytes()
            + self.heap.memory_bytes()
            + self.fifo.capacity() * 4
            + self.stack.capacity() * 4
            + self.any_angle.memory_bytes()
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
    ) -> Result<RunningQuery, SearchError<G::Node>>
    where
        G: Graph + ?Sized,
        I: NodeIndex<G>,
    {
        let clock = std::time::Instant::now();
        check_endpoints(graph, start, goal)?;
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
        if let Some(log) = self.expanded_log.as_mut() {
            log.clear();
        }
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
        Ok(RunningQuery { start: s, goal: t, open, closed, clock })
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
        query: &RunningQuery,
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
