//! Sampling-based planners for continuous spaces: RRT, RRT-Connect, RRT*, Informed RRT*, BIT*
//! and PRM over any
//! configuration space of `trailmark-space` (R², Rⁿ, SE(2), Dubins, Reeds-Shepp, your own), with
//! exact collision checks and seeded, reproducible runs.
//!
//! The spaces, validity, samplers and nearest neighbours the planners run on are
//! `trailmark-space`'s, re-exported here (`trailmark_sample::R2` is `trailmark_space::R2`).
//!
//! - [`problem`] (start states and a goal: a state with a tolerance or the user's region),
//!   `trailmark_core::termination` (iterations, time, target cost, the caller's condition;
//!   shared with the anytime searches), [`plan`] (exact, approximate or no solution, why the
//!   run stopped, statistics);
//! - [`planner`]: the one interface of every planner, so they swap at run time; [`rrt`](mod@rrt),
//!   [`rrt_connect`](mod@rrt_connect), [`rrt_star`](mod@rrt_star),
//!   [`informed_rrt_star`](mod@informed_rrt_star) and [`bit_star`](mod@bit_star) (the informed
//!   planners: once solved, they draw only states a cheaper path can pass through) and [`prm`]
//!   (PRM and PRM*, multi-query) implement it;
//! - [`PolygonPrm`]: the same PRM built alone over a polygon world kept beside it: obstacles
//!   added and removed with the changed edges reported for D* Lite, saved and loaded, Dubins and
//!   Reeds-Shepp roadmaps for cars; its queries go through `trailmark-graph`'s `Roadmap`;
//! - [`boxes`]: worlds of axis-aligned boxes in `N` dimensions, checked exactly; [`arm`]: a
//!   planar arm of revolute joints among polygons, for planning in its joint space;
//! - [`benchmark`]: seeded runs of any planner, measured, and logs in OMPL's format;
//! - [`paths`]: a path's length, interpolation to a resolution, and a re-check of every state and
//!   motion; [`simplify`](mod@simplify): shortcutting and corner cutting. Smoothing with curves
//!   is in `trailmark_core::smooth`.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::termination::Termination;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Problem, R2, RrtConnect};
//!
//! // A disc of radius 0.25 in a 10 x 10 room with a wall from the floor to y = 8.
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let mut planner = RrtConnect::new(KdNearest::<R2, 2>::new(&space)?).with_seed(3);
//! let plan = planner.solve(&problem, &Termination::iterations(10_000))?;
//! let path = plan.path().expect("a way over the wall");
//! assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

// The families: tree planners, batch planners, roadmap planners, the worlds, benchmarking; and what every
// planner shares at the top (problem, plan, the Planner trait, a run, paths). One documented
// path per item: the root, or for the three families that read better under their names,
// `arm::`, `benchmark::` and `paths::`. The other module paths stay public, hidden, for one
// release.
mod batch;
pub mod benchmark;
mod informed;
pub mod paths;
#[doc(hidden)]
pub mod plan;
#[doc(hidden)]
pub mod planner;
#[doc(hidden)]
pub mod problem;
mod roadmap;
mod run;
#[doc(hidden)]
pub mod simplify;
#[cfg(test)]
mod test_worlds;
mod tree;
mod worlds;

pub use worlds::arm;
#[doc(hidden)]
pub use {
    batch::bit_star, roadmap::polygon, roadmap::prm, tree::informed_rrt_star, tree::rrt, tree::rrt_connect,
    tree::rrt_star, worlds::boxes,
};

// The configuration-space vocabulary, at the paths it had when it lived here.
#[doc(hidden)]
pub use trailmark_space::{nearest, sampler, space, validity};

pub use bit_star::{BitOptions, BitStar, MAX_BATCH_SIZE};
pub use boxes::BoxWorld;
pub use informed_rrt_star::{InformedGrowth, InformedRrtStar};
/// The states of [`Rn`]: nalgebra's fixed-size column vectors (nalgebra 0.35).
pub use nalgebra::SVector;
pub use plan::{Improvement, Plan, PlanError, PlanStats, Rejection, Solution};
pub use planner::Planner;
pub use polygon::{
    DubinsPrm, MAX_ROADMAP_NODES, PlanarSpace, PolygonPrm, PrmError, PrmOptions, PrmQuery, PrmSampler,
    ReedsSheppPrm,
};
pub use prm::{Growth, Prm};
pub use problem::{Goal, GoalState, Problem, admit};
/// The `rand` crate (0.10) the generator implements: `rand::RngExt` draws ranges and floats.
pub use rand;
/// The random generator the planners draw from (`rand_chacha` 0.10), so a user's own space or
/// sampler needs no version-matched dependency.
pub use rand_chacha::ChaCha8Rng;
pub use rrt::{Rrt, RrtGrowth};
pub use rrt_connect::{ConnectGrowth, MAX_CONNECT_STEPS, MAX_GOAL_ROOTS, RrtConnect};
pub use rrt_star::{RrtStar, StarGrowth, neighbour_count};
pub use simplify::{shortcut, simplify, smooth};
/// The configuration-space vocabulary of `trailmark-space`: spaces, validity, samplers, nearest
/// neighbours, connection rules.
pub use trailmark_space::{
    Bridge, BruteForce, Connection, DEFAULT_ATTEMPTS, DEFAULT_SHARE, Direction, Draw, Dubins,
    FootprintValidity, Gaussian, Halton, Joints, KdNearest, MAX_ATTEMPTS, NearestNeighbors, R2, ReedsShepp,
    Rn, Sampled, SamplerError, Se2, SpaceError, StateSampler, StateSpace, Uniform, UnitCube, Validity,
};
pub use tree::options::{MIN_RELATIVE_RANGE, RrtOptions};
pub use tree::planner::TreePlanner;
