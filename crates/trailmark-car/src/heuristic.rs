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
//!   Nav2 maps (docs/car.md), and Hybrid A*'s paths are good rather than optimal anyway. Merged
//!   two by two, as Smac downsamples, the Dijkstra took a fifth of the time, but a merged cell
//!   open wherever one of its cells is opens gaps the car cannot pass, and the hard queries
//!   expanded up to 5.7 times more states (docs/car.md).
//! - **Without obstacles**: the length of the shortest Reeds-Shepp (or, forward only, Dubins)
//!   path to the goal, times the cheapest price of a metre on the map.

use trailmark_core::dubins::DubinsPath;
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::Pose;
use trailmark_core::grid::{Cell, Connectivity, Grid};
use trailmark_core::reeds_shepp::ReedsSheppPath;
use trailmark_graph::GridGraph;
use trailmark_search::Search;

use trailmark_map::MapError;

use crate::error::CarError;
use crate::map::CarMap;

/// The grid the estimate around the obstacles is computed on, made once per planner: the map's
/// prices, with the cells closed where every point lies closer to an obstacle than the
/// footprint's inscribed radius.
#[derive(Debug, Clone)]
pub(crate) struct HeuristicGrid {
    grid: Grid,
    resolution: f64,
}

impl HeuristicGrid {
    /// The grid of `map` for `footprint`: cells closed where every point lies closer to an
    /// obstacle than its inscribed radius, and obstacle cells closed when the footprint holds
    /// its reference point. A footprint that does not (a forklift planned by its forks' tips)
    /// may have its reference point over an obstacle: such cells stay open at the map's least
    /// price, so that the estimate stays below the cost and a closed way stays a proof.
    pub fn new(map: &CarMap, footprint: &Footprint) -> Result<Self, CarError> {
        let inscribed = footprint.inscribed_radius()?;
        let over_obstacles =
            if footprint.holds_reference_point() { f64::INFINITY } else { map.least_price() };
        let (w, h) = map.size();
        let costs = (0..w * h)
            .map(|i| match map.price(i) {
                _ if map.clearance_at_most(i) < inscribed => f64::INFINITY,
                price if price.is_finite() => price,
                _ => over_obstacles,
            })
            .collect();
        let grid = Grid::from_costs(w, h, costs).map_err(MapError::from)?;
        Ok(HeuristicGrid { grid, resolution: map.resolution() })
    }
}

/// The cost from each cell to the goal's cell around the obstacles, per cell index.
#[derive(Debug, Clone)]
pub(crate) struct ObstacleHeuristic {
    cost: Vec<f64>,
}

impl ObstacleHeuristic {
    /// The costs to the map's cell `goal` (a cell index): a Dijkstra from it over `grid`.
    pub fn new(grid: &HeuristicGrid, goal: usize) -> Self {
        let w = grid.grid.width() as usize;
        let mut cost = vec![f64::INFINITY; w * grid.grid.height() as usize];
        let graph = GridGraph::new(&grid.grid, Connectivity::Eight);
        let mut search = Search::new();
        // The goal's cell is open whenever the goal pose is valid; were it closed, no cell
        // would have a cost and the planner would report no path.
        let goal = Cell::new((goal % w) as u32, (goal / w) as u32);
        if search.dijkstra_all(&graph, goal).is_err() {
            // A search that failed proves nothing: no estimate, rather than one that closes all.
            cost.fill(0.0);
            return ObstacleHeuristic { cost };
        }
        for (i, slot) in cost.iter_mut().enumerate() {
            let cell = Cell::new((i % w) as u32, (i / w) as u32);
            if let Some(c) = search.cost_to(&graph, cell) {
                *slot = c * grid.resolution;
            }
        }
        ObstacleHeuristic { cost }
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
