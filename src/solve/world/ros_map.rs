//! ROS-map worlds as documents give them: a map_server map made into a Nav2-style costmap
//! around the robot, its travel costs, and points in metres on its cells.

use std::path::Path;

use trailmark_core::geometry::Point;
use trailmark_core::grid::{Cell, Grid};
use trailmark_map::{
    Costmap, CostmapOptions, Footprint, INSCRIBED, Inflation, MapError, TravelCost, Unknown, load_map,
};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::RosMapSpec;

/// Nav2's default `robot_radius`, in metres.
pub const DEFAULT_ROBOT_RADIUS: f64 = 0.1;

/// Nav2's default `inflation_radius`, in metres.
pub const DEFAULT_INFLATION_RADIUS: f64 = 0.55;

/// Nav2's default `cost_scaling_factor`, per metre.
pub const DEFAULT_COST_SCALING_FACTOR: f64 = 10.0;

/// Smac 2-D's default `cost_travel_multiplier`.
pub const DEFAULT_COST_FACTOR: f64 = 2.0;

/// The largest `cost_factor` a ROS-map world takes.
pub const MAX_COST_FACTOR: f64 = 1e6;

/// The costmap of a ROS-map world: the map loaded (relative paths against `base_dir`), its
/// unknown cells read as the world says, inflated around the robot.
pub fn ros_costmap(world: &RosMapSpec, base_dir: impl AsRef<Path>) -> Result<Costmap, SolveError> {
    let footprint = match (&world.robot_radius, &world.footprint) {
        (Some(_), Some(_)) => return Err(DocumentError::RadiusAndFootprint.into()),
        (_, Some(points)) => Footprint::polygon(points.clone()).map_err(DocumentError::Footprint)?,
        (radius, None) => Footprint::Radius(radius.unwrap_or(DEFAULT_ROBOT_RADIUS)),
    };
    let inflation = Inflation {
        inflation_radius: world.inflation_radius.unwrap_or(DEFAULT_INFLATION_RADIUS),
        cost_scaling_factor: world.cost_scaling_factor.unwrap_or(DEFAULT_COST_SCALING_FACTOR),
        ..Inflation::around(&footprint)?
    };
    // Checked as the document gives it: the travel cost scales it by the map's resolution,
    // whose own range would otherwise decide what is accepted, under another name.
    if let Some(factor) = world.cost_factor
        && !(factor.is_finite() && (0.0..=MAX_COST_FACTOR).contains(&factor))
    {
        let expected = "a number in 0..=1e6";
        return Err(MapError::Setting { setting: "cost_factor", expected, value: factor }.into());
    }
    let map = load_map(base_dir.as_ref().join(&world.yaml))?;
    let settings = CostmapOptions {
        unknown: world.unknown.unwrap_or(Unknown::Lethal),
        inflation: Some(inflation),
        ..CostmapOptions::default()
    };
    Ok(Costmap::from_occupancy(&map, &settings)?)
}

/// A ROS-map world made ready for searches: its costmap around the robot and the grid of
/// travel costs the searches walk. A document builds it before its one search; a program that
/// plans many times on one map builds it once ([`RosMapWorld::search`]).
#[derive(Debug, Clone)]
pub struct RosMapWorld {
    pub(crate) costmap: Costmap,
    pub(crate) grid: Grid,
}

impl RosMapWorld {
    /// The world of `spec`, its files read relative to `base_dir`.
    pub fn load(spec: &RosMapSpec, base_dir: impl AsRef<Path>) -> Result<Self, SolveError> {
        let costmap = ros_costmap(spec, base_dir)?;
        let grid = costmap.to_grid(&ros_travel_cost(spec, costmap.frame().resolution()))?;
        Ok(RosMapWorld { costmap, grid })
    }

    /// Its costmap: Nav2's cell costs (0 free to 252, 253 inscribed, 254 lethal, 255 unknown)
    /// in the map's frame.
    pub fn costmap(&self) -> &Costmap {
        &self.costmap
    }
}

/// The price of travel over a ROS-map world's costmap, per metre: a move over free cells costs
/// its length in metres, over costly cells `1 + cost_factor * cost / 252` times that.
pub fn ros_travel_cost(world: &RosMapSpec, resolution: f64) -> TravelCost {
    let factor = world.cost_factor.unwrap_or(DEFAULT_COST_FACTOR);
    TravelCost { neutral: resolution, factor: factor * resolution, blocked_from: INSCRIBED }
}

/// The cell of `which` (`[x, y]` in metres), or why the robot cannot start or end there.
pub(crate) fn cell_at(which: &'static str, value: &[f64], costmap: &Costmap) -> Result<Cell, DocumentError> {
    let &[x, y] = value else {
        return Err(DocumentError::NotAPoint { which, value: value.to_vec(), graph: "ros_map" });
    };
    if !(x.is_finite() && y.is_finite()) {
        return Err(DocumentError::NotAPoint { which, value: value.to_vec(), graph: "ros_map" });
    }
    let cell =
        costmap.frame().try_cell_at(Point::new(x, y)).ok_or(DocumentError::OutsideMap { which, x, y })?;
    match costmap.cost(cell) {
        Some(cost) if cost < INSCRIBED => Ok(cell),
        Some(cost) => Err(DocumentError::BlockedPoint { which, x, y, cost }),
        None => Err(DocumentError::OutsideMap { which, x, y }),
    }
}
