//! The state spaces a polygon roadmap is built in, and the world's exact checks as their validity.

use std::fmt::Debug;

use trailmark_core::world::CollisionChecker;
use trailmark_space::space::UnitCube;
use trailmark_space::validity::Validity;

/// A state space a roadmap over a polygon world is built in: one whose states the world's exact
/// [`CollisionChecker`] checks ([`R2`](trailmark_space::R2) for a disc robot, [`Se2`](trailmark_space::Se2),
/// [`Dubins`](trailmark_space::Dubins) for a car), that maps the unit cube (for the Halton
/// sequence) and whose states are small values. Every such space of `trailmark-sample` is one.
pub trait PlanarSpace: UnitCube<State: Copy> + Clone + Debug {
    /// Whether the world of `checker` leaves `state` free.
    fn state_is_free(&self, checker: &CollisionChecker, state: &Self::State) -> bool;

    /// Whether the world of `checker` leaves the space's motion from `from` to `to` free.
    fn motion_is_free(&self, checker: &CollisionChecker, from: &Self::State, to: &Self::State) -> bool;
}

impl<S> PlanarSpace for S
where
    S: UnitCube<State: Copy> + Clone + Debug,
    CollisionChecker: Validity<S>,
{
    fn state_is_free(&self, checker: &CollisionChecker, state: &S::State) -> bool {
        checker.state_is_valid(self, state)
    }

    fn motion_is_free(&self, checker: &CollisionChecker, from: &S::State, to: &S::State) -> bool {
        checker.motion_is_valid(self, from, to)
    }
}

/// The world's checker as the samplers' validity.
pub(super) struct ExactValidity<'a>(pub(super) &'a CollisionChecker);

impl<S: PlanarSpace> Validity<S> for ExactValidity<'_> {
    fn state_is_valid(&self, space: &S, state: &S::State) -> bool {
        space.state_is_free(self.0, state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        space.motion_is_free(self.0, from, to)
    }
}
