//! Exact collision tests of points, segments, arcs and curves against a world's obstacles.

use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy};

use crate::curve::Bezier;
use crate::dubins::{DubinsPath, Piece};
use crate::geometry::Point;
use crate::predicates::{on_segment, orient, winding_number};
use crate::reeds_shepp::ReedsSheppPath;

use super::PolygonWorld;
use super::polygon::{Polygon, segments_touch};

/// Exact collision tests against a [`PolygonWorld`]: a configuration collides when the robot's
/// disc overlaps an obstacle's interior (touching is allowed) or its centre leaves the bounds.
#[derive(Clone, Debug)]
pub struct CollisionChecker {
    world: PolygonWorld,
    bvh: Bvh,
}

impl PolygonWorld {
    /// The exact collision checker of this world.
    pub fn checker(&self) -> CollisionChecker {
        CollisionChecker::new(self.clone())
    }
}

impl CollisionChecker {
    /// The checker of `world`, with a bounding-volume hierarchy over its grown obstacles.
    pub fn new(world: PolygonWorld) -> Self {
        let r = world.robot_radius;
        let leaves: Vec<Aabb> = world.obstacles.iter().map(|o| o.aabb(r)).collect();
        let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
        CollisionChecker { world, bvh }
    }

    /// The world checked.
    pub fn world(&self) -> &PolygonWorld {
        &self.world
    }

    /// Whether `test` holds for every obstacle whose grown box meets the box `min`-`max`
    /// (through the bounding-volume hierarchy, without allocating).
    fn all_near(&self, min: Point, max: Point, mut test: impl FnMut(&Polygon) -> bool) -> bool {
        let query = Aabb::new(PVector::new(min.x, min.y), PVector::new(max.x, max.y));
        self.bvh.intersect_aabb(&query).all(|i| test(&self.world.obstacles[i as usize]))
    }

    /// Whether the robot at `p` is collision-free.
    pub fn point_is_free(&self, p: Point) -> bool {
        if !(p.x.is_finite() && p.y.is_finite() && self.world.bounds.contains(p)) {
            return false;
        }
        let r = self.world.robot_radius;
        let around = Margin::new(p, p, r);
        self.all_near(p, p, |o| {
            !o.contains_strictly(p)
                && o.edges().all(|(a, b)| around.apart(a, b) || point_segment_distance(p, a, b) >= r)
        })
    }

    /// Whether the robot moving in a straight line from `a` to `b` stays collision-free: both
    /// ends in the bounds (which are convex), and for every obstacle near the segment, the start
    /// not strictly inside and, for a disc, every edge at least the radius from the segment
    /// (which covers the ends' own clearance); for a point robot, neither end inside and no
    /// stretch of the segment in the obstacle's interior. One pass through the hierarchy.
    pub fn segment_is_free(&self, a: Point, b: Point) -> bool {
        let finite = [a.x, a.y, b.x, b.y].iter().all(|v| v.is_finite());
        if !(finite && self.world.bounds.contains(a) && self.world.bounds.contains(b)) {
            return false;
        }
        let r = self.world.robot_radius;
        let min = Point::new(a.x.min(b.x), a.y.min(b.y));
        let max = Point::new(a.x.max(b.x), a.y.max(b.y));
        let around = Margin::new(min, max, r);
        self.all_near(min, max, |o| {
            if r > 0.0 {
                // With the start outside, the segment can only get in (and the end can only be
                // inside) through the boundary, which every edge's distance rules out.
                !o.contains_strictly(a)
                    && o.edges().all(|(p, q)| around.apart(p, q) || segment_distance(a, b, p, q) >= r)
            } else {
                !(o.contains_strictly(a) || o.contains_strictly(b) || segment_enters(o, a, b))
            }
        })
    }

    /// Whether a polygon robot whose outline has the corners `outline` (a simple polygon, in
    /// order, as [`Footprint::corners_at`](crate::footprint::Footprint::corners_at) places it)
    /// is collision-free, its outline grown by the world's robot radius: every edge free as
    /// [`segment_is_free`](Self::segment_is_free) tests it (its ends in the bounds, no obstacle
    /// crossed or nearer than the radius), no obstacle vertex strictly inside the outline (an
    /// obstacle wholly inside crosses no edge), and the outline's centroid, when inside it, not
    /// inside an obstacle (an outline lying exactly on an obstacle's boundary crosses nothing
    /// either). Touching is allowed, as for the disc. Exact; fewer than three corners are tested
    /// as their segment or point.
    pub fn polygon_is_free(&self, outline: &[Point]) -> bool {
        let n = outline.len();
        if n < 3 {
            return self.first_blocked_segment(outline).is_none() && n > 0;
        }
        if !(0..n).all(|k| self.segment_is_free(outline[k], outline[(k + 1) % n])) {
            return false;
        }
        let edges = || (0..n).map(|k| (outline[k], outline[(k + 1) % n]));
        let inside = |p: Point| winding_number(p, edges()).is_some_and(|w| w != 0);
        let (mut min, mut max) = (outline[0], outline[0]);
        for p in outline {
            min = Point::new(min.x.min(p.x), min.y.min(p.y));
            max = Point::new(max.x.max(p.x), max.y.max(p.y));
        }
        let centroid =
            Point::from(outline.iter().map(|p| p.coords).sum::<nalgebra::Vector2<f64>>() / n as f64);
        (!inside(centroid) || self.point_is_free(centroid))
            && self.all_near(min, max, |o| o.vertices().iter().all(|&v| !inside(v)))
    }

    /// Whether the robot moving along the circular arc with `center`, `radius`, starting at
    /// angle `start_angle` and turning by `sweep` radians (counter-clockwise when positive)
    /// stays collision-free.
    pub fn arc_is_free(&self, center: Point, radius: f64, start_angle: f64, sweep: f64) -> bool {
        let arc = Arc { center, radius, start: start_angle, sweep };
        let (a, b) = (arc.point(start_angle), arc.point(start_angle + sweep));
        if !(self.point_is_free(a) && self.point_is_free(b)) {
            return false;
        }
        // The arc must stay in the (convex) bounds: check its extreme points.
        let bounds = self.world.bounds;
        for k in 0..4 {
            let t = f64::from(k) * std::f64::consts::FRAC_PI_2;
            if arc.holds_angle(t) && !bounds.contains(arc.point(t)) {
                return false;
            }
        }
        let r = self.world.robot_radius;
        let reach = radius + r;
        let (min, max) =
            (center - nalgebra::Vector2::new(reach, reach), center + nalgebra::Vector2::new(reach, reach));
        self.all_near(min, max, |o| {
            o.edges().all(|(p, q)| arc.distance_to_segment(p, q) >= r.max(f64::MIN_POSITIVE))
        })
    }

    /// The first segment of the polyline `points` that the robot cannot follow (segment `i`
    /// joins points `i` and `i + 1`), or `None` when every segment is collision-free; a single
    /// point is tested as a point (segment 0). Exact: the re-check a roadmap's answer passes
    /// before it is reported as a path.
    pub fn first_blocked_segment(&self, points: &[Point]) -> Option<usize> {
        if let [p] = points {
            return (!self.point_is_free(*p)).then_some(0);
        }
        points.windows(2).position(|pair| !self.segment_is_free(pair[0], pair[1]))
    }

    /// Whether the robot following a Dubins path stays collision-free (every arc and segment
    /// tested exactly).
    pub fn dubins_is_free(&self, path: &DubinsPath) -> bool {
        self.pieces_are_free(&path.pieces())
    }

    /// Whether the robot following a Reeds-Shepp path, forward and in reverse, stays
    /// collision-free (every arc and segment tested exactly).
    pub fn reeds_shepp_is_free(&self, path: &ReedsSheppPath) -> bool {
        self.pieces_are_free(&path.pieces())
    }

    /// Whether the robot along each arc and segment stays collision-free.
    pub fn pieces_are_free(&self, pieces: &[Piece]) -> bool {
        pieces.iter().all(|piece| match *piece {
            Piece::Segment { from, to } => self.segment_is_free(from, to),
            Piece::Arc { center, radius, start_angle, sweep } => {
                self.arc_is_free(center, radius, start_angle, sweep)
            }
        })
    }

    /// Whether the robot following the Bézier curve stays collision-free. Conservative and
    /// exact in what it accepts: a curve is accepted only when the convex hulls of its control
    /// points (split in halves up to 12 times where needed) are proven free, so a curve grazing
    /// an obstacle at exactly the robot's radius may be refused, and a refused curve may still
    /// be free. A straight segment (degree 1) is tested exactly.
    pub fn bezier_is_free(&self, curve: &Bezier) -> bool {
        self.bezier_is_free_within(curve, 12)
    }

    fn bezier_is_free_within(&self, curve: &Bezier, depth: u32) -> bool {
        let points = curve.control_points();
        if let [a, b] = points {
            return self.segment_is_free(*a, *b);
        }
        if !self.point_is_free(curve.point(0.5)) {
            return false;
        }
        if self.hull_is_free(points) {
            return true;
        }
        if depth == 0 {
            return false;
        }
        let (before, after) = curve.split(0.5);
        self.bezier_is_free_within(&before, depth - 1) && self.bezier_is_free_within(&after, depth - 1)
    }

    /// Whether the robot anywhere in the convex hull of `points` is collision-free: every
    /// segment between two of the points is free (the hull's edges among them), and no nearby
    /// obstacle has a vertex in the hull (an obstacle inside the hull whose boundary no edge
    /// crosses).
    fn hull_is_free(&self, points: &[Point]) -> bool {
        let pairs = (0..points.len()).flat_map(|i| (i + 1..points.len()).map(move |j| (i, j)));
        for (i, j) in pairs {
            if !self.segment_is_free(points[i], points[j]) {
                return false;
            }
        }
        let min = points.iter().fold(points[0], |m, p| Point::new(m.x.min(p.x), m.y.min(p.y)));
        let max = points.iter().fold(points[0], |m, p| Point::new(m.x.max(p.x), m.y.max(p.y)));
        let n = points.len();
        let triangles = (0..n).flat_map(|i| (i + 1..n).flat_map(move |j| (j + 1..n).map(move |k| (i, j, k))));
        let triangles: Vec<_> = triangles.collect();
        self.all_near(min, max, |o| {
            o.vertices().iter().all(|&v| {
                !triangles.iter().any(|&(i, j, k)| in_closed_triangle(points[i], points[j], points[k], v))
            })
        })
    }
}

/// Whether `p` lies in the closed triangle `a b c` (a segment or a point when degenerate), by
/// exact orientation tests.
fn in_closed_triangle(a: Point, b: Point, c: Point, p: Point) -> bool {
    let turn = orient(a, b, c);
    if turn == 0.0 {
        return on_segment(a, b, p) || on_segment(b, c, p) || on_segment(a, c, p);
    }
    let sides = [orient(a, b, p), orient(b, c, p), orient(c, a, p)];
    sides.iter().all(|&s| s * turn >= 0.0)
}

/// The box `min`-`max` widened by a radius and a rounding allowance: edges wholly outside it
/// are farther than the radius from everything in the box. A few comparisons that spare most
/// exact distances, and never spare a close one.
struct Margin {
    min: Point,
    max: Point,
    reach: f64,
}

impl Margin {
    fn new(min: Point, max: Point, r: f64) -> Self {
        let scale = min.x.abs().max(min.y.abs()).max(max.x.abs()).max(max.y.abs());
        Margin { min, max, reach: r + 1e-9 * (r + scale) }
    }

    /// Whether the segment `p-q` lies wholly beyond one side of the box by more than the reach.
    #[inline]
    fn apart(&self, p: Point, q: Point) -> bool {
        let (min, max, reach) = (self.min, self.max, self.reach);
        min.x - p.x.max(q.x) > reach
            || p.x.min(q.x) - max.x > reach
            || min.y - p.y.max(q.y) > reach
            || p.y.min(q.y) - max.y > reach
    }
}

/// The distance from `p` to the closed segment `a-b`. Written out rather than parry's, whose
/// tolerances are absolute and give wrong distances in worlds measured in micrometres.
pub(crate) fn point_segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let t = if len2 > 0.0 { ((p - a).dot(&ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + ab * t)).norm()
}

/// The distance between closed segments `a-b` and `p-q`: 0 when they touch (exact), else the
/// least of the four end-to-segment distances (the closest points of disjoint segments include
/// an end of one of them).
fn segment_distance(a: Point, b: Point, p: Point, q: Point) -> f64 {
    if segments_touch(a, b, p, q) {
        return 0.0;
    }
    point_segment_distance(a, p, q)
        .min(point_segment_distance(b, p, q))
        .min(point_segment_distance(p, a, b))
        .min(point_segment_distance(q, a, b))
}

/// For a point robot: whether the open segment `a-b` meets the polygon's open interior. The
/// segment is cut where it meets the boundary, and each piece's midpoint is tested.
fn segment_enters(o: &Polygon, a: Point, b: Point) -> bool {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let mut cuts = vec![0.0, 1.0];
    // Stretches of the segment that run along an edge: on the boundary, not inside.
    let mut along: Vec<(f64, f64)> = Vec::new();
    for (p, q) in o.edges() {
        if !segments_touch(a, b, p, q) {
            continue;
        }
        let denom = ab.perp(&(q - p));
        if orient(p, q, a) == 0.0 && orient(p, q, b) == 0.0 {
            let (s, t) = ((p - a).dot(&ab) / len2, (q - a).dot(&ab) / len2);
            let (lo, hi) = (s.min(t).clamp(0.0, 1.0), s.max(t).clamp(0.0, 1.0));
            cuts.extend([lo, hi]);
            along.push((lo, hi));
        } else if orient(p, q, a) == 0.0 {
            cuts.push(0.0); // touching at the segment's ends: exactly there, not nearly
        } else if orient(p, q, b) == 0.0 {
            cuts.push(1.0);
        } else if orient(a, b, p) == 0.0 {
            cuts.push(((p - a).dot(&ab) / len2).clamp(0.0, 1.0));
        } else if orient(a, b, q) == 0.0 {
            cuts.push(((q - a).dot(&ab) / len2).clamp(0.0, 1.0));
        } else if denom != 0.0 {
            cuts.push(((p - a).perp(&(q - p)) / denom).clamp(0.0, 1.0));
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.windows(2).any(|w| {
        let mid = 0.5 * (w[0] + w[1]);
        w[1] > w[0]
            && !along.iter().any(|&(lo, hi)| lo <= mid && mid <= hi)
            && o.contains_strictly(a + ab * mid)
    })
}

/// A circular arc.
#[derive(Debug)]
pub(super) struct Arc {
    pub(super) center: Point,
    pub(super) radius: f64,
    pub(super) start: f64,
    pub(super) sweep: f64,
}

impl Arc {
    pub(super) fn point(&self, t: f64) -> Point {
        self.center + self.radius * nalgebra::Vector2::new(t.cos(), t.sin())
    }

    /// Whether the arc passes through angle `t`.
    fn holds_angle(&self, t: f64) -> bool {
        let tau = std::f64::consts::TAU;
        if self.sweep.abs() >= tau {
            return true;
        }
        let offset = if self.sweep >= 0.0 { t - self.start } else { self.start - t };
        offset.rem_euclid(tau) <= self.sweep.abs()
    }

    fn distance_to_point(&self, p: Point) -> f64 {
        let d = p - self.center;
        let ends = (self.point(self.start) - p).norm().min((self.point(self.start + self.sweep) - p).norm());
        if d.norm() > 0.0 && self.holds_angle(d.y.atan2(d.x)) {
            (d.norm() - self.radius).abs().min(ends)
        } else {
            ends
        }
    }

    /// The distance between the arc and segment `p-q`: the least over the pairs where the
    /// closest points can be (an end of one, or the normal through the centre), zero where the
    /// segment crosses the arc.
    pub(super) fn distance_to_segment(&self, p: Point, q: Point) -> f64 {
        let (a, b) = (self.point(self.start), self.point(self.start + self.sweep));
        let mut best = point_segment_distance(a, p, q)
            .min(point_segment_distance(b, p, q))
            .min(self.distance_to_point(p))
            .min(self.distance_to_point(q));
        // The point of the segment nearest the centre, and the circle's crossings of the segment.
        let pq = q - p;
        let len2 = pq.norm_squared();
        if len2 > 0.0 {
            // The foot on the line (for the crossings) and on the segment (for the distance).
            let t = (self.center - p).dot(&pq) / len2;
            best = best.min(self.distance_to_point(p + pq * t.clamp(0.0, 1.0)));
            let h = (p + pq * t - self.center).norm();
            if h <= self.radius {
                let half = (self.radius * self.radius - h * h).max(0.0).sqrt() / len2.sqrt();
                for s in [t - half, t + half] {
                    if (0.0..=1.0).contains(&s) {
                        let x = p + pq * s;
                        let d = x - self.center;
                        if self.holds_angle(d.y.atan2(d.x)) {
                            return 0.0;
                        }
                    }
                }
            }
        }
        best
    }
}
