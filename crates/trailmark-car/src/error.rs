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
    /// The footprint at the start or the goal is free, but nearer an obstacle than the margin
    /// the planner grows it by between checked poses
    /// ([`HybridAStar::margin`](crate::HybridAStar::margin)).
    #[error(
        "the footprint at the {which} pose {pose:?} is free but within {margin} of an obstacle, the margin the planner keeps between the poses it checks (half a cell's step along the car's arc); move the pose away or use finer cells"
    )]
    WithinMargin {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The pose, `[x, y, heading]`.
        pose: [f64; 3],
        /// The margin, in the map's units.
        margin: f64,
    },
    /// The search ended without a path. `stop` says what is known: [`Stop::Unreachable`] (the
    /// only proof), [`Stop::LatticeExhausted`] (the lattice ran out; nothing proved), or the
    /// limit that stopped it.
    #[error("no path found ({}; {} expansions)", match stop {
        Stop::Unreachable => "proved unreachable: no chain of cells the car's reference point may occupy joins the start to the goal".to_string(),
        Stop::LatticeExhausted => "every state of the lattice of cells and heading bins was expanded without a free shot to the goal; nothing is proved: try more heading bins, finer cells or a longer analytic_expansion_max_length".to_string(),
        other => format!("stopped: {other:?}"),
    }, stats.expansions)]
    NoPath {
        /// Why the search ended.
        stop: Stop,
        /// What the search did.
        stats: HybridStats,
    },
}
