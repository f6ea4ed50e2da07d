//! A polygon roadmap as a graph of the core traits and as a [`Roadmap`].

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_space::nearest::NearestNeighbors;

use super::{PlanarSpace, PolygonPrm};
use crate::roadmap::Roadmap;

impl<S: PlanarSpace> Roadmap for PolygonPrm<S> {
    type Position = S::State;
    const DIRECTED: bool = !S::SYMMETRIC;

    fn node_count(&self) -> usize {
        self.nearest.len()
    }

    fn position(&self, node: u32) -> S::State {
        *self.nearest.state(node)
    }

    /// The space's distance: every edge costs its motion's distance, and a path of motions is
    /// no shorter than the shortest motion between its ends (in `R2` the straight line, in
    /// `Dubins` the shortest Dubins path).
    fn lower_bound(&self, a: S::State, b: S::State) -> Cost {
        self.space.distance(&a, &b)
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &id in &self.out[node as usize] {
            let (v, c) = self.other_end(id, node);
            if c.is_finite() {
                visit(v, c);
            }
        }
    }

    fn for_each_in<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        if S::SYMMETRIC {
            return self.for_each_out(node, visit);
        }
        for &id in &self.into[node as usize] {
            let (u, c) = self.other_end(id, node);
            if c.is_finite() {
                visit(u, c);
            }
        }
    }
}

impl<S: PlanarSpace> Graph for PolygonPrm<S> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.nearest.len()
    }
}

impl<S: PlanarSpace> Successors for PolygonPrm<S> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_out(node, visit)
    }
}

impl<S: PlanarSpace> Predecessors for PolygonPrm<S> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_in(node, visit)
    }
}

impl<S: PlanarSpace> IndexedGraph for PolygonPrm<S> {
    fn node_bound(&self) -> usize {
        self.nearest.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}
