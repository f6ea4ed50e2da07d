//! Polygons laid on cells: which cells of a grid a polygon touches, so that a polygon world
//! becomes a map a car's footprint is checked on. A cell counts when any point of its closed
//! square lies in the closed polygon, so a footprint clear of the marked cells is clear of the
//! polygons.

use trailmark_core::geometry::Point;
use trailmark_core::world::Polygon;

/// How far past a cell's side, in cells, a point still counts as touching it: rounding in the
/// division by the resolution must never leave a touched cell unmarked.
const SLACK: f64 = 1e-9;

/// Cells of `width` x `height`, `resolution` wide, the lower-left one's outer corner at
/// `origin`, indexed from the top row down (the grid's order), as [`Cells::mark`] marks them.
pub(crate) struct Cells {
    width: usize,
    height: usize,
    origin: Point,
    resolution: f64,
    /// Per cell, in the grid's order: whether a polygon touches it.
    pub(crate) marked: Vec<bool>,
}

impl Cells {
    /// No cell marked.
    pub(crate) fn new(width: usize, height: usize, origin: Point, resolution: f64) -> Self {
        Cells { width, height, origin, resolution, marked: vec![false; width * height] }
    }

    /// Marks every cell whose closed square meets the closed `polygon`: the cells its boundary
    /// crosses, then those whose centres it encloses (a cell meeting the polygon but not its
    /// boundary lies inside it).
    pub(crate) fn mark(&mut self, polygon: &Polygon) {
        let local: Vec<(f64, f64)> = polygon
            .vertices()
            .iter()
            .map(|v| ((v.x - self.origin.x) / self.resolution, (v.y - self.origin.y) / self.resolution))
            .collect();
        for (k, &a) in local.iter().enumerate() {
            self.mark_edge(a, local[(k + 1) % local.len()]);
        }
        self.mark_inside(&local);
    }

    /// Marks cell column `i`, rows `lo..=hi` (counted from the bottom, in cells), clipped to the
    /// grid.
    fn mark_column(&mut self, i: f64, lo: f64, hi: f64) {
        if i < 0.0 || i >= self.width as f64 {
            return;
        }
        let rows = lo.max(0.0)..=hi.min(self.height as f64 - 1.0);
        if rows.is_empty() {
            return;
        }
        let (first, last) = (*rows.start() as usize, *rows.end() as usize);
        for j in first..=last {
            self.marked[(self.height - 1 - j) * self.width + i as usize] = true;
        }
    }

    /// Marks every cell the segment `a`-`b` (cell units) passes through or touches: column by
    /// column, the rows its clipped piece spans.
    fn mark_edge(&mut self, a: (f64, f64), b: (f64, f64)) {
        let (left, right) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        let y_at = |x: f64| {
            if right.0 == left.0 {
                left.1
            } else {
                left.1 + (right.1 - left.1) * ((x - left.0) / (right.0 - left.0)).clamp(0.0, 1.0)
            }
        };
        let first = (left.0 - SLACK).floor().max(-1.0);
        let last = (right.0 + SLACK).floor().min(self.width as f64);
        let mut i = first;
        while i <= last {
            let (x0, x1) = (left.0.max(i), right.0.min(i + 1.0));
            let (y0, y1) = if right.0 == left.0 {
                (left.1.min(right.1), left.1.max(right.1))
            } else {
                let (p, q) = (y_at(x0), y_at(x1));
                (p.min(q), p.max(q))
            };
            self.mark_column(i, (y0 - SLACK).floor(), (y1 + SLACK).floor());
            i += 1.0;
        }
    }

    /// Marks every cell whose centre lies inside the polygon (`vertices` in cell units), row by
    /// row between the boundary's crossings of the centres' line.
    fn mark_inside(&mut self, vertices: &[(f64, f64)]) {
        let (low, high) =
            vertices.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v.1), h.max(v.1)));
        let first = (low - 0.5).ceil().max(0.0);
        let last = (high - 0.5).floor().min(self.height as f64 - 1.0);
        let mut crossings = Vec::new();
        let mut j = first;
        while j <= last {
            let y = j + 0.5;
            crossings.clear();
            for (k, &a) in vertices.iter().enumerate() {
                let b = vertices[(k + 1) % vertices.len()];
                if (a.1 <= y) != (b.1 <= y) {
                    crossings.push(a.0 + (y - a.1) * (b.0 - a.0) / (b.1 - a.1));
                }
            }
            crossings.sort_by(f64::total_cmp);
            for pair in crossings.chunks_exact(2) {
                let (from, to) = ((pair[0] - 0.5).ceil().max(0.0), (pair[1] - 0.5).floor());
                let mut i = from;
                while i <= to.min(self.width as f64 - 1.0) {
                    self.mark_column(i, j, j);
                    i += 1.0;
                }
            }
            j += 1.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    /// Whether the closed square `[x, x + 1] x [y, y + 1]` meets the closed polygon, by the
    /// plain definition: a vertex in the square, an edge crossing one of its sides, or the
    /// square's centre inside.
    fn touches(polygon: &[Point], x: f64, y: f64) -> bool {
        let inside_square = |p: Point| p.x >= x && p.x <= x + 1.0 && p.y >= y && p.y <= y + 1.0;
        let cross = |a: Point, b: Point, c: Point, d: Point| {
            let orient = |p: Point, q: Point, r: Point| (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            let (d1, d2) = (orient(c, d, a), orient(c, d, b));
            let (d3, d4) = (orient(a, b, c), orient(a, b, d));
            d1 * d2 <= 0.0 && d3 * d4 <= 0.0
        };
        let corners =
            [Point::new(x, y), Point::new(x + 1.0, y), Point::new(x + 1.0, y + 1.0), Point::new(x, y + 1.0)];
        let n = polygon.len();
        let centre = Point::new(x + 0.5, y + 0.5);
        let mut centre_inside = false;
        for k in 0..n {
            let (a, b) = (polygon[k], polygon[(k + 1) % n]);
            if inside_square(a) || (0..4).any(|s| cross(a, b, corners[s], corners[(s + 1) % 4])) {
                return true;
            }
            if (a.y <= centre.y) != (b.y <= centre.y)
                && centre.x < a.x + (centre.y - a.y) * (b.x - a.x) / (b.y - a.y)
            {
                centre_inside = !centre_inside;
            }
        }
        centre_inside
    }

    /// A star-shaped polygon about `centre`: `radii` at evenly spaced angles.
    fn star(centre: (f64, f64), radii: &[f64], turn: f64) -> Vec<Point> {
        let n = radii.len() as f64;
        radii
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let a = turn + k as f64 * std::f64::consts::TAU / n;
                Point::new(centre.0 + r * a.cos(), centre.1 + r * a.sin())
            })
            .collect()
    }

    proptest! {
        #[test]
        fn marks_exactly_the_cells_a_polygon_touches(
            cx in -2.0..14.0f64, cy in -2.0..10.0f64,
            radii in proptest::collection::vec(0.2..5.0f64, 3..12),
            turn in 0.0..6.3f64,
        ) {
            let vertices = star((cx, cy), &radii, turn);
            let Ok(polygon) = Polygon::new(vertices.clone()) else { return Ok(()) };
            let (width, height) = (12, 8);
            let mut cells = Cells::new(width, height, Point::new(0.0, 0.0), 1.0);
            cells.mark(&polygon);
            for j in 0..height {
                for i in 0..width {
                    let expected = touches(&vertices, i as f64, j as f64);
                    let got = cells.marked[(height - 1 - j) * width + i];
                    prop_assert_eq!(got, expected, "cell ({}, {})", i, j);
                }
            }
        }
    }

    #[test]
    fn an_edge_along_a_cell_side_marks_both_neighbours() {
        let square = [(2.0, 2.0), (4.0, 2.0), (4.0, 4.0), (2.0, 4.0)];
        let polygon = Polygon::new(square.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap();
        let mut cells = Cells::new(6, 6, Point::new(0.0, 0.0), 1.0);
        cells.mark(&polygon);
        // The closed square [2, 4] touches columns and rows 1 to 4.
        let marked: usize = cells.marked.iter().filter(|&&m| m).count();
        assert_eq!(marked, 16);
    }
}
