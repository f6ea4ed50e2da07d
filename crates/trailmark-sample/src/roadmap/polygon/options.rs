//! How a polygon roadmap samples and joins its nodes, and what can go wrong.

use serde::{Deserialize, Serialize};
use thiserror::Error;
use trailmark_core::world::WorldError;
use trailmark_space::Connection;
use trailmark_space::sampler::{Bridge, Draw, Gaussian, Halton, SamplerError, StateSampler, Uniform};
use trailmark_space::space::SpaceError;
use trailmark_space::space::UnitCube;
use trailmark_space::validity::Validity;

/// How samples are drawn: which of `trailmark-sample`'s samplers, with its settings.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PrmSampler {
    /// Independent uniform samples ([`Uniform`](trailmark_space::Uniform)) from a ChaCha8 generator with this seed: the
    /// same seed gives the same roadmap on every machine.
    Uniform {
        /// The generator's seed.
        seed: u64,
    },
    /// The Halton sequence ([`Halton`]) in bases 2, 3 (and 5 for a heading): deterministic, and
    /// more even than independent samples.
    Halton,
    /// Near obstacles' surfaces ([`Gaussian`]), half the draws, the others uniform.
    Gaussian {
        /// The generator's seed.
        seed: u64,
        /// The standard deviation of the partner's distance.
        std_dev: f64,
    },
    /// In narrow passages ([`Bridge`], the bridge test), half the draws, the others uniform.
    Bridge {
        /// The generator's seed.
        seed: u64,
        /// The standard deviation of the partner's distance (about a passage's width).
        std_dev: f64,
    },
}

/// A [`PrmSampler`] made.
#[derive(Clone, Debug)]
pub(super) enum Drawer {
    Uniform,
    Halton(Halton),
    Gaussian(Gaussian),
    Bridge(Bridge),
}

impl Drawer {
    pub(super) fn new(sampler: PrmSampler) -> Result<Self, PrmError> {
        Ok(match sampler {
            PrmSampler::Uniform { .. } => Drawer::Uniform,
            PrmSampler::Halton => Drawer::Halton(Halton::new()),
            PrmSampler::Gaussian { std_dev, .. } => Drawer::Gaussian(Gaussian::new(std_dev)?),
            PrmSampler::Bridge { std_dev, .. } => Drawer::Bridge(Bridge::new(std_dev)?),
        })
    }
}

impl<S: UnitCube> StateSampler<S> for Drawer {
    fn sample<V: Validity<S>>(&self, space: &S, validity: &V, draw: &mut Draw<'_>) -> Option<S::State> {
        match self {
            Drawer::Uniform => Uniform.sample(space, validity, draw),
            Drawer::Halton(halton) => halton.sample(space, validity, draw),
            Drawer::Gaussian(gaussian) => gaussian.sample(space, validity, draw),
            Drawer::Bridge(bridge) => bridge.sample(space, validity, draw),
        }
    }
}

impl PrmSampler {
    /// The generator's seed (0 for the Halton sequence, which does not use it).
    pub(super) fn seed(&self) -> u64 {
        match *self {
            PrmSampler::Uniform { seed }
            | PrmSampler::Gaussian { seed, .. }
            | PrmSampler::Bridge { seed, .. } => seed,
            PrmSampler::Halton => 0,
        }
    }
}

/// The settings of a [`PolygonPrm`](crate::PolygonPrm).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PrmOptions {
    /// How samples are drawn.
    pub sampler: PrmSampler,
    /// Which nodes a new node is joined to.
    pub connection: Connection,
    /// How many draws [`PolygonPrm::grow`](crate::PolygonPrm::grow) may make per sample asked for before it gives up (draws in
    /// obstacles are rejected).
    pub attempts_per_sample: u32,
}

impl Default for PrmOptions {
    /// Seed-0 uniform samples joined to their 10 nearest neighbours, 1000 draws per sample.
    fn default() -> Self {
        PrmOptions {
            sampler: PrmSampler::Uniform { seed: 0 },
            connection: Connection::Nearest { k: 10 },
            attempts_per_sample: 1000,
        }
    }
}

/// The most nodes a roadmap holds. Each node keeps its state, a few dozen edges (PRM*'s
/// `k` grows with the logarithm of the nodes), their collision results and the nearest-neighbour
/// tree's entry: about 2 KB a node in eight dimensions (docs/core.md has the measurements), so
/// a million take about 2 GB. A larger request is refused with [`PrmError::TooManyNodes`]
/// before anything is drawn.
pub const MAX_ROADMAP_NODES: usize = 1_000_000;

/// What went wrong building, growing, querying, changing or loading a roadmap.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrmError {
    /// `Connection::Nearest` needs at least one neighbour.
    #[error("a nearest-neighbour connection needs k >= 1")]
    InvalidK,
    /// A connection radius must be positive and finite.
    #[error("the connection radius must be positive and finite, got {0:?}")]
    InvalidRadius(f64),
    /// `attempts_per_sample` must be at least 1.
    #[error("attempts_per_sample must be at least 1")]
    InvalidAttempts,
    /// The space could not be made (a Dubins turning radius that is not positive and finite,
    /// or out of the solver's range for the bounds).
    #[error(transparent)]
    Space(#[from] SpaceError),
    /// A sampler setting out of its range.
    #[error(transparent)]
    PrmSampler(#[from] SamplerError),
    /// [`PolygonPrm::grow`](crate::PolygonPrm::grow) ran out of draws: the free space is empty or very small. The samples
    /// found were added.
    #[error("found only {added} of {requested} free samples in {attempts} draws")]
    SamplingExhausted {
        /// Samples asked for.
        requested: usize,
        /// Samples found and added.
        added: usize,
        /// Draws made.
        attempts: u64,
    },
    /// A configuration given to [`PolygonPrm::insert`](crate::PolygonPrm::insert) collides or leaves
    /// the bounds.
    #[error("the configuration {0:?} collides or is outside the bounds")]
    Blocked(Vec<f64>),
    /// A query's start collides or is outside the bounds.
    #[error("the start {0:?} collides or is outside the bounds")]
    StartBlocked(Vec<f64>),
    /// A query's goal collides or is outside the bounds.
    #[error("the goal {0:?} collides or is outside the bounds")]
    GoalBlocked(Vec<f64>),
    /// The roadmap would pass [`MAX_ROADMAP_NODES`] nodes.
    #[error("a roadmap holds at most {max} nodes", max = MAX_ROADMAP_NODES)]
    TooManyNodes,
    /// The world rejected an obstacle change: an invalid polygon, or an obstacle to remove that
    /// is not there ([`WorldError::NoSuchObstacle`]).
    #[error(transparent)]
    World(#[from] WorldError),
    /// A saved roadmap's node is malformed, collides, or repeats an earlier node.
    #[error("saved node {index} is malformed, collides, or repeats an earlier node")]
    InvalidNode {
        /// Its index.
        index: usize,
    },
    /// A saved roadmap's sample-stream position is not a decimal number.
    #[error("the saved stream position is not a decimal number")]
    InvalidStream,
    /// A saved roadmap's edge names a missing node, a loop, or a free/blocked state its local
    /// path does not have in this world.
    #[error("saved edge {index} names a missing node or a loop, or its free flag is wrong")]
    InvalidEdge {
        /// Its index.
        index: usize,
    },
}
