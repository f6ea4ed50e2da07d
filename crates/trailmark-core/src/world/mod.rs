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
use serde::{Deserialize, Serialize};

use crate::freespace::FreeSpace;
use crate::geometry::Point;

mod bounds;
pub(crate) mod checker;
mod error;
mod polygon;

pub use bounds::Bounds;
pub use checker::CollisionChecker;
use error::in_range;
pub use error::{MAX_COORDINATE, MIN_RELATIVE_SIDE, MIN_SIDE, PolygonError, WorldError};
pub use polygon::Polygon;
use polygon::signed_area;

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
    /// removed; [`WorldError::NoSuchObstacle`] if there is no such obstacle.
    pub fn without_obstacle(&self, index: usize) -> Result<(Self, Polygon), WorldError> {
        let count = self.obstacles.len();
        if index >= count {
            return Err(WorldError::NoSuchObstacle { index, count });
        }
        let mut world = self.clone();
        let removed = world.obstacles.remove(index);
        Ok((world, removed))
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

#[cfg(test)]
mod tests;
