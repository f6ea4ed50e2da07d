//! Hybrid A* on the Nav2 example maps in `../shared/rosmaps`: seeded parking and corridor
//! queries for a car with a rectangular footprint. Every path is checked by code that shares
//! nothing with the planner's checks: the exact footprint at poses every 1/8 cell along the
//! path, each cell tested against the footprint's rectangle by separating axes; the curvature
//! between cusps from the sampled headings; the ends against the asked poses.
//!
//! Skipped with a message when the maps are absent. Planning times are printed (run with
//! `--nocapture`); the figures are in docs/car.md.

use std::time::Duration;

mod common;

use common::{TURNING_RADIUS, data, footprint, independently_free, random_pose};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use trailmark_car::{CarError, CarMap, CarPath, HybridAStar, HybridOptions};
use trailmark_core::geometry::Pose;
use trailmark_core::reeds_shepp::Gear;
use trailmark_core::termination::{Stop, Termination};
use trailmark_map::{Costmap, CostmapOptions, Inflation, load_map};

fn heading_gap(a: f64, b: f64) -> f64 {
    let d = (b - a).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// The checks every path passes; panics with the query on a failure.
fn check_path(costmap: &Costmap, path: &CarPath, start: &Pose, goal: &Pose, what: &str) {
    let res = costmap.frame().resolution();
    let first = path.start().unwrap();
    let last = path.end().unwrap();
    assert!((first.translation.vector - start.translation.vector).norm() < 1e-9, "{what}: start");
    assert!((last.translation.vector - goal.translation.vector).norm() < 1e-6, "{what}: end {last:?}");
    assert!(heading_gap(last.rotation.angle(), goal.rotation.angle()) < 1e-6, "{what}: end heading");
    // Stretches join end to start, position and heading.
    for pair in path.stretches.windows(2) {
        let end = pair[0].pose_at(pair[0].length, path.turning_radius);
        assert!((end.translation.vector - pair[1].start.translation.vector).norm() < 1e-9, "{what}: gap");
        assert!(heading_gap(end.rotation.angle(), pair[1].start.rotation.angle()) < 1e-9, "{what}: kink");
    }
    // Dense poses: the footprint free at every one, the curvature at most 1 / radius between
    // consecutive poses of one gear, cusps only where the gear changes (and then the car
    // stands: no turn without travel).
    let samples = path.sample(res / 8.0);
    for (pose, _) in &samples {
        assert!(independently_free(costmap, pose), "{what}: footprint hits at {pose:?}");
    }
    for pair in samples.windows(2) {
        let ((a, _), (b, gear)) = (pair[0], pair[1]);
        let ds = (b.translation.vector - a.translation.vector).norm();
        let turn = heading_gap(a.rotation.angle(), b.rotation.angle());
        // On an arc of the turning radius a chord `ds` turns the heading by 2 asin(ds / 2r).
        let most = 2.0 * (ds / (2.0 * TURNING_RADIUS)).min(1.0).asin();
        assert!(turn <= most * (1.0 + 1e-9) + 1e-12, "{what}: curvature {turn} over {ds}");
        // Moving in the direction of the heading forward, against it in reverse.
        if ds > 1e-9 {
            let heading = nalgebra::Vector2::new(a.rotation.angle().cos(), a.rotation.angle().sin());
            let along = (b.translation.vector - a.translation.vector).dot(&heading);
            match gear {
                Gear::Forward => assert!(along > 0.0, "{what}: forward stretch moving back"),
                Gear::Reverse => assert!(along < 0.0, "{what}: reverse stretch moving forward"),
            }
        }
    }
    let cusps = path.stretches.windows(2).filter(|w| w[0].gear != w[1].gear).count();
    assert_eq!(cusps, path.cusps().len());
}

fn quantile(sorted: &[f64], q: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

/// Plans `queries` seeded queries on the map `name` (half of them to a parked pose), checks
/// every path, prints the planning times, and asserts that at least `least` were solved.
fn queries_on(dir: &std::path::Path, name: &str, queries: usize, least: usize) {
    let car = footprint();
    let map = load_map(dir.join(format!("{name}.yaml"))).unwrap();
    let settings =
        CostmapOptions { inflation: Some(Inflation::around(&car).unwrap()), ..CostmapOptions::default() };
    let costmap = Costmap::from_occupancy(&map, &settings).unwrap();
    let car_map = CarMap::from_costmap(&costmap, &Default::default()).unwrap();
    let hybrid = HybridOptions { turning_radius: TURNING_RADIUS, ..HybridOptions::default() };
    let planner = HybridAStar::new(&car_map, &car, hybrid).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let (mut times, mut solved, mut unreachable, mut stopped, mut cusps) = (Vec::new(), 0, 0, 0, 0);
    // The costs before and after smoothing, and the smoothing's times.
    let (mut searched, mut smoothed, mut smoothing) = (0.0, 0.0, Vec::new());
    for q in 0..queries {
        let start = random_pose(&costmap, &planner, &mut rng, false);
        let goal = random_pose(&costmap, &planner, &mut rng, q % 2 == 0);
        let what = format!("{name} query {q}: {start:?} -> {goal:?}");
        let limit = Termination::time(Duration::from_secs(10));
        match planner.plan(&start, &goal, &limit) {
            Ok(plan) => {
                check_path(&costmap, &plan.path, &start, &goal, &what);
                times.push(plan.stats.time.as_secs_f64() * 1e3);
                cusps += plan.path.cusps().len();
                solved += 1;
                // Smoothing never makes a path dearer.
                assert!(plan.path.cost <= plan.stats.search_cost * (1.0 + 1e-12), "{what}");
                searched += plan.stats.search_cost;
                smoothed += plan.path.cost;
                smoothing.push(plan.stats.smoothing_time.as_secs_f64() * 1e3);
            }
            Err(CarError::NoPath { stop: Stop::Unreachable, .. }) => unreachable += 1,
            Err(CarError::NoPath { .. }) => stopped += 1,
            Err(e) => panic!("{what}: {e}"),
        }
    }
    times.sort_by(f64::total_cmp);
    smoothing.sort_by(f64::total_cmp);
    let (w, h) = (costmap.frame().width(), costmap.frame().height());
    println!(
        "{name} ({w} x {h} cells): {solved} solved, {unreachable} proven unreachable, {stopped} stopped at 10 s; \
         planning median {:.1} ms, 90th percentile {:.1} ms; {cusps} cusps; smoothing {:.1}% off the cost, \
         median {:.2} ms",
        quantile(&times, 0.5),
        quantile(&times, 0.9),
        100.0 * (1.0 - smoothed / searched),
        quantile(&smoothing, 0.5)
    );
    assert!(solved >= least, "{name}: only {solved} of {queries} solved");
    assert!(smoothed < searched, "{name}: smoothing shortened no path");
}

#[test]
fn hybrid_astar_paths_on_the_sandbox_and_the_depot_pass_an_independent_check() {
    let Some(dir) = data() else { return };
    queries_on(&dir, "tb3_sandbox", 12, 10);
    queries_on(&dir, "depot", 12, 10);
}

/// The warehouse: 1.7 million cells of 3 cm, queries of 20-50 m (about 30 s in all).
#[test]
#[ignore = "heavy: run with --release -- --ignored"]
fn hybrid_astar_paths_on_the_warehouse_pass_an_independent_check() {
    let Some(dir) = data() else { return };
    queries_on(&dir, "warehouse", 8, 6);
}
