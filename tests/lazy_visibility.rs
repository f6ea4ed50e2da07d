//! The lazy visibility graph against the full one (`VisibilityGraph`, built by sweeping every
//! node): on random grid and polygon worlds, every bounded graph holds exactly the full graph's
//! edges that its bound keeps, and the rounds end at the full graph's shortest length.

use std::collections::BTreeSet;

use proptest::prelude::*;
use trailmark::core::freespace::{FreeSpace, Location};
use trailmark::core::geometry::Point;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::graph::{BoundedVisibility, LazyVisibilityGraph, Roadmap, RoadmapQuery};
use trailmark::prelude::*;

mod common;
use common::grid_strategy;

/// The shortest length by the full tangent graph, or `None` without a path.
fn full_length(space: &FreeSpace, start: Point, goal: Point) -> Option<f64> {
    let graph = VisibilityGraph::with_options(space.clone(), Edges::Tangent, 1);
    let q = graph.query(start, goal).expect("free ends");
    astar(&q, q.start(), q.goal(), q.heuristic()).expect("valid").cost()
}

/// The shortest length by the lazy graph's rounds, and the number of rounds.
fn lazy_length(graph: &LazyVisibilityGraph, start: Point, goal: Point) -> (Option<f64>, usize) {
    let mut bound = LazyVisibilityGraph::first_bound(start, goal);
    for round in 1.. {
        let bounded = graph.within(start, goal, bound).expect("free ends");
        let q = bounded.query();
        let cost = astar(&q, q.start(), q.goal(), q.heuristic()).expect("valid").cost();
        match bounded.next_bound(cost) {
            Some(next) => {
                assert!(next > bound, "the bound grows: {bound} then {next}");
                bound = next;
            }
            None => return (cost, round),
        }
    }
    unreachable!()
}

/// Every edge of a query graph as (from, to, cost) by the positions of its ends (the graphs
/// number the start and goal differently), but those into the start or out of the goal (the
/// full graph's query is undirected: they are on no path from the start to the goal).
fn edges_of<R: Roadmap<Position = Point>>(q: &RoadmapQuery<'_, R>) -> BTreeSet<([u64; 2], [u64; 2], u64)> {
    let key = |p: Point| [p.x.to_bits(), p.y.to_bits()];
    let mut edges = BTreeSet::new();
    for v in (0..q.node_bound() as u32).filter(|&v| v != q.goal()) {
        q.for_each_successor(v, |u, c| {
            if u != q.start() {
                edges.insert((key(q.position(v)), key(q.position(u)), c.to_bits()));
            }
        });
    }
    edges
}

/// Checks a bounded graph against the full one: its out-edges (and the start's and goal's
/// links) are the full graph's edges u -> w with |su| + |uw| + |wg| within the bound (those
/// close to it, within rounding, may go either way), and its in-edges are its out-edges.
fn check_bounded(
    full: &VisibilityGraph,
    bounded: &BoundedVisibility<'_>,
    start: Point,
    goal: Point,
    world: &str,
) {
    let q = full.query(start, goal).expect("free ends");
    let lazy = bounded.query();
    let bound = bounded.bound();
    let sum = |a: Point, b: Point| (a - start).norm() + (b - a).norm() + (goal - b).norm();
    let point = |k: [u64; 2]| Point::new(f64::from_bits(k[0]), f64::from_bits(k[1]));
    let expected: BTreeSet<_> =
        edges_of(&q).into_iter().filter(|&(a, b, _)| sum(point(a), point(b)) <= bound).collect();
    let found = edges_of(&lazy);
    let within =
        |e: &([u64; 2], [u64; 2], u64)| (sum(point(e.0), point(e.1)) - bound).abs() <= 1e-9 * bound.max(1.0);
    for e in expected.symmetric_difference(&found) {
        assert!(
            within(e),
            "{world}: {start} -> {goal}, edge {e:?} differs (bound {bound}): full {}, lazy {}",
            expected.contains(e),
            found.contains(e)
        );
    }
    // In-edges: u -> w is an in-edge of w exactly when it is an out-edge of u.
    let roadmap = lazy.roadmap();
    let mut outs = BTreeSet::new();
    let mut ins = BTreeSet::new();
    for v in 0..roadmap.node_count() as u32 {
        roadmap.for_each_out(v, |w, c| {
            outs.insert((v, w, c.to_bits()));
        });
        roadmap.for_each_in(v, |u, c| {
            ins.insert((u, v, c.to_bits()));
        });
    }
    assert_eq!(outs, ins, "in-edges and out-edges differ (bound {bound})");
}

/// A grid world's free cell corners (the GPPC query points) and centres.
fn grid_points(grid: &Grid) -> Vec<Point> {
    let mut points = Vec::new();
    for c in grid.cells().filter(|&c| grid.is_passable(c)) {
        let (x, y) = (f64::from(c.x), f64::from(c.y));
        points.extend([Point::new(x, y), Point::new(x + 0.5, y + 0.5)]);
    }
    points
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// On grid worlds, the rounds end at the full graph's shortest length (or at no path where
    /// it has none), and bounded graphs at bounds from the straight line to twice it hold
    /// exactly the full graph's edges that the bound keeps.
    #[test]
    fn grid_worlds_agree_with_the_full_graph(
        grid in grid_strategy(),
        pick in any::<(usize, usize)>(),
        slack in 0.0f64..1.0,
    ) {
        let points = grid_points(&grid);
        prop_assume!(!points.is_empty());
        let (start, goal) = (points[pick.0 % points.len()], points[pick.1 % points.len()]);
        let space = FreeSpace::from_grid(&grid);
        let lazy = LazyVisibilityGraph::new(space.clone());
        let expected = full_length(&space, start, goal);
        let (found, _) = lazy_length(&lazy, start, goal);
        prop_assert_eq!(found.is_some(), expected.is_some(), "{:?} {} -> {}", grid.to_rows(), start, goal);
        if let (Some(a), Some(b)) = (found, expected) {
            prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "lazy {} full {}", a, b);
        }
        let full = VisibilityGraph::with_options(space, Edges::Tangent, 1);
        let line = (goal - start).norm();
        for bound in [line + line * slack, f64::INFINITY] {
            let world = format!("{:?}", grid.to_rows());
            check_bounded(&full, &lazy.within(start, goal, bound).expect("free"), start, goal, &world);
        }
    }
}

/// A generated polygon world's free space and two points of it.
fn polygon_world() -> impl Strategy<Value = (FreeSpace, Point, Point)> {
    (1usize..30, prop_oneof![Just(0.0), 0.0f64..1.5], any::<u64>(), any::<[u32; 4]>()).prop_filter_map(
        "start and goal must be free",
        |(count, radius, seed, picks)| {
            let world = trailmark::core::generate::convex_obstacles(40.0, count, 5, radius, seed).ok()?;
            let at = |a: u32, b: u32| Point::new(f64::from(a % 4001) / 100.0, f64::from(b % 4001) / 100.0);
            let (start, goal) = (at(picks[0], picks[1]), at(picks[2], picks[3]));
            let space = world.free_space();
            let usable = |p: Point| space.locate(p) != Location::Blocked;
            (usable(start) && usable(goal)).then_some((space, start, goal))
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The same on polygon worlds (random convex obstacles grown by a robot radius).
    #[test]
    fn polygon_worlds_agree_with_the_full_graph((space, start, goal) in polygon_world(), slack in 0.0f64..0.3) {
        let lazy = LazyVisibilityGraph::new(space.clone());
        let expected = full_length(&space, start, goal);
        let (found, _) = lazy_length(&lazy, start, goal);
        prop_assert_eq!(found.is_some(), expected.is_some());
        if let (Some(a), Some(b)) = (found, expected) {
            prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "lazy {} full {}", a, b);
        }
        let full = VisibilityGraph::with_options(space, Edges::Tangent, 1);
        let line = (goal - start).norm();
        let bounded = lazy.within(start, goal, line + line * slack).expect("free");
        check_bounded(&full, &bounded, start, goal, "a polygon world");
    }
}

/// The free space of a lattice of `k` x `k` unit blocks.
fn lattice(k: usize) -> FreeSpace {
    FreeSpace::from_grid(&trailmark::core::generate::lattice(k).expect("a grid"))
}

#[test]
fn a_lattice_query_sweeps_a_fraction_of_the_nodes() {
    // 400 blocks, 1,600 nodes; corner to corner the path is nearly straight.
    let space = lattice(20);
    let (start, goal) = (Point::new(0.5, 0.5), Point::new(40.5, 40.5));
    let lazy = LazyVisibilityGraph::new(space.clone());
    let (found, rounds) = lazy_length(&lazy, start, goal);
    let expected = full_length(&space, start, goal).expect("a path");
    assert!((found.expect("a path") - expected).abs() <= 1e-9 * expected);
    assert_eq!(rounds, 1, "the first bound holds a nearly straight path");
    let bounded = lazy.within(start, goal, LazyVisibilityGraph::first_bound(start, goal)).unwrap();
    let q = bounded.query();
    astar(&q, q.start(), q.goal(), q.heuristic()).unwrap();
    assert!(bounded.swept() * 10 < lazy.node_count(), "swept {} of {}", bounded.swept(), lazy.node_count());
}

#[test]
fn bounds_below_the_line_or_not_a_number_keep_no_edge() {
    let space = lattice(3);
    let lazy = LazyVisibilityGraph::new(space);
    let (start, goal) = (Point::new(0.5, 0.5), Point::new(6.5, 0.5));
    for bound in [5.9, f64::NAN, -1.0, f64::NEG_INFINITY] {
        let bounded = lazy.within(start, goal, bound).unwrap();
        let q = bounded.query();
        assert_eq!(astar(&q, q.start(), q.goal(), q.heuristic()).unwrap().cost(), None);
        for v in 0..q.node_bound() as u32 {
            q.for_each_successor(v, |u, _| panic!("an edge {v} -> {u} at bound {bound}"));
            q.for_each_predecessor(v, |u, _| panic!("an edge {u} -> {v} at bound {bound}"));
        }
        assert!(bounded.next_bound(None).is_some(), "a next round after {bound}");
    }
    // The straight line along the free row is found at the first bound.
    let bounded = lazy.within(start, goal, LazyVisibilityGraph::first_bound(start, goal)).unwrap();
    let q = bounded.query();
    assert_eq!(astar(&q, q.start(), q.goal(), q.heuristic()).unwrap().cost(), Some(6.0));
    assert_eq!(bounded.next_bound(Some(6.0)), None);
}

#[test]
fn rounds_end_even_when_every_path_found_is_longer_than_its_bound() {
    // A search that is not least-cost may keep returning a path just above each bound.
    let lazy = LazyVisibilityGraph::new(lattice(3));
    let (start, goal) = (Point::new(0.5, 0.5), Point::new(6.5, 6.5));
    let mut bound = LazyVisibilityGraph::first_bound(start, goal);
    let mut rounds = 1;
    while let Some(next) = lazy.within(start, goal, bound).unwrap().next_bound(Some(bound * 1.0001)) {
        assert!(next > bound);
        bound = next;
        rounds += 1;
        assert!(rounds <= 11, "round {rounds} at bound {bound}");
    }
    assert_eq!(bound, f64::INFINITY, "the last round is unbounded");
}

#[test]
fn blocked_ends_are_errors() {
    let lazy = LazyVisibilityGraph::new(lattice(2));
    assert!(lazy.within(Point::new(1.5, 1.5), Point::new(0.0, 0.0), f64::INFINITY).is_err());
    assert!(lazy.within(Point::new(0.0, 0.0), Point::new(1.5, 1.5), 10.0).is_err());
    assert!(lazy.within(Point::new(f64::NAN, 0.0), Point::new(0.0, 0.0), 10.0).is_err());
}
