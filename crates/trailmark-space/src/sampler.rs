//! Where the planners draw the states they steer toward.
//!
//! RRT, RRT-Connect and RRT* steer toward a random state each iteration. [`Uniform`] (the
//! default of every planner) draws it uniformly from the space, as OMPL's
//! planners do. A narrow passage is then found only when a sample happens to fall where its
//! nearest tree state sees through it, which grows rarer with every passage in a row. The
//! samplers here spend validity checks to draw where passages are, as OMPL's valid-state
//! samplers of the same names do:
//!
//! - [`Bridge`] (Hsu et al. 2003, the bridge test): a state in collision, a second one near it
//!   also in collision, and the free midpoint between them. Such midpoints lie between two
//!   obstacles close together: in doors and corridors.
//! - [`Gaussian`] (Boor, Overmars and van der Stappen 1999): two states near each other, one
//!   free and one not; the free one lies near an obstacle's surface.
//!
//! [`Halton`] draws the deterministic Halton sequence instead, for spaces that map the unit cube
//! ([`UnitCube`]): evener than independent draws, as OMPL's quasi-random samplers.
//!
//! Each of the first two draws such a state with probability `share` and a uniform one otherwise, so the trees
//! keep their spread over open space; after `attempts` failed tries it draws uniformly too.
//! Every validity check a sampler makes is counted in the plan's collision checks. Users
//! implement [`StateSampler`] for their own strategies.
//!
//! ```
//! use rand::SeedableRng;
//! use rand_chacha::ChaCha8Rng;
//! use trailmark_core::generate;
//! use trailmark_space::{Bridge, Draw, R2, StateSampler, Validity};
//!
//! // Six walls, each with a door 1.5 wide, for a robot of radius 0.25.
//! let world = generate::narrow_passages(40.0, 6, 1.5, 0.25, 2)?;
//! let checker = world.checker();
//! let space = R2::new(world.bounds());
//! let bridge = Bridge::new(1.0)?.with_share(1.0)?; // partners about one door width away
//! let (mut rng, mut checks) = (ChaCha8Rng::seed_from_u64(1), 0);
//! let mut draw = Draw::new(&mut rng, &mut checks);
//! let samples: Vec<_> = (0..100).filter_map(|_| bridge.sample(&space, &checker, &mut draw)).collect();
//! // Mostly free midpoints between two obstacles (the doors); uniform ones where no bridge was found.
//! let free = samples.iter().filter(|s| checker.state_is_valid(&space, s)).count();
//! assert!(samples.len() == 100 && free >= 75, "{free} free");
//! assert!(checks > 200); // every test counted
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::sync::atomic::{AtomicU64, Ordering};

use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use thiserror::Error;

use crate::space::{StateSpace, UnitCube};
use crate::validity::Validity;
use trailmark_core::termination::Watch;

/// A sampler setting out of its range.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SamplerError {
    /// A standard deviation that is not positive and finite.
    #[error("the sampler's standard deviation must be positive and finite, got {0:?}")]
    StdDev(f64),
    /// A share outside `[0, 1]`.
    #[error("the sampler's share must be in [0, 1], got {0:?}")]
    Share(f64),
    /// No attempts.
    #[error("the sampler needs at least one attempt")]
    NoAttempts,
    /// More attempts than [`MAX_ATTEMPTS`].
    #[error("the sampler makes at most {max} attempts per sample, not {0}", max = MAX_ATTEMPTS)]
    TooManyAttempts(u32),
}

/// The most attempts an obstacle sampler makes per sample: each attempt is up to two
/// validity tests, so a planner iteration stays within a few hundred thousand tests (at
/// `u32::MAX`, one iteration in a world without such states ran for hours).
pub const MAX_ATTEMPTS: u32 = 100_000;

/// A source of the states a planner steers toward.
pub trait StateSampler<S: StateSpace> {
    /// A state of `space`, possibly found by testing states with `validity` through `draw`
    /// (which counts the tests); `None` when [`Draw::should_stop`] says the run is over, or when
    /// the sampler has nothing to give this time.
    fn sample<V: Validity<S>>(&self, space: &S, validity: &V, draw: &mut Draw<'_>) -> Option<S::State>;
}

impl<S: StateSpace, T: StateSampler<S>> StateSampler<S> for &T {
    fn sample<V: Validity<S>>(&self, space: &S, validity: &V, draw: &mut Draw<'_>) -> Option<S::State> {
        (**self).sample(space, validity, draw)
    }
}

/// What a sampler draws with: the run's random generator, its count of validity tests, whether
/// the run must stop (asked between attempts), and the cost of the best solution so far.
pub struct Draw<'a> {
    rng: &'a mut ChaCha8Rng,
    checks: &'a mut u64,
    watch: Option<&'a Watch<'a>>,
    best_cost: f64,
}

impl<'a> Draw<'a> {
    /// Draws from `rng`, counting tests in `checks`, with no termination to answer to (for
    /// using a sampler outside a planner).
    pub fn new(rng: &'a mut ChaCha8Rng, checks: &'a mut u64) -> Self {
        Draw { rng, checks, watch: None, best_cost: f64::INFINITY }
    }

    /// Draws for a planner's run: from `rng`, counting tests in `checks`, answering
    /// [`should_stop`](Self::should_stop) from `watch`.
    pub fn watched(rng: &'a mut ChaCha8Rng, checks: &'a mut u64, watch: &'a Watch<'a>) -> Self {
        Draw { rng, checks, watch: Some(watch), best_cost: f64::INFINITY }
    }

    /// The same draw, told that the run's best solution so far costs `cost`: a planner that
    /// optimizes tells its sampler, so that an informed sampler draws only states through
    /// which a cheaper path could pass.
    pub fn with_best_cost(self, cost: f64) -> Self {
        Draw { best_cost: cost, ..self }
    }

    /// The cost of the run's best solution so far: `f64::INFINITY` before the first one, or
    /// when the planner does not say.
    pub fn best_cost(&self) -> f64 {
        self.best_cost
    }

    /// The run's random generator.
    pub fn rng(&mut self) -> &mut ChaCha8Rng {
        self.rng
    }

    /// Whether `state` is valid, counted as one test.
    pub fn is_valid<S: StateSpace, V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        state: &S::State,
    ) -> bool {
        *self.checks += 1;
        validity.state_is_valid(space, state)
    }

    /// Whether the run's time limit has passed or its condition asks to stop: a sampler that
    /// tries many times asks between tries.
    pub fn should_stop(&self) -> bool {
        self.watch.is_some_and(|w| w.interrupted().is_some())
    }
}

/// Uniform samples from the space ([`StateSpace::sample`]); no validity checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Uniform;

impl<S: StateSpace> StateSampler<S> for Uniform {
    fn sample<V: Validity<S>>(&self, space: &S, _: &V, draw: &mut Draw<'_>) -> Option<S::State> {
        Some(space.sample(draw.rng()))
    }
}

/// The primes that serve as [`Halton`]'s bases, one per coordinate.
const HALTON_BASES: [u64; 32] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103,
    107, 109, 113, 127, 131,
];

/// The Halton sequence (Halton 1960): element `i` has coordinate `j` the radical inverse of `i`
/// in the `j`-th prime (2, 3, 5, ...), mapped onto the space by [`UnitCube::state_from_unit`].
/// Deterministic, and more even than independent samples in few dimensions; the seed is not
/// used. It counts its own elements, so a roadmap grown in two steps draws what one step of the
/// same total would. Up to 32 dimensions; beyond that it draws nothing (`None`).
#[derive(Debug, Default)]
pub struct Halton {
    /// Elements drawn so far (an atomic, so that a planner sharing it stays `Sync`).
    drawn: AtomicU64,
}

impl Halton {
    /// The sequence from its first element (element 1: element 0 is the cube's corner).
    pub fn new() -> Self {
        Self::default()
    }

    /// The sequence after its first `drawn` elements, to go on where a saved one stopped.
    pub fn after(drawn: u64) -> Self {
        Halton { drawn: AtomicU64::new(drawn) }
    }

    /// The elements drawn so far.
    pub fn drawn(&self) -> u64 {
        self.drawn.load(Ordering::Relaxed)
    }
}

impl Clone for Halton {
    fn clone(&self) -> Self {
        Halton::after(self.drawn())
    }
}

/// The radical inverse of `i` in `base`: the `i`-th element of the van der Corput sequence.
fn radical_inverse(mut i: u64, base: u64) -> f64 {
    let (mut result, mut scale) = (0.0, 1.0 / base as f64);
    while i > 0 {
        result += (i % base) as f64 * scale;
        i /= base;
        scale /= base as f64;
    }
    result
}

impl<S: UnitCube> StateSampler<S> for Halton {
    fn sample<V: Validity<S>>(&self, space: &S, _: &V, _: &mut Draw<'_>) -> Option<S::State> {
        let bases = HALTON_BASES.get(..space.dimension())?;
        let i = self.drawn.fetch_add(1, Ordering::Relaxed) + 1;
        let unit: Vec<f64> = bases.iter().map(|&b| radical_inverse(i, b)).collect();
        Some(space.state_from_unit(&unit))
    }
}

/// The default probability that [`Bridge`] and [`Gaussian`] look for a state rather than draw a
/// uniform one.
pub const DEFAULT_SHARE: f64 = 0.5;

/// The default tries of [`Bridge`] and [`Gaussian`] before a uniform sample.
pub const DEFAULT_ATTEMPTS: u32 = 100;

/// The settings shared by the samplers that look for obstacles.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Focus {
    std_dev: f64,
    share: f64,
    attempts: u32,
}

impl Focus {
    fn new(std_dev: f64) -> Result<Self, SamplerError> {
        if !(std_dev > 0.0 && std_dev.is_finite()) {
            return Err(SamplerError::StdDev(std_dev));
        }
        Ok(Focus { std_dev, share: DEFAULT_SHARE, attempts: DEFAULT_ATTEMPTS })
    }

    fn with_share(mut self, share: f64) -> Result<Self, SamplerError> {
        if !(0.0..=1.0).contains(&share) {
            return Err(SamplerError::Share(share));
        }
        self.share = share;
        Ok(self)
    }

    fn with_attempts(mut self, attempts: u32) -> Result<Self, SamplerError> {
        if attempts == 0 {
            return Err(SamplerError::NoAttempts);
        }
        if attempts > MAX_ATTEMPTS {
            return Err(SamplerError::TooManyAttempts(attempts));
        }
        self.attempts = attempts;
        Ok(self)
    }

    /// `find` tried up to `attempts` times with probability `share`, else (or when every try
    /// failed) a uniform sample.
    /// `None` if the run must stop between tries.
    fn draw<S: StateSpace>(
        &self,
        space: &S,
        draw: &mut Draw<'_>,
        mut find: impl FnMut(&mut Draw<'_>) -> Option<S::State>,
    ) -> Option<S::State> {
        if draw.rng().random::<f64>() < self.share {
            for _ in 0..self.attempts {
                if draw.should_stop() {
                    return None;
                }
                if let Some(state) = find(draw) {
                    return Some(state);
                }
            }
        }
        Some(space.sample(draw.rng()))
    }
}

macro_rules! focus_settings {
    ($name:ident) => {
        impl $name {
            /// The sampler with partners drawn at a standard deviation of `std_dev` (a distance
            /// of the space, about the width of the passages sought), a share of 0.5 and 100
            /// attempts.
            pub fn new(std_dev: f64) -> Result<Self, SamplerError> {
                Ok($name(Focus::new(std_dev)?))
            }

            /// The probability, in `[0, 1]`, of looking for such a state rather than drawing a
            /// uniform one.
            pub fn with_share(self, share: f64) -> Result<Self, SamplerError> {
                Ok($name(self.0.with_share(share)?))
            }

            /// The tries (at least 1, at most [`MAX_ATTEMPTS`]) before falling back to a
            /// uniform sample.
            pub fn with_attempts(self, attempts: u32) -> Result<Self, SamplerError> {
                Ok($name(self.0.with_attempts(attempts)?))
            }

            /// The standard deviation of the partner's distance.
            pub fn std_dev(&self) -> f64 {
                self.0.std_dev
            }

            /// The probability of looking rather than drawing uniformly.
            pub fn share(&self) -> f64 {
                self.0.share
            }

            /// The tries before a uniform sample.
            pub fn attempts(&self) -> u32 {
                self.0.attempts
            }
        }
    };
}

/// The bridge test: the free midpoint of two states in collision near each other. Finds states
/// in narrow passages; see the [module](self) documentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bridge(Focus);

focus_settings!(Bridge);

impl<S: StateSpace> StateSampler<S> for Bridge {
    fn sample<V: Validity<S>>(&self, space: &S, validity: &V, draw: &mut Draw<'_>) -> Option<S::State> {
        self.0.draw(space, draw, |draw| {
            let a = space.sample(draw.rng());
            if draw.is_valid(space, validity, &a) {
                return None;
            }
            let b = space.sample_near(&a, self.0.std_dev, draw.rng());
            if draw.is_valid(space, validity, &b) {
                return None;
            }
            let middle = space.interpolate(&a, &b, 0.5);
            draw.is_valid(space, validity, &middle).then_some(middle)
        })
    }
}

/// Near obstacles' surfaces: of two states near each other, the free one when the other is in
/// collision; see the [module](self) documentation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gaussian(Focus);

focus_settings!(Gaussian);

impl<S: StateSpace> StateSampler<S> for Gaussian {
    fn sample<V: Validity<S>>(&self, space: &S, validity: &V, draw: &mut Draw<'_>) -> Option<S::State> {
        self.0.draw(space, draw, |draw| {
            let a = space.sample(draw.rng());
            let b = space.sample_near(&a, self.0.std_dev, draw.rng());
            match (draw.is_valid(space, validity, &a), draw.is_valid(space, validity, &b)) {
                (true, false) => Some(a),
                (false, true) => Some(b),
                _ => None,
            }
        })
    }
}
