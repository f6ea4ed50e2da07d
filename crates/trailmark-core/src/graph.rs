//! Graph traits: what a search algorithm needs to know about a graph, and nothing more.
//!
//! A graph is described by small traits, in the manner of petgraph's `visit` module, so an
//! algorithm asks only for what it uses and works on any storage:
//!
//! - [`Graph`] names the node type and says which nodes belong to the graph;
//! - [`Successors`] enumerates the out-edges of a node (forward search);
//! - [`Predecessors`] enumerates the in-edges of a node (backward search, D* Lite);
//! - [`IndexedGraph`] numbers the nodes densely, `0..node_bound()`, so an algorithm can keep its
//!   state in `Vec`s instead of hash maps.
//!
//! Edges are reported through a callback rather than an iterator, so a graph whose edges are
//! computed on the fly (a grid, a lattice) enumerates them without allocating.
//!
//! ```
//! use trailmark_core::graph::{Graph, Successors};
//!
//! /// A ring of `n` nodes, each with an edge of cost 1 to the next.
//! struct Ring(u32);
//!
//! impl Graph for Ring {
//!     type Node = u32;
//!     fn contains(&self, node: u32) -> bool {
//!         node < self.0
//!     }
//! }
//!
//! impl Successors for Ring {
//!     fn for_each_successor<F: FnMut(u32, f64)>(&self, node: u32, mut visit: F) {
//!         visit((node + 1) % self.0, 1.0);
//!     }
//! }
//!
//! let mut next = Vec::new();
//! Ring(5).for_each_successor(4, |n, c| next.push((n, c)));
//! assert_eq!(next, [(0, 1.0)]);
//! ```

use std::fmt::Debug;
use std::hash::Hash;

use serde::{Deserialize, Serialize};

use crate::cost::Cost;

/// A graph: a type of node and a membership test.
pub trait Graph {
    /// A node: small, copyable, comparable and hashable (a cell, an index, a handle).
    type Node: Copy + Eq + Hash + Debug;

    /// Whether `node` is a node of this graph. Algorithms check their start and goal with it
    /// before searching, so an invalid query is an error rather than a wrong answer.
    fn contains(&self, node: Self::Node) -> bool;
}

/// A graph whose out-edges can be enumerated.
pub trait Successors: Graph {
    /// Calls `visit(successor, cost)` once for each edge leaving `node`.
    ///
    /// `node` must satisfy [`Graph::contains`]. Costs must be finite and non-negative; an edge
    /// that does not exist is simply not reported (algorithms also skip a cost of
    /// [`NO_EDGE`](crate::cost::NO_EDGE) and reject negative or NaN costs with an error).
    fn for_each_successor<F: FnMut(Self::Node, Cost)>(&self, node: Self::Node, visit: F);

    /// For an [`IndexedGraph`]: calls `visit(successor index, successor, cost)` once for each
    /// edge leaving the node with index `index`.
    ///
    /// The provided version converts between nodes and indices; a graph that can enumerate its
    /// edges by index directly (a grid, a compressed adjacency array) overrides it, and searches
    /// over dense indices then never convert at all.
    #[inline]
    fn for_each_successor_index<F: FnMut(usize, Self::Node, Cost)>(&self, index: usize, mut visit: F)
    where
        Self: IndexedGraph,
    {
        self.for_each_successor(self.node_at(index), |n, c| visit(self.index_of(n), n, c))
    }
}

/// A graph whose in-edges can be enumerated, for algorithms that search backwards.
pub trait Predecessors: Graph {
    /// Calls `visit(predecessor, cost)` once for each edge `predecessor -> node`, where `cost` is
    /// the cost of that edge (in its forward direction).
    fn for_each_predecessor<F: FnMut(Self::Node, Cost)>(&self, node: Self::Node, visit: F);

    /// For an [`IndexedGraph`]: calls `visit(predecessor index, predecessor, cost)` once for each
    /// edge entering the node with index `index`. Provided by conversion, like
    /// [`Successors::for_each_successor_index`].
    #[inline]
    fn for_each_predecessor_index<F: FnMut(usize, Self::Node, Cost)>(&self, index: usize, mut visit: F)
    where
        Self: IndexedGraph,
    {
        self.for_each_predecessor(self.node_at(index), |n, c| visit(self.index_of(n), n, c))
    }
}

/// A graph whose nodes are numbered densely, so algorithms can keep per-node state in `Vec`s.
///
/// Every node `n` with `contains(n)` has an index `index_of(n) < node_bound()`, and
/// `node_at(index_of(n)) == n`. Indices need not all be used (a grid may skip its border).
pub trait IndexedGraph: Graph {
    /// An upper bound (exclusive) on node indices.
    fn node_bound(&self) -> usize;

    /// The index of `node`, which must satisfy [`Graph::contains`].
    fn index_of(&self, node: Self::Node) -> usize;

    /// The node with index `index`, which must be the index of a node of the graph.
    fn node_at(&self, index: usize) -> Self::Node;

    /// The index of `node` if it names a node this graph has or can have after a change, `None`
    /// if it names nothing: a blocked cell of a grid has an index (it may open again), a cell
    /// outside the grid has none. Incremental planners check the nodes of a change
    /// notification with it.
    ///
    /// The provided version accepts the nodes the graph contains now; graphs whose nodes come
    /// and go (a grid whose cells are blocked and freed) override it.
    #[inline]
    fn checked_index(&self, node: Self::Node) -> Option<usize> {
        self.contains(node).then(|| self.index_of(node))
    }
}

impl<G: Graph + ?Sized> Graph for &G {
    type Node = G::Node;

    #[inline]
    fn contains(&self, node: Self::Node) -> bool {
        (**self).contains(node)
    }
}

impl<G: Successors + ?Sized> Successors for &G {
    #[inline]
    fn for_each_successor<F: FnMut(Self::Node, Cost)>(&self, node: Self::Node, visit: F) {
        (**self).for_each_successor(node, visit)
    }
}

impl<G: Predecessors + ?Sized> Predecessors for &G {
    #[inline]
    fn for_each_predecessor<F: FnMut(Self::Node, Cost)>(&self, node: Self::Node, visit: F) {
        (**self).for_each_predecessor(node, visit)
    }
}

impl<G: IndexedGraph + ?Sized> IndexedGraph for &G {
    #[inline]
    fn node_bound(&self) -> usize {
        (**self).node_bound()
    }

    #[inline]
    fn index_of(&self, node: Self::Node) -> usize {
        (**self).index_of(node)
    }

    #[inline]
    fn node_at(&self, index: usize) -> Self::Node {
        (**self).node_at(index)
    }

    #[inline]
    fn checked_index(&self, node: Self::Node) -> Option<usize> {
        (**self).checked_index(node)
    }
}

/// Straight lines between the nodes of a graph whose nodes are places: what an any-angle search
/// (Theta*) draws its segments with. A grid graph joins cell centres, a corner graph cell
/// corners; a closure `|a, b| -> Option<Cost>` is one too.
pub trait Lines<N> {
    /// The cost of the straight line from `from` to `to`, `None` when it is blocked.
    fn line_cost(&self, from: N, to: N) -> Option<Cost>;

    /// [`Lines::line_cost`] for a caller that will only use a line costing at most `budget`:
    /// a graph may stop pricing the line, and answer `None`, once it knows the line costs more.
    #[inline]
    fn line_cost_within(&self, from: N, to: N, _budget: Cost) -> Option<Cost> {
        self.line_cost(from, to)
    }

    /// A lower bound on [`Lines::line_cost`] of any clear line from `from` to `to` (0 unless a
    /// graph knows better, e.g. the length times the cheapest cost): an any-angle search
    /// that knows it can put off checking a line until it must.
    #[inline]
    fn line_lower_bound(&self, _from: N, _to: N) -> Cost {
        0.0
    }
}

impl<N, F: Fn(N, N) -> Option<Cost> + ?Sized> Lines<N> for F {
    #[inline]
    fn line_cost(&self, from: N, to: N) -> Option<Cost> {
        self(from, to)
    }
}

/// A change of one directed edge, told to an incremental planner after the graph changed: its
/// endpoints. The new cost is read from the graph; the old one is not needed.
///
/// Graphs that change (a grid whose cells are blocked, a roadmap whose obstacles move) report
/// their changes in this form, and the incremental planners of `trailmark-search` take it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct EdgeChange<N> {
    /// The tail of the edge.
    pub from: N,
    /// The head of the edge.
    pub to: N,
}

impl<N> EdgeChange<N> {
    /// The change of the edge `from -> to` (one that appeared, went, or changed cost).
    pub fn new(from: N, to: N) -> Self {
        EdgeChange { from, to }
    }
}
