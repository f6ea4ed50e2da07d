//! A planar arm of `N` revolute joints among polygons, planned in its joint space
//! ([`Rn<N>`](crate::space::Rn)): forward kinematics, and exact tests of whole configurations.
//!
//! The links are capsules (segments between the joints, with a radius). A configuration is
//! free when every joint stays inside the workspace, no link touches an obstacle (the
//! workspace's exact segment test against the obstacles grown by the link radius), and no two
//! links that do not share a joint touch each other (parry2d capsules).
//!
//! Motions in joint space are checked by sampling ([`Sampled`](crate::validity::Sampled)). Between
//! two checked states no point of the arm moves further than the step times
//! [`PlanarArm::max_speed`], so an [`ArmChecker`] built with the links grown by
//! [`PlanarArm::clearance`] makes every state between two checked ones free for the true arm.
//!
//! ```
//! use std::f64::consts::PI;
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::arm::{ArmChecker, PlanarArm};
//! use trailmark_sample::{KdNearest, Planner, Problem, Rn, RrtConnect, Sampled};
//! use trailmark_core::termination::Termination;
//!
//! // A 3-link arm on the floor of a 10 x 6 room with a post to reach over.
//! let post = vec![Point::new(7.0, 0.0), Point::new(7.5, 0.0), Point::new(7.5, 2.0), Point::new(7.0, 2.0)];
//! let room = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 6.0)?, vec![post], 0.0)?;
//! let arm = PlanarArm::new(Point::new(5.0, 0.0), [2.5, 2.0, 1.5], 0.15)?;
//! let space = Rn::new([-PI; 3], [PI; 3])?;
//! let resolution = 1e-3;
//! let checker = ArmChecker::new(arm, &room, arm.clearance(&space, resolution))?;
//! let validity = Sampled::new(|q: &_| checker.is_free(q), resolution)?;
//! let (start, goal) = ([2.6, -0.5, -0.5].into(), [1.0, -0.7, -1.5].into());
//! let problem = Problem::new(&space, &validity, start, goal);
//! let mut planner = RrtConnect::new(KdNearest::<Rn<3>, 3>::new(&space)?).with_seed(1);
//! let plan = planner.solve(&problem, &Termination::iterations(20_000))?;
//! let path = plan.path().expect("a path");
//! // The hand ends beyond the post, above the floor.
//! let hand = arm.joints(&path[path.len() - 1])[2];
//! assert!(hand.x > 7.5 && hand.y > 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::SVector;
use parry2d_f64::math::{Pose2, Vector2};
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::Capsule;
use thiserror::Error;
use trailmark_core::geometry::{Point, Vector};
use trailmark_core::world::{Bounds, CollisionChecker, PolygonWorld, WorldError};

use crate::space::{Rn, StateSpace};

/// Why an arm or its checker could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ArmError {
    /// The base is not a finite point.
    #[error("the base must be a finite point, got ({0}, {1})")]
    InvalidBase(f64, f64),
    /// A link length is not positive and finite.
    #[error("link {index} must have a positive finite length, got {length}")]
    InvalidLength {
        /// The link, from the base out.
        index: usize,
        /// Its length.
        length: f64,
    },
    /// The link radius is negative or not finite.
    #[error("the link radius must be finite and at least 0, got {0}")]
    InvalidRadius(f64),
    /// The clearance is negative or not finite.
    #[error("the clearance must be finite and at least 0, got {0}")]
    InvalidClearance(f64),
    /// The workspace, shrunk by the clearance or with the obstacles grown, is not valid.
    #[error(transparent)]
    World(#[from] WorldError),
}

/// A planar arm of `N` revolute joints with its base fixed; its configurations are the joint
/// angles in radians, the first measured from the +x axis and each other relative to the link
/// before.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarArm<const N: usize> {
    base: Point,
    lengths: [f64; N],
    radius: f64,
}

impl<const N: usize> PlanarArm<N> {
    /// An arm whose first joint is at `base`, with links of `lengths` (from the base out), each
    /// a capsule of `radius`.
    pub fn new(base: Point, lengths: [f64; N], radius: f64) -> Result<Self, ArmError> {
        if !(base.x.is_finite() && base.y.is_finite()) {
            return Err(ArmError::InvalidBase(base.x, base.y));
        }
        if let Some((index, &length)) =
            lengths.iter().enumerate().find(|(_, l)| !(l.is_finite() && **l > 0.0))
        {
            return Err(ArmError::InvalidLength { index, length });
        }
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(ArmError::InvalidRadius(radius));
        }
        Ok(PlanarArm { base, lengths, radius })
    }

    /// Where the first joint is.
    pub fn base(&self) -> Point {
        self.base
    }

    /// The link lengths, from the base out.
    pub fn lengths(&self) -> [f64; N] {
        self.lengths
    }

    /// The links' radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Forward kinematics: the far end of each link at `q` (the last is the hand). Link `i`
    /// runs from the end of link `i - 1` (the base for link 0) to `joints(q)[i]`.
    pub fn joints(&self, q: &SVector<f64, N>) -> [Point; N] {
        let mut heading = 0.0;
        let mut at = self.base;
        std::array::from_fn(|i| {
            heading += q[i];
            at += self.lengths[i] * Vector::new(heading.cos(), heading.sin());
            at
        })
    }

    /// The most any point of the arm moves per unit of joint-space (Euclidean) distance: joint
    /// `i` swings points at most `lengths[i] + ... + lengths[N - 1]` away from it, and by
    /// Cauchy-Schwarz the sum over the joints is at most the norm of those lever arms times the
    /// distance.
    pub fn max_speed(&self) -> f64 {
        let mut reach = 0.0;
        let mut sum = 0.0;
        for length in self.lengths.iter().rev() {
            reach += length;
            sum += reach * reach;
        }
        f64::sqrt(sum)
    }

    /// The clearance that makes motions checked every `resolution` x `space`'s extent (as
    /// [`Sampled`](crate::validity::Sampled) checks them) safe: half the step times
    /// [`PlanarArm::max_speed`], the furthest any point of the arm gets from both checked
    /// states around it.
    pub fn clearance(&self, space: &Rn<N>, resolution: f64) -> f64 {
        0.5 * resolution * space.extent() * self.max_speed()
    }
}

/// Exact tests of whole configurations of a [`PlanarArm`] in a workspace, with every link grown
/// by a clearance.
#[derive(Debug, Clone)]
pub struct ArmChecker<const N: usize> {
    arm: PlanarArm<N>,
    /// The obstacles grown by the link radius plus the clearance.
    obstacles: CollisionChecker,
    /// The region the joints must stay in: the workspace shrunk by the clearance.
    inner: Bounds,
    /// The link radius plus the clearance.
    thickness: f64,
}

impl<const N: usize> ArmChecker<N> {
    /// Tests of `arm` among `workspace`'s obstacles (its robot radius is ignored: the links'
    /// radius plus `clearance` is used instead) and inside its bounds shrunk by `clearance`.
    pub fn new(arm: PlanarArm<N>, workspace: &PolygonWorld, clearance: f64) -> Result<Self, ArmError> {
        if !(clearance.is_finite() && clearance >= 0.0) {
            return Err(ArmError::InvalidClearance(clearance));
        }
        let thickness = arm.radius + clearance;
        let obstacles = workspace.obstacles().iter().map(|o| o.vertices().to_vec()).collect();
        let obstacles = PolygonWorld::new(workspace.bounds(), obstacles, thickness)?.checker();
        let (lo, hi) = (workspace.bounds().min(), workspace.bounds().max());
        let inner = Bounds::new(lo.x + clearance, lo.y + clearance, hi.x - clearance, hi.y - clearance)?;
        Ok(ArmChecker { arm, obstacles, inner, thickness })
    }

    /// The arm tested.
    pub fn arm(&self) -> &PlanarArm<N> {
        &self.arm
    }

    /// Whether the arm at `q` keeps its joints in the workspace and touches neither an obstacle
    /// nor itself.
    pub fn is_free(&self, q: &SVector<f64, N>) -> bool {
        let ends = self.arm.joints(q);
        let start = |i: usize| if i == 0 { self.arm.base } else { ends[i - 1] };
        ends.iter().all(|&p| self.inner.contains(p))
            && (0..N).all(|i| self.obstacles.segment_is_free(start(i), ends[i]))
            && (0..N).all(|i| (i + 2..N).all(|j| !self.links_touch([start(i), ends[i]], [start(j), ends[j]])))
    }

    /// Whether two links, as parry2d capsules of the grown thickness, touch.
    fn links_touch(&self, [a, b]: [Point; 2], [c, d]: [Point; 2]) -> bool {
        let capsule =
            |p: Point, q: Point| Capsule::new(Vector2::new(p.x, p.y), Vector2::new(q.x, q.y), self.thickness);
        let here = Pose2::IDENTITY;
        // Capsule-capsule is always supported; an unsupported pair counts as touching.
        intersection_test(&here, &capsule(a, b), &here, &capsule(c, d)).map_or(true, |hit| hit.intersecting)
    }
}

/// The states along `path` in `space`, each motion cut so that no joint turns more than `step`
/// from one state to the next (the ends of every motion included): for re-checking a path
/// finely.
pub fn densify<const N: usize>(space: &Rn<N>, path: &[SVector<f64, N>], step: f64) -> Vec<SVector<f64, N>> {
    let Some(&first) = path.first() else { return Vec::new() };
    let mut states = vec![first];
    for m in path.windows(2) {
        let n = ((m[1] - m[0]).amax() / step).ceil().max(1.0) as usize;
        states.extend((1..=n).map(|i| space.interpolate(&m[0], &m[1], i as f64 / n as f64)));
    }
    states
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arm() -> PlanarArm<3> {
        PlanarArm::new(Point::new(5.0, 0.0), [2.5, 2.0, 1.5], 0.15).expect("valid")
    }

    #[test]
    fn forward_kinematics_of_known_poses() {
        let arm = arm();
        // Straight up: the joints stack on the base's vertical.
        let up = arm.joints(&SVector::from([std::f64::consts::FRAC_PI_2, 0.0, 0.0]));
        for (p, y) in up.iter().zip([2.5, 4.5, 6.0]) {
            assert!((p.x - 5.0).abs() < 1e-12 && (p.y - y).abs() < 1e-12, "{p:?}");
        }
        // Right, then a quarter turn left at each joint: (7.5, 0), (7.5, 2), (6, 2).
        let q = SVector::from([0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2]);
        let expected = [Point::new(7.5, 0.0), Point::new(7.5, 2.0), Point::new(6.0, 2.0)];
        for (p, e) in arm.joints(&q).iter().zip(expected) {
            assert!((p - e).norm() < 1e-12, "{p:?} != {e:?}");
        }
    }

    #[test]
    fn max_speed_bounds_the_motion_of_every_joint() {
        use rand::{RngExt, SeedableRng};
        let arm = arm();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for _ in 0..1000 {
            let q = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(-3.0..3.0));
            let dq = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(-1e-3..1e-3));
            let (before, after) = (arm.joints(&q), arm.joints(&(q + dq)));
            let worst = before.iter().zip(after).map(|(a, b)| (b - a).norm()).fold(0.0, f64::max);
            // First order in dq, so allow the second-order remainder.
            assert!(worst <= arm.max_speed() * dq.norm() * (1.0 + 1e-2), "{worst} > {}", arm.max_speed());
        }
    }

    #[test]
    fn checks_obstacles_bounds_and_self_contact() {
        let bounds = Bounds::new(0.0, 0.0, 10.0, 5.0).expect("bounds");
        let room = PolygonWorld::new(bounds, vec![], 0.0).expect("world");
        let checker = ArmChecker::new(arm(), &room, 0.0).expect("checker");
        let reaching = SVector::from([1.2, -0.5, -0.5]);
        assert!(checker.is_free(&reaching));
        // Straight up, the hand is at y = 6, above the room.
        assert!(!checker.is_free(&SVector::from([std::f64::consts::FRAC_PI_2, 0.0, 0.0])));
        // Folded back on itself: link 3 lies along link 1.
        assert!(!checker.is_free(&SVector::from([1.2, std::f64::consts::PI, std::f64::consts::PI])));
        let post =
            vec![Point::new(6.0, 0.0), Point::new(6.5, 0.0), Point::new(6.5, 1.0), Point::new(6.0, 1.0)];
        let checker =
            ArmChecker::new(arm(), &PolygonWorld::new(bounds, vec![post], 0.0).expect("world"), 0.0)
                .expect("checker");
        // Low across the floor, link 1 runs into the post.
        assert!(!checker.is_free(&SVector::from([0.2, 0.0, 0.0])));
        assert!(checker.is_free(&reaching));
    }

    #[test]
    fn bad_arms_are_errors() {
        let at = Point::new(0.0, 0.0);
        assert_eq!(
            PlanarArm::new(at, [1.0, 0.0], 0.1),
            Err(ArmError::InvalidLength { index: 1, length: 0.0 })
        );
        assert!(matches!(PlanarArm::new(at, [f64::NAN], 0.1), Err(ArmError::InvalidLength { index: 0, .. })));
        assert_eq!(PlanarArm::new(at, [1.0], -0.1), Err(ArmError::InvalidRadius(-0.1)));
        assert!(matches!(
            PlanarArm::new(Point::new(f64::INFINITY, 0.0), [1.0], 0.1),
            Err(ArmError::InvalidBase(..))
        ));
        let room =
            PolygonWorld::new(Bounds::new(0.0, 0.0, 1.0, 1.0).expect("bounds"), vec![], 0.0).expect("world");
        let arm = PlanarArm::new(at, [1.0], 0.1).expect("valid");
        assert_eq!(ArmChecker::new(arm, &room, -1.0).err(), Some(ArmError::InvalidClearance(-1.0)));
        // Shrunk by 0.6 on each side, a unit square has no interior.
        assert!(matches!(ArmChecker::new(arm, &room, 0.6), Err(ArmError::World(_))));
    }
}
