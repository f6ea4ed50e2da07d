//! The anytime searches' old limits, replaced by the shared
//! [`Termination`](trailmark_core::termination::Termination); kept working for one release.

#![allow(deprecated)]

use std::time::Duration;

use serde::{Deserialize, Serialize};
use trailmark_core::termination::{Stop, Termination};

/// When an anytime search stops before reaching ε = 1: wall time, expansions, or both.
#[deprecated(since = "0.2.0", note = "use trailmark_core::termination::Termination")]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Budget {
    /// Wall-clock time for the whole search.
    pub time: Option<Duration>,
    /// Expansions for the whole search.
    pub expansions: Option<u64>,
}

impl Budget {
    /// No limit: run until ε = 1.
    pub fn unlimited() -> Self {
        Budget::default()
    }

    /// Whether the budget is spent, `elapsed` and `expansions` into the search.
    pub fn spent(&self, elapsed: Duration, expansions: u64) -> Option<Stop> {
        if self.time.is_some_and(|t| elapsed >= t) {
            return Some(Stop::TimeLimit);
        }
        if self.expansions.is_some_and(|e| expansions >= e) {
            return Some(Stop::ExpansionLimit);
        }
        None
    }
}

/// The same limits as a termination: `time` as its time limit, `expansions` as its expansion
/// limit.
impl From<Budget> for Termination {
    fn from(budget: Budget) -> Self {
        Termination { time_limit: budget.time, max_expansions: budget.expansions, ..Termination::default() }
    }
}
