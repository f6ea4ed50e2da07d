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
    /// `is_valid` checked every `resolution` (a fraction of the space's extent, from
    /// [`MIN_RESOLUTION`] to 1).
    pub fn new(is_valid: F, resolution: f64) -> Result<Self, SpaceError> {
        check_resolution(resolution)?;
        Ok(Sampled { is_valid, resolution })
    }
}

impl<S: StateSpace, F: Fn(&S::State) -> bool> Validity<S> for Sampled<F> {
    fn state_is_valid(&self, _: &S, state: &S::State) -> bool {
        (self.is_valid)(state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        let Some(n) = motion_steps(space, from, to, self.resolution) else { return false };
        (0..=n).all(|i| {
            let state = space.interpolate(from, to, i as f64 / n as f64);
            space.satisfies_bounds(&state) && (self.is_valid)(&state)
        })
    }
}

/// A motion resolution of [`Sampled`] or [`Batched`]: from [`MIN_RESOLUTION`] to 1.
fn check_resolution(resolution: f64) -> Result<(), SpaceError> {
    if !(MIN_RESOLUTION..=1.0).contains(&resolution) {
        return Err(SpaceError::NotPositive { what: "resolution (from 1e-9 to 1)", value: resolution });
    }
    Ok(())
}

/// The steps of a motion checked every `resolution x extent`: at least one; `None` when the
/// distance is not finite.
fn motion_steps<S: StateSpace>(space: &S, from: &S::State, to: &S::State, resolution: f64) -> Option<u64> {
    let steps = (space.distance(from, to) / (resolution * space.extent())).ceil();
    // Saturating: a count past u64 is checked (and refused) state by state, never wrapped.
    steps.is_finite().then(|| (steps as u64).max(1))
}

/// The finest resolution of [`Sampled`] and [`Batched`]: a billionth of the space's extent (a
/// finer one would check a motion at more states than any run can afford).
pub const MIN_RESOLUTION: f64 = 1e-9;

/// The most states a [`Batched`] test is given at once.
pub const MAX_BATCH: usize = 1024;

/// A test of many states at once (a closure given a slice of states, `true` when every one
/// of them is valid), with motions checked at a resolution as [`Sampled`] checks them, but up
/// to [`MAX_BATCH`] states per call, in order, stopping at the first batch that fails: for
/// tests where each call is dear (a function of another language, a simulator, a GPU) and one
/// call for many states pays.
///
/// ```
/// use trailmark_core::geometry::Point;
/// use trailmark_core::world::Bounds;
/// use trailmark_space::space::R2;
/// use trailmark_space::validity::{Batched, Validity};
///
/// let space = R2::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?);
/// let free = |states: &[Point]| states.iter().all(|p| !(p.x > 4.0 && p.x < 6.0 && p.y < 8.0));
/// let batched = Batched::new(free, 0.01)?;
/// assert!(!batched.motion_is_valid(&space, &Point::new(1.0, 1.0), &Point::new(9.0, 1.0)));
/// assert!(batched.motion_is_valid(&space, &Point::new(1.0, 9.0), &Point::new(9.0, 9.0)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Batched<F> {
    all_valid: F,
    resolution: f64,
}

impl<F> Batched<F> {
    /// `all_valid` asked of the states every `resolution` (a fraction of the space's extent,
    /// from [`MIN_RESOLUTION`] to 1) along each motion.
    pub fn new(all_valid: F, resolution: f64) -> Result<Self, SpaceError> {
        check_resolution(resolution)?;
        Ok(Batched { all_valid, resolution })
    }
}

impl<S: StateSpace, F: Fn(&[S::State]) -> bool> Validity<S> for Batched<F> {
    fn state_is_valid(&self, _: &S, state: &S::State) -> bool {
        (self.all_valid)(std::slice::from_ref(state))
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        let Some(n) = motion_steps(space, from, to, self.resolution) else { return false };
        let mut batch =
            Vec::with_capacity(usize::try_from(n.saturating_add(1)).unwrap_or(MAX_BATCH).min(MAX_BATCH));
        for i in 0..=n {
            let state = space.interpolate(from, to, i as f64 / n as f64);
            if !space.satisfies_bounds(&state) {
                return false;
            }
            batch.push(state);
            if (batch.len() == MAX_BATCH || i == n) && !(self.all_valid)(&batch) {
                return false;
            }
            if batch.len() == MAX_BATCH {
                batch.clear();
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use proptest::prelude::*;
    use trailmark_core::geometry::Point;
    use trailmark_core::world::Bounds;

    use super::{Batched, MAX_BATCH, Sampled, Validity};
    use crate::space::R2;

    fn free(p: &Point) -> bool {
        (p.x - 5.0).hypot(p.y - 5.0) > 2.0
    }

    proptest! {
        /// One call per batch answers every motion as one call per state does.
        #[test]
        fn batched_answers_as_sampled(
            a in (0.0..10.0, 0.0..10.0), b in (0.0..10.0, 0.0..10.0), resolution in 1e-5..1.0,
        ) {
            let space = R2::new(Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap());
            let calls = Cell::new(0usize);
            let batched = Batched::new(
                |states: &[Point]| {
                    calls.set(calls.get() + 1);
                    assert!(states.len() <= MAX_BATCH);
                    states.iter().all(free)
                },
                resolution,
            )
            .unwrap();
            let sampled = Sampled::new(free, resolution).unwrap();
            let (a, b) = (Point::new(a.0, a.1), Point::new(b.0, b.1));
            prop_assert_eq!(batched.motion_is_valid(&space, &a, &b), sampled.motion_is_valid(&space, &a, &b));
            prop_assert_eq!(batched.state_is_valid(&space, &a), free(&a));
        }
    }
}
