//! Car-like robots for trailmark: a footprint that turns with the car, checked on a costmap's
//! cells, and Hybrid A*, which plans forward and reverse arcs at the car's turning radius to an
//! exact goal pose and smooths them with the car's shortest curves.
//!
//! Start from the map you have: a ROS costmap ([`CarMap::from_costmap`]), any grid
//! ([`CarMap::from_grid`]) or a polygon world laid on cells ([`CarMap::from_world`]); the robot's [`Footprint`](trailmark_core::footprint::Footprint),
//! a disc or a polygon about its reference point (for a car, the middle of the rear axle); and
//! its turning radius. Poses are in the world's frame, `[x, y, heading]` as nalgebra's `Pose`.
//!
//! ```
//! use trailmark_car::{CarMap, HybridAStar, HybridOptions};
//! use trailmark_core::footprint::Footprint;
//! use trailmark_core::geometry::{Point, Pose};
//! use trailmark_core::grid::Grid;
//! use trailmark_core::reeds_shepp::Gear;
//! use trailmark_core::termination::Termination;
//! use trailmark_core::world::Polygon;
//!
//! // A 10 m x 6 m lot of 0.1 m cells; a parked row of cars fills the bottom 2 m except a bay.
//! let mut rows = vec![".".repeat(100); 60];
//! for row in rows.iter_mut().skip(40) {
//!     row.replace_range(0..40, &"@".repeat(40));
//!     row.replace_range(64..100, &"@".repeat(36));
//! }
//! let map = CarMap::from_grid(&Grid::from_rows(&rows)?, 0.1)?;
//! // A 1.6 m x 0.8 m car, its reference point 0.3 m from the back.
//! let corners = [(-0.3, -0.4), (1.3, -0.4), (1.3, 0.4), (-0.3, 0.4)];
//! let car = Footprint::Polygon(Polygon::new(corners.iter().map(|&(x, y)| Point::new(x, y)).collect())?);
//! let settings = HybridOptions { turning_radius: 1.5, ..HybridOptions::default() };
//! let planner = HybridAStar::new(&map, &car, settings)?;
//! // From the aisle, facing +x, into the bay facing down (nose in or tail in, as it finds).
//! let start = Pose::new(nalgebra::Vector2::new(1.5, 4.0), 0.0);
//! let goal = Pose::new(nalgebra::Vector2::new(5.2, 1.5), -std::f64::consts::FRAC_PI_2);
//! let plan = planner.plan(&start, &goal, &Termination::unlimited())?;
//! // Every pose along it keeps the car off the parked ones.
//! assert!(plan.path.sample(0.02).iter().all(|(pose, _)| planner.is_free(pose)));
//! let reversing = plan.path.stretches.iter().filter(|s| s.gear == Gear::Reverse).count();
//! println!("{:.1} m, {} cusps, {reversing} stretches in reverse", plan.path.length(), plan.path.cusps().len());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

mod collision;
mod error;
mod heuristic;
mod hybrid_astar;
mod map;
mod motion;
mod options;
mod path;
mod raster;
mod smooth;
mod stats;
mod validity;

pub use collision::FootprintChecker;
pub use error::CarError;
pub use hybrid_astar::{CarPlan, HybridAStar, MAX_MOTION_CELLS};
pub use map::CarMap;
pub use options::{HybridOptions, MAX_HEADING_BINS};
pub use path::{CarPath, Stretch};
/// Old name of [`HybridOptions`], kept for one release.
#[deprecated(since = "0.3.0", note = "use trailmark_car::HybridOptions")]
pub type HybridSettings = HybridOptions;
pub use stats::HybridStats;
/// The gear and turn of a [`Stretch`] of a car's path (from `trailmark_core`'s Reeds-Shepp and
/// Dubins curves).
pub use trailmark_core::{dubins::Turn, reeds_shepp::Gear};
pub use validity::MapFootprintValidity;
