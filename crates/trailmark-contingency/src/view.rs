//! A grid graph seen through a filter on the cells that may be entered.
//!
//! The planner searches the same grid in several views: a region alone (no choke point may be
//! entered), one choke point and the cells beside it (a crossing), and the world as the vehicle
//! knows it (blocked choke points may not be entered). A view keeps the grid's moves, corner
//! rule included, and drops every move into or out of a cell the filter refuses: a refused cell
//! has no edges at all.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::grid::Cell;
use trailmark_graph::GridGraph;

/// `graph` with only the cells `allowed` accepts.
pub(crate) struct View<'a, F> {
    graph: &'a GridGraph,
    allowed: F,
}

impl<'a, F: Fn(Cell) -> bool> View<'a, F> {
    pub(crate) fn new(graph: &'a GridGraph, allowed: F) -> Self {
        View { graph, allowed }
    }
}

impl<F: Fn(Cell) -> bool> Graph for View<'_, F> {
    type Node = Cell;

    #[inline]
    fn contains(&self, cell: Cell) -> bool {
        self.graph.contains(cell) && (self.allowed)(cell)
    }
}

impl<F: Fn(Cell) -> bool> Successors for View<'_, F> {
    #[inline]
    fn for_each_successor<V: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: V) {
        if !(self.allowed)(cell) {
            return;
        }
        self.graph.for_each_successor(cell, |n, c| {
            if (self.allowed)(n) {
                visit(n, c)
            }
        })
    }
}

impl<F: Fn(Cell) -> bool> Predecessors for View<'_, F> {
    /// Symmetric, like the grid graph.
    #[inline]
    fn for_each_predecessor<V: FnMut(Cell, Cost)>(&self, cell: Cell, visit: V) {
        self.for_each_successor(cell, visit)
    }
}

impl<F: Fn(Cell) -> bool> IndexedGraph for View<'_, F> {
    #[inline]
    fn node_bound(&self) -> usize {
        self.graph.node_bound()
    }

    #[inline]
    fn index_of(&self, cell: Cell) -> usize {
        self.graph.index_of(cell)
    }

    #[inline]
    fn node_at(&self, index: usize) -> Cell {
        self.graph.node_at(index)
    }

    /// Every cell inside the grid has an index: a refused cell may be allowed later.
    #[inline]
    fn checked_index(&self, cell: Cell) -> Option<usize> {
        self.graph.checked_index(cell)
    }
}
