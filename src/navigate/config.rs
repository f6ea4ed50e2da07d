//! How a simulation runs: the planner, the target, the sensor and the world's follower.

use serde::{Deserialize, Serialize};

use trailmark_core::grid::{Cell, GridHeuristic};

use crate::navigate::error::NavigateError;
use crate::solve::PlannerSpec;

/// Errors when the planner does not replan ([`PlannerSpec::replans`]: asked first, so that a
/// one-shot planner is named as such and not for its heuristic), when its settings are out of
/// range (its limits, as `solve` checks them) or it asks for a heuristic other than the octile
/// distance that guides every navigation planner.
pub(super) fn check_planner(planner: &PlannerSpec) -> Result<(), NavigateError> {
    if !planner.replans() {
        return Err(NavigateError::NotAReplanner { planner: planner.name() });
    }
    planner.check_limits()?;
    match planner.heuristic().0 {
        None | Some(GridHeuristic::Octile) => Ok(()),
        Some(heuristic) => Err(NavigateError::Heuristic(heuristic)),
    }
}

/// Where the robot is going.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Target {
    /// A goal cell.
    Cell(Cell),
    /// Greedy mapping: visit every reachable cell, nearest unvisited first.
    Explore,
}

/// How the simulation runs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Navigation {
    /// The planner that drives the robot: a planner of the solve registry that can replan
    /// ([`PlannerSpec::replanner`]), as in a problem document (`{"name": "dstar_lite"}`):
    /// `astar` (A* from scratch at every step), `lpa_star` (restarted each time the start
    /// moves: a forward search cannot keep its values when its start moves), `dstar_lite`, or
    /// `ad_star`, whose `max_expansions` and `time_limit_s` bound each step's improvement from
    /// `epsilon` down by `epsilon_step` (when they stop it before a path, the iteration in
    /// progress is completed anyway, since the robot needs a path to move; a budget of 0 makes
    /// one iteration per step). Every planner is guided by the octile distance (its
    /// `heuristic` may be left out or be `octile`).
    pub planner: PlannerSpec,
    /// Cells within this Chebyshev distance are sensed each step (at least 1).
    pub sensor_radius: u32,
    /// An obstacle that occupies the cell the robot stood on this many steps ago (when that
    /// cell is free and is neither the robot's cell nor the goal); `None` for a static world.
    pub follower_lag: Option<u32>,
    /// The most steps before giving up (`None`: 20 times the number of cells).
    pub max_steps: Option<usize>,
}

impl Default for Navigation {
    fn default() -> Self {
        Navigation {
            planner: PlannerSpec::DStarLite { heuristic: None },
            sensor_radius: 1,
            follower_lag: None,
            max_steps: None,
        }
    }
}
