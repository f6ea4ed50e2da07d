//! How a simulation runs: the planner, the target, the sensor and the world's follower.

use serde::{Deserialize, Serialize};

use trailmark_core::cost::Cost;
use trailmark_core::grid::Cell;
use trailmark_core::termination::Termination;
use trailmark_search::{AdStar, DStarLite, EpsilonSchedule, LpaStar, RepeatedAStar, Replanner, SearchError};

use crate::navigate::graph::NavGraph;

/// Which planner drives the robot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", rename_all = "snake_case")]
pub enum PlannerChoice {
    /// A* from scratch at every step.
    #[serde(rename = "astar")]
    AStar,
    /// LPA*, restarted each time the start moves.
    LpaStar,
    /// D* Lite.
    DStarLite,
    /// AD*: each step improves within `expansions_per_step` expansions, from `epsilon` down by
    /// `epsilon_step`; when the budget runs out before a path, the iteration in progress is
    /// completed anyway (the robot needs a path to move). A budget of 0 makes one iteration per
    /// step.
    AdStar {
        /// The initial inflation.
        #[serde(default = "default_epsilon")]
        epsilon: f64,
        /// The decrease per iteration.
        #[serde(default = "default_epsilon_step")]
        epsilon_step: f64,
        /// The expansion budget of one step's improvement; `None` improves to epsilon = 1.
        #[serde(default)]
        expansions_per_step: Option<u64>,
    },
}

fn default_epsilon() -> f64 {
    EpsilonSchedule::default().initial
}

fn default_epsilon_step() -> f64 {
    EpsilonSchedule::default().step
}

impl PlannerChoice {
    /// Errors when the planner's settings are invalid (an AD* epsilon schedule), before anything
    /// runs.
    pub(super) fn check(&self) -> Result<(), SearchError<Cell>> {
        match *self {
            PlannerChoice::AdStar { epsilon, epsilon_step, .. } => {
                EpsilonSchedule::new(epsilon, epsilon_step).check::<Cell>()
            }
            _ => Ok(()),
        }
    }

    /// The planner, from `start` to `target` on the robot's graph with the heuristic `h`. Each
    /// is kept between steps and told what changed; LPA* restarts when the robot moves, since a
    /// forward search cannot keep its values when its start moves.
    pub(super) fn replanner<H>(
        &self,
        graph: &NavGraph,
        start: Cell,
        target: Cell,
        h: H,
    ) -> Result<Box<dyn Replanner<NavGraph>>, SearchError<Cell>>
    where
        H: Fn(Cell, Cell) -> Cost + Copy + 'static,
    {
        Ok(match *self {
            PlannerChoice::AStar => Box::new(RepeatedAStar::new(graph, start, target, h)?),
            PlannerChoice::LpaStar => Box::new(LpaStar::new(graph, start, target, h)?),
            PlannerChoice::DStarLite => Box::new(DStarLite::new(graph, start, target, h)?),
            PlannerChoice::AdStar { epsilon, epsilon_step, expansions_per_step } => {
                let schedule = EpsilonSchedule::new(epsilon, epsilon_step);
                let per_plan = Termination { max_expansions: expansions_per_step, ..Termination::default() };
                Box::new(AdStar::new(graph, start, target, h, schedule)?.with_termination_per_plan(per_plan))
            }
        })
    }

    /// The planner's name as in the problem JSON (`"astar"`, `"lpa_star"`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            PlannerChoice::AStar => "astar",
            PlannerChoice::LpaStar => "lpa_star",
            PlannerChoice::DStarLite => "dstar_lite",
            PlannerChoice::AdStar { .. } => "ad_star",
        }
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
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Navigation {
    /// The planner.
    pub planner: PlannerChoice,
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
            planner: PlannerChoice::DStarLite,
            sensor_radius: 1,
            follower_lag: None,
            max_steps: None,
        }
    }
}
