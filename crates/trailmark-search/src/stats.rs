//! What a search did: counters and time.

use std::ops::AddAssign;
use std::time::Duration;

use serde::{Deserialize, Serialize};

/// Counters and wall-clock time of one search.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct SearchStats {
    /// Nodes expanded: taken from the open list (or queue, or stack) and their successors
    /// generated. The goal, once reached, is not expanded.
    pub expansions: u64,
    /// Nodes inserted into the open list (queue, stack), re-insertions included.
    pub pushes: u64,
    /// Keys lowered in the open list because a cheaper path to an open node was found.
    pub decreases: u64,
    /// Expanded nodes put back in the open list because a cheaper path to them was found (only
    /// with an inconsistent heuristic).
    pub reopenings: u64,
    /// Wall-clock time of the search.
    pub elapsed: Duration,
}

/// Adds the counters and times of another search (totals over several calls).
impl AddAssign for SearchStats {
    fn add_assign(&mut self, other: SearchStats) {
        self.expansions += other.expansions;
        self.pushes += other.pushes;
        self.decreases += other.decreases;
        self.reopenings += other.reopenings;
        self.elapsed += other.elapsed;
    }
}
