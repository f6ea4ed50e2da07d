//! Property tests of the grid searches on random worlds, against an oracle written here from the
//! documented grid rules (not from the code under test): Bellman-Ford on an explicit edge list.

use proptest::prelude::*;
use trailmark::core::cost::SQRT_2;
use trailmark::prelude::*;
use trailmark::search::Hashed;

/// A random world: a grid with costs, a graph configuration, a start and a goal.
#[derive(Debug, Clone)]
struct World {
    grid: Grid,
    connectivity: Connectivity,
    corners: CornerCutting,
    start: Cell,
    goal: Cell,
}

fn world() -> impl Strategy<Value = World> {
    (1u32..12, 1u32..12, 0.0f64..0.45, any::<bool>(), 0usize..3, any::<bool>(), any::<u64>()).prop_flat_map(
        |(w, h, density, eight, corner, costly, seed)| {
            let cells = (w * h) as usize;
            (
                prop::collection::vec(0.0f64..1.0, cells),
                prop::collection::vec(0.25f64..4.0, cells),
                (0..w, 0..h, 0..w, 0..h),
            )
                .prop_map(move |(draw, costs, (sx, sy, gx, gy))| {
                    let start = Cell::new(sx, sy);
                    let goal = Cell::new(gx, gy);
                    let si = (sy * w + sx) as usize;
                    let gi = (gy * w + gx) as usize;
                    let costs: Vec<f64> = (0..cells)
                        .map(|i| {
                            if draw[i] < density && i != si && i != gi {
                                f64::INFINITY
                            } else if costly {
                                costs[i]
                            } else {
                                1.0
                            }
                        })
                        .collect();
                    let _ = seed;
                    World {
                        grid: Grid::from_costs(w as usize, h as usize, costs).unwrap(),
                        connectivity: if eight { Connectivity::Eight } else { Connectivity::Four },
                        corners: [CornerCutting::Forbidden, CornerCutting::Allowed, CornerCutting::Squeeze]
                            [corner],
                        start,
                        goal,
                    }
                })
        },
    )
}

/// The edges of the world by the documented rules: a move to a passable neighbour costs its
/// length times the mean of the two cell costs; a diagonal needs both corners passable
/// (Forbidden), one (Allowed) or none (Squeeze).
fn oracle_edges(world: &World) -> Vec<(Cell, Cell, f64)> {
    let g = &world.grid;
    let free = |x: i64, y: i64| x >= 0 && y >= 0 && g.is_passable(Cell::new(x as u32, y as u32));
    let mut edges = Vec::new();
    for a in g.cells().filter(|&c| g.is_passable(c)) {
        for dx in -1i64..=1 {
            for dy in -1i64..=1 {
                let diagonal = dx != 0 && dy != 0;
                if (dx == 0 && dy == 0) || (diagonal && world.connectivity == Connectivity::Four) {
                    continue;
                }
                let (x, y) = (a.x as i64 + dx, a.y as i64 + dy);
                if !free(x, y) {
                    continue;
                }
                if diagonal {
                    let corners = [free(a.x as i64 + dx, a.y as i64), free(a.x as i64, a.y as i64 + dy)];
                    let ok = match world.corners {
                        CornerCutting::Forbidden => corners[0] && corners[1],
                        CornerCutting::Allowed => corners[0] || corners[1],
                        CornerCutting::Squeeze => true,
                    };
                    if !ok {
                        continue;
                    }
                }
                let b = Cell::new(x as u32, y as u32);
                let length = if diagonal { SQRT_2 } else { 1.0 };
                edges.push((a, b, length * (g.cost(a).unwrap() + g.cost(b).unwrap()) / 2.0));
            }
        }
    }
    edges
}

/// Least cost from `start` to every cell by Bellman-Ford over `edges` (`unit`: every edge 1).
fn oracle_distance(world: &World, edges: &[(Cell, Cell, f64)], unit: bool) -> Option<f64> {
    let w = world.grid.width() as usize;
    let at = |c: Cell| c.y as usize * w + c.x as usize;
    let mut dist = vec![f64::INFINITY; world.grid.len()];
    dist[at(world.start)] = 0.0;
    loop {
        let mut changed = false;
        for &(a, b, c) in edges {
            let d = dist[at(a)] + if unit { 1.0 } else { c };
            if d < dist[at(b)] - 1e-12 {
                dist[at(b)] = d;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let d = dist[at(world.goal)];
    d.is_finite().then_some(d)
}

fn graph_of(world: &World) -> GridGraph {
    GridGraph::new(&world.grid, world.connectivity).with_corner_cutting(world.corners)
}

/// A returned path must start and end right, follow oracle edges, and cost what it says.
fn check_path(world: &World, edges: &[(Cell, Cell, f64)], path: &Path<Cell>) -> Result<(), TestCaseError> {
    prop_assert_eq!(path.start(), Some(world.start));
    prop_assert_eq!(path.goal(), Some(world.goal));
    let mut sum = 0.0;
    for pair in path.nodes.windows(2) {
        let edge = edges.iter().find(|e| e.0 == pair[0] && e.1 == pair[1]);
        prop_assert!(edge.is_some(), "{:?} -> {:?} is not a move", pair[0], pair[1]);
        sum += edge.unwrap().2;
    }
    prop_assert!((sum - path.cost).abs() <= 1e-9 * sum.max(1.0), "reported {} summed {}", path.cost, sum);
    Ok(())
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Dijkstra, A* (every admissible heuristic) and weighted A* against the oracle.
    #[test]
    fn optimal_and_bounded_searches(world in world()) {
        let edges = oracle_edges(&world);
        let optimal = oracle_distance(&world, &edges, false);
        let graph = graph_of(&world);
        let (s, t) = (world.start, world.goal);
        let mut results = vec![("dijkstra", dijkstra(&graph, s, t).unwrap(), 1.0)];
        for kind in [GridHeuristic::Zero, GridHeuristic::Octile, GridHeuristic::Euclidean, GridHeuristic::Manhattan] {
            if kind.is_admissible(world.connectivity) {
                results.push(("astar", astar(&graph, s, t, graph.heuristic(kind, t)).unwrap(), 1.0));
            }
        }
        let natural = graph.heuristic(GridHeuristic::for_connectivity(world.connectivity), t);
        for w in [1.0, 1.5, 3.0] {
            results.push(("weighted_astar", weighted_astar(&graph, s, t, natural, w).unwrap(), w));
        }
        // The hashing workspace gives the same answers.
        results.push(("astar (hashed)", Search::<Hashed<Cell>>::hashed().astar(&graph, s, t, natural).unwrap(), 1.0));
        for (name, found, bound) in results {
            match (&found.path, optimal) {
                (None, None) => {}
                (Some(path), Some(opt)) => {
                    check_path(&world, &edges, path)?;
                    if bound == 1.0 {
                        prop_assert!(close(path.cost, opt), "{}: {} vs optimal {}", name, path.cost, opt);
                    } else {
                        prop_assert!(path.cost <= bound * opt + 1e-9, "{}: {} > {} x {}", name, path.cost, bound, opt);
                    }
                }
                (got, want) => prop_assert!(false, "{}: found {:?}, oracle {:?}", name, got.as_ref().map(|p| p.cost), want),
            }
        }
    }

    /// BFS finds a path with the fewest moves; DFS finds a valid path whenever one exists.
    #[test]
    fn bfs_fewest_moves_and_dfs_valid(world in world()) {
        let edges = oracle_edges(&world);
        let moves = oracle_distance(&world, &edges, true);
        let graph = graph_of(&world);
        let bfs = bfs(&graph, world.start, world.goal).unwrap();
        let dfs = dfs(&graph, world.start, world.goal).unwrap();
        prop_assert_eq!(bfs.path.as_ref().map(|p| p.moves() as f64), moves);
        prop_assert_eq!(dfs.path.is_some(), moves.is_some());
        for path in bfs.path.iter().chain(dfs.path.iter()) {
            check_path(&world, &edges, path)?;
        }
    }

    /// Dijkstra to every node agrees with single-goal searches.
    #[test]
    fn dijkstra_all_matches_single_queries(world in world()) {
        let graph = graph_of(&world);
        let mut all = Search::new();
        all.dijkstra_all(&graph, world.start).unwrap();
        let mut one = Search::new();
        for cell in world.grid.cells().filter(|&c| world.grid.is_passable(c)) {
            let single = one.dijkstra(&graph, world.start, cell).unwrap().cost();
            let tree = all.cost_to(&graph, cell);
            prop_assert_eq!(single.is_some(), tree.is_some());
            if let (Some(a), Some(b)) = (single, tree) {
                prop_assert!(close(a, b), "{:?}: {} vs {}", cell, a, b);
                let path = all.path_to_node(&graph, cell).unwrap();
                prop_assert_eq!(path.goal(), Some(cell));
            }
        }
    }
}

#[test]
fn blocked_or_outside_endpoints_are_errors() {
    let grid = Grid::from_rows(&["..@", "..."]).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (ok, blocked, outside) = (Cell::new(0, 0), Cell::new(2, 0), Cell::new(5, 5));
    assert_eq!(dijkstra(&graph, blocked, ok).unwrap_err(), SearchError::StartNotInGraph(blocked));
    assert_eq!(bfs(&graph, ok, outside).unwrap_err(), SearchError::GoalNotInGraph(outside));
    let h = graph.heuristic(GridHeuristic::Octile, ok);
    assert_eq!(weighted_astar(&graph, ok, ok, h, 0.5).unwrap_err(), SearchError::InvalidWeight(0.5));
    assert!(matches!(weighted_astar(&graph, ok, ok, h, f64::NAN), Err(SearchError::InvalidWeight(_))));
    let err = astar(&graph, ok, Cell::new(2, 1), |_| f64::NAN).unwrap_err();
    assert!(matches!(err, SearchError::InvalidHeuristic { .. }), "{err}");
}

#[test]
fn unreachable_goal_is_no_path_for_every_algorithm() {
    let grid = Grid::from_rows(&["..@..", "..@..", "..@.."]).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (s, t) = (Cell::new(0, 0), Cell::new(4, 2));
    let h = graph.heuristic(GridHeuristic::Octile, t);
    for found in [
        bfs(&graph, s, t).unwrap(),
        dfs(&graph, s, t).unwrap(),
        dijkstra(&graph, s, t).unwrap(),
        astar(&graph, s, t, h).unwrap(),
        weighted_astar(&graph, s, t, h, 2.0).unwrap(),
    ] {
        assert_eq!(found.path, None);
        assert_eq!(found.stats.expansions, 6, "every reachable cell is expanded once");
    }
}

#[test]
fn start_is_goal() {
    let graph = GridGraph::new(&Grid::new(3, 3).unwrap(), Connectivity::Four);
    let c = Cell::new(1, 1);
    let found = astar(&graph, c, c, graph.heuristic(GridHeuristic::Manhattan, c)).unwrap();
    assert_eq!(found.path.unwrap().nodes, [c]);
    assert_eq!(bfs(&graph, c, c).unwrap().cost(), Some(0.0));
    assert_eq!(dfs(&graph, c, c).unwrap().cost(), Some(0.0));
}
