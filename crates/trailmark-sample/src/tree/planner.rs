//! The face every tree planner shows: [`TreePlanner`], the nearest-neighbour structure its trees
//! grow in, its sampler, options and seed, with the builders and the [`Planner`] impl; and
//! `Grow`, what each planner's own file implements: how a checked run grows its trees.

use trailmark_core::termination::{Termination, Watch};

use super::options::{RrtOptions, checked_range};
use crate::nearest::NearestNeighbors;
use crate::plan::{Plan, PlanError};
use crate::planner::Planner;
use crate::problem::{Goal, Problem};
use crate::run::{Run, Spent, check_empty};
use crate::sampler::{StateSampler, Uniform};
use crate::space::StateSpace;
use crate::validity::Validity;

/// A tree planner: its algorithm `A` ([`RrtGrowth`](super::rrt::RrtGrowth),
/// [`ConnectGrowth`](super::rrt_connect::ConnectGrowth), [`StarGrowth`](super::rrt_star::StarGrowth)),
/// its trees in clones of the empty nearest-neighbour structure `N`, its sampler `Q`, its
/// options and seed. [`Rrt`](crate::Rrt), [`RrtConnect`](crate::RrtConnect) and
/// [`RrtStar`](crate::RrtStar) are its three kinds.
#[derive(Debug, Clone)]
pub struct TreePlanner<A, N, Q = Uniform> {
    algorithm: A,
    pub(crate) nearest: N,
    pub(crate) sampler: Q,
    /// Range and goal bias (RRT-Connect steers toward its other tree and reads no goal bias).
    pub options: RrtOptions,
    /// The seed of the ChaCha8 generator each run starts from: the same seed, the same run.
    pub seed: u64,
    /// What the last run grew, kept until the next run or `clear`.
    pub(crate) spent: Spent<N>,
}

impl<A: Default, N> TreePlanner<A, N> {
    /// The planner with its trees in (clones of) `nearest`, which must be empty, uniform
    /// samples, the default options and seed 0.
    pub fn new(nearest: N) -> Self {
        let (options, spent) = (RrtOptions::default(), Spent::default());
        TreePlanner { algorithm: A::default(), nearest, sampler: Uniform, options, seed: 0, spent }
    }
}

impl<A, N, Q> TreePlanner<A, N, Q> {
    /// The same planner drawing the states it steers toward from `sampler`.
    pub fn with_sampler<R>(self, sampler: R) -> TreePlanner<A, N, R> {
        let TreePlanner { algorithm, nearest, options, seed, spent, .. } = self;
        TreePlanner { algorithm, nearest, sampler, options, seed, spent }
    }

    /// The same planner with these options.
    pub fn with_options(self, options: RrtOptions) -> Self {
        TreePlanner { options, ..self }
    }

    /// The same planner seeded with `seed`.
    pub fn with_seed(self, seed: u64) -> Self {
        TreePlanner { seed, ..self }
    }

    /// The sampler.
    pub fn sampler(&self) -> &Q {
        &self.sampler
    }
}

/// What a run of a tree planner returns.
pub(crate) type Grown<S> = Result<Plan<<S as StateSpace>::State>, PlanError>;

/// How one tree planner grows its trees in a run that [`Planner::solve`] has checked and
/// started: the part of a tree planner that is its own.
pub(crate) trait Grow: Sized {
    /// Its name, as [`Planner::name`] gives it.
    const NAME: &'static str;
    /// Whether it improves its solution until its termination.
    const OPTIMIZES: bool;

    /// The trees grown until the run stops, and the plan.
    fn grow<S: StateSpace, V: Validity<S>, N: NearestNeighbors<S> + Clone, Q: StateSampler<S>>(
        job: Job<'_, S, V, Self, N, Q>,
    ) -> Grown<S>;
}

/// A run of a tree planner that [`Planner::solve`] has checked and started: the planner, the
/// problem and its parts, and the run, as every planner's growth begins with them.
pub(crate) struct Job<'r, S: StateSpace, V, A, N, Q> {
    pub(crate) planner: &'r mut TreePlanner<A, N, Q>,
    pub(crate) problem: &'r Problem<'r, S, V>,
    pub(crate) space: &'r S,
    pub(crate) validity: &'r V,
    pub(crate) goal: &'r dyn Goal<S>,
    pub(crate) run: Run<'r>,
}

impl<S, V, A, N, Q> Planner<S, V> for TreePlanner<A, N, Q>
where
    S: StateSpace,
    V: Validity<S>,
    A: Grow,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
{
    fn name(&self) -> &str {
        A::NAME
    }

    fn set_seed(&mut self, seed: u64) {
        self.seed = seed;
    }

    fn clear(&mut self) {
        self.spent.release();
    }

    fn optimizes(&self) -> bool {
        A::OPTIMIZES
    }

    fn solve(
        &mut self,
        problem: &Problem<'_, S, V>,
        termination: &Termination,
    ) -> Result<Plan<S::State>, PlanError> {
        // The last run's trees are freed before this run's clock starts.
        self.spent.release();
        check_empty(&self.nearest)?;
        let watch = Watch::start(termination);
        let range = checked_range(problem.space, &self.options)?;
        let run = Run::checked(problem, watch, range, self.seed)?;
        let (space, validity, goal) = (problem.space, problem.validity, &*problem.goal);
        A::grow(Job { planner: self, problem, space, validity, goal, run })
    }
}
