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
use crate::predicates::{on_segment, orient};
use crate::world::checker::point_segment_distance;
use crate::world::{Polygon, PolygonError};

/// The most vertices a footprint polygon may have. A robot's outline has a handful (Nav2's
/// examples four to eight); every pose a planner checks places each of them, so a longer
/// outline is refused before it is read rather than slowing every check.
pub const MAX_FOOTPRINT_VERTICES: usize = 1024;

/// How far a footprint checked at poses `step` apart along a car's curves must be grown so that
/// the poses between two checked ones are covered too: between two poses `step` apart along an
/// arc of radius `turning_radius`, a point `reach` from the reference point moves at most
/// `step (1 + reach / turning_radius)`, so a pose in between is within half of that of one of
/// them. Hybrid A* and the car spaces' footprint validities grow their checks by it.
pub fn sweep_margin(step: f64, reach: f64, turning_radius: f64) -> f64 {
    0.5 * step * (1.0 + reach / turning_radius)
}

/// The robot's shape about its reference point (the point whose pose a planner plans), in the
/// robot's frame: x forward, y to the left. Serialized as `{"radius": r}` or
/// `{"polygon": [[x, y], ...]}` (Nav2's `robot_radius` and `footprint`); a polygon read from a
/// document has at most [`MAX_FOOTPRINT_VERTICES`] vertices.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Footprint {
    /// A disc of this radius centred on the reference point.
    Radius(f64),
    /// A simple polygon (checked when made: see [`Polygon::new`]); see
    /// [`Footprint::polygon`] for one checked against [`MAX_FOOTPRINT_VERTICES`] too.
    Polygon(#[serde(deserialize_with = "outline")] Polygon),
}

/// Why a footprint cannot be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FootprintError {
    /// The radius is negative, NaN or infinite.
    #[error("a footprint radius must be finite and not negative, got {0}")]
    Radius(f64),
    /// More vertices than [`MAX_FOOTPRINT_VERTICES`].
    #[error("a footprint polygon has at most {max} vertices, this one has {count}", max = MAX_FOOTPRINT_VERTICES)]
    TooManyVertices {
        /// The vertices given.
        count: usize,
    },
    /// The outline is not a simple polygon.
    #[error("{0}")]
    Polygon(#[from] PolygonError),
}

/// Reads a footprint polygon, its vertices counted before they are checked.
fn outline<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<Polygon, D::Error> {
    checked_outline(Vec::<[f64; 2]>::deserialize(deserializer)?).map_err(serde::de::Error::custom)
}

/// The polygon of `corners`, counted first.
fn checked_outline(corners: Vec<[f64; 2]>) -> Result<Polygon, FootprintError> {
    if corners.len() > MAX_FOOTPRINT_VERTICES {
        return Err(FootprintError::TooManyVertices { count: corners.len() });
    }
    Ok(Polygon::try_from(corners)?)
}

impl Footprint {
    /// A polygon footprint from its corners `[x, y]` in the robot's frame (either orientation):
    /// at most [`MAX_FOOTPRINT_VERTICES`] of them, counted before anything else is checked,
    /// making a simple polygon ([`Polygon::new`]).
    ///
    /// ```
    /// use trailmark_core::footprint::{Footprint, FootprintError};
    ///
    /// let car = Footprint::polygon(vec![[-0.2, -0.3], [1.0, -0.3], [1.0, 0.3], [-0.2, 0.3]])?;
    /// assert!((car.inscribed_radius()? - 0.2).abs() < 1e-12);
    /// let long = (0..5000).map(|i| { let a = i as f64 / 5000.0 * std::f64::consts::TAU; [a.cos(), a.sin()] });
    /// assert!(matches!(Footprint::polygon(long.collect()), Err(FootprintError::TooManyVertices { count: 5000 })));
    /// # Ok::<(), FootprintError>(())
    /// ```
    pub fn polygon(corners: Vec<[f64; 2]>) -> Result<Footprint, FootprintError> {
        checked_outline(corners).map(Footprint::Polygon)
    }

    /// Checks a footprint made in code: a radius finite and not negative, a polygon of at most
    /// [`MAX_FOOTPRINT_VERTICES`] vertices.
    pub fn check(&self) -> Result<(), FootprintError> {
        match self {
            Footprint::Radius(r) => check_radius(*r).map(|_| ()),
            Footprint::Polygon(polygon) if polygon.vertices().len() > MAX_FOOTPRINT_VERTICES => {
                Err(FootprintError::TooManyVertices { count: polygon.vertices().len() })
            }
            Footprint::Polygon(_) => Ok(()),
        }
    }

    /// The radius of the largest circle about the reference point inside the footprint: the
    /// radius itself, or for a polygon the least distance from the reference point to an edge
    /// when the reference point lies inside it, and 0 when it does not (a forklift planned by
    /// the tip of its forks, a trailer by its hitch). Nav2's `calculateMinAndMaxDistances`
    /// takes the distance to the nearest edge there too, a circle that is not inside the
    /// robot: a costmap inflated by it blocks cells the robot's reference point may reach, and
    /// a heuristic that closes them proves reachable goals unreachable.
    ///
    /// Errors: a negative or non-finite radius.
    ///
    /// ```
    /// use trailmark_core::footprint::Footprint;
    /// use trailmark_core::world::Polygon;
    ///
    /// // A 1 m square whose reference point is 0.5 m behind it.
    /// let ahead = Polygon::try_from(vec![[0.5, -0.5], [1.5, -0.5], [1.5, 0.5], [0.5, 0.5]])?;
    /// assert_eq!(Footprint::Polygon(ahead).inscribed_radius()?, 0.0);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn inscribed_radius(&self) -> Result<f64, FootprintError> {
        match self {
            Footprint::Radius(r) => check_radius(*r),
            Footprint::Polygon(polygon) if !polygon.contains_strictly(Point::origin()) => Ok(0.0),
            Footprint::Polygon(polygon) => Ok(polygon
                .edges()
                .map(|(a, b)| point_segment_distance(Point::origin(), a, b))
                .fold(f64::INFINITY, f64::min)),
        }
    }

    /// Whether the reference point lies in the footprint, inside or on its outline: then a
    /// free footprint never has its reference point over an obstacle. A disc holds its centre.
    pub fn holds_reference_point(&self) -> bool {
        match self {
            Footprint::Radius(_) => true,
            Footprint::Polygon(polygon) => {
                let o = Point::origin();
                polygon.contains_strictly(o)
                    || polygon.edges().any(|(a, b)| orient(a, b, o) == 0.0 && on_segment(a, b, o))
            }
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
    fn a_reference_point_outside_the_polygon_has_no_inscribed_circle() {
        // The nearest edge is 0.5 away, but no circle about the origin lies inside the square.
        let ahead = Footprint::polygon(vec![[0.5, -0.5], [1.5, -0.5], [1.5, 0.5], [0.5, 0.5]]).unwrap();
        assert_eq!(ahead.inscribed_radius().unwrap(), 0.0);
        // On an edge: 0 as well.
        let on_edge = Footprint::polygon(vec![[0.0, -0.5], [1.0, -0.5], [1.0, 0.5], [0.0, 0.5]]).unwrap();
        assert_eq!(on_edge.inscribed_radius().unwrap(), 0.0);
        assert!(!ahead.holds_reference_point());
        assert!(on_edge.holds_reference_point());
        assert!(rectangle().holds_reference_point());
        assert!(Footprint::Radius(0.0).holds_reference_point());
    }

    #[test]
    fn long_outlines_are_refused_before_they_are_checked() {
        let ring = |n: usize| -> Vec<[f64; 2]> {
            (0..n).map(|i| i as f64 / n as f64 * std::f64::consts::TAU).map(|a| [a.cos(), a.sin()]).collect()
        };
        assert!(Footprint::polygon(ring(MAX_FOOTPRINT_VERTICES)).is_ok());
        let count = 100_000;
        assert_eq!(Footprint::polygon(ring(count)), Err(FootprintError::TooManyVertices { count }));
        let json = serde_json::json!({ "polygon": ring(count) }).to_string();
        let read = serde_json::from_str::<Footprint>(&json).unwrap_err().to_string();
        assert!(read.contains("at most 1024 vertices, this one has 100000"), "{read}");
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
