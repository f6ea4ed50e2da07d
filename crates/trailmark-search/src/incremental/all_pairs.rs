//! Shortest distances from many sources to every node, kept right as edges change: Ramalingam
//! and Reps' dynamic single-source algorithm (DynamicSWSF-FP, the one LPA* grew from) run for
//! each source over the rows a change can reach.
//!
//! Each source keeps its row of distances `g`. After edges change, the head of each changed edge
//! gets its one-step value `rhs` (the least distance of a predecessor plus the edge); where it
//! differs from `g`, the node is queued by `min(g, rhs)` and the queue is drained as LPA* drains
//! it without a heuristic: a node whose `rhs` fell takes it and offers its successors less; a
//! node whose `rhs` rose is reset to infinity and its successors re-derive theirs. A source that
//! no changed edge can affect costs one look at each changed edge's in-edges; the others repair
//! only the nodes whose distance changed and their neighbours.

use std::collections::HashMap;
use std::time::Instant;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{EdgeChange, IndexedGraph, Predecessors, Successors};

use crate::error::SearchError;
use crate::limits::MAX_PAIRS;
use crate::queue::IndexedHeap;
use crate::stats::SearchStats;

/// No compact id: an index that is not a node, or a node that is not a source.
const NONE: u32 = u32::MAX;

/// Shortest distances from a set of sources (by default every node) to every node of a graph,
/// kept up to date through [`update_edges`](Self::update_edges) as edges change cost, appear
/// or go. For a fleet asking many start-goal pairs of one changing map, or a route table over a
/// road network: a change repairs the distances it affects instead of recomputing every row.
///
/// Edge costs must be positive (as for LPA* and D* Lite), large enough not to vanish when added
/// to a path's length (a cost below its rounding is refused as zero), and at most `f64::MAX`
/// divided by the number of nodes, so that no path's length overflows. A graph must report the
/// same cost for an edge as a successor and as a predecessor, to the bit.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, IndexedGraph};
/// use trailmark_core::graph::EdgeChange;
/// use trailmark_graph::GridGraph;
/// use trailmark_search::AllPairs;
///
/// let grid = Grid::from_rows(&["....", "....", "...."])?;
/// let mut graph = GridGraph::new(&grid, Connectivity::Four);
/// let mut table = AllPairs::new(&graph, grid.cells())?;
/// let (a, b) = (Cell::new(0, 1), Cell::new(3, 1));
/// assert_eq!(table.distance(a, b), Some(3.0));
///
/// // The middle row becomes costly: tell the table which edges changed (into and out of each
/// // cell, for the cells `cells_affected_by` names).
/// let mut changes = Vec::new();
/// for x in 1..3 {
///     let cell = Cell::new(x, 1);
///     graph.set_cost(cell, 10.0)?;
///     for other in graph.cells_affected_by(cell) {
///         changes.extend([EdgeChange::new(other, cell), EdgeChange::new(cell, other)]);
///     }
/// }
/// table.update_edges(&graph, &changes)?;
/// assert_eq!(table.distance(a, b), Some(5.0)); // around, through the top or bottom row
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct AllPairs<N: std::fmt::Debug> {
    /// The compact id of each dense index, [`NONE`] where the index is not a node.
    compact: Vec<u32>,
    /// The node of each compact id, and the compact id of each node.
    nodes: Vec<N>,
    ids: HashMap<N, u32>,
    /// The compact id of each row's source.
    sources: Vec<u32>,
    /// The row of each compact id, [`NONE`] where the node is not a source.
    row_of: Vec<u32>,
    /// `dist[row * n + v]`: the distance from the row's source to node `v`.
    dist: Vec<Cost>,
    /// The largest edge cost that keeps every path's length finite.
    max_cost: Cost,
    scratch: Scratch,
    totals: SearchStats,
    /// The error that stopped a repair part-way: the rows are then out of date for good.
    broken: Option<SearchError<N>>,
}

/// What a row's repair reuses: the one-step values it has changed (`rhs`, valid where `stamp`
/// is the current generation) and the queue.
#[derive(Clone, Debug, Default)]
struct Scratch {
    rhs: Vec<Cost>,
    stamp: Vec<u32>,
    generation: u32,
    queue: IndexedHeap<Cost>,
    edges: Vec<(u32, Cost)>,
    successors: Vec<(u32, Cost)>,
}

impl Scratch {
    /// The one-step value of `v`: set in this repair, or else its distance (consistent).
    fn rhs(&self, v: u32, row: &[Cost]) -> Cost {
        if self.stamp[v as usize] == self.generation { self.rhs[v as usize] } else { row[v as usize] }
    }

    fn set_rhs(&mut self, v: u32, value: Cost) {
        self.stamp[v as usize] = self.generation;
        self.rhs[v as usize] = value;
    }

    /// Starts a repair: no one-step value set, nothing queued.
    fn begin(&mut self) {
        if self.generation == u32::MAX {
            self.stamp.fill(0);
            self.generation = 0;
        }
        self.generation += 1;
        self.queue.clear();
    }

    /// Queues `v` by `min(g, rhs)` where the two differ, takes it off the queue where they agree.
    fn requeue(&mut self, v: u32, row: &[Cost], stats: &mut SearchStats) {
        let (g, rhs) = (row[v as usize], self.rhs(v, row));
        if g != rhs {
            if self.queue.push(v as usize, g.min(rhs)).is_none() {
                stats.pushes += 1;
            }
        } else {
            self.queue.remove(v as usize);
        }
    }
}

impl<N: Copy + Eq + std::hash::Hash + std::fmt::Debug> AllPairs<N> {
    /// The table of every node to every node: a Dijkstra search from each node. `nodes` are
    /// every node the graph has, and may have after a change (a grid's cells, the blocked ones
    /// too, so that a cell may open): the graph's traits cannot list them.
    ///
    /// # Errors
    ///
    /// [`SearchError::UnknownNode`] for one of `nodes` that names nothing, or a node the graph
    /// reports that `nodes` lacks; [`SearchError::TooManyPairs`] when the table would hold more
    /// than [`MAX_PAIRS`] distances; an edge cost that is negative or NaN
    /// ([`SearchError::InvalidEdgeCost`]), zero ([`SearchError::ZeroCostEdge`]) or so large that
    /// a path could overflow ([`SearchError::CostOverflow`]).
    pub fn new<G>(graph: &G, nodes: impl IntoIterator<Item = N>) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let nodes = distinct(nodes);
        Self::build(graph, nodes.clone(), &nodes)
    }

    /// The table of the distances from each of `sources` to every node (a row per source, in
    /// the order given; a source named twice has one row). `nodes` as for [`new`](Self::new).
    ///
    /// # Errors
    ///
    /// [`SearchError::StartNotInGraph`] for a source that is not one of `nodes`, and those of
    /// [`new`](Self::new).
    pub fn from_sources<G>(
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
        sources: &[N],
    ) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        Self::build(graph, distinct(nodes), sources)
    }

    fn build<G>(graph: &G, nodes: Vec<N>, sources: &[N]) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let bound = graph.node_bound();
        if bound > crate::limits::MAX_NODES {
            return Err(SearchError::TooManyNodes(bound));
        }
        let mut compact = vec![NONE; bound];
        for (c, &node) in nodes.iter().enumerate() {
            let index =
                graph.checked_index(node).filter(|&i| i < bound).ok_or(SearchError::UnknownNode(node))?;
            compact[index] = c as u32;
        }
        let n = nodes.len();
        let mut row_of = vec![NONE; n];
        let mut rows = Vec::new();
        let ids: HashMap<N, u32> = nodes.iter().enumerate().map(|(c, &node)| (node, c as u32)).collect();
        for &s in sources {
            let c = *ids.get(&s).ok_or(SearchError::StartNotInGraph(s))?;
            if row_of[c as usize] == NONE {
                row_of[c as usize] = rows.len() as u32;
                rows.push(c);
            }
        }
        let pairs = rows.len().checked_mul(n).filter(|&p| p <= MAX_PAIRS);
        let Some(pairs) = pairs else {
            return Err(SearchError::TooManyPairs { sources: rows.len(), nodes: n });
        };
        let mut table = AllPairs {
            compact,
            nodes,
            ids,
            sources: rows,
            row_of,
            dist: vec![Cost::INFINITY; pairs],
            max_cost: Cost::MAX / n.max(1) as f64,
            scratch: Scratch::default(),
            totals: SearchStats::default(),
            broken: None,
        };
        table.scratch.rhs = vec![Cost::INFINITY; n];
        table.scratch.stamp = vec![0; n];
        // Every edge at every node checked now, so that a repair meets no surprise but an edge
        // the graph changed without telling.
        for v in 0..table.nodes.len() as u32 {
            table.load_edges(graph, v, true)?;
            table.load_edges(graph, v, false)?;
        }
        for row in 0..table.sources.len() {
            table.dijkstra(graph, row)?;
        }
        Ok(table)
    }

    /// The number of nodes (the length of a row).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The sources, one per row.
    pub fn sources(&self) -> impl Iterator<Item = N> + '_ {
        self.sources.iter().map(|&c| self.nodes[c as usize])
    }

    /// The distance of a shortest path from `from` to `to`; `None` when there is none, or when
    /// `from` is not a source of the table or `to` not a node.
    pub fn distance(&self, from: N, to: N) -> Option<Cost> {
        if self.broken.is_some() {
            return None;
        }
        let row = self.row_of[*self.ids.get(&from)? as usize];
        let v = *self.ids.get(&to)? as usize;
        (row != NONE).then(|| self.dist[row as usize * self.nodes.len() + v]).filter(|d| d.is_finite())
    }

    /// The distances from `from` to every node, in the order of [`nodes`](Self::nodes)
    /// (infinite: no path);
    /// `None` when `from` is not a source.
    pub fn row_from(&self, from: N) -> Option<&[Cost]> {
        if self.broken.is_some() {
            return None;
        }
        let row = self.row_of[*self.ids.get(&from)? as usize];
        let n = self.nodes.len();
        (row != NONE).then(|| &self.dist[row as usize * n..(row as usize + 1) * n])
    }

    /// Whether a repair stopped part-way (an edge the graph changed without telling, with a
    /// cost the table refuses): the table then answers nothing and refuses every update with
    /// that error; build it again.
    pub fn is_broken(&self) -> bool {
        self.broken.is_some()
    }

    /// The nodes, in the order given: what each position of a [`row_from`](Self::row_from) is.
    pub fn nodes(&self) -> &[N] {
        &self.nodes
    }

    /// Counters summed over the construction and every update since: `expansions` the nodes
    /// settled or repaired, `pushes` and `decreases` the queue's.
    pub fn totals(&self) -> SearchStats {
        self.totals
    }

    /// Bytes held by the table.
    pub fn memory_bytes(&self) -> usize {
        self.dist.len() * 8
            + (self.compact.len() + self.row_of.len() + self.sources.len()) * 4
            + self.nodes.len() * std::mem::size_of::<N>()
            + self.scratch.rhs.len() * 12
            + self.scratch.queue.memory_bytes()
    }

    /// Tells the table that these edges changed (appeared, went, or changed cost; the graph
    /// already has them as they are now) and repairs every row. The old costs are not needed:
    /// the head of each changed edge has its one-step value recomputed from all its in-edges.
    /// Returns what the repair did.
    ///
    /// The table's nodes are those of the graph when it was built. A node the graph has lost
    /// since (a cell blocked) keeps its place with no edges; a change naming something that is
    /// no node of either is no edge and is passed over; a node the graph has gained is
    /// [`SearchError::UnknownNode`]. Every change is checked before any is applied: that, and an
    /// in-edge of a changed edge's head with a cost the table refuses (the error
    /// [`new`](Self::new) gives for it), leave the table as it was.
    /// An edge the graph changed without telling is met during the repair: an invalid cost there
    /// is an error too, and the table, part repaired, is broken ([`is_broken`](Self::is_broken)):
    /// it answers nothing and refuses every update from then on; build it again.
    ///
    /// # Errors
    ///
    /// As above.
    pub fn update_edges<G>(
        &mut self,
        graph: &G,
        changes: &[EdgeChange<N>],
    ) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if let Some(e) = &self.broken {
            return Err(e.clone());
        }
        let clock = Instant::now();
        let mut heads: Vec<(u32, Vec<(u32, Cost)>)> = Vec::new();
        self.scratch.begin();
        for change in changes {
            let (from, to) = (self.id_of(graph, change.from)?, self.id_of(graph, change.to)?);
            // An edge between a node and something that is no node, then or now: none.
            let (Some(_), Some(head)) = (from, to) else { continue };
            // Each head once: marked by this generation's stamp (cleared by the first repair).
            if self.scratch.stamp[head as usize] != self.scratch.generation {
                self.scratch.stamp[head as usize] = self.scratch.generation;
                self.load_edges(graph, head, false)?;
                heads.push((head, self.scratch.edges.clone()));
            }
        }
        let before = self.totals;
        for row in 0..self.sources.len() {
            if let Err(e) = self.repair(graph, row, &heads) {
                self.broken = Some(e.clone());
                return Err(e);
            }
        }
        let after = self.totals;
        Ok(SearchStats {
            expansions: after.expansions - before.expansions,
            pushes: after.pushes - before.pushes,
            decreases: after.decreases - before.decreases,
            reopenings: 0,
            elapsed: clock.elapsed(),
        })
    }

    /// Repairs row `row` after the in-edges of `heads` changed (each head with its in-edges now).
    fn repair<G>(
        &mut self,
        graph: &G,
        row: usize,
        heads: &[(u32, Vec<(u32, Cost)>)],
    ) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let n = self.nodes.len();
        let source = self.sources[row];
        self.scratch.begin();
        let mut stats = SearchStats::default();
        for (v, into) in heads.iter().filter(|(v, _)| *v != source) {
            let dist = &self.dist[row * n..(row + 1) * n];
            let rhs = self.one_step(into, dist, *v)?;
            if rhs != dist[*v as usize] {
                self.scratch.set_rhs(*v, rhs);
                self.scratch.requeue(*v, dist, &mut stats);
            }
        }
        while let Some((v, _)) = self.scratch.queue.pop() {
            stats.expansions += 1;
            let v = v as u32;
            let g = self.dist[row * n + v as usize];
            let rhs = self.scratch.rhs(v, &self.dist[row * n..(row + 1) * n]);
            self.load_edges(graph, v, true)?;
            let mut successors = std::mem::take(&mut self.scratch.successors);
            successors.clone_from(&self.scratch.edges);
            if rhs < g {
                // Shorter now: take it, and offer each successor the shorter way.
                self.dist[row * n + v as usize] = rhs;
                for &(w, cost) in successors.iter().filter(|(w, _)| *w != source) {
                    let dist = &self.dist[row * n..(row + 1) * n];
                    let through = self.extend(rhs, cost, v, w)?;
                    if through < self.scratch.rhs(w, dist) {
                        self.scratch.set_rhs(w, through);
                        stats.decreases += 1;
                        self.scratch.requeue(w, dist, &mut stats);
                    }
                }
            } else {
                // Longer now: forget it, and every successor whose way ran through it
                // re-derives its one-step value from its in-edges.
                self.dist[row * n + v as usize] = Cost::INFINITY;
                self.scratch.requeue(v, &self.dist[row * n..(row + 1) * n], &mut stats);
                for &(w, cost) in successors.iter().filter(|(w, _)| *w != source) {
                    if self.scratch.rhs(w, &self.dist[row * n..(row + 1) * n]) != g + cost {
                        continue;
                    }
                    self.load_edges(graph, w, false)?;
                    let dist = &self.dist[row * n..(row + 1) * n];
                    let rhs = self.one_step(&self.scratch.edges, dist, w)?;
                    self.scratch.set_rhs(w, rhs);
                    self.scratch.requeue(w, dist, &mut stats);
                }
            }
            self.scratch.successors = successors;
        }
        self.totals += stats;
        Ok(())
    }

    /// The compact id of `node` in a change: `None` for what is no node of the table nor of the
    /// graph (an edge to it is no edge). A node of the table the graph no longer has (a cell
    /// blocked since) keeps its id and has no edges.
    fn id_of<G: IndexedGraph<Node = N> + ?Sized>(
        &self,
        graph: &G,
        node: N,
    ) -> Result<Option<u32>, SearchError<N>> {
        match self.ids.get(&node) {
            Some(&c) => Ok(Some(c)),
            None if graph.contains(node) => Err(SearchError::UnknownNode(node)),
            None => Ok(None),
        }
    }

    /// The compact id of a neighbour the graph reports: a node the table has.
    fn neighbour<G: IndexedGraph<Node = N> + ?Sized>(&self, graph: &G, node: N) -> Option<u32> {
        self.compact.get(graph.index_of(node)).copied().filter(|&c| c != NONE)
    }

    /// `d + cost` for the edge `from -> to`: an error where the cost is lost to rounding (a
    /// cost below the spacing of `f64`s at `d` would let a node keep a distance that no longer
    /// exists).
    fn extend(&self, d: Cost, cost: Cost, from: u32, to: u32) -> Result<Cost, SearchError<N>> {
        let through = d + cost;
        if through == d && d.is_finite() {
            return Err(SearchError::ZeroCostEdge {
                from: self.nodes[from as usize],
                to: self.nodes[to as usize],
            });
        }
        Ok(through)
    }

    /// The one-step value of `v` from its in-edges `into` and the distances `row`.
    fn one_step(&self, into: &[(u32, Cost)], row: &[Cost], v: u32) -> Result<Cost, SearchError<N>> {
        let mut best = Cost::INFINITY;
        for &(p, c) in into {
            best = best.min(self.extend(row[p as usize], c, p, v)?);
        }
        Ok(best)
    }

    /// The cost of an edge read from the graph, checked: positive, and small enough that no path
    /// overflows.
    fn checked(&self, from: N, to: N, cost: Cost) -> Result<Cost, SearchError<N>> {
        if cost.is_nan() || cost < 0.0 {
            Err(SearchError::InvalidEdgeCost { from, to, cost })
        } else if cost == 0.0 {
            Err(SearchError::ZeroCostEdge { from, to })
        } else if cost > self.max_cost && cost.is_finite() {
            Err(SearchError::CostOverflow { node: to })
        } else {
            Ok(cost)
        }
    }

    /// The edges out of (`forward`) or into compact node `v`, as (compact node, cost), checked,
    /// into the scratch list. Infinite costs are no edge; edges to nodes the table does not
    /// have (the graph changed its node set) are an error.
    fn load_edges<G>(&mut self, graph: &G, v: u32, forward: bool) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let node = self.nodes[v as usize];
        let mut edges = std::mem::take(&mut self.scratch.edges);
        edges.clear();
        if !graph.contains(node) {
            // Gone from the graph since the table was built: no edges.
            self.scratch.edges = edges;
            return Ok(());
        }
        let mut failure = None;
        let mut take = |other: N, cost: Cost| {
            if failure.is_some() || cost == Cost::INFINITY {
                return;
            }
            let (from, to) = if forward { (node, other) } else { (other, node) };
            match (self.checked(from, to, cost), self.neighbour(graph, other)) {
                (Ok(cost), Some(u)) => edges.push((u, cost)),
                (Err(e), _) => failure = Some(e),
                (Ok(_), None) => failure = Some(SearchError::UnknownNode(other)),
            }
        };
        if forward {
            graph.for_each_successor(node, &mut take);
        } else {
            graph.for_each_predecessor(node, &mut take);
        }
        self.scratch.edges = edges;
        failure.map_or(Ok(()), Err)
    }

    /// Row `row` from scratch: Dijkstra from its source.
    fn dijkstra<G>(&mut self, graph: &G, row: usize) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let n = self.nodes.len();
        let source = self.sources[row];
        self.dist[row * n..(row + 1) * n].fill(Cost::INFINITY);
        self.dist[row * n + source as usize] = 0.0;
        let mut queue = std::mem::take(&mut self.scratch.queue);
        queue.clear();
        queue.push(source as usize, 0.0);
        self.totals.pushes += 1;
        while let Some((v, d)) = queue.pop() {
            self.totals.expansions += 1;
            self.load_edges(graph, v as u32, true)?;
            for i in 0..self.scratch.edges.len() {
                let (w, cost) = self.scratch.edges[i];
                let through = self.extend(d, cost, v as u32, w)?;
                let slot = row * n + w as usize;
                if through < self.dist[slot] {
                    if self.dist[slot].is_finite() {
                        self.totals.decreases += 1;
                    } else {
                        self.totals.pushes += 1;
                    }
                    self.dist[slot] = through;
                    queue.push(w as usize, through);
                }
            }
        }
        self.scratch.queue = queue;
        Ok(())
    }
}

/// The nodes given, each once, in the order first given.
fn distinct<N: Copy + Eq + std::hash::Hash>(nodes: impl IntoIterator<Item = N>) -> Vec<N> {
    let mut seen = std::collections::HashSet::new();
    nodes.into_iter().filter(|&node| seen.insert(node)).collect()
}
