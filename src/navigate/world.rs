//! The simulated world: the true map with its follower, the robot's map, what it sensed.

use trailmark_core::graph::IndexedGraph;
use trailmark_core::grid::{Cell, Connectivity, Grid};
use trailmark_graph::GridGraph;

use crate::navigate::graph::NavGraph;

/// The true world (with the follower), the robot's map, and the cells visited.
pub(super) struct SimulatedWorld {
    truth: Grid,
    /// The true map without the follower.
    fixed: Grid,
    pub(super) known: NavGraph,
    follower: Option<Cell>,
    /// Per cell of the grid (row-major): sensed at least once.
    pub(super) sensed: Vec<bool>,
    /// Cells found to differ from the map.
    pub(super) discoveries: usize,
}

impl SimulatedWorld {
    pub(super) fn new(truth: &Grid, prior: &Grid, start: Cell, explore: bool) -> Self {
        let grid = GridGraph::new(prior, Connectivity::Eight);
        let mut visited = vec![false; grid.node_bound()];
        visited[grid.index_of(start)] = true;
        let known = NavGraph { grid, visited, explore };
        SimulatedWorld {
            truth: truth.clone(),
            fixed: truth.clone(),
            known,
            follower: None,
            sensed: vec![false; truth.len()],
            discoveries: 0,
        }
    }

    /// Senses the window around `robot`: updates the map where it differs from the truth and
    /// returns the cells whose cost changed.
    pub(super) fn sense(&mut self, robot: Cell, radius: u32) -> Vec<Cell> {
        let (w, h) = (self.truth.width(), self.truth.height());
        let mut changed = Vec::new();
        for y in robot.y.saturating_sub(radius)..=robot.y.saturating_add(radius).min(h - 1) {
            for x in robot.x.saturating_sub(radius)..=robot.x.saturating_add(radius).min(w - 1) {
                let cell = Cell::new(x, y);
                self.sensed[y as usize * w as usize + x as usize] = true;
                let truth = self.truth.cost(cell).expect("inside the map");
                if self.known.grid.cost(cell) != Some(truth) {
                    self.known.grid.set_cost(cell, truth).expect("a cost of a valid grid");
                    self.discoveries += 1;
                    changed.push(cell);
                }
            }
        }
        changed
    }

    /// Marks `cell` visited; in greedy mapping its edge to the virtual goal goes, so it changed.
    pub(super) fn visit(&mut self, cell: Cell, explore: bool) -> Vec<Cell> {
        let i = self.known.grid.index_of(cell);
        let first = !self.known.visited[i];
        self.known.visited[i] = true;
        if explore && first { vec![cell] } else { Vec::new() }
    }

    /// Moves the follower to `to` (or nowhere), freeing the cell it left.
    pub(super) fn move_follower(&mut self, to: Option<Cell>) {
        let to = to.filter(|&c| self.fixed.is_passable(c));
        if to == self.follower {
            return;
        }
        if let Some(old) = self.follower {
            let cost = self.fixed.cost(old).expect("inside the map");
            self.truth.set_cost(old, cost).expect("a cost of a valid grid");
        }
        if let Some(new) = to {
            self.truth.set_blocked(new, true).expect("inside the map");
        }
        self.follower = to;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_follower_blocks_and_frees_cells() {
        let truth = Grid::new(5, 1).unwrap();
        let mut world = SimulatedWorld::new(&truth, &truth, Cell::new(0, 0), false);
        world.move_follower(Some(Cell::new(1, 0)));
        assert!(!world.truth.is_passable(Cell::new(1, 0)));
        world.move_follower(Some(Cell::new(2, 0)));
        assert!(world.truth.is_passable(Cell::new(1, 0)) && !world.truth.is_passable(Cell::new(2, 0)));
        world.move_follower(None);
        assert!(world.truth.is_passable(Cell::new(2, 0)));
    }
}
