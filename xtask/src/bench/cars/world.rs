//! The car section's worlds (random convex obstacles, a bug trap, walls with doors, all 40 x 40
//! with a disc robot), their seeded pose queries, and the re-check every path planned in them
//! must pass.
//!
//! A path is re-checked by what no planner shares: its poses every [`RECHECK_STEP`] by the
//! exact point test against the obstacles grown by the robot's radius, the heading turning no
//! faster than the turning radius allows between them (the chord rule), and its ends exactly
//! where asked. Curves of the sampling planners and of OMPL are also checked exactly, arc by arc.

use std::f64::consts::PI;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::car::CarPath;
use trailmark::core::generate;
use trailmark::core::geometry::{Point, Pose, Vector};
use trailmark::core::reeds_shepp::Gear;
use trailmark::core::world::{CollisionChecker, PolygonWorld};
use trailmark::sample::space::CarCurves;

/// The side of the square worlds.
pub const SIZE: f64 = 40.0;
/// The robot's radius.
pub const ROBOT_RADIUS: f64 = 0.25;
/// The car's turning radius.
pub const TURNING_RADIUS: f64 = 1.0;
/// The re-checks' step along a path.
pub const RECHECK_STEP: f64 = 1e-3;

/// A world of the section.
pub struct CarWorld {
    /// Its name in the report.
    pub name: String,
    /// The obstacles, with the robot's radius.
    pub world: PolygonWorld,
    /// The exact checker of the robot.
    pub checker: CollisionChecker,
    /// Where every query starts, if not anywhere.
    start: Option<Point>,
}

/// The worlds: 30 random convex hexagons, a bug trap left from inside, three walls with doors.
pub fn worlds(seed: u64) -> Result<Vec<CarWorld>, String> {
    let e = |e: generate::GenerateError| e.to_string();
    let (trap, inside) = generate::bug_trap(SIZE, ROBOT_RADIUS).map_err(e)?;
    let world = |name: &str, world: PolygonWorld, start| CarWorld {
        name: name.into(),
        checker: world.checker(),
        world,
        start,
    };
    Ok(vec![
        world("convex-30", generate::convex_obstacles(SIZE, 30, 6, ROBOT_RADIUS, seed).map_err(e)?, None),
        world("bug-trap", trap, Some(inside)),
        world("doors-3", generate::narrow_passages(SIZE, 3, 3.0, ROBOT_RADIUS, seed).map_err(e)?, None),
    ])
}

impl CarWorld {
    /// `n` seeded queries: poses free for the robot (and for `also_free`, the other planners'
    /// own test) from which the car can drive a full circle, so that no end is a pose it cannot
    /// leave or reach, such as facing a wall closer than its turning radius.
    pub fn queries(&self, n: usize, seed: u64, also_free: impl Fn(&Pose) -> bool) -> Vec<(Pose, Pose)> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let pose_at = |p: Point, rng: &mut ChaCha8Rng| {
            (0..100)
                .map(|_| Pose::new(p.coords, rng.random_range(-PI..PI)))
                .find(|pose| self.can_circle(pose) && also_free(pose))
        };
        let mut out = Vec::with_capacity(n);
        for _ in 0..100 * n {
            if out.len() == n {
                break;
            }
            let point =
                |rng: &mut ChaCha8Rng| Point::new(rng.random_range(0.0..SIZE), rng.random_range(0.0..SIZE));
            let a = self.start.unwrap_or_else(|| point(&mut rng));
            let b = point(&mut rng);
            if let (Some(a), Some(b)) = (pose_at(a, &mut rng), pose_at(b, &mut rng)) {
                out.push((a, b));
            }
        }
        out
    }

    /// Whether the car at `pose` can drive a full circle of the turning radius to its left or
    /// its right (points every 0.01 rad free): a filter for queries, not a check of paths.
    fn can_circle(&self, pose: &Pose) -> bool {
        let (p, heading) = (Point::from(pose.translation.vector), pose.rotation.angle());
        [1.0, -1.0].iter().any(|side| {
            let centre = p + side * TURNING_RADIUS * Vector::new(-heading.sin(), heading.cos());
            (0..629).all(|k| {
                let a = k as f64 * 0.01;
                self.checker.point_is_free(centre + TURNING_RADIUS * Vector::new(a.cos(), a.sin()))
            })
        })
    }

    /// Whether `poses`, at most [`RECHECK_STEP`] apart along a path, are all free and turn no
    /// tighter than the turning radius.
    fn poses_pass(&self, poses: &[Pose]) -> bool {
        poses.iter().all(|p| self.checker.point_is_free(Point::from(p.translation.vector)))
            && poses.windows(2).all(|m| {
                let chord = (m[1].translation.vector - m[0].translation.vector).norm();
                let turned = (m[0].rotation.inverse() * m[1].rotation).angle().abs();
                turned <= 2.0 * (chord / (2.0 * TURNING_RADIUS)).min(1.0).asin() + 1e-9
            })
    }

    /// The length and cusps of a Hybrid A* path from `a` to `b`, if it passes the re-check.
    pub fn check_car_path(&self, path: &CarPath, a: &Pose, b: &Pose) -> Option<(f64, usize)> {
        let end = path.end().unwrap_or(*a);
        let first = path.stretches.first().map_or(*a, |s| s.start);
        let joints =
            path.stretches.windows(2).all(|w| same(&w[0].pose_at(w[0].length, TURNING_RADIUS), &w[1].start));
        let poses: Vec<Pose> = path.sample(RECHECK_STEP).into_iter().map(|(p, _)| p).collect();
        (same(&first, a) && same(&end, b) && joints && self.poses_pass(&poses))
            .then(|| (path.length(), path.cusps().len()))
    }

    /// The length and cusps of a path of poses joined by the curves `C`, if every curve is
    /// free (exactly, and by the re-check) and the path runs from `a` to `b`. `cusps_of` gives
    /// the arc lengths where a curve changes gear: poses are taken there too, so that no two
    /// consecutive ones straddle a cusp, where the chord rule does not hold.
    pub fn check_curves<C: CarCurves>(
        &self,
        path: &[Pose],
        a: &Pose,
        b: &Pose,
        cusps_of: impl Fn(&C::Path) -> Vec<f64>,
    ) -> Option<(f64, usize)> {
        let ends = path.first().is_some_and(|p| same(p, a)) && path.last().is_some_and(|p| same(p, b));
        let mut length = 0.0;
        let mut poses = Vec::new();
        for m in path.windows(2) {
            let curve = C::path(&m[0], &m[1], TURNING_RADIUS)?;
            if !C::is_free(&self.checker, &curve) {
                return None;
            }
            let total = C::path_length(&curve);
            let n = (total / RECHECK_STEP).ceil() as usize;
            let mut at: Vec<f64> = (0..=n).map(|i| (i as f64 * RECHECK_STEP).min(total)).collect();
            at.extend(cusps_of(&curve));
            at.sort_by(f64::total_cmp);
            for s in at {
                poses.push(C::pose_along(&curve, s)?);
            }
            length += total;
        }
        (ends && self.poses_pass(&poses)).then(|| (length, cusps(&poses)))
    }
}

/// Whether two poses agree to 1e-6 in position and heading.
fn same(p: &Pose, q: &Pose) -> bool {
    (p.translation.vector - q.translation.vector).norm() < 1e-6
        && (p.rotation.inverse() * q.rotation).angle().abs() < 1e-6
}

/// A pose as the OMPL driver reads and prints it.
pub fn ompl_pose(p: &Pose) -> [f64; 3] {
    [p.translation.x, p.translation.y, p.rotation.angle()]
}

/// The changes of gear along `poses`: where the way the car moves, along its heading or
/// against it, turns over.
fn cusps(poses: &[Pose]) -> usize {
    let gears: Vec<Gear> = poses
        .windows(2)
        .filter_map(|m| {
            let moved = m[1].translation.vector - m[0].translation.vector;
            let heading = m[0].rotation * Vector::new(1.0, 0.0);
            let along = moved.dot(&heading);
            (moved.norm() > 1e-9).then_some(if along >= 0.0 { Gear::Forward } else { Gear::Reverse })
        })
        .collect();
    gears.windows(2).filter(|g| g[0] != g[1]).count()
}
