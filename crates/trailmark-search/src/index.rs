//! How a search numbers the nodes it meets: by the graph's own dense indices, or by hashing.
//!
//! Search state lives in `Vec`s indexed by a *slot* per node. [`Dense`] takes the slot from
//! [`IndexedGraph::index_of`] (no hashing, state sized once to `node_bound`); [`Hashed`] gives
//! nodes slots in the order the search meets them, for graphs that cannot number their nodes.

use std::collections::HashMap;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Successors};

/// A way to give the nodes of `G` dense slots during one search.
pub trait NodeIndex<G: Graph + ?Sized> {
    /// Starts a new search on `graph`; returns how many slots to prepare (a hint).
    fn begin(&mut self, graph: &G) -> usize;

    /// The slot of `node` (assigning one if the node is new to this search).
    fn slot(&mut self, graph: &G, node: G::Node) -> usize;

    /// The node in `slot`, which this search assigned.
    fn node(&self, graph: &G, slot: usize) -> G::Node;

    /// Calls `visit(slot, successor, cost)` for each edge leaving the node in `slot`.
    fn for_each_successor<F>(&mut self, graph: &G, slot: usize, visit: F)
    where
        G: Successors,
        F: FnMut(usize, G::Node, Cost);
}

/// Slots are the graph's own indices ([`IndexedGraph`]): no hashing at all.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dense;

impl<G: IndexedGraph + ?Sized> NodeIndex<G> for Dense {
    #[inline]
    fn begin(&mut self, graph: &G) -> usize {
        graph.node_bound()
    }

    #[inline]
    fn slot(&mut self, graph: &G, node: G::Node) -> usize {
        graph.index_of(node)
    }

    #[inline]
    fn node(&self, graph: &G, slot: usize) -> G::Node {
        graph.node_at(slot)
    }

    #[inline]
    fn for_each_successor<F>(&mut self, graph: &G, slot: usize, visit: F)
    where
        G: Successors,
        F: FnMut(usize, G::Node, Cost),
    {
        graph.for_each_successor_index(slot, visit)
    }
}

/// Slots are handed out in the order nodes are met, through a hash map: for graphs without
/// dense indices (implicit or unbounded graphs).
#[derive(Debug, Clone)]
pub struct Hashed<N> {
    slots: HashMap<N, u32>,
    nodes: Vec<N>,
}

impl<N> Default for Hashed<N> {
    fn default() -> Self {
        Hashed { slots: HashMap::new(), nodes: Vec::new() }
    }
}

impl<G: Graph + ?Sized> NodeIndex<G> for Hashed<G::Node>
where
    G::Node: Hash + Eq,
{
    fn begin(&mut self, _graph: &G) -> usize {
        self.slots.clear();
        self.nodes.clear();
        0
    }

    #[inline]
    fn slot(&mut self, _graph: &G, node: G::Node) -> usize {
        let next = self.nodes.len() as u32;
        let slot = *self.slots.entry(node).or_insert(next);
        if slot == next {
            self.nodes.push(node);
        }
        slot as usize
    }

    #[inline]
    fn node(&self, _graph: &G, slot: usize) -> G::Node {
        self.nodes[slot]
    }

    #[inline]
    fn for_each_successor<F>(&mut self, graph: &G, slot: usize, mut visit: F)
    where
        G: Successors,
        F: FnMut(usize, G::Node, Cost),
    {
        let node = self.nodes[slot];
        graph.for_each_successor(node, |next, cost| {
            let s = <Self as NodeIndex<G>>::slot(self, graph, next);
            visit(s, next, cost)
        })
    }
}
