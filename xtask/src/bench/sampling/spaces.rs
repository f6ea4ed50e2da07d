//! The sampling section's other state spaces: RRT-Connect for a 3-link planar arm in its joint
//! space (the scene of `examples/arm.rs`); cars have their own section.
//!
//! Arm paths are re-checked every 1e-3 rad of any joint with the true arm (no clearance). A
//! path that fails, or that does not start and end where asked, is an error that fails the run.

use std::f64::consts::PI;
use std::time::Instant;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::core::world::{Bounds, PolygonWorld};
use trailmark::sample::arm::{ArmChecker, PlanarArm, densify};
use trailmark::sample::{KdNearest, Plan, Planner, Problem, Rn, RrtConnect, RrtOptions, Sampled, StateSpace};

use crate::bench::sampling::tally::{ConnectStats, ConnectTally};

/// The iteration limit of every run.
const ITERATIONS: u64 = 10_000;
/// The step of the sampled re-checks: radians of any joint.
const RECHECK_STEP: f64 = 1e-3;
/// Arm motions are checked every `ARM_RESOLUTION` x the joint space's extent.
const ARM_RESOLUTION: f64 = 1e-3;
/// The arm's RRT-Connect range, radians (as in the example).
const ARM_RANGE: f64 = 0.5;

/// RRT-Connect in one state space on one world.
#[derive(Debug, Clone, Serialize)]
pub struct SpaceRow {
    /// `arm`.
    pub space: &'static str,
    /// The world.
    pub world: String,
    /// Seeded queries run.
    pub queries: usize,
    /// What RRT-Connect did; costs are over a lower bound (the straight line in joint space).
    pub stats: ConnectStats,
}

/// Adds one run taking `ms` to `tally`; `checked` re-checks its path and returns its cost,
/// `None` when the path fails.
fn add<T>(
    tally: &mut ConnectTally,
    plan: &Plan<T>,
    ms: f64,
    bound: f64,
    checked: impl FnOnce(&[T]) -> Option<f64>,
) {
    let counts = (ms, plan.stats.iterations, plan.stats.collision_checks);
    let path = plan.path();
    tally.add(Some(bound), counts, path.is_some(), |_| path.and_then(checked));
}

/// The arm scene of `examples/arm.rs`: a 10 x 6 workspace with a shelf on the left, a post on
/// the right and a block hanging from the ceiling, and the arm standing in the middle of the
/// floor.
fn arm_scene() -> Result<(PolygonWorld, PlanarArm<3>), String> {
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| {
        vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
    };
    let obstacles = vec![rect(0.5, 3.0, 3.0, 3.6), rect(7.2, 0.0, 7.8, 2.5), rect(3.9, 3.3, 6.1, 6.0)];
    let bounds = Bounds::new(0.0, 0.0, 10.0, 6.0).map_err(|e| e.to_string())?;
    let workspace = PolygonWorld::new(bounds, obstacles, 0.0).map_err(|e| e.to_string())?;
    let arm = PlanarArm::new(Point::new(5.0, 0.0), [2.5, 2.0, 1.5], 0.15).map_err(|e| e.to_string())?;
    Ok((workspace, arm))
}

/// RRT-Connect for the arm between `n` seeded pairs of free configurations.
pub fn bench_arm(n: usize, seed: u64) -> Result<SpaceRow, String> {
    let err = |e: &dyn std::fmt::Display| format!("arm: {e}");
    let (workspace, arm) = arm_scene()?;
    let space = Rn::new([-PI; 3], [PI; 3]).map_err(|e| err(&e))?;
    let planning =
        ArmChecker::new(arm, &workspace, arm.clearance(&space, ARM_RESOLUTION)).map_err(|e| err(&e))?;
    let exact = ArmChecker::new(arm, &workspace, 0.0).map_err(|e| err(&e))?;
    let validity = Sampled::new(|q: &_| planning.is_free(q), ARM_RESOLUTION).map_err(|e| err(&e))?;
    let nearest = KdNearest::<Rn<3>, 3>::new(&space).map_err(|e| err(&e))?;
    let options = RrtOptions { range: Some(ARM_RANGE), ..RrtOptions::default() };
    let limit = Termination::iterations(ITERATIONS);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xa53);
    let mut free = || loop {
        let q = space.sample(&mut rng);
        if planning.is_free(&q) {
            return q;
        }
    };
    let mut tally = ConnectTally::default();
    for i in 0..n {
        let (a, b) = (free(), free());
        let problem = Problem::new(&space, &validity, a, b);
        let clock = Instant::now();
        let mut planner = RrtConnect::new(nearest.clone()).with_options(options).with_seed(seed + i as u64);
        let plan = planner.solve(&problem, &limit).map_err(|e| err(&e))?;
        let ms = clock.elapsed().as_secs_f64() * 1e3;
        let bound = space.distance(&a, &b);
        add(&mut tally, &plan, ms, bound, |path| {
            let ends = path.first() == Some(&a) && path.last() == Some(&b);
            let free = densify(&space, path, RECHECK_STEP).iter().all(|q| exact.is_free(q));
            let cost: f64 = path.windows(2).map(|m| space.distance(&m[0], &m[1])).sum();
            (ends && free).then_some(cost)
        });
    }
    Ok(SpaceRow { space: "arm", world: "arm-3-link".into(), queries: n, stats: tally.stats() })
}

/// The section's table.
pub fn markdown(rows: &[SpaceRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "### RRT-Connect for an arm ({ITERATIONS} iterations at most)\n\n\
         - **Arm**: the 3-link arm of `examples/arm.rs` (links 2.5, 2, 1.5, radius 0.15, among a shelf, a post \
         and a hanging block), between seeded pairs of free configurations; motions checked every {ARM_RESOLUTION} \
         of the joint space's extent with the links grown to make that safe, range {ARM_RANGE} rad. Cost is \
         over the straight line in joint space.\n\
         - Re-checks: every {RECHECK_STEP} rad of any joint with the true arm (cars: see the car section).\n\n\
         | space | world | queries | solved | median ms | median iterations | median checks | median cost / lower bound | invalid |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|\n"
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} ({:.1}%) | {:.3} | {:.0} | {:.0} | {:.3} | {} |\n",
            r.space,
            r.world,
            r.queries,
            r.stats.solved,
            100.0 * r.stats.solved as f64 / r.queries.max(1) as f64,
            r.stats.median_ms,
            r.stats.median_iterations,
            r.stats.median_checks,
            r.stats.median_cost_ratio,
            r.stats.invalid
        ));
    }
    s.push('\n');
    s
}
