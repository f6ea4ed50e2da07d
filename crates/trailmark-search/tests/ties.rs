//! Near-ties from rounding: on an open grid every cell between two far endpoints has the same
//! `f` in exact arithmetic, and the searches must walk across that region (ties to the node
//! nearer the target) rather than fill it, however the sums were rounded.

use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::{DStarLite, LpaStar, astar};

/// Endpoints far apart on both axes: about 40,000 cells tie on `f` between them.
const START: Cell = Cell::new(108, 305);
const GOAL: Cell = Cell::new(508, 111);
/// Cells on a least-cost path: the larger of the two distances, plus one.
const PATH_CELLS: u64 = 401;

fn open_grid() -> GridGraph {
    GridGraph::new(&Grid::new(512, 512).expect("valid size"), Connectivity::Eight)
}

#[test]
fn astar_walks_across_an_open_grid() {
    let graph = open_grid();
    let found = astar(&graph, START, GOAL, graph.heuristic(GridHeuristic::Octile, GOAL)).unwrap();
    assert_eq!(found.path.as_ref().map(|p| p.nodes.len() as u64), Some(PATH_CELLS));
    assert!(found.stats.expansions <= PATH_CELLS, "{} expansions", found.stats.expansions);
}

#[test]
fn lifelong_planners_walk_across_an_open_grid() {
    let graph = open_grid();
    let h = graph.heuristic_between(GridHeuristic::Octile);
    let mut dstar = DStarLite::new(&graph, START, GOAL, h).unwrap();
    let stats = dstar.compute_shortest_path(&graph).unwrap();
    assert!(stats.expansions <= PATH_CELLS + 1, "D* Lite: {} expansions", stats.expansions);
    let mut lpa = LpaStar::new(&graph, START, GOAL, h).unwrap();
    let stats = lpa.compute_shortest_path(&graph).unwrap();
    assert!(stats.expansions <= PATH_CELLS + 1, "LPA*: {} expansions", stats.expansions);
    let optimal = astar(&graph, START, GOAL, graph.heuristic(GridHeuristic::Octile, GOAL)).unwrap().cost();
    for cost in [dstar.cost(), lpa.cost()] {
        assert!((cost.unwrap() - optimal.unwrap()).abs() <= 1e-9 * optimal.unwrap());
    }
}
