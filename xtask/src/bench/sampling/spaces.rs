//! The sampling section's other state spaces: RRT-Connect for a car (Dubins: forward only;
//! Reeds-Shepp: forward and in reverse) on two of the section's polygon worlds, and for a 3-link
//! planar arm in its joint space (the scene of `examples/arm.rs`).
//!
//! Car paths are re-checked twice: each motion's curve exactly (its arcs and segment against
//! the grown obstacles), and the poses every 1e-3 along it by the point test, which also checks
//! that the heading never turns faster than the turning radius allows. Arm paths are re-checked
//! every 1e-3 rad of any joint with the true arm (no clearance). A path that fails, or that
//! does not start and end where asked, is an error that fails the run.

use std::f64::consts::PI;
use std::time::Instant;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::geometry::{Point, Pose, Vector};
use trailmark::core::termination::Termination;
use trailmark::core::world::{Bounds, CollisionChecker, PolygonWorld};
use trailmark::sample::arm::{ArmChecker, PlanarArm, densify};
use trailmark::sample::space::{Car, CarCurves};
use trailmark::sample::{KdNearest, Plan, Planner, Problem, Rn, RrtConnect, RrtOptions, Sampled, StateSpace};

use crate::bench::sampling::tally::{ConnectStats, ConnectTally};
use crate::bench::sampling::world::{PlaneQuery, SamplingWorld};

/// The worlds where RRT-Connect also plans for a Dubins car.
pub const DUBINS_WORLDS: [&str; 2] = ["convex-30", "bug-trap"];
/// The Dubins car's turning radius.
pub const TURNING_RADIUS: f64 = 1.0;
/// The iteration limit of every run.
const ITERATIONS: u64 = 10_000;
/// The step of the sampled re-checks: world units along a Dubins curve, radians of any joint.
const RECHECK_STEP: f64 = 1e-3;
/// Arm motions are checked every `ARM_RESOLUTION` x the joint space's extent.
const ARM_RESOLUTION: f64 = 1e-3;
/// The arm's RRT-Connect range, radians (as in the example).
const ARM_RANGE: f64 = 0.5;

/// RRT-Connect in one state space on one world.
#[derive(Debug, Clone, Serialize)]
pub struct SpaceRow {
    /// `dubins`, `reeds_shepp` or `arm`.
    pub space: &'static str,
    /// The world.
    pub world: String,
    /// Seeded queries run.
    pub queries: usize,
    /// What RRT-Connect did; costs are over a lower bound (Dubins: the disc robot's shortest
    /// path in the plane; arm: the straight line in joint space).
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

/// RRT-Connect for the car of the curves `C` (`space` its name) on `w`'s queries that have a
/// path for the disc robot, each end given a seeded heading from which the car can drive a full
/// circle (so neither end is a pose it cannot leave or reach, such as facing a wall at less than
/// its turning radius).
pub fn bench_car<C: CarCurves>(
    w: &SamplingWorld,
    queries: &[PlaneQuery],
    seed: u64,
    space_name: &'static str,
) -> Result<SpaceRow, String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {space_name}: {e}", w.name);
    let space = Car::<C>::new(w.world.bounds(), TURNING_RADIUS).map_err(|e| err(&e))?;
    let nearest = KdNearest::<Car<C>, 2>::new(&space).map_err(|e| err(&e))?;
    let limit = Termination::iterations(ITERATIONS);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xd0b1);
    let mut tally = ConnectTally::default();
    for (i, &(a, b, best)) in queries.iter().enumerate() {
        let Some(best) = best else { continue };
        let mut pose = |p: Point| {
            let mut draws = (0..100).map(|_| Pose::new(p.coords, rng.random_range(-PI..PI)));
            draws.find(|pose| can_circle(&w.checker, pose))
        };
        let (Some(a), Some(b)) = (pose(a), pose(b)) else { continue };
        let problem = Problem::new(&space, &w.checker, a, b);
        let clock = Instant::now();
        let plan = RrtConnect::new(nearest.clone())
            .with_seed(seed + i as u64)
            .solve(&problem, &limit)
            .map_err(|e| err(&e))?;
        let ms = clock.elapsed().as_secs_f64() * 1e3;
        add(&mut tally, &plan, ms, best, |path| {
            let ends = path.first() == Some(&a) && path.last() == Some(&b);
            let mut cost = 0.0;
            for m in path.windows(2) {
                let curve = space.path(&m[0], &m[1]);
                if !(C::is_free(&w.checker, &curve)
                    && sampled_free(&w.checker, &C::sample(&curve, RECHECK_STEP)?))
                {
                    return None;
                }
                cost += C::path_length(&curve);
            }
            ends.then_some(cost)
        });
    }
    Ok(SpaceRow { space: space_name, world: w.name.clone(), queries: tally.solvable, stats: tally.stats() })
}

/// Whether the car at `pose` can drive a full circle of the turning radius to its left or to
/// its right (points every 0.01 rad free): a filter for queries, not a check of paths.
fn can_circle(checker: &CollisionChecker, pose: &Pose) -> bool {
    let (p, heading) = (Point::from(pose.translation.vector), pose.rotation.angle());
    [1.0, -1.0].iter().any(|side| {
        let centre = p + side * TURNING_RADIUS * Vector::new(-heading.sin(), heading.cos());
        (0..629).all(|k| {
            let a = k as f64 * 0.01;
            checker.point_is_free(centre + TURNING_RADIUS * Vector::new(a.cos(), a.sin()))
        })
    })
}

/// Whether every pose is free by the point test and the heading turns by at most
/// `RECHECK_STEP / TURNING_RADIUS` between consecutive poses (which are at most
/// `RECHECK_STEP` apart along the curve).
fn sampled_free(checker: &CollisionChecker, poses: &[Pose]) -> bool {
    let turn = RECHECK_STEP / TURNING_RADIUS * (1.0 + 1e-9) + 1e-12;
    poses.iter().all(|p| checker.point_is_free(Point::from(p.translation.vector)))
        && poses.windows(2).all(|m| (m[0].rotation.inverse() * m[1].rotation).angle().abs() <= turn)
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
        "### RRT-Connect in other state spaces ({ITERATIONS} iterations at most)\n\n\
         - **Dubins** and **Reeds-Shepp**: a car of turning radius {TURNING_RADIUS} (forward only, or in reverse \
         too) on the worlds above, on the queries that have a \
         path for the disc robot, with seeded headings from which the car can drive a full circle (a query is \
         skipped when 100 headings at an end give none); motions are the shortest curves checked exactly (arcs and \
         segments against the grown obstacles). Cost is over the disc robot's shortest path in the plane, a \
         lower bound. Some queries may have no path for the car.\n\
         - **Arm**: the 3-link arm of `examples/arm.rs` (links 2.5, 2, 1.5, radius 0.15, among a shelf, a post \
         and a hanging block), between seeded pairs of free configurations; motions checked every {ARM_RESOLUTION} \
         of the joint space's extent with the links grown to make that safe, range {ARM_RANGE} rad. Cost is \
         over the straight line in joint space.\n\
         - Re-checks: the cars' curves exactly and every {RECHECK_STEP} by the point test with the turning rate \
         bounded; arm paths every {RECHECK_STEP} rad of any joint with the true arm.\n\n\
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
