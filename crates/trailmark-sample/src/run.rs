//! What every planner's run starts with and ends with (the tree planners' and PRM's): the
//! checked problem, the clock, the statistics, the seeded generator; and the plan it returns.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::plan::{Improvement, Plan, PlanError, PlanStats, Solution};
use crate::problem::{Problem, admit};
use crate::sampler::{Draw, StateSampler};
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Stop;
use trailmark_core::termination::Watch;

/// A run under way.
pub(crate) struct Run<'t> {
    pub(crate) watch: Watch<'t>,
    pub(crate) stats: PlanStats,
    pub(crate) range: f64,
    pub(crate) rng: ChaCha8Rng,
    pub(crate) history: Vec<Improvement>,
}

impl<'t> Run<'t> {
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

impl Run<'_> {
    /// The plan of a run that stopped for `stop` with nothing to return.
    pub(crate) fn nothing<T>(mut self, stop: Stop) -> Plan<T> {
        self.stats.iterations = self.watch.iterations();
        self.stats.elapsed = self.watch.elapsed();
        Plan { solution: Solution::None, stop, history: self.history, stats: self.stats }
    }
}

/// What a run built: its nearest-neighbour structures and per-state lists, kept by the planner
/// after the run (OMPL's planners keep their data until `clear` too). Freeing a large tree
/// returns its pages to the system, which takes long enough (about 0.3 ms for 28,000 states)
/// to make a run return well past its time limit; the planner frees it when it is cleared or
/// before the next run starts its clock. The tree planners and BIT* keep theirs here.
#[derive(Debug, Clone)]
pub(crate) struct Spent<N> {
    pub(crate) nearest: Vec<N>,
    pub(crate) ids: Vec<Vec<u32>>,
    pub(crate) costs: Vec<Vec<f64>>,
}

impl<N> Default for Spent<N> {
    fn default() -> Self {
        Spent { nearest: Vec::new(), ids: Vec::new(), costs: Vec::new() }
    }
}

impl<N> Spent<N> {
    /// Frees what the last run built.
    pub(crate) fn release(&mut self) {
        *self = Spent::default();
    }
}
