//! What a Hybrid A* search did.

use std::time::Duration;

use serde::{Deserialize, Serialize};

/// Counters and times of one Hybrid A* query.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct HybridStats {
    /// States taken off the open list and expanded.
    pub expansions: u64,
    /// Motions tried from expanded states (each checked for collisions unless it left the map).
    pub motions: u64,
    /// Footprint checks made (poses along motions and analytic shots).
    pub footprint_checks: u64,
    /// Of those, the ones that had to look at the footprint's cells (the pose was near an
    /// obstacle); the others were cleared by the distance to the nearest obstacle alone.
    pub footprint_rasters: u64,
    /// Analytic shots to the goal tried, the last one successful when a path was found.
    pub analytic_attempts: u64,
    /// Time spent on the obstacle heuristic (a Dijkstra from the goal over the map's cells).
    pub heuristic_time: Duration,
    /// The cost of the path the search found, before smoothing.
    pub search_cost: f64,
    /// Time spent smoothing the path.
    pub smoothing_time: Duration,
    /// Time of the whole query.
    pub time: Duration,
}
