//! Poses of a car that turns no tighter than a radius: distances and motions along Dubins
//! curves.

use std::f64::consts::PI;
use std::fmt::Debug;

use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use trailmark_core::dubins::{DubinsPath, check_extent};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::Bounds;

use super::{
    SpaceError, StateSpace, UnitCube, area, clamp_pose, diagonal, in_bounds, place, planar, pose_at,
    sample_pose, unit_pose,
};

/// Poses of a car that only drives forward and turns no tighter than `turning_radius`: the
/// distance from `a` to `b` is the length of the shortest Dubins path (not symmetric), and
/// motions follow it. Saved as `{"bounds", "turning_radius"}`, checked on loading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "DubinsDocument", into = "DubinsDocument")]
pub struct Dubins {
    bounds: Bounds,
    turning_radius: f64,
}

impl Dubins {
    /// The poses over `bounds` for a car with this turning radius.
    pub fn new(bounds: Bounds, turning_radius: f64) -> Result<Self, SpaceError> {
        if !(turning_radius.is_finite() && turning_radius > 0.0) {
            return Err(SpaceError::NotPositive { what: "turning radius", value: turning_radius });
        }
        // Every two poses in the bounds must be within the Dubins solver's supported range.
        let diagonal = (bounds.max() - bounds.min()).norm();
        check_extent(turning_radius, diagonal)?;
        Ok(Dubins { bounds, turning_radius })
    }

    /// The turning radius.
    pub fn turning_radius(&self) -> f64 {
        self.turning_radius
    }

    /// The bounds of the positions.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// The shortest Dubins path from `a` to `b`.
    ///
    /// # Panics
    ///
    /// If a pose is not finite or lies so far outside the bounds that the two are more than
    /// [`MAX_NORMALISED_DISTANCE`](trailmark_core::dubins::MAX_NORMALISED_DISTANCE) turning radii apart ([`new`](Self::new) guarantees the range
    /// for poses in the bounds, which is where the planners' validity checks keep states).
    pub fn path(&self, a: &Pose, b: &Pose) -> DubinsPath {
        DubinsPath::shortest(a, b, self.turning_radius).expect("a valid radius and finite poses")
    }
}

impl StateSpace for Dubins {
    type State = Pose;
    const SYMMETRIC: bool = false;

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
        DubinsPath::shortest_length(a, b, self.turning_radius).unwrap_or(f64::INFINITY)
    }

    fn interpolate(&self, a: &Pose, b: &Pose, t: f64) -> Pose {
        let path = self.path(a, b);
        if t >= 1.0 {
            return *b;
        }
        path.pose_at((path.length() * t.max(0.0)).min(path.length())).unwrap_or(*b)
    }

    fn extent(&self) -> f64 {
        // Any two poses are joined by a turn, a straight line and a turn of at most a circle each.
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

impl UnitCube for Dubins {
    fn state_from_unit(&self, unit: &[f64]) -> Pose {
        unit_pose(&self.bounds, unit)
    }
}

/// A saved [`Dubins`].
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct DubinsDocument {
    bounds: Bounds,
    turning_radius: f64,
}

impl TryFrom<DubinsDocument> for Dubins {
    type Error = SpaceError;
    fn try_from(d: DubinsDocument) -> Result<Self, SpaceError> {
        Dubins::new(d.bounds, d.turning_radius)
    }
}

impl From<Dubins> for DubinsDocument {
    fn from(s: Dubins) -> Self {
        DubinsDocument { bounds: s.bounds, turning_radius: s.turning_radius }
    }
}
