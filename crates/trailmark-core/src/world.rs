//! Polygon worlds: bounds, polygonal obstacles and a disc-shaped robot.
//!
//! A [`PolygonWorld`] is what a roadmap builder or a sampling planner plans in: a rectangle of
//! bounds that the robot's centre stays in, simple polygons as obstacles (convex or not), and
//! the robot's radius. Two views of it answer the two kinds of question:
//!
//! - [`PolygonWorld::checker`] gives a [`CollisionChecker`]: exact tests of points, segments,
//!   circular arcs and Dubins paths against the obstacles grown by the robot radius (the
//!   Minkowski sum with a disc, with its round corners), through a bounding-volume hierarchy
//!   (parry2d's BVH) so a query only looks at the obstacles near it;
//! - [`PolygonWorld::free_space`] gives a [`FreeSpace`]: the same grown obstacles as polygons
//!   (round corners replaced by short edges *outside* the exact disc, so nothing the polygons
//!   allow collides), overlapping ones merged, cut out of the bounds. Builders that need
//!   vertices (the visibility graph) work on it.
//!
//! Obstacles are validated where they enter: fewer than three distinct vertices, zero area,
//! self-intersection and non-finite coordinates are typed errors ([`PolygonError`]).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//!
//! let square = vec![Point::new(4.0, 4.0), Point::new(6.0, 4.0), Point::new(6.0, 6.0), Point::new(4.0, 6.0)];
//! let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?, vec![square], 0.5)?;
//! let checker = world.checker();
//! assert!(!checker.point_is_free(Point::new(3.7, 5.0))); // within 0.5 of the square
//! assert!(checker.point_is_free(Point::new(3.4, 5.0)));
//! assert!(checker.segment_is_free(Point::new(1.0, 3.4), Point::new(9.0, 3.4)));
//! assert!(!checker.segment_is_free(Point::new(1.0, 5.0), Point::new(9.0, 5.0)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use geo::algorithm::buffer::{Buffer, BufferStyle, LineJoin};
use geo::{BooleanOps, Coord, LineString, MultiPolygon, unary_union};
use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::math::Vector as PVector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::curve::Bezier;
use crate::dubins::{DubinsPath, Piece};
use crate::freespace::{FreeSpace, dedup_ring, on_segment, orient, winding_number};
use crate::geometry::Point;

/// Why a polygon is not a valid obstacle.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum PolygonError {
    /// A vertex has a NaN or infinite coordinate.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinite {
        /// Index of the vertex.
        vertex: usize,
    },
    /// A vertex has a coordinate larger in magnitude than [`MAX_COORDINATE`].
    #[error("vertex {vertex} has a coordinate beyond +-{max:e}, the largest a world supports", max = MAX_COORDINATE)]
    OutOfRange {
        /// Index of the vertex.
        vertex: usize,
    },
    /// Fewer than three distinct vertices (after dropping repeats of the previous vertex).
    #[error("a polygon needs at least three distinct vertices, this one has {count}")]
    TooFewVertices {
        /// The number of distinct vertices.
        count: usize,
    },
    /// All vertices on one line.
    #[error("the polygon has zero area")]
    ZeroArea,
    /// Two edges cross or touch (other than consecutive edges at their shared vertex).
    #[error("edges {first} and {second} intersect: the polygon is not simple")]
    SelfIntersecting {
        /// Index of the first edge (edge i joins vertex i to vertex i + 1).
        first: usize,
        /// Index of the second edge.
        second: usize,
    },
}

/// Why a world is not valid.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum WorldError {
    /// The bounds are not a finite rectangle of positive area.
    #[error(
        "bounds [{xmin:?}, {ymin:?}, {xmax:?}, {ymax:?}] must be finite with xmin < xmax and ymin < ymax"
    )]
    InvalidBounds {
        /// Left.
        xmin: f64,
        /// Bottom.
        ymin: f64,
        /// Right.
        xmax: f64,
        /// Top.
        ymax: f64,
    },
    /// The bounds have a coordinate beyond [`MAX_COORDINATE`] in magnitude, or a side shorter
    /// than [`MIN_RELATIVE_SIDE`] times their largest coordinate (or than [`MIN_SIDE`]): the
    /// polygon operations could not resolve such a world.
    #[error(
        "bounds [{xmin:?}, {ymin:?}, {xmax:?}, {ymax:?}] are outside the supported range: coordinates within +-{max:e}, each side at least {side:e} and at least {rel:e} times the largest coordinate",
        max = MAX_COORDINATE, side = MIN_SIDE, rel = MIN_RELATIVE_SIDE
    )]
    BoundsOutOfRange {
        /// Left.
        xmin: f64,
        /// Bottom.
        ymin: f64,
        /// Right.
        xmax: f64,
        /// Top.
        ymax: f64,
    },
    /// The robot radius is negative or not finite.
    #[error("robot radius {0:?} must be finite and non-negative")]
    InvalidRadius(f64),
    /// The robot radius is larger than [`MAX_COORDINATE`].
    #[error("robot radius {0:e} is beyond {max:e}, the largest a world supports", max = MAX_COORDINATE)]
    RadiusOutOfRange(f64),
    /// The angle step for round corners is outside `(0, PI/2]`.
    #[error("arc step {0} must lie in (0, PI/2]")]
    InvalidArcStep(f64),
    /// An obstacle is not a valid polygon.
    #[error("obstacle {index}: {error}")]
    Obstacle {
        /// Index of the obstacle.
        index: usize,
        /// What is wrong with it.
        error: PolygonError,
    },
}

/// The largest coordinate magnitude (of bounds, obstacle vertices and the robot radius) a
/// world accepts. Exact predicates hold at any magnitude, but the polygon operations that grow
/// and merge obstacles round to a fixed-point grid and lose obstacles beyond about 1e12; 1e9
/// (a million kilometres in metres, a thousand in millimetres) keeps a wide margin.
pub const MAX_COORDINATE: f64 = 1e9;

/// The shortest side the bounds may have, in absolute terms.
pub const MIN_SIDE: f64 = 1e-6;

/// The shortest side the bounds may have relative to their largest coordinate magnitude: the
/// free space is resolved to 2^-20 of the bounds' larger side, which must stay far above the
/// spacing of `f64` values at the bounds' coordinates (about 2.2e-16 times their magnitude).
pub const MIN_RELATIVE_SIDE: f64 = 1e-7;

/// Whether `v` is within the magnitude a world supports.
fn in_range(v: f64) -> bool {
    v.abs() <= MAX_COORDINATE
}

/// An axis-aligned rectangle: the region the robot's centre must stay in. Serialized as
/// `[xmin, ymin, xmax, ymax]`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "[f64; 4]", into = "[f64; 4]")]
pub struct Bounds {
    min: Point,
    max: Point,
}

impl Bounds {
    /// The rectangle `[xmin, xmax] x [ymin, ymax]`; an error unless finite with positive area,
    /// and within the supported range: every coordinate within [`MAX_COORDINATE`], each side
    /// at least [`MIN_SIDE`] and at least [`MIN_RELATIVE_SIDE`] times the largest coordinate.
    pub fn new(xmin: f64, ymin: f64, xmax: f64, ymax: f64) -> Result<Self, WorldError> {
        let corners = [xmin, ymin, xmax, ymax];
        let finite = corners.iter().all(|v| v.is_finite());
        if !(finite && xmin < xmax && ymin < ymax) {
            return Err(WorldError::InvalidBounds { xmin, ymin, xmax, ymax });
        }
        let largest = corners.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let side = (xmax - xmin).min(ymax - ymin);
        if !(largest <= MAX_COORDINATE && side >= MIN_SIDE && side >= MIN_RELATIVE_SIDE * largest) {
            return Err(WorldError::BoundsOutOfRange { xmin, ymin, xmax, ymax });
        }
        Ok(Bounds { min: Point::new(xmin, ymin), max: Point::new(xmax, ymax) })
    }

    /// The lower-left corner.
    pub fn min(&self) -> Point {
        self.min
    }

    /// The upper-right corner.
    pub fn max(&self) -> Point {
        self.max
    }

    /// Whether `p` lies in the closed rectangle.
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }

    /// The four corners, counter-clockwise from the lower left.
    pub fn corners(&self) -> [Point; 4] {
        let (a, b) = (self.min, self.max);
        [a, Point::new(b.x, a.y), b, Point::new(a.x, b.y)]
    }
}

impl TryFrom<[f64; 4]> for Bounds {
    type Error = WorldError;

    fn try_from([xmin, ymin, xmax, ymax]: [f64; 4]) -> Result<Self, WorldError> {
        Bounds::new(xmin, ymin, xmax, ymax)
    }
}

impl From<Bounds> for [f64; 4] {
    fn from(b: Bounds) -> Self {
        [b.min.x, b.min.y, b.max.x, b.max.y]
    }
}

/// A simple polygon, its vertices counter-clockwise. Serialized as a list of `[x, y]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Vec<[f64; 2]>", into = "Vec<[f64; 2]>")]
pub struct Polygon {
    vertices: Vec<Point>,
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

    fn edges(&self) -> impl Iterator<Item = (Point, Point)> + '_ {
        let n = self.vertices.len();
        (0..n).map(move |i| (self.vertices[i], self.vertices[(i + 1) % n]))
    }

    fn aabb(&self, margin: f64) -> Aabb {
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

fn signed_area(v: &[Point]) -> f64 {
    // Relative to the first vertex: with coordinates near 1e9, the plain shoelace's products
    // (about 1e18) cancel away a small ring's area and can give it the wrong sign.
    let Some(&o) = v.first() else { return 0.0 };
    let n = v.len();
    0.5 * (1..n.saturating_sub(1)).map(|i| (v[i] - o).perp(&(v[i + 1] - o))).sum::<f64>()
}

/// The first pair of edges that intersect other than at the shared vertex of consecutive edges
/// (or that fold back over each other there). Quadratic: obstacles are validated once.
fn self_intersection(v: &[Point]) -> Option<(usize, usize)> {
    let n = v.len();
    let edge = |i: usize| (v[i], v[(i + 1) % n]);
    for i in 0..n {
        for j in i + 1..n {
            let ((a, b), (c, d)) = (edge(i), edge(j));
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if adjacent {
                // Consecutive edges share one vertex; they must not overlap along a line.
                let (shared, p, q) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                if orient(shared, p, q) == 0.0 && (p - shared).dot(&(q - shared)) > 0.0 {
                    return Some((i, j));
                }
            } else if segments_touch(a, b, c, d) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Whether closed segments `a-b` and `c-d` share a point. Exact.
fn segments_touch(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2) = (orient(a, b, c), orient(a, b, d));
    let (d3, d4) = (orient(c, d, a), orient(c, d, b));
    (d1 * d2 < 0.0 && d3 * d4 < 0.0)
        || (d1 == 0.0 && on_segment(a, b, c))
        || (d2 == 0.0 && on_segment(a, b, d))
        || (d3 == 0.0 && on_segment(c, d, a))
        || (d4 == 0.0 && on_segment(c, d, b))
}

/// A world of polygonal obstacles for a disc robot. Serialized as
/// `{"bounds": [xmin, ymin, xmax, ymax], "obstacles": [[[x, y], ...], ...], "robot_radius": r}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "WorldDocument", into = "WorldDocument")]
pub struct PolygonWorld {
    bounds: Bounds,
    obstacles: Vec<Polygon>,
    robot_radius: f64,
}

/// The serialized form of a [`PolygonWorld`], checked on the way in.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct WorldDocument {
    bounds: Bounds,
    #[serde(default)]
    obstacles: Vec<Vec<[f64; 2]>>,
    #[serde(default)]
    robot_radius: f64,
}

impl TryFrom<WorldDocument> for PolygonWorld {
    type Error = WorldError;

    fn try_from(doc: WorldDocument) -> Result<Self, WorldError> {
        let obstacles = doc
            .obstacles
            .into_iter()
            .map(|o| o.into_iter().map(|[x, y]| Point::new(x, y)).collect())
            .collect();
        PolygonWorld::new(doc.bounds, obstacles, doc.robot_radius)
    }
}

impl From<PolygonWorld> for WorldDocument {
    fn from(w: PolygonWorld) -> Self {
        WorldDocument {
            bounds: w.bounds,
            obstacles: w.obstacles.into_iter().map(Vec::from).collect(),
            robot_radius: w.robot_radius,
        }
    }
}

/// The largest angle one straight edge of a grown obstacle's round corner may span, in
/// radians, unless [`PolygonWorld::free_space_with_step`] is given another.
pub const DEFAULT_ARC_STEP: f64 = std::f64::consts::PI / 8.0;

impl PolygonWorld {
    /// A world with the given bounds, obstacles (each a vertex list, checked by
    /// [`Polygon::new`]) and robot radius.
    pub fn new(bounds: Bounds, obstacles: Vec<Vec<Point>>, robot_radius: f64) -> Result<Self, WorldError> {
        if !(robot_radius.is_finite() && robot_radius >= 0.0) {
            return Err(WorldError::InvalidRadius(robot_radius));
        }
        if !in_range(robot_radius) {
            return Err(WorldError::RadiusOutOfRange(robot_radius));
        }
        let obstacles = obstacles
            .into_iter()
            .enumerate()
            .map(|(index, v)| Polygon::new(v).map_err(|error| WorldError::Obstacle { index, error }))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(PolygonWorld { bounds, obstacles, robot_radius })
    }

    /// This world with one more obstacle (checked by [`Polygon::new`]; its index in the error
    /// is the index it would have had).
    pub fn with_obstacle(&self, vertices: Vec<Point>) -> Result<Self, WorldError> {
        let index = self.obstacles.len();
        let polygon = Polygon::new(vertices).map_err(|error| WorldError::Obstacle { index, error })?;
        let mut world = self.clone();
        world.obstacles.push(polygon);
        Ok(world)
    }

    /// This world without obstacle `index` (the later ones move down by one), and the obstacle
    /// removed; `None` if there is no such obstacle.
    pub fn without_obstacle(&self, index: usize) -> Option<(Self, Polygon)> {
        (index < self.obstacles.len()).then(|| {
            let mut world = self.clone();
            let removed = world.obstacles.remove(index);
            (world, removed)
        })
    }

    /// The world of `obstacle` alone, with these bounds and radius: its checker tells which
    /// motions that obstacle blocks.
    pub fn only(&self, obstacle: Polygon) -> Self {
        PolygonWorld { bounds: self.bounds, obstacles: vec![obstacle], robot_radius: self.robot_radius }
    }

    /// The bounds of the robot's centre.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }

    /// The obstacles, as given (not grown).
    pub fn obstacles(&self) -> &[Polygon] {
        &self.obstacles
    }

    /// The robot's radius.
    pub fn robot_radius(&self) -> f64 {
        self.robot_radius
    }

    /// Whether the robot at `p` is clear of every obstacle by the plain O(n) distances of
    /// [`Polygon::distance_to`] (no hierarchy, no exact predicates), within `tolerance` of the
    /// radius, and its centre is in the bounds: a reference for checking the exact tests.
    pub fn reference_is_clear(&self, p: Point, tolerance: f64) -> bool {
        let r = self.robot_radius - tolerance;
        self.bounds.contains(p)
            && self.obstacles.iter().all(|o| !o.contains_strictly(p) && o.distance_to(p) >= r)
    }

    /// The resolution of [`free_space`](Self::free_space): the margin its grown obstacles
    /// carry for the rounding of polygon operations, 2^-20 of the bounds' larger side. A point
    /// the exact [`checker`](Self::checker) finds free may be blocked in the free space when it
    /// is closer than this to a grown obstacle.
    pub fn resolution(&self) -> f64 {
        let size = self.bounds.max - self.bounds.min;
        size.x.max(size.y) * (-20f64).exp2()
    }

    /// The radius to grow `obstacle` by for the free space: the robot radius, but no more than
    /// twice the diagonal of the box around the bounds and the obstacle. Beyond that distance
    /// the grown obstacle covers the bounds whatever the radius, and the polygon operations
    /// lose an obstacle grown far beyond its own size.
    fn growth_radius(&self, obstacle: &Polygon) -> f64 {
        let mut lo = self.bounds.min;
        let mut hi = self.bounds.max;
        for v in &obstacle.vertices {
            lo = Point::new(lo.x.min(v.x), lo.y.min(v.y));
            hi = Point::new(hi.x.max(v.x), hi.y.max(v.y));
        }
        self.robot_radius.min(2.0 * (hi - lo).norm())
    }

    /// The exact collision checker of this world.
    pub fn checker(&self) -> CollisionChecker {
        CollisionChecker::new(self.clone())
    }

    /// The free space for the robot's centre as polygons, with [`DEFAULT_ARC_STEP`].
    pub fn free_space(&self) -> FreeSpace {
        self.free_space_with_step(DEFAULT_ARC_STEP).expect("the default step is valid")
    }

    /// The free space for the robot's centre as polygons: each obstacle grown by the robot
    /// radius, its round corners replaced by edges spanning at most `arc_step` radians that lie
    /// outside the exact disc (so the polygons are conservative), overlapping obstacles merged,
    /// and the union cut out of the bounds. A smaller step is closer to the exact shape and has
    /// more vertices; it must lie in `(0, PI/2]`.
    pub fn free_space_with_step(&self, arc_step: f64) -> Result<FreeSpace, WorldError> {
        if !(arc_step > 0.0 && arc_step <= std::f64::consts::FRAC_PI_2) {
            return Err(WorldError::InvalidArcStep(arc_step));
        }
        let step = arc_step;
        let to_geo = |p: &Polygon| {
            let mut ring: Vec<Coord<f64>> = p.vertices.iter().map(|v| Coord { x: v.x, y: v.y }).collect();
            ring.push(ring[0]);
            geo::Polygon::new(LineString::new(ring), vec![])
        };
        let grown: Vec<MultiPolygon<f64>> = self
            .obstacles
            .iter()
            .map(|p| {
                let polygon = to_geo(p);
                let margin = self.resolution();
                if self.robot_radius > 0.0 {
                    // Vertices on a circle of radius r / cos(step / 2): chords spanning at most
                    // `step` then stay outside the disc of radius r. The join's parameter is the
                    // chord length over the radius; it asks for chords of half the step, since
                    // the corner's arc is split into a power of two of pieces, each up to twice
                    // the requested angle. The polygon operations snap coordinates to a
                    // fixed-point grid (about 1e-9 of the extent): a margin covers that.
                    let distance = self.growth_radius(p) / (step / 2.0).cos() + margin;
                    let join = LineJoin::Round(2.0 * (step / 4.0).sin());
                    polygon.buffer_with_style(BufferStyle::new(distance).line_join(join))
                } else {
                    MultiPolygon::new(vec![polygon])
                }
            })
            .collect();
        let union = unary_union(grown.iter());
        let bounds_polygon = to_geo(&Polygon { vertices: self.bounds.corners().to_vec() });
        let free = bounds_polygon.difference(&union);
        // For a point robot, the union's vertices are the obstacles' own vertices (snapped to the
        // fixed-point grid of the polygon operations) and crossings of their edges: put the
        // former back exactly, so a path may touch an obstacle's corner without entering it.
        let tolerance = self.resolution();
        let originals: std::collections::HashMap<(i64, i64), Vec<Point>> = if self.robot_radius == 0.0 {
            let mut map: std::collections::HashMap<(i64, i64), Vec<Point>> = std::collections::HashMap::new();
            for v in self.obstacles.iter().flat_map(|o| o.vertices.iter()).chain(self.bounds.corners().iter())
            {
                map.entry(((v.x / tolerance).floor() as i64, (v.y / tolerance).floor() as i64))
                    .or_default()
                    .push(*v);
            }
            map
        } else {
            Default::default()
        };
        let restore = |p: Point| {
            let (cx, cy) = ((p.x / tolerance).floor() as i64, (p.y / tolerance).floor() as i64);
            (cx - 1..=cx + 1)
                .flat_map(|x| (cy - 1..=cy + 1).map(move |y| (x, y)))
                .filter_map(|k| originals.get(&k))
                .flatten()
                .copied()
                .filter(|v| (v - p).norm() <= tolerance)
                // The nearest: two vertices closer than the tolerance must not swap.
                .min_by(|a, b| (a - p).norm().total_cmp(&(b - p).norm()))
                .unwrap_or(p)
        };
        // Where an obstacle crosses the bounds, the union puts the crossing a rounding away
        // from the side, inside or out, and a vertex restored exactly on the side (an obstacle
        // touching it) can then lie outside the free space's outer ring: put points within a
        // rounding of a side (1/64 of the resolution, which the grown obstacles' margin covers)
        // on the side, exactly, and those outside onto it.
        let (lo, hi) = (self.bounds.min, self.bounds.max);
        let rounding = tolerance / 64.0;
        let onto_side = |v: f64, min: f64, max: f64| {
            if v - min <= rounding {
                min
            } else if max - v <= rounding {
                max
            } else {
                v
            }
        };
        let restore = |p: Point| {
            let p = restore(p);
            Point::new(onto_side(p.x, lo.x, hi.x), onto_side(p.y, lo.y, hi.y))
        };
        let mut rings = Vec::new();
        for polygon in free.iter() {
            let ring = |l: &LineString<f64>, outer: bool| {
                let mut v: Vec<Point> = l.coords().map(|c| restore(Point::new(c.x, c.y))).collect();
                if v.len() > 1 && v.first() == v.last() {
                    v.pop();
                }
                // Free space on the left: the outer ring counter-clockwise, holes clockwise.
                if (signed_area(&v) > 0.0) != outer {
                    v.reverse();
                }
                v
            };
            rings.push(ring(polygon.exterior(), true));
            rings.extend(polygon.interiors().iter().map(|l| ring(l, false)));
        }
        Ok(FreeSpace::from_rings_dropping_degenerate(rings))
    }
}

/// Exact collision tests against a [`PolygonWorld`]: a configuration collides when the robot's
/// disc overlaps an obstacle's interior (touching is allowed) or its centre leaves the bounds.
#[derive(Clone, Debug)]
pub struct CollisionChecker {
    world: PolygonWorld,
    bvh: Bvh,
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
        path.pieces().iter().all(|piece| match *piece {
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
fn point_segment_distance(p: Point, a: Point, b: Point) -> f64 {
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
struct Arc {
    center: Point,
    radius: f64,
    start: f64,
    sweep: f64,
}

impl Arc {
    fn point(&self, t: f64) -> Point {
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
    fn distance_to_segment(&self, p: Point, q: Point) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn square(x: f64, y: f64, s: f64) -> Vec<Point> {
        vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]
    }

    /// Far from the origin, a small ring's area is the same as at the origin (the shoelace on
    /// raw coordinates cancelled it away and could flip its sign).
    #[test]
    fn areas_do_not_depend_on_where_the_ring_is() {
        for (x, y) in [(0.0, 0.0), (990000098.9042064, 990000098.9042064), (-1e9, 1e9)] {
            let ring =
                [p(x + 1.0958, y), p(x + 0.6019, y + 0.6019), p(x, y + 1.0958), p(x + 1.0958, y + 1.0958)];
            let area = signed_area(&ring);
            let reference = signed_area(&ring.map(|q| p(q.x - x, q.y - y)));
            // Clockwise: the pocket the trapezoid sweep met near 1e9.
            assert!(reference < -0.5, "{reference}");
            assert!((area - reference).abs() <= 1e-6, "at ({x}, {y}): {area} vs {reference}");
        }
    }

    #[test]
    fn bad_polygons_are_typed_errors() {
        assert_eq!(
            Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0)]),
            Err(PolygonError::TooFewVertices { count: 2 })
        );
        assert_eq!(
            Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 0.0), p(0.0, 0.0)]),
            Err(PolygonError::TooFewVertices { count: 2 })
        );
        assert_eq!(Polygon::new(vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0)]), Err(PolygonError::ZeroArea));
        assert_eq!(
            Polygon::new(vec![p(0.0, 0.0), p(f64::NAN, 1.0), p(2.0, 2.0)]),
            Err(PolygonError::NonFinite { vertex: 1 })
        );
        // A bow tie.
        let bow = vec![p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)];
        assert!(matches!(Polygon::new(bow), Err(PolygonError::SelfIntersecting { .. })));
        // A spike folding back on itself.
        let spike = vec![p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)];
        assert!(matches!(Polygon::new(spike), Err(PolygonError::SelfIntersecting { .. })));
        // A vertex touching another edge.
        let touch = vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(2.0, 0.0), p(0.0, 4.0)];
        assert!(matches!(Polygon::new(touch), Err(PolygonError::SelfIntersecting { .. })));
    }

    #[test]
    fn clockwise_input_is_reversed() {
        let mut v = square(0.0, 0.0, 1.0);
        v.reverse();
        let poly = Polygon::new(v).unwrap();
        assert!(poly.area() > 0.0);
        assert!(poly.is_convex());
    }

    #[test]
    fn bad_worlds_are_typed_errors() {
        assert!(matches!(Bounds::new(0.0, 0.0, 0.0, 1.0), Err(WorldError::InvalidBounds { .. })));
        let b = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        assert_eq!(PolygonWorld::new(b, vec![], -1.0), Err(WorldError::InvalidRadius(-1.0)));
        assert_eq!(
            PolygonWorld::new(b, vec![], f64::NAN).unwrap_err().to_string(),
            "robot radius NaN must be finite and non-negative"
        );
        let e = PolygonWorld::new(b, vec![square(1.0, 1.0, 1.0), vec![p(0.0, 0.0)]], 0.0).unwrap_err();
        assert_eq!(e, WorldError::Obstacle { index: 1, error: PolygonError::TooFewVertices { count: 1 } });
    }

    #[test]
    fn json_round_trip_and_checked_input() {
        let text = r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "robot_radius": 0.5}"#;
        let world: PolygonWorld = serde_json::from_str(text).unwrap();
        assert_eq!(world.obstacles().len(), 1);
        let again: PolygonWorld = serde_json::from_str(&serde_json::to_string(&world).unwrap()).unwrap();
        assert_eq!(again, world);
        let bad = r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4]]]}"#;
        let err = serde_json::from_str::<PolygonWorld>(bad).unwrap_err().to_string();
        assert!(err.contains("obstacle 0"), "{err}");
    }

    #[test]
    fn point_robot_segments_touch_but_do_not_enter() {
        let b = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        let world = PolygonWorld::new(b, vec![square(4.0, 4.0, 2.0)], 0.0).unwrap();
        let c = world.checker();
        assert!(c.segment_is_free(p(0.0, 4.0), p(10.0, 4.0))); // along the bottom side
        assert!(c.segment_is_free(p(2.0, 2.0), p(4.0, 4.0))); // to a corner
        assert!(c.segment_is_free(p(3.0, 5.0), p(5.0, 3.0))); // touching a corner
        assert!(!c.segment_is_free(p(3.0, 5.0), p(5.0, 4.5))); // cutting it
        assert!(!c.segment_is_free(p(0.0, 5.0), p(10.0, 5.0)));
        assert!(!c.segment_is_free(p(2.0, 2.0), p(8.0, 8.0))); // through two corners
        assert!(!c.segment_is_free(p(-1.0, 0.0), p(1.0, 1.0))); // leaves the bounds
    }

    #[test]
    fn arcs_against_a_square() {
        let b = Bounds::new(-10.0, -10.0, 10.0, 10.0).unwrap();
        let world = PolygonWorld::new(b, vec![square(-1.0, 3.0, 2.0)], 0.5).unwrap();
        let c = world.checker();
        let half = std::f64::consts::PI;
        // The upper half of a circle of radius 3 around the origin runs through the square.
        assert!(!c.arc_is_free(p(0.0, 0.0), 3.0, 0.0, half));
        // The lower half does not.
        assert!(c.arc_is_free(p(0.0, 0.0), 3.0, 0.0, -half));
        // Radius 2.4: the top of the arc passes 0.6 below the square, more than the robot radius.
        assert!(c.arc_is_free(p(0.0, 0.0), 2.4, 0.0, half));
        assert!(!c.arc_is_free(p(0.0, 0.0), 2.6, 0.0, half));
        // A full turn leaving the bounds.
        assert!(!c.arc_is_free(p(0.0, -8.0), 3.0, 0.0, 2.0 * half));
    }

    /// For a point robot the free space keeps every obstacle vertex exactly, even two closer
    /// together than the snapping tolerance (extent x 2^-20): each snapped vertex goes back to
    /// its nearest original. (Restoring to the first one in range once merged them and cut a
    /// sliver off the obstacle.)
    #[test]
    fn close_vertices_survive_the_union() {
        let b = Bounds::new(0.0, 0.0, 40.0, 40.0).unwrap();
        let v = vec![
            p(19.85748855920151, 21.500917134384114),
            p(19.49651392900802, 21.218310167815684),
            p(18.772466308939965, 19.203178962697976),
            p(20.357924526009626, 17.236321386233328),
            p(20.357959235248966, 17.236309328012158),
        ];
        let world = PolygonWorld::new(b, vec![v.clone()], 0.0).unwrap();
        let space = world.free_space();
        for q in &v {
            assert!(space.position_at(*q).is_some(), "{q} lost");
        }
        let from = p(35.78906048710447, 30.95817254821389);
        assert!(!world.checker().segment_is_free(from, v[3]));
        assert!(!space.segment_is_free(from, v[3]));
    }

    /// The arc-to-segment distance against dense sampling of the arc, on random arcs and
    /// segments: never above the sampled distance, and within the sampling's resolution of
    /// it. (A segment whose line foot lay outside it once hid a crossing.)
    #[test]
    fn arc_to_segment_distance_matches_sampling() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let mut coordinate = || rng.random_range(-4.0..4.0);
        for _ in 0..3000 {
            let (a, b) = (p(coordinate(), coordinate()), p(coordinate(), coordinate()));
            let (cx, cy, radius, start, sweep) =
                (coordinate(), coordinate(), coordinate().abs() + 0.1, coordinate(), 1.6 * coordinate());
            let arc = Arc { center: p(cx, cy), radius, start, sweep };
            let steps = 4000;
            let sampled = (0..=steps)
                .map(|k| {
                    point_segment_distance(arc.point(start + sweep * f64::from(k) / f64::from(steps)), a, b)
                })
                .fold(f64::INFINITY, f64::min);
            let computed = arc.distance_to_segment(a, b);
            // Between samples the arc strays at most radius * (step angle)^2 / 8 from a chord,
            // and the chord's points lie within half a step of a sample.
            let step = (sweep / f64::from(steps)).abs() * radius;
            assert!(computed <= sampled + 1e-12, "{computed} > sampled {sampled}");
            assert!(computed >= sampled - step, "{computed} < sampled {sampled} for {arc:?}, {a} {b}");
        }
    }

    #[test]
    fn grown_polygons_are_conservative_and_merge() {
        let b = Bounds::new(0.0, 0.0, 20.0, 20.0).unwrap();
        // Two squares 0.8 apart, robot radius 0.5: grown, they overlap and merge.
        let world = PolygonWorld::new(b, vec![square(5.0, 5.0, 2.0), square(7.8, 5.0, 2.0)], 0.5).unwrap();
        let space = world.free_space();
        let checker = world.checker();
        // Outer ring plus one merged hole.
        let (lo, hi) = space.bounding_box();
        assert_eq!((lo, hi), (p(0.0, 0.0), p(20.0, 20.0)));
        let holes = space.positions().iter().filter(|v| v.x > 1.0 && v.x < 19.0).count();
        assert!(holes > 8);
        // Every edge of the grown polygons is outside the exact disc sum (checked at its ends and
        // middle), and no vertex is much farther out than the circumscribed polygon's corners
        // (where two grown outlines cross, a little farther).
        let limit = 1.001 * (0.5 / (DEFAULT_ARC_STEP / 2.0).cos() + world.resolution());
        for e in 0..space.edges().len() {
            let (a, z) = space.edge_points(e);
            if !(b.contains(a) && b.contains(z)) || a.x == 0.0 || a.x == 20.0 || a.y == 0.0 || a.y == 20.0 {
                continue; // the outer boundary
            }
            for q in [a, z, a + (z - a) * 0.5] {
                assert!(checker.point_is_free(q), "{q}");
            }
            let distance = world
                .obstacles()
                .iter()
                .flat_map(|o| o.edges())
                .map(|(s, t)| point_segment_distance(a, s, t))
                .fold(f64::INFINITY, f64::min);
            assert!(distance <= limit, "{a} is {distance} from the obstacles");
        }
        assert!(!space.segment_is_free(p(7.4, 0.0), p(7.4, 20.0)));
    }
}
