//! The repair engine of the incremental searches: vertex updates, the response to changed
//! edges, and the repair loop, for either direction.

use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};

use crate::error::SearchError;
use crate::incremental::mode::{Anytime, Mode};
use crate::incremental::packed_key::{PackedKey, below};
use crate::incremental::values::Values;
use crate::incremental::{Consistency, Expansion, Key};
use crate::limits::MAX_NODES;
use crate::queue::IndexedHeap;
use crate::stats::SearchStats;

/// Which way the values flow: from the start (LPA*) or from the goal (D* Lite).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SearchDirection {
    Forward,
    Backward,
}

/// `g`, `rhs`, the queue, and counters, for nodes numbered by an [`IndexedGraph`]; `M` says how
/// expanded nodes are treated ([`Exact`] for LPA* and D* Lite, [`Anytime`] for AD*).
#[derive(Debug, Clone)]
pub(crate) struct RepairEngine<N: Debug, M> {
    pub dir: SearchDirection,
    /// `g` and `rhs` of every slot.
    v: Values,
    queue: IndexedHeap<PackedKey>,
    /// The underconsistent nodes of `queue`, by the primary part of their key: the loop's end
    /// waits for those near the target's key (see [`RepairEngine::compute`]).
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
    /// computation reports it until [`RepairEngine::reset`].
    overflow: Option<N>,
    /// Every queued key was computed with the current heuristic (and `k_m`, and inflation), so
    /// none is stale and the repair loop need not recompute the key of each node it pops. Moving
    /// the start or changing the inflation clears it; re-keying the queue sets it.
    keys_current: bool,
    /// How expanded nodes are treated, and the inflation of keys.
    pub mode: M,
}

/// Whether `cost` is a valid edge cost for lifelong planning: positive, possibly infinite (no
/// edge). Zero is not: around a cycle of zero-cost edges, nodes can keep supporting each other's
/// stale values after the way out is cut, and the repair never notices (the algorithms' proofs
/// assume positive costs).
#[inline]
pub(crate) fn valid_cost(cost: Cost) -> bool {
    cost > 0.0
}

/// The error for an invalid edge cost.
pub(crate) fn cost_error<N: Debug>(from: N, to: N, cost: Cost) -> SearchError<N> {
    if cost == 0.0 {
        SearchError::ZeroCostEdge { from, to }
    } else {
        SearchError::InvalidEdgeCost { from, to, cost }
    }
}

impl<N: Copy + Eq + std::hash::Hash + Debug, M: Mode> RepairEngine<N, M> {
    /// An empty search with `source` (already checked to be a node) at `rhs = 0`; the caller
    /// queues it with [`RepairEngine::update_vertex`].
    pub fn new<G>(dir: SearchDirection, graph: &G, source: N, mode: M) -> Result<Self, SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        // Keys computed with an inflation other than 1 are stale until the first re-keying.
        let keys_current = mode.inflation() == 1.0;
        let mut search = RepairEngine {
            dir,
            v: Values::default(),
            queue: IndexedHeap::new(),
            under: IndexedHeap::new(),
            source: 0,
            stats: SearchStats::default(),
            totals: SearchStats::default(),
            fault: None,
            overflow: None,
            keys_current,
            mode,
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
        self.mode.fit(bound);
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
        self.mode.reset();
        self.keys_current = true;
        self.stats = SearchStats::default();
        self.fault = None;
        self.overflow = None;
        self.fit(graph)?;
        self.source = graph.index_of(source);
        self.v.set_rhs(self.source, 0.0);
        Ok(())
    }

    /// Marks the queued keys stale: the heuristic part of keys changed (the start moved).
    pub fn keys_changed(&mut self) {
        self.keys_current = false;
    }

    /// Recomputes the key of every queued node with `h` (after the key modifier was reset).
    pub fn rekey<G>(&mut self, graph: &G, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        let slots: Vec<usize> = self.queue.iter().map(|(s, _)| s).collect();
        for s in slots {
            let key = self.packed_key(graph, s, h);
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
        let mut items: Vec<(usize, PackedKey)> = self.queue.iter().collect();
        items.sort_by_key(|&(s, k)| (k, s));
        items.into_iter().map(|(s, k)| (s, k.key())).collect()
    }

    /// Bytes held by the state and the queue.
    pub fn memory_bytes(&self) -> usize {
        self.v.memory_bytes() + self.mode.memory_bytes() + self.queue.memory_bytes()
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
    fn packed_key<G>(&mut self, graph: &G, slot: usize, h: &mut impl FnMut(N) -> Cost) -> PackedKey
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.packed_key_at(slot, graph.node_at(slot), h)
    }

    /// The queue's key of `slot`, which is `node`.
    #[inline]
    fn packed_key_at(&mut self, slot: usize, node: N, h: &mut impl FnMut(N) -> Cost) -> PackedKey {
        let key = self.key_at(slot, node, h);
        PackedKey::new(key, self.v.g(slot) > self.v.rhs(slot))
    }

    /// Queues `slot` with `key`, or changes its key (and keeps `under` in step).
    #[inline]
    fn enqueue(&mut self, slot: usize, key: PackedKey) {
        let old = self.queue.push(slot, key);
        match old {
            None => self.stats.pushes += 1,
            Some(_) => self.stats.decreases += 1,
        }
        if key.under() {
            self.under.push(slot, key.primary_bits());
        } else if old.is_some_and(PackedKey::under) {
            self.under.remove(slot);
        }
    }

    /// Takes `slot` out of the queue if it is there.
    #[inline]
    fn dequeue(&mut self, slot: usize) {
        if self.queue.remove(slot).is_some_and(PackedKey::under) {
            self.under.remove(slot);
        }
    }

    /// The key of `slot`, which is `node`, with `h` the heuristic part (and `k_m`) of the node.
    /// A primary part that overflows (finite `min(g, rhs)` and `h`, infinite sum) is `+inf`,
    /// which would make the node a dead end: it is remembered (see [`RepairEngine::overflow`]).
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
        let key = if g > rhs { Key::new(rhs + self.mode.inflation() * h, rhs) } else { Key::new(g + h, g) };
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

    /// [`RepairEngine::update_vertex`] of `slot`, which is `node`.
    #[inline]
    fn update_vertex_at(&mut self, slot: usize, node: N, h: &mut impl FnMut(N) -> Cost) {
        let (g, rhs) = (self.v.g(slot), self.v.rhs(slot));
        if self.mode.is_closed(slot) && g > rhs && g < f64::INFINITY {
            // A node expanded in this iteration that can now improve waits for the next one
            // (that is what bounds an iteration's work, as in ARA*): its `g` is the cost of a
            // real path meanwhile. Any other inconsistent closed node is queued now: one whose
            // value rose (underconsistent), or that lost its value (`g` infinite). In exact
            // arithmetic neither happens to a closed node, but when rounding ties reorder two
            // keys it does, and deferring it would leave nodes resting on a stale value.
            // As in the paper's UpdateState, a node moved to INCONS leaves OPEN (it may have
            // been queued as underconsistent since its expansion).
            self.dequeue(slot);
            self.mode.hold_back(slot);
        } else if g != rhs {
            let key = self.packed_key_at(slot, node, h);
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
        self.each_edge(graph, slot, self.dir == SearchDirection::Forward, visit)
    }

    /// Calls `visit(self, slot, neighbour, cost)` for each edge `slot`'s `rhs` is computed over: its
    /// successors (backward) or predecessors (forward).
    #[inline]
    fn each_support<G>(&mut self, graph: &G, slot: usize, visit: impl FnMut(&mut Self, usize, N, Cost))
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        self.each_edge(graph, slot, self.dir == SearchDirection::Backward, visit)
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
    /// [`RepairEngine::overflow`]); an overflowing sum beside a finite one is simply not the least.
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

    /// [`RepairEngine::set_rhs`] of `slot`, which is `node`.
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
    /// The edge's old cost is not needed (the papers' test "was the old edge the best?" asks for
    /// it): when the edge now offers less than the dependent's `rhs`, that is the new `rhs`; when
    /// it offers the same, nothing changes; when it offers more, it may have been the best before
    /// and got dearer, and `rhs` is recomputed from all of the dependent's edges. This gives what
    /// the papers' version gives (the same values, the same queue), at the price of a
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
        let mut target_key = self.packed_key(graph, target, h);
        while let Some((top, k_top)) = self.queue.peek() {
            let values = (self.v.g(target), self.v.rhs(target));
            if values != target_values {
                target_values = values;
                target_key = self.packed_key(graph, target, h);
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
                let k_new = self.packed_key(graph, u, h);
                if k_old < k_new {
                    // The key was computed with an older `k_m` or start: requeue, expand later.
                    self.enqueue(u, k_new);
                    continue;
                }
            } else {
                debug_assert!(k_old == self.packed_key(graph, u, h), "a stale key while keys are current");
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
                    self.mode.close(u);
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

    /// Folds the current call's counters into the totals and returns them with `elapsed`.
    pub fn take_call_stats(&mut self, elapsed: std::time::Duration) -> SearchStats {
        let mut stats = std::mem::take(&mut self.stats);
        stats.elapsed = elapsed;
        self.totals += stats;
        stats
    }
}

/// AD*'s iterations.
impl<N: Copy + Eq + std::hash::Hash + Debug> RepairEngine<N, Anytime> {
    /// Sets the inflation of overconsistent keys; queued keys are stale until re-keyed.
    pub fn set_epsilon(&mut self, epsilon: f64) {
        if epsilon != self.mode.epsilon {
            self.mode.epsilon = epsilon;
            self.keys_current = false;
        }
    }

    /// Starts a new iteration (AD*): nothing is closed any more, the inconsistent nodes held
    /// back join the queue, and every queued key is recomputed (the inflation or the start may
    /// have changed).
    pub fn next_iteration<G>(&mut self, graph: &G, h: &mut impl FnMut(N) -> Cost)
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.mode.advance_iteration();
        let mut slots: Vec<usize> = self.queue.iter().map(|(s, _)| s).collect();
        slots.extend(self.mode.take_held_back());
        self.queue.clear();
        self.under.clear();
        for s in slots {
            if self.v.g(s) != self.v.rhs(s) {
                let key = self.packed_key(graph, s, h);
                self.enqueue(s, key);
            }
        }
        self.keys_current = true;
    }
}
