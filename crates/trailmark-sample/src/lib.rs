//! Sampling-based planners for continuous spaces: RRT, RRT-Connect and RRT* over pluggable state
//! spaces (R², Rⁿ, SE(2), Dubins, Reeds-Shepp), with exact collision checks and seeded, reproducible runs.
//!
//! - [`space`]: the state spaces (sampling, distances, interpolation, steering);
//! - [`nearest`]: exact nearest-neighbour structures for every space (a k-d tree over positions,
//!   pruned by the straight-line lower bound, and brute force);
//! - [`validity`]: exact checks against polygon worlds, sampled checks for your own spaces;
//!   [`boxes`]: worlds of axis-aligned boxes in `N` dimensions, checked exactly;
//! - [`sampler`]: where the planners draw samples: uniformly, or near obstacles and in narrow
//!   passages (the Gaussian and bridge-test samplers);
//! - [`problem`] (start states and a goal: a state with a tolerance or the user's region),
//!   `trailmark_core::termination` (iterations, time, target cost, the caller's condition;
//!   shared with the anytime searches), [`plan`] (exact, approximate or no solution, why the
//!   run stopped, statistics);
//! - [`planner`]: the one interface of every planner, so they swap at run time; [`rrt`](mod@rrt),
//!   [`rrt_connect`](mod@rrt_connect), [`rrt_star`](mod@rrt_star) and [`prm`] (PRM and PRM*,
//!   multi-query) implement it;
//! - [`arm`]: a planar arm of revolute joints among polygons, for planning in its joint space;
//! - [`benchmark`]: seeded runs of any planner, measured, and logs in OMPL's format;
//! - [`paths`]: a path's length, interpolation to a resolution, and a re-check of every state and
//!   motion; [`simplify`]: shortcutting. Smoothing with curves is in `trailmark_core::smooth`.
//!
//! ```
//! use rand::SeedableRng;
//! use rand_chacha::ChaCha8Rng;
//! use trailmark_core::world::Bounds;
//! use trailmark_sample::nearest::{Direction, KdNearest, NearestNeighbors};
//! use trailmark_sample::space::{Dubins, StateSpace};
//!
//! // A car with a turning radius of 1 in a 20 x 20 square: the nearest pose *from which* the
//! // car reaches a sample soonest (Dubins distances are not symmetric).
//! let space = Dubins::new(Bounds::new(0.0, 0.0, 20.0, 20.0)?, 1.0)?;
//! let mut rng = ChaCha8Rng::seed_from_u64(7);
//! let mut tree = KdNearest::<Dubins, 2>::new(&space)?;
//! for _ in 0..500 {
//!     tree.insert(&space, space.sample(&mut rng));
//! }
//! let target = space.sample(&mut rng);
//! let (id, distance) = tree.nearest(&space, &target, Direction::ToQuery).expect("a full tree");
//! assert_eq!(distance, space.distance(tree.state(id), &target));
//! let step = space.steer(tree.state(id), &target, 2.0); // at most 2 along the curve
//! assert!(space.distance(tree.state(id), &step) <= 2.0 + 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

// One documented path per item: the root, or for the three families that read better under
// their names, `arm::`, `benchmark::` and `paths::`. The other modules stay public, hidden,
// for one release.
pub mod arm;
pub mod benchmark;
#[doc(hidden)]
pub mod boxes;
#[doc(hidden)]
pub mod nearest;
pub mod paths;
#[doc(hidden)]
pub mod plan;
#[doc(hidden)]
pub mod planner;
#[doc(hidden)]
pub mod prm;
#[doc(hidden)]
pub mod problem;
#[doc(hidden)]
pub mod rrt;
#[doc(hidden)]
pub mod rrt_connect;
#[doc(hidden)]
pub mod rrt_star;
mod run;
#[doc(hidden)]
pub mod sampler;
#[doc(hidden)]
pub mod simplify;
#[doc(hidden)]
pub mod space;
#[doc(hidden)]
pub mod termination;
mod tree;
#[doc(hidden)]
pub mod validity;

pub use boxes::BoxWorld;
/// The states of [`Rn`]: nalgebra's fixed-size column vectors (nalgebra 0.35).
pub use nalgebra::SVector;
pub use nearest::{BruteForce, Direction, KdNearest, NearestNeighbors};
#[allow(deprecated)]
pub use plan::Stop;
pub use plan::{Improvement, Plan, PlanError, PlanStats, Rejection, Solution};
pub use planner::Planner;
pub use prm::{Connection, Growth, Prm};
pub use problem::{Goal, GoalState, Problem, admit};
/// The `rand` crate (0.10) the generator implements: `rand::RngExt` draws ranges and floats.
pub use rand;
/// The random generator the planners and state spaces draw from (`rand_chacha` 0.10), so a
/// user's own space or sampler needs no version-matched dependency.
pub use rand_chacha::ChaCha8Rng;
pub use rrt::Rrt;
pub use rrt_connect::{MAX_CONNECT_STEPS, MAX_GOAL_ROOTS, RrtConnect};
pub use rrt_star::{RrtStar, neighbour_count};
pub use run::{MIN_RELATIVE_RANGE, RrtOptions};
pub use sampler::{
    Bridge, DEFAULT_ATTEMPTS, DEFAULT_SHARE, Draw, Gaussian, Halton, MAX_ATTEMPTS, SamplerError,
    StateSampler, Uniform,
};
pub use simplify::shortcut;
pub use space::{Dubins, R2, ReedsShepp, Rn, Se2, SpaceError, StateSpace, UnitCube};
#[allow(deprecated)]
pub use termination::{Condition, Progress, Termination};
pub use validity::{FootprintValidity, Sampled, Validity};
