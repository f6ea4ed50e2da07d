//! Where queries on a grid start and end: the largest region reached from a few seeded cells,
//! and far-apart endpoints in it. The benchmark's suite and navigation cases and the `navigate`
//! command draw their queries the same way.

use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use trailmark::prelude::*;

/// The largest of the regions reached from five seeded passable cells, `None` without any
/// passable cell. Leaves `search` holding the last of those searches.
pub fn largest_region(
    grid: &Grid,
    graph: &GridGraph,
    search: &mut Search,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<Cell>> {
    let passable: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    if passable.is_empty() {
        return None;
    }
    let mut region: Vec<Cell> = Vec::new();
    for _ in 0..5 {
        let from = passable[rng.random_range(0..passable.len())];
        search.dijkstra_all(graph, from).ok()?;
        let reached: Vec<Cell> = search.reached(graph).collect();
        if reached.len() > region.len() {
            region = reached;
        }
    }
    Some(region)
}

/// A start and a goal in the largest region reached from a few seeded cells, the goal the
/// farthest of a few seeded candidates from the start.
pub fn endpoints(grid: &Grid, rng: &mut ChaCha8Rng) -> Option<(Cell, Cell)> {
    let graph = GridGraph::new(grid, Connectivity::Eight);
    let mut search = Search::new();
    let region = largest_region(grid, &graph, &mut search, rng)?;
    let start = region[rng.random_range(0..region.len())];
    search.dijkstra_all(&graph, start).ok()?;
    let goal = (0..16).map(|_| region[rng.random_range(0..region.len())]).max_by(|a, b| {
        let (ca, cb) = (search.cost_to(&graph, *a), search.cost_to(&graph, *b));
        ca.partial_cmp(&cb).unwrap_or(std::cmp::Ordering::Equal)
    })?;
    Some((start, goal))
}
