//! A costmap as a world to smooth paths in: a point is free when its cell costs less than a
//! chosen cost, so core's smoothing (shortcut lines, Hermite, corner-rounding Bézier, B-spline)
//! keeps a path on the cells a robot may cross.
//!
//! Segments are checked exactly: every cell a segment's interior enters (and, where it passes
//! exactly through a corner, the two cells it touches there) must be below the cost. A curve is
//! checked as a chain of segments so short that the curve strays less than 1% of a cell from
//! them (the bound comes from the curve's second derivative).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::smooth::{Clearance, Smoothing, smooth};
//! use trailmark_map::{Costmap, CostmapClearance, MapFrame, INSCRIBED};
//!
//! // A 10 x 10 map of 0.1 m cells with a lethal block in the middle.
//! let mut costs = vec![0u8; 100];
//! for y in 4..6 { for x in 3..7 { costs[y * 10 + x] = 254; } }
//! let costmap = Costmap::new(MapFrame::new(10, 10, 0.1, [0.0; 3])?, costs)?;
//! let clear = CostmapClearance::new(&costmap, INSCRIBED);
//! let path = [Point::new(0.15, 0.45), Point::new(0.25, 0.75), Point::new(0.85, 0.75), Point::new(0.95, 0.45)];
//! let smoothed = smooth(&clear, &path, Smoothing::BSpline)?;
//! assert!(smoothed.pieces.iter().all(|piece| clear.bezier_is_free(piece)));
//! assert!(!clear.segment_is_free(Point::new(0.15, 0.45), Point::new(0.95, 0.45))); // through the block
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use trailmark_core::curve::Bezier;
use trailmark_core::geometry::Point;
use trailmark_core::grid::Cell;
use trailmark_core::smooth::Clearance;

use crate::costmap::Costmap;

/// A costmap seen as free (cells below `below`) and blocked (the rest, and outside the map), in
/// metres.
#[derive(Debug, Clone, Copy)]
pub struct CostmapClearance<'a> {
    costmap: &'a Costmap,
    below: u8,
}

impl<'a> CostmapClearance<'a> {
    /// Free where a cell's cost is below `below` (e.g. [`crate::INSCRIBED`]: the cells the
    /// robot's centre may occupy).
    pub fn new(costmap: &'a Costmap, below: u8) -> Self {
        CostmapClearance { costmap, below }
    }

    fn free(&self, x: i64, y: i64) -> bool {
        let cell = u32::try_from(x).ok().zip(u32::try_from(y).ok()).map(|(x, y)| Cell::new(x, y));
        cell.and_then(|c| self.costmap.cost(c)).is_some_and(|cost| cost < self.below)
    }

    /// Whether the segment between two points in grid units (x right, y down) crosses only
    /// free cells: a walk over the cells its interior enters, in order. A segment lying on a
    /// grid line touches the cells on both sides of it, and both are checked.
    fn grid_segment_is_free(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        let ((ax, ay), (bx, by)) = (a, b);
        if !(ax.is_finite() && ay.is_finite() && bx.is_finite() && by.is_finite()) {
            return false;
        }
        const NUDGE: f64 = 1e-9;
        if ay == by && ay.fract() == 0.0 {
            return self.walk((ax, ay - NUDGE), (bx, by - NUDGE))
                && self.walk((ax, ay + NUDGE), (bx, by + NUDGE));
        }
        if ax == bx && ax.fract() == 0.0 {
            return self.walk((ax - NUDGE, ay), (bx - NUDGE, by))
                && self.walk((ax + NUDGE, ay), (bx + NUDGE, by));
        }
        self.walk(a, b)
    }

    fn walk(&self, (ax, ay): (f64, f64), (bx, by): (f64, f64)) -> bool {
        let (dx, dy) = (bx - ax, by - ay);
        // The cell the segment starts in: on a grid line, the one it heads into.
        let start =
            |p: f64, d: f64| if d < 0.0 && p.fract() == 0.0 { p as i64 - 1 } else { p.floor() as i64 };
        let (mut x, mut y) = (start(ax, dx), start(ay, dy));
        if !self.free(x, y) {
            return false;
        }
        let (sx, sy) = (if dx > 0.0 { 1 } else { -1 }, if dy > 0.0 { 1 } else { -1 });
        // The parameter at which the segment leaves the current cell across a vertical (x) or a
        // horizontal (y) grid line, and between two such lines.
        let exit = |cell: i64, p: f64, d: f64| match d {
            0.0 => f64::INFINITY,
            d if d > 0.0 => (cell as f64 + 1.0 - p) / d,
            d => (p - cell as f64) / -d,
        };
        let (mut t_x, mut t_y) = (exit(x, ax, dx), exit(y, ay, dy));
        let step = |d: f64| if d == 0.0 { f64::INFINITY } else { 1.0 / d.abs() };
        let (step_x, step_y) = (step(dx), step(dy));
        while t_x.min(t_y) < 1.0 {
            if t_x == t_y {
                // Exactly through a corner: the two cells beside it are touched.
                if !self.free(x + sx, y) || !self.free(x, y + sy) {
                    return false;
                }
                x += sx;
                y += sy;
                t_x += step_x;
                t_y += step_y;
            } else if t_x < t_y {
                x += sx;
                t_x += step_x;
            } else {
                y += sy;
                t_y += step_y;
            }
            if !self.free(x, y) {
                return false;
            }
        }
        true
    }
}

impl Clearance for CostmapClearance<'_> {
    fn segment_is_free(&self, a: Point, b: Point) -> bool {
        let frame = self.costmap.frame();
        self.grid_segment_is_free(frame.point_to_grid(a), frame.point_to_grid(b))
    }

    fn bezier_is_free(&self, curve: &Bezier) -> bool {
        let control = curve.control_points();
        let n = curve.degree() as f64;
        // A chain of m equal parameter steps strays at most max|B''| / (8 m^2) from the curve;
        // max|B''| <= n (n - 1) max |P[i+2] - 2 P[i+1] + P[i]|.
        let second = control
            .windows(3)
            .map(|w| (w[2] - 2.0 * w[1].coords + w[0].coords).coords.norm())
            .fold(0.0, f64::max);
        let bound = n * (n - 1.0) * second;
        let tolerance = 0.01 * self.costmap.frame().resolution();
        let steps = ((bound / (8.0 * tolerance)).sqrt().ceil() as usize).clamp(1, 1 << 16);
        let length = curve.polygon_length() / self.costmap.frame().resolution();
        // And never longer than a cell per step, so no cell is skipped between checks.
        let steps = steps.max(length.ceil() as usize).clamp(1, 1 << 16);
        let points: Vec<Point> = (0..=steps).map(|k| curve.point(k as f64 / steps as f64)).collect();
        points.windows(2).all(|w| self.segment_is_free(w[0], w[1]))
    }
}
