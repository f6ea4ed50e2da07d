//! Small SVG writers: for grids (blocked and costly cells, explored cells, paths, start and
//! goal) and for polygon worlds (obstacles, grown boundaries, cells, roadmap edges, paths).
//!
//! Runs of equal cells in a row are drawn as one rectangle, so a 1024 x 1024 map stays a file of
//! reasonable size. Coordinates are in cells (the `viewBox`), scaled by [`GridSvg::cell_size`].
//!
//! ```
//! use trailmark_core::grid::{Cell, Grid};
//! use trailmark_core::svg::GridSvg;
//!
//! let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
//! let path = [Cell::new(0, 0), Cell::new(0, 1), Cell::new(1, 2), Cell::new(3, 2)];
//! let svg = GridSvg::new(&grid)
//!     .cell_size(20.0)
//!     .explored([Cell::new(0, 0), Cell::new(1, 0)])
//!     .path(&path)
//!     .to_svg();
//! assert!(svg.starts_with("<svg") && svg.contains("<polyline"));
//! # Ok::<(), trailmark_core::grid::GridError>(())
//! ```

use std::fmt::Write as _;

use crate::freespace::FreeSpace;
use crate::geometry::{Point, Pose};
use crate::grid::{Cell, Grid};
use crate::world::PolygonWorld;

/// The colour of blocked cells.
const BLOCKED: &str = "#2f3640";
/// The colour of blocked cells the viewer does not know about.
const UNKNOWN_BLOCKED: &str = "#b8bec6";
/// The colour of explored cells.
const EXPLORED: &str = "#9fd3f5";
/// The colours of successive paths.
const PATH_COLOURS: [&str; 4] = ["#e1306c", "#f39c12", "#8e44ad", "#16a085"];

/// A picture of a grid and what a search did on it.
#[derive(Debug, Clone)]
pub struct GridSvg<'a> {
    grid: &'a Grid,
    cell_size: f64,
    explored: Vec<bool>,
    unknown: Vec<bool>,
    paths: Vec<Vec<Cell>>,
    start: Option<Cell>,
    goal: Option<Cell>,
    title: Option<String>,
}

impl<'a> GridSvg<'a> {
    /// A picture of `grid`, 4 pixels per cell.
    pub fn new(grid: &'a Grid) -> Self {
        GridSvg {
            grid,
            cell_size: 4.0,
            explored: Vec::new(),
            unknown: Vec::new(),
            paths: Vec::new(),
            start: None,
            goal: None,
            title: None,
        }
    }

    /// The width and height of one cell in pixels.
    pub fn cell_size(mut self, pixels: f64) -> Self {
        if pixels.is_finite() && pixels > 0.0 {
            self.cell_size = pixels;
        }
        self
    }

    /// Marks cells as explored (drawn light blue); cells outside the grid are ignored.
    pub fn explored(mut self, cells: impl IntoIterator<Item = Cell>) -> Self {
        if self.explored.is_empty() {
            self.explored = vec![false; self.grid.len()];
        }
        let w = self.grid.width() as usize;
        for c in cells.into_iter().filter(|&c| self.grid.contains(c)) {
            self.explored[c.y as usize * w + c.x as usize] = true;
        }
        self
    }

    /// Adds a path, drawn as a line through cell centres; its first and last cells become the
    /// start and goal markers unless set otherwise.
    pub fn path(mut self, cells: &[Cell]) -> Self {
        if let (Some(&first), Some(&last)) = (cells.first(), cells.last()) {
            self.start.get_or_insert(first);
            self.goal.get_or_insert(last);
            self.paths.push(cells.to_vec());
        }
        self
    }

    /// Marks the start cell (a green disc).
    pub fn start(mut self, cell: Cell) -> Self {
        self.start = Some(cell);
        self
    }

    /// Marks the goal cell (a red ring).
    pub fn goal(mut self, cell: Cell) -> Self {
        self.goal = Some(cell);
        self
    }

    /// Marks cells as unknown to whoever moved on the grid (a robot that never sensed them):
    /// blocked ones are drawn pale instead of dark. Cells outside the grid are ignored.
    pub fn unknown(mut self, cells: impl IntoIterator<Item = Cell>) -> Self {
        let w = self.grid.width() as usize;
        self.unknown.resize(self.grid.len(), false);
        for c in cells {
            if self.grid.contains(c) {
                self.unknown[c.y as usize * w + c.x as usize] = true;
            }
        }
        self
    }

    /// A title, shown as a tooltip and read by screen readers.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// The SVG document.
    pub fn to_svg(&self) -> String {
        let (w, h) = (self.grid.width(), self.grid.height());
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {w} {h}" shape-rendering="crispEdges">"#,
            fmt_num(f64::from(w) * self.cell_size),
            fmt_num(f64::from(h) * self.cell_size),
        );
        if let Some(title) = &self.title {
            let _ = writeln!(out, "<title>{}</title>", escape(title));
        }
        let _ = writeln!(out, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        let costs = self.grid.costs();
        let max_cost = self.grid.costs().iter().copied().filter(|c| c.is_finite()).fold(1.0, f64::max);
        // Costly cells, shaded by cost; then explored cells; then blocked cells on top.
        if !self.grid.is_uniform() {
            self.runs(&mut out, |i| {
                let c = costs[i];
                (c.is_finite() && c != 1.0).then(|| {
                    let t = ((c - 1.0) / (max_cost - 1.0).max(1e-9)).clamp(0.0, 1.0);
                    let shade = (235.0 - 120.0 * t) as u8;
                    format!("#{:02x}{:02x}{:02x}", 245, shade, shade.saturating_sub(40))
                })
            });
        }
        if !self.explored.is_empty() {
            self.runs(&mut out, |i| self.explored[i].then(|| EXPLORED.to_string()));
        }
        let unknown = |i: usize| self.unknown.get(i).copied().unwrap_or(false);
        self.runs(&mut out, |i| {
            (!costs[i].is_finite()).then(|| if unknown(i) { UNKNOWN_BLOCKED } else { BLOCKED }.to_string())
        });
        let stroke = (f64::from(w.max(h)) / 150.0).clamp(0.25, 2.0);
        for (k, path) in self.paths.iter().enumerate() {
            let points: Vec<String> =
                path.iter().map(|c| format!("{},{}", f64::from(c.x) + 0.5, f64::from(c.y) + 0.5)).collect();
            let _ = writeln!(
                out,
                r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="{}" stroke-linejoin="round" stroke-linecap="round" shape-rendering="geometricPrecision"/>"#,
                points.join(" "),
                PATH_COLOURS[k % PATH_COLOURS.len()],
                fmt_num(stroke),
            );
        }
        let r = (stroke * 1.6).max(0.45);
        if let Some(s) = self.start {
            let _ = writeln!(
                out,
                r##"<circle cx="{}" cy="{}" r="{}" fill="#27ae60" shape-rendering="geometricPrecision"/>"##,
                f64::from(s.x) + 0.5,
                f64::from(s.y) + 0.5,
                fmt_num(r)
            );
        }
        if let Some(g) = self.goal {
            let _ = writeln!(
                out,
                r##"<circle cx="{}" cy="{}" r="{}" fill="none" stroke="#c0392b" stroke-width="{}" shape-rendering="geometricPrecision"/>"##,
                f64::from(g.x) + 0.5,
                f64::from(g.y) + 0.5,
                fmt_num(r),
                fmt_num(r / 2.0)
            );
        }
        out.push_str("</svg>\n");
        out
    }

    /// Writes the horizontal runs of cells with the same colour as rectangles.
    fn runs(&self, out: &mut String, colour_of: impl Fn(usize) -> Option<String>) {
        let w = self.grid.width() as usize;
        for y in 0..self.grid.height() as usize {
            let mut x = 0;
            while x < w {
                let Some(colour) = colour_of(y * w + x) else {
                    x += 1;
                    continue;
                };
                let mut end = x + 1;
                while end < w && colour_of(y * w + end).as_ref() == Some(&colour) {
                    end += 1;
                }
                let _ = writeln!(
                    out,
                    r#"<rect x="{x}" y="{y}" width="{}" height="1" fill="{colour}"/>"#,
                    end - x
                );
                x = end;
            }
        }
    }
}

/// A picture of a polygon world and what a roadmap builder made of it: the obstacles, the
/// grown free-space boundary, cells, graph edges and nodes, paths, and start and goal.
///
/// World coordinates are drawn with y up, scaled by [`WorldSvg::scale`] pixels per unit.
///
/// ```
/// use trailmark_core::geometry::Point;
/// use trailmark_core::svg::WorldSvg;
/// use trailmark_core::world::{Bounds, PolygonWorld};
///
/// let square = vec![Point::new(4.0, 4.0), Point::new(6.0, 4.0), Point::new(6.0, 6.0), Point::new(4.0, 6.0)];
/// let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?, vec![square], 0.5)?;
/// let svg = WorldSvg::new(&world)
///     .free_space(&world.free_space())
///     .edges([(Point::new(1.0, 1.0), Point::new(3.5, 3.5))])
///     .path(&[Point::new(1.0, 1.0), Point::new(3.5, 3.5), Point::new(9.0, 9.0)])
///     .to_svg();
/// assert!(svg.starts_with("<svg") && svg.contains("<polygon") && svg.contains("<polyline"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct WorldSvg<'a> {
    world: &'a PolygonWorld,
    scale: f64,
    boundary: Vec<(Point, Point)>,
    cells: Vec<Vec<Point>>,
    edges: Vec<(Point, Point)>,
    nodes: Vec<Point>,
    paths: Vec<Vec<Point>>,
    poses: Vec<Pose>,
    outlines: Vec<Vec<Point>>,
    marks: Vec<Point>,
    start: Option<Point>,
    goal: Option<Point>,
    title: Option<String>,
}

impl<'a> WorldSvg<'a> {
    /// A picture of `world`'s bounds and obstacles, 20 pixels per unit.
    pub fn new(world: &'a PolygonWorld) -> Self {
        WorldSvg {
            world,
            scale: 20.0,
            boundary: Vec::new(),
            cells: Vec::new(),
            edges: Vec::new(),
            nodes: Vec::new(),
            paths: Vec::new(),
            poses: Vec::new(),
            outlines: Vec::new(),
            marks: Vec::new(),
            start: None,
            goal: None,
            title: None,
        }
    }

    /// Pixels per world unit.
    pub fn scale(mut self, pixels: f64) -> Self {
        self.scale = pixels;
        self
    }

    /// Draws the boundary of `space` (the obstacles grown by the robot radius), dashed.
    pub fn free_space(mut self, space: &FreeSpace) -> Self {
        self.boundary.extend((0..space.edges().len()).map(|e| space.edge_points(e)));
        self
    }

    /// Draws cells (polygons), lightly shaded.
    pub fn cells(mut self, cells: impl IntoIterator<Item = Vec<Point>>) -> Self {
        self.cells.extend(cells);
        self
    }

    /// Draws graph edges as thin lines.
    pub fn edges(mut self, edges: impl IntoIterator<Item = (Point, Point)>) -> Self {
        self.edges.extend(edges);
        self
    }

    /// Draws graph nodes as dots.
    pub fn nodes(mut self, nodes: impl IntoIterator<Item = Point>) -> Self {
        self.nodes.extend(nodes);
        self
    }

    /// Draws a path as a bold polyline (successive paths in different colours).
    pub fn path(mut self, points: &[Point]) -> Self {
        self.paths.push(points.to_vec());
        self
    }

    /// Draws poses as short arrows.
    pub fn poses(mut self, poses: impl IntoIterator<Item = Pose>) -> Self {
        self.poses.extend(poses);
        self
    }

    /// Draws a closed outline under the paths: the robot's footprint at a pose.
    pub fn outline(mut self, corners: &[Point]) -> Self {
        self.outlines.push(corners.to_vec());
        self
    }

    /// Marks a point in red: where a car changes gear.
    pub fn mark(mut self, p: Point) -> Self {
        self.marks.push(p);
        self
    }

    /// Marks the start.
    pub fn start(mut self, p: Point) -> Self {
        self.start = Some(p);
        self
    }

    /// Marks the goal.
    pub fn goal(mut self, p: Point) -> Self {
        self.goal = Some(p);
        self
    }

    /// A title (shown as a tooltip by most viewers).
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// The SVG document.
    pub fn to_svg(&self) -> String {
        let (min, max) = (self.world.bounds().min(), self.world.bounds().max());
        let k = self.scale;
        let at = |p: Point| format!("{},{}", fmt_num((p.x - min.x) * k), fmt_num((max.y - p.y) * k));
        let (w, h) = ((max.x - min.x) * k, (max.y - min.y) * k);
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {} {}">"#,
            fmt_num(w),
            fmt_num(h),
            fmt_num(w),
            fmt_num(h)
        );
        if let Some(title) = &self.title {
            let _ = writeln!(out, "<title>{}</title>", escape(title));
        }
        let _ = writeln!(
            out,
            r#"<rect width="100%" height="100%" fill="white" stroke="{BLOCKED}" stroke-width="2"/>"#
        );
        for cell in &self.cells {
            let points: Vec<String> = cell.iter().map(|&p| at(p)).collect();
            let _ = writeln!(
                out,
                r##"<polygon points="{}" fill="#eaf4fb" stroke="#7fb3d5" stroke-width="0.8"/>"##,
                points.join(" ")
            );
        }
        for o in self.world.obstacles() {
            let points: Vec<String> = o.vertices().iter().map(|&p| at(p)).collect();
            let _ = writeln!(out, r#"<polygon points="{}" fill="{BLOCKED}"/>"#, points.join(" "));
        }
        for &(a, b) in &self.boundary {
            let (a, b) = (at(a), at(b));
            let _ = writeln!(
                out,
                r##"<polyline points="{a} {b}" fill="none" stroke="#7f8c8d" stroke-width="1" stroke-dasharray="3 2"/>"##
            );
        }
        for &(a, b) in &self.edges {
            let (a, b) = (at(a), at(b));
            let _ = writeln!(
                out,
                r##"<polyline points="{a} {b}" fill="none" stroke="#9fd3f5" stroke-width="0.7"/>"##
            );
        }
        for &p in &self.nodes {
            let c = at(p);
            let (x, y) = c.split_once(',').unwrap_or(("0", "0"));
            let _ = writeln!(out, r##"<circle cx="{x}" cy="{y}" r="1.6" fill="#2e86c1"/>"##);
        }
        for pose in &self.poses {
            let p = Point::from(pose.translation.vector);
            let heading = pose.rotation.angle();
            let tip = p + crate::geometry::Vector::new(heading.cos(), heading.sin()) * (8.0 / k);
            let _ = writeln!(
                out,
                r##"<polyline points="{} {}" fill="none" stroke="#2e86c1" stroke-width="1"/>"##,
                at(p),
                at(tip)
            );
        }
        for outline in &self.outlines {
            let points: Vec<String> = outline.iter().map(|&p| at(p)).collect();
            let _ = writeln!(
                out,
                r##"<polygon points="{}" fill="#7f8c8d" fill-opacity="0.15" stroke="#555" stroke-width="0.7"/>"##,
                points.join(" ")
            );
        }
        for (i, path) in self.paths.iter().enumerate() {
            let points: Vec<String> = path.iter().map(|&p| at(p)).collect();
            let _ = writeln!(
                out,
                r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="3" stroke-linejoin="round" stroke-linecap="round"/>"#,
                points.join(" "),
                PATH_COLOURS[i % PATH_COLOURS.len()]
            );
        }
        for &p in &self.marks {
            let c = at(p);
            let (x, y) = c.split_once(',').unwrap_or(("0", "0"));
            let _ = writeln!(out, r##"<circle cx="{x}" cy="{y}" r="3" fill="#c0392b"/>"##);
        }
        for (p, style) in [
            (self.start, r##"fill="#27ae60""##),
            (self.goal, r##"fill="none" stroke="#c0392b" stroke-width="2.5""##),
        ] {
            if let Some(p) = p {
                let c = at(p);
                let (x, y) = c.split_once(',').unwrap_or(("0", "0"));
                let _ = writeln!(out, r#"<circle cx="{x}" cy="{y}" r="6" {style}/>"#);
            }
        }
        out.push_str("</svg>\n");
        out
    }
}

fn fmt_num(v: f64) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocked_runs_are_merged() {
        let grid = Grid::from_rows(&["@@@.", "...."]).unwrap();
        let svg = GridSvg::new(&grid).to_svg();
        assert_eq!(svg.matches(BLOCKED).count(), 1, "{svg}");
        assert!(svg.contains(r##"<rect x="0" y="0" width="3" height="1" fill="#2f3640"/>"##));
    }

    #[test]
    fn paths_and_markers_are_drawn() {
        let grid = Grid::new(3, 3).unwrap();
        let svg = GridSvg::new(&grid).title("a <test>").path(&[Cell::new(0, 0), Cell::new(2, 2)]).to_svg();
        assert!(svg.contains(r#"points="0.5,0.5 2.5,2.5""#));
        assert!(svg.contains("#27ae60") && svg.contains("#c0392b"));
        assert!(svg.contains("a &lt;test&gt;"));
    }
}
