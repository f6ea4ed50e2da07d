//! Footprint checks on a [`CarMap`]: whether the robot at a pose touches an obstacle cell or
//! leaves the map.
//!
//! The planner checks poses a short step apart along every motion. So that the poses between
//! two checked ones are covered too, the footprint is checked grown by a margin: half the
//! farthest any point of the robot moves over one step. A polygon is checked as its convex hull
//! grown by the margin (a car's rectangle is its own hull), a disc as a larger disc.
//!
//! Most poses are decided by the map's distances alone: a pose whose cell is farther from every
//! obstacle than the footprint reaches is free. Near obstacles the grown footprint is laid on
//! the cells: row by row, the cells its convex outline spans.

use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::predicates::orient;

use crate::map::CarMap;

/// The footprint, grown by the margin, as the checks use it.
#[derive(Debug, Clone)]
enum Shape {
    /// A disc about the reference point.
    Disc(f64),
    /// A convex polygon, counter-clockwise, in the robot's frame.
    Convex(Vec<Point>),
}

/// A footprint, grown by a margin, checked on a map's cells: Hybrid A*'s check, and the test a
/// [`CarMap`] gives [`MapFootprintValidity`](crate::MapFootprintValidity).
#[derive(Debug, Clone)]
pub struct FootprintChecker {
    shape: Shape,
    /// Discs covering the grown footprint, in the robot's frame: when each is clear of
    /// obstacles by the map's distances, so is the footprint. An elongated car is covered by
    /// a row of small discs, which near walls decide far more poses than the one disc about
    /// its reference point.
    cover: Vec<(Point, f64)>,
}

impl FootprintChecker {
    /// Checks `footprint` grown by `margin`. The footprint must have been checked
    /// ([`Footprint::check`]): a polygon's hull and discs are built from it as it is.
    pub fn new(footprint: &Footprint, margin: f64) -> Self {
        match footprint {
            Footprint::Radius(r) => FootprintChecker {
                shape: Shape::Disc(r + margin),
                cover: vec![(Point::origin(), r + margin)],
            },
            Footprint::Polygon(polygon) => {
                let hull = grown(&convex_hull(polygon.vertices()), margin);
                let cover = disc_cover(&hull);
                FootprintChecker { shape: Shape::Convex(hull), cover }
            }
        }
    }

    /// Whether the footprint at `pose` (map coordinates) stays on the map and off every
    /// obstacle cell; `rastered` counts the checks that looked at cells.
    pub fn is_free(&self, map: &CarMap, pose: &Pose, rastered: &mut u64) -> bool {
        let p = Point::from(pose.translation.vector);
        if self.cover.iter().all(|&(c, r)| map.is_clear_around(pose * c, r)) {
            return true;
        }
        *rastered += 1;
        match &self.shape {
            Shape::Disc(r) => disc_is_free(map, p, *r),
            Shape::Convex(hull) => {
                let placed: Vec<Point> = hull.iter().map(|v| pose * v).collect();
                convex_is_free(map, &placed)
            }
        }
    }
}

/// Discs covering the convex polygon `hull`: a row along x, each over an equal slice of the
/// hull's bounding box, as many as the box is long over wide (at least one).
fn disc_cover(hull: &[Point]) -> Vec<(Point, f64)> {
    let (mut lo, mut hi) =
        (Point::new(f64::INFINITY, f64::INFINITY), Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
    for p in hull {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    let (long, wide) = (hi.x - lo.x, hi.y - lo.y);
    let k = (long / wide.max(f64::MIN_POSITIVE)).ceil().clamp(1.0, 16.0);
    let slice = long / k;
    let radius = (0.5 * slice).hypot(0.5 * wide);
    (0..k as usize)
        .map(|i| (Point::new(lo.x + slice * (i as f64 + 0.5), 0.5 * (lo.y + hi.y)), radius))
        .collect()
}

/// Whether no obstacle cell and no cell off the map lies within `r` of `p`.
fn disc_is_free(map: &CarMap, p: Point, r: f64) -> bool {
    let res = map.resolution();
    // Off the map (or not finite): refused before any cell is counted, so that no cell index
    // overflows.
    let (w, h) = (map.size().0 as f64 * res, map.size().1 as f64 * res);
    if !(p.x - r >= 0.0 && p.y - r >= 0.0 && p.x + r < w && p.y + r < h) {
        return false;
    }
    let (i0, i1) = (((p.x - r) / res).floor() as i64, ((p.x + r) / res).floor() as i64);
    let (j0, j1) = (((p.y - r) / res).floor() as i64, ((p.y + r) / res).floor() as i64);
    for j in j0..=j1 {
        for i in i0..=i1 {
            // The nearest point of the cell's square to p.
            let qx = p.x.clamp(i as f64 * res, (i + 1) as f64 * res);
            let qy = p.y.clamp(j as f64 * res, (j + 1) as f64 * res);
            let (dx, dy) = (qx - p.x, qy - p.y);
            if dx * dx + dy * dy > r * r {
                continue;
            }
            match map.index_at(i, j) {
                Some(index) if !map.is_obstacle(index) => {}
                _ => return false,
            }
        }
    }
    true
}

/// Whether every cell the convex polygon `v` (map coordinates) meets is on the map and free:
/// for each row of cells, the span of x the polygon covers within the row's strip.
fn convex_is_free(map: &CarMap, v: &[Point]) -> bool {
    let res = map.resolution();
    // A corner off the map (or not finite) touches a cell off it.
    let (w, h) = (map.size().0 as f64 * res, map.size().1 as f64 * res);
    if !v.iter().all(|p| p.x >= 0.0 && p.y >= 0.0 && p.x < w && p.y < h) {
        return false;
    }
    let (ymin, ymax) =
        v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.y), b.max(p.y)));
    if !(ymin.is_finite() && ymax.is_finite()) {
        return false;
    }
    let (j0, j1) = ((ymin / res).floor() as i64, (ymax / res).floor() as i64);
    for j in j0..=j1 {
        let (lo, hi) = (j as f64 * res, (j + 1) as f64 * res);
        let (mut xmin, mut xmax) = (f64::INFINITY, f64::NEG_INFINITY);
        for k in 0..v.len() {
            let (a, b) = (v[k], v[(k + 1) % v.len()]);
            // The part of edge a-b within the strip lo <= y <= hi.
            if let Some((x0, x1)) = clip_to_strip(a, b, lo, hi) {
                xmin = xmin.min(x0.min(x1));
                xmax = xmax.max(x0.max(x1));
            }
        }
        if xmin > xmax {
            continue; // the polygon only touches this strip at a point, or not at all
        }
        for i in (xmin / res).floor() as i64..=(xmax / res).floor() as i64 {
            match map.index_at(i, j) {
                Some(index) if !map.is_obstacle(index) => {}
                _ => return false,
            }
        }
    }
    true
}

/// The x values at the ends of the part of segment `a`-`b` with `lo <= y <= hi`, if any.
fn clip_to_strip(a: Point, b: Point, lo: f64, hi: f64) -> Option<(f64, f64)> {
    let (a, b) = if a.y <= b.y { (a, b) } else { (b, a) };
    if b.y < lo || a.y > hi {
        return None;
    }
    if b.y == a.y {
        return Some((a.x, b.x));
    }
    let x_at = |y: f64| a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y)).clamp(0.0, 1.0);
    let (y0, y1) = (a.y.max(lo), b.y.min(hi));
    Some((x_at(y0), x_at(y1)))
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain, exact turns).
fn convex_hull(points: &[Point]) -> Vec<Point> {
    let mut p: Vec<Point> = points.to_vec();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut hull: Vec<Point> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = hull.len();
        let ordered: Box<dyn Iterator<Item = &Point>> =
            if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
        for &q in ordered {
            while hull.len() >= start + 2 && orient(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0 {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// The largest turn of the outline drawn about a grown corner, per segment: each segment is
/// tangent to the circle of the margin, so the outline is within `margin / cos(PI / 8)`, 8%
/// beyond the margin, of the hull. A car's rectangle gets eight corners: finer turns (16 at
/// PI / 8) made the checks that lay the outline on cells slower, for millimetres.
const CORNER_TURN: f64 = std::f64::consts::PI / 4.0;

/// The convex polygon `hull` (counter-clockwise) grown by `margin`: it holds every point within
/// `margin` of the hull and none farther than `margin / cos(CORNER_TURN / 2)`. Each corner is
/// rounded by segments tangent to the circle of the margin about it; the corner where the two
/// moved edges meet would lie `margin / cos(angle / 2)` out, far beyond the margin at a
/// sharp corner (a thin triangle grown by a centimetre reached a metre).
fn grown(hull: &[Point], margin: f64) -> Vec<Point> {
    let n = hull.len();
    if margin == 0.0 || n < 3 {
        return hull.to_vec();
    }
    let normal = |a: Point, b: Point| {
        let d = (b - a).normalize();
        nalgebra::Vector2::new(d.y, -d.x)
    };
    let mut outline = Vec::with_capacity(2 * n);
    for i in 0..n {
        let (prev, here, next) = (hull[(i + n - 1) % n], hull[i], hull[(i + 1) % n]);
        let (from, to) = (normal(prev, here), normal(here, next));
        // The outline turns left by `turn` (in [0, PI)) at a corner of a counter-clockwise hull.
        let turn = from.perp(&to).atan2(from.dot(&to)).max(0.0);
        let pieces = (turn / CORNER_TURN).ceil().max(1.0);
        let piece = turn / pieces;
        let reach = margin / (0.5 * piece).cos();
        // The corners of the tangent segments; the moved edges join them (their points of
        // tangency lie on those edges).
        let start = from.y.atan2(from.x);
        for k in 0..pieces as usize {
            let angle = start + piece * (k as f64 + 0.5);
            outline.push(here + nalgebra::Vector2::new(angle.cos(), angle.sin()) * reach);
        }
    }
    outline.dedup();
    outline
}

#[cfg(test)]
mod tests {
    use super::*;
    use trailmark_core::grid::Grid;
    use trailmark_core::world::Polygon;

    fn rectangle(x0: f64, y0: f64, x1: f64, y1: f64) -> Footprint {
        let corners = vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)];
        Footprint::Polygon(Polygon::new(corners).unwrap())
    }

    #[test]
    fn the_hull_of_a_notched_polygon_and_its_growth() {
        let notched = [
            Point::new(0.0, 0.0),
            Point::new(2.0, 0.0),
            Point::new(2.0, 2.0),
            Point::new(1.0, 1.0),
            Point::new(0.0, 2.0),
        ];
        let hull = convex_hull(&notched);
        assert_eq!(hull.len(), 4);
        let big = grown(&hull, 0.5);
        // The square's corners are rounded, not mitred: (2.5, 2.5) is 0.71 from the hull.
        assert_eq!(big.len(), 8);
        assert!(!big.iter().any(|p| (p.x - 2.5).abs() < 1e-9 && (p.y - 2.5).abs() < 1e-9));
    }

    /// The distance from `p` to the convex polygon `v` (0 inside).
    fn distance_to_convex(v: &[Point], p: Point) -> f64 {
        let n = v.len();
        let inside = (0..n).all(|i| orient(v[i], v[(i + 1) % n], p) >= 0.0);
        if inside {
            return 0.0;
        }
        let to_segment = |a: Point, b: Point| {
            let ab = b - a;
            let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            (p - (a + ab * t)).norm()
        };
        (0..n).map(|i| to_segment(v[i], v[(i + 1) % n])).fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn growth_holds_the_margin_and_stays_near_it_at_sharp_corners() {
        // A thin triangle: a 2-degree corner at (10, 0).
        let thin = [Point::new(0.0, -0.1), Point::new(10.0, 0.0), Point::new(0.0, 0.1)];
        for margin in [0.01, 0.3] {
            let hull = convex_hull(&thin);
            let big = grown(&hull, margin);
            let n = big.len();
            assert!((0..n).all(|i| orient(big[i], big[(i + 1) % n], big[(i + 2) % n]) >= 0.0), "convex");
            // Every outline vertex lies within 8% beyond the margin of the hull...
            for &p in &big {
                let d = distance_to_convex(&hull, p);
                assert!(d >= margin * (1.0 - 1e-9) && d <= margin * 1.0824, "{p:?}: {d}");
            }
            // ... and every point at the margin around the hull lies inside the outline.
            for &corner in &hull {
                for k in 0..360 {
                    let a = f64::from(k).to_radians();
                    let p = corner + nalgebra::Vector2::new(a.cos(), a.sin()) * margin;
                    assert!(distance_to_convex(&big, p) <= 1e-12, "{p:?} outside");
                }
            }
        }
    }

    #[test]
    fn a_rectangle_touches_exactly_the_cells_it_overlaps() {
        // One obstacle cell at column 5, row 5 from the bottom of a 10 x 10 grid of unit cells.
        let mut grid = Grid::new(10, 10).unwrap();
        grid.set_blocked(trailmark_core::grid::Cell::new(5, 4), true).unwrap();
        let map = CarMap::from_grid(&grid, 1.0).unwrap();
        let checker = FootprintChecker::new(&rectangle(-0.5, -0.5, 0.5, 0.5), 0.0);
        let mut n = 0;
        let at = |x: f64, y: f64, h: f64| Pose::new(nalgebra::Vector2::new(x, y), h);
        // A unit square centred at (4.45, 5.5) reaches x = 4.95: free; at (4.55, 5.5), x = 5.05.
        assert!(checker.is_free(&map, &at(4.45, 5.5, 0.0), &mut n));
        assert!(!checker.is_free(&map, &at(4.55, 5.5, 0.0), &mut n));
        // Turned 45 degrees at (4.2, 5.5) its corner reaches 4.2 + 0.707 < 5: free; at 4.35 not.
        assert!(checker.is_free(&map, &at(4.2, 5.5, std::f64::consts::FRAC_PI_4), &mut n));
        assert!(!checker.is_free(&map, &at(4.35, 5.5, std::f64::consts::FRAC_PI_4), &mut n));
        // Off the map.
        assert!(!checker.is_free(&map, &at(0.3, 5.0, 0.0), &mut n));
        // Far from everything: decided by the distances alone.
        let before = n;
        assert!(checker.is_free(&map, &at(8.0, 1.5, 0.3), &mut n));
        assert_eq!(n, before);
    }

    #[test]
    fn a_disc_touches_the_cells_within_its_radius() {
        let mut grid = Grid::new(10, 10).unwrap();
        grid.set_blocked(trailmark_core::grid::Cell::new(5, 4), true).unwrap();
        let map = CarMap::from_grid(&grid, 1.0).unwrap();
        let checker = FootprintChecker::new(&Footprint::Radius(1.0), 0.0);
        let mut n = 0;
        let at = |x: f64, y: f64| Pose::new(nalgebra::Vector2::new(x, y), 0.0);
        // The obstacle's corner (5, 5) is 1.0 from (4.3, 4.3) * ... check on both sides.
        assert!(checker.is_free(&map, &at(4.25, 4.25), &mut n)); // 1.06 from the corner
        assert!(!checker.is_free(&map, &at(4.35, 4.35), &mut n)); // 0.92 from it
    }
}
