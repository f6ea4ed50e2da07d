//! The map a car plans on: which cells its footprint may not touch, what a metre costs in each
//! cell, and how far each cell lies from the nearest obstacle (so that most footprint checks
//! end without looking at the footprint's cells).
//!
//! Positions inside the planner are in map coordinates: metres from the map's lower-left corner
//! along its own axes (x right, y up), so that a ROS map turned by a yaw plans as if it were
//! not, and headings keep their sense. [`CarMap::to_map`] and [`CarMap::to_world`] convert.

use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::grid::Grid;
use trailmark_core::world::PolygonWorld;
use trailmark_map::{Costmap, LETHAL, MAX_NON_OBSTACLE, MapFrame, NO_SOURCE, TravelCost, squared_distances};

use crate::error::CarError;
use crate::raster::Cells;

/// A map for car planning: obstacle cells, the price of a metre per cell, and the distance from
/// each cell to the nearest obstacle cell.
#[derive(Debug, Clone)]
pub struct CarMap {
    frame: MapFrame,
    width: usize,
    height: usize,
    resolution: f64,
    /// Per cell, in the grid's order (row 0 at the top): the price of a metre, `+inf` on an
    /// obstacle.
    price: Vec<f64>,
    /// Per cell: metres from its centre to the centre of the nearest obstacle cell (`+inf`
    /// without obstacles).
    clearance: Vec<f64>,
    /// Whether its obstacle cells are the obstacles themselves (a costmap, a grid), so that
    /// no way through the cells is no way at all; a polygon world's cells cover its obstacles
    /// and more.
    exact: bool,
}

impl CarMap {
    /// The most cells a polygon world is laid on (4096 x 4096), about 300 MB with the
    /// planner's tables.
    pub const MAX_WORLD_CELLS: usize = 1 << 24;

    /// A costmap as a car sees it: lethal cells (254) and unknown ones (255) are obstacles
    /// that no part of the footprint may touch; inscribed cells (253) are not, the footprint
    /// itself being checked. A metre costs `travel.neutral + travel.factor * cost / 252`
    /// (inscribed cells as 252), as Smac prices it.
    ///
    /// Errors: a `travel` out of range.
    pub fn from_costmap(costmap: &Costmap, travel: &TravelCost) -> Result<Self, CarError> {
        travel.check()?;
        let price = costmap
            .costs()
            .iter()
            .map(|&c| {
                if c >= LETHAL {
                    f64::INFINITY
                } else {
                    travel.neutral + travel.factor * f64::from(c.min(MAX_NON_OBSTACLE)) / 252.0
                }
            })
            .collect();
        Ok(Self::with_prices(*costmap.frame(), price, true))
    }

    /// A grid as a car sees it, each cell `resolution` wide with the grid's top-left corner
    /// at `(0, height * resolution)` (the map frame's convention: y up): blocked cells are
    /// obstacles, and a metre costs the cell's cost.
    ///
    /// Errors: a resolution that is not positive and finite, a grid beyond a map's limits
    /// ([`MAX_MAP_CELLS`](trailmark_map::MAX_MAP_CELLS) cells and
    /// [`MAX_IMAGE_SIDE`](trailmark_map::MAX_IMAGE_SIDE) a side, [`MapError::TooLarge`](trailmark_map::MapError::TooLarge)).
    pub fn from_grid(grid: &Grid, resolution: f64) -> Result<Self, CarError> {
        let frame = MapFrame::new(grid.width() as usize, grid.height() as usize, resolution, [0.0; 3])?;
        Ok(Self::with_prices(frame, grid.costs().to_vec(), true))
    }

    /// A polygon world as a car sees it, laid on cells `resolution` wide from the bounds'
    /// lower-left corner: a cell any point of which lies in an obstacle (boundary included) or
    /// outside the bounds is an obstacle, so a footprint clear of the cells is clear of the
    /// polygons and inside the bounds; a metre costs 1 elsewhere. The world's robot radius is
    /// not used: the car's footprint is checked itself. The cells cover more than the
    /// obstacles, so a search on them proves no goal unreachable: Hybrid A* reports
    /// [`Stop::LatticeExhausted`](trailmark_core::termination::Stop::LatticeExhausted) where on
    /// a grid or a costmap it would report [`Stop::Unreachable`](trailmark_core::termination::Stop::Unreachable).
    ///
    /// Errors: a resolution that is not positive and finite ([`CarError::Map`]), or so fine
    /// that the map would exceed [`CarMap::MAX_WORLD_CELLS`] ([`CarError::Setting`]).
    pub fn from_world(world: &PolygonWorld, resolution: f64) -> Result<Self, CarError> {
        let (min, max) = (world.bounds().min(), world.bounds().max());
        let cells = |extent: f64| {
            let n = extent / resolution;
            // A side within rounding of a whole number of cells is that number.
            if (n - n.round()).abs() <= 1e-9 * n.max(1.0) { n.round() } else { n.ceil() }
        };
        // The resolution is checked before the size it sets.
        MapFrame::new(1, 1, resolution, [min.x, min.y, 0.0])?;
        let (w, h) = (cells(max.x - min.x), cells(max.y - min.y));
        if w * h > Self::MAX_WORLD_CELLS as f64 {
            let expected = "coarse enough for at most 16,777,216 cells over the world's bounds";
            return Err(CarError::Setting { setting: "resolution", expected, value: resolution });
        }
        // Saturating casts: a size too large for the map is refused by the frame.
        let frame = MapFrame::new(w as usize, h as usize, resolution, [min.x, min.y, 0.0])?;
        let (width, height) = (w as usize, h as usize);
        let mut raster = Cells::new(width, height, min, resolution);
        for obstacle in world.obstacles() {
            raster.mark(obstacle);
        }
        let outside_x = w * resolution > max.x - min.x;
        let outside_y = h * resolution > max.y - min.y;
        let price = (0..width * height)
            .map(|k| {
                let (i, row) = (k % width, k / width);
                let out = (outside_x && i == width - 1) || (outside_y && row == 0);
                if raster.marked[k] || out { f64::INFINITY } else { 1.0 }
            })
            .collect();
        Ok(Self::with_prices(frame, price, false))
    }

    fn with_prices(frame: MapFrame, price: Vec<f64>, exact: bool) -> Self {
        let (width, height) = (frame.width() as usize, frame.height() as usize);
        let resolution = frame.resolution();
        let clearance = squared_distances(&frame, |i| price[i].is_infinite())
            .into_iter()
            .map(|d| if d == NO_SOURCE { f64::INFINITY } else { f64::from(d).sqrt() * resolution })
            .collect();
        CarMap { frame, width, height, resolution, price, clearance, exact }
    }

    /// Whether the obstacle cells are the obstacles themselves (a costmap, a grid) rather than
    /// cells that cover them (a polygon world): only then does no way through the cells prove
    /// that there is none.
    pub fn is_exact(&self) -> bool {
        self.exact
    }

    /// The map's frame.
    pub fn frame(&self) -> &MapFrame {
        &self.frame
    }

    /// The width of a cell.
    pub fn resolution(&self) -> f64 {
        self.resolution
    }

    /// The width and height in cells.
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// A pose of the world in map coordinates.
    pub fn to_map(&self, pose: &Pose) -> Pose {
        self.origin().inverse() * pose
    }

    /// A pose in map coordinates in the world.
    pub fn to_world(&self, pose: &Pose) -> Pose {
        self.origin() * pose
    }

    fn origin(&self) -> Pose {
        let [x, y, yaw] = self.frame.origin();
        Pose::new(Vector::new(x, y), yaw)
    }

    /// The index of the cell holding `p` (map coordinates), or `None` outside the map.
    #[inline]
    pub(crate) fn cell_index(&self, p: Point) -> Option<usize> {
        let (x, y) = (p.x / self.resolution, p.y / self.resolution);
        let inside = x >= 0.0 && y >= 0.0 && x < self.width as f64 && y < self.height as f64;
        // NaN fails every comparison; inside, truncation is the floor (and no call to libm's).
        inside.then(|| (self.height - 1 - y as usize) * self.width + x as usize)
    }

    /// The index of the cell in column `i`, row `j` counted from the bottom, if inside.
    #[inline]
    pub(crate) fn index_at(&self, i: i64, j: i64) -> Option<usize> {
        let inside = i >= 0 && j >= 0 && (i as usize) < self.width && (j as usize) < self.height;
        inside.then(|| (self.height - 1 - j as usize) * self.width + i as usize)
    }

    /// The price of a metre in cell `index`, `+inf` on an obstacle.
    #[inline]
    pub(crate) fn price(&self, index: usize) -> f64 {
        self.price[index]
    }

    /// Whether cell `index` is an obstacle.
    #[inline]
    pub(crate) fn is_obstacle(&self, index: usize) -> bool {
        self.price[index].is_infinite()
    }

    /// Whether the disc of radius `r` about `p` lies on the map and off every obstacle cell, as
    /// far as the distances between cell centres tell (`false` when they cannot tell): the
    /// nearest obstacle cell's square is at least its centre's distance from `p`'s cell centre,
    /// less `p`'s offset from that centre, less half a cell's diagonal.
    #[inline]
    pub(crate) fn is_clear_around(&self, p: Point, r: f64) -> bool {
        let res = self.resolution;
        let on_map =
            p.x >= r && p.y >= r && p.x + r < self.width as f64 * res && p.y + r < self.height as f64 * res;
        if !on_map {
            return false;
        }
        // On the map, the coordinates are not negative: truncation is the floor.
        let (i, j) = ((p.x / res) as i64, (p.y / res) as i64);
        let Some(index) = self.index_at(i, j) else { return false };
        let (i, j) = (i as f64, j as f64);
        // offset < room, compared squared: no square root on the planner's hottest path.
        let (dx, dy) = ((i + 0.5) * res - p.x, (j + 0.5) * res - p.y);
        let room = self.clearance[index] - std::f64::consts::FRAC_1_SQRT_2 * res - r;
        room > 0.0 && dx * dx + dy * dy < room * room
    }

    /// An upper bound on the distance from every point of cell `index` to the nearest obstacle
    /// cell (the distance between centres plus half a diagonal).
    #[inline]
    pub(crate) fn clearance_at_most(&self, index: usize) -> f64 {
        self.clearance[index] + std::f64::consts::FRAC_1_SQRT_2 * self.resolution
    }

    /// The cheapest price of a metre anywhere off the obstacles (1 on a map of free cells).
    pub(crate) fn least_price(&self) -> f64 {
        self.price.iter().copied().filter(|p| p.is_finite()).fold(f64::INFINITY, f64::min)
    }
}
