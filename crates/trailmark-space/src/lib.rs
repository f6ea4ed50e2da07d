//! Configuration spaces: the vocabulary every continuous planner of trailmark speaks, the
//! sampling planners and the roadmaps of `trailmark-sample` and the car planners of
//! `trailmark-car` alike.
//!
//! - [`space`]: the state spaces (sampling, distances, interpolation, steering): [`R2`],
//!   [`Rn`], [`Se2`], the car spaces [`Dubins`] and [`ReedsShepp`], and the [`StateSpace`]
//!   trait for your own;
//! - [`validity`]: which states and motions are valid: exact checks against polygon worlds and
//!   motions checked at a resolution for your own spaces ([`Sampled`], or [`Batched`] for tests that take many states in one call);
//! - [`footprint`]: a car's footprint in any world that says where a footprint fits
//!   ([`FootprintWorld`]: a polygon world here, a map's cells in `trailmark-car`), one
//!   [`FootprintValidity`];
//! - [`sampler`]: where a planner draws its states: uniformly, in a Halton sequence, or near
//!   obstacles and in narrow passages (Gaussian, bridge); a sampler sees the best cost so far
//!   ([`Draw::best_cost`]), for informed sampling;
//! - [`nearest`]: exact nearest neighbours for every space (a k-d tree over positions, pruned by
//!   the straight-line lower bound, and brute force);
//! - [`Connection`]: how a roadmap joins a new milestone to the others.
//!
//! ```
//! use rand::SeedableRng;
//! use rand_chacha::ChaCha8Rng;
//! use trailmark_core::world::Bounds;
//! use trailmark_space::{Direction, Dubins, KdNearest, NearestNeighbors, StateSpace};
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

mod connection;
pub mod footprint;
pub mod nearest;
pub mod sampler;
pub mod space;
pub mod validity;

pub use connection::Connection;
pub use footprint::{FootprintValidity, FootprintWorld, PolygonFootprint};
/// The states of [`Rn`]: nalgebra's fixed-size column vectors (nalgebra 0.35).
pub use nalgebra::SVector;
pub use nearest::{BruteForce, Direction, KdNearest, NearestNeighbors};
/// The `rand` crate (0.10) the generator implements: `rand::RngExt` draws ranges and floats.
pub use rand;
/// The random generator the state spaces and samplers draw from (`rand_chacha` 0.10), so a
/// user's own space or sampler needs no version-matched dependency.
pub use rand_chacha::ChaCha8Rng;
pub use sampler::{
    Bridge, DEFAULT_ATTEMPTS, DEFAULT_SHARE, Draw, Gaussian, Halton, MAX_ATTEMPTS, SamplerError,
    StateSampler, Uniform,
};
pub use space::{
    Car, CarCurves, Dubins, DubinsCurves, Joints, R2, ReedsShepp, ReedsSheppCurves, Rn, Se2, SpaceError,
    StateSpace, UnitCube,
};
pub use validity::{Batched, Sampled, Validity};
