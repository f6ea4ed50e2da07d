//! The hidden second paths of the modules `error`, `index`, `queue` and `stats` keep naming the
//! items at the crate root.

use trailmark_core::{Cell, Connectivity, Grid};
use trailmark_graph::GridGraph;

#[test]
fn the_old_module_paths_still_name_the_same_items() {
    let graph = GridGraph::new(&Grid::new(4, 3).unwrap(), Connectivity::Eight);
    let mut search = trailmark_search::Search::new();
    let found = search.bfs(&graph, Cell::new(0, 0), Cell::new(3, 2)).unwrap();
    let stats: trailmark_search::stats::SearchStats = found.stats;
    assert_eq!(found.path.map(|p| p.moves()), Some(3));
    assert!(stats.expansions > 0);

    let error: trailmark_search::error::SearchError<Cell> =
        search.bfs(&graph, Cell::new(9, 9), Cell::new(0, 0)).unwrap_err();
    assert_eq!(error, trailmark_search::SearchError::StartNotInGraph(Cell::new(9, 9)));
    let _hashed: trailmark_search::Search<trailmark_search::index::Hashed<Cell>> =
        trailmark_search::Search::with_index(trailmark_search::index::Hashed::default());
    let _dense = trailmark_search::Search::with_index(trailmark_search::index::Dense);

    let mut queue = trailmark_search::queue::IndexedHeap::new();
    queue.push(3, 1.0);
    assert_eq!(queue.pop(), Some((3, 1.0)));
}
