//! What a valid world is: the limits on its numbers, and the errors that name what broke them.

use thiserror::Error;

/// Why a polygon is not a valid obstacle.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum PolygonError {
    /// A vertex has a NaN or infinite coordinate.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinite {
        /// Index of the vertex.
        vertex: usize,
    },
    /// A vertex has a coordinate larger in magnitude than [`MAX_COORDINATE`].
    #[error("vertex {vertex} has a coordinate beyond +-{max:e}, the largest a world supports", max = MAX_COORDINATE)]
    OutOfRange {
        /// Index of the vertex.
        vertex: usize,
    },
    /// Fewer than three distinct vertices (after dropping repeats of the previous vertex).
    #[error("a polygon needs at least three distinct vertices, this one has {count}")]
    TooFewVertices {
        /// The number of distinct vertices.
        count: usize,
    },
    /// All vertices on one line.
    #[error("the polygon has zero area")]
    ZeroArea,
    /// Two edges cross or touch (other than consecutive edges at their shared vertex).
    #[error("edges {first} and {second} intersect: the polygon is not simple")]
    SelfIntersecting {
        /// Index of the first edge (edge i joins vertex i to vertex i + 1).
        first: usize,
        /// Index of the second edge.
        second: usize,
    },
}

/// Why a world is not valid.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum WorldError {
    /// The bounds are not a finite rectangle of positive area.
    #[error(
        "bounds [{xmin:?}, {ymin:?}, {xmax:?}, {ymax:?}] must be finite with xmin < xmax and ymin < ymax"
    )]
    InvalidBounds {
        /// Left.
        xmin: f64,
        /// Bottom.
        ymin: f64,
        /// Right.
        xmax: f64,
        /// Top.
        ymax: f64,
    },
    /// The bounds have a coordinate beyond [`MAX_COORDINATE`] in magnitude, or a side shorter
    /// than [`MIN_RELATIVE_SIDE`] times their largest coordinate (or than [`MIN_SIDE`]): the
    /// polygon operations could not resolve such a world.
    #[error(
        "bounds [{xmin:?}, {ymin:?}, {xmax:?}, {ymax:?}] are outside the supported range: coordinates within +-{max:e}, each side at least {side:e} and at least {rel:e} times the largest coordinate",
        max = MAX_COORDINATE, side = MIN_SIDE, rel = MIN_RELATIVE_SIDE
    )]
    BoundsOutOfRange {
        /// Left.
        xmin: f64,
        /// Bottom.
        ymin: f64,
        /// Right.
        xmax: f64,
        /// Top.
        ymax: f64,
    },
    /// The robot radius is negative or not finite.
    #[error("robot radius {0:?} must be finite and non-negative")]
    InvalidRadius(f64),
    /// The robot radius is larger than [`MAX_COORDINATE`].
    #[error("robot radius {0:e} is beyond {max:e}, the largest a world supports", max = MAX_COORDINATE)]
    RadiusOutOfRange(f64),
    /// The angle step for round corners is outside `(0, PI/2]`.
    #[error("arc step {0} must lie in (0, PI/2]")]
    InvalidArcStep(f64),
    /// An obstacle is not a valid polygon.
    #[error("obstacle {index}: {error}")]
    Obstacle {
        /// Index of the obstacle.
        index: usize,
        /// What is wrong with it.
        error: PolygonError,
    },
    /// An obstacle to remove is not there.
    #[error("there is no obstacle {index} (the world has {count})")]
    NoSuchObstacle {
        /// The index asked for.
        index: usize,
        /// The number of obstacles.
        count: usize,
    },
}

/// The largest coordinate magnitude (of bounds, obstacle vertices and the robot radius) a
/// world accepts. Exact predicates hold at any magnitude, but the polygon operations that grow
/// and merge obstacles round to a fixed-point grid and lose obstacles beyond about 1e12; 1e9
/// (a million kilometres in metres, a thousand in millimetres) keeps a wide margin.
pub const MAX_COORDINATE: f64 = 1e9;

/// The shortest side the bounds may have, in absolute terms.
pub const MIN_SIDE: f64 = 1e-6;

/// The shortest side the bounds may have relative to their largest coordinate magnitude: the
/// free space is resolved to 2^-20 of the bounds' larger side, which must stay far above the
/// spacing of `f64` values at the bounds' coordinates (about 2.2e-16 times their magnitude).
pub const MIN_RELATIVE_SIDE: f64 = 1e-7;

/// Whether `v` is within the magnitude a world supports.
pub(super) fn in_range(v: f64) -> bool {
    v.abs() <= MAX_COORDINATE
}
