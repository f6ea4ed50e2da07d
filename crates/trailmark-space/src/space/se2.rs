//! Poses in the plane: position and heading, with a weight on the heading.

use std::f64::consts::PI;
use std::fmt::Debug;

use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::Bounds;

use super::{
    SpaceError, StateSpace, UnitCube, angle_between, area, clamp_pose, diagonal, in_bounds, place, planar,
    pose_at, sample_pose, unit_pose,
};

/// Poses in a plane region (position and heading), as OMPL's SE(2): the distance is the
/// Euclidean distance of the positions plus `heading_weight` times the smaller angle between
/// the headings; motions move the position in a straight line and turn the heading the short
/// way round. Saved as `{"bounds", "heading_weight"}`, checked on loading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Se2Document", into = "Se2Document")]
pub struct Se2 {
    bounds: Bounds,
    heading_weight: f64,
}

impl Se2 {
    /// The poses over `bounds`, the heading weighted by 0.5 (OMPL's default).
    pub fn new(bounds: Bounds) -> Self {
        Se2 { bounds, heading_weight: 0.5 }
    }

    /// The poses over `bounds`, the heading weighted by `weight` (distance per radian).
    pub fn with_heading_weight(bounds: Bounds, weight: f64) -> Result<Self, SpaceError> {
        if !(weight.is_finite() && weight > 0.0) {
            return Err(SpaceError::NotPositive { what: "heading weight", value: weight });
        }
        Ok(Se2 { bounds, heading_weight: weight })
    }

    /// The bounds of the positions.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }
}

impl StateSpace for Se2 {
    type State = Pose;
    const SYMMETRIC: bool = true;

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
        (b.translation.vector - a.translation.vector).norm() + self.heading_weight * angle_between(a, b).abs()
    }

    fn interpolate(&self, a: &Pose, b: &Pose, t: f64) -> Pose {
        let p = a.translation.vector + (b.translation.vector - a.translation.vector) * t;
        let heading = a.rotation.angle() + angle_between(a, b) * t;
        Pose::new(p, heading)
    }

    fn extent(&self) -> f64 {
        diagonal(&self.bounds) + self.heading_weight * PI
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

impl UnitCube for Se2 {
    fn state_from_unit(&self, unit: &[f64]) -> Pose {
        unit_pose(&self.bounds, unit)
    }
}

/// A saved [`Se2`].
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Se2Document {
    bounds: Bounds,
    heading_weight: f64,
}

impl TryFrom<Se2Document> for Se2 {
    type Error = SpaceError;
    fn try_from(d: Se2Document) -> Result<Self, SpaceError> {
        Se2::with_heading_weight(d.bounds, d.heading_weight)
    }
}

impl From<Se2> for Se2Document {
    fn from(s: Se2) -> Self {
        Se2Document { bounds: s.bounds, heading_weight: s.heading_weight }
    }
}
