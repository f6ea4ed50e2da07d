//! Informed sampling (Gammell, Srinivasa and Barfoot 2014): once a planner holds a solution of
//! cost `c`, only states through which a cheaper path can pass are worth drawing, those whose
//! distance from a start plus their [`cost_to_go`](crate::Goal::cost_to_go) is below `c`.
//! Where the problem has one start, the goal is one state ([`Goal::focus`](crate::Goal::focus))
//! and the space draws from that set directly
//! ([`StateSpace::sample_informed`](crate::StateSpace::sample_informed): an ellipsoid in
//! straight-line spaces), and while the set is smaller than the space, states come from it;
//! otherwise from the planner's sampler, refused until one falls inside (OMPL's
//! `PathLengthDirectInfSampler` and `RejectionInfSampler`). Informed RRT* and BIT* draw through
//! it; both prune with its [`estimate`](Informed::estimate).

use trailmark_core::termination::Stop;

use crate::problem::{Goal, Problem};
use crate::run::Run;
use crate::sampler::StateSampler;
use crate::space::StateSpace;
use crate::validity::Validity;

/// The share by which the best cost must fall before an informed planner prunes again (OMPL's
/// `pruneThreshold`, 5%): pruning rebuilds the nearest-neighbour structure.
pub(crate) const PRUNE_THRESHOLD: f64 = 0.05;

/// Draws per informed sample before the run moves on (OMPL's `numSampleAttempts_`).
pub(crate) const ATTEMPTS: usize = 100;

/// The informed set of one problem.
pub(crate) struct Informed<'p, S: StateSpace> {
    starts: &'p [S::State],
    goal: &'p dyn Goal<S>,
}

impl<'p, S: StateSpace> Informed<'p, S> {
    pub(crate) fn new<V>(problem: &'p Problem<'p, S, V>) -> Self {
        Informed { starts: &problem.starts, goal: &*problem.goal }
    }

    /// A lower bound on the cost of any solution through `state`: its distance from the
    /// nearest start plus the goal's bound from it.
    pub(crate) fn estimate(&self, space: &S, state: &S::State) -> f64 {
        self.come(space, state) + self.go(space, state)
    }

    /// A lower bound on the cost from the starts to `state`: its distance from the nearest.
    pub(crate) fn come(&self, space: &S, state: &S::State) -> f64 {
        self.starts.iter().map(|s| space.distance(s, state)).fold(f64::INFINITY, f64::min)
    }

    /// A lower bound on the cost from `state` to the goal ([`Goal::cost_to_go`]).
    pub(crate) fn go(&self, space: &S, state: &S::State) -> f64 {
        self.goal.cost_to_go(space, state)
    }

    /// A state of the space whose [`estimate`](Self::estimate) is below `best` (all of them
    /// while `best` is infinite): drawn from the set directly where it can be, else from
    /// `sampler` until one falls inside. `Ok(None)` after [`ATTEMPTS`] draws without one;
    /// `Err` when the run must stop.
    pub(crate) fn sample<V: Validity<S>, Q: StateSampler<S>>(
        &self,
        run: &mut Run<'_>,
        space: &S,
        validity: &V,
        sampler: &Q,
        best: f64,
    ) -> Result<Option<S::State>, Stop> {
        if best == f64::INFINITY {
            return run.sample(space, validity, sampler);
        }
        if let ([start], Some((goal, tolerance))) = (self.starts, self.goal.focus()) {
            let cost = best + tolerance;
            if space.informed_measure(start, goal, cost).is_some_and(|m| m < space.measure()) {
                for _ in 0..ATTEMPTS {
                    let Some(state) = space.sample_informed(start, goal, cost, &mut run.rng) else { break };
                    if space.satisfies_bounds(&state) {
                        return Ok(Some(state));
                    }
                }
                return Ok(None);
            }
        }
        for _ in 0..ATTEMPTS {
            if let Some(state) = run.sample(space, validity, sampler)?
                && self.estimate(space, &state) < best
            {
                return Ok(Some(state));
            }
        }
        Ok(None)
    }
}
