//! Theta* on random grids with costs: every segment of its paths is checked by dense sampling
//! (every point of the segment lies in a passable cell), its cost is the sum of its lines'
//! costs, it finds a path exactly when Dijkstra does, and its paths are never cheaper than the
//! straight line allows nor costlier than the grid path, with the Euclidean heuristic or the
//! octile one. Shortcut grid paths likewise.

use proptest::prelude::*;
use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::{CornerCutting, GridGraph};
use trailmark_search::{SearchError, astar, dijkstra, theta_star};

fn world() -> impl Strategy<Value = (Grid, Cell, Cell)> {
    (2u32..24, 2u32..24).prop_flat_map(|(w, h)| {
        let cells = (w * h) as usize;
        (
            proptest::collection::vec(
                prop_oneof![6 => Just(1.0), 2 => 1.0..4.0f64, 2 => Just(f64::INFINITY)],
                cells,
            ),
            0..w,
            0..h,
            0..w,
            0..h,
        )
            .prop_map(move |(mut costs, sx, sy, gx, gy)| {
                costs[(sy * w + sx) as usize] = 1.0;
                costs[(gy * w + gx) as usize] = 1.0;
                let grid = Grid::from_costs(w as usize, h as usize, costs).unwrap();
                (grid, Cell::new(sx, sy), Cell::new(gx, gy))
            })
    })
}

/// Whether every point of the segment between the centres of `a` and `b`, sampled every
/// 1/1000 of a cell, lies in a passable cell (points on a cell boundary are skipped: they belong
/// to two cells).
fn clear_by_sampling(grid: &Grid, a: Cell, b: Cell) -> bool {
    let (ax, ay) = (f64::from(a.x) + 0.5, f64::from(a.y) + 0.5);
    let (bx, by) = (f64::from(b.x) + 0.5, f64::from(b.y) + 0.5);
    let n = (((bx - ax).hypot(by - ay)) * 1000.0).ceil().max(1.0) as usize;
    (0..=n).all(|k| {
        let t = k as f64 / n as f64;
        let (x, y) = (ax + t * (bx - ax), ay + t * (by - ay));
        if x.fract() == 0.0 || y.fract() == 0.0 {
            return true;
        }
        grid.is_passable(Cell::new(x.floor() as u32, y.floor() as u32))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn paths_are_clear_and_priced_by_their_lines((grid, start, goal) in world(), octile in any::<bool>()) {
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        // The octile heuristic overestimates lines but is consistent along the graph's edges:
        // enough for a path never dearer than the grid's.
        let kind = if octile { GridHeuristic::Octile } else { GridHeuristic::Euclidean };
        let h = graph.heuristic(kind, goal);
        let found = theta_star(&graph, start, goal, h, &graph).unwrap();
        let reference = dijkstra(&graph, start, goal).unwrap();
        prop_assert_eq!(found.path.is_some(), reference.path.is_some());
        let Some(path) = found.path else { return Ok(()) };
        prop_assert_eq!(path.nodes.first(), Some(&start));
        prop_assert_eq!(path.nodes.last(), Some(&goal));
        let mut sum = 0.0;
        let mut length = 0.0;
        for pair in path.nodes.windows(2) {
            prop_assert!(clear_by_sampling(&grid, pair[0], pair[1]), "segment {:?} crosses a wall", pair);
            sum += graph.line_cost(pair[0], pair[1]).unwrap();
            length += f64::from(pair[0].x.abs_diff(pair[1].x)).hypot(f64::from(pair[0].y.abs_diff(pair[1].y)));
        }
        prop_assert!((sum - path.cost).abs() <= 1e-9 * sum.max(1.0), "cost {} but lines sum to {}", path.cost, sum);
        let straight = f64::from(start.x.abs_diff(goal.x)).hypot(f64::from(start.y.abs_diff(goal.y)));
        prop_assert!(length >= straight - 1e-9);
        prop_assert!(path.cost >= straight * graph.min_cost() - 1e-9);
        let grid_cost = reference.cost().unwrap();
        prop_assert!(path.cost <= grid_cost * (1.0 + 1e-9), "Theta* {} above the grid path {}", path.cost, grid_cost);
    }

    #[test]
    fn shortcut_grid_paths_stay_clear_and_never_cost_more((grid, start, goal) in world()) {
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let found = astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal)).unwrap();
        let Some(path) = found.path else { return Ok(()) };
        let short = graph.shortcut(&path.nodes);
        prop_assert_eq!(short.first(), path.nodes.first());
        prop_assert_eq!(short.last(), path.nodes.last());
        let mut cost = 0.0;
        for pair in short.windows(2) {
            prop_assert!(clear_by_sampling(&grid, pair[0], pair[1]), "segment {:?} crosses a wall", pair);
            cost += graph.line_cost(pair[0], pair[1]).unwrap();
        }
        prop_assert!(cost <= path.cost * (1.0 + 1e-9), "shortcut {} above the path {}", cost, path.cost);
    }
}

#[test]
fn corners_follow_the_graph_rule() {
    // Two blocked cells touching at a corner: the diagonal line between the free ones passes
    // exactly through it.
    let grid = Grid::from_rows(&[".@", "@."]).unwrap();
    for (rule, clear) in
        [(CornerCutting::Forbidden, false), (CornerCutting::Allowed, false), (CornerCutting::Squeeze, true)]
    {
        let graph = GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
        assert_eq!(graph.line_of_sight(Cell::new(0, 0), Cell::new(1, 1)), clear, "{rule:?}");
    }
    let one = Grid::from_rows(&["..", "@."]).unwrap();
    let graph = GridGraph::new(&one, Connectivity::Eight).with_corner_cutting(CornerCutting::Allowed);
    assert!(graph.line_of_sight(Cell::new(0, 0), Cell::new(1, 1)));
    let graph = GridGraph::new(&one, Connectivity::Eight);
    assert!(!graph.line_of_sight(Cell::new(0, 0), Cell::new(1, 1)));
}

#[test]
fn around_a_wall_the_path_bends_at_its_corner() {
    let grid =
        Grid::from_rows(&["..........", "....@.....", "....@.....", "....@.....", ".........."]).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (start, goal) = (Cell::new(0, 2), Cell::new(9, 2));
    let h = graph.heuristic(GridHeuristic::Euclidean, goal);
    let found = theta_star(&graph, start, goal, h, &graph).unwrap();
    let path = found.path.unwrap();
    let grid_path = astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal)).unwrap();
    assert!(path.nodes.len() <= 4, "{:?}", path.nodes);
    assert!(path.cost < grid_path.cost().unwrap());
}

#[test]
fn a_bad_line_cost_is_an_error() {
    let graph = GridGraph::new(&Grid::new(4, 1).unwrap(), Connectivity::Eight);
    let goal = Cell::new(3, 0);
    let found = theta_star(&graph, Cell::new(0, 0), goal, |_| 0.0, &|_, _| Some(f64::NAN));
    assert!(matches!(found, Err(SearchError::InvalidLineCost { .. })));
}
