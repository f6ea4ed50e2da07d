//! A car's footprint on a [`CarMap`] as the configuration spaces' [`Validity`]: the check
//! Hybrid A* makes (one footprint checker for both), for the sampling planners in
//! the car spaces (RRT-Connect or RRT* over [`Dubins`](trailmark_space::Dubins) or
//! [`ReedsShepp`](trailmark_space::ReedsShepp) poses) on costmaps, grids and polygon worlds laid
//! on cells.

use trailmark_core::footprint::{Footprint, sweep_margin};
use trailmark_core::geometry::Pose;
use trailmark_space::{Car, CarCurves, Validity};

use crate::collision::FootprintChecker;
use crate::error::CarError;
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
#[derive(Debug, Clone)]
pub struct MapFootprintValidity<'m> {
    map: &'m CarMap,
    exact: FootprintChecker,
    swept: FootprintChecker,
    step: f64,
}

impl<'m> MapFootprintValidity<'m> {
    /// `footprint` on `map`, for motions along the curves of `space` checked every `step`
    /// metres.
    ///
    /// Errors: a footprint that is not a valid disc or polygon, or a `step` that is not positive
    /// and finite.
    pub fn new<C: CarCurves>(
        map: &'m CarMap,
        footprint: &Footprint,
        space: &Car<C>,
        step: f64,
    ) -> Result<Self, CarError> {
        footprint.check()?;
        if !(step > 0.0 && step.is_finite()) {
            return Err(CarError::Setting { setting: "step", expected: "positive and finite", value: step });
        }
        let reach = footprint.circumscribed_radius()?;
        let margin = sweep_margin(step, reach, space.turning_radius());
        Ok(MapFootprintValidity {
            map,
            exact: FootprintChecker::new(footprint, 0.0),
            swept: FootprintChecker::new(footprint, margin),
            step,
        })
    }
}

impl<C: CarCurves> Validity<Car<C>> for MapFootprintValidity<'_> {
    fn state_is_valid(&self, _: &Car<C>, s: &Pose) -> bool {
        self.exact.is_free(self.map, &self.map.to_map(s), &mut 0)
    }

    fn motion_is_valid(&self, space: &Car<C>, a: &Pose, b: &Pose) -> bool {
        C::sample(&space.path(a, b), self.step).is_some_and(|poses| {
            poses.iter().all(|p| self.swept.is_free(self.map, &self.map.to_map(p), &mut 0))
        })
    }
}
