//! What a run did, and its picture.

use std::time::Duration;

use serde::{Deserialize, Serialize};

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::svg::GridSvg;

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NavigationOutcome {
    /// The robot stands on the goal.
    Reached,
    /// Greedy mapping: no unvisited cell is reachable any more.
    Explored,
    /// No path exists in the robot's map. With an optimistic prior (free space, or any map
    /// that blocks no truly free cell) the goal is truly unreachable.
    Unreachable,
    /// The step limit ran out.
    StepLimit,
}

/// What a run did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NavigationReport {
    /// The planner's name.
    pub planner: String,
    /// How the run ended.
    pub outcome: NavigationOutcome,
    /// Moves made.
    pub steps: usize,
    /// The cost of the trajectory (cell costs of the true map).
    pub distance: Cost,
    /// Planning episodes (one per step, plus the first).
    pub plans: usize,
    /// Node expansions summed over every plan.
    pub expansions: u64,
    /// Planning time summed over every plan (sensing and moving excluded).
    pub planning_time: Duration,
    /// The longest single plan.
    pub max_plan_time: Duration,
    /// Cells whose true state the robot learned differed from its map.
    pub discoveries: usize,
    /// The cells the robot stood on, start first.
    pub trajectory: Vec<Cell>,
    /// The cost of each plan, from where the robot stood to the target in what it knew then
    /// (`inf`: no path).
    #[serde(skip)]
    pub plan_costs: Vec<Cost>,
    /// The suboptimality bound of each plan: 1 for the optimal planners, AD*'s epsilon.
    #[serde(skip)]
    pub plan_bounds: Vec<f64>,
    /// The expansions of each plan.
    #[serde(skip)]
    pub plan_expansions: Vec<u64>,
    /// The time of each plan (the first includes making the planner).
    #[serde(skip)]
    pub plan_times: Vec<Duration>,
    /// Whether each cell of the grid (row-major) was ever sensed.
    #[serde(skip)]
    pub sensed: Vec<bool>,
}

impl NavigationReport {
    /// Whether the robot reached its goal (or, mapping, visited all it could reach).
    pub fn reached(&self) -> bool {
        matches!(self.outcome, NavigationOutcome::Reached | NavigationOutcome::Explored)
    }

    /// The mean planning time per plan.
    pub fn mean_plan_time(&self) -> Duration {
        self.planning_time / u32::try_from(self.plans.max(1)).unwrap_or(u32::MAX)
    }

    /// An SVG of the true map, what the robot sensed (shaded), the obstacles it never saw
    /// (pale), and its trajectory.
    pub fn svg(&self, truth: &Grid, goal: Option<Cell>) -> String {
        let w = truth.width() as usize;
        let sensed: Vec<Cell> =
            truth.cells().filter(|c| self.sensed[c.y as usize * w + c.x as usize]).collect();
        let unseen = truth.cells().filter(|c| !self.sensed[c.y as usize * w + c.x as usize]);
        let mut svg = GridSvg::new(truth)
            .cell_size((1024.0 / f64::from(truth.width().max(truth.height()))).clamp(1.0, 24.0))
            .explored(sensed)
            .unknown(unseen)
            .path(&self.trajectory)
            .title(format!("{}: {:?} after {} steps", self.planner, self.outcome, self.steps));
        if let Some(&s) = self.trajectory.first() {
            svg = svg.start(s);
        }
        if let Some(g) = goal {
            svg = svg.goal(g);
        }
        svg.to_svg()
    }
}
