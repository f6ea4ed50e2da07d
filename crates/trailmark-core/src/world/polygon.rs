//! Obstacles: simple polygons, checked as they are made.

use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::Vector as PVector;
use serde::{Deserialize, Serialize};

use crate::geometry::Point;
use crate::predicates::{dedup_ring, on_segment, orient, winding_number};

use super::error::{PolygonError, in_range};

/// A simple polygon, its vertices counter-clockwise. Serialized as a list of `[x, y]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Vec<[f64; 2]>", into = "Vec<[f64; 2]>")]
pub struct Polygon {
    pub(super) vertices: Vec<Point>,
}

impl Polygon {
    /// A polygon from its vertices in either orientation (a clockwise list is reversed).
    /// A vertex equal to the one before it is dropped, and so is a closing repeat of the first.
    pub fn new(vertices: Vec<Point>) -> Result<Self, PolygonError> {
        if let Some(vertex) = vertices.iter().position(|p| !(p.x.is_finite() && p.y.is_finite())) {
            return Err(PolygonError::NonFinite { vertex });
        }
        if let Some(vertex) = vertices.iter().position(|p| !(in_range(p.x) && in_range(p.y))) {
            return Err(PolygonError::OutOfRange { vertex });
        }
        let mut kept = dedup_ring(vertices);
        if kept.len() < 3 {
            return Err(PolygonError::TooFewVertices { count: kept.len() });
        }
        let n = kept.len();
        if (0..n).all(|i| orient(kept[0], kept[1], kept[i]) == 0.0) {
            return Err(PolygonError::ZeroArea);
        }
        if let Some((first, second)) = self_intersection(&kept) {
            return Err(PolygonError::SelfIntersecting { first, second });
        }
        if signed_area(&kept) < 0.0 {
            kept.reverse();
        }
        Ok(Polygon { vertices: kept })
    }

    /// The vertices, counter-clockwise.
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// The area.
    pub fn area(&self) -> f64 {
        signed_area(&self.vertices)
    }

    /// Whether the polygon is convex.
    pub fn is_convex(&self) -> bool {
        let v = &self.vertices;
        let n = v.len();
        (0..n).all(|i| orient(v[i], v[(i + 1) % n], v[(i + 2) % n]) >= 0.0)
    }

    /// Whether `p` lies strictly inside. Exact.
    pub fn contains_strictly(&self, p: Point) -> bool {
        winding_number(p, self.edges()).is_some_and(|w| w != 0)
    }

    /// The distance from `p` to the closed region (0 inside or on the boundary), edge by edge:
    /// a plain O(n) reference with no bounding-volume hierarchy, for checking faster tests.
    pub fn distance_to(&self, p: Point) -> f64 {
        if self.contains_strictly(p) {
            return 0.0;
        }
        self.edges()
            .map(|(a, b)| {
                let ab = b - a;
                let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
                (p - (a + ab * t)).norm()
            })
            .fold(f64::INFINITY, f64::min)
    }

    pub(crate) fn edges(&self) -> impl Iterator<Item = (Point, Point)> + '_ {
        let n = self.vertices.len();
        (0..n).map(move |i| (self.vertices[i], self.vertices[(i + 1) % n]))
    }

    pub(super) fn aabb(&self, margin: f64) -> Aabb {
        let (mut lo, mut hi) = (self.vertices[0], self.vertices[0]);
        for p in &self.vertices {
            lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        Aabb::new(PVector::new(lo.x - margin, lo.y - margin), PVector::new(hi.x + margin, hi.y + margin))
    }
}

impl TryFrom<Vec<[f64; 2]>> for Polygon {
    type Error = PolygonError;

    fn try_from(points: Vec<[f64; 2]>) -> Result<Self, PolygonError> {
        Polygon::new(points.into_iter().map(|[x, y]| Point::new(x, y)).collect())
    }
}

impl From<Polygon> for Vec<[f64; 2]> {
    fn from(p: Polygon) -> Self {
        p.vertices.iter().map(|v| [v.x, v.y]).collect()
    }
}

pub(super) fn signed_area(v: &[Point]) -> f64 {
    // Relative to the first vertex: with coordinates near 1e9, the plain shoelace's products
    // (about 1e18) cancel away a small ring's area and can give it the wrong sign.
    let Some(&o) = v.first() else { return 0.0 };
    let n = v.len();
    0.5 * (1..n.saturating_sub(1)).map(|i| (v[i] - o).perp(&(v[i + 1] - o))).sum::<f64>()
}

/// A pair of edges that intersect other than at the shared vertex of consecutive edges (or
/// that fold back over each other there). Edges are swept by their least x, and a pair is
/// tested only when the two edges' boxes overlap: an outline of short edges (a contour traced
/// from a map) is checked in about `n log n` where every pair would take minutes. Edges that
/// all span the same x (a comb of long teeth) are still compared pair by pair, cheaply, by
/// their y ranges; a footprint is capped at
/// [`MAX_FOOTPRINT_VERTICES`](crate::footprint::MAX_FOOTPRINT_VERTICES) before this.
fn self_intersection(v: &[Point]) -> Option<(usize, usize)> {
    let n = v.len();
    let edge = |i: usize| (v[i], v[(i + 1) % n]);
    let span = |i: usize| {
        let (a, b) = edge(i);
        (a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y))
    };
    let spans: Vec<(f64, f64, f64, f64)> = (0..n).map(span).collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| spans[i].0.total_cmp(&spans[j].0));
    for (k, &first) in order.iter().enumerate() {
        let (_, right, low, high) = spans[first];
        for &other in &order[k + 1..] {
            let (left, _, other_low, other_high) = spans[other];
            if left > right {
                break; // this and every later edge start right of `first`
            }
            if other_low > high || other_high < low {
                continue;
            }
            let (i, j) = (first.min(other), first.max(other));
            if edges_meet(edge(i), edge(j), j == i + 1, i == 0 && j == n - 1) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Whether edges `i` and `j` (`i < j`) meet where a simple polygon's may not: anywhere, or for
/// consecutive edges (`next`: `j = i + 1`; `wrap`: the last and the first) along a line beyond
/// their shared vertex.
fn edges_meet((a, b): (Point, Point), (c, d): (Point, Point), next: bool, wrap: bool) -> bool {
    if next || wrap {
        // Consecutive edges share one vertex; they must not overlap along a line.
        let (shared, p, q) = if next { (b, a, d) } else { (a, b, c) };
        orient(shared, p, q) == 0.0 && (p - shared).dot(&(q - shared)) > 0.0
    } else {
        segments_touch(a, b, c, d)
    }
}

/// Whether closed segments `a-b` and `c-d` share a point. Exact.
pub(super) fn segments_touch(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2) = (orient(a, b, c), orient(a, b, d));
    let (d3, d4) = (orient(c, d, a), orient(c, d, b));
    (d1 * d2 < 0.0 && d3 * d4 < 0.0)
        || (d1 == 0.0 && on_segment(a, b, c))
        || (d2 == 0.0 && on_segment(a, b, d))
        || (d3 == 0.0 && on_segment(c, d, a))
        || (d4 == 0.0 && on_segment(c, d, b))
}
