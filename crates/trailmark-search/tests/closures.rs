//! The searches given as closures against the same searches on the grid graph, on random grids:
//! the same least costs (A*, Dijkstra), the fewest moves (BFS), a valid path (DFS), weighted A*
//! within its bound; several goals by a test; bad costs and weights as typed errors.

use proptest::prelude::*;
use trailmark_core::grid::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::{SearchError, bfs, closures, dijkstra};

fn random_grid() -> impl Strategy<Value = (Grid, [u32; 4])> {
    (1u32..30, 1u32..30, 0.0..0.4f64, any::<u64>(), prop::array::uniform4(any::<u32>())).prop_map(
        |(w, h, density, seed, ends)| {
            let mut grid = Grid::new(w as usize, h as usize).unwrap();
            let mut state = seed | 1;
            for cell in grid.cells().collect::<Vec<_>>() {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                let r = (state >> 11) as f64 / (1u64 << 53) as f64;
                if r <= density {
                    grid.set_blocked(cell, true).unwrap();
                } else {
                    grid.set_cost(cell, 1.0 + 4.0 * r).unwrap();
                }
            }
            (grid, ends)
        },
    )
}

/// Whether `nodes` is a chain of the graph's moves from `start` to `goal`, and its cost.
fn walk(graph: &GridGraph, nodes: &[Cell], start: Cell, goal: Cell) -> Option<f64> {
    (nodes.first() == Some(&start) && nodes.last() == Some(&goal))
        .then(|| nodes.windows(2).map(|w| graph.edge_cost(w[0], w[1])).sum::<Option<f64>>())
        .flatten()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn closures_find_what_the_graph_searches_find((grid, ends) in random_grid()) {
        let (w, h) = (grid.width(), grid.height());
        let start = Cell::new(ends[0] % w, ends[1] % h);
        let goal = Cell::new(ends[2] % w, ends[3] % h);
        prop_assume!(grid.is_passable(start) && grid.is_passable(goal));
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let next = |c: &Cell| graph.neighbours(*c);
        let at_goal = |c: &Cell| *c == goal;
        let h = graph.heuristic(GridHeuristic::Octile, goal);
        let best = dijkstra(&graph, start, goal).unwrap();
        let fewest = bfs(&graph, start, goal).unwrap();
        let found = [
            closures::astar(&start, next, |c| h(*c), at_goal).unwrap(),
            closures::dijkstra(&start, next, at_goal).unwrap(),
            closures::weighted_astar(&start, next, |c| h(*c), at_goal, 2.0).unwrap(),
            closures::bfs(&start, next, at_goal).unwrap(),
            closures::dfs(&start, next, at_goal).unwrap(),
        ];
        for (k, result) in found.iter().enumerate() {
            prop_assert_eq!(result.path.is_some(), best.path.is_some(), "search {}", k);
            let (Some(path), Some(least)) = (&result.path, best.cost()) else { continue };
            let cost = walk(&graph, &path.nodes, start, goal);
            prop_assert!(cost.is_some_and(|c| (c - path.cost).abs() <= 1e-9 * c.max(1.0)), "search {}: not a path of its cost", k);
            match k {
                0 | 1 => prop_assert!((path.cost - least).abs() <= 1e-9 * least.max(1.0), "{} against {}", path.cost, least),
                2 => prop_assert!(path.cost <= 2.0 * least + 1e-9),
                3 => prop_assert_eq!(path.nodes.len(), fewest.path.as_ref().unwrap().nodes.len()),
                _ => {}
            }
        }
    }
}

#[test]
fn the_nearest_of_several_goals_and_the_start_alone() {
    let graph = GridGraph::new(
        &Grid::from_rows(&["..........", "....@@@...", ".........."]).unwrap(),
        Connectivity::Eight,
    );
    let next = |c: &Cell| graph.neighbours(*c);
    let goals = [Cell::new(9, 0), Cell::new(0, 2)];
    let found = closures::dijkstra(&Cell::new(2, 0), next, |c| goals.contains(c)).unwrap();
    let path = found.path.unwrap();
    assert_eq!(path.nodes.last(), Some(&Cell::new(0, 2)));
    assert!((path.cost - 2.0 * 2f64.sqrt()).abs() < 1e-12);
    let alone = closures::astar(&Cell::new(5, 2), next, |_| 0.0, |_| true).unwrap().path.unwrap();
    assert_eq!((alone.nodes, alone.cost), (vec![Cell::new(5, 2)], 0.0));
    // No goal anywhere: every reachable node expanded, then no path.
    let none = closures::bfs(&Cell::new(0, 0), next, |_| false).unwrap();
    assert_eq!((none.path, none.stats.expansions), (None, 27));
}

#[test]
fn bad_costs_and_weights_are_typed_errors_naming_nodes() {
    let line = |n: &u32| if *n < 5 { vec![(n + 1, if *n == 3 { -1.0 } else { 1.0 })] } else { vec![] };
    match closures::dijkstra(&0u32, line, |n| *n == 5) {
        Err(SearchError::InvalidEdgeCost { from, to, cost }) => {
            assert_eq!((from, to, cost.to_string()), (3, 4, "-1".to_string()))
        }
        other => panic!("{other:?}"),
    }
    let nan = |n: &u32| vec![(n + 1, f64::NAN)];
    assert!(closures::astar(&0u32, nan, |_| 0.0, |n| *n == 2).is_err());
    let ok = |n: &u32| vec![(n + 1, 1.0)];
    assert!(matches!(
        closures::weighted_astar(&0u32, ok, |_| 0.0, |n| *n == 2, 0.5),
        Err(SearchError::InvalidWeight(_))
    ));
    assert!(matches!(
        closures::astar(&0u32, ok, |_| f64::NAN, |n| *n == 2),
        Err(SearchError::InvalidHeuristic { .. })
    ));
}
