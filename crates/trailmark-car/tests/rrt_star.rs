//! Hybrid A* beside RRT* in the Reeds-Shepp space, on Nav2's depot map, the same car and the
//! same footprint checks: every query RRT* solves in 10 s, Hybrid A* solves, and its path is at
//! most 10% longer than the best RRT* finds in 10 s (the penalties set to 1 and the cells priced
//! alike, so that both minimise length). Heavy: run with
//! `cargo test --release -p trailmark-car --test rrt_star -- --ignored --nocapture`.

use std::time::Duration;

mod common;

use common::{TURNING_RADIUS, data, footprint, random_pose};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use trailmark_car::{CarMap, HybridAStar, HybridOptions};
use trailmark_core::geometry::Pose;
use trailmark_core::termination::Termination;
use trailmark_core::world::Bounds;
use trailmark_map::{Costmap, CostmapOptions, Inflation, TravelCost, load_map};
use trailmark_sample::{KdNearest, Planner, Problem, ReedsShepp, RrtStar, StateSpace, Validity};

/// The car on the map, as Hybrid A* checks it: states by its footprint check, motions by that
/// check every half cell along the Reeds-Shepp curve.
struct OnMap<'a> {
    planner: &'a HybridAStar<'a>,
    step: f64,
}

impl Validity<ReedsShepp> for OnMap<'_> {
    fn state_is_valid(&self, _: &ReedsShepp, s: &Pose) -> bool {
        self.planner.is_free(s)
    }

    fn motion_is_valid(&self, space: &ReedsShepp, a: &Pose, b: &Pose) -> bool {
        let n = (space.distance(a, b) / self.step).ceil().clamp(1.0, 1e5) as usize;
        (0..=n).all(|i| self.planner.is_free(&space.interpolate(a, b, i as f64 / n as f64)))
    }
}

#[test]
#[ignore = "heavy: 10 s of RRT* per query"]
fn hybrid_astar_solves_what_rrt_star_solves_and_its_length_beside_rrt_stars() {
    let Some(dir) = data() else { return };
    let car = footprint();
    let map = load_map(dir.join("depot.yaml")).unwrap();
    let settings =
        CostmapOptions { inflation: Some(Inflation::around(&car).unwrap()), ..CostmapOptions::default() };
    let costmap = Costmap::from_occupancy(&map, &settings).unwrap();
    // Every free cell priced alike: both planners minimise length.
    let flat = TravelCost { factor: 0.0, ..TravelCost::default() };
    let car_map = CarMap::from_costmap(&costmap, &flat).unwrap();
    let hybrid = HybridOptions {
        turning_radius: TURNING_RADIUS,
        reverse_penalty: 1.0,
        non_straight_penalty: 1.0,
        ..HybridOptions::default()
    };
    let planner = HybridAStar::new(&car_map, &car, hybrid).unwrap();
    let frame = costmap.frame();
    let (w, h) =
        (f64::from(frame.width()) * frame.resolution(), f64::from(frame.height()) * frame.resolution());
    let bounds = Bounds::new(0.0, 0.0, w, h).unwrap();
    let space = ReedsShepp::new(bounds, TURNING_RADIUS).unwrap();
    let validity = OnMap { planner: &planner, step: frame.resolution() / 2.0 };
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut ratios = Vec::new();
    for q in 0..6 {
        let start = random_pose(&costmap, &planner, &mut rng, false);
        let goal = random_pose(&costmap, &planner, &mut rng, q % 2 == 1);
        let problem = Problem::new(&space, &validity, start, goal);
        let mut rrt_star = RrtStar::new(KdNearest::<ReedsShepp, 2>::new(&space).unwrap()).with_seed(q);
        let sampled = rrt_star.solve(&problem, &Termination::time(Duration::from_secs(10))).unwrap();
        let found = planner.plan(&start, &goal, &Termination::time(Duration::from_secs(10)));
        match (sampled.cost(), &found) {
            (Some(best), Ok(plan)) => {
                let ratio = plan.path.length() / best;
                println!(
                    "query {q}: Hybrid A* {:.2} m in {:.0} ms, RRT* best {best:.2} m in 10 s: {ratio:.3}",
                    plan.path.length(),
                    plan.stats.time.as_secs_f64() * 1e3
                );
                ratios.push(ratio);
            }
            (Some(best), Err(e)) => panic!("query {q}: RRT* found {best:.2} m, Hybrid A*: {e}"),
            (None, Ok(plan)) => {
                println!("query {q}: Hybrid A* {:.2} m, RRT* none in 10 s", plan.path.length())
            }
            (None, Err(e)) => println!("query {q}: neither ({e})"),
        }
    }
    ratios.sort_by(f64::total_cmp);
    println!("Hybrid A* length / RRT* best: {ratios:.3?}");
    // Issue 28's bound: within 10% of the best RRT* finds in 10 s.
    assert!(ratios.iter().all(|&r| r <= 1.10), "{ratios:?}");
    assert!(ratios.len() >= 4, "{} queries solved by both", ratios.len());
}
