//! Why a simulation could not start.

use thiserror::Error;

use trailmark_core::grid::{Cell, GridHeuristic};
use trailmark_search::SearchError;

use crate::solve::DocumentError;

/// Why a simulation could not start.
#[derive(Debug, Error, PartialEq)]
pub enum NavigateError {
    /// The prior map's size differs from the true map's.
    #[error("the prior map is {prior:?} cells but the true map is {truth:?}")]
    PriorSize {
        /// Width and height of the prior map.
        prior: (u32, u32),
        /// Width and height of the true map.
        truth: (u32, u32),
    },
    /// The map has more than [`MAX_NAVIGATION_CELLS`](super::MAX_NAVIGATION_CELLS) cells.
    #[error("a {width} x {height} map is too large to navigate: at most {max} cells", max = super::MAX_NAVIGATION_CELLS)]
    TooLarge {
        /// The width in cells.
        width: u32,
        /// The height in cells.
        height: u32,
    },
    /// The start is outside the map or blocked in the true map.
    #[error("the start {0} is outside the map or blocked")]
    Start(Cell),
    /// The goal is outside the map or blocked in the true map.
    #[error("the goal {0} is outside the map or blocked")]
    Goal(Cell),
    /// The sensor radius is 0: the robot could not see where it steps.
    #[error("the sensor radius must be at least 1")]
    SensorRadius,
    /// A planner refused its input (an invalid epsilon schedule, for instance).
    #[error("planner: {0}")]
    Planner(#[from] SearchError<Cell>),
    /// The planner does not replan (a one-shot search or a sampling planner).
    #[error(
        "\"{planner}\" does not replan, so it cannot drive the robot: choose one of {choices}",
        choices = crate::solve::PlannerName::replanner_names()
    )]
    NotAReplanner {
        /// The planner's name.
        planner: &'static str,
    },
    /// The planner asks for a heuristic other than the octile distance, which guides every
    /// navigation planner on its 8-connected grid.
    #[error("navigation guides its planners by the octile distance, not {0:?}")]
    Heuristic(GridHeuristic),
    /// A limit of the planner's settings is out of range (as `solve` refuses it).
    #[error("planner settings: {0}")]
    Settings(#[from] DocumentError),
}
