//! The map frame: where the cells of a map lie in metres.
//!
//! ROS puts a map's origin at the outer corner of its lower-left cell, with y pointing up and
//! the map possibly turned by a yaw about that corner; trailmark's grids number cells from the
//! top-left, y pointing down. A [`MapFrame`] converts between the two, so a user speaks in
//! metres and never flips a row: [`MapFrame::cell_at`] gives the cell that holds a point,
//! [`MapFrame::centre`] the point at the middle of a cell.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::grid::Cell;
//! use trailmark_map::MapFrame;
//!
//! // 4 x 3 cells of 0.5 m, the lower-left corner at (-1, 2).
//! let frame = MapFrame::new(4, 3, 0.5, [-1.0, 2.0, 0.0])?;
//! // The top-left cell of the grid is the top row of the map: y from 3.0 to 3.5.
//! assert_eq!(frame.cell_at(Point::new(-0.9, 3.4))?, Cell::new(0, 0));
//! assert_eq!(frame.cell_at(Point::new(0.9, 2.1))?, Cell::new(3, 2));
//! assert_eq!(frame.centre(Cell::new(3, 2)), Point::new(0.75, 2.25));
//! assert!(frame.cell_at(Point::new(1.1, 2.1)).is_err()); // beyond the right edge
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use serde::{Deserialize, Serialize};
use trailmark_core::geometry::{Point, Vector};
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::world::MAX_COORDINATE;

use crate::error::MapError;

/// The most cells a map may have: 8192 x 8192, 410 m x 410 m at 5 cm. Every map is checked
/// against it ([`MapFrame::new`]), a map file from its image's header before any pixel is
/// decoded.
///
/// What a map costs, in bytes per cell, from the code:
///
/// - Loading ([`crate::load_map`], [`crate::decode_map`]): the image file's bytes, held while
///   it is decoded (at most [`crate::MAX_IMAGE_BYTES`]), and 1 byte a cell for the values. A
///   PGM and a non-interlaced PNG are decoded a row at a time; an interlaced PNG's passes are
///   gathered into a whole frame first, up to 8 bytes a cell more (16-bit RGBA). The PNG
///   decoder's own buffers are capped apart from the cells (16 MiB: rows, ancillary chunks).
/// - The map, an [`crate::OccupancyGrid`]: 1 byte a cell.
/// - A [`crate::Costmap`]: 1 byte a cell; inflating it ([`crate::Costmap::inflate`]) 4 bytes a
///   cell more while it runs (the squared distances, [`crate::squared_distances`]) and 24
///   bytes per cell of the longer side.
///
/// At this maximum a byte a cell is 64 MiB: loading takes at most 9 bytes a cell beside the
/// file (576 MiB, for an interlaced 16-bit RGBA PNG; 64 MiB for a PGM), and a loaded map made
/// into a costmap and inflated 6 (384 MiB: the map, the costmap, the distances). The grid a
/// planner searches ([`crate::Costmap::to_grid`]) is core's [`Grid`], 8 bytes a cell for its
/// costs.
pub const MAX_MAP_CELLS: usize = 1 << 26;

/// The longest side of a map, in cells (its image's, in pixels): 32768. Within it the squared
/// distance between two cells of a map, at most `2 x 32767^2`, fits the `u32` of
/// [`crate::squared_distances`].
pub const MAX_IMAGE_SIDE: u32 = 1 << 15;

/// The largest resolution of a map, in metres per cell (10 km): at it, a map of the largest
/// side ([`crate::MAX_IMAGE_SIDE`] cells) spans less than a third of
/// [`MAX_COORDINATE`](trailmark_core::world::MAX_COORDINATE), the largest coordinate a polygon
/// world supports and the bound on every corner of a map.
pub const MAX_RESOLUTION: f64 = 1e4;

/// The smallest cell of a map relative to the largest coordinate its corners reach: `f64`
/// values lie about 2.2e-16 times their magnitude apart, so a cell of at least 1e-9 of the
/// coordinates still holds millions of distinct points a side, and no two cell centres or path
/// points collapse into one. A map at the far edge (1e9 m) has cells of at least a metre; one
/// at UTM coordinates (up to 1e7 m) of at least a centimetre.
pub const MIN_RELATIVE_RESOLUTION: f64 = 1e-9;

/// A map's size in cells, its resolution and the pose of its lower-left corner.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MapFrame {
    width: u32,
    height: u32,
    resolution: f64,
    origin: [f64; 3],
}

impl MapFrame {
    /// A frame of `width x height` cells of `resolution` metres, the outer corner of the
    /// lower-left cell at `origin = [x, y, yaw]` (metres, radians, yaw counter-clockwise).
    ///
    /// Errors: more than [`MAX_MAP_CELLS`] cells or a side longer than [`MAX_IMAGE_SIDE`]
    /// ([`MapError::TooLarge`]), an empty size ([`MapError::Grid`]), a resolution that is not
    /// positive and finite or above [`MAX_RESOLUTION`] ([`MapError::Resolution`]), an origin
    /// that is not finite or whose x or y is beyond
    /// [`MAX_COORDINATE`](trailmark_core::world::MAX_COORDINATE) ([`MapError::Origin`]), a
    /// corner of the map beyond it, or cells smaller than [`MIN_RELATIVE_RESOLUTION`] times
    /// the largest coordinate a corner reaches ([`MapError::Extent`]).
    pub fn new(width: usize, height: usize, resolution: f64, origin: [f64; 3]) -> Result<Self, MapError> {
        let side = MAX_IMAGE_SIDE as usize;
        if width > side || height > side || width * height > MAX_MAP_CELLS {
            return Err(MapError::TooLarge { width: width as u64, height: height as u64 });
        }
        Grid::cell_count(width, height)?;
        check_resolution(resolution)?;
        check_origin(origin)?;
        // Within MAX_IMAGE_SIDE both sides fit a u32.
        let frame = MapFrame { width: width as u32, height: height as u32, resolution, origin };
        let (w, h) = (f64::from(frame.width) * resolution, f64::from(frame.height) * resolution);
        let reach = [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)]
            .map(|(u, v)| frame.world_point(u, v))
            .iter()
            .fold(0.0, |m: f64, p| m.max(p.x.abs()).max(p.y.abs()));
        // NaN fails the comparison: a corner that is not finite is refused too.
        if !(reach <= MAX_COORDINATE && resolution >= MIN_RELATIVE_RESOLUTION * reach) {
            return Err(MapError::Extent { origin, width: frame.width, height: frame.height, resolution });
        }
        Ok(frame)
    }

    /// The width in cells.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The height in cells.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Metres per cell.
    pub fn resolution(&self) -> f64 {
        self.resolution
    }

    /// The row-major index of `cell` (row 0 at the top), or `None` outside the map: where its
    /// value is in a map's data.
    pub fn index_of(&self, cell: Cell) -> Option<usize> {
        (cell.x < self.width && cell.y < self.height)
            .then(|| cell.y as usize * self.width as usize + cell.x as usize)
    }

    /// Errors unless `found` values are one per cell ([`MapError::CellCount`]).
    pub(crate) fn check_count(&self, found: usize) -> Result<(), MapError> {
        let (w, h) = (u64::from(self.width), u64::from(self.height));
        if found as u64 == w * h {
            Ok(())
        } else {
            Err(MapError::CellCount { width: w, height: h, expected: w * h, found })
        }
    }

    /// `[x, y, yaw]` of the lower-left corner, in metres and radians.
    pub fn origin(&self) -> [f64; 3] {
        self.origin
    }

    /// The point `p` in map coordinates: metres from the origin along the map's own axes.
    fn map_coordinates(&self, p: Point) -> (f64, f64) {
        let [ox, oy, yaw] = self.origin;
        let (dx, dy) = (p.x - ox, p.y - oy);
        if yaw == 0.0 {
            return (dx, dy);
        }
        let (s, c) = yaw.sin_cos();
        (c * dx + s * dy, -s * dx + c * dy)
    }

    /// The point at map coordinates `(u, v)` metres from the origin.
    fn world_point(&self, u: f64, v: f64) -> Point {
        let [ox, oy, yaw] = self.origin;
        if yaw == 0.0 {
            return Point::new(ox + u, oy + v);
        }
        let (s, c) = yaw.sin_cos();
        Point::new(ox + c * u - s * v, oy + s * u + c * v)
    }

    /// The cell holding `p` (metres), or [`MapError::OutsideMap`]. A point on the line between
    /// two cells belongs to the one to its right (larger x) and above it (larger y), as
    /// `floor` gives; a point on the map's right or top edge is outside.
    pub fn cell_at(&self, p: Point) -> Result<Cell, MapError> {
        self.try_cell_at(p).ok_or(MapError::OutsideMap { x: p.x, y: p.y })
    }

    /// The cell holding `p`, or `None` when it lies outside the map (or is not finite).
    pub fn try_cell_at(&self, p: Point) -> Option<Cell> {
        let (u, v) = self.map_coordinates(p);
        let (i, j) = ((u / self.resolution).floor(), (v / self.resolution).floor());
        let inside = i >= 0.0 && j >= 0.0 && i < f64::from(self.width) && j < f64::from(self.height);
        // NaN fails every comparison above.
        inside.then(|| Cell::new(i as u32, self.height - 1 - j as u32))
    }

    /// The centre of `cell`, in metres. The cell need not be inside the map.
    pub fn centre(&self, cell: Cell) -> Point {
        let row_from_bottom = f64::from(self.height) - 1.0 - f64::from(cell.y);
        self.world_point(
            (f64::from(cell.x) + 0.5) * self.resolution,
            (row_from_bottom + 0.5) * self.resolution,
        )
    }

    /// A point given in cell units of the grid (x right, y down from the top-left corner of the
    /// map, so a cell's centre is `(x + 0.5, y + 0.5)`), in metres: for paths whose corners are
    /// not cell centres (any-angle paths, smoothed curves).
    pub fn point_from_grid(&self, gx: f64, gy: f64) -> Point {
        self.world_point(gx * self.resolution, (f64::from(self.height) - gy) * self.resolution)
    }

    /// The inverse of [`MapFrame::point_from_grid`]: `p` in cell units of the grid.
    pub fn point_to_grid(&self, p: Point) -> (f64, f64) {
        let (u, v) = self.map_coordinates(p);
        (u / self.resolution, f64::from(self.height) - v / self.resolution)
    }

    /// A grid planner's cost on this map, in metres: a grid graph prices moves in cell lengths
    /// (1 a side, √2 a diagonal, times the cells' costs), so `cost x resolution`.
    pub fn metres(&self, cost_in_cells: f64) -> f64 {
        cost_in_cells * self.resolution
    }

    /// The length in metres of a path through the centres of `cells` (the straight segments
    /// between consecutive centres, whatever the cells cost).
    pub fn length(&self, cells: &[Cell]) -> f64 {
        cells.windows(2).map(|w| (self.centre(w[1]) - self.centre(w[0])).norm()).sum()
    }

    /// The map's x axis in the world: a unit vector.
    pub fn x_axis(&self) -> Vector {
        let (s, c) = self.origin[2].sin_cos();
        Vector::new(c, s)
    }
}

pub(crate) fn check_resolution(resolution: f64) -> Result<(), MapError> {
    // NaN fails the comparison.
    if resolution > 0.0 && resolution <= MAX_RESOLUTION {
        Ok(())
    } else {
        Err(MapError::Resolution { resolution })
    }
}

pub(crate) fn check_origin(origin: [f64; 3]) -> Result<(), MapError> {
    let [x, y, yaw] = origin;
    if x.abs() <= MAX_COORDINATE && y.abs() <= MAX_COORDINATE && yaw.is_finite() {
        Ok(())
    } else {
        Err(MapError::Origin { x: origin[0], y: origin[1], yaw: origin[2] })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_and_costs_in_metres() {
        let frame = MapFrame::new(7, 5, 0.25, [1.5, -3.0, 0.7]).unwrap();
        let cells = [Cell::new(0, 0), Cell::new(1, 0), Cell::new(2, 1), Cell::new(2, 2)];
        let expected = 0.25 + 0.25 * 2f64.sqrt() + 0.25;
        assert!((frame.length(&cells) - expected).abs() < 1e-12);
        assert_eq!(frame.length(&cells[..1]), 0.0);
        assert_eq!(frame.metres(2.0 + 2f64.sqrt()), 0.25 * (2.0 + 2f64.sqrt()));
    }

    #[test]
    fn cells_and_centres_agree() {
        for yaw in [0.0, 0.3, -2.0, std::f64::consts::PI] {
            let frame = MapFrame::new(7, 5, 0.25, [1.5, -3.0, yaw]).unwrap();
            for y in 0..5 {
                for x in 0..7 {
                    let cell = Cell::new(x, y);
                    assert_eq!(frame.cell_at(frame.centre(cell)).unwrap(), cell, "yaw {yaw}");
                    let (gx, gy) = frame.point_to_grid(frame.centre(cell));
                    assert!(
                        (gx - (f64::from(x) + 0.5)).abs() < 1e-9 && (gy - (f64::from(y) + 0.5)).abs() < 1e-9
                    );
                }
            }
        }
    }

    #[test]
    fn the_lower_left_corner_is_the_origin() {
        let frame = MapFrame::new(10, 20, 0.1, [2.0, 3.0, 0.0]).unwrap();
        assert_eq!(frame.cell_at(Point::new(2.0, 3.0)).unwrap(), Cell::new(0, 19));
        assert_eq!(frame.cell_at(Point::new(2.999, 4.999)).unwrap(), Cell::new(9, 0));
        assert!(frame.cell_at(Point::new(3.0, 3.5)).is_err());
        assert!(frame.cell_at(Point::new(1.999, 3.5)).is_err());
        assert!(frame.cell_at(Point::new(f64::NAN, 3.5)).is_err());
        let turned = MapFrame::new(10, 20, 0.1, [0.0, 0.0, std::f64::consts::FRAC_PI_2]).unwrap();
        // Turned a quarter to the left: the map's x axis points up the world's y.
        assert_eq!(turned.cell_at(Point::new(-0.05, 0.05)).unwrap(), Cell::new(0, 19));
    }

    #[test]
    fn bad_frames_are_refused() {
        assert!(matches!(MapFrame::new(0, 3, 0.1, [0.0; 3]), Err(MapError::Grid(_))));
        for r in [0.0, -0.05, f64::NAN, f64::INFINITY] {
            assert!(matches!(MapFrame::new(3, 3, r, [0.0; 3]), Err(MapError::Resolution { .. })));
        }
        assert!(matches!(MapFrame::new(3, 3, 0.1, [0.0, f64::NAN, 0.0]), Err(MapError::Origin { .. })));
    }

    #[test]
    fn maps_are_at_most_max_map_cells_and_max_image_side() {
        let too_large = |w: usize, h: usize| match MapFrame::new(w, h, 0.05, [0.0; 3]) {
            Err(MapError::TooLarge { width, height }) => assert_eq!((width, height), (w as u64, h as u64)),
            other => panic!("{w} x {h}: expected a map too large, got {other:?}"),
        };
        assert!(MapFrame::new(8192, 8192, 0.05, [0.0; 3]).is_ok());
        too_large(8192, 8193);
        too_large(16384, 16384);
        assert!(MapFrame::new(crate::MAX_IMAGE_SIDE as usize, 2048, 0.05, [0.0; 3]).is_ok());
        too_large(crate::MAX_IMAGE_SIDE as usize + 1, 1);
        too_large(1, 1 << 20);
        // The message states the limits (error.rs names no constant of the crate, so that
        // it depends on no other file).
        let e = MapFrame::new(8192, 8193, 0.05, [0.0; 3]).unwrap_err().to_string();
        let limits = format!("at most {MAX_MAP_CELLS} cells and {MAX_IMAGE_SIDE} a side");
        assert!(e.contains("8192 x 8193") && e.contains(&limits), "{e}");
    }

    #[test]
    fn coordinates_stay_within_what_a_world_supports() {
        // Far origins, where f64 spacing swallows the cells, and absurd resolutions.
        let origin = |o: [f64; 3]| match MapFrame::new(3, 3, 0.05, o) {
            Err(e @ MapError::Origin { .. }) => e.to_string(),
            other => panic!("expected an origin error, got {other:?}"),
        };
        assert!(
            origin([1e15, 0.0, 0.0]).contains("`origin`")
                && origin([1e15, 0.0, 0.0]).contains("1000000000000000")
        );
        assert!(origin([0.0, -1.5e9, 0.0]).contains("-1500000000"));
        for r in [1e300, 2e4] {
            let e = MapFrame::new(3, 3, r, [0.0; 3]).unwrap_err();
            assert!(matches!(e, MapError::Resolution { resolution } if resolution == r), "{e}");
            assert!(e.to_string().contains(&format!(
                "`resolution` must be a positive number of metres per cell, at most {MAX_RESOLUTION:e}"
            )));
        }
        // Within the limits at their edge: the corner at -1e9, cells of MAX_RESOLUTION.
        assert!(MapFrame::new(3, 3, 1e4, [-1e9, -1e9, 0.0]).is_ok());
        // The far corner beyond 1e9, straight or turned a quarter.
        let extent = |w: usize, r: f64, o: [f64; 3]| match MapFrame::new(w, 2, r, o) {
            Err(e @ MapError::Extent { .. }) => e.to_string(),
            other => panic!("expected an extent error, got {other:?}"),
        };
        assert!(extent(10, 0.05, [1e9 - 0.1, 0.0, 0.0]).contains("`origin` [999999999.9, 0.0, 0.0]"));
        assert!(extent(10, 1.0, [0.0, 1e9 - 5.0, std::f64::consts::FRAC_PI_2]).contains("10 x 2"));
        assert!(MapFrame::new(10, 2, 1.0, [0.0, 1e9 - 11.0, std::f64::consts::FRAC_PI_2]).is_ok());
        // Cells too fine to be told apart so far out: under 1e-9 of the farthest coordinate.
        assert!(extent(10, 0.5, [-1e9, 0.0, 0.0]).contains("`resolution` 0.5"));
        let relative = format!("at least {MIN_RELATIVE_RESOLUTION:e} times");
        assert!(extent(10, 0.5, [-1e9, 0.0, 0.0]).contains(&relative));
        assert!(MapFrame::new(10, 2, 1.0, [-1e9, 0.0, 0.0]).is_ok());
    }
}
