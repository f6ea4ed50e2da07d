//! The memory of a search, measured by a counting allocator: the search state for a
//! 1024 x 1024 map stays under 32 bytes per cell, even when the search covers the whole map.

use trailmark::prelude::*;

#[path = "support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::peak_during;

#[test]
fn search_state_under_32_bytes_per_cell_on_1024_squared() {
    // One test function, so no other test allocates while this one measures.
    let cells = 1024 * 1024;
    let open = Grid::new(1024, 1024).unwrap();
    let rooms = trailmark::core::generate::rooms(1024, 1024, 15, 3).unwrap();
    for (name, grid) in [("open", open), ("rooms", rooms)] {
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let (start, goal) = (Cell::new(0, 0), Cell::new(1022, 1022));
        let mut search = Search::new();
        // Dijkstra over the whole map: every cell reached, the largest open list.
        let (result, peak) = peak_during(|| search.dijkstra_all(&graph, start).unwrap());
        let per_cell = peak as f64 / cells as f64;
        println!(
            "{name}: dijkstra over {} expansions: {peak} bytes peak, {per_cell:.2} bytes per cell",
            result.stats.expansions
        );
        assert!(per_cell < 32.0, "{name}: {per_cell} bytes per cell");
        // `memory_bytes` reports the buffers held; the peak also saw an old and a new open list
        // buffer side by side while it grew.
        let held = search.memory_bytes();
        assert!(held <= peak && peak - held < cells, "{name}: memory_bytes {held}, peak {peak}");
        // A* reuses the workspace: no new allocation beyond the open list's growth.
        let h = graph.heuristic(GridHeuristic::Octile, goal);
        let (_, more) = peak_during(|| search.astar(&graph, start, goal, h).unwrap());
        assert!(more as f64 / (cells as f64) < 1.0, "{name}: A* allocated {more} more bytes");
    }
}
