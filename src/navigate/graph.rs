//! The robot's graph: its grid map, and in greedy mapping a virtual goal that every unvisited
//! cell leads to, so that a planner to "the nearest unvisited cell" is a planner to one node.

use trailmark_core::cost::{Cost, octile};
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::grid::Cell;
use trailmark_graph::GridGraph;

/// The node standing for "any unvisited cell" in greedy mapping.
pub const VIRTUAL_GOAL: Cell = Cell { x: u32::MAX, y: u32::MAX };

/// The cost of the edge from an unvisited cell to the virtual goal: positive (the incremental
/// planners need positive costs) and small enough not to change which cell is nearest.
pub const VIRTUAL_EDGE_COST: Cost = 1e-3;

/// The robot's graph: its grid map, plus in greedy mapping the virtual goal that every
/// unvisited passable cell leads to.
pub(super) struct NavGraph {
    pub(super) grid: GridGraph,
    /// Per padded grid index: visited by the robot.
    pub(super) visited: Vec<bool>,
    /// Greedy mapping: the virtual goal exists.
    pub(super) explore: bool,
}

impl NavGraph {
    fn unvisited(&self, index: usize) -> bool {
        self.explore && !self.visited[index]
    }
}

impl Graph for NavGraph {
    type Node = Cell;
    fn contains(&self, cell: Cell) -> bool {
        if cell == VIRTUAL_GOAL { self.explore } else { self.grid.contains(cell) }
    }
}

impl Successors for NavGraph {
    fn for_each_successor<F: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: F) {
        if cell == VIRTUAL_GOAL {
            return;
        }
        if !self.explore {
            return self.grid.for_each_successor(cell, visit);
        }
        self.grid.for_each_successor(cell, &mut visit);
        if self.grid.contains(cell) && self.unvisited(self.grid.index_of(cell)) {
            visit(VIRTUAL_GOAL, VIRTUAL_EDGE_COST);
        }
    }

    #[inline]
    fn for_each_successor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, mut visit: F) {
        let bound = self.grid.node_bound();
        if index == bound {
            return;
        }
        if !self.explore {
            // Handing `visit` over by value keeps the grid's loop and the search's callback in
            // one inlined body, as on a bare grid.
            return self.grid.for_each_successor_index(index, visit);
        }
        self.grid.for_each_successor_index(index, &mut visit);
        if self.unvisited(index) && self.grid.contains(self.grid.node_at(index)) {
            visit(bound, VIRTUAL_GOAL, VIRTUAL_EDGE_COST);
        }
    }
}

impl Predecessors for NavGraph {
    fn for_each_predecessor<F: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: F) {
        self.for_each_predecessor_index(self.index_of(cell), |_, c, cost| visit(c, cost));
    }

    #[inline]
    fn for_each_predecessor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, mut visit: F) {
        if index < self.grid.node_bound() {
            // Grid moves are symmetric; nothing leads out of the virtual goal.
            return self.grid.for_each_predecessor_index(index, visit);
        }
        if !self.explore {
            return;
        }
        for y in 0..self.grid.height() {
            for x in 0..self.grid.width() {
                let cell = Cell::new(x, y);
                let i = self.grid.index_of(cell);
                if !self.visited[i] && self.grid.contains(cell) {
                    visit(i, cell, VIRTUAL_EDGE_COST);
                }
            }
        }
    }
}

impl IndexedGraph for NavGraph {
    fn node_bound(&self) -> usize {
        self.grid.node_bound() + 1
    }
    fn index_of(&self, cell: Cell) -> usize {
        if cell == VIRTUAL_GOAL { self.grid.node_bound() } else { self.grid.index_of(cell) }
    }
    fn node_at(&self, index: usize) -> Cell {
        if index == self.grid.node_bound() { VIRTUAL_GOAL } else { self.grid.node_at(index) }
    }
    fn checked_index(&self, cell: Cell) -> Option<usize> {
        if cell == VIRTUAL_GOAL { Some(self.grid.node_bound()) } else { self.grid.checked_index(cell) }
    }
}

/// The octile distance between cells, 0 to or from the virtual goal: consistent on a grid whose
/// cells cost at least 1 (the simulation scales it by the smallest cell cost otherwise).
pub(super) fn estimate(scale: Cost) -> impl Fn(Cell, Cell) -> Cost + Copy {
    move |a: Cell, b: Cell| {
        if a == VIRTUAL_GOAL || b == VIRTUAL_GOAL {
            0.0
        } else {
            scale * octile(a.x.abs_diff(b.x), a.y.abs_diff(b.y))
        }
    }
}
