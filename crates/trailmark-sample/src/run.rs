//! What every run of a tree planner starts with and ends with: the checked problem and
//! settings, the clock, the statistics, the seeded generator; and the plan it returns.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::plan::{Improvement, Plan, PlanError, PlanStats, Solution};
use crate::problem::{Problem, admit};
use crate::sampler::{Draw, StateSampler};
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Stop;
use trailmark_core::termination::{Termination, Watch};

/// The settings of the tree planners (RRT, RRT-Connect, RRT*).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtOptions {
    /// The longest motion added at once (default: 0.2 x the space's extent, as OMPL; at least
    /// [`MIN_RELATIVE_RANGE`] of it).
    pub range: Option<f64>,
    /// RRT and RRT*: the probability of steering toward a state of the goal (default 0.05).
    pub goal_bias: f64,
}

impl Default for RrtOptions {
    fn default() -> Self {
        RrtOptions { range: None, goal_bias: 0.05 }
    }
}

/// The shortest `range` a planner takes, as a share of the space's extent: 1e-4, so that one
/// connect phase of [`MAX_CONNECT_STEPS`](crate::rrt_connect::MAX_CONNECT_STEPS) can cross the
/// space. Shorter steps only pile up states (a range of 1e-8 of a world had made RRT-Connect
/// run for minutes, its trees millions of states along lines).
pub const MIN_RELATIVE_RANGE: f64 = 1e-4;

/// A run under way.
pub(crate) struct Run<'t> {
    pub(crate) watch: Watch<'t>,
    pub(crate) stats: PlanStats,
    pub(crate) range: f64,
    pub(crate) rng: ChaCha8Rng,
    pub(crate) history: Vec<Improvement>,
}

impl<'t> Run<'t> {
    /// Checks the termination, the tree planners' settings and the problem, and starts the
    /// clock.
    pub(crate) fn begin<S: StateSpace, V: Validity<S>>(
        problem: &Problem<'_, S, V>,
        options: &RrtOptions,
        termination: &'t Termination,
        seed: u64,
    ) -> Result<Self, PlanError> {
        let watch = Watch::start(termination);
        let range = checked_range(problem.space, options)?;
        Run::checked(problem, watch, range, seed)
    }

    /// Checks the termination and the problem, with the clock started as `watch`.
    pub(crate) fn checked<S: StateSpace, V: Validity<S>>(
        problem: &Problem<'_, S, V>,
        watch: Watch<'t>,
        range: f64,
        seed: u64,
    ) -> Result<Self, PlanError> {
        if !watch.termination().is_bounded() {
            return Err(PlanError::NoLimit);
        }
        let mut stats = PlanStats::default();
        problem.check(&mut stats.collision_checks)?;
        Ok(Run { watch, stats, range, rng: ChaCha8Rng::seed_from_u64(seed), history: Vec::new() })
    }

    /// A state from `sampler`, or why the run must stop (`Ok(None)`: nothing this time).
    pub(crate) fn sample<S: StateSpace, V: Validity<S>, Q: StateSampler<S>>(
        &mut self,
        space: &S,
        validity: &V,
        sampler: &Q,
    ) -> Result<Option<S::State>, Stop> {
        let best = self.history.last().map_or(f64::INFINITY, |b| b.cost);
        let mut draw =
            Draw::watched(&mut self.rng, &mut self.stats.collision_checks, &self.watch).with_best_cost(best);
        match sampler.sample(space, validity, &mut draw) {
            Some(state) => Ok(Some(state)),
            None => self.watch.interrupted().map_or(Ok(None), Err),
        }
    }

    /// A state of the goal to steer toward, with probability `bias`: sampled, in bounds and
    /// valid (RRT's and RRT*'s goal bias).
    pub(crate) fn goal_target<S: StateSpace, V: Validity<S>>(
        &mut self,
        problem: &Problem<'_, S, V>,
        bias: f64,
    ) -> Option<S::State> {
        if bias == 0.0 || self.rng.random::<f64>() >= bias {
            return None;
        }
        let state = problem.goal.sample(problem.space, &mut self.rng)?;
        self.stats.collision_checks += 1;
        admit(problem.space, problem.validity, &state).ok().map(|_| state)
    }

    /// Records a solution of cost `cost` if it is the best so far.
    pub(crate) fn improved(&mut self, cost: f64) {
        if self.history.last().is_none_or(|b| cost < b.cost) {
            let at = Improvement { iteration: self.watch.iterations(), time: self.watch.elapsed(), cost };
            self.stats.time_to_solution.get_or_insert(at.time);
            self.history.push(at);
            self.watch.improved(cost);
        }
    }

    /// The plan of a run that stopped for `stop` with `path` ending `goal_distance` from the
    /// goal (`None`: at the goal).
    pub(crate) fn finish<S: StateSpace>(
        mut self,
        space: &S,
        path: Vec<S::State>,
        goal_distance: Option<f64>,
        stop: Stop,
    ) -> Plan<S::State> {
        self.stats.iterations = self.watch.iterations();
        let cost = crate::paths::length(space, &path);
        let solution = match goal_distance {
            None => Solution::Exact { path, cost },
            Some(goal_distance) => Solution::Approximate { path, cost, goal_distance },
        };
        self.stats.elapsed = self.watch.elapsed();
        Plan { solution, stop, history: self.history, stats: self.stats }
    }
}

/// Refuses a nearest-neighbour structure that already holds states: a planner's ids are its
/// own trees' (a state stored before would belong to no tree).
pub(crate) fn check_empty<S: StateSpace, N: crate::nearest::NearestNeighbors<S>>(
    nearest: &N,
) -> Result<(), PlanError> {
    if nearest.is_empty() {
        Ok(())
    } else {
        let value = nearest.len() as f64;
        Err(PlanError::InvalidOption { name: "nearest", expected: "an empty structure", value })
    }
}

/// The range of the tree planners' motions, checked.
fn checked_range<S: StateSpace>(space: &S, options: &RrtOptions) -> Result<f64, PlanError> {
    let range = options.range.unwrap_or(0.2 * space.extent());
    if !(range.is_finite() && range > 0.0) {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "positive and finite",
            value: range,
        });
    }
    if range < MIN_RELATIVE_RANGE * space.extent() {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "at least 1e-4 of the space's extent (MIN_RELATIVE_RANGE)",
            value: range,
        });
    }
    if !(0.0..=1.0).contains(&options.goal_bias) {
        let value = options.goal_bias;
        return Err(PlanError::InvalidOption { name: "goal_bias", expected: "in [0, 1]", value });
    }
    Ok(range)
}

impl Run<'_> {
    /// The plan of a run that stopped for `stop` with nothing to return.
    pub(crate) fn nothing<T>(mut self, stop: Stop) -> Plan<T> {
        self.stats.iterations = self.watch.iterations();
        self.stats.elapsed = self.watch.elapsed();
        Plan { solution: Solution::None, stop, history: self.history, stats: self.stats }
    }
}

/// What a run grew: its trees, kept by the planner after the run (OMPL's planners keep their
/// data until `clear` too). Freeing a large tree returns its pages to the system, which takes
/// long enough (about 0.3 ms for 28,000 states) to make a run return well past its time limit;
/// the planner frees it when it is cleared or before the next run starts its clock.
#[derive(Debug, Clone)]
pub(crate) struct Spent<N> {
    pub(crate) nearest: Vec<N>,
    pub(crate) ids: Vec<Vec<u32>>,
    pub(crate) costs: Vec<f64>,
    pub(crate) lists: Vec<Vec<u32>>,
}

impl<N> Default for Spent<N> {
    fn default() -> Self {
        Spent { nearest: Vec::new(), ids: Vec::new(), costs: Vec::new(), lists: Vec::new() }
    }
}

impl<N> Spent<N> {
    /// Frees what the last run grew.
    pub(crate) fn release(&mut self) {
        *self = Spent::default();
    }
}

/// The settings every tree planner has: an empty nearest-neighbour structure to grow its trees
/// in, a sampler, the options and the seed; with the methods that set them, and the `Planner`
/// impl that checks a run and hands it to the planner's own `grow`.
macro_rules! tree_planner {
    ($(#[$doc:meta])* $name:ident, $label:literal, optimizes: $optimizes:literal) => {
        $(#[$doc])*
        #[derive(Debug, Clone)]
        pub struct $name<N, Q = $crate::sampler::Uniform> {
            nearest: N,
            sampler: Q,
            /// Range and goal bias.
            pub options: $crate::run::RrtOptions,
            /// The seed of the ChaCha8 generator each run starts from: the same seed, the same
            /// run.
            pub seed: u64,
            /// What the last run grew, kept until the next run or `clear`.
            spent: $crate::run::Spent<N>,
        }

        impl<N> $name<N> {
            /// The planner with its trees in (clones of) `nearest`, which must be empty, uniform
            /// samples, the default options and seed 0.
            pub fn new(nearest: N) -> Self {
                $name {
                    nearest,
                    sampler: $crate::sampler::Uniform,
                    options: $crate::run::RrtOptions::default(),
                    seed: 0,
                    spent: $crate::run::Spent::default(),
                }
            }
        }

        impl<N, Q> $name<N, Q> {
            /// The same planner drawing its samples from `sampler`.
            pub fn with_sampler<R>(self, sampler: R) -> $name<N, R> {
                $name { nearest: self.nearest, sampler, options: self.options, seed: self.seed, spent: self.spent }
            }

            /// The same planner with these options.
            pub fn with_options(self, options: $crate::run::RrtOptions) -> Self {
                $name { options, ..self }
            }

            /// The same planner seeded with `seed`.
            pub fn with_seed(self, seed: u64) -> Self {
                $name { seed, ..self }
            }

            /// The sampler.
            pub fn sampler(&self) -> &Q {
                &self.sampler
            }
        }

        impl<S, V, N, Q> $crate::planner::Planner<S, V> for $name<N, Q>
        where
            S: $crate::space::StateSpace,
            V: $crate::validity::Validity<S>,
            N: $crate::nearest::NearestNeighbors<S> + Clone,
            Q: $crate::sampler::StateSampler<S>,
        {
            fn name(&self) -> &str {
                $label
            }

            fn set_seed(&mut self, seed: u64) {
                self.seed = seed;
            }

            fn clear(&mut self) {
                self.spent.release();
            }

            fn optimizes(&self) -> bool {
                $optimizes
            }

            fn solve(
                &mut self,
                problem: &$crate::problem::Problem<'_, S, V>,
                termination: &::trailmark_core::termination::Termination,
            ) -> Result<$crate::plan::Plan<S::State>, $crate::plan::PlanError> {
                // The last run's trees are freed before this run's clock starts.
                self.spent.release();
                $crate::run::check_empty(&self.nearest)?;
                let run = $crate::run::Run::begin(problem, &self.options, termination, self.seed)?;
                self.grow(problem, run)
            }
        }
    };
}

pub(crate) use tree_planner;
