//! Geometry types of the public API.
//!
//! trailmark speaks nalgebra at its boundaries: positions are [`Point2<f64>`], displacements
//! [`Vector2<f64>`], rigid poses [`Isometry2<f64>`]. Lengths are in the world's units and angles
//! in radians, counter-clockwise from the +x axis.
//!
//! The nalgebra types are re-exported here (nalgebra 0.35), so a caller names them without a
//! version-matched dependency of their own.

pub use nalgebra::{Isometry2, Point2, SVector, Vector2};

/// A position in the plane, in world units.
pub type Point = Point2<f64>;

/// A displacement in the plane, in world units.
pub type Vector = Vector2<f64>;

/// A rigid pose in the plane: translation in world units, rotation in radians.
pub type Pose = Isometry2<f64>;
