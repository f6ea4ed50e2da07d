//! One interface for every planner: solve a [`Problem`] under a [`Termination`].
//!
//! Planners are values (OMPL's `Planner`): built once with their settings, asked to solve any
//! number of problems, and swapped at run time behind `Box<dyn Planner<S, V>>`. The planners of
//! this crate ([`Rrt`](crate::Rrt), [`RrtConnect`](crate::RrtConnect),
//! [`RrtStar`](crate::RrtStar)) implement it, and so can the user's own, which the benchmark
//! runner then measures beside them.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Problem, R2, Rrt, RrtConnect, RrtStar};
//! use trailmark_core::termination::Termination;
//! use trailmark_core::world::CollisionChecker;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let nearest = KdNearest::<R2, 2>::new(&space)?;
//! let mut planners: Vec<Box<dyn Planner<R2, CollisionChecker>>> = vec![
//!     Box::new(Rrt::new(nearest.clone())),
//!     Box::new(RrtConnect::new(nearest.clone())),
//!     Box::new(RrtStar::new(nearest)),
//! ];
//! let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! for planner in &mut planners {
//!     let plan = planner.solve(&problem, &Termination::iterations(5_000))?;
//!     let path = plan.path().expect("over the wall");
//!     assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])), "{}", planner.name());
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::plan::{Plan, PlanError};
use crate::problem::Problem;
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Termination;

/// A motion planner over the space `S` with validity `V`.
pub trait Planner<S: StateSpace, V: Validity<S>> {
    /// The planner's name, for reports.
    fn name(&self) -> &str;

    /// Plans for `problem` until a solution (for planners that stop at their first) or until
    /// `termination`. The problem is checked first: starts and goal finite, in bounds and valid.
    ///
    /// The planners of this crate honour the termination's iteration limit (samples drawn), time
    /// limit, condition and, those that improve their solution, target cost. They count no
    /// expansions, so an expansion limit does not bound them, and they refuse a termination
    /// without an iteration limit, a time limit or a condition ([`PlanError::NoLimit`]).
    fn solve(
        &mut self,
        problem: &Problem<'_, S, V>,
        termination: &Termination,
    ) -> Result<Plan<S::State>, PlanError>;

    /// Forgets what earlier runs built (a roadmap, say), so the next run starts afresh. The
    /// tree planners keep nothing between runs.
    fn clear(&mut self) {}

    /// Seeds the planner's next runs (a deterministic planner ignores it).
    fn set_seed(&mut self, seed: u64) {
        let _ = seed;
    }

    /// Whether the planner improves its solution after the first (RRT*), so that a benchmark
    /// logs its progress.
    fn optimizes(&self) -> bool {
        false
    }
}
