//! A polygon roadmap as a graph of the core traits and as a [`Roadmap`]: its [`Prm`](crate::Prm)'s
//! edges.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_graph::Roadmap;

use super::{PlanarSpace, PolygonPrm};

impl<S: PlanarSpace> Roadmap for PolygonPrm<S> {
    type Position = S::State;
    const DIRECTED: bool = !S::SYMMETRIC;

    fn node_count(&self) -> usize {
        self.roadmap.node_count()
    }

    fn position(&self, node: u32) -> S::State {
        *self.roadmap.state(node)
    }

    /// The space's distance: every edge costs its motion's distance, and a path of motions is
    /// no shorter than the shortest motion between its ends (in `R2` the straight line, in
    /// `Dubins` the shortest Dubins path).
    fn lower_bound(&self, a: S::State, b: S::State) -> Cost {
        self.space.distance(&a, &b)
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.roadmap.for_each_successor(node, visit)
    }

    fn for_each_in<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.roadmap.for_each_predecessor(node, visit)
    }
}

impl<S: PlanarSpace> Graph for PolygonPrm<S> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        self.roadmap.contains(node)
    }
}

impl<S: PlanarSpace> Successors for PolygonPrm<S> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.roadmap.for_each_successor(node, visit)
    }
}

impl<S: PlanarSpace> Predecessors for PolygonPrm<S> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.roadmap.for_each_predecessor(node, visit)
    }
}

impl<S: PlanarSpace> IndexedGraph for PolygonPrm<S> {
    fn node_bound(&self) -> usize {
        self.roadmap.node_bound()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}
