//! What a planner returns: a solution that cannot be misread, why the run stopped, what it did.
//!
//! A [`Plan`]'s [`Solution`] is exact (every motion valid, from a start to a state that
//! satisfies the goal), approximate (valid, but ending short of the goal, with the distance
//! left) or none. [`Plan::path`] and [`Plan::cost`] answer for exact solutions only, so the
//! easy call never mistakes an approximate path for an answer; match on
//! [`solution`](Plan::solution) to use an approximate one.

use std::time::Duration;

use thiserror::Error;

/// Why a state given to a planner was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rejection {
    /// A coordinate is NaN or infinite.
    NotFinite,
    /// Outside the space's bounds ([`StateSpace::satisfies_bounds`](crate::space::StateSpace::satisfies_bounds)).
    OutOfBounds,
    /// In bounds, but the validity checker refuses it (in collision).
    Invalid,
}

impl std::fmt::Display for Rejection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Rejection::NotFinite => "not finite",
            Rejection::OutOfBounds => "outside the space's bounds",
            Rejection::Invalid => "not valid (in collision)",
        })
    }
}

/// Why a planner did not run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlanError {
    /// The problem has no start state.
    #[error("the problem has no start state")]
    NoStart,
    /// A start state is refused.
    #[error("start {index} is {reason}")]
    InvalidStart {
        /// Which start, in the problem's order.
        index: usize,
        /// Why.
        reason: Rejection,
    },
    /// The goal state (or the only goal state a planner could sample) is refused.
    #[error("the goal is {0}")]
    InvalidGoal(Rejection),
    /// The planner grows a tree from the goal, and the goal gives no state to grow it from.
    #[error("{planner} grows a tree from the goal, which needs a goal that can sample states (Goal::sample)")]
    GoalNotSampleable {
        /// The planner.
        planner: &'static str,
    },
    /// A setting out of its range.
    #[error("{name} must be {expected}, got {value}")]
    InvalidOption {
        /// The setting.
        name: &'static str,
        /// Its range.
        expected: &'static str,
        /// The value given.
        value: f64,
    },
    /// A termination condition with no limit.
    #[error("the termination condition sets no limit (iterations, time or a user condition)")]
    NoLimit,
    /// A planner's own failure (for planners outside this crate).
    #[error("{0}")]
    Other(String),
}

/// The answer of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Solution<T> {
    /// From a start to a state that satisfies the goal; every state in bounds and valid, every
    /// motion valid.
    Exact {
        /// The states, a start first.
        path: Vec<T>,
        /// The sum of the motions' distances.
        cost: f64,
    },
    /// No state satisfying the goal was reached: the valid path from a start to the state
    /// nearest the goal.
    Approximate {
        /// The states, a start first.
        path: Vec<T>,
        /// The sum of the motions' distances.
        cost: f64,
        /// The goal's distance from the last state ([`Goal::distance`](crate::problem::Goal::distance)).
        goal_distance: f64,
    },
    /// Nothing to return.
    None,
}

impl<T> Solution<T> {
    /// Whether the solution reaches the goal.
    pub fn is_exact(&self) -> bool {
        matches!(self, Solution::Exact { .. })
    }

    /// The path of an exact or an approximate solution.
    pub fn any_path(&self) -> Option<&[T]> {
        match self {
            Solution::Exact { path, .. } | Solution::Approximate { path, .. } => Some(path),
            Solution::None => None,
        }
    }
}

/// What a run did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlanStats {
    /// Iterations (samples drawn).
    pub iterations: u64,
    /// States in the start tree and in the goal tree (RRT-Connect), or the roadmap's milestones
    /// (PRM; its edges are [`Prm::edge_count`](crate::Prm::edge_count)).
    pub tree_sizes: [usize; 2],
    /// State and motion validity checks.
    pub collision_checks: u64,
    /// Time to the first solution.
    pub time_to_solution: Option<Duration>,
    /// Time of the whole run.
    pub elapsed: Duration,
}

/// A new best solution of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Improvement {
    /// The iteration that found it.
    pub iteration: u64,
    /// The time since the start of the run.
    pub time: Duration,
    /// Its cost.
    pub cost: f64,
}

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan<T> {
    /// The answer.
    pub solution: Solution<T>,
    /// Why the run stopped.
    pub stop: trailmark_core::termination::Stop,
    /// The cost of the best solution each time it improved (one entry for planners that stop at
    /// their first solution; empty without one).
    pub history: Vec<Improvement>,
    /// What the run did.
    pub stats: PlanStats,
}

impl<T> Plan<T> {
    /// The path of an exact solution; `None` when the goal was not reached.
    pub fn path(&self) -> Option<&[T]> {
        match &self.solution {
            Solution::Exact { path, .. } => Some(path),
            _ => None,
        }
    }

    /// The cost of an exact solution; `None` when the goal was not reached.
    pub fn cost(&self) -> Option<f64> {
        match self.solution {
            Solution::Exact { cost, .. } => Some(cost),
            _ => None,
        }
    }

    /// Whether the goal was reached.
    pub fn is_exact(&self) -> bool {
        self.solution.is_exact()
    }
}
