//! A car's footprint on a [`CarMap`] as the configuration spaces' [`Validity`]: the map is a
//! [`FootprintWorld`], so `trailmark-space`'s one [`FootprintValidity`] checks a footprint on
//! its cells as Hybrid A* does (the same [`FootprintChecker`]), for the sampling planners in
//! the car spaces (RRT-Connect or RRT* over [`Dubins`](trailmark_space::Dubins) or
//! [`ReedsShepp`](trailmark_space::ReedsShepp) poses) on costmaps, grids and polygon worlds laid
//! on cells.

use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::Pose;
#[cfg(doc)]
use trailmark_space::Validity;
use trailmark_space::{FootprintValidity, FootprintWorld, SpaceError};

use crate::collision::FootprintChecker;
use crate::map::CarMap;

/// A footprint on a map, for the car spaces: a state is valid when the footprint there stays on
/// the map and off every obstacle cell (as [`HybridAStar::is_free`](crate::HybridAStar::is_free)
/// decides it, with no margin); a motion when it is at poses along the curve at most `step`
/// apart, each checked grown by half the farthest any point of the robot moves over a step, so
/// that the poses in between are covered too.
///
/// ```
/// use trailmark_car::{CarMap, MapFootprintValidity};
/// use trailmark_core::footprint::Footprint;
/// use trailmark_core::geometry::{Pose, Vector};
/// use trailmark_core::grid::Grid;
/// use trailmark_core::world::Bounds;
/// use trailmark_space::{ReedsShepp, Validity};
///
/// // A 10 m x 5 m yard of 0.1 m cells with a 1 m post in the middle, a car of radius 0.4 m.
/// let mut rows = vec![".".repeat(100); 50];
/// for row in rows.iter_mut().skip(20).take(10) {
///     row.replace_range(45..55, &"@".repeat(10));
/// }
/// let map = CarMap::from_grid(&Grid::from_rows(&rows)?, 0.1)?;
/// let space = ReedsShepp::new(Bounds::new(0.0, 0.0, 10.0, 5.0)?, 1.0)?;
/// let validity = MapFootprintValidity::new(&map, &Footprint::Radius(0.4), &space, 0.05)?;
/// assert!(validity.state_is_valid(&space, &Pose::new(Vector::new(2.0, 2.5), 0.0)));
/// assert!(!validity.state_is_valid(&space, &Pose::new(Vector::new(4.3, 2.5), 0.0))); // 0.2 m from the post
/// // Straight across the yard, through the post: refused.
/// let (a, b) = (Pose::new(Vector::new(2.0, 2.5), 0.0), Pose::new(Vector::new(8.0, 2.5), 0.0));
/// assert!(!validity.motion_is_valid(&space, &a, &b));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub type MapFootprintValidity<'m> = FootprintValidity<&'m CarMap>;

/// A map's cells as a footprint's world: the footprint laid on the cells ([`FootprintChecker`],
/// Hybrid A*'s check), at poses given in world coordinates.
impl FootprintWorld for CarMap {
    type Test = FootprintChecker;

    /// Errors: a footprint that is not a valid disc or polygon.
    fn footprint_test(&self, footprint: &Footprint, margin: f64) -> Result<FootprintChecker, SpaceError> {
        footprint.check().map_err(|_| SpaceError::NotPositive {
            what: "footprint radius",
            value: match footprint {
                Footprint::Radius(r) => *r,
                Footprint::Polygon(_) => f64::NAN,
            },
        })?;
        Ok(FootprintChecker::new(footprint, margin))
    }

    fn footprint_is_free(&self, test: &FootprintChecker, pose: &Pose) -> bool {
        test.is_free(self, &self.to_map(pose), &mut 0)
    }
}
