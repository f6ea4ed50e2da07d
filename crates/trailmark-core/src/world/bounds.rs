//! The bounds of a world: the rectangle the robot's centre stays in.

use serde::{Deserialize, Serialize};

use crate::geometry::Point;

use super::error::{MAX_COORDINATE, MIN_RELATIVE_SIDE, MIN_SIDE, WorldError};

/// An axis-aligned rectangle: the region the robot's centre must stay in. Serialized as
/// `[xmin, ymin, xmax, ymax]`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "[f64; 4]", into = "[f64; 4]")]
pub struct Bounds {
    pub(super) min: Point,
    pub(super) max: Point,
}

impl Bounds {
    /// The rectangle `[xmin, xmax] x [ymin, ymax]`; an error unless finite with positive area,
    /// and within the supported range: every coordinate within [`MAX_COORDINATE`], each side
    /// at least [`MIN_SIDE`] and at least [`MIN_RELATIVE_SIDE`] times the largest coordinate.
    pub fn new(xmin: f64, ymin: f64, xmax: f64, ymax: f64) -> Result<Self, WorldError> {
        let corners = [xmin, ymin, xmax, ymax];
        let finite = corners.iter().all(|v| v.is_finite());
        if !(finite && xmin < xmax && ymin < ymax) {
            return Err(WorldError::InvalidBounds { xmin, ymin, xmax, ymax });
        }
        let largest = corners.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let side = (xmax - xmin).min(ymax - ymin);
        if !(largest <= MAX_COORDINATE && side >= MIN_SIDE && side >= MIN_RELATIVE_SIDE * largest) {
            return Err(WorldError::BoundsOutOfRange { xmin, ymin, xmax, ymax });
        }
        Ok(Bounds { min: Point::new(xmin, ymin), max: Point::new(xmax, ymax) })
    }

    /// The lower-left corner.
    pub fn min(&self) -> Point {
        self.min
    }

    /// The upper-right corner.
    pub fn max(&self) -> Point {
        self.max
    }

    /// Whether `p` lies in the closed rectangle.
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }

    /// The four corners, counter-clockwise from the lower left.
    pub fn corners(&self) -> [Point; 4] {
        let (a, b) = (self.min, self.max);
        [a, Point::new(b.x, a.y), b, Point::new(a.x, b.y)]
    }
}

impl TryFrom<[f64; 4]> for Bounds {
    type Error = WorldError;

    fn try_from([xmin, ymin, xmax, ymax]: [f64; 4]) -> Result<Self, WorldError> {
        Bounds::new(xmin, ymin, xmax, ymax)
    }
}

impl From<Bounds> for [f64; 4] {
    fn from(b: Bounds) -> Self {
        [b.min.x, b.min.y, b.max.x, b.max.y]
    }
}
