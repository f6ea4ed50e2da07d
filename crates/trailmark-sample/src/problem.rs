//! What to plan: a space, what is valid in it, the start states and a goal (OMPL's
//! `ProblemDefinition`).
//!
//! A goal is anything that implements [`Goal`]: a [`GoalState`] with a tolerance (what
//! [`Problem::new`] makes), or a region of the user's own that tells whether a state satisfies
//! it, how far a state is from it, and, for planners that grow a tree from the goal
//! (RRT-Connect) or steer toward it (RRT's and RRT*'s goal bias), states that satisfy it.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{Goal, KdNearest, Planner, Problem, R2, Rrt, StateSpace};
//! use trailmark_core::termination::Termination;
//! use rand_chacha::ChaCha8Rng;
//!
//! /// Anywhere right of x = 8: a dock along the east wall.
//! struct Dock;
//!
//! impl Goal<R2> for Dock {
//!     fn is_satisfied(&self, _: &R2, p: &Point) -> bool {
//!         p.x >= 8.0
//!     }
//!     fn distance(&self, _: &R2, p: &Point) -> f64 {
//!         (8.0 - p.x).max(0.0)
//!     }
//!     fn sample(&self, space: &R2, rng: &mut ChaCha8Rng) -> Option<Point> {
//!         let p = space.sample(rng);
//!         Some(Point::new(8.0 + (p.x / 10.0) * 2.0, p.y))
//!     }
//! }
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let checker = PolygonWorld::new(bounds, vec![], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::with_goal(&space, &checker, Point::new(1.0, 5.0), Dock);
//! let plan = Rrt::new(KdNearest::<R2, 2>::new(&space)?).solve(&problem, &Termination::iterations(1000))?;
//! assert!(plan.path().expect("the dock is in reach").last().unwrap().x >= 8.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rand_chacha::ChaCha8Rng;

use crate::plan::{PlanError, Rejection};
use crate::space::StateSpace;
use crate::validity::Validity;

/// Where a plan must end.
pub trait Goal<S: StateSpace> {
    /// Whether `state` reaches the goal.
    fn is_satisfied(&self, space: &S, state: &S::State) -> bool;

    /// How far `state` is from the goal (0 or less where it is satisfied): approximate
    /// solutions end at the state with the least.
    fn distance(&self, space: &S, state: &S::State) -> f64;

    /// A state that satisfies the goal, for planners that grow a tree from the goal or steer
    /// toward it; `None` when the goal cannot give one. The planners check each state for
    /// bounds and validity before they use it.
    fn sample(&self, space: &S, rng: &mut ChaCha8Rng) -> Option<S::State> {
        let _ = (space, rng);
        None
    }

    /// A lower bound on the cost of any path from `state` to a state that satisfies the goal (0,
    /// the default, is always one). Informed planners (Informed RRT*, BIT*) draw only states
    /// whose distance from a start plus this is below the best cost found: the tighter the
    /// bound, the fewer states they spend on. A [`GoalState`] answers its distance less its
    /// tolerance.
    fn cost_to_go(&self, space: &S, state: &S::State) -> f64 {
        let _ = (space, state);
        0.0
    }

    /// The goal as one state and a tolerance, when it is one ([`GoalState`]): informed planners
    /// then draw directly from the states a cheaper path could pass through
    /// ([`StateSpace::sample_informed`]); `None` (the default) makes them draw and refuse.
    fn focus(&self) -> Option<(&S::State, f64)> {
        None
    }

    /// Refuses a goal that cannot be planned for (a goal state out of bounds or in collision);
    /// asked once at the start of every run.
    fn check(&self, space: &S, validity: &dyn Validity<S>) -> Result<(), PlanError> {
        let _ = (space, validity);
        Ok(())
    }
}

/// One goal state, reached within `tolerance` (the distance from a state to it).
#[derive(Debug, Clone, PartialEq)]
pub struct GoalState<T> {
    /// The state.
    pub state: T,
    /// How close is close enough (0: the state itself).
    pub tolerance: f64,
}

impl<T> GoalState<T> {
    /// `state` itself.
    pub fn new(state: T) -> Self {
        GoalState { state, tolerance: 0.0 }
    }

    /// Any state within `tolerance` of `state`.
    pub fn within(state: T, tolerance: f64) -> Self {
        GoalState { state, tolerance }
    }
}

impl<S: StateSpace<State = T>, T: Clone> Goal<S> for GoalState<T> {
    fn is_satisfied(&self, space: &S, state: &T) -> bool {
        space.distance(state, &self.state) <= self.tolerance
    }

    fn distance(&self, space: &S, state: &T) -> f64 {
        space.distance(state, &self.state)
    }

    fn sample(&self, _: &S, _: &mut ChaCha8Rng) -> Option<T> {
        Some(self.state.clone())
    }

    fn cost_to_go(&self, space: &S, state: &T) -> f64 {
        (space.distance(state, &self.state) - self.tolerance).max(0.0)
    }

    fn focus(&self) -> Option<(&T, f64)> {
        Some((&self.state, self.tolerance))
    }

    fn check(&self, space: &S, validity: &dyn Validity<S>) -> Result<(), PlanError> {
        if !(self.tolerance >= 0.0 && self.tolerance.is_finite()) {
            let value = self.tolerance;
            return Err(PlanError::InvalidOption {
                name: "goal tolerance",
                expected: ">= 0 and finite",
                value,
            });
        }
        admit(space, validity, &self.state).map_err(PlanError::InvalidGoal)
    }
}

/// Whether a planner may use `state`: finite, in bounds and valid.
pub fn admit<S: StateSpace>(
    space: &S,
    validity: &dyn Validity<S>,
    state: &S::State,
) -> Result<(), Rejection> {
    if !space.coordinates(state).iter().all(|c| c.is_finite()) {
        return Err(Rejection::NotFinite);
    }
    if !space.satisfies_bounds(state) {
        return Err(Rejection::OutOfBounds);
    }
    if !validity.state_is_valid(space, state) {
        return Err(Rejection::Invalid);
    }
    Ok(())
}

/// A planning problem: the space, the validity of its states and motions, where the robot may
/// start (one state or several) and the goal.
pub struct Problem<'a, S: StateSpace, V> {
    /// The state space.
    pub space: &'a S,
    /// The validity of states and motions.
    pub validity: &'a V,
    /// Where the robot may start: a plan begins at one of these.
    pub starts: Vec<S::State>,
    /// Where it must go.
    pub goal: Box<dyn Goal<S> + 'a>,
}

impl<S: StateSpace, V> std::fmt::Debug for Problem<'_, S, V> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Problem").field("starts", &self.starts).finish_non_exhaustive()
    }
}

impl<'a, S: StateSpace + 'a, V> Problem<'a, S, V> {
    /// From `start` to the state `goal` exactly.
    pub fn new(space: &'a S, validity: &'a V, start: S::State, goal: S::State) -> Self
    where
        S::State: 'a,
    {
        Problem::with_goal(space, validity, start, GoalState::new(goal))
    }

    /// From `start` to `goal`, any [`Goal`].
    pub fn with_goal(space: &'a S, validity: &'a V, start: S::State, goal: impl Goal<S> + 'a) -> Self {
        Problem { space, validity, starts: vec![start], goal: Box::new(goal) }
    }

    /// The same problem with one more start state.
    pub fn and_start(mut self, start: S::State) -> Self {
        self.starts.push(start);
        self
    }
}

impl<S: StateSpace, V: Validity<S>> Problem<'_, S, V> {
    /// Refuses a problem without starts, with a start that is not finite, in bounds and valid,
    /// or with a goal that its [`Goal::check`] refuses. Each state test adds one to `checks`.
    pub fn check(&self, checks: &mut u64) -> Result<(), PlanError> {
        if self.starts.is_empty() {
            return Err(PlanError::NoStart);
        }
        for (index, start) in self.starts.iter().enumerate() {
            *checks += 1;
            admit(self.space, self.validity, start)
                .map_err(|reason| PlanError::InvalidStart { index, reason })?;
        }
        *checks += 1;
        self.goal.check(self.space, self.validity)
    }
}
