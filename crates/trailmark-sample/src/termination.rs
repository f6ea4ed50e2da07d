//! When a planner stops: limits on iterations, time and cost, and the caller's own condition.
//!
//! A [`Termination`] is OMPL's `PlannerTerminationCondition`: the planners ask it before every
//! iteration, and ask its time limit and condition again inside an iteration, before every
//! motion check and every sampler attempt (the connect phase of RRT-Connect, RRT*'s parent
//! search and rewiring, a roadmap's connections). A run therefore overshoots its time limit by
//! at most one motion check and one nearest-neighbour query; the harness measures the overshoot.
//!
//! The condition sees the run's [`Progress`] each time it is asked, so it is also the place to
//! report progress.
//!
//! ```
//! use std::sync::Arc;
//! use std::sync::atomic::{AtomicBool, Ordering};
//! use std::time::Duration;
//! use trailmark_sample::termination::Termination;
//!
//! // At most 50,000 iterations or 2 s, and stop early when another thread says so.
//! let cancel = Arc::new(AtomicBool::new(false));
//! let flag = Arc::clone(&cancel);
//! let limit = Termination::iterations(50_000)
//!     .and_time(Duration::from_secs(2))
//!     .or_when(move |_| flag.load(Ordering::Relaxed));
//! assert!(limit.is_bounded());
//! ```

use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::plan::Stop;

/// When a planner gives up (whichever comes first). At least one limit must be set: iterations,
/// time or a user condition.
#[derive(Clone, Default)]
pub struct Termination {
    /// Iterations (samples drawn).
    pub max_iterations: Option<u64>,
    /// Wall-clock time.
    pub time_limit: Option<Duration>,
    /// Planners that improve their solution (RRT*, PRM*): stop once the best path costs at most
    /// this (with a limit above as well).
    pub target_cost: Option<f64>,
    /// A user condition, asked before every iteration and between the motion checks of one:
    /// stop when it returns `true`.
    pub condition: Option<Condition>,
}

/// A user stopping condition: asked with the run's progress.
pub type Condition = Arc<dyn Fn(&Progress) -> bool + Send + Sync>;

/// How far a run has come, as a [`Condition`] sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Iterations done.
    pub iterations: u64,
    /// Time since the run began.
    pub elapsed: Duration,
    /// The best solution's cost so far (`None` before the first solution).
    pub best_cost: Option<f64>,
}

impl std::fmt::Debug for Termination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Termination")
            .field("max_iterations", &self.max_iterations)
            .field("time_limit", &self.time_limit)
            .field("target_cost", &self.target_cost)
            .field("condition", &self.condition.as_ref().map(|_| "user closure"))
            .finish()
    }
}

impl Termination {
    /// Stop after `n` iterations.
    pub fn iterations(n: u64) -> Self {
        Termination { max_iterations: Some(n), ..Termination::default() }
    }

    /// Stop after `limit`.
    pub fn time(limit: Duration) -> Self {
        Termination { time_limit: Some(limit), ..Termination::default() }
    }

    /// Stop when `condition` returns `true` (and at no other limit).
    pub fn when(condition: impl Fn(&Progress) -> bool + Send + Sync + 'static) -> Self {
        Termination::default().or_when(condition)
    }

    /// These limits, and also stop after `n` iterations.
    pub fn and_iterations(self, n: u64) -> Self {
        Termination { max_iterations: Some(n), ..self }
    }

    /// These limits, and also stop after `limit`.
    pub fn and_time(self, limit: Duration) -> Self {
        Termination { time_limit: Some(limit), ..self }
    }

    /// These limits, and also stop once the best path costs at most `cost`.
    pub fn and_target_cost(self, cost: f64) -> Self {
        Termination { target_cost: Some(cost), ..self }
    }

    /// These limits, and also stop when `condition` returns `true` (replacing any earlier
    /// condition).
    pub fn or_when(self, condition: impl Fn(&Progress) -> bool + Send + Sync + 'static) -> Self {
        Termination { condition: Some(Arc::new(condition)), ..self }
    }

    /// Whether any limit is set (a target cost alone is not one: it may never be reached).
    pub fn is_bounded(&self) -> bool {
        self.max_iterations.is_some() || self.time_limit.is_some() || self.condition.is_some()
    }
}

/// A run's clock and its termination: what the planners' loops ask.
pub(crate) struct Watch<'t> {
    termination: &'t Termination,
    clock: Instant,
    /// Iterations begun, and the best cost, as the condition is told.
    iterations: u64,
    best_cost: Option<f64>,
}

impl<'t> Watch<'t> {
    /// Starts the clock.
    pub(crate) fn start(termination: &'t Termination) -> Self {
        Watch { termination, clock: Instant::now(), iterations: 0, best_cost: None }
    }

    /// The termination asked.
    pub(crate) fn termination(&self) -> &'t Termination {
        self.termination
    }

    /// The time since the start.
    pub(crate) fn elapsed(&self) -> Duration {
        self.clock.elapsed()
    }

    /// Iterations begun.
    pub(crate) fn iterations(&self) -> u64 {
        self.iterations
    }

    /// Records a new best cost.
    pub(crate) fn improved(&mut self, cost: f64) {
        self.best_cost = Some(cost);
    }

    /// Before an iteration: why the run must stop, if it must; else counts the iteration.
    pub(crate) fn next_iteration(&mut self) -> Option<Stop> {
        let t = self.termination;
        if t.max_iterations.is_some_and(|n| self.iterations >= n) {
            return Some(Stop::IterationLimit);
        }
        if t.target_cost.is_some_and(|target| self.best_cost.is_some_and(|c| c <= target)) {
            return Some(Stop::TargetCost);
        }
        if let Some(stop) = self.interrupted() {
            return Some(stop);
        }
        self.iterations += 1;
        None
    }

    /// Within an iteration: whether the time limit has passed or the condition asks to stop.
    pub(crate) fn interrupted(&self) -> Option<Stop> {
        let t = self.termination;
        if t.time_limit.is_some_and(|limit| self.clock.elapsed() >= limit) {
            return Some(Stop::TimeLimit);
        }
        let progress = || Progress {
            iterations: self.iterations,
            elapsed: self.clock.elapsed(),
            best_cost: self.best_cost,
        };
        if t.condition.as_ref().is_some_and(|stop| stop(&progress())) {
            return Some(Stop::Caller);
        }
        None
    }
}
