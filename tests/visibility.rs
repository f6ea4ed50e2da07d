//! Visibility graphs on random grid worlds, checked against references that do not share the
//! sweep: a brute-force pairwise construction, the grid itself (sampled points of every edge
//! must lie in free cells), and the 8-connected corner lattice (an upper bound on any-angle
//! lengths), plus the straight-line lower bound.

use std::collections::BTreeSet;

use proptest::prelude::*;
use trailmark::core::freespace::{FreeSpace, Location};
use trailmark::core::geometry::Point;
use trailmark::graph::CornerGraph;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::prelude::*;
use trailmark::search::theta_star;

mod common;
use common::grid_strategy;

/// The free cells' top-left corners: the GPPC query points.
fn query_points(grid: &Grid) -> Vec<Point> {
    grid.cells()
        .filter(|&c| grid.is_passable(c))
        .map(|c| Point::new(f64::from(c.x), f64::from(c.y)))
        .collect()
}

/// Whether a point lies strictly inside a blocked cell (or strictly outside the map).
fn strictly_blocked(grid: &Grid, p: Point) -> bool {
    let (w, h) = (f64::from(grid.width()), f64::from(grid.height()));
    if p.x < 0.0 || p.y < 0.0 || p.x > w || p.y > h {
        return true;
    }
    let (fx, fy) = (p.x.floor(), p.y.floor());
    if fx == p.x || fy == p.y {
        return false; // on a cell side: not strictly inside any cell
    }
    !grid.is_passable(Cell::new(fx as u32, fy as u32))
}

/// An undirected edge as a key: the endpoints' bit patterns, in order.
fn edge_key(a: Point, b: Point) -> [(u64, u64); 2] {
    let key = |p: Point| (p.x.to_bits(), p.y.to_bits());
    let (ka, kb) = (key(a), key(b));
    if ka < kb { [ka, kb] } else { [kb, ka] }
}

/// Every node pair that sees each other, by testing each pair on its own.
fn brute_force_edges(space: &FreeSpace) -> BTreeSet<[(u64, u64); 2]> {
    let mut nodes = Vec::new();
    for (i, &at) in space.positions().iter().enumerate() {
        for corner in space.corners(i) {
            if corner.is_convex_obstacle(at) {
                nodes.push((at, *corner));
            }
        }
    }
    let mut edges = BTreeSet::new();
    for (i, &(a, ca)) in nodes.iter().enumerate() {
        for &(b, cb) in &nodes[i + 1..] {
            if a != b && ca.admits(a, b) && cb.admits(b, a) && space.segment_is_free(a, b) {
                edges.insert(edge_key(a, b));
            }
        }
    }
    edges
}

fn graph_edges(graph: &VisibilityGraph) -> BTreeSet<[(u64, u64); 2]> {
    (0..graph.node_count() as u32)
        .flat_map(|v| graph.neighbours(v).map(move |(u, _)| edge_key(graph.position(v), graph.position(u))))
        .collect()
}

/// A lattice move: its step and the cells beside it.
type Move<'a> = (i64, i64, &'a [(i64, i64)]);

/// The 8-connected lattice of cell corners: a side between two cells may be followed when one of
/// them is free, a cell's diagonal when the cell is free. Where two blocked cells touch at a
/// corner, the corner is two lattice nodes, one per free cell, so no lattice path slips between
/// the blocked cells. An any-angle path is never longer.
fn lattice_cost(grid: &Grid, start: Point, goal: Point) -> Option<f64> {
    let (w, h) = (grid.width() as i64, grid.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && grid.is_passable(Cell::new(x as u32, y as u32))
    };
    let pinch = |x: i64, y: i64| {
        let (nw, ne, sw, se) = (free(x - 1, y - 1), free(x, y - 1), free(x - 1, y), free(x, y));
        (nw && se && !ne && !sw) || (ne && sw && !nw && !se)
    };
    // Which node of corner (x, y) a move beside free cell (cx, cy) uses: at a pinch the two free
    // cells are in different rows.
    let part = |x: i64, y: i64, cy: i64| usize::from(pinch(x, y) && cy < y);
    let index = |x: i64, y: i64, p: usize| ((y * (w + 1) + x) as usize) * 2 + p;
    let mut dist = vec![f64::INFINITY; ((w + 1) * (h + 1) * 2) as usize];
    let mut open = std::collections::BinaryHeap::new();
    let (sx, sy) = (start.x as i64, start.y as i64);
    for p in 0..2 {
        dist[index(sx, sy, p)] = 0.0;
        open.push((std::cmp::Reverse(ordered_float::OrderedFloat(0.0)), sx, sy, p));
    }
    while let Some((std::cmp::Reverse(d), x, y, p)) = open.pop() {
        if d.0 > dist[index(x, y, p)] {
            continue;
        }
        if (x as f64, y as f64) == (goal.x, goal.y) {
            return Some(d.0);
        }
        // (dx, dy, the cells beside the move).
        let moves: [Move; 8] = [
            (1, 0, &[(x, y - 1), (x, y)]),
            (-1, 0, &[(x - 1, y - 1), (x - 1, y)]),
            (0, 1, &[(x - 1, y), (x, y)]),
            (0, -1, &[(x - 1, y - 1), (x, y - 1)]),
            (1, 1, &[(x, y)]),
            (-1, 1, &[(x - 1, y)]),
            (1, -1, &[(x, y - 1)]),
            (-1, -1, &[(x - 1, y - 1)]),
        ];
        for (dx, dy, beside) in moves {
            let (nx, ny) = (x + dx, y + dy);
            let Some(&(_, cy)) = beside.iter().find(|&&(cx, cy)| free(cx, cy)) else { continue };
            if nx < 0 || ny < 0 || nx > w || ny > h || part(x, y, cy) != p {
                continue;
            }
            let np = part(nx, ny, cy);
            let nd = d.0 + if dx != 0 && dy != 0 { std::f64::consts::SQRT_2 } else { 1.0 };
            if nd < dist[index(nx, ny, np)] {
                dist[index(nx, ny, np)] = nd;
                open.push((std::cmp::Reverse(ordered_float::OrderedFloat(nd)), nx, ny, np));
            }
        }
    }
    None
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(192))]

    /// The sweep finds exactly the pairs that a pairwise test finds.
    #[test]
    fn sweep_matches_brute_force(grid in grid_strategy()) {
        let space = FreeSpace::from_grid(&grid);
        let expected = brute_force_edges(&space);
        let graph = VisibilityGraph::with_options(space, Edges::All, 1);
        prop_assert_eq!(graph_edges(&graph), expected);
    }

    /// Every edge, and every query edge, stays out of blocked cells (sampled on the grid itself)
    /// and passes the exact segment test.
    #[test]
    fn every_edge_is_collision_free(grid in grid_strategy(), pick in any::<(usize, usize)>()) {
        let points = query_points(&grid);
        prop_assume!(!points.is_empty());
        let graph = VisibilityGraph::new(FreeSpace::from_grid(&grid));
        let (start, goal) = (points[pick.0 % points.len()], points[pick.1 % points.len()]);
        let query = graph.query(start, goal).expect("query points are free");
        for v in 0..query.node_bound() as u32 {
            query.for_each_successor(v, |u, cost| {
                let (a, b) = (query.position(v), query.position(u));
                assert!((cost - (a - b).norm()).abs() < 1e-12);
                assert!(graph.space().segment_is_free(a, b), "{a} -> {b}");
                for k in 1..64 {
                    let p = a + (b - a) * (f64::from(k) / 64.0);
                    assert!(!strictly_blocked(&grid, p), "{a} -> {b} crosses a blocked cell at {p}");
                }
            });
        }
    }

    /// Shortest paths: at least the straight line, at most the corner lattice, and the same on
    /// the full and the tangent graph.
    #[test]
    fn shortest_paths_are_bounded_and_agree(grid in grid_strategy(), pick in any::<(usize, usize)>()) {
        let points = query_points(&grid);
        prop_assume!(!points.is_empty());
        let (start, goal) = (points[pick.0 % points.len()], points[pick.1 % points.len()]);
        let space = FreeSpace::from_grid(&grid);
        let full = VisibilityGraph::with_options(space.clone(), Edges::All, 1);
        let tangent = VisibilityGraph::with_options(space, Edges::Tangent, 2);
        let cost = |graph: &VisibilityGraph| {
            let q = graph.query(start, goal).expect("free");
            astar(&q, q.start(), q.goal(), q.heuristic()).expect("valid").cost()
        };
        let (a, b) = (cost(&full), cost(&tangent));
        let lattice = lattice_cost(&grid, start, goal);
        prop_assert_eq!(a.is_some(), lattice.is_some(), "{:?} {} -> {}", grid.to_rows(), start, goal);
        if let (Some(a), Some(b), Some(lattice)) = (a, b, lattice) {
            prop_assert!((a - b).abs() <= 1e-9 * a.max(1.0), "full {} tangent {}", a, b);
            prop_assert!(a >= (goal - start).norm() - 1e-9);
            prop_assert!(a <= lattice + 1e-9, "any-angle {} above lattice {}", a, lattice);
        }
    }

    /// Theta* on the corner graph: never shorter than the visibility graph's optimum, every
    /// segment clear of blocked cells (sampled), a path only where one exists.
    #[test]
    fn theta_star_on_corners_is_never_shorter(grid in grid_strategy(), pick in any::<(usize, usize)>()) {
        let points = query_points(&grid);
        prop_assume!(!points.is_empty());
        let (start, goal) = (points[pick.0 % points.len()], points[pick.1 % points.len()]);
        let graph = VisibilityGraph::new(FreeSpace::from_grid(&grid));
        let q = graph.query(start, goal).expect("free");
        let optimum = astar(&q, q.start(), q.goal(), q.heuristic()).expect("valid").cost();
        let corners = CornerGraph::new(&grid);
        let corner = |p: Point| Cell::new(p.x as u32, p.y as u32);
        let (s, g) = (corner(start), corner(goal));
        let h = |c: Cell| f64::from(c.x.abs_diff(g.x)).hypot(f64::from(c.y.abs_diff(g.y)));
        let found = theta_star(&corners, s, g, h, &corners).expect("valid");
        if let Some(path) = found.path {
            let optimum = optimum.expect("Theta* found a path where the visibility graph finds none");
            prop_assert!(path.cost >= optimum - 1e-9, "Theta* {} below the optimum {}", path.cost, optimum);
            for pair in path.nodes.windows(2) {
                let (a, b) = (Point::new(f64::from(pair[0].x), f64::from(pair[0].y)), Point::new(f64::from(pair[1].x), f64::from(pair[1].y)));
                for k in 1..64 {
                    let p = a + (b - a) * (f64::from(k) / 64.0);
                    prop_assert!(!strictly_blocked(&grid, p), "{} -> {} crosses a blocked cell at {}", a, b, p);
                }
            }
        }
    }
}

#[test]
fn around_a_block() {
    // From the middle of the left side to the middle of the right, around a 2x1 block.
    let grid = Grid::from_rows(&["....", ".@@.", "...."]).unwrap();
    let graph = VisibilityGraph::new(FreeSpace::from_grid(&grid));
    let q = graph.query(Point::new(0.0, 1.0), Point::new(4.0, 2.0)).unwrap();
    let found = astar(&q, q.start(), q.goal(), q.heuristic()).unwrap();
    // (0,1) -> (1,1) -> (3,1)? No: the block spans x 1..3, y 1..2; the path runs along its top
    // side to (3, 1), then diagonally to (4, 2).
    let expected = 3.0 + std::f64::consts::SQRT_2;
    assert!((found.cost().unwrap() - expected).abs() < 1e-12);
}

#[test]
fn start_and_goal_inside_obstacles_are_errors() {
    let grid = Grid::from_rows(&["...", ".@.", "..."]).unwrap();
    let graph = VisibilityGraph::new(FreeSpace::from_grid(&grid));
    assert!(graph.query(Point::new(1.5, 1.5), Point::new(0.0, 0.0)).is_err());
    assert!(graph.query(Point::new(0.0, 0.0), Point::new(1.5, 1.5)).is_err());
    assert!(graph.query(Point::new(f64::NAN, 0.0), Point::new(0.0, 0.0)).is_err());
}

/// A generated polygon world: random convex obstacles, a robot radius, and two free points.
fn polygon_world() -> impl Strategy<Value = (trailmark::core::world::PolygonWorld, Point, Point)> {
    (1usize..25, prop_oneof![Just(0.0), 0.0f64..1.5], any::<u64>(), any::<[u32; 4]>()).prop_filter_map(
        "start and goal must be free",
        |(count, radius, seed, picks)| {
            let world = trailmark::core::generate::convex_obstacles(40.0, count, 5, radius, seed).ok()?;
            let checker = world.checker();
            let at = |a: u32, b: u32| Point::new(f64::from(a % 4001) / 100.0, f64::from(b % 4001) / 100.0);
            let (start, goal) = (at(picks[0], picks[1]), at(picks[2], picks[3]));
            let space = world.free_space();
            let usable = |p: Point| checker.point_is_free(p) && space.locate(p) != Location::Blocked;
            (usable(start) && usable(goal)).then_some((world, start, goal))
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// On polygon worlds, every edge of the visibility graph (and of a query) is collision-free
    /// for the disc robot by the exact checker (round shapes, not the polygons the graph was
    /// built on), and the shortest path is no shorter than the straight line.
    #[test]
    fn polygon_world_edges_are_collision_free((world, start, goal) in polygon_world()) {
        let checker = world.checker();
        let graph = VisibilityGraph::new(world.free_space());
        let query = graph.query(start, goal).expect("free points");
        for v in 0..query.node_bound() as u32 {
            query.for_each_successor(v, |u, _| {
                let (a, b) = (query.position(v), query.position(u));
                assert!(checker.segment_is_free(a, b), "{a} -> {b} collides");
            });
        }
        if let Some(cost) = astar(&query, query.start(), query.goal(), query.heuristic()).expect("valid").cost() {
            prop_assert!(cost >= (goal - start).norm() - 1e-9);
        }
    }
}
