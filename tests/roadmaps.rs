//! Probabilistic roadmaps on random polygon worlds, checked against references that do not
//! share their code: an independent sampled distance test of every edge, the visibility graph
//! (the true shortest path, a lower bound on any roadmap's), Dijkstra from scratch after
//! obstacle changes (for D* Lite's repair), and the Dubins path properties.

use proptest::prelude::*;
use trailmark::core::dubins::DubinsPath;
use trailmark::core::freespace::Location;
use trailmark::core::geometry::{Point, Pose, Vector};
use trailmark::core::world::PolygonWorld;
use trailmark::graph::Roadmap;
use trailmark::graph::Trapezoids;
use trailmark::graph::dynamic::{DynamicRoadmap, Rebuild};
use trailmark::graph::visibility::Edges;
use trailmark::graph::visibility::VisibilityGraph;
use trailmark::prelude::*;
use trailmark::sample::Dubins;
use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

mod common;

/// Whether the robot's disc, sampled every `step` along `a -> b`, keeps clear of every
/// obstacle (a rounding allowance of 1e-9), never strictly inside one (which matters at radius
/// 0), and its centre stays in the bounds.
fn sampled_free(world: &PolygonWorld, a: Point, b: Point, step: f64) -> bool {
    let n = ((b - a).norm() / step).ceil().max(1.0) as usize;
    (0..=n).all(|i| {
        let p = a + (b - a) * (i as f64 / n as f64);
        world.reference_is_clear(p, 1e-9)
    })
}

/// A generated world (random convex obstacles in a 40 x 40 square), a robot radius, two
/// free points the visibility graph also sees as free, and a sampler.
fn world_strategy(
    radius: impl Strategy<Value = f64>,
) -> impl Strategy<Value = (PolygonWorld, Point, Point, PrmSampler)> {
    (
        1usize..20,
        radius,
        any::<u64>(),
        any::<[u32; 4]>(),
        prop_oneof![Just(None), any::<u64>().prop_map(Some)],
    )
        .prop_filter_map("start and goal must be free", |(count, radius, seed, picks, sampler)| {
            let world = trailmark::core::generate::convex_obstacles(40.0, count, 5, radius, seed).ok()?;
            let checker = world.checker();
            let at = |a: u32, b: u32| Point::new(f64::from(a % 4001) / 100.0, f64::from(b % 4001) / 100.0);
            let (start, goal) = (at(picks[0], picks[1]), at(picks[2], picks[3]));
            let space = world.free_space_with_step(std::f64::consts::PI / 64.0).ok()?;
            let usable = |p: Point| checker.point_is_free(p) && space.locate(p) != Location::Blocked;
            let sampler = sampler.map_or(PrmSampler::Halton, |seed| PrmSampler::Uniform { seed });
            (usable(start) && usable(goal)).then_some((world, start, goal, sampler))
        })
}

/// Adds the square `blocks` one by one, then removes one obstacle, repairing D* Lite after
/// each change; its cost must equal `fresh`'s on the world of the moment.
fn repair_matches<R: Rebuild>(
    mut roadmap: DynamicRoadmap<R>,
    start: Point,
    goal: Point,
    blocks: &[(f64, f64, f64)],
    remove: prop::sample::Index,
    fresh: impl Fn(&PolygonWorld) -> Option<f64>,
) -> Result<(), TestCaseError> {
    let (s, g) = (roadmap.pin(start), roadmap.pin(goal));
    let mut planner = DStarLite::new(&roadmap, s, g, roadmap.heuristic_between()).unwrap();
    planner.compute_shortest_path(&roadmap).unwrap();
    let mut check = |roadmap: &DynamicRoadmap<R>, changes: &[EdgeChange<u32>]| {
        planner.update_edges(roadmap, changes).unwrap();
        planner.compute_shortest_path(roadmap).unwrap();
        match (planner.cost(), fresh(roadmap.world())) {
            (Some(a), Some(b)) => {
                prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "D* Lite {a} vs fresh {b}")
            }
            (a, b) => prop_assert_eq!(a, b),
        }
        Ok(())
    };
    check(&roadmap, &[])?;
    for &(x, y, half) in blocks {
        let square = vec![
            Point::new(x - half, y - half),
            Point::new(x + half, y - half),
            Point::new(x + half, y + half),
            Point::new(x - half, y + half),
        ];
        let changes = roadmap.add_obstacle(square).unwrap();
        check(&roadmap, &changes)?;
    }
    let index = remove.index(roadmap.world().obstacles().len());
    let changes = roadmap.remove_obstacle(index).unwrap();
    check(&roadmap, &changes)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Every roadmap and query edge is collision-free, both by the exact checker and by an
    /// independent test sampled at 1e-3 of the world's size.
    #[test]
    fn prm_edges_are_collision_free((world, start, goal, sampler) in world_strategy(0.0f64..1.5)) {
        let options = PrmOptions { sampler, connection: Connection::PrmStar, ..PrmOptions::default() };
        let prm = PolygonPrm::new(world.clone(), options).expect("valid options");
        let mut prm = prm;
        if prm.grow(200).is_err() {
            return Ok(()); // a world too full to sample is reported, not a failure here
        }
        let query = prm.query(start, goal).expect("free ends");
        let checker = world.checker();
        let mut edges = 0;
        for v in 0..query.node_bound() as u32 {
            query.for_each_successor(v, |u, cost| {
                let (a, b) = (query.position(v), query.position(u));
                assert!(checker.segment_is_free(a, b), "{a} -> {b} collides");
                assert!(sampled_free(&world, a, b, 0.04), "{a} -> {b} collides when sampled");
                assert!((cost - (b - a).norm()).abs() <= 1e-12);
                edges += 1;
            });
        }
        prop_assert!(edges >= 2 * prm.edge_count());
        prop_assert_eq!(prm.count_edges(), prm.edge_count());
        let ends = prm.edge_ends();
        prop_assert_eq!(ends.len(), prm.edge_count());
        prop_assert!(ends.iter().all(|&(a, b)| checker.segment_is_free(a, b)));
    }

    /// No roadmap beats the visibility graph, whose paths are the shortest: for a point robot
    /// exactly, for a disc within the polygonal approximation of its round corners (grown by
    /// 1 / cos(PI / 128), a relative 3e-4).
    #[test]
    fn visibility_cost_is_a_lower_bound_on_prm_cost(
        (world, start, goal, sampler) in world_strategy(prop_oneof![Just(0.0), 0.1f64..1.0])
    ) {
        let space = world.free_space_with_step(std::f64::consts::PI / 64.0).expect("valid step");
        let graph = VisibilityGraph::new(space);
        prop_assert_eq!(graph.count_edges(), graph.edge_count());
        let q = graph.query(start, goal).expect("free ends");
        let best = dijkstra(&q, q.start(), q.goal()).expect("valid").cost();
        for connection in [Connection::PrmStar, Connection::Radius { radius: 6.0 }] {
            let mut prm = PolygonPrm::new(world.clone(), PrmOptions { sampler, connection, ..PrmOptions::default() }).unwrap();
            if prm.grow(300).is_err() {
                return Ok(());
            }
            let q = prm.query(start, goal).expect("free ends");
            if let Some(cost) = dijkstra(&q, q.start(), q.goal()).expect("valid").cost() {
                let best = best.expect("the visibility graph connects whatever a roadmap connects");
                let slack = if world.robot_radius() == 0.0 { 1e-9 } else { 3e-4 * best + 1e-9 };
                prop_assert!(best <= cost + slack, "visibility {best} > roadmap {cost}");
            }
        }
    }

    /// After obstacles are added and removed, D* Lite told only the reported edge changes finds
    /// the cost Dijkstra finds from scratch on the changed roadmap.
    #[test]
    fn dstar_lite_repairs_match_dijkstra(
        (world, start, goal, sampler) in world_strategy(0.0f64..1.0),
        blocks in prop::collection::vec((2.0f64..38.0, 2.0f64..38.0, 1.0f64..6.0), 1..4)
    ) {
        let mut prm = PolygonPrm::new(world, PrmOptions { sampler, ..PrmOptions::default() }).unwrap();
        if prm.grow(250).is_err() {
            return Ok(());
        }
        let (s, g) = (prm.insert(start).unwrap(), prm.insert(goal).unwrap());
        let points: Vec<Point> = (0..prm.node_count() as u32).map(|u| prm.position(u)).collect();
        let h = move |u: u32, v: u32| (points[u as usize] - points[v as usize]).norm();
        let mut planner = DStarLite::new(&prm, s, g, h).unwrap();
        planner.compute_shortest_path(&prm).unwrap();
        let first = prm.world().obstacles().len();
        let mut steps = Vec::new();
        for &(x, y, half) in &blocks {
            let square = vec![
                Point::new(x - half, y - half), Point::new(x + half, y - half),
                Point::new(x + half, y + half), Point::new(x - half, y + half),
            ];
            steps.push(prm.add_obstacle(square).unwrap());
        }
        steps.push(prm.remove_obstacle(first).unwrap());
        for changes in steps {
            // The changes of one step are told after that step; the roadmap is already at the
            // last step here, which D* Lite allows as long as every changed edge is named.
            planner.update_edges(&prm, &changes).unwrap();
        }
        planner.compute_shortest_path(&prm).unwrap();
        let fresh = dijkstra(&prm, s, g).unwrap().cost();
        match (planner.cost(), fresh) {
            (Some(a), Some(b)) => prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "D* Lite {a} vs Dijkstra {b}"),
            (a, b) => prop_assert_eq!(a, b),
        }
    }

    /// A visibility graph and a trapezoidal decomposition of a changing world: after each
    /// obstacle added or removed, D* Lite told only the reported changes finds the cost that
    /// Dijkstra finds on a query of a roadmap built from scratch for the new world.
    #[test]
    fn dynamic_roadmaps_repair_to_fresh_costs(
        (world, start, goal, _sampler) in world_strategy(prop_oneof![Just(0.0), 0.1f64..1.0]),
        blocks in prop::collection::vec((2.0f64..38.0, 2.0f64..38.0, 1.0f64..6.0), 1..4),
        remove in any::<prop::sample::Index>(),
    ) {
        let visibility = |w: &PolygonWorld| -> Option<f64> {
            let graph = VisibilityGraph::with_edges(w.free_space(), Edges::Tangent);
            let q = graph.query(start, goal).ok()?;
            dijkstra(&q, q.start(), q.goal()).unwrap().cost()
        };
        let cells = |w: &PolygonWorld| -> Option<f64> {
            let graph = Trapezoids::new(&w.free_space());
            let q = graph.query(start, goal).ok()?;
            dijkstra(&q, q.start(), q.goal()).unwrap().cost()
        };
        repair_matches(DynamicRoadmap::<VisibilityGraph>::new(world.clone(), Edges::Tangent), start, goal, &blocks, remove, visibility)?;
        repair_matches(DynamicRoadmap::<Trapezoids>::new(world, ()), start, goal, &blocks, remove, cells)?;
    }

    /// Dubins roadmap edges: each is a shortest Dubins path from its tail's pose to its head's,
    /// free by the exact checker and by the independent sampled test of its pieces, and no
    /// shorter than the straight line.
    #[test]
    fn dubins_prm_edges_are_free_shortest_curves((world, start, goal, sampler) in world_strategy(0.0f64..1.0), rho in 0.5f64..3.0) {
        let space = Dubins::new(world.bounds(), rho).unwrap();
        let options = PrmOptions { sampler, connection: Connection::Nearest { k: 6 }, ..PrmOptions::default() };
        let mut prm = PolygonPrm::with_space(world.clone(), space, options).unwrap();
        if prm.grow(60).is_err() {
            return Ok(());
        }
        let (a, b) = (Pose::new(start.coords, 0.3), Pose::new(goal.coords, -2.0));
        let query = prm.query(a, b).expect("free ends");
        let checker = world.checker();
        for v in 0..query.node_bound() as u32 {
            query.for_each_successor(v, |u, cost| {
                let (p, q) = (query.position(v), query.position(u));
                let path = DubinsPath::shortest(&p, &q, rho).unwrap();
                // The space's distance is the length-only solver's, within rounding.
                assert!((cost - path.length()).abs() <= 1e-12 * cost, "{cost} vs {}", path.length());
                assert!(checker.dubins_is_free(&path));
                // Poses 0.04 apart along the curve, each tested on its own. A curve ending on the
                // world's edge (the query's ends may lie on it) samples its end within rounding
                // of the edge, on either side: brought back onto it, as the obstacles' distances
                // are allowed the same 1e-9.
                let (low, high) = (world.bounds().min(), world.bounds().max());
                for pose in path.sample(0.04).unwrap() {
                    let mut x = Point::from(pose.translation.vector);
                    for i in 0..2 {
                        let onto = x[i].clamp(low[i], high[i]);
                        if (onto - x[i]).abs() <= 1e-9 {
                            x[i] = onto;
                        }
                    }
                    assert!(sampled_free(&world, x, x, 1.0), "{x} on {path:?} collides when sampled");
                }
                let chord: Vector = q.translation.vector - p.translation.vector;
                assert!(cost >= chord.norm() - 1e-9);
            });
        }
    }
}

mod trapezoids {
    use proptest::prelude::*;
    use trailmark::core::freespace::{FreeSpace, Location};
    use trailmark::core::geometry::Point;
    use trailmark::graph::trapezoid::Trapezoids;
    use trailmark::graph::visibility::VisibilityGraph;
    use trailmark::prelude::*;

    use super::common::grid_strategy;
    use super::world_strategy;

    /// Checks a decomposition against its free space: positive-area cells inside it, portals on
    /// both their cells' sides, point location agreeing with the free space's own exact test,
    /// and queries whose edges are free, whose reachability is the visibility graph's and whose
    /// cost is no lower than the visibility graph's.
    fn check(space: &FreeSpace, cells: &Trapezoids, probes: &[Point], pairs: &[(Point, Point)]) {
        for c in 0..cells.cell_count() {
            let cell = cells.cell(c);
            assert!(cell.area() > 0.0 && cell.left < cell.right, "cell {c}: {cell:?}");
            assert!(cell.contains(cell.centroid()), "cell {c}: {cell:?} corners {:?}", cell.corners());
            assert_ne!(space.locate(cell.centroid()), Location::Blocked, "cell {c} centroid");
            assert!(cell.contains(cell.centroid()));
        }
        for portal in cells.portals() {
            assert!(portal.low < portal.high);
            for c in [portal.left, portal.right] {
                assert!(cells.cell(c as usize).contains(portal.midpoint()));
            }
            assert_eq!(cells.cell(portal.left as usize).right, portal.x);
            assert_eq!(cells.cell(portal.right as usize).left, portal.x);
        }
        for &p in probes {
            let inside = space.locate(p) != Location::Blocked;
            assert_eq!(cells.locate(p).is_some(), inside, "{p}");
        }
        let graph = VisibilityGraph::new(space.clone());
        for &(start, goal) in pairs {
            let q = cells.query(start, goal).expect("free ends");
            for v in 0..q.node_bound() as u32 {
                q.for_each_successor(v, |u, _| {
                    let (a, b) = (q.position(v), q.position(u));
                    assert!(space.segment_is_free(a, b), "{a} -> {b} leaves the free space");
                });
            }
            let cost = dijkstra(&q, q.start(), q.goal()).expect("valid").cost();
            let v = graph.query(start, goal).expect("free ends");
            let best = dijkstra(&v, v.start(), v.goal()).expect("valid").cost();
            assert_eq!(cost.is_some(), best.is_some(), "{start} -> {goal}: reachability differs");
            if let (Some(cost), Some(best)) = (cost, best) {
                assert!(best <= cost + 1e-9, "visibility {best} > trapezoid {cost}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// On grid maps (unit-square obstacles, many vertices on one vertical line, vertical
        /// edges, corner pinches) the cells tile exactly the free cells: their areas sum to the
        /// number of free cells.
        #[test]
        fn grid_decompositions_tile_the_free_cells(grid in grid_strategy(), picks in any::<[u16; 8]>()) {
            let space = FreeSpace::from_grid(&grid);
            let cells = Trapezoids::new(&space);
            let free = grid.cells().filter(|&c| grid.is_passable(c)).count() as f64;
            let area: f64 = (0..cells.cell_count()).map(|c| cells.cell(c).area()).sum();
            prop_assert!((area - free).abs() <= 1e-9 * free.max(1.0), "area {area} vs {free} free cells");
            let (w, h) = (f64::from(grid.width()), f64::from(grid.height()));
            let probe = |a: u16, b: u16| Point::new(f64::from(a) / 65535.0 * (w + 1.0) - 0.5, f64::from(b) / 65535.0 * (h + 1.0) - 0.5);
            let mut probes: Vec<Point> = picks.chunks(2).map(|c| probe(c[0], c[1])).collect();
            // Cell corners and centres: on vertices, sides and pinches.
            probes.extend(grid.cells().flat_map(|c| {
                let (x, y) = (f64::from(c.x), f64::from(c.y));
                [Point::new(x, y), Point::new(x + 0.5, y + 0.5), Point::new(x + 0.5, y)]
            }));
            let free_points: Vec<Point> = grid
                .cells()
                .filter(|&c| grid.is_passable(c))
                .map(|c| Point::new(f64::from(c.x) + 0.5, f64::from(c.y) + 0.5))
                .collect();
            let pairs: Vec<(Point, Point)> = if free_points.is_empty() {
                Vec::new()
            } else {
                picks.chunks(2).map(|c| (free_points[c[0] as usize % free_points.len()], free_points[c[1] as usize % free_points.len()])).collect()
            };
            check(&space, &cells, &probes, &pairs);
        }

        /// On polygon worlds (grown obstacles, merged where they overlap) the same checks hold.
        #[test]
        fn polygon_decompositions_are_sound((world, start, goal, _sampler) in world_strategy(prop_oneof![Just(0.0), 0.1f64..1.0])) {
            let space = world.free_space_with_step(std::f64::consts::PI / 64.0).expect("valid step");
            let cells = Trapezoids::new(&space);
            let area: f64 = (0..cells.cell_count()).map(|c| cells.cell(c).area()).sum();
            prop_assert!(area <= 40.0 * 40.0 * (1.0 + 1e-12));
            let probes: Vec<Point> = (0..64).map(|k| Point::new(f64::from(k % 8) * 5.3 + 0.7, f64::from(k / 8) * 5.1 + 0.4)).collect();
            check(&space, &cells, &probes, &[(start, goal)]);
        }
    }
}

/// Each accessor that takes an id panics past the last id as documented, and its checked form
/// answers `None` there and the same value inside.
#[test]
fn checked_accessors_answer_none_past_the_last_id() {
    let world: PolygonWorld = serde_json::from_str(
        r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]], "robot_radius": 0.25}"#,
    )
    .unwrap();
    let visibility = VisibilityGraph::new(world.free_space());
    let n = visibility.node_count() as u32;
    assert_eq!(visibility.get_position(0), Some(visibility.position(0)));
    assert_eq!(visibility.get_position(n), None);
    assert_eq!(visibility.get_position(u32::MAX), None);
    let space = world.free_space();
    assert_eq!(space.get_corners(0), Some(space.corners(0)));
    assert_eq!(space.get_corners(space.positions().len()), None);
    let cells = Trapezoids::new(&space);
    assert!(cells.get_cell(0).is_some());
    assert!(cells.get_cell(cells.cell_count()).is_none());
    let mut prm = PolygonPrm::new(world.clone(), PrmOptions::default()).unwrap();
    prm.grow(50).unwrap();
    let last = prm.node_count() as u32 - 1;
    assert_eq!(prm.get_position(last), Some(prm.position(last)));
    assert_eq!(prm.get_position(last + 1), None);
    assert_eq!(prm.get_component(last), Some(prm.component(last)));
    assert_eq!(prm.get_component(u32::MAX), None);
    let dynamic = DynamicRoadmap::<VisibilityGraph>::new(world, Edges::Tangent);
    let m = dynamic.node_count() as u32;
    assert_eq!(dynamic.get_position(m), None);
    assert_eq!(dynamic.get_neighbours(m), None);
    assert_eq!(dynamic.get_neighbours(0), Some(dynamic.neighbours(0)));
}
