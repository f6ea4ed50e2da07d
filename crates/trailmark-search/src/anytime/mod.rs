//! Anytime searches: [`ara_star`](crate::ara_star()) and [`AdStar`](crate::AdStar) return an
//! inflated solution fast and improve it while time allows, lowering the inflation of the
//! heuristic iteration by iteration.
//!
//! What they share lives here: the inflation schedule, the record of each iteration and the
//! result. When to stop is a [`Termination`](trailmark_core::termination::Termination), the
//! vocabulary the sampling planners share: the anytime searches honour its iteration limit
//! (improvement iterations completed), expansion limit, time limit, target cost and condition
//! (asked every 256 expansions and between iterations); without any limit they run to the
//! optimum.

use std::time::Duration;

use serde::{Deserialize, Serialize};
use trailmark_core::cost::Cost;
use trailmark_core::path::Path;

use trailmark_core::termination::Stop;

use crate::error::SearchError;
use crate::limits::{MAX_EPSILON, MAX_ITERATIONS};
use crate::stats::SearchStats;

pub(crate) mod ad_star;
pub(crate) mod ara_star;

/// How an anytime planner lowers its heuristic inflation: from `initial` down to 1 by `step`
/// per iteration (the last step lands on 1 exactly). [`EpsilonSchedule::check`] says which
/// schedules a planner accepts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EpsilonSchedule {
    /// The first inflation, from 1 to [`MAX_EPSILON`] (3 by default).
    pub initial: f64,
    /// The decrease per iteration, `> 0` (0.5 by default).
    pub step: f64,
}

impl Default for EpsilonSchedule {
    fn default() -> Self {
        EpsilonSchedule { initial: 3.0, step: 0.5 }
    }
}

impl EpsilonSchedule {
    /// A schedule from `initial` down by `step`.
    pub fn new(initial: f64, step: f64) -> Self {
        EpsilonSchedule { initial, step }
    }

    /// Errors ([`SearchError::InvalidEpsilon`]) unless `1 <= initial <= MAX_EPSILON`, `step > 0`
    /// is finite, and the schedule reaches 1 in at most [`MAX_ITERATIONS`] iterations, each of
    /// which lowers the inflation by `step`: a step lost to rounding (`1e20 - 1 == 1e20` in
    /// `f64`) would never arrive.
    pub fn check<N: std::fmt::Debug>(&self) -> Result<(), SearchError<N>> {
        let valid = (1.0..=MAX_EPSILON).contains(&self.initial) && self.step.is_finite() && self.step > 0.0;
        if !valid || self.iterations() > MAX_ITERATIONS {
            return Err(SearchError::InvalidEpsilon { initial: self.initial, step: self.step });
        }
        Ok(())
    }

    /// The number of iterations from `initial` to 1, counted by stepping through the schedule
    /// as a planner does. A schedule longer than [`MAX_ITERATIONS`], or one that does not reach 1
    /// because `initial - step` rounds back to `initial` somewhere on the way, counts as
    /// `MAX_ITERATIONS + 1`; a NaN `initial` counts 1 (it is not above 1).
    pub fn iterations(&self) -> usize {
        let mut epsilon = self.initial;
        let mut count = 1;
        while epsilon > 1.0 {
            count += 1;
            let lower = epsilon - self.step;
            if count > MAX_ITERATIONS || lower.is_nan() || lower >= epsilon {
                return MAX_ITERATIONS + 1;
            }
            epsilon = self.next(epsilon);
        }
        count
    }

    /// The inflation after `epsilon`: lower by `step`, never below 1. Above 1 it is always
    /// strictly lower than `epsilon`, by a unit in the last place at least should `step` be lost
    /// to rounding (a schedule [`check`](Self::check) refuses), so stepping always ends.
    pub fn next(&self, epsilon: f64) -> f64 {
        (epsilon - self.step).min(epsilon.next_down()).max(1.0)
    }
}

/// One completed iteration of an anytime search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Iteration {
    /// The inflation this iteration searched with.
    pub epsilon: f64,
    /// The cost of the path after this iteration (`None` while the goal is unreached).
    pub cost: Option<Cost>,
    /// The proven suboptimality bound: the cost is at most `bound x` the optimum.
    /// `min(epsilon, g(goal) / min over open and inconsistent nodes of g + h)`.
    pub bound: f64,
    /// Expansions in this iteration.
    pub expansions: u64,
    /// Time since the search began, at the end of this iteration.
    pub elapsed: Duration,
}

/// What an anytime search returns: the best path found, every iteration, why it stopped.
///
/// A result without a path says the goal is unreachable only when it stopped with
/// [`Stop::Unreachable`]; stopped by a budget or the caller, it proves nothing (see
/// [`AnytimeResult::proved_unreachable`]).
#[derive(Debug, Clone, PartialEq)]
pub struct AnytimeResult<N> {
    /// The best path found (from the last completed iteration), `None` if none was found.
    pub path: Option<Path<N>>,
    /// The iterations completed, in order.
    pub iterations: Vec<Iteration>,
    /// Why the search stopped.
    pub stop: Stop,
    /// Counters over the whole search.
    pub stats: SearchStats,
}

impl<N> AnytimeResult<N> {
    /// The cost of the best path found.
    pub fn cost(&self) -> Option<Cost> {
        self.path.as_ref().map(|p| p.cost)
    }

    /// Whether the search proved that the goal is unreachable: no path, and stopped with
    /// [`Stop::Unreachable`], not by a limit before it could tell.
    pub fn proved_unreachable(&self) -> bool {
        self.path.is_none() && self.stop == Stop::Unreachable
    }

    /// The suboptimality bound proven for that path (`None` without a path).
    pub fn bound(&self) -> Option<f64> {
        self.path.as_ref()?;
        self.iterations.last().map(|i| i.bound)
    }
}
