//! Trapezoidal (vertical) cell decomposition of a polygonal free space.
//!
//! A vertical line swept from left to right stops at every boundary vertex; from each vertex a
//! vertical extension runs up and down to the nearest boundary edges. The extensions cut the
//! free space into *cells*: trapezoids (or triangles) with two vertical sides and a boundary edge
//! below and above. Two cells are adjacent where they share a piece of vertical side, a
//! *portal*. The roadmap of the decomposition has a node at every cell's centroid and at every
//! portal's midpoint, and joins each cell's centroid to the midpoints of its portals, as in the
//! textbook construction, and also the portal midpoints of one cell to each other (a path need
//! not detour through the centroid of every cell it crosses). Each of those segments lies inside
//! one convex cell, so the roadmap is collision-free by construction.
//!
//! A query locates the start's and goal's cells (a bounding-volume hierarchy over the cells,
//! then exact orientation tests) and joins each to its cells' centroids and portal midpoints,
//! and the start to the goal when they share a cell. Searching the query graph gives the
//! cell path and the polyline through it; it is a path, not the shortest one (the visibility
//! graph gives that), and its cost is an upper bound.
//!
//! The sweep handles what grid maps are made of: many vertices on one vertical line, vertical
//! boundary edges, and obstacles touching at a corner (cells meet there only at a point, so no
//! portal crosses the pinch). Every above/below decision is an exact orientation test.
//!
//! ```
//! use trailmark_core::freespace::FreeSpace;
//! use trailmark_core::geometry::{Point, Vector};
//! use trailmark_core::Grid;
//! use trailmark_graph::trapezoid::Trapezoids;
//!
//! // Blocked cells are unit squares: one block in the middle of a 4 x 3 map.
//! let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
//! let cells = Trapezoids::new(&FreeSpace::from_grid(&grid));
//! assert_eq!(cells.cell_count(), 4); // left, below, above and right of the block
//! let area: f64 = (0..cells.cell_count()).map(|c| cells.cell(c).area()).sum();
//! assert_eq!(area, 10.0); // the free cells of the map
//!
//! let query = cells.query(Point::new(0.5, 1.5), Point::new(3.5, 1.5))?;
//! let route = trailmark_search::dijkstra(&query, query.start(), query.goal())?;
//! let cost = route.cost().expect("around the block");
//! assert!(cost > 3.0); // longer than the straight line through the block
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::cmp::Ordering;

use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy};
use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::freespace::FreeSpace;
use trailmark_core::geometry::{Point, Vector};
use trailmark_core::predicates::orient;

use crate::roadmap::{Roadmap, RoadmapQuery};

/// A query point outside every cell.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum TrapezoidError {
    /// The start is not in the free space.
    #[error("the start ({x}, {y}) is not in the free space")]
    StartBlocked {
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
    },
    /// The goal is not in the free space.
    #[error("the goal ({x}, {y}) is not in the free space")]
    GoalBlocked {
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
    },
}

/// A boundary edge, its ends ordered by x (then y), and which side is free.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Side {
    /// The left end.
    pub from: Point,
    /// The right end.
    pub to: Point,
}

impl Side {
    /// The edge's height at `x` (within its x range).
    pub fn y_at(&self, x: f64) -> f64 {
        if x == self.from.x {
            self.from.y
        } else if x == self.to.x {
            self.to.y
        } else {
            self.from.y + (self.to.y - self.from.y) * ((x - self.from.x) / (self.to.x - self.from.x))
        }
    }

    /// Whether `p` is on or above the edge's line (exact).
    fn holds_above(&self, p: Point) -> bool {
        orient(self.from, self.to, p) >= 0.0
    }

    /// Whether `p` is on or below the edge's line (exact).
    fn holds_below(&self, p: Point) -> bool {
        orient(self.from, self.to, p) <= 0.0
    }
}

/// One cell: the region between two vertical lines, above one boundary edge and below another.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trapezoid {
    /// The x of the left side.
    pub left: f64,
    /// The x of the right side.
    pub right: f64,
    /// The boundary edge below.
    pub bottom: Side,
    /// The boundary edge above.
    pub top: Side,
}

impl Trapezoid {
    /// The corners, counter-clockwise from the bottom left (a triangle repeats a corner).
    pub fn corners(&self) -> [Point; 4] {
        [
            Point::new(self.left, self.bottom.y_at(self.left)),
            Point::new(self.right, self.bottom.y_at(self.right)),
            Point::new(self.right, self.top.y_at(self.right)),
            Point::new(self.left, self.top.y_at(self.left)),
        ]
    }

    /// The area.
    pub fn area(&self) -> f64 {
        let [a, b, c, d] = self.corners();
        0.5 * (self.right - self.left) * ((d.y - a.y) + (c.y - b.y))
    }

    /// The centroid (of the area).
    pub fn centroid(&self) -> Point {
        // Relative to the first corner, so a sliver far from the origin keeps its digits.
        let origin = self.corners()[0];
        let corners = self.corners().map(|c| Point::from(c - origin));
        let (mut area, mut cx, mut cy) = (0.0, 0.0, 0.0);
        for i in 0..4 {
            let (p, q) = (corners[i], corners[(i + 1) % 4]);
            let cross = p.x * q.y - q.x * p.y;
            area += cross;
            cx += (p.x + q.x) * cross;
            cy += (p.y + q.y) * cross;
        }
        if area == 0.0 {
            return corners.iter().fold(origin, |s, p| s + p.coords / 4.0);
        }
        origin + Vector::new(cx / (3.0 * area), cy / (3.0 * area))
    }

    /// Whether `p` lies in the closed cell (exact above/below tests).
    pub fn contains(&self, p: Point) -> bool {
        self.left <= p.x && p.x <= self.right && self.bottom.holds_above(p) && self.top.holds_below(p)
    }
}

/// A shared piece of vertical side between a cell on its left and a cell on its right.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Portal {
    /// The cell on the left.
    pub left: u32,
    /// The cell on the right.
    pub right: u32,
    /// The x of the vertical line.
    pub x: f64,
    /// The lower end's y.
    pub low: f64,
    /// The upper end's y.
    pub high: f64,
}

impl Portal {
    /// The midpoint: the roadmap's node for this portal.
    pub fn midpoint(&self) -> Point {
        Point::new(self.x, 0.5 * (self.low + self.high))
    }
}

/// The trapezoidal decomposition of a [`FreeSpace`] and its roadmap.
///
/// Roadmap nodes `0..cell_count()` are the cells' centroids, then one node per portal at its
/// midpoint; edges join a cell's centroid to its portals' midpoints and a cell's portal
/// midpoints to each other, undirected, costing their length.
#[derive(Clone, Debug)]
pub struct Trapezoids {
    cells: Vec<Trapezoid>,
    portals: Vec<Portal>,
    /// Portals of each cell: `cell_portals[cell_start[c]..cell_start[c + 1]]`.
    cell_start: Vec<u32>,
    cell_portals: Vec<u32>,
    points: Vec<Point>,
    bvh: Bvh,
}

/// A non-vertical boundary edge during the sweep.
#[derive(Clone, Copy, Debug)]
struct SweepEdge {
    side: Side,
    /// Whether the free space lies above it.
    free_above: bool,
}

/// Compares two boundary edges that do not cross and overlap in x over an interval of positive
/// length: `Less` when `e` is below `f` there.
fn below(e: &Side, f: &Side) -> Ordering {
    if e.from.x >= f.from.x {
        let s = orient(f.from, f.to, e.from);
        let s = if s == 0.0 { orient(f.from, f.to, e.to) } else { s };
        0.0.partial_cmp(&s).unwrap_or(Ordering::Equal).reverse()
    } else {
        below(f, e).reverse()
    }
}

/// An open cell during the sweep.
#[derive(Clone, Copy)]
struct Open {
    cell: u32,
    bottom: u32,
    top: u32,
}

impl Trapezoids {
    /// Decomposes `space` by a sweep over its vertices: O(n log n + n k) for n vertices and at
    /// most k edges crossing one vertical line.
    pub fn new(space: &FreeSpace) -> Self {
        let edges: Vec<SweepEdge> = (0..space.edges().len())
            .filter_map(|e| {
                let (p, q) = space.edge_points(e);
                if p.x == q.x {
                    return None; // vertical: a boundary on an event line, not in the status
                }
                let side = if p.x < q.x { Side { from: p, to: q } } else { Side { from: q, to: p } };
                // Free on the left of p -> q: above when it runs rightwards.
                Some(SweepEdge { side, free_above: p.x < q.x })
            })
            .collect();
        let verticals: Vec<(f64, f64, f64)> = (0..space.edges().len())
            .filter_map(|e| {
                let (p, q) = space.edge_points(e);
                (p.x == q.x).then(|| (p.x, p.y.min(q.y), p.y.max(q.y)))
            })
            .collect();
        // Events: the distinct x of the vertices; edges start and end at them.
        let mut order: Vec<u32> = (0..edges.len() as u32).collect();
        order.sort_by(|&a, &b| edges[a as usize].side.from.x.total_cmp(&edges[b as usize].side.from.x));
        let mut ends: Vec<u32> = (0..edges.len() as u32).collect();
        ends.sort_by(|&a, &b| edges[a as usize].side.to.x.total_cmp(&edges[b as usize].side.to.x));
        let mut points: Vec<Point> = space.positions().to_vec();
        points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        let mut verticals_sorted = verticals;
        verticals_sorted.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));

        let mut status: Vec<u32> = Vec::new();
        let mut open_above: Vec<Option<Open>> = vec![None; edges.len()];
        let mut cells: Vec<Trapezoid> = Vec::new();
        let mut portals: Vec<Portal> = Vec::new();
        let (mut next_start, mut next_end, mut next_vertical) = (0, 0, 0);
        let mut i = 0;
        let side = |e: u32| &edges[e as usize].side;
        while i < points.len() {
            let x = points[i].x;
            let mut j = i;
            while j < points.len() && points[j].x == x {
                j += 1;
            }
            let at_x = &points[i..j];
            i = j;

            // Close the cells whose closed vertical extent at x holds a vertex.
            let mut closing: Vec<Open> = Vec::new();
            for &v in at_x {
                for bottom in gap_bottoms(&status, &edges, v) {
                    if let Some(open) = open_above[bottom as usize].take() {
                        cells[open.cell as usize].right = x;
                        closing.push(open);
                    }
                }
            }

            // Update the status: edges ending at x leave, edges starting at x enter.
            while next_end < ends.len() && side(ends[next_end]).to.x == x {
                let e = ends[next_end];
                if let Some(k) = status.iter().position(|&s| s == e) {
                    status.remove(k);
                }
                next_end += 1;
            }
            while next_start < order.len() && side(order[next_start]).from.x == x {
                let e = order[next_start];
                let k = status.partition_point(|&s| below(side(s), side(e)) == Ordering::Less);
                status.insert(k, e);
                next_start += 1;
            }

            // Open the cells whose closed vertical extent at x holds a vertex.
            let mut opening: Vec<Open> = Vec::new();
            for &v in at_x {
                for bottom in gap_bottoms(&status, &edges, v) {
                    if open_above[bottom as usize].is_none() {
                        // A free-above edge has a boundary edge above it in a valid free
                        // space; rings that break that (crossing each other after rounding)
                        // leave the gap without a cell rather than panic.
                        let Some(k) = status.iter().position(|&s| s == bottom) else { continue };
                        let Some(&top) = status.get(k + 1) else { continue };
                        let open = Open { cell: cells.len() as u32, bottom, top };
                        cells.push(Trapezoid {
                            left: x,
                            right: f64::NAN,
                            bottom: *side(bottom),
                            top: *side(top),
                        });
                        open_above[bottom as usize] = Some(open);
                        opening.push(open);
                    }
                }
            }

            // Portals: where a closed cell's right side and an opened cell's left side overlap
            // by a positive length, less any vertical boundary edge on the line.
            let mut walls: Vec<(f64, f64)> = Vec::new();
            while next_vertical < verticals_sorted.len() && verticals_sorted[next_vertical].0 == x {
                let (_, low, high) = verticals_sorted[next_vertical];
                walls.push((low, high));
                next_vertical += 1;
            }
            for left in &closing {
                let (l_low, l_high) = (side(left.bottom).y_at(x), side(left.top).y_at(x));
                for right in &opening {
                    let (r_low, r_high) = (side(right.bottom).y_at(x), side(right.top).y_at(x));
                    let (low, high) = (l_low.max(r_low), l_high.min(r_high));
                    for (low, high) in subtract(low, high, &walls) {
                        portals.push(Portal { left: left.cell, right: right.cell, x, low, high });
                    }
                }
            }
        }
        Self::finish(cells, portals)
    }

    fn finish(cells: Vec<Trapezoid>, portals: Vec<Portal>) -> Self {
        let mut cell_start = vec![0u32; cells.len() + 1];
        for p in &portals {
            cell_start[p.left as usize + 1] += 1;
            cell_start[p.right as usize + 1] += 1;
        }
        for c in 0..cells.len() {
            cell_start[c + 1] += cell_start[c];
        }
        let mut fill = cell_start.clone();
        let mut cell_portals = vec![0u32; 2 * portals.len()];
        for (k, p) in portals.iter().enumerate() {
            for c in [p.left, p.right] {
                cell_portals[fill[c as usize] as usize] = k as u32;
                fill[c as usize] += 1;
            }
        }
        let mut points: Vec<Point> = cells.iter().map(Trapezoid::centroid).collect();
        points.extend(portals.iter().map(Portal::midpoint));
        let leaves: Vec<Aabb> = cells
            .iter()
            .map(|c| {
                let corners = c.corners();
                let low = corners.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
                let high = corners.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
                Aabb::new(PVector::new(c.left, low), PVector::new(c.right, high))
            })
            .collect();
        let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
        Trapezoids { cells, portals, cell_start, cell_portals, points, bvh }
    }

    /// The number of cells.
    pub fn cell_count(&self) -> usize {
        self.cells.len()
    }

    /// Cell `index`.
    ///
    /// # Panics
    ///
    /// If `index` is not below [`cell_count`](Self::cell_count): cell ids are indices, as a
    /// slice's. [`get_cell`](Self::get_cell) is the checked form.
    pub fn cell(&self, index: usize) -> &Trapezoid {
        &self.cells[index]
    }

    /// Cell `index`, `None` if there is no such cell.
    pub fn get_cell(&self, index: usize) -> Option<&Trapezoid> {
        self.cells.get(index)
    }

    /// The portals between cells.
    pub fn portals(&self) -> &[Portal] {
        &self.portals
    }

    /// The portals of cell `index`.
    ///
    /// # Panics
    ///
    /// If `index` is not below [`cell_count`](Self::cell_count).
    pub fn portals_of(&self, index: usize) -> impl Iterator<Item = &Portal> + '_ {
        let range = self.cell_start[index] as usize..self.cell_start[index + 1] as usize;
        self.cell_portals[range].iter().map(|&k| &self.portals[k as usize])
    }

    /// The cells adjacent to cell `index` (through a portal).
    ///
    /// # Panics
    ///
    /// If `index` is not below [`cell_count`](Self::cell_count).
    pub fn neighbours(&self, index: usize) -> impl Iterator<Item = usize> + '_ {
        self.portals_of(index)
            .map(move |p| if p.left as usize == index { p.right as usize } else { p.left as usize })
    }

    /// Every cell holding `p` (more than one on a shared side), in index order.
    pub fn locate_all(&self, p: Point) -> Vec<usize> {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Vec::new();
        }
        let query = Aabb::new(PVector::new(p.x, p.y), PVector::new(p.x, p.y));
        let mut found: Vec<usize> = self
            .bvh
            .intersect_aabb(&query)
            .map(|i| i as usize)
            .filter(|&c| self.cells[c].contains(p))
            .collect();
        found.sort_unstable();
        found
    }

    /// A cell holding `p`, `None` if `p` is not in the free space.
    pub fn locate(&self, p: Point) -> Option<usize> {
        self.locate_all(p).first().copied()
    }

    /// The graph with `start` and `goal` joined to the centroids and portal midpoints of the
    /// cells holding them, and to each other when they share a cell.
    pub fn query(&self, start: Point, goal: Point) -> Result<TrapezoidQuery<'_>, TrapezoidError> {
        let starts = self.locate_all(start);
        if starts.is_empty() {
            return Err(TrapezoidError::StartBlocked { x: start.x, y: start.y });
        }
        let goals = self.locate_all(goal);
        if goals.is_empty() {
            return Err(TrapezoidError::GoalBlocked { x: goal.x, y: goal.y });
        }
        let n = self.points.len();
        let links = |at: Point, cells: &[usize]| {
            let mut row = vec![Cost::INFINITY; n];
            for &c in cells {
                row[c] = (self.points[c] - at).norm();
                let range = self.cell_start[c] as usize..self.cell_start[c + 1] as usize;
                for &k in &self.cell_portals[range] {
                    let node = self.cells.len() + k as usize;
                    row[node] = (self.points[node] - at).norm();
                }
            }
            row
        };
        let shared = starts.iter().any(|c| goals.contains(c));
        let direct = shared.then(|| (goal - start).norm());
        Ok(RoadmapQuery::new(self, (start, goal), links(start, &starts), links(goal, &goals), direct)
            .expect("a link per roadmap node"))
    }
}

/// The bottoms of the status gaps whose closed extent holds `v`: the edge just below `v`, and
/// every edge through `v` (the gap above each), keeping those with free space above.
fn gap_bottoms(status: &[u32], edges: &[SweepEdge], v: Point) -> Vec<u32> {
    let side = |e: u32| &edges[e as usize].side;
    let first = status.partition_point(|&s| orient(side(s).from, side(s).to, v) > 0.0);
    let mut bottoms = Vec::new();
    if first > 0 {
        bottoms.push(status[first - 1]);
    }
    let mut k = first;
    while k < status.len() && orient(side(status[k]).from, side(status[k]).to, v) == 0.0 {
        bottoms.push(status[k]);
        k += 1;
    }
    bottoms.retain(|&e| edges[e as usize].free_above);
    bottoms
}

/// The pieces of `[low, high]` of positive length not covered by `walls`.
fn subtract(low: f64, high: f64, walls: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut pieces = Vec::new();
    let mut from = low;
    for &(a, b) in walls {
        if b <= from || a >= high {
            continue;
        }
        if a > from {
            pieces.push((from, a));
        }
        from = from.max(b);
    }
    if high > from {
        pieces.push((from, high));
    }
    pieces
}

/// A trapezoidal decomposition's roadmap with a start and a goal: the graph to search for one
/// query.
pub type TrapezoidQuery<'g> = RoadmapQuery<'g, Trapezoids>;

impl Roadmap for Trapezoids {
    type Position = Point;
    const DIRECTED: bool = false;

    fn node_count(&self) -> usize {
        self.points.len()
    }

    fn position(&self, node: u32) -> Point {
        self.points[node as usize]
    }

    fn lower_bound(&self, a: Point, b: Point) -> Cost {
        (b - a).norm()
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        let cells = self.cells.len();
        let at = self.points[node as usize];
        if (node as usize) < cells {
            let range = self.cell_start[node as usize] as usize..self.cell_start[node as usize + 1] as usize;
            for &k in &self.cell_portals[range] {
                let v = cells + k as usize;
                visit(v as u32, (self.points[v] - at).norm());
            }
        } else {
            let k = node as usize - cells;
            let portal = &self.portals[k];
            for c in [portal.left, portal.right] {
                visit(c, (self.points[c as usize] - at).norm());
                let range = self.cell_start[c as usize] as usize..self.cell_start[c as usize + 1] as usize;
                for &other in &self.cell_portals[range] {
                    if other as usize != k {
                        let v = cells + other as usize;
                        visit(v as u32, (self.points[v] - at).norm());
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// A 10 x 10 room (counter-clockwise) with a triangular hole (clockwise).
    fn room_with_triangle() -> FreeSpace {
        let outer = vec![p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0), p(0.0, 10.0)];
        let hole = vec![p(3.0, 3.0), p(5.0, 7.0), p(7.0, 3.0)];
        FreeSpace::from_rings(&[outer, hole]).unwrap()
    }

    #[test]
    fn a_triangle_splits_the_room_into_five_cells() {
        let cells = Trapezoids::new(&room_with_triangle());
        // Left of the triangle, below it (its apex extends only upwards), above it (two cells,
        // split at the apex), and right of it.
        assert_eq!(cells.cell_count(), 5);
        let area: f64 = (0..5).map(|c| cells.cell(c).area()).sum();
        assert!((area - (100.0 - 8.0)).abs() < 1e-12, "{area}");
        // The left cell touches the two cells below and above the triangle's left half.
        let left = cells.locate(p(1.0, 5.0)).unwrap();
        assert_eq!(cells.neighbours(left).count(), 2);
        // Inside the triangle is no cell; on its boundary are.
        assert_eq!(cells.locate(p(5.0, 4.0)), None);
        assert!(cells.locate(p(5.0, 3.0)).is_some());
        // On the vertical line through the apex, above it, a point is in two cells.
        assert_eq!(cells.locate_all(p(5.0, 9.0)).len(), 2);
    }

    #[test]
    fn queries_join_the_ends_and_reject_blocked_points() {
        let cells = Trapezoids::new(&room_with_triangle());
        let q = cells.query(p(1.0, 1.0), p(1.0, 9.0)).unwrap();
        assert!(q.sees_goal(), "both in the left cell");
        let q = cells.query(p(1.0, 1.0), p(9.0, 9.0)).unwrap();
        assert!(!q.sees_goal());
        let (from_start, to_goal) = q.link_counts();
        assert!(from_start >= 2 && to_goal >= 2);
        assert_eq!(
            cells.query(p(5.0, 4.0), p(1.0, 1.0)).unwrap_err(),
            TrapezoidError::StartBlocked { x: 5.0, y: 4.0 }
        );
        assert!(matches!(
            cells.query(p(1.0, 1.0), p(f64::NAN, 1.0)),
            Err(TrapezoidError::GoalBlocked { .. })
        ));
    }

    #[test]
    fn subtracting_walls_keeps_positive_pieces() {
        assert_eq!(subtract(0.0, 5.0, &[(1.0, 2.0), (1.5, 3.0)]), [(0.0, 1.0), (3.0, 5.0)]);
        assert_eq!(subtract(0.0, 5.0, &[(-1.0, 6.0)]), []);
        assert_eq!(subtract(0.0, 5.0, &[(5.0, 6.0)]), [(0.0, 5.0)]);
    }
}
