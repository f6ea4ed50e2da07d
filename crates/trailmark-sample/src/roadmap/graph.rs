//! A [`Prm`]'s roadmap as a graph of the core traits: milestone ids as nodes, free motions as
//! edges costing their distance (a blocked motion a roadmap keeps is no edge), so every search
//! of `trailmark-search` runs on it.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};

use super::prm::Prm;
use crate::space::StateSpace;

impl<S: StateSpace, N, Q> Graph for Prm<S, N, Q> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.out.len()
    }
}

impl<S: StateSpace, N, Q> Successors for Prm<S, N, Q> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &(v, c) in &self.out[node as usize] {
            if c.is_finite() {
                visit(v, c);
            }
        }
    }
}

impl<S: StateSpace, N, Q> Predecessors for Prm<S, N, Q> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        let edges = if S::SYMMETRIC { &self.out } else { &self.into };
        for &(u, c) in &edges[node as usize] {
            if c.is_finite() {
                visit(u, c);
            }
        }
    }
}

impl<S: StateSpace, N, Q> IndexedGraph for Prm<S, N, Q> {
    fn node_bound(&self) -> usize {
        self.out.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}
