//! The machinery LPA* and D* Lite share: `g` and `rhs` values, the two-part keys, vertex
//! updates and the repair loop, written once for both directions.
//!
//! LPA* searches forward from its start: `rhs(v) = min over predecessors u of g(u) + c(u, v)`,
//! and an expanded node updates its successors. D* Lite searches backward from its goal:
//! `rhs(u) = min over successors v of c(u, v) + g(v)`, and an expanded node updates its
//! predecessors. Everything else, the keys, the queue and the loop (the optimized version of
//! Koenig and Likhachev's "D* Lite", AAAI 2002, figure 4), is the same, so it lives here with a
//! [`Direction`] flag. The node whose `rhs` is fixed at 0 is the *source* (LPA*'s start, D*
//! Lite's goal); the node whose value the loop computes is the *target* (LPA*'s goal, D* Lite's
//! current start).

use std::collections::{HashMap, VecDeque};
use std::fmt::Debug;

use serde::{Deserialize, Serialize};
use trailmark_core::cost::Cost;
pub use trailmark_core::graph::EdgeChange;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::queue::IndexedHeap;
use crate::search::{MAX_NODES, priority_bits};
use crate::stats::SearchStats;

/// The priority of a node in the queue of LPA* and D* Lite: `[min(g, rhs) + h (+ k_m);
/// min(g, rhs)]`, compared lexicographically (smaller first).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Serialize, Deserialize)]
pub struct Key {
    /// `min(g, rhs) + h`, plus the key modifier `k_m` in D* Lite.
    pub primary: Cost,
    /// `min(g, rhs)`, which breaks ties of the primary part.
    pub secondary: Cost,
}

impl Key {
    /// A key from its two parts.
    pub fn new(primary: Cost, secondary: Cost) -> Self {
        Key { primary, secondary }
    }
}

/// A [`Key`] as one integer, in the order the queue takes nodes: by the primary part, then,
/// among ties, the underconsistent nodes (smaller `g` first, as in the papers) before the
/// overconsistent ones (larger `rhs` first).
///
/// Among overconsistent nodes of equal primary key, the one with the larger `rhs` is the one
/// nearer the target (its heuristic is smaller), so taking it first dives toward the target the
/// way A* does when it breaks ties toward larger `g`. On an open map with the octile
/// heuristic, every cell of the parallelogram between the endpoints ties; the papers' order
/// (smaller first) fills it, this one walks across it. The order among overconsistent ties
/// does not matter for correctness: a node whose `rhs` is not yet its least cost always has a
/// queued node with a strictly smaller primary key. Underconsistent nodes are another matter:
/// their stale values can hold up a tied node's `rhs`, so they keep the papers' order and come
/// first (see [`Lifelong::compute`] for how the loop ends).
///
/// Bits: the primary part's (rounded as [`priority_bits`] says) above the secondary word, whose top bit says overconsistent; the
/// secondary part's bits below it, as they are (underconsistent) or complemented (overconsistent).
/// Both parts are non-negative (or +inf), whose bit patterns order like the numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct QKey(u128);

/// The top bit of the secondary word: an overconsistent node.
const OVER: u64 = 1 << 63;

impl QKey {
    #[inline]
    fn new(key: Key, overconsistent: bool) -> Self {
        let secondary = (key.secondary + 0.0).to_bits();
        let low = if overconsistent { OVER | ((OVER - 1) - secondary) } else { secondary };
        QKey((u128::from(priority_bits(key.primary)) << 64) | u128::from(low))
    }

    /// The bits of the (rounded) primary part, which order like its value.
    #[inline]
    fn primary_bits(self) -> u64 {
        (self.0 >> 64) as u64
    }

    /// Whether the node was underconsistent when queued.
    #[inline]
    fn under(self) -> bool {
        (self.0 as u64) & OVER == 0
    }

    #[inline]
    fn key(self) -> Key {
        let low = self.0 as u64;
        let secondary = if low & OVER == 0 { low } else { (OVER - 1) - (low & !OVER) };
        Key::new(f64::from_bits(self.primary_bits()), f64::from_bits(secondary))
    }
}

/// Whether an underconsistent node whose key has the (rounded) `primary` part must be expanded
/// before the repair loop ends at a `target` primary key: when it is below, or when the two
/// differ by no more than rounding (a relative 1e-9).
///
/// The primary part of a key adds `g`, `h` (and `k_m`) in an order that can differ, in the last
/// bits, from the sums that made the target's `g`; rounding priorities to 32 mantissa bits
/// (see `priority_bits`) makes most such near-ties exact, but two values on either side of a
/// rounding boundary still differ by one unit. Leaving behind an underconsistent node whose
/// key ties with the target's in exact arithmetic could leave a stale value a path would
/// follow; overconsistent near-ties cannot lower the target's value and may wait.
#[inline]
fn below(primary: Cost, target: Cost) -> bool {
    // Written as a difference so that a target near the largest `f64` cannot overflow to a
    // tolerance that admits every key.
    primary <= target || (target.is_finite() && primary - target <= 1e-9 * target.max(1.0))
}

/// What an expansion did to a node's `g`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Consistency {
    /// `g > rhs`: `g` was lowered to `rhs` (the node is now consistent).
    Overconsistent,
    /// `g < rhs`: `g` was raised to infinity (the node will be expanded again if it can still be
    /// reached).
    Underconsistent,
}

/// One expansion of an incremental search, as reported to a trace callback.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expansion<N> {
    /// The node expanded.
    pub node: N,
    /// Its key when it left the queue.
    pub key: Key,
    /// Whether it was over- or underconsistent.
    pub kind: Consistency,
}

/// Which way the values flow: from the start (LPA*) or from the goal (D* Lite).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Direction {
    Forward,
    Backward,
}

/// `g`, `rhs`, the queue, and counters, for nodes numbered by an [`IndexedGraph`].
#[derive(Debug, Clone)]
pub(crate) struct Lifelong<N: Debug> {
    pub dir: Direction,
    /// `g` and `rhs` of every slot.
    v: Values,
    queue: IndexedHeap<QKey>,
    /// The underconsistent nodes of `queue`, by the primary part of their key: the loop's end
    /// waits for those near the target's key (see [`Lifelong::compute`]).
    under: IndexedHeap<u64>,
    /// The slot whose `rhs` is 0.
    pub source: usize,
    /// Counters of the current call.
    pub stats: SearchStats,
    /// Counters since creation.
    pub totals: SearchStats,
    /// The first invalid edge cost met since the last report.
    fault: Option<SearchError<N>>,
    /// The first node whose value (`rhs`) or key overflowed since the search began or was
    /// reset: finite costs whose sum is infinite. Saturated values are no longer exact, so every
    /// computation reports it until [`Lifelong::reset`].
    overflow: Option<N>,
    /// The heuristic inflation of overconsistent keys (AD*); 1 for LPA* and D* Lite.
    epsilon: f64,
    /// Every queued key was computed with the current heuristic (and `k_m`, and inflation), so
    /// none is stale and the repair loop need not recompute the key of each node it pops. Moving
    /// the start or changing the inflation clears it; re-keying the queue sets it.
    keys_current: bool,
    /// Whether nodes expanded in an iteration are closed until the next (AD*): an inconsistent
    /// closed node waits in `incons` instead of the queue.
    anytime: bool,
    /// `closed[s] == iteration` when `s` was expanded (overconsistent) in this iteration.
    closed: Vec<u32>,
    iteration: u32,
    /// Closed nodes made inconsistent in this iteration (may repeat).
    incons: Vec<u32>,
}

/// `g` and `rhs` per slot, side by side (the repair loop reads both of a node at once: one
/// cache line), `+inf` until set. Stored as bits XOR the bits of `+inf`, so that `+inf` is 0 and
/// a fresh table is zeroed memory: the allocator hands large zeroed blocks out without writing
/// them, so a planner made for one query on a large graph pays for the pages its search
/// touches, not for the whole graph.
///
/// The slots set since the last [`Values::reset`] are listed, so that a reset costs what the
/// search touched, not the size of the graph.
#[derive(Debug, Clone, Default)]
struct Values {
    bits: Vec<[u64; 2]>,
    touched: Vec<u32>,
}

const INF_BITS: u64 = 0x7ff0_0000_0000_0000;

impl Values {
    #[inline]
    fn g(&self, slot: usize) -> Cost {
        f64::from_bits(self.bits[slot][0] ^ INF_BITS)
    }

    #[inline]
    fn rhs(&self, slot: usize) -> Cost {
        f64::from_bits(self.bits[slot][1] ^ INF_BITS)
    }

    #[inline]
    fn set_g(&mut self, slot: usize, cost: Cost) {
        self.set(slot, 0, cost)
    }

    #[inline]
    fn set_rhs(&mut self, slot: usize, cost: Cost) {
        self.set(slot, 1, cost)
    }

    #[inline]
    fn set(&mut self, slot: usize, which: usize, cost: Cost) {
        let pair = &mut self.bits[slot];
        if *pair == [0, 0] {
            self.touched.push(slot as u32);
        }
        pair[which] = cost.to_bits() ^ INF_BITS;
    }

    /// Every value back to `+inf`.
    fn reset(&mut self) {
        for &slot in &self.touched {
            self.bits[slot as usize] = [0, 0];
        }
        self.touched.clear();
    }

    fn len(&self) -> usize {
        self.bits.len()
    }

    fn grow(&mut self, len: usize) {
        grow_zeroed(&mut self.bits, len);
    }
}

/// Makes `v` `len` long, new entries 0; a first allocation is a zeroed one (see [`Values`]).
fn grow_zeroed<T: Copy + Default + PartialEq>(v: &mut Vec<T>, len: usize) {
    if v.is_empty() {
        *v = vec![T::default(); len];
    } else if v.len() < len {
        v.resize(len, T::default());
    }
}

/// Whether `cost` is a valid edge cost for lifelong planning: positive, possibly infinite (no
/// edge). Zero is not: around a cycle of zero-cost edges, nodes can keep supporting each other's
/// stale values after the way out is cut, and the repair never notices (the algorithms' proofs
/// assume positive costs).
#[inline]
fn valid_cost(cost: Cost) -> bool {
    cost > 0.0
}

/// The error for an invalid edge cost.
fn cost_error<N: Debug>(from: N, to: N, cost: Cost) -> SearchError<N> {
    if cost == 0.0 {
        SearchError::ZeroCostEdge { from, to }
    } else {
        SearchError::InvalidEdgeCost { from, to, cost }
    }
}

/// Whether `value` is a valid heuristic value: non-negative, possibly infinite (dead end).
#[inline]
pub(crate) fn valid_estimate(value: Cost) -> bool {
    value >= 0.0
}

impl<N: Copy + Eq + std::hash::Hash + Debug> Lifelong<N> {
    /// An empty search with `source` (already checked to be a node) at `rhs = 0`; the caller
    /// queues it with [`Lifelong::update_vertex`].
    pub fn new<G>(dir: Direction, graph: &G, source: N) -> Result<Self, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let mut search = Lifelong {
            dir,
            v: Values::default(),
            queue: IndexedHeap::new(),
            under: IndexedHeap::new(),
            source: 0,
            stats: SearchStats::default(),
            totals: SearchStats::default(),
            fault: None,
            overflow: None,
            epsilon: 1.0,
            keys_current: true,
            anytime: false,
            closed: Vec::new(),
            iteration: 1,
            incons: Vec::new(),
        };
        search.fit(graph)?;
        search.source = graph.index_of(source);
        search.v.set_rhs(search.source, 0.0);
        Ok(search)
    }

    /// Sizes the state to the graph's node bound (graphs may grow between calls).
    pub fn fit<G>(&mut self, graph: &G) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let bound = graph.node_bound();
        if bound > MAX_NODES {
            return Err(SearchError::TooManyNodes(bound));
        }
        if self.v.len() < bound {
            self.v.grow(bound);
            self.queue.reserve_items(bound);
        }
        if self.anytime && self.closed.len() < bound {
            grow_zeroed(&mut self.closed, bound);
        }
        Ok(())
    }

    /// Forgets everything for a new query from `source` (already checked to be a node), keeping
    /// the memory: the cost is that of the nodes the previous queries touched.
    pub fn reset<G>(&mut self, graph: &G, source: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.v.reset();
        self.queue.clear();
        self.under.clear();
        self.incons.clear();
        // Closed marks are iteration numbers: the next one makes them all stale.
        self.advance_iteration();
        self.keys_current = true;
        self.stats = SearchStats::default();
        self.fault = None;
        self.overflow = None;
        self.fit(graph)?;
        self.source = graph.index_of(source);
        self.v.set_rhs(self.source, 0.0);
        Ok(())
    }

    /// Moves to the next iteration number, which makes every closed mark stale. After 2^32 - 1
    /// iterations (resets included) the marks are cleared and the numbers start again.
    fn advance_iteration(&mut self) {
        if self.iteration == u32::MAX {
            self.closed.fill(0);
            self.iteration = 0;
        }
        self.iteration += 1;
    }

    /// Turns on the anytime behaviour of AD* (closed lists per iteration, inflated keys).
    pub fn make_anytime(&mut self, epsilon: f64) {
        self.anytime = true;
        self.set_epsilon(epsilon);
        grow_zeroed(&mut self.closed, self.v.len());
    }

    /// Sets the inflation of overconsistent keys; queued keys are stale until re-keyed.
    pub fn set_epsilon(&mut self, epsilon: f64) {
        if epsilon != self.epsilon {
            self.epsilon = epsilon;
            self.keys_current = false;
        }
    }

    /// Marks the queued keys stale: the heuristic part of keys changed (the start moved).
    pub fn keys_changed(&mut self) {
        self.keys_current = false;
    }

    /// Starts a new iteration (AD*): nothing is closed any more, the inconsistent nodes held
    /// back join the queue, and every queued key is recomputed (the inflation or the start may
    /// have changed).
    pub fn next_iteration<G>(&mut self, graph: &G, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.advance_iteration();
        let mut slots: Vec<usize> = self.queue.iter().map(|(s, _)| s).collect();
        slots.extend(self.incons.drain(..).map(|s| s as usize));
        self.queue.clear();
        self.under.clear();
        for s in slots {
            if self.v.g(s) != self.v.rhs(s) {
                let key = self.qkey(graph, s, h);
                self.enqueue(s, key);
            }
        }
        self.keys_current = true;
    }

    /// Recomputes the key of every queued node with `h` (after the key modifier was reset).
    pub fn rekey<G>(&mut self, graph: &G, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let slots: Vec<usize> = self.queue.iter().map(|(s, _)| s).collect();
        for s in slots {
            let key = self.qkey(graph, s, h);
            self.enqueue(s, key);
        }
        self.keys_current = true;
    }

    /// The first node whose value or key overflowed since the search began or was reset.
    pub fn overflow(&self) -> Option<N> {
        self.overflow
    }

    /// Remembers that the value or key of `node` overflowed (the first such node only).
    #[cold]
    #[inline(never)]
    fn overflowed(&mut self, node: N) {
        self.overflow.get_or_insert(node);
    }

    /// The slot of a node named by the user, or an error if it names nothing.
    pub fn slot_of<G>(&self, graph: &G, node: N) -> Result<usize, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        match graph.checked_index(node) {
            Some(i) if i < self.v.len() => Ok(i),
            _ => Err(SearchError::UnknownNode(node)),
        }
    }

    #[inline]
    pub fn g(&self, slot: usize) -> Cost {
        self.v.g(slot)
    }

    #[inline]
    pub fn rhs(&self, slot: usize) -> Cost {
        self.v.rhs(slot)
    }

    /// The queued nodes and their keys, least first.
    pub fn queue(&self) -> Vec<(usize, Key)> {
        let mut items: Vec<(usize, QKey)> = self.queue.iter().collect();
        items.sort_by_key(|&(s, k)| (k, s));
        items.into_iter().map(|(s, k)| (s, k.key())).collect()
    }

    /// Bytes held by the state and the queue.
    pub fn memory_bytes(&self) -> usize {
        self.v.bits.capacity() * 16
            + (self.closed.capacity() + self.incons.capacity()) * 4
            + self.queue.memory_bytes()
    }

    /// Takes the first fault met since the last call.
    pub fn take_fault(&mut self) -> Option<SearchError<N>> {
        self.fault.take()
    }

    /// Remembers an invalid edge (the first one only).
    #[cold]
    fn bad_edge(&mut self, from: N, to: N, cost: Cost) {
        if self.fault.is_none() {
            self.fault = Some(cost_error(from, to, cost));
        }
    }

    /// The queue's key of `slot`.
    #[inline]
    fn qkey<G>(&mut self, graph: &G, slot: usize, h: &mut impl FnMut(N) -> Cost) -> QKey
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.qkey_at(slot, graph.node_at(slot), h)
    }

    /// The queue's key of `slot`, which is `node`.
    #[inline]
    fn qkey_at(&mut self, slot: usize, node: N, h: &mut impl FnMut(N) -> Cost) -> QKey {
        let key = self.key_at(slot, node, h);
        QKey::new(key, self.v.g(slot) > self.v.rhs(slot))
    }

    /// Queues `slot` with `key`, or changes its key (and keeps `under` in step).
    #[inline]
    fn enqueue(&mut self, slot: usize, key: QKey) {
        let old = self.queue.push(slot, key);
        match old {
            None => self.stats.pushes += 1,
            Some(_) => self.stats.decreases += 1,
        }
        if key.under() {
            self.under.push(slot, key.primary_bits());
        } else if old.is_some_and(QKey::under) {
            self.under.remove(slot);
        }
    }

    /// Takes `slot` out of the queue if it is there.
    #[inline]
    fn dequeue(&mut self, slot: usize) {
        if self.queue.remove(slot).is_some_and(QKey::under) {
            self.under.remove(slot);
        }
    }

    /// The key of `slot`, which is `node`, with `h` the heuristic part (and `k_m`) of the node.
    /// A primary part that overflows (finite `min(g, rhs)` and `h`, infinite sum) is `+inf`,
    /// which would make the node a dead end: it is remembered (see [`Lifelong::overflow`]).
    #[inline]
    fn key_at(&mut self, slot: usize, node: N, h: &mut impl FnMut(N) -> Cost) -> Key {
        // `[min(g, rhs) + h; min(g, rhs)]`, with AD*'s inflation of overconsistent nodes
        // (`[rhs + epsilon h; rhs]`), which is the same key when epsilon is 1.
        let (g, rhs) = (self.v.g(slot), self.v.rhs(slot));
        let m = g.min(rhs);
        if m == f64::INFINITY {
            return Key::new(m, m);
        }
        let h = h(node);
        let key = if g > rhs { Key::new(rhs + self.epsilon * h, rhs) } else { Key::new(g + h, g) };
        if key.primary == f64::INFINITY && h < f64::INFINITY {
            self.overflowed(node);
        }
        key
    }

    /// Queues `slot` with its current key when it is inconsistent, takes it out otherwise.
    #[inline]
    pub fn update_vertex<G>(&mut self, graph: &G, slot: usize, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.update_vertex_at(slot, graph.node_at(slot), h)
    }

    /// [`Lifelong::update_vertex`] of `slot`, which is `node`.
    #[inline]
    fn update_vertex_at(&mut self, slot: usize, node: N, h: &mut impl FnMut(N) -> Cost) {
        let (g, rhs) = (self.v.g(slot), self.v.rhs(slot));
        if self.anytime && self.closed[slot] == self.iteration && g > rhs && g < f64::INFINITY {
            // A node expanded in this iteration that can now improve waits for the next one
            // (that is what bounds an iteration's work, as in ARA*): its `g` is the cost of a
            // real path meanwhile. Any other inconsistent closed node is queued now: one whose
            // value rose (underconsistent), or that lost its value (`g` infinite). In exact
            // arithmetic neither happens to a closed node, but when rounding ties reorder two
            // keys it does, and deferring it would leave nodes resting on a stale value.
            // As in the paper's UpdateState, a node moved to INCONS leaves OPEN (it may have
            // been queued as underconsistent since its expansion).
            self.dequeue(slot);
            self.incons.push(slot as u32);
        } else if g != rhs {
            let key = self.qkey_at(slot, node, h);
            self.enqueue(slot, key);
        } else {
            self.dequeue(slot);
        }
    }

    /// Calls `visit(self, slot, neighbour, cost)` for each edge along which `slot`'s `g` flows: its
    /// predecessors (backward) or successors (forward).
    #[inline]
    fn each_dependent<G>(&mut self, graph: &G, slot: usize, visit: impl FnMut(&mut Self, usize, N, Cost))
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.each_edge(graph, slot, self.dir == Direction::Forward, visit)
    }

    /// Calls `visit(self, slot, neighbour, cost)` for each edge `slot`'s `rhs` is computed over: its
    /// successors (backward) or predecessors (forward).
    #[inline]
    fn each_support<G>(&mut self, graph: &G, slot: usize, visit: impl FnMut(&mut Self, usize, N, Cost))
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.each_edge(graph, slot, self.dir == Direction::Backward, visit)
    }

    /// Calls `visit(self, slot, neighbour, cost)` for each edge leaving (`outgoing`) or entering
    /// `slot`. Invalid costs are remembered and skipped, self-loops skipped.
    #[inline]
    fn each_edge<G>(
        &mut self,
        graph: &G,
        slot: usize,
        outgoing: bool,
        mut visit: impl FnMut(&mut Self, usize, N, Cost),
    ) where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut step = |this: &mut Self, s: usize, node: N, c: Cost| {
            if s == slot {
                return;
            }
            if !valid_cost(c) {
                let here = graph.node_at(slot);
                let (from, to) = if outgoing { (here, node) } else { (node, here) };
                return this.bad_edge(from, to, c);
            }
            visit(this, s, node, c)
        };
        if outgoing {
            graph.for_each_successor_index(slot, |s, node, c| step(self, s, node, c))
        } else {
            graph.for_each_predecessor_index(slot, |s, node, c| step(self, s, node, c))
        }
    }

    /// `rhs` of `slot` computed afresh from its neighbours' `g`. When it is infinite only because
    /// a finite `g` plus a finite edge cost overflowed, that is remembered (see
    /// [`Lifelong::overflow`]); an overflowing sum beside a finite one is simply not the least.
    fn rhs_from_scratch<G>(&mut self, graph: &G, slot: usize) -> Cost
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut best = f64::INFINITY;
        let mut overflow = false;
        self.each_support(graph, slot, |this, s, _, c| {
            let g = this.v.g(s);
            let via = c + g;
            overflow |= via == f64::INFINITY && g < f64::INFINITY && c < f64::INFINITY;
            best = best.min(via);
        });
        if overflow && best == f64::INFINITY {
            self.overflowed(graph.node_at(slot));
        }
        best
    }

    /// Recomputes `rhs` of `slot` from scratch (unless it is the source) and requeues it: the
    /// response to a change of any of its edges.
    pub fn refresh<G>(&mut self, graph: &G, slot: usize, h: &mut impl FnMut(N) -> Cost)
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if slot == self.source {
            return;
        }
        let rhs = self.rhs_from_scratch(graph, slot);
        self.set_rhs(graph, slot, rhs, h);
    }

    /// Sets `rhs` of `slot` and requeues it, if `rhs` changed: a node whose `rhs` (and `g`) did
    /// not change keeps its place in the queue or stays out of it, and a key it keeps from an
    /// older `k_m` is a lower bound, requeued when popped. Skipping it saves a key computation
    /// and a heap operation.
    #[inline]
    fn set_rhs<G>(&mut self, graph: &G, slot: usize, rhs: Cost, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.set_rhs_at(slot, graph.node_at(slot), rhs, h)
    }

    /// [`Lifelong::set_rhs`] of `slot`, which is `node`.
    #[inline]
    fn set_rhs_at(&mut self, slot: usize, node: N, rhs: Cost, h: &mut impl FnMut(N) -> Cost) {
        if rhs != self.v.rhs(slot) {
            self.v.set_rhs(slot, rhs);
            self.update_vertex_at(slot, node, h);
        }
    }

    /// The response to the change of one edge, whose cost is now `new` (as the graph says): the
    /// edge joins `dependent` (whose `rhs` it enters) and `support` (whose `g` it carries). Only
    /// the dependent's `rhs` can change.
    ///
    /// The edge's old cost is not used, so a caller who gives a wrong one cannot mislead the
    /// repair (the papers' test "was the old edge the best?" trusts it): when the edge now offers
    /// less than the dependent's `rhs`, that is the new `rhs`; when it offers the same, nothing
    /// changes; when it offers more, it may have been the best before and got dearer, and `rhs`
    /// is recomputed from all of the dependent's edges. With a right old cost this does what
    /// the papers' version does (the same values, the same queue), at the price of a
    /// recomputation for an edge that got dearer without being the best.
    pub fn edge_changed<G>(
        &mut self,
        graph: &G,
        dependent: usize,
        support: usize,
        new: Cost,
        h: &mut impl FnMut(N) -> Cost,
    ) where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if dependent == self.source || dependent == support {
            return;
        }
        let through = self.v.g(support);
        if through == f64::INFINITY {
            // The edge carries nothing, before or after, whatever its cost.
            return;
        }
        let (via, before) = (new + through, self.v.rhs(dependent));
        let rhs = if via < before {
            via
        } else if via == before {
            if via == f64::INFINITY && new < f64::INFINITY {
                self.overflowed(graph.node_at(dependent));
            }
            return;
        } else {
            self.rhs_from_scratch(graph, dependent)
        };
        self.set_rhs(graph, dependent, rhs, h);
    }

    /// The repair loop: expands inconsistent nodes in key order until `target` is consistent and
    /// no queued key is below its key: it ends at the first queued node whose primary key
    /// reaches the target's (as A* stops at its goal), since expanding it could not lower the
    /// target's value, once every underconsistent node whose primary key ties with the
    /// target's up to rounding (see [`below`]) is expanded too, so that no stale value is left
    /// where a path could follow it. `h` gives the heuristic part of a node's key. Before each
    /// expansion `interrupt(expansions so far in this call)` may stop the loop early, leaving a
    /// valid state to continue from; returns whether the loop ran to its end.
    pub fn compute<G>(
        &mut self,
        graph: &G,
        target: usize,
        h: &mut impl FnMut(N) -> Cost,
        trace: &mut impl FnMut(Expansion<N>),
        interrupt: &mut impl FnMut(u64) -> bool,
    ) -> bool
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        // The target's key, recomputed only when its values change (the heuristic does not
        // change during the loop).
        let mut target_values = (self.v.g(target), self.v.rhs(target));
        let mut target_key = self.qkey(graph, target, h);
        while let Some((top, k_top)) = self.queue.peek() {
            let values = (self.v.g(target), self.v.rhs(target));
            if values != target_values {
                target_values = values;
                target_key = self.qkey(graph, target, h);
            }
            let (u, k_old) = if k_top.primary_bits() < target_key.primary_bits() || values.0 != values.1 {
                (top, k_top)
            } else {
                // No node below the target's key can improve its value; but an underconsistent
                // node whose key ties with it up to rounding may hold a stale value that a path
                // would follow: those are expanded first.
                let target_primary = f64::from_bits(target_key.primary_bits());
                match self.under.peek() {
                    Some((w, bits)) if below(f64::from_bits(bits), target_primary) => {
                        (w, self.queue.key(w).expect("underconsistent nodes are queued"))
                    }
                    _ => break,
                }
            };
            if !self.keys_current {
                let k_new = self.qkey(graph, u, h);
                if k_old < k_new {
                    // The key was computed with an older `k_m` or start: requeue, expand later.
                    self.enqueue(u, k_new);
                    continue;
                }
            } else {
                debug_assert!(k_old == self.qkey(graph, u, h), "a stale key while keys are current");
            }
            if interrupt(self.stats.expansions) {
                return false;
            }
            if u == top {
                self.queue.pop();
            } else {
                self.queue.remove(u);
            }
            if k_old.under() {
                self.under.remove(u);
            }
            self.stats.expansions += 1;
            let kind = if self.v.g(u) > self.v.rhs(u) {
                Consistency::Overconsistent
            } else {
                Consistency::Underconsistent
            };
            trace(Expansion { node: graph.node_at(u), key: k_old.key(), kind });
            match kind {
                Consistency::Overconsistent => {
                    let gu = self.v.rhs(u);
                    self.v.set_g(u, gu);
                    if self.anytime {
                        self.closed[u] = self.iteration;
                    }
                    // The paper updates every dependent; `set_rhs` skips those whose `rhs` did
                    // not change.
                    self.each_dependent(graph, u, |this, s, node, c| {
                        let via = c + gu;
                        if s != this.source && via < this.v.rhs(s) {
                            this.set_rhs_at(s, node, via, h);
                        } else if via == f64::INFINITY
                            && c < f64::INFINITY
                            && s != this.source
                            && this.v.rhs(s) == f64::INFINITY
                        {
                            // Reachable, at a cost beyond the largest `f64`.
                            this.overflowed(node);
                        }
                    });
                }
                Consistency::Underconsistent => {
                    let g_old = self.v.g(u);
                    self.v.set_g(u, f64::INFINITY);
                    self.each_dependent(graph, u, |this, s, node, c| {
                        if s != this.source && this.v.rhs(s) == c + g_old {
                            let rhs = this.rhs_from_scratch(graph, s);
                            this.set_rhs_at(s, node, rhs, h);
                        }
                    });
                    self.update_vertex(graph, u, h);
                }
            }
        }
        true
    }

    /// The path from `target` to the source along the best supports (`argmin c + g`), in the
    /// order walked; `None` when the target's value is infinite. Ties prefer the smaller `g`.
    ///
    /// With positive costs `g` falls strictly along such a path, so the walk only takes
    /// supports of smaller `g` and needs no record of where it has been. Where rounding makes
    /// the best support's `g` equal to the node's own (an edge far cheaper than the values it
    /// joins, absorbed in the sum), a greedy walk could go round in circles or, kept from doing
    /// so, take a worse support: the walk is then made breadth-first over every best support.
    pub fn walk<G>(&self, graph: &G, target: usize) -> Option<Vec<usize>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if self.v.g(target).min(self.v.rhs(target)) == f64::INFINITY {
            return None;
        }
        let mut slots = vec![target];
        let mut at = target;
        while at != self.source {
            let limit = self.v.g(at).min(self.v.rhs(at));
            match self.best_support(graph, at) {
                Some(next) if self.v.g(next) < limit => {
                    slots.push(next);
                    at = next;
                }
                _ => return self.walk_breadth_first(graph, target),
            }
        }
        Some(slots)
    }

    /// [`Lifelong::walk`] as a breadth-first search from `target` over the edges to each node's
    /// best supports (all those with the least `c + g`, rounded): the fewest edges among the
    /// paths whose every step is a best support, so the path's cost is the target's value.
    fn walk_breadth_first<G>(&self, graph: &G, target: usize) -> Option<Vec<usize>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut parent = HashMap::from([(target, target)]);
        let mut queue = VecDeque::from([target]);
        let mut supports: Vec<(usize, Cost)> = Vec::new();
        while let Some(at) = queue.pop_front() {
            if at == self.source {
                let mut slots = vec![at];
                let mut node = at;
                while node != target {
                    node = parent[&node];
                    slots.push(node);
                }
                slots.reverse();
                return Some(slots);
            }
            supports.clear();
            let mut collect = |s: usize, c: Cost| {
                let via = c + self.v.g(s);
                // `via < inf` also rejects invalid (NaN) costs.
                if s != at && via < f64::INFINITY {
                    supports.push((s, via));
                }
            };
            match self.dir {
                Direction::Backward => graph.for_each_successor_index(at, |s, _, c| collect(s, c)),
                Direction::Forward => graph.for_each_predecessor_index(at, |s, _, c| collect(s, c)),
            }
            let best = supports.iter().map(|&(_, via)| via).fold(f64::INFINITY, f64::min);
            for &(s, via) in &supports {
                if via == best && !parent.contains_key(&s) {
                    parent.insert(s, at);
                    queue.push_back(s);
                }
            }
        }
        None
    }

    /// The neighbour of `at` that `at`'s value flows through: `argmin c + g` over its supports
    /// (successors backward, predecessors forward), ties to the smaller `g`; `None` when every
    /// support is infinitely far.
    pub fn best_support<G>(&self, graph: &G, at: usize) -> Option<usize>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut best: Option<(Cost, Cost, usize)> = None;
        let mut consider = |s: usize, c: Cost| {
            let via = (c + self.v.g(s), self.v.g(s), s);
            // `via.0 < inf` also rejects invalid (NaN) costs; negative ones never come this
            // far, since the search refused them.
            if via.0 < f64::INFINITY && s != at && best.is_none_or(|b| (via.0, via.1) < (b.0, b.1)) {
                best = Some(via);
            }
        };
        match self.dir {
            Direction::Backward => graph.for_each_successor_index(at, |s, _, c| consider(s, c)),
            Direction::Forward => graph.for_each_predecessor_index(at, |s, _, c| consider(s, c)),
        }
        best.map(|b| b.2)
    }

    /// The walk as a path of nodes from the start to the goal, with `cost`.
    pub fn path<G>(&self, graph: &G, target: usize, cost: Cost) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut nodes: Vec<N> = self.walk(graph, target)?.into_iter().map(|s| graph.node_at(s)).collect();
        if self.dir == Direction::Forward {
            nodes.reverse();
        }
        Some(Path { nodes, cost })
    }

    /// Folds the current call's counters into the totals and returns them with `elapsed`.
    pub fn close_call(&mut self, elapsed: std::time::Duration) -> SearchStats {
        let mut stats = std::mem::take(&mut self.stats);
        stats.elapsed = elapsed;
        self.totals.expansions += stats.expansions;
        self.totals.pushes += stats.pushes;
        self.totals.decreases += stats.decreases;
        self.totals.elapsed += elapsed;
        stats
    }
}

/// The cost of the edge `from -> to` in `graph` now (the least of parallel edges), `+inf` when
/// there is none; an invalid cost is returned as it is, for the caller to reject.
pub(crate) fn edge_cost<G>(graph: &G, from: G::Node, to: G::Node) -> Cost
where
    G: Successors + ?Sized,
{
    let mut cost = f64::INFINITY;
    if graph.contains(from) {
        graph.for_each_successor(from, |n, c| {
            // NaN replaces anything, so that the caller sees (and rejects) it.
            if n == to && (c < cost || c.is_nan()) {
                cost = c;
            }
        });
    }
    cost
}

/// A lifelong planner between a start and a goal: the search, the heuristic, the endpoints and
/// D* Lite's key modifier. [`LpaStar`](crate::LpaStar) and [`DStarLite`](crate::DStarLite) are
/// this, forward and backward.
#[derive(Debug, Clone)]
pub(crate) struct Planner<N: Debug, H> {
    pub search: Lifelong<N>,
    heuristic: H,
    pub start: N,
    start_slot: usize,
    pub goal: N,
    goal_slot: usize,
    /// The start when `k_m` was last brought up to date (backward only).
    last: N,
    pub k_m: Cost,
    /// The first invalid heuristic value met since the last report.
    bad_h: Option<(N, Cost)>,
    /// The first node whose heuristic part `h(start, s) + k_m` overflowed since the planner was
    /// made or reset (see [`Lifelong::overflow`]).
    h_overflow: Option<N>,
}

impl<N, H> Planner<N, H>
where
    N: Copy + Eq + std::hash::Hash + Debug,
    H: FnMut(N, N) -> Cost,
{
    /// A planner; `anytime` is AD*'s initial inflation (`None` for LPA* and D* Lite).
    pub fn new<G>(
        dir: Direction,
        graph: &G,
        start: N,
        goal: N,
        heuristic: H,
        anytime: Option<f64>,
    ) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        check_endpoints(graph, start, goal)?;
        let source = if dir == Direction::Backward { goal } else { start };
        let mut search = Lifelong::new(dir, graph, source)?;
        if let Some(epsilon) = anytime {
            search.make_anytime(epsilon);
        }
        let (start_slot, goal_slot) = (graph.index_of(start), graph.index_of(goal));
        let mut planner = Planner {
            search,
            heuristic,
            start,
            start_slot,
            goal,
            goal_slot,
            last: start,
            k_m: 0.0,
            bad_h: None,
            h_overflow: None,
        };
        let source = planner.search.source;
        {
            let (search, mut h) = planner.keyed(graph);
            search.update_vertex(graph, source, &mut h);
        }
        planner.search.close_call(std::time::Duration::ZERO);
        Ok(planner)
    }

    /// A new query from `start` to `goal` with the planner's memory (see [`Lifelong::reset`]).
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        check_endpoints(graph, start, goal)?;
        let source = if self.search.dir == Direction::Backward { goal } else { start };
        self.search.reset(graph, source)?;
        (self.start, self.goal, self.last) = (start, goal, start);
        (self.start_slot, self.goal_slot) = (graph.index_of(start), graph.index_of(goal));
        self.k_m = 0.0;
        self.bad_h = None;
        self.h_overflow = None;
        let source = self.search.source;
        {
            let (search, mut h) = self.keyed(graph);
            search.update_vertex(graph, source, &mut h);
        }
        self.search.close_call(std::time::Duration::ZERO);
        Ok(())
    }

    /// The node whose value the search computes: the goal (forward) or the start (backward).
    fn target(&self) -> usize {
        match self.search.dir {
            Direction::Forward => self.goal_slot,
            Direction::Backward => self.start_slot,
        }
    }

    /// The search, with the heuristic part of keys: `h(s, goal)` forward, `h(start, s) + k_m`
    /// backward (bringing `k_m` up to date first if the robot moved). Invalid heuristic values
    /// count as 0 and are remembered.
    ///
    /// Should `k_m` overflow (or a hostile heuristic make it infinite), it starts again from 0
    /// and every queued key is recomputed from the current start, which is what `k_m` exists to
    /// avoid, and exact.
    fn keyed<G>(&mut self, graph: &G) -> (&mut Lifelong<N>, impl FnMut(N) -> Cost + '_)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let Planner { search, heuristic, start, goal, last, k_m, bad_h, h_overflow, .. } = self;
        let backward = search.dir == Direction::Backward;
        let mut estimate = move |a: N, b: N| {
            let v = heuristic(a, b);
            if valid_estimate(v) {
                v
            } else {
                bad_h.get_or_insert((if backward { b } else { a }, v));
                0.0
            }
        };
        let mut rekey = false;
        if backward && !search.anytime && *last != *start {
            let moved = *k_m + estimate(*last, *start);
            if moved.is_finite() {
                *k_m = moved;
            } else {
                *k_m = 0.0;
                rekey = true;
            }
            *last = *start;
        }
        let (start, goal, k_m) = (*start, *goal, *k_m);
        let mut h = move |s: N| {
            if backward {
                let v = estimate(start, s);
                let sum = v + k_m;
                if sum == f64::INFINITY && v < f64::INFINITY {
                    h_overflow.get_or_insert(s);
                }
                sum
            } else {
                estimate(s, goal)
            }
        };
        if rekey {
            search.rekey(graph, &mut h);
        }
        (search, h)
    }

    pub fn compute<G>(
        &mut self,
        graph: &G,
        trace: impl FnMut(Expansion<N>),
    ) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.run(graph, trace, &mut |_| false).map(|(_, stats)| stats)
    }

    /// AD*: one pass of the repair loop at the current inflation, from the current start,
    /// stopped early when `interrupt(expansions)` says so. Returns whether the pass completed,
    /// and the pass's statistics.
    pub fn compute_interruptible<G>(
        &mut self,
        graph: &G,
        interrupt: &mut impl FnMut(u64) -> bool,
    ) -> Result<(bool, SearchStats), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.run(graph, |_| {}, interrupt)
    }

    /// The repair loop from the current start, with its checks, statistics and error report.
    fn run<G>(
        &mut self,
        graph: &G,
        mut trace: impl FnMut(Expansion<N>),
        interrupt: &mut impl FnMut(u64) -> bool,
    ) -> Result<(bool, SearchStats), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let clock = std::time::Instant::now();
        check_endpoints(graph, self.start, self.goal)?;
        self.search.fit(graph)?;
        let target = self.target();
        let complete = {
            let (search, mut h) = self.keyed(graph);
            search.compute(graph, target, &mut h, &mut trace, interrupt)
        };
        let stats = self.search.close_call(clock.elapsed());
        self.report()?;
        if let Some(node) = self.search.overflow().or(self.h_overflow) {
            return Err(SearchError::CostOverflow { node });
        }
        Ok((complete, stats))
    }

    /// AD*: starts a new iteration at inflation `epsilon` (see [`Lifelong::next_iteration`]).
    pub fn next_iteration<G>(&mut self, graph: &G, epsilon: f64)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.search.set_epsilon(epsilon);
        let (search, mut h) = self.keyed(graph);
        search.next_iteration(graph, &mut h);
    }

    /// The first fault since the last report, as an error.
    fn report(&mut self) -> Result<(), SearchError<N>> {
        if let Some(e) = self.search.take_fault() {
            self.bad_h = None;
            return Err(e);
        }
        match self.bad_h.take() {
            Some((node, value)) => Err(SearchError::InvalidHeuristic { node, value }),
            None => Ok(()),
        }
    }

    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        if !graph.contains(to) {
            return Err(SearchError::StartNotInGraph(to));
        }
        self.start_slot = self.search.slot_of(graph, to)?;
        if to != self.start {
            // Backward, the heuristic part of every key is measured from the start.
            self.search.keys_changed();
        }
        self.start = to;
        Ok(())
    }

    pub fn update_edges<G>(&mut self, graph: &G, changes: &[EdgeChange<N>]) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.fit(graph)?;
        let slots = changes
            .iter()
            .map(|c| {
                let slots = (self.search.slot_of(graph, c.from)?, self.search.slot_of(graph, c.to)?);
                let new = edge_cost(graph, c.from, c.to);
                // The old cost is checked (one that cannot be a cost says the caller is confused)
                // but not used: the repair reads the graph (see `Lifelong::edge_changed`).
                for cost in [c.old_cost, new] {
                    if !valid_cost(cost) {
                        return Err(cost_error(c.from, c.to, cost));
                    }
                }
                Ok((slots, new))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let backward = self.search.dir == Direction::Backward;
        {
            let (search, mut h) = self.keyed(graph);
            for ((from, to), new) in slots {
                let (dependent, support) = if backward { (from, to) } else { (to, from) };
                search.edge_changed(graph, dependent, support, new, &mut h);
            }
        }
        self.search.close_call(std::time::Duration::ZERO);
        self.report()
    }

    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<usize, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.fit(graph)?;
        let slots =
            nodes.into_iter().map(|n| self.search.slot_of(graph, n)).collect::<Result<Vec<_>, _>>()?;
        let told = slots.len();
        {
            let (search, mut h) = self.keyed(graph);
            for slot in slots {
                search.refresh(graph, slot, &mut h);
            }
        }
        self.search.close_call(std::time::Duration::ZERO);
        self.report().map(|()| told)
    }

    pub fn cost(&self) -> Option<Cost> {
        let g = self.search.g(self.target());
        g.is_finite().then_some(g)
    }

    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.search.path(graph, self.target(), self.cost()?)
    }

    /// The second node of the path (backward: the robot's next move).
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.cost()?;
        let target = self.target();
        if target == self.search.source {
            return None;
        }
        self.search.best_support(graph, target).map(|s| graph.node_at(s))
    }

    pub fn g<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.search.g(self.search.slot_of(graph, node)?))
    }

    pub fn rhs<G>(&self, graph: &G, node: N) -> Result<Cost, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        Ok(self.search.rhs(self.search.slot_of(graph, node)?))
    }

    pub fn queue<G>(&self, graph: &G) -> Vec<(N, Key)>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.search.queue().into_iter().map(|(s, k)| (graph.node_at(s), k)).collect()
    }
}

/// Errors unless both endpoints are nodes of the graph.
pub(crate) fn check_endpoints<G>(graph: &G, start: G::Node, goal: G::Node) -> Result<(), SearchError<G::Node>>
where
    G: IndexedGraph + ?Sized,
{
    if !graph.contains(start) {
        return Err(SearchError::StartNotInGraph(start));
    }
    if !graph.contains(goal) {
        return Err(SearchError::GoalNotInGraph(goal));
    }
    Ok(())
}
