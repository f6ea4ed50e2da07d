//! The free space of a 2D world as polygonal boundary rings, with exact visibility predicates.
//!
//! A [`FreeSpace`] is the region a point robot may occupy, described by its boundary: closed
//! rings of vertices, each walked with the free space on its **left** (an outer boundary
//! counter-clockwise, the boundary of an obstacle inside it clockwise, in the usual
//! y-up picture). It is what the roadmap builders of `trailmark-graph` work on, and it comes
//! from a [`PolygonWorld`](crate::world::PolygonWorld) (obstacles inflated by the robot radius
//! and merged) or from a [`Grid`] (blocked cells as unit squares, the outside of the map
//! blocked, as in the GPPC any-angle track).
//!
//! Obstacles may touch at a vertex (two blocked cells that meet at a corner do). Such a point is
//! a zero-width gap: a segment may touch it, or pass it with every obstacle on one side, but may
//! not pass *between* the obstacles that meet there.
//!
//! Every predicate here is exact: orientation signs come from Shewchuk's adaptive predicates
//! (the `robust` crate), so collinear and touching configurations, which grid maps are full of,
//! are decided without tolerance.
//!
//! ```
//! use trailmark_core::freespace::{FreeSpace, Location};
//! use trailmark_core::geometry::Point;
//! use trailmark_core::Grid;
//!
//! // Blocked cells are unit squares; the outside of the map is blocked.
//! let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
//! let space = FreeSpace::from_grid(&grid);
//! assert_eq!(space.locate(Point::new(0.5, 0.5)), Location::Free);
//! assert_eq!(space.locate(Point::new(1.5, 1.5)), Location::Blocked);
//! assert_eq!(space.locate(Point::new(1.0, 1.0)), Location::Boundary);
//!
//! // A segment may run along the block's side, not through it.
//! assert!(space.segment_is_free(Point::new(0.0, 1.0), Point::new(4.0, 1.0)));
//! assert!(!space.segment_is_free(Point::new(0.0, 0.0), Point::new(4.0, 3.0)));
//! # Ok::<(), trailmark_core::GridError>(())
//! ```

use std::collections::HashMap;

use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy};
use thiserror::Error;

use crate::geometry::Point;
use crate::grid::{Cell, Grid};
use crate::predicates;

/// One free wedge at a boundary vertex: a ring arrives from `prev` and leaves toward `next`, with
/// free space on its left, so the wedge swept counter-clockwise from the direction of `next` to
/// the direction of `prev` is free.
///
/// A vertex where obstacles touch has several corners, one per free wedge between them; the
/// free directions there are the union of the wedges, and a segment may pass through the vertex
/// only within one wedge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Corner {
    /// The vertex before, along the ring.
    pub prev: Point,
    /// The vertex after, along the ring.
    pub next: Point,
}

impl Corner {
    /// Whether the obstacle at this corner is convex (its free wedge exceeds a half turn), the
    /// kind of vertex a shortest path can bend around.
    #[inline]
    pub fn is_convex_obstacle(&self, at: Point) -> bool {
        predicates::orient(self.prev, at, self.next) < 0.0
    }

    /// Whether the direction from `at` toward `q` is free at this corner (on the boundary counts).
    #[inline]
    pub fn admits(&self, at: Point, q: Point) -> bool {
        predicates::in_wedge(at, self.next, self.prev, q)
    }
}

/// Where a point lies relative to a [`FreeSpace`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// Strictly inside the free space.
    Free,
    /// On a boundary ring (touching an obstacle or the outer boundary).
    Boundary,
    /// Inside an obstacle or outside the outer boundary.
    Blocked,
}

/// Why a set of rings does not describe a free space.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum FreeSpaceError {
    /// A vertex has a NaN or infinite coordinate.
    #[error("ring {ring}, vertex {vertex}: coordinates must be finite")]
    NonFinite {
        /// Index of the ring.
        ring: usize,
        /// Index of the vertex in the ring.
        vertex: usize,
    },
    /// A ring has fewer than three distinct vertices after removing repeats.
    #[error("ring {ring}: a ring needs at least three distinct vertices")]
    TooFewVertices {
        /// Index of the ring.
        ring: usize,
    },
}

/// A free space bounded by polygonal rings (free on the left), indexed for exact queries.
///
/// Vertices at the same position are merged into one *position* with one [`Corner`] per ring
/// passage, so obstacles touching at a point are represented faithfully. Edges join positions.
#[derive(Clone, Debug)]
pub struct FreeSpace {
    positions: Vec<Point>,
    corner_start: Vec<u32>,
    corners: Vec<Corner>,
    edges: Vec<[u32; 2]>,
    bvh: Bvh,
}

impl FreeSpace {
    /// A free space from boundary rings, each walked with the free space on its left.
    ///
    /// Consecutive repeated vertices and collinear runs are kept as given except exact repeats,
    /// which are dropped. The rings must not cross each other or themselves (touching at
    /// vertices is allowed); that is not checked here, since the builders of this crate
    /// ([`PolygonWorld::free_space`](crate::world::PolygonWorld::free_space),
    /// [`FreeSpace::from_grid`]) produce such rings by construction.
    pub fn from_rings(rings: &[Vec<Point>]) -> Result<Self, FreeSpaceError> {
        let cleaned =
            rings.iter().enumerate().map(|(r, ring)| clean_ring(r, ring)).collect::<Result<Vec<_>, _>>()?;
        Ok(Self::from_clean_rings(cleaned))
    }

    /// A free space from rings, dropping those that are not rings (fewer than three distinct
    /// vertices, or non-finite ones): the slivers a polygon union can leave.
    pub(crate) fn from_rings_dropping_degenerate(rings: Vec<Vec<Point>>) -> Self {
        Self::from_clean_rings(
            rings.iter().enumerate().filter_map(|(r, ring)| clean_ring(r, ring).ok()).collect(),
        )
    }

    fn from_clean_rings(rings: Vec<Vec<Point>>) -> Self {
        let mut index: HashMap<(u64, u64), u32> = HashMap::new();
        let mut positions = Vec::new();
        let mut id_of = |p: Point, positions: &mut Vec<Point>| -> u32 {
            // +0.0 and -0.0 are one position.
            let key = ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits());
            *index.entry(key).or_insert_with(|| {
                positions.push(p);
                (positions.len() - 1) as u32
            })
        };
        let mut edges = Vec::new();
        let mut passages: Vec<(u32, Corner)> = Vec::new();
        for ring in &rings {
            let n = ring.len();
            let ids: Vec<u32> = ring.iter().map(|&p| id_of(p, &mut positions)).collect();
            for i in 0..n {
                let prev = ring[(i + n - 1) % n];
                let next = ring[(i + 1) % n];
                passages.push((ids[i], Corner { prev, next }));
                edges.push([ids[i], ids[(i + 1) % n]]);
            }
        }
        passages.sort_by_key(|&(id, _)| id);
        let mut corner_start = vec![0u32; positions.len() + 1];
        for &(id, _) in &passages {
            corner_start[id as usize + 1] += 1;
        }
        for i in 0..positions.len() {
            corner_start[i + 1] += corner_start[i];
        }
        let mut corners: Vec<Corner> = passages.into_iter().map(|(_, c)| c).collect();
        for (i, &at) in positions.iter().enumerate() {
            let range = corner_start[i] as usize..corner_start[i + 1] as usize;
            if range.len() > 1 {
                pair_free_wedges(at, &mut corners[range]);
            }
        }
        let leaves: Vec<Aabb> =
            edges.iter().map(|&[a, b]| segment_aabb(positions[a as usize], positions[b as usize])).collect();
        let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
        FreeSpace { positions, corner_start, corners, edges, bvh }
    }

    /// The free space of a grid: passable cells are unit squares `[x, x+1] x [y, y+1]` (x the
    /// column, y the row, as in the GPPC any-angle track), blocked cells and the outside of the
    /// map are obstacles. Where two blocked cells meet only at a corner, the corner is a
    /// zero-width gap that segments may touch but not pass through.
    pub fn from_grid(grid: &Grid) -> Self {
        FreeSpace::from_clean_rings(grid_rings(grid))
    }

    /// The distinct vertex positions of the boundary.
    pub fn positions(&self) -> &[Point] {
        &self.positions
    }

    /// The ring passages through position `index` (one, or more where obstacles touch).
    ///
    /// # Panics
    ///
    /// If `index` is not below the number of [`positions`](Self::positions).
    /// [`get_corners`](Self::get_corners) is the checked form.
    pub fn corners(&self, index: usize) -> &[Corner] {
        &self.corners[self.corner_start[index] as usize..self.corner_start[index + 1] as usize]
    }

    /// The ring passages through position `index`, `None` if there is no such position.
    pub fn get_corners(&self, index: usize) -> Option<&[Corner]> {
        (index < self.positions.len()).then(|| self.corners(index))
    }

    /// The boundary edges as pairs of position indices, free space on the left of `a -> b`.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// The endpoints of edge `e`.
    #[inline]
    pub fn edge_points(&self, e: usize) -> (Point, Point) {
        let [a, b] = self.edges[e];
        (self.positions[a as usize], self.positions[b as usize])
    }

    /// The smallest axis-aligned box holding the boundary: `(min, max)`.
    pub fn bounding_box(&self) -> (Point, Point) {
        let aabb = self.bvh.root_aabb();
        (Point::new(aabb.mins.x, aabb.mins.y), Point::new(aabb.maxs.x, aabb.maxs.y))
    }

    /// Indices of the edges whose bounding boxes meet the box `min..max`.
    fn edges_near(&self, min: Point, max: Point) -> impl Iterator<Item = usize> + '_ {
        let query = Aabb::new(PVector::new(min.x, min.y), PVector::new(max.x, max.y));
        // The iterator borrows the query box, so collect the few candidates.
        self.bvh.intersect_aabb(&query).map(|i| i as usize).collect::<Vec<_>>().into_iter()
    }

    /// Indices of the edges found by descending the boundary's bounding-volume tree through
    /// every box `(min, max)` that `keep` accepts (a subtree whose box is refused is skipped;
    /// an edge is returned when its own bounding box is accepted). `keep` must accept every box
    /// that holds a box it accepts, as a region test does.
    pub fn edges_where<'a>(
        &'a self,
        keep: impl Fn(Point, Point) -> bool + 'a,
    ) -> impl Iterator<Item = usize> + 'a {
        self.bvh
            .leaves(move |node| {
                let (min, max) = (node.mins(), node.maxs());
                keep(Point::new(min.x, min.y), Point::new(max.x, max.y))
            })
            .map(|i| i as usize)
    }

    /// The edges that pass through `p` (as an endpoint or in their interior).
    pub fn edges_through(&self, p: Point) -> impl Iterator<Item = usize> + '_ {
        self.edges_near(p, p).filter(move |&e| {
            let (a, b) = self.edge_points(e);
            predicates::on_segment(a, b, p)
        })
    }

    /// The position index at exactly `p`, if `p` is a vertex.
    pub fn position_at(&self, p: Point) -> Option<usize> {
        self.edges_near(p, p).find_map(|e| {
            let [a, b] = self.edges[e];
            [a, b].into_iter().map(|i| i as usize).find(|&i| self.positions[i] == p)
        })
    }

    /// Where `p` lies: free, on the boundary, or blocked. Exact.
    pub fn locate(&self, p: Point) -> Location {
        let (_, max) = self.bounding_box();
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Location::Blocked;
        }
        // Winding number of the rings around p, from the edges near the ray to +x.
        let near = self.edges_near(p, Point::new(max.x.max(p.x), p.y)).map(|e| self.edge_points(e));
        match predicates::winding_number(p, near) {
            None => Location::Boundary,
            Some(w) if w > 0 => Location::Free,
            Some(_) => Location::Blocked,
        }
    }

    /// The free directions at point `p` on the boundary: whether the direction toward `q` leaves
    /// `p` into free space (or along the boundary). `p` must be on the boundary.
    pub fn admits_direction(&self, p: Point, q: Point) -> bool {
        self.departure(p)(q)
    }

    /// The test of [`admits_direction`](Self::admits_direction) for one point `p` and many
    /// directions: the vertex or edges at `p` are looked up once. At a point of the open free
    /// space every direction is admitted.
    pub fn departure(&self, p: Point) -> impl Fn(Point) -> bool + '_ {
        let vertex = self.position_at(p);
        // On the interior of edges: free on their left.
        let through: Vec<(Point, Point)> = match vertex {
            Some(_) => Vec::new(),
            None => self
                .edges_near(p, p)
                .map(|e| self.edge_points(e))
                .filter(|&(a, b)| predicates::orient(a, b, p) == 0.0 && predicates::strictly_between(a, b, p))
                .collect(),
        };
        move |q| match vertex {
            Some(i) => self.corners(i).iter().any(|c| c.admits(p, q)),
            None => through.iter().all(|&(a, b)| predicates::orient(a, b, q) >= 0.0),
        }
    }

    /// Whether a segment through the vertex at position `index`, from `a` to `b` (the vertex
    /// strictly between them), stays in free space there: both directions within one free wedge,
    /// so the segment touches the obstacles meeting there from one side only.
    pub fn passes_through(&self, index: usize, a: Point, b: Point) -> bool {
        let at = self.positions[index];
        self.corners(index).iter().any(|c| c.admits(at, a) && c.admits(at, b))
    }

    /// Whether the closed segment `a`-`b` lies in the free space (touching the boundary allowed,
    /// passing between obstacles that touch at a point not). Exact; independent of any graph,
    /// so tests use it to check the edges that builders produce.
    pub fn segment_is_free(&self, a: Point, b: Point) -> bool {
        let (la, lb) = (self.locate(a), self.locate(b));
        if la == Location::Blocked || lb == Location::Blocked {
            return false;
        }
        if a == b {
            return true;
        }
        if la == Location::Boundary && !self.admits_direction(a, b) {
            return false;
        }
        if lb == Location::Boundary && !self.admits_direction(b, a) {
            return false;
        }
        let min = Point::new(a.x.min(b.x), a.y.min(b.y));
        let max = Point::new(a.x.max(b.x), a.y.max(b.y));
        for e in self.edges_near(min, max) {
            let [i, j] = self.edges[e];
            let (p, q) = (self.positions[i as usize], self.positions[j as usize]);
            let (sp, sq) = (predicates::orient(a, b, p), predicates::orient(a, b, q));
            let (sa, sb) = (predicates::orient(p, q, a), predicates::orient(p, q, b));
            if sp * sq < 0.0 && sa * sb < 0.0 {
                return false;
            }
            for (k, s) in [(i, sp), (j, sq)] {
                let v = self.positions[k as usize];
                if s == 0.0 && predicates::strictly_between(a, b, v) && !self.passes_through(k as usize, a, b)
                {
                    return false;
                }
            }
        }
        true
    }
}

/// Re-pairs the ring passages through one vertex so that each corner is one free wedge: every
/// edge leaving the vertex has free space counter-clockwise of it, up to the next edge arriving.
/// (Rings that touch at a vertex may be linked either way there; this makes the two agree.)
fn pair_free_wedges(at: Point, corners: &mut [Corner]) {
    // (direction point, leaving?) sorted counter-clockwise from +x.
    let mut directions: Vec<(Point, bool)> =
        corners.iter().flat_map(|c| [(c.next, true), (c.prev, false)]).collect();
    directions.sort_by(|&(p, _), &(q, _)| predicates::angular_order(at, p, q));
    let n = directions.len();
    let mut paired = Vec::with_capacity(corners.len());
    for (k, &(next, leaving)) in directions.iter().enumerate() {
        if !leaving {
            continue;
        }
        if let Some(&(prev, _)) = (1..n).map(|s| &directions[(k + s) % n]).find(|(_, l)| !l) {
            paired.push(Corner { prev, next });
        }
    }
    if paired.len() == corners.len() {
        corners.copy_from_slice(&paired);
    }
}

/// Ring `r` with repeated consecutive vertices (and a closing repeat) dropped, checked.
fn clean_ring(r: usize, ring: &[Point]) -> Result<Vec<Point>, FreeSpaceError> {
    if let Some(v) = ring.iter().position(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(FreeSpaceError::NonFinite { ring: r, vertex: v });
    }
    let kept = predicates::dedup_ring(ring.iter().copied());
    if kept.len() < 3 {
        return Err(FreeSpaceError::TooFewVertices { ring: r });
    }
    Ok(kept)
}

fn segment_aabb(a: Point, b: Point) -> Aabb {
    Aabb::new(PVector::new(a.x.min(b.x), a.y.min(b.y)), PVector::new(a.x.max(b.x), a.y.max(b.y)))
}

/// The boundary rings of a grid's free cells, free on the left, collinear unit edges merged.
fn grid_rings(grid: &Grid) -> Vec<Vec<Point>> {
    let (w, h) = (grid.width() as i64, grid.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && grid.is_passable(Cell::new(x as u32, y as u32))
    };
    // Unit edges between a free cell and a blocked one, free on the left (orient > 0).
    // Each edge: (start, end, direction 0..4) with directions +x, +y, -x, -y.
    let mut edges: Vec<([i64; 2], u8)> = Vec::new();
    for y in 0..h {
        for x in 0..w {
            if !free(x, y) {
                continue;
            }
            if !free(x, y - 1) {
                edges.push(([x, y], 0));
            }
            if !free(x + 1, y) {
                edges.push(([x + 1, y], 1));
            }
            if !free(x, y + 1) {
                edges.push(([x + 1, y + 1], 2));
            }
            if !free(x - 1, y) {
                edges.push(([x, y + 1], 3));
            }
        }
    }
    const STEP: [[i64; 2]; 4] = [[1, 0], [0, 1], [-1, 0], [0, -1]];
    let end = |(s, d): ([i64; 2], u8)| [s[0] + STEP[d as usize][0], s[1] + STEP[d as usize][1]];
    let mut starting: HashMap<[i64; 2], Vec<usize>> = HashMap::with_capacity(edges.len());
    for (i, &(s, _)) in edges.iter().enumerate() {
        starting.entry(s).or_default().push(i);
    }
    let mut used = vec![false; edges.len()];
    let mut rings = Vec::new();
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        let mut ring: Vec<Point> = Vec::new();
        let mut current = first;
        loop {
            used[current] = true;
            let (s, d) = edges[current];
            ring.push(Point::new(s[0] as f64, s[1] as f64));
            let e = end(edges[current]);
            let candidates = &starting[&e];
            // At a corner where blocked cells touch diagonally, two edges leave: keep to the
            // free cell being walked around, which is a left turn (counter-clockwise).
            let next = if candidates.len() == 1 {
                candidates[0]
            } else {
                let left = (d + 1) % 4;
                *candidates.iter().find(|&&c| edges[c].1 == left).unwrap_or(&candidates[0])
            };
            current = next;
            if used[current] {
                break;
            }
        }
        rings.push(merge_collinear(ring));
    }
    rings
}

/// Drops the vertices of a ring of axis-aligned unit edges where the ring goes straight on.
fn merge_collinear(ring: Vec<Point>) -> Vec<Point> {
    let n = ring.len();
    (0..n)
        .filter(|&i| predicates::orient(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) != 0.0)
        .map(|i| ring[i])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn wedges_of_every_size() {
        let o = p(0.0, 0.0);
        // Quarter turn from +x to +y.
        assert!(predicates::in_wedge(o, p(1.0, 0.0), p(0.0, 1.0), p(1.0, 1.0)));
        assert!(predicates::in_wedge(o, p(1.0, 0.0), p(0.0, 1.0), p(2.0, 0.0)));
        assert!(!predicates::in_wedge(o, p(1.0, 0.0), p(0.0, 1.0), p(-1.0, -1.0)));
        // Three quarters from +y to +x.
        assert!(predicates::in_wedge(o, p(0.0, 1.0), p(1.0, 0.0), p(-1.0, -1.0)));
        assert!(!predicates::in_wedge(o, p(0.0, 1.0), p(1.0, 0.0), p(1.0, 1.0)));
        // Half turn from +x to -x: the upper half-plane.
        assert!(predicates::in_wedge(o, p(1.0, 0.0), p(-1.0, 0.0), p(0.0, 1.0)));
        assert!(!predicates::in_wedge(o, p(1.0, 0.0), p(-1.0, 0.0), p(0.0, -1.0)));
    }

    #[test]
    fn grid_rings_walk_free_space_on_the_left() {
        let grid = Grid::from_rows(&["..", ".."]).unwrap();
        let rings = grid_rings(&grid);
        assert_eq!(rings.len(), 1);
        assert_eq!(rings[0].len(), 4);
        let r = &rings[0];
        assert!(predicates::orient(r[0], r[1], r[2]) > 0.0);
    }

    #[test]
    fn diagonal_touch_is_a_gap_that_cannot_be_crossed() {
        // Blocked cells (1,0) and (0,1) meet at (1,1); so do the free cells (0,0) and (1,1).
        let grid = Grid::from_rows(&[".@.", "@..", "..."]).unwrap();
        let space = FreeSpace::from_grid(&grid);
        let pinch = space.position_at(p(1.0, 1.0)).unwrap();
        assert_eq!(space.corners(pinch).len(), 2);
        // From inside cell (0,0) through the pinch into cell (1,1): not allowed.
        assert!(!space.segment_is_free(p(0.5, 0.5), p(1.5, 1.5)));
        // Touching the pinch and turning back is fine.
        assert!(space.segment_is_free(p(0.5, 0.5), p(1.0, 1.0)));
        assert!(space.segment_is_free(p(2.0, 2.0), p(1.0, 1.0)));
        // Grazing the corner of one blocked cell from free space on one side.
        assert!(space.segment_is_free(p(2.0, 1.0), p(0.0, 3.0)));
    }

    #[test]
    fn segments_along_walls_and_through_blocks() {
        let grid = Grid::from_rows(&["....", ".@@.", "...."]).unwrap();
        let space = FreeSpace::from_grid(&grid);
        assert!(space.segment_is_free(p(0.0, 1.0), p(4.0, 1.0)));
        assert!(space.segment_is_free(p(0.0, 2.0), p(4.0, 2.0)));
        assert!(!space.segment_is_free(p(0.0, 1.5), p(4.0, 1.5)));
        // Along the map's outer boundary: fine, it is a wall with free space on one side.
        assert!(space.segment_is_free(p(0.0, 0.0), p(4.0, 0.0)));
        // Leaving the map.
        assert!(!space.segment_is_free(p(0.0, 0.0), p(-1.0, 0.0)));
        // Grazing a corner of the block.
        assert!(space.segment_is_free(p(0.0, 0.0), p(2.0, 1.0)));
        assert!(space.segment_is_free(p(1.0, 0.0), p(0.0, 1.0)));
        assert!(!space.segment_is_free(p(0.0, 0.0), p(2.0, 2.0)));
    }

    #[test]
    fn walls_of_blocked_cells_on_the_map_edge_cannot_be_followed() {
        // The top row's middle cells are blocked: the map edge there is no longer free boundary.
        let grid = Grid::from_rows(&[".@@.", "...."]).unwrap();
        let space = FreeSpace::from_grid(&grid);
        assert!(!space.segment_is_free(p(0.0, 0.0), p(4.0, 0.0)));
        assert!(space.segment_is_free(p(0.0, 1.0), p(4.0, 1.0)));
    }

    #[test]
    fn bad_rings_are_errors() {
        let ring = vec![p(0.0, 0.0), p(1.0, 0.0), p(f64::NAN, 1.0)];
        assert_eq!(
            FreeSpace::from_rings(&[ring]).unwrap_err(),
            FreeSpaceError::NonFinite { ring: 0, vertex: 2 }
        );
        let ring = vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 0.0), p(0.0, 0.0)];
        assert_eq!(FreeSpace::from_rings(&[ring]).unwrap_err(), FreeSpaceError::TooFewVertices { ring: 0 });
    }
}
