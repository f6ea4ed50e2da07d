//! State spaces: where a sampling planner draws, measures and moves.
//!
//! A [`StateSpace`] samples states uniformly, measures the distance from one state to another
//! (possibly asymmetric: a car cannot reverse), interpolates between them, and steers from one
//! toward another by at most a step. Six are provided: [`R2`] (a point in the plane), [`Rn`]
//! (a box of any fixed dimension, such as an arm's joint angles), [`Joints`] (a robot's joints,
//! continuous ones wrapping around), [`Se2`] (a pose: position and
//! heading, with a weight on the heading), [`Dubins`] (a pose of a car that turns no tighter
//! than a radius: distances and motions along Dubins curves) and [`ReedsShepp`] (the same car
//! driving in reverse too, along Reeds-Shepp curves). Users implement the trait for their own
//! spaces.
//!
//! ```
//! use rand::SeedableRng;
//! use rand_chacha::ChaCha8Rng;
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::Bounds;
//! use trailmark_space::space::{R2, StateSpace};
//!
//! let space = R2::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?);
//! let (a, b) = (Point::new(1.0, 1.0), Point::new(7.0, 9.0));
//! assert_eq!(space.distance(&a, &b), 10.0);
//! assert_eq!(space.steer(&a, &b, 5.0), Point::new(4.0, 5.0)); // halfway, 5 units along
//! let mut rng = ChaCha8Rng::seed_from_u64(1);
//! assert!(space.bounds().contains(space.sample(&mut rng)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::f64::consts::PI;
use std::fmt::Debug;

use nalgebra::SVector;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use thiserror::Error;
use trailmark_core::dubins::RadiusOutOfScale;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::Bounds;

mod car;
mod ellipsoid;
mod joints;
mod r2;
mod rn;
mod se2;

pub use car::{Car, CarCurves, Dubins, DubinsCurves, ReedsShepp, ReedsSheppCurves};
pub use joints::Joints;
pub use r2::R2;
pub use rn::Rn;
pub use se2::Se2;

/// Why a space could not be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SpaceError {
    /// A box side with `low >= high`, a bound that is not finite, or a width beyond `f64`.
    #[error("axis {axis}: the bounds [{low}, {high}] must be finite with low < high and a finite width")]
    InvalidBounds {
        /// The axis.
        axis: usize,
        /// Its lower bound.
        low: f64,
        /// Its upper bound.
        high: f64,
    },
    /// An obstacle box of a box world with `low >= high` or a bound that is not finite.
    #[error("obstacle box {index}, axis {axis}: [{low}, {high}] must be finite with low < high")]
    InvalidBox {
        /// The box, counted from 0 in the order given.
        index: usize,
        /// The axis.
        axis: usize,
        /// Its lower bound.
        low: f64,
        /// Its upper bound.
        high: f64,
    },
    /// Bounds whose every side is finite but whose diagonal or volume is not (or whose volume
    /// underflows to 0: tiny sides in many dimensions): planners draw their step (a fifth of
    /// the diagonal) and their radii (from the volume) from them.
    #[error(
        "the bounds are too large or too small for f64: their diagonal ({diagonal:e}) must be finite and their volume ({volume:e}) finite and above 0"
    )]
    RegionTooLarge {
        /// The length of the bounds' diagonal.
        diagonal: f64,
        /// The product of their sides.
        volume: f64,
    },
    /// A nearest-neighbour structure over positions of a dimension the space does not have.
    #[error("the space's states have no position with {dimension} coordinates")]
    NoPosition {
        /// The dimension asked for.
        dimension: usize,
    },
    /// A turning radius out of the Dubins solver's supported range for the bounds.
    #[error(transparent)]
    TurningRadiusOutOfScale(#[from] RadiusOutOfScale),
    /// A weight or turning radius that is not positive and finite.
    #[error("the {what} must be positive and finite, got {value:?}")]
    NotPositive {
        /// What it is.
        what: &'static str,
        /// The value given.
        value: f64,
    },
}

/// The length of `v`, never 0 for a non-zero vector: the plain norm squares the coordinates,
/// which underflows to 0 below about 1e-154 (two distinct states at distance 0 had ended a
/// plan at a state that was not the goal); then the vector is scaled first.
#[inline]
fn separation<const N: usize>(v: &SVector<f64, N>) -> f64 {
    let d = v.norm();
    if d > 0.0 || v.iter().all(|&c| c == 0.0) {
        return d;
    }
    let largest = v.amax();
    largest * (v / largest).norm()
}

/// A space of states a sampling planner moves in.
pub trait StateSpace {
    /// A state.
    type State: Clone + Debug + PartialEq;

    /// Whether `distance(a, b) == distance(b, a)` for all states.
    const SYMMETRIC: bool;

    /// The number of coordinates of a state.
    fn dimension(&self) -> usize;

    /// Whether `state` is finite and inside the space's bounds (OMPL's `satisfiesBounds`).
    /// Planners refuse starts and goals that are not, and every state they return satisfies it.
    fn satisfies_bounds(&self, state: &Self::State) -> bool;

    /// Moves a finite `state` to the nearest state in the bounds, coordinate by coordinate
    /// (OMPL's `enforceBounds`); a state that is not finite is left as it is.
    fn enforce_bounds(&self, state: &mut Self::State);

    /// A state drawn uniformly from the space.
    fn sample(&self, rng: &mut ChaCha8Rng) -> Self::State;

    /// The distance (the cost of the motion) from `a` to `b`.
    fn distance(&self, a: &Self::State, b: &Self::State) -> f64;

    /// The state a fraction `t` in `[0, 1]` of the way along the motion from `a` to `b`.
    fn interpolate(&self, a: &Self::State, b: &Self::State, t: f64) -> Self::State;

    /// `to` when it is within `step` of `from`, else the state `step` along the motion toward it.
    fn steer(&self, from: &Self::State, to: &Self::State, step: f64) -> Self::State {
        let d = self.distance(from, to);
        if d <= step { to.clone() } else { self.interpolate(from, to, step / d) }
    }

    /// A state near `near`, for samplers that look for obstacles' surroundings (OMPL's
    /// `sampleGaussian`). By default: `steer` from `near` toward a uniform sample by a distance
    /// drawn from `|N(0, std_dev)|`, so any space has one. [`R2`] and [`Rn`] draw each
    /// coordinate from `N(near, std_dev)` and keep it in the bounds (clamped, as OMPL's
    /// `enforceBounds`): a sampler should meet obstacles, not the edge of the space.
    fn sample_near(&self, near: &Self::State, std_dev: f64, rng: &mut ChaCha8Rng) -> Self::State {
        let step = (std_dev * gaussian(rng)).abs();
        let toward = self.sample(rng);
        self.steer(near, &toward, step)
    }

    /// A state drawn uniformly from the *informed set* of a path from `a` to `b` no longer than
    /// `cost`: the states `x` with `distance(a, x) + distance(x, b) <= cost`, the only ones
    /// through which such a path can pass (Gammell et al.'s direct informed sampling, what
    /// Informed RRT* and BIT* draw from once they have a solution). The space's bounds are not
    /// applied: the caller refuses draws outside them. `None` where the space has no direct
    /// sampler (the default); the informed planners then draw uniform states and refuse those
    /// outside the set. [`R2`], [`Rn`] and [`Joints`] without wrapping joints draw from the
    /// ellipsoid with foci `a` and `b`.
    fn sample_informed(
        &self,
        a: &Self::State,
        b: &Self::State,
        cost: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<Self::State> {
        let _ = (a, b, cost, rng);
        None
    }

    /// The volume of that informed set, where [`sample_informed`](Self::sample_informed) draws
    /// from it (`None` otherwise): a planner draws directly only while it is smaller than the
    /// space's [`measure`](Self::measure), and uniformly with rejection before.
    fn informed_measure(&self, a: &Self::State, b: &Self::State, cost: f64) -> Option<f64> {
        let _ = (a, b, cost);
        None
    }

    /// The largest distance between two states (or a bound on it): a planner's default step is
    /// a fraction of it.
    fn extent(&self) -> f64;

    /// The volume of the space (the area of a plane region, times 2π for a heading): RRT*'s
    /// radius grows with it.
    fn measure(&self) -> f64;

    /// The coordinates of a state, for results and pictures.
    fn coordinates(&self, state: &Self::State) -> Vec<f64>;

    /// The state with these [`coordinates`](Self::coordinates), for loading saved states:
    /// `None` if they are not [`dimension`](Self::dimension) finite numbers, or if the space
    /// cannot build states from coordinates (the default). Bounds are not checked here.
    fn state_from_coordinates(&self, coordinates: &[f64]) -> Option<Self::State> {
        let _ = coordinates;
        None
    }

    /// A lower bound on `distance(a, b)` (and on `distance(b, a)`) from the positions only: the
    /// straight-line distance between `position(a)` and `position(b)` in `D` dimensions. What
    /// lets a k-d tree over positions answer exact nearest-neighbour queries.
    fn position<const D: usize>(&self, state: &Self::State) -> Option<[f64; D]>;
}

/// A space whose states are the image of the unit cube `[0, 1)^d` (`d` its
/// [`dimension`](StateSpace::dimension)): what lets a deterministic low-discrepancy sequence
/// such as [`Halton`](crate::sampler::Halton) cover it evenly.
pub trait UnitCube: StateSpace {
    /// The state at `unit` (`d` coordinates in `[0, 1)`): an affine map of each coordinate onto
    /// its bounds, so uniform points of the cube give uniform states.
    fn state_from_unit(&self, unit: &[f64]) -> Self::State;
}

/// The finite coordinates `c` if there are exactly `N`.
fn finite<const N: usize>(c: &[f64]) -> Option<[f64; N]> {
    let c: [f64; N] = c.try_into().ok()?;
    c.iter().all(|x| x.is_finite()).then_some(c)
}

/// The point at `unit` (at least two coordinates in `[0, 1)`) of `bounds`.
fn unit_point(bounds: &Bounds, unit: &[f64]) -> Point {
    let (lo, hi) = (bounds.min(), bounds.max());
    Point::new(lo.x + unit[0] * (hi.x - lo.x), lo.y + unit[1] * (hi.y - lo.y))
}

/// The pose at `unit` (three coordinates in `[0, 1)`) of `bounds`, the heading in `[-π, π)`.
fn unit_pose(bounds: &Bounds, unit: &[f64]) -> Pose {
    Pose::new(unit_point(bounds, unit).coords, (2.0 * unit[2] - 1.0) * PI)
}

/// The pose at coordinates `[x, y, heading]`.
fn pose_at(c: &[f64]) -> Option<Pose> {
    let [x, y, heading] = finite::<3>(c)?;
    Some(Pose::new(Point::new(x, y).coords, heading))
}

/// A draw from the standard normal distribution.
fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    StandardNormal.sample(rng)
}

fn sample_in(bounds: &Bounds, rng: &mut ChaCha8Rng) -> Point {
    let (lo, hi) = (bounds.min(), bounds.max());
    Point::new(rng.random_range(lo.x..hi.x), rng.random_range(lo.y..hi.y))
}

/// Whether `p` is finite and in `bounds` (sides included).
fn in_bounds(bounds: &Bounds, p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite() && bounds.contains(*p)
}

/// `p` moved into `bounds` coordinate by coordinate (a NaN stays NaN: `clamp` keeps it).
fn clamp_into(bounds: &Bounds, p: &mut Point) {
    let (lo, hi) = (bounds.min(), bounds.max());
    *p = Point::new(p.x.clamp(lo.x, hi.x), p.y.clamp(lo.y, hi.y));
}

/// The position of a pose.
fn place(pose: &Pose) -> Point {
    Point::from(pose.translation.vector)
}

/// `pose` with its position moved into `bounds`, its heading kept.
fn clamp_pose(bounds: &Bounds, pose: &mut Pose) {
    let mut p = place(pose);
    clamp_into(bounds, &mut p);
    pose.translation.vector = p.coords;
}

fn diagonal(bounds: &Bounds) -> f64 {
    (bounds.max() - bounds.min()).norm()
}

fn area(bounds: &Bounds) -> f64 {
    let d = bounds.max() - bounds.min();
    d.x * d.y
}

fn planar<const D: usize>(p: Point) -> Option<[f64; D]> {
    (D == 2).then(|| std::array::from_fn(|i| p[i]))
}

/// The signed difference `b - a` of two headings, in `[-π, π]`.
fn angle_between(a: &Pose, b: &Pose) -> f64 {
    (a.rotation.inverse() * b.rotation).angle()
}

/// A uniform random heading.
fn sample_pose(bounds: &Bounds, rng: &mut ChaCha8Rng) -> Pose {
    let p = sample_in(bounds, rng);
    Pose::new(p.coords, rng.random_range(-PI..PI))
}
