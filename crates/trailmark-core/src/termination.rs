//! When a long-running planner stops: limits on iterations, expansions, time and cost, the
//! caller's own condition, and why a run stopped. One vocabulary for the anytime searches of
//! `trailmark-search` and the sampling planners of `trailmark-sample`.
//!
//! A [`Termination`] is OMPL's `PlannerTerminationCondition`: a planner asks it between
//! iterations and, through a [`Watch`], inside them. What a planner counts:
//!
//! - **iterations**: a sampling planner's samples drawn; an anytime search's improvement
//!   iterations (one per inflation), counted in the call that runs them;
//! - **expansions**: the nodes a search takes from its open list; sampling planners expand none,
//!   so an expansion limit never stops them (but a limit of 0, which stops at once);
//! - **time**: wall-clock time since the call began;
//! - **target cost**: planners that improve a solution (RRT*, PRM*, ARA*, AD*) stop once the best
//!   path costs at most this;
//! - **condition**: a closure that sees the run's [`Progress`] and says when to stop.
//!
//! Each planner's documentation says which limits it honours. Sampling planners refuse a
//! termination that sets no iteration limit, time limit or condition (it might never stop); the
//! anytime searches accept one (they stop at the optimum on their own).
//!
//! ```
//! use std::sync::Arc;
//! use std::sync::atomic::{AtomicBool, Ordering};
//! use std::time::Duration;
//! use trailmark_core::termination::Termination;
//!
//! // At most 50,000 iterations or 2 s, and stop early when another thread says so.
//! let cancel = Arc::new(AtomicBool::new(false));
//! let flag = Arc::clone(&cancel);
//! let limit = Termination::iterations(50_000)
//!     .and_time(Duration::from_secs(2))
//!     .or_when(move |_| flag.load(Ordering::Relaxed));
//! assert!(limit.is_bounded());
//! assert!(!Termination::unlimited().is_bounded());
//! ```

use std::sync::Arc;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

/// When a planner gives up: whichever limit comes first. No limit at all
/// ([`Termination::unlimited`], the default) lets a planner that ends on its own run to its end.
#[derive(Clone, Default)]
pub struct Termination {
    /// Iterations: samples drawn (sampling planners), improvement iterations (anytime searches).
    pub max_iterations: Option<u64>,
    /// Node expansions (searches).
    pub max_expansions: Option<u64>,
    /// Wall-clock time.
    pub time_limit: Option<Duration>,
    /// Planners that improve their solution: stop once the best path costs at most this.
    pub target_cost: Option<f64>,
    /// A user condition, asked between iterations and inside them: stop when it returns `true`.
    pub condition: Option<Condition>,
}

/// A user stopping condition: asked with the run's progress.
pub type Condition = Arc<dyn Fn(&Progress) -> bool + Send + Sync>;

/// How far a run has come, as a [`Condition`] sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Iterations begun.
    pub iterations: u64,
    /// Node expansions (0 for sampling planners).
    pub expansions: u64,
    /// Time since the run began.
    pub elapsed: Duration,
    /// The best solution's cost so far (`None` before the first solution).
    pub best_cost: Option<f64>,
}

/// Why a run stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// A planner that stops at its first solution found one.
    Solved,
    /// An anytime search's last iteration ran at inflation 1: the path is optimal (for an
    /// admissible, consistent heuristic).
    Optimal,
    /// A search proved the goal unreachable (the only stop that proves it).
    Unreachable,
    /// The best solution reached the termination's target cost.
    TargetCost,
    /// The iteration limit. Without a solution, nothing is known about the goal.
    IterationLimit,
    /// The expansion limit. Without a solution, nothing is known about the goal.
    ExpansionLimit,
    /// The time limit. Without a solution, nothing is known about the goal.
    TimeLimit,
    /// The caller's condition asked to stop (or, for a planner asked for a given number of
    /// iterations, they are done).
    Caller,
    /// A search over a lattice that stands for a continuous problem (Hybrid A*'s cells and
    /// heading bins) expanded every state it reached without a path. Nothing is proved: a
    /// finer lattice (more heading bins, smaller cells) or longer shots to the goal may find one.
    LatticeExhausted,
}

impl std::fmt::Debug for Termination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Termination")
            .field("max_iterations", &self.max_iterations)
            .field("max_expansions", &self.max_expansions)
            .field("time_limit", &self.time_limit)
            .field("target_cost", &self.target_cost)
            .field("condition", &self.condition.as_ref().map(|_| "user closure"))
            .finish()
    }
}

/// A copy of the termination, so that planners can take `&termination` or `termination` alike.
impl From<&Termination> for Termination {
    fn from(termination: &Termination) -> Self {
        termination.clone()
    }
}

impl Termination {
    /// No limit: a planner that ends on its own (an anytime search, at the optimum) runs to its
    /// end; a sampling planner refuses it.
    pub fn unlimited() -> Self {
        Termination::default()
    }

    /// Stop after `n` iterations.
    pub fn iterations(n: u64) -> Self {
        Termination::default().and_iterations(n)
    }

    /// Stop after `n` expansions.
    pub fn expansions(n: u64) -> Self {
        Termination::default().and_expansions(n)
    }

    /// Stop after `limit`.
    pub fn time(limit: Duration) -> Self {
        Termination::default().and_time(limit)
    }

    /// Stop when `condition` returns `true` (and at no other limit).
    pub fn when(condition: impl Fn(&Progress) -> bool + Send + Sync + 'static) -> Self {
        Termination::default().or_when(condition)
    }

    /// These limits, and also stop after `n` iterations.
    pub fn and_iterations(self, n: u64) -> Self {
        Termination { max_iterations: Some(n), ..self }
    }

    /// These limits, and also stop after `n` expansions.
    pub fn and_expansions(self, n: u64) -> Self {
        Termination { max_expansions: Some(n), ..self }
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

    /// Whether an iteration limit, a time limit or a condition is set: what a sampling planner
    /// needs to be sure to stop (a target cost may never be reached, and sampling planners count
    /// no expansions).
    pub fn is_bounded(&self) -> bool {
        self.max_iterations.is_some() || self.time_limit.is_some() || self.condition.is_some()
    }

    /// Whether `expansions` reach the expansion limit: the one test a search's inner loop makes
    /// at every expansion ([`Watch::interrupted`] makes the others).
    #[inline]
    pub fn expansions_spent(&self, expansions: u64) -> bool {
        self.max_expansions.is_some_and(|limit| expansions >= limit)
    }
}

/// A run's clock and counters, checked against its [`Termination`]: what a planner's loops ask.
///
/// ```
/// use trailmark_core::termination::{Stop, Termination, Watch};
///
/// let limit = Termination::iterations(2);
/// let mut watch = Watch::start(&limit);
/// assert_eq!(watch.next_iteration(), None);
/// assert_eq!(watch.next_iteration(), None);
/// assert_eq!(watch.next_iteration(), Some(Stop::IterationLimit));
/// assert_eq!(watch.iterations(), 2);
/// ```
#[derive(Debug, Clone)]
pub struct Watch<'t> {
    termination: &'t Termination,
    clock: Instant,
    /// Iterations begun, expansions so far and the best cost, as the condition is told.
    iterations: u64,
    expansions: u64,
    best_cost: Option<f64>,
}

impl<'t> Watch<'t> {
    /// Starts the clock.
    pub fn start(termination: &'t Termination) -> Self {
        Watch { termination, clock: Instant::now(), iterations: 0, expansions: 0, best_cost: None }
    }

    /// The termination asked.
    pub fn termination(&self) -> &'t Termination {
        self.termination
    }

    /// The time since the start.
    pub fn elapsed(&self) -> Duration {
        self.clock.elapsed()
    }

    /// Iterations begun.
    pub fn iterations(&self) -> u64 {
        self.iterations
    }

    /// The run's progress now.
    pub fn progress(&self) -> Progress {
        Progress {
            iterations: self.iterations,
            expansions: self.expansions,
            elapsed: self.clock.elapsed(),
            best_cost: self.best_cost,
        }
    }

    /// Records a new best cost.
    pub fn improved(&mut self, cost: f64) {
        self.best_cost = Some(cost);
    }

    /// Records the expansions made so far.
    #[inline]
    pub fn set_expansions(&mut self, expansions: u64) {
        self.expansions = expansions;
    }

    /// Counts an iteration begun without asking the termination: the first iteration of a
    /// planner that always makes one.
    pub fn begin_iteration(&mut self) {
        self.iterations += 1;
    }

    /// Before an iteration: why the run must stop, if it must (the iteration limit, the target
    /// cost, then as [`interrupted`](Self::interrupted)); else counts the iteration begun.
    pub fn next_iteration(&mut self) -> Option<Stop> {
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

    /// Within an iteration: whether the time limit has passed, the expansions recorded reach
    /// their limit, or the condition asks to stop (in that order). The clock is read only when
    /// a time limit or a condition needs it.
    pub fn interrupted(&self) -> Option<Stop> {
        let t = self.termination;
        if t.time_limit.is_some_and(|limit| self.clock.elapsed() >= limit) {
            return Some(Stop::TimeLimit);
        }
        if t.expansions_spent(self.expansions) {
            return Some(Stop::ExpansionLimit);
        }
        if t.condition.as_ref().is_some_and(|stop| stop(&self.progress())) {
            return Some(Stop::Caller);
        }
        None
    }
}
