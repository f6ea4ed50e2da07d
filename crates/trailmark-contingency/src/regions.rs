//! The regions of a grid: the connected sets of passable cells between the choke points.

use trailmark_core::grid::{Cell, Grid};
use trailmark_graph::GridGraph;

/// The region of a cell that belongs to none (impassable cells and choke points).
pub(crate) const NO_REGION: u32 = u32::MAX;

/// Labels the regions of a grid: the connected sets of passable cells outside the choke points
/// (`is_choke`). Returns the region of each cell, row-major (`u32::MAX` for impassable cells and
/// choke points), and the number of regions.
pub(crate) fn label_regions(
    grid: &Grid,
    graph: &GridGraph,
    is_choke: impl Fn(Cell) -> bool,
) -> (Vec<u32>, usize) {
    let width = grid.width() as usize;
    let index = |c: Cell| c.y as usize * width + c.x as usize;
    let mut region_of = vec![NO_REGION; grid.len()];
    let mut regions = 0u32;
    let mut stack = Vec::new();
    for cell in grid.cells() {
        if !grid.is_passable(cell) || is_choke(cell) || region_of[index(cell)] != NO_REGION {
            continue;
        }
        region_of[index(cell)] = regions;
        stack.push(cell);
        while let Some(c) = stack.pop() {
            for (n, _) in graph.neighbours(c) {
                if !is_choke(n) && region_of[index(n)] == NO_REGION {
                    region_of[index(n)] = regions;
                    stack.push(n);
                }
            }
        }
        regions += 1;
    }
    (region_of, regions as usize)
}
