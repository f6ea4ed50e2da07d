//! Jump point search and JPS+ against Dijkstra on random grids under every corner-cutting rule:
//! the same reachability and least cost, and every returned path a chain of legal moves
//! (8-adjacent cells, all passable, corners as the rule allows) whose costs add up to the reported
//! cost; grids of unequal costs refused with a typed error.

use proptest::prelude::*;
use trailmark_core::grid::{Cell, Connectivity, CornerCutting, Grid};
use trailmark_graph::GridGraph;
use trailmark_search::{Jps, JpsPlus, SearchError, SearchResult, dijkstra, jps};

const RULES: [CornerCutting; 3] = [CornerCutting::Forbidden, CornerCutting::Allowed, CornerCutting::Squeeze];

/// Whether the move `a -> b` is one `rule` allows on `grid`, and its length.
fn legal_move(grid: &Grid, rule: CornerCutting, a: Cell, b: Cell) -> Option<f64> {
    let (dx, dy) = (b.x as i64 - a.x as i64, b.y as i64 - a.y as i64);
    let free = |x: i64, y: i64| {
        x >= 0
            && y >= 0
            && grid.contains(Cell::new(x as u32, y as u32))
            && grid.is_passable(Cell::new(x as u32, y as u32))
    };
    let (ax, ay) = (a.x as i64, a.y as i64);
    match (dx.abs(), dy.abs()) {
        (1, 0) | (0, 1) => free(ax + dx, ay + dy).then_some(1.0),
        (1, 1) => {
            let (c, d) = (free(ax + dx, ay), free(ax, ay + dy));
            let corners = match rule {
                CornerCutting::Forbidden => c && d,
                CornerCutting::Allowed => c || d,
                CornerCutting::Squeeze => true,
            };
            (free(ax + dx, ay + dy) && corners).then_some(2f64.sqrt())
        }
        _ => None,
    }
}

/// Grids up to 150 x 140 cells, so that scans cross the 64-cell words of the bit rows.
fn random_grid() -> impl Strategy<Value = (Grid, [u32; 4])> {
    (1u32..150, 1u32..140, 0.0..0.45f64, any::<u64>(), prop::array::uniform4(any::<u32>())).prop_map(
        |(w, h, density, seed, ends)| {
            let mut grid = Grid::new(w as usize, h as usize).unwrap();
            let mut state = seed | 1;
            for y in 0..h {
                for x in 0..w {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    let blocked = (state >> 11) as f64 / (1u64 << 53) as f64 <= density;
                    grid.set_blocked(Cell::new(x, y), blocked).unwrap();
                }
            }
            (grid, ends)
        },
    )
}

/// Checks `found` against `reference`: the same reachability, the same cost, and a path of legal
/// moves from `start` to `goal` whose costs sum to its cost.
fn agrees(
    grid: &Grid,
    rule: CornerCutting,
    cost: f64,
    (start, goal): (Cell, Cell),
    reference: &SearchResult<Cell>,
    found: &SearchResult<Cell>,
) -> Result<(), TestCaseError> {
    match (&reference.path, &found.path) {
        (None, None) => {}
        (Some(best), Some(path)) => {
            prop_assert!(
                (path.cost - best.cost).abs() <= 1e-9 * best.cost.max(1.0),
                "{} against {}",
                path.cost,
                best.cost
            );
            prop_assert_eq!(path.nodes.first(), Some(&start));
            prop_assert_eq!(path.nodes.last(), Some(&goal));
            let mut sum = 0.0;
            for pair in path.nodes.windows(2) {
                let length = legal_move(grid, rule, pair[0], pair[1]);
                prop_assert!(length.is_some(), "{} -> {} is not a legal move", pair[0], pair[1]);
                sum += length.unwrap() * cost;
            }
            prop_assert!(
                (sum - path.cost).abs() <= 1e-9 * sum.max(1.0),
                "moves sum to {sum}, cost {}",
                path.cost
            );
        }
        (a, b) => prop_assert!(false, "dijkstra {:?}, jump points {:?}", a.is_some(), b.is_some()),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 768, ..ProptestConfig::default() })]

    #[test]
    fn jps_and_jps_plus_find_what_dijkstra_finds_at_the_same_cost(
        (grid, ends) in random_grid(),
        cost in prop::sample::select(vec![1.0, 2.5, 0.25]),
        rule in prop::sample::select(RULES.to_vec()),
    ) {
        let mut grid = grid;
        for cell in grid.cells().collect::<Vec<_>>() {
            if grid.is_passable(cell) {
                grid.set_cost(cell, cost).unwrap();
            }
        }
        let (w, h) = (grid.width(), grid.height());
        let start = Cell::new(ends[0] % w, ends[1] % h);
        let goal = Cell::new(ends[2] % w, ends[3] % h);
        prop_assume!(grid.is_passable(start) && grid.is_passable(goal));
        let graph = GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
        let reference = dijkstra(&graph, start, goal).unwrap();
        let online = jps(&grid, rule, start, goal).unwrap();
        agrees(&grid, rule, cost, (start, goal), &reference, &online)?;
        let plus = JpsPlus::new(&grid, rule).unwrap().search(start, goal).unwrap();
        agrees(&grid, rule, cost, (start, goal), &reference, &plus)?;
    }
}

#[test]
fn one_planner_answers_many_queries_and_the_start_alone_when_it_is_the_goal() {
    let grid = Grid::from_rows(&["....@....", "....@....", ".........", "@@@@@@@.."]).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut online = Jps::new(&grid, CornerCutting::Forbidden).unwrap();
    let mut plus = JpsPlus::new(&grid, CornerCutting::Forbidden).unwrap();
    assert!(online.expanded().is_empty() && plus.expanded().is_empty());
    for (a, b) in [((0, 0), (8, 0)), ((8, 2), (0, 0)), ((3, 2), (3, 2)), ((0, 0), (8, 3))] {
        let (a, b) = (Cell::new(a.0, a.1), Cell::new(b.0, b.1));
        let best = dijkstra(&graph, a, b).unwrap();
        let found = [online.search(a, b).unwrap(), plus.search(a, b).unwrap()];
        // The cells each says it expanded are as many as its statistics count.
        assert_eq!(online.expanded().len() as u64, found[0].stats.expansions);
        assert_eq!(plus.expanded().len() as u64, found[1].stats.expansions);
        for found in found {
            assert_eq!(found.cost().is_some(), best.cost().is_some());
            if let (Some(x), Some(y)) = (found.cost(), best.cost()) {
                assert!((x - y).abs() < 1e-9, "{a} -> {b}: {x} against {y}");
            }
        }
    }
    for found in
        [online.search(Cell::new(2, 2), Cell::new(2, 2)), plus.search(Cell::new(2, 2), Cell::new(2, 2))]
    {
        let alone = found.unwrap().path.unwrap();
        assert_eq!((alone.nodes, alone.cost), (vec![Cell::new(2, 2)], 0.0));
    }
}

#[test]
fn unequal_costs_and_ends_off_the_grid_are_typed_errors() {
    let mut grid = Grid::from_rows(&["....", "....", "...."]).unwrap();
    grid.set_cost(Cell::new(2, 1), 3.0).unwrap();
    for rule in RULES {
        let errors = [Jps::new(&grid, rule).err(), JpsPlus::new(&grid, rule).err()];
        for error in errors {
            match error {
                Some(SearchError::NonUniformCost { cell, cost, expected }) => {
                    assert_eq!((cell, cost, expected), (Cell::new(2, 1), 3.0, 1.0));
                }
                other => panic!("{other:?}"),
            }
        }
    }
    let small = Grid::from_rows(&["..@", "..."]).unwrap();
    let mut online = Jps::new(&small, CornerCutting::Forbidden).unwrap();
    let mut plus = JpsPlus::new(&small, CornerCutting::Forbidden).unwrap();
    assert!(matches!(online.search(Cell::new(2, 0), Cell::new(0, 0)), Err(SearchError::StartNotInGraph(_))));
    assert!(matches!(online.search(Cell::new(0, 0), Cell::new(9, 0)), Err(SearchError::GoalNotInGraph(_))));
    assert!(matches!(plus.search(Cell::new(2, 0), Cell::new(0, 0)), Err(SearchError::StartNotInGraph(_))));
    assert!(matches!(plus.search(Cell::new(0, 0), Cell::new(9, 0)), Err(SearchError::GoalNotInGraph(_))));
    let (wide, huge) =
        (Grid::new(JpsPlus::MAX_SIDE as usize + 1, 1).unwrap(), Grid::new(4097, 4096).unwrap());
    assert!(matches!(
        JpsPlus::new(&wide, CornerCutting::Forbidden),
        Err(SearchError::TableTooLarge { width: 32767, height: 1 })
    ));
    assert!(matches!(
        JpsPlus::new(&huge, CornerCutting::Forbidden),
        Err(SearchError::TableTooLarge { width: 4097, height: 4096 })
    ));
    // The longest side allowed: a jump the length of the row.
    let row = Grid::new(JpsPlus::MAX_SIDE as usize, 2).unwrap();
    let far = Cell::new(JpsPlus::MAX_SIDE - 1, 1);
    let found = JpsPlus::new(&row, CornerCutting::Forbidden).unwrap().search(Cell::new(0, 0), far).unwrap();
    assert_eq!(found.path.map(|p| p.nodes.len()), Some(JpsPlus::MAX_SIDE as usize));
}
