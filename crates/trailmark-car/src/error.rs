//! What can go wrong planning for a car: settings, a footprint or poses out of range, ends in
//! collision, no path within the limits.

use thiserror::Error;
use trailmark_core::footprint::FootprintError;
use trailmark_core::termination::Stop;
use trailmark_map::MapError;

use crate::stats::HybridStats;

/// Why Hybrid A* could not plan, or would not start.
#[derive(Debug, Error)]
pub enum CarError {
    /// A setting out of its range; `expected` says what it must be.
    #[error("the setting {setting} must be {expected}, got {value}")]
    Setting {
        /// The setting's name in problem documents.
        setting: &'static str,
        /// What it must be.
        expected: &'static str,
        /// The value given.
        value: f64,
    },
    /// The footprint cannot be used.
    #[error("the footprint: {0}")]
    Footprint(#[from] FootprintError),
    /// The map cannot be used.
    #[error("the map: {0}")]
    Map(#[from] MapError),
    /// A pose with a NaN or infinite value.
    #[error("the {which} pose has a non-finite value: {pose:?}")]
    Pose {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The pose as given, `[x, y, heading]`.
        pose: [f64; 3],
    },
    /// The footprint at the start or the goal touches an obstacle or leaves the map.
    #[error("the footprint at the {which} pose {pose:?} touches an obstacle or leaves the map")]
    InCollision {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The pose, `[x, y, heading]`.
        pose: [f64; 3],
    },
    /// The search ended without a path: every reachable state was expanded, or it was
    /// stopped (`stop`).
    #[error("no path found ({}; {} expansions)", stop.map_or("every reachable state expanded".to_string(), |s| format!("{s:?}")), stats.expansions)]
    NoPath {
        /// Why the search stopped early, if it did.
        stop: Option<Stop>,
        /// What the search did.
        stats: HybridStats,
    },
}
