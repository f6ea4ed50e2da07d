//! The robot's shape about its reference point: a disc, or a simple polygon (a car's rectangle
//! with its rear axle off centre, a forklift with its forks). The costmaps' inflation asks it
//! for its inscribed radius; the car planners place it at every pose they check.
//!
//! ```
//! use trailmark_core::footprint::Footprint;
//! use trailmark_core::geometry::{Point, Pose};
//! use trailmark_core::world::Polygon;
//!
//! // A 1.2 m x 0.6 m car whose reference point is the middle of its rear axle, 0.2 m from the back.
//! let car = Polygon::new(vec![
//!     Point::new(-0.2, -0.3), Point::new(1.0, -0.3), Point::new(1.0, 0.3), Point::new(-0.2, 0.3),
//! ])?;
//! let footprint = Footprint::Polygon(car);
//! assert!((footprint.inscribed_radius()? - 0.2).abs() < 1e-12);
//! assert!((footprint.circumscribed_radius()? - (1.0f64 + 0.09).sqrt()).abs() < 1e-12);
//! // Facing +y at (5, 5): the front corners are at y = 6.
//! let corners = footprint.corners_at(&Pose::new(nalgebra::Vector2::new(5.0, 5.0), std::f64::consts::FRAC_PI_2));
//! assert!(corners.iter().filter(|p| (p.y - 6.0).abs() < 1e-12).count() == 2);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::geometry::{Point, Pose};
use crate::world::Polygon;
use crate::world::checker::point_segment_distance;

/// The robot's shape about its reference point (the point whose pose a planner plans), in the
/// robot's frame: x forward, y to the left. Serialized as `{"radius": r}` or
/// `{"polygon": [[x, y], ...]}` (Nav2's `robot_radius` and `footprint`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Footprint {
    /// A disc of this radius centred on the reference point.
    Radius(f64),
    /// A simple polygon (checked when made: see [`Polygon::new`]).
    Polygon(Polygon),
}

/// Why a footprint cannot be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FootprintError {
    /// The radius is negative, NaN or infinite.
    #[error("a footprint radius must be finite and not negative, got {0}")]
    Radius(f64),
}

impl Footprint {
    /// The radius of the largest circle about the reference point inside the footprint: the
    /// radius itself, or for a polygon the least distance from the reference point to an edge
    /// (as Nav2's `calculateMinAndMaxDistances`, which also takes the distance to the nearest
    /// edge when the reference point lies outside the polygon).
    ///
    /// Errors: a negative or non-finite radius.
    pub fn inscribed_radius(&self) -> Result<f64, FootprintError> {
        match self {
            Footprint::Radius(r) => check_radius(*r),
            Footprint::Polygon(polygon) => Ok(polygon
                .edges()
                .map(|(a, b)| point_segment_distance(Point::origin(), a, b))
                .fold(f64::INFINITY, f64::min)),
        }
    }

    /// The radius of the smallest circle about the reference point holding the footprint: the
    /// farthest any part of the robot gets from its reference point as it turns in place.
    ///
    /// Errors: a negative or non-finite radius.
    pub fn circumscribed_radius(&self) -> Result<f64, FootprintError> {
        match self {
            Footprint::Radius(r) => check_radius(*r),
            Footprint::Polygon(polygon) => {
                Ok(polygon.vertices().iter().map(|p| p.coords.norm()).fold(0.0, f64::max))
            }
        }
    }

    /// The polygon's corners with the robot at `pose` (counter-clockwise); empty for a disc.
    pub fn corners_at(&self, pose: &Pose) -> Vec<Point> {
        match self {
            Footprint::Radius(_) => Vec::new(),
            Footprint::Polygon(polygon) => polygon.vertices().iter().map(|p| pose * p).collect(),
        }
    }
}

fn check_radius(r: f64) -> Result<f64, FootprintError> {
    if r.is_finite() && r >= 0.0 { Ok(r) } else { Err(FootprintError::Radius(r)) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rectangle() -> Footprint {
        let points = [[-0.3, -0.2], [0.5, -0.2], [0.5, 0.2], [-0.3, 0.2]];
        Footprint::Polygon(Polygon::new(points.iter().map(|p| Point::new(p[0], p[1])).collect()).unwrap())
    }

    #[test]
    fn radii_of_a_rectangle_about_an_off_centre_point() {
        assert!((rectangle().inscribed_radius().unwrap() - 0.2).abs() < 1e-12);
        let far = (0.5f64 * 0.5 + 0.2 * 0.2).sqrt();
        assert!((rectangle().circumscribed_radius().unwrap() - far).abs() < 1e-12);
        assert_eq!(Footprint::Radius(0.22).inscribed_radius().unwrap(), 0.22);
    }

    #[test]
    fn bad_radii_are_errors() {
        for r in [-1.0, f64::NAN, f64::INFINITY] {
            assert!(Footprint::Radius(r).inscribed_radius().is_err());
            assert!(Footprint::Radius(r).circumscribed_radius().is_err());
        }
    }

    #[test]
    fn documents_read_both_shapes_and_check_polygons() {
        let disc: Footprint = serde_json::from_str(r#"{"radius": 0.3}"#).unwrap();
        assert_eq!(disc, Footprint::Radius(0.3));
        let poly: Footprint =
            serde_json::from_str(r#"{"polygon": [[-0.3, -0.2], [0.5, -0.2], [0.5, 0.2], [-0.3, 0.2]]}"#)
                .unwrap();
        assert_eq!(poly, rectangle());
        // A bow tie is not a simple polygon.
        let bow = serde_json::from_str::<Footprint>(r#"{"polygon": [[0, 0], [1, 1], [1, 0], [0, 1]]}"#);
        assert!(bow.is_err());
    }
}
