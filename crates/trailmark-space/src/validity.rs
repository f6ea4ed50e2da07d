//! Which states and motions a planner may use.
//!
//! A [`Validity`] answers two questions, as OMPL's state validity checker and motion validator
//! do: may the robot be at this state, and may it move from this state to that one along the
//! space's motion. For a `PolygonWorld`, the [`CollisionChecker`] answers both *exactly* in
//! [`R2`], [`Se2`] (a disc robot: the heading does not matter, the position moves in a straight
//! line), [`Dubins`](crate::space::Dubins) and [`ReedsShepp`](crate::space::ReedsShepp) (every arc and segment of the curve tested against the grown
//! obstacles), with no sampling resolution. For any other space or world, [`Sampled`] wraps a
//! state test and checks motions at a resolution, a fraction of the space's extent (OMPL's
//! longest valid segment fraction).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_space::space::{R2, StateSpace};
//! use trailmark_space::validity::{Sampled, Validity};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let (a, b) = (Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! assert!(checker.state_is_valid(&space, &a));
//! assert!(!checker.motion_is_valid(&space, &a, &b)); // through the wall: exact
//! // The same question by sampling a closure every 1% of the space's extent.
//! let sampled = Sampled::new(|p: &Point| !(p.x > 4.0 && p.x < 6.0 && p.y < 8.0), 0.01)?;
//! assert!(!sampled.motion_is_valid(&space, &a, &b));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::CollisionChecker;

use crate::space::{Car, CarCurves, R2, Se2, SpaceError, StateSpace};

/// Whether states and motions of a space are allowed.
pub trait Validity<S: StateSpace> {
    /// Whether the robot may be at `state`.
    fn state_is_valid(&self, space: &S, state: &S::State) -> bool;

    /// Whether the robot may move from `from` to `to` along the space's motion (both ends
    /// included).
    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool;
}

/// A borrowed validity, or one behind `dyn` (one planner compiled for every checker of a
/// space).
impl<S: StateSpace, V: Validity<S> + ?Sized> Validity<S> for &V {
    fn state_is_valid(&self, space: &S, state: &S::State) -> bool {
        (**self).state_is_valid(space, state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        (**self).motion_is_valid(space, from, to)
    }
}

impl Validity<R2> for CollisionChecker {
    fn state_is_valid(&self, _: &R2, p: &Point) -> bool {
        self.point_is_free(*p)
    }

    fn motion_is_valid(&self, _: &R2, a: &Point, b: &Point) -> bool {
        self.segment_is_free(*a, *b)
    }
}

fn position(pose: &Pose) -> Point {
    Point::from(pose.translation.vector)
}

impl Validity<Se2> for CollisionChecker {
    fn state_is_valid(&self, _: &Se2, s: &Pose) -> bool {
        self.point_is_free(position(s))
    }

    fn motion_is_valid(&self, _: &Se2, a: &Pose, b: &Pose) -> bool {
        self.segment_is_free(position(a), position(b))
    }
}

impl<C: CarCurves> Validity<Car<C>> for CollisionChecker {
    fn state_is_valid(&self, _: &Car<C>, s: &Pose) -> bool {
        self.point_is_free(position(s))
    }

    fn motion_is_valid(&self, space: &Car<C>, a: &Pose, b: &Pose) -> bool {
        C::is_free(self, &space.path(a, b))
    }
}

/// A state test (a closure) with motions checked at a resolution: states every `resolution x
/// extent` along the motion, both ends included, each also within the space's bounds (a curve
/// between two states in bounds may leave them). Not exact: an obstacle thinner than the step
/// can be missed, as with any sampled check.
#[derive(Clone, Debug)]
pub struct Sampled<F> {
    is_valid: F,
    resolution: f64,
}

impl<F> Sampled<F> {
    /// `is_valid` checked every `resolution` (a fraction of the space's extent, in `(0, 1]`).
    pub fn new(is_valid: F, resolution: f64) -> Result<Self, SpaceError> {
        if !(resolution > 0.0 && resolution <= 1.0) {
            return Err(SpaceError::NotPositive { what: "resolution (at most 1)", value: resolution });
        }
        Ok(Sampled { is_valid, resolution })
    }
}

impl<S: StateSpace, F: Fn(&S::State) -> bool> Validity<S> for Sampled<F> {
    fn state_is_valid(&self, _: &S, state: &S::State) -> bool {
        (self.is_valid)(state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        let step = self.resolution * space.extent();
        let steps = (space.distance(from, to) / step).ceil();
        if !steps.is_finite() {
            return false;
        }
        let n = (steps as u64).max(1);
        (0..=n).all(|i| {
            let state = space.interpolate(from, to, i as f64 / n as f64);
            space.satisfies_bounds(&state) && (self.is_valid)(&state)
        })
    }
}
