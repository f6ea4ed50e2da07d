//! Hybrid A*'s estimate of the cost to the goal: the larger of two lower bounds (Dolgov et al.
//! 2010), one that knows the obstacles but not the car's turning, one that knows the turning
//! but not the obstacles.
//!
//! - **With obstacles**: the least cost from each cell to the goal's cell over the map's
//!   8-connected grid (a Dijkstra from the goal, once per query), where a cell is closed when
//!   every point of it lies closer to an obstacle than the footprint's inscribed radius. As in
//!   Smac, the grid's costs are taken as they are, although a grid path runs up to 8.2% longer
//!   than the straight line at its angle (moves at 0 and 45 degrees only): divided by 1.0824
//!   they would never overestimate, but the search then expanded 2-5 times more states on the
//!   Nav2 maps (docs/car.md), and Hybrid A*'s paths are good rather than optimal anyway.
//! - **Without obstacles**: the length of the shortest Reeds-Shepp (or, forward only, Dubins)
//!   path to the goal, times the cheapest price of a metre on the map.

use trailmark_core::dubins::DubinsPath;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::grid::{Cell, Connectivity};
use trailmark_core::reeds_shepp::ReedsSheppPath;
use trailmark_graph::GridGraph;
use trailmark_search::Search;

use crate::error::CarError;
use crate::map::CarMap;

/// The cost from each cell to the goal's cell around the obstacles, per cell index.
#[derive(Debug, Clone)]
pub(crate) struct ObstacleHeuristic {
    cost: Vec<f64>,
}

impl ObstacleHeuristic {
    /// The costs to the cell holding `goal` (map coordinates), for a footprint of `inscribed`
    /// radius.
    pub fn new(map: &CarMap, goal: Point, inscribed: f64) -> Result<Self, CarError> {
        let grid = map.grid_with(|i| map.clearance_at_most(i) < inscribed)?;
        let (w, h) = map.size();
        let mut cost = vec![f64::INFINITY; w * h];
        let Some(goal_index) = map.cell_index(goal) else { return Ok(ObstacleHeuristic { cost }) };
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let goal_cell = Cell::new((goal_index % w) as u32, (goal_index / w) as u32);
        let mut search = Search::new();
        // The goal's cell is open whenever the goal pose is valid; were it closed, no cell
        // would have a cost and the planner would report no path.
        if search.dijkstra_all(&graph, goal_cell).is_ok() {
            let scale = map.resolution();
            for (i, slot) in cost.iter_mut().enumerate() {
                let cell = Cell::new((i % w) as u32, (i / w) as u32);
                if let Some(c) = search.cost_to(&graph, cell) {
                    *slot = c * scale;
                }
            }
        }
        Ok(ObstacleHeuristic { cost })
    }

    /// The estimate at cell `index`, `+inf` where the goal cannot be reached.
    #[inline]
    pub fn at(&self, index: usize) -> f64 {
        self.cost[index]
    }
}

/// The length of the shortest curve from `from` to `to` for a car of `radius`, in reverse too
/// when `reverse` (0 when the poses are out of the curves' range, which keeps it a lower bound).
pub(crate) fn curve_length(from: &Pose, to: &Pose, radius: f64, reverse: bool) -> f64 {
    let length = if reverse {
        ReedsSheppPath::shortest_length(from, to, radius)
    } else {
        DubinsPath::shortest_length(from, to, radius).map_err(Into::into)
    };
    length.unwrap_or(0.0)
}
