//! Poses of a car that turns no tighter than a radius, with distances and motions along the
//! shortest curves of one family: Dubins curves (forward only) or Reeds-Shepp curves (forward
//! and in reverse).

use std::f64::consts::PI;
use std::fmt::Debug;

use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use trailmark_core::dubins::{DubinsPath, check_extent};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::reeds_shepp::ReedsSheppPath;
use trailmark_core::world::{Bounds, CollisionChecker};

use super::{
    SpaceError, StateSpace, UnitCube, area, clamp_pose, diagonal, in_bounds, place, planar, pose_at,
    sample_pose, unit_pose,
};

/// A family of shortest car curves between two poses: what a [`Car`] space measures and moves
/// along.
pub trait CarCurves: Debug + Clone + Copy + PartialEq + Send + Sync + 'static {
    /// The shortest path of the family between two poses.
    type Path: Debug + Clone;
    /// Whether the distance from `a` to `b` is always the distance from `b` to `a`.
    const SYMMETRIC: bool;
    /// The shortest path from `a` to `b`, or `None` for poses out of the supported range.
    fn path(a: &Pose, b: &Pose, turning_radius: f64) -> Option<Self::Path>;
    /// The length of the shortest path alone, `None` as for [`CarCurves::path`].
    fn length(a: &Pose, b: &Pose, turning_radius: f64) -> Option<f64>;
    /// The path's length.
    fn path_length(path: &Self::Path) -> f64;
    /// The pose `s` world units along the path (`0 <= s <= length`).
    fn pose_along(path: &Self::Path, s: f64) -> Option<Pose>;
    /// Poses every `step` world units along the path, then its end (`None` for a step that is
    /// not positive and finite, or too many poses).
    fn sample(path: &Self::Path, step: f64) -> Option<Vec<Pose>>;
    /// Whether a disc robot following the path stays clear of a polygon world's obstacles,
    /// every arc and segment tested exactly.
    fn is_free(checker: &CollisionChecker, path: &Self::Path) -> bool;
}

/// Dubins curves: the car drives forward only, and the distance is not symmetric.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DubinsCurves;

impl CarCurves for DubinsCurves {
    type Path = DubinsPath;
    const SYMMETRIC: bool = false;

    fn path(a: &Pose, b: &Pose, r: f64) -> Option<DubinsPath> {
        DubinsPath::shortest(a, b, r).ok()
    }

    fn length(a: &Pose, b: &Pose, r: f64) -> Option<f64> {
        DubinsPath::shortest_length(a, b, r).ok()
    }

    fn path_length(path: &DubinsPath) -> f64 {
        path.length()
    }

    fn pose_along(path: &DubinsPath, s: f64) -> Option<Pose> {
        path.pose_at(s).ok()
    }

    fn sample(path: &DubinsPath, step: f64) -> Option<Vec<Pose>> {
        path.sample(step).ok()
    }

    fn is_free(checker: &CollisionChecker, path: &DubinsPath) -> bool {
        checker.dubins_is_free(path)
    }
}

/// Reeds-Shepp curves: the car drives forward and in reverse, and the distance is symmetric.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReedsSheppCurves;

impl CarCurves for ReedsSheppCurves {
    type Path = ReedsSheppPath;
    const SYMMETRIC: bool = true;

    fn path(a: &Pose, b: &Pose, r: f64) -> Option<ReedsSheppPath> {
        ReedsSheppPath::shortest(a, b, r).ok()
    }

    fn length(a: &Pose, b: &Pose, r: f64) -> Option<f64> {
        ReedsSheppPath::shortest_length(a, b, r).ok()
    }

    fn path_length(path: &ReedsSheppPath) -> f64 {
        path.length()
    }

    fn pose_along(path: &ReedsSheppPath, s: f64) -> Option<Pose> {
        path.pose_at(s).ok()
    }

    fn sample(path: &ReedsSheppPath, step: f64) -> Option<Vec<Pose>> {
        path.sample(step).ok()
    }

    fn is_free(checker: &CollisionChecker, path: &ReedsSheppPath) -> bool {
        checker.reeds_shepp_is_free(path)
    }
}

/// Poses of a car that turns no tighter than `turning_radius`: the distance from `a` to `b` is
/// the length of the shortest curve of the family `C` ([`Dubins`]: forward only, not
/// symmetric; [`ReedsShepp`]: forward and in reverse), and motions follow it. Saved as
/// `{"bounds", "turning_radius"}`, checked on loading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "CarDocument", into = "CarDocument")]
#[serde(bound = "")]
pub struct Car<C: CarCurves> {
    bounds: Bounds,
    turning_radius: f64,
    #[serde(skip)]
    curves: std::marker::PhantomData<C>,
}

/// Poses of a car that only drives forward, along Dubins curves.
pub type Dubins = Car<DubinsCurves>;

/// Poses of a car that drives forward and in reverse, along Reeds-Shepp curves.
pub type ReedsShepp = Car<ReedsSheppCurves>;

impl<C: CarCurves> Car<C> {
    /// The poses over `bounds` for a car with this turning radius.
    pub fn new(bounds: Bounds, turning_radius: f64) -> Result<Self, SpaceError> {
        if !(turning_radius.is_finite() && turning_radius > 0.0) {
            return Err(SpaceError::NotPositive { what: "turning radius", value: turning_radius });
        }
        // Every two poses in the bounds must be within the solvers' supported range (the same
        // for both families).
        let diagonal = (bounds.max() - bounds.min()).norm();
        check_extent(turning_radius, diagonal)?;
        Ok(Car { bounds, turning_radius, curves: std::marker::PhantomData })
    }

    /// The turning radius.
    pub fn turning_radius(&self) -> f64 {
        self.turning_radius
    }

    /// The bounds of the positions.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// The shortest curve from `a` to `b`.
    ///
    /// # Panics
    ///
    /// If a pose is not finite or lies so far outside the bounds that the two are more than
    /// [`MAX_NORMALISED_DISTANCE`](trailmark_core::dubins::MAX_NORMALISED_DISTANCE) turning
    /// radii apart ([`new`](Self::new) guarantees the range for poses in the bounds, which is
    /// where the planners' validity checks keep states).
    pub fn path(&self, a: &Pose, b: &Pose) -> C::Path {
        C::path(a, b, self.turning_radius).expect("a valid radius and finite poses")
    }
}

// The bounds, samples and coordinates of poses are `Se2`'s (the shared helpers of `mod.rs`);
// the trait's shells around them look alike.
impl<C: CarCurves> StateSpace for Car<C> {
    type State = Pose;
    const SYMMETRIC: bool = C::SYMMETRIC;

    fn dimension(&self) -> usize {
        3
    }

    fn satisfies_bounds(&self, s: &Pose) -> bool {
        // A unit complex heading is in range by construction; a NaN one is not finite.
        in_bounds(&self.bounds, &place(s)) && s.rotation.re.is_finite() && s.rotation.im.is_finite()
    }

    fn enforce_bounds(&self, s: &mut Pose) {
        clamp_pose(&self.bounds, s);
    }

    fn sample(&self, rng: &mut ChaCha8Rng) -> Pose {
        sample_pose(&self.bounds, rng)
    }

    fn distance(&self, a: &Pose, b: &Pose) -> f64 {
        C::length(a, b, self.turning_radius).unwrap_or(f64::INFINITY)
    }

    fn interpolate(&self, a: &Pose, b: &Pose, t: f64) -> Pose {
        let path = self.path(a, b);
        if t >= 1.0 {
            return *b;
        }
        let length = C::path_length(&path);
        C::pose_along(&path, (length * t.max(0.0)).min(length)).unwrap_or(*b)
    }

    fn extent(&self) -> f64 {
        // Any two poses are joined by a turn, a straight line and a turn of at most a circle
        // each (a Reeds-Shepp path is never longer than that Dubins path).
        diagonal(&self.bounds) + 4.0 * PI * self.turning_radius
    }

    fn measure(&self) -> f64 {
        area(&self.bounds) * 2.0 * PI
    }

    fn coordinates(&self, s: &Pose) -> Vec<f64> {
        vec![s.translation.x, s.translation.y, s.rotation.angle()]
    }

    fn state_from_coordinates(&self, c: &[f64]) -> Option<Pose> {
        pose_at(c)
    }

    fn position<const D: usize>(&self, s: &Pose) -> Option<[f64; D]> {
        planar(Point::from(s.translation.vector))
    }
}

impl<C: CarCurves> UnitCube for Car<C> {
    fn state_from_unit(&self, unit: &[f64]) -> Pose {
        unit_pose(&self.bounds, unit)
    }
}

/// A saved [`Car`] space.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct CarDocument {
    bounds: Bounds,
    turning_radius: f64,
}

impl<C: CarCurves> TryFrom<CarDocument> for Car<C> {
    type Error = SpaceError;
    fn try_from(d: CarDocument) -> Result<Self, SpaceError> {
        Car::new(d.bounds, d.turning_radius)
    }
}

impl<C: CarCurves> From<Car<C>> for CarDocument {
    fn from(s: Car<C>) -> Self {
        CarDocument { bounds: s.bounds, turning_radius: s.turning_radius }
    }
}
