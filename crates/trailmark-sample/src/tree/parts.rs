//! What every tree planner holds between runs: the empty nearest-neighbour structure its trees
//! grow in, its sampler, and what its last run grew; and how a run of one starts.

use trailmark_core::termination::{Termination, Watch};

use super::options::{RrtOptions, checked_range};
use crate::plan::PlanError;
use crate::problem::Problem;
use crate::run::{Run, check_empty};
use crate::sampler::Uniform;
use crate::space::StateSpace;
use crate::validity::Validity;

/// A tree planner's parts: an empty nearest-neighbour structure (cloned for each tree), the
/// sampler, and the trees of the last run.
#[derive(Debug, Clone)]
pub(crate) struct TreeParts<N, Q> {
    pub(crate) nearest: N,
    pub(crate) sampler: Q,
    pub(crate) spent: Spent<N>,
}

impl<N> TreeParts<N, Uniform> {
    /// Trees in clones of `nearest`, uniform samples.
    pub(crate) fn new(nearest: N) -> Self {
        TreeParts { nearest, sampler: Uniform, spent: Spent::default() }
    }
}

impl<N, Q> TreeParts<N, Q> {
    /// The same parts drawing from `sampler`.
    pub(crate) fn with_sampler<R>(self, sampler: R) -> TreeParts<N, R> {
        TreeParts { nearest: self.nearest, sampler, spent: self.spent }
    }

    /// Frees the last run's trees (before this run's clock starts), checks the structure is
    /// empty, the options and the problem, and starts the run.
    pub(crate) fn begin<'t, S, V>(
        &mut self,
        problem: &Problem<'_, S, V>,
        options: &RrtOptions,
        termination: &'t Termination,
        seed: u64,
    ) -> Result<Run<'t>, PlanError>
    where
        S: StateSpace,
        V: Validity<S>,
        N: crate::nearest::NearestNeighbors<S>,
    {
        self.spent.release();
        check_empty(&self.nearest)?;
        let watch = Watch::start(termination);
        let range = checked_range(problem.space, options)?;
        Run::checked(problem, watch, range, seed)
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
