//! Hybrid A* on polygon worlds laid on cells: every pose of every path keeps a rectangular
//! car inside the bounds and off every obstacle, by an exact test of the two polygons written
//! here (edges crossing, or a vertex of one inside the other); the path is continuous, turns no
//! tighter than the turning radius and ends at the goal.

use proptest::prelude::*;
use trailmark_car::{CarError, CarMap, HybridAStar, HybridOptions};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::termination::Termination;
use trailmark_core::world::{Bounds, Polygon, PolygonWorld};
use trailmark_sample::space::ReedsShepp;
use trailmark_sample::{FootprintValidity, KdNearest, Planner, Problem, RrtConnect};

/// A 1 m x 0.6 m car, its reference point 0.2 m from the back.
const CAR: [[f64; 2]; 4] = [[-0.2, -0.3], [0.8, -0.3], [0.8, 0.3], [-0.2, 0.3]];
const TURNING_RADIUS: f64 = 1.0;
const RESOLUTION: f64 = 0.125;
const SIZE: (f64, f64) = (16.0, 10.0);

fn orient(p: Point, q: Point, r: Point) -> f64 {
    (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)
}

/// Whether the closed segments `a`-`b` and `c`-`d` meet.
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2, d3, d4) = (orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return true;
    }
    let on = |p: Point, q: Point, r: Point, o: f64| {
        o == 0.0 && r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// Whether `p` lies inside the polygon `vertices` (even-odd rule).
fn inside(vertices: &[Point], p: Point) -> bool {
    let n = vertices.len();
    let mut odd = false;
    for k in 0..n {
        let (a, b) = (vertices[k], vertices[(k + 1) % n]);
        if (a.y <= p.y) != (b.y <= p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            odd = !odd;
        }
    }
    odd
}

/// Whether two closed polygons share a point.
fn polygons_meet(a: &[Point], b: &[Point]) -> bool {
    let edges = |v: &[Point]| (0..v.len()).map(|k| (v[k], v[(k + 1) % v.len()])).collect::<Vec<_>>();
    let (ea, eb) = (edges(a), edges(b));
    ea.iter().any(|&(p, q)| eb.iter().any(|&(r, s)| segments_meet(p, q, r, s)))
        || inside(b, a[0])
        || inside(a, b[0])
}

/// Whether the car at `pose` is inside the bounds and touches no obstacle.
fn car_free(world: &PolygonWorld, pose: &Pose) -> bool {
    let corners: Vec<Point> = CAR.iter().map(|c| pose * Point::new(c[0], c[1])).collect();
    let (lo, hi) = (world.bounds().min(), world.bounds().max());
    corners.iter().all(|c| c.x >= lo.x && c.y >= lo.y && c.x <= hi.x && c.y <= hi.y)
        && world.obstacles().iter().all(|o| !polygons_meet(&corners, o.vertices()))
}

fn heading_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// A world of 3 to 8 rotated rectangles.
fn world() -> impl Strategy<Value = (PolygonWorld, [f64; 6], bool)> {
    (
        prop::collection::vec(prop::array::uniform5(0.0..1.0f64), 3..9),
        prop::array::uniform6(0.0..1.0f64),
        any::<bool>(),
    )
        .prop_map(|(boxes, ends, reverse)| {
            let obstacles = boxes
                .iter()
                .map(|b| {
                    let (cx, cy) = (b[0] * SIZE.0, b[1] * SIZE.1);
                    let (w, h, a) = (0.5 + 3.0 * b[2], 0.5 + 2.0 * b[3], b[4] * std::f64::consts::PI);
                    let (s, c) = a.sin_cos();
                    [(-w, -h), (w, -h), (w, h), (-w, h)]
                        .iter()
                        .map(|&(x, y)| {
                            Point::new(cx + c * x / 2.0 - s * y / 2.0, cy + s * x / 2.0 + c * y / 2.0)
                        })
                        .collect()
                })
                .collect();
            let bounds = Bounds::new(0.0, 0.0, SIZE.0, SIZE.1).unwrap();
            (PolygonWorld::new(bounds, obstacles, 0.0).unwrap(), ends, reverse)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, max_global_rejects: 100_000, ..ProptestConfig::default() })]

    #[test]
    fn paths_keep_the_car_off_the_polygons((world, e, reverse) in world()) {
        let map = CarMap::from_world(&world, RESOLUTION).unwrap();
        let car = Footprint::Polygon(Polygon::new(CAR.iter().map(|c| Point::new(c[0], c[1])).collect()).unwrap());
        let settings = HybridOptions { turning_radius: TURNING_RADIUS, reverse, ..HybridOptions::default() };
        let planner = HybridAStar::new(&map, &car, settings).unwrap();
        let tau = std::f64::consts::TAU;
        let start = Pose::new(nalgebra::Vector2::new(e[0] * SIZE.0, e[1] * SIZE.1), e[2] * tau);
        let goal = Pose::new(nalgebra::Vector2::new(e[3] * SIZE.0, e[4] * SIZE.1), e[5] * tau);
        prop_assume!(planner.is_free(&start) && planner.is_free(&goal));
        // What the planner finds free, the exact test does too.
        prop_assert!(car_free(&world, &start) && car_free(&world, &goal));
        match planner.plan(&start, &goal, &Termination::expansions(100_000)) {
            Ok(plan) => {
                let path = plan.path;
                let end = path.end().unwrap_or(start);
                prop_assert!((end.translation.vector - goal.translation.vector).norm() < 1e-6);
                prop_assert!(heading_gap(end.rotation.angle(), goal.rotation.angle()) < 1e-6);
                // No stretch of no length (a cusp of no motion).
                prop_assert!(path.stretches.iter().all(|s| s.length > 1e-9 * TURNING_RADIUS));
                for pair in path.stretches.windows(2) {
                    let joint = pair[0].pose_at(pair[0].length, TURNING_RADIUS);
                    prop_assert!((joint.translation.vector - pair[1].start.translation.vector).norm() < 1e-6);
                    prop_assert!(heading_gap(joint.rotation.angle(), pair[1].start.rotation.angle()) < 1e-6);
                }
                let step = RESOLUTION / 8.0;
                let poses = path.sample(step);
                for (pose, _) in &poses {
                    prop_assert!(car_free(&world, pose), "{:?} hits", pose);
                }
                // Between two poses a chord c apart, the heading turns by at most the arc of
                // the turning circle on that chord, 2 asin(c / 2r).
                for pair in poses.windows(2) {
                    let chord = (pair[1].0.translation.vector - pair[0].0.translation.vector).norm();
                    let turned = heading_gap(pair[1].0.rotation.angle(), pair[0].0.rotation.angle());
                    let most = 2.0 * (chord / (2.0 * TURNING_RADIUS)).min(1.0).asin();
                    prop_assert!(turned <= most + 1e-9, "turned {} over a chord of {}", turned, chord);
                }
                prop_assert!(path.cost <= plan.stats.search_cost * (1.0 + 1e-12));
            }
            Err(CarError::NoPath { .. }) => {}
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

fn car() -> Footprint {
    Footprint::Polygon(Polygon::new(CAR.iter().map(|c| Point::new(c[0], c[1])).collect()).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, max_global_rejects: 100_000, ..ProptestConfig::default() })]

    /// The exact polygon check of the world's checker agrees with the test written here, at
    /// random poses (touching, where the two differ, has probability zero).
    #[test]
    fn the_checker_places_the_car_as_the_exact_test_does((world, _, _) in world(), seed in any::<u64>()) {
        let checker = world.checker();
        let mut state = seed | 1;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..200 {
            let pose = Pose::new(nalgebra::Vector2::new(next() * SIZE.0, next() * SIZE.1), next() * 6.3);
            let corners: Vec<Point> = CAR.iter().map(|c| pose * Point::new(c[0], c[1])).collect();
            prop_assert_eq!(checker.polygon_is_free(&corners), car_free(&world, &pose), "{:?}", pose);
        }
    }

    /// RRT-Connect in the Reeds-Shepp space with the car's rectangle: every pose of every path,
    /// every 0.01 along its curves, keeps the car off the polygons by the exact test here.
    #[test]
    fn sampling_planners_keep_the_rectangle_off_the_polygons((world, e, _) in world()) {
        let space = ReedsShepp::new(world.bounds(), TURNING_RADIUS).unwrap();
        let validity = FootprintValidity::new(&world, &car(), &space, RESOLUTION / 2.0).unwrap();
        let tau = std::f64::consts::TAU;
        let start = Pose::new(nalgebra::Vector2::new(e[0] * SIZE.0, e[1] * SIZE.1), e[2] * tau);
        let goal = Pose::new(nalgebra::Vector2::new(e[3] * SIZE.0, e[4] * SIZE.1), e[5] * tau);
        prop_assume!(car_free(&world, &start) && car_free(&world, &goal));
        let problem = Problem::new(&space, &validity, start, goal);
        let nearest = KdNearest::<ReedsShepp, 2>::new(&space).unwrap();
        let plan = RrtConnect::new(nearest).with_seed(e[5].to_bits()).solve(&problem, &Termination::iterations(3000)).unwrap();
        if let Some(path) = plan.path() {
            prop_assert!(path.first() == Some(&start) && path.last() == Some(&goal));
            for m in path.windows(2) {
                for pose in space.path(&m[0], &m[1]).sample(0.01).unwrap() {
                    prop_assert!(car_free(&world, &pose), "{:?} hits", pose);
                }
            }
        }
    }
}

#[test]
fn a_polygon_world_refuses_resolutions_that_are_not_cell_widths() {
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap(), Vec::new(), 0.0).unwrap();
    for resolution in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        match CarMap::from_world(&world, resolution) {
            Err(CarError::Map(_)) => {}
            other => panic!("{resolution}: {other:?}"),
        }
    }
    // Too fine: more cells than the bound, refused before anything is allocated.
    for resolution in [1e-9, 10.0 / 4097.0] {
        match CarMap::from_world(&world, resolution) {
            Err(CarError::Setting { setting: "resolution", .. }) => {}
            other => panic!("{resolution}: {other:?}"),
        }
    }
    assert!(CarMap::from_world(&world, 10.0 / 4096.0).is_ok());
    // Cells past the bounds are obstacles: a 10 m world of 3 m cells has four columns, the
    // last beyond the bounds.
    let map = CarMap::from_world(&world, 3.0).unwrap();
    assert_eq!(map.size(), (4, 4));
}
