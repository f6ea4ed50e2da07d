//! The exact tier: a group's states and motions checked with the URDF's own collision geometry
//! (meshes, boxes, cylinders, capsules, spheres) against the scene's primitives and the other
//! links, by parry3d, in `f64`. Slower than the spheres by orders of magnitude: the reference a
//! path planned with spheres is checked against, not what planners plan with.
//!
//! **States**: two shapes collide when parry finds them intersecting (touching counts). A mesh
//! is its triangles, as FCL and MoveIt take it: an obstacle wholly inside a closed mesh, not
//! meeting its surface, is not found (a robot moving into it would cross the surface first).
//!
//! **Motions** (straight in joint space, continuous joints the short way round) are certified,
//! pair by pair, by distances: over a window of the motion's parameter of length `w`, no point
//! of a link moves farther than `w` times its speed bound (the [`ArmChecker`](crate::ArmChecker)'s
//! bound, over the link's farthest point), so a link and an obstacle whose distance at the
//! window's middle exceeds half that are apart over the whole window. Windows that fail are
//! halved; a pair still unproven when the window's half-motion is below `step / 2` makes the
//! motion colliding (a motion passing that close may be refused), and a distance of zero at a
//! checked state makes it colliding; so does a motion needing more than [`MAX_WINDOWS`].

use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

use nalgebra::{Isometry3, Point3};
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, Cuboid, Cylinder, Shape, SharedShape, TriMesh};

use crate::checker::{
    along, check_start_and_step, extension, is_motion, motion_delta, moved_by, moving_links, pair_reaches,
    reaches, robot_values, speed,
};
use crate::cloud::PointCloud;
use crate::error::RobotError;
use crate::mesh::{Mesh, resolve};
use crate::robot::{Group, Robot};
use crate::scene::{Scene, Shape as ObstacleShape};
use crate::spheres::excluded_pairs;
use crate::srdf::Srdf;
use crate::urdf::Geometry;

/// One link's collision shapes.
#[derive(Clone)]
struct LinkShapes {
    link: usize,
    /// Each shape and its pose in the link's frame.
    shapes: Vec<(Pose, SharedShape)>,
    /// The farthest any point of its shapes is from the link's origin.
    farthest: f64,
}

/// One scene primitive.
#[derive(Clone)]
struct ObstacleShapes {
    id: String,
    pose: Pose,
    shape: SharedShape,
}

/// A pair checked: a link against an obstacle, a point cloud or another link.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pair {
    /// Link entry, obstacle.
    Obstacle(usize, usize),
    /// Link entry, cloud.
    Cloud(usize, usize),
    /// Link entry, link entry.
    Links(usize, usize),
}

/// The most windows one motion's check measures: past it the motion is refused (a motion that
/// needs more passes within micrometres of something over metres of travel).
pub const MAX_WINDOWS: usize = 1_000_000;

/// How far around a link its point cloud neighbours are measured: beyond it, the distance is
/// only bounded from below (by this), which proves a motion's window free as well.
const CLOUD_HORIZON: f64 = 0.25;

/// The exact geometry of one robot's group in one scene, checked as the [module](self) says.
#[derive(Clone)]
pub struct ExactChecker {
    robot: Robot,
    group: Group,
    template: Vec<f64>,
    links: Vec<LinkShapes>,
    obstacles: Vec<ObstacleShapes>,
    clouds: Vec<PointCloud>,
    pairs: Vec<Pair>,
    /// Per pair, per group joint: how fast the pair's distance changes per unit of the joint.
    reach: Vec<Vec<f64>>,
    step: f64,
}

impl std::fmt::Debug for ExactChecker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ExactChecker")
            .field("group", &self.group.name)
            .field("links", &self.links.len())
            .field("obstacles", &self.obstacles.len())
            .field("pairs", &self.pairs.len())
            .field("step", &self.step)
            .finish()
    }
}

impl ExactChecker {
    /// The exact checker of `group` of `robot` in `scene`, joints outside the group at `start`
    /// (a value per joint of the robot), the pairs never checked as for the spheres (one rigid
    /// body, one movable joint apart, the SRDF's and the scene's allowed pairs), mesh files
    /// found from `urdf_dir` ([`resolve`]) and motions proven down to `step` (see the
    /// [module](self)). Errors on a mesh that cannot be read, a `start` of another length or
    /// not finite, and a `step` that is not positive and finite.
    pub fn new(
        robot: Robot,
        srdf: &Srdf,
        group: Group,
        scene: &Scene,
        start: Vec<f64>,
        urdf_dir: &Path,
        step: f64,
    ) -> Result<ExactChecker, RobotError> {
        check_start_and_step(&robot, &start, step, "exact checker")?;
        let excluded = excluded_pairs(&robot, srdf, &scene.allowed)?;
        let moving = moving_links(&robot, &group);
        let mut meshes: HashMap<String, Arc<Mesh>> = HashMap::new();
        let mut links = Vec::new();
        let mut items = Vec::new();
        for (link, l) in robot.urdf().links.iter().enumerate() {
            let mut shapes = Vec::new();
            let mut farthest: f64 = 0.0;
            for c in &l.collisions {
                // The shape, whether it lies along parry's y axis, and its farthest point from
                // the link's origin.
                let offset = c.origin.translation.vector.norm();
                let (shape, turn, reach) = match &c.geometry {
                    Geometry::Mesh { filename, scale } => {
                        let mesh = match meshes.get(filename) {
                            Some(mesh) => mesh.clone(),
                            None => {
                                let mesh = Arc::new(Mesh::from_file(resolve(filename, urdf_dir)?)?);
                                meshes.insert(filename.clone(), mesh.clone());
                                mesh
                            }
                        };
                        let scaled: Vec<Point3<f64>> = mesh
                            .vertices
                            .iter()
                            .map(|v| Point3::from(v.coords.component_mul(scale)))
                            .collect();
                        let reach = scaled.iter().map(|v| (c.origin * v).coords.norm()).fold(0.0, f64::max);
                        let vertices = scaled.iter().map(|v| Vector::new(v.x, v.y, v.z)).collect();
                        let mesh = TriMesh::new(vertices, mesh.triangles.clone()).map_err(|e| {
                            RobotError::Mesh { file: filename.clone(), reason: e.to_string() }
                        })?;
                        (SharedShape::new(mesh), false, reach)
                    }
                    Geometry::Sphere { radius } => {
                        (SharedShape::new(Ball::new(*radius)), false, offset + radius)
                    }
                    Geometry::Box { size } => {
                        let half = size / 2.0;
                        let cuboid = Cuboid::new(Vector::new(half.x, half.y, half.z));
                        (SharedShape::new(cuboid), false, offset + half.norm())
                    }
                    Geometry::Cylinder { radius, length } => {
                        let cylinder = Cylinder::new(length / 2.0, *radius);
                        (SharedShape::new(cylinder), true, offset + radius.hypot(length / 2.0))
                    }
                    Geometry::Capsule { radius, length } => {
                        let capsule = Capsule::new_z(length / 2.0, *radius);
                        (SharedShape::new(capsule), false, offset + radius + length / 2.0)
                    }
                };
                farthest = farthest.max(reach);
                shapes.push((along_z(pose(&c.origin), turn), shape));
            }
            if !shapes.is_empty() {
                links.push(LinkShapes { link, shapes, farthest });
                items.push((link, farthest));
            }
        }
        let obstacles: Vec<ObstacleShapes> = scene
            .obstacles
            .iter()
            .map(|o| {
                let (shape, turn) = match o.shape {
                    ObstacleShape::Box { half } => {
                        (SharedShape::new(Cuboid::new(Vector::new(half.x, half.y, half.z))), false)
                    }
                    ObstacleShape::Cylinder { radius, half_height } => {
                        (SharedShape::new(Cylinder::new(half_height, radius)), true)
                    }
                    ObstacleShape::Sphere { radius } => (SharedShape::new(Ball::new(radius)), false),
                };
                ObstacleShapes { id: o.id.clone(), pose: along_z(pose(&o.pose), turn), shape }
            })
            .collect();
        let allowed = |link: usize, id: &str| {
            let name = &robot.urdf().links[link].name;
            scene.allowed.iter().any(|(a, b)| (a == name && b == id) || (b == name && a == id))
        };
        let mut pairs = Vec::new();
        for (e, l) in links.iter().enumerate() {
            // Every link against the world, as the spheres are (a link the group does not move
            // costs one measure a motion: its speed is zero).
            for (o, obstacle) in obstacles.iter().enumerate() {
                if !allowed(l.link, &obstacle.id) {
                    pairs.push(Pair::Obstacle(e, o));
                }
            }
            for (c, cloud) in scene.clouds.iter().enumerate() {
                if !allowed(l.link, cloud.id()) {
                    pairs.push(Pair::Cloud(e, c));
                }
            }
            for (f, m) in links.iter().enumerate().skip(e + 1) {
                let key = (l.link.min(m.link), l.link.max(m.link));
                if (moving[l.link] || moving[m.link]) && !excluded.contains(&key) {
                    pairs.push(Pair::Links(e, f));
                }
            }
        }
        let moved = moved_by(&robot, &group, &items, &extension(&robot, &group, &start));
        let link_reach = reaches(&group, &moved);
        let link_pairs = pairs.iter().filter_map(|p| match *p {
            Pair::Links(a, b) => Some((a, b)),
            Pair::Obstacle(..) | Pair::Cloud(..) => None,
        });
        let mut pair_reach = pair_reaches(&group, &moved, link_pairs).into_iter();
        let reach = pairs
            .iter()
            .map(|p| match *p {
                Pair::Obstacle(e, _) | Pair::Cloud(e, _) => link_reach[e].clone(),
                Pair::Links(..) => pair_reach.next().unwrap_or_default(),
            })
            .collect();
        let clouds = scene.clouds.clone();
        Ok(ExactChecker { robot, group, template: start, links, obstacles, clouds, pairs, reach, step })
    }

    /// The group.
    pub fn group(&self) -> &Group {
        &self.group
    }

    /// Whether the group at `q` (a value per group joint) is free: no link's shape intersecting
    /// an obstacle's or another link's it is checked against. `false` for a `q` of another
    /// length or not finite.
    pub fn is_free(&self, q: &[f64]) -> bool {
        self.contacts(q).is_ok_and(|c| c.is_empty())
    }

    /// What intersects at `q`: each link and the obstacle (by id) or link (by name) it meets.
    /// Errors on a `q` of another length or not finite.
    pub fn contacts(&self, q: &[f64]) -> Result<Vec<(String, String)>, RobotError> {
        let poses = self
            .poses(q)
            .ok_or(RobotError::Dimension { expected: self.group.joints.len(), found: q.len() })?;
        let links = &self.robot.urdf().links;
        let mut found = Vec::new();
        for &pair in &self.pairs {
            if self.distance(pair, &poses) <= 0.0 {
                let (a, with) = match pair {
                    Pair::Obstacle(e, o) => (self.links[e].link, self.obstacles[o].id.clone()),
                    Pair::Cloud(e, c) => (self.links[e].link, self.clouds[c].id().to_string()),
                    Pair::Links(e, f) => (self.links[e].link, links[self.links[f].link].name.clone()),
                };
                found.push((links[a].name.clone(), with));
            }
        }
        Ok(found)
    }

    /// Whether the straight motion from `a` to `b` is free, proven as the [module](self) says.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        if !is_motion(&self.group, a, b) {
            return false;
        }
        let dims = a.len();
        let mut delta = Vec::with_capacity(dims);
        motion_delta(&self.group, a, b, &mut delta);
        // Poses by the bits of their parameter: windows of different pairs share middles.
        let mut cache: HashMap<u64, Vec<Isometry3<f64>>> = HashMap::new();
        let mut poses_at = |t: f64| -> Option<Vec<Isometry3<f64>>> {
            if let Some(p) = cache.get(&t.to_bits()) {
                return Some(p.clone());
            }
            let q: Vec<f64> = (0..dims).map(|d| along(a[d], delta[d], t)).collect();
            let p = self.poses(&q)?;
            cache.insert(t.to_bits(), p.clone());
            Some(p)
        };
        let mut tested = 0usize;
        for (p, &pair) in self.pairs.iter().enumerate() {
            let rate = speed(&self.reach[p], &delta);
            // A bound too large to be a number (a hostile robot's frames) proves nothing.
            if !rate.is_finite() {
                return false;
            }
            // Windows (middle, half width) of the parameter still to prove.
            let mut windows = vec![(0.5, 0.5)];
            while let Some((t, half)) = windows.pop() {
                tested += 1;
                if tested > MAX_WINDOWS {
                    return false;
                }
                let Some(poses) = poses_at(t) else { return false };
                let distance = self.distance(pair, &poses);
                if distance <= 0.0 {
                    return false;
                }
                if distance > rate * half {
                    continue;
                }
                if rate * half < self.step / 2.0 {
                    return false;
                }
                windows.push((t - half / 2.0, half / 2.0));
                windows.push((t + half / 2.0, half / 2.0));
            }
        }
        true
    }

    /// Every link's pose at `q`; `None` for a `q` of another length or not finite.
    fn poses(&self, q: &[f64]) -> Option<Vec<Isometry3<f64>>> {
        self.robot.link_poses(&robot_values(&self.group, &self.template, q)?).ok()
    }

    /// The distance of `pair` with the links at `poses` (0 when they intersect; also 0 for a
    /// pair of shapes parry cannot measure, so that it is never taken as free).
    fn distance(&self, pair: Pair, poses: &[Isometry3<f64>]) -> f64 {
        let placed = |e: usize| {
            let l = &self.links[e];
            let at = pose(&poses[l.link]);
            l.shapes.iter().map(move |(local, shape)| (at * *local, shape))
        };
        let between = |p1: &Pose, s1: &SharedShape, p2: &Pose, s2: &SharedShape| {
            query::distance(p1, &**s1 as &dyn Shape, p2, &**s2 as &dyn Shape).map_or(0.0, |d| d.distance)
        };
        let mut least = f64::INFINITY;
        match pair {
            Pair::Obstacle(e, o) => {
                let obstacle = &self.obstacles[o];
                for (at, shape) in placed(e) {
                    least = least.min(between(&at, shape, &obstacle.pose, &obstacle.shape));
                }
            }
            Pair::Cloud(e, c) => {
                // The points near enough to matter, each a ball; the rest are beyond the
                // horizon from every point of the link.
                let cloud = &self.clouds[c];
                let origin = Point3::from(poses[self.links[e].link].translation.vector);
                let reach = self.links[e].farthest + cloud.radius() + CLOUD_HORIZON;
                least = CLOUD_HORIZON;
                let ball = SharedShape::new(Ball::new(cloud.radius()));
                for p in cloud.within(&origin, reach) {
                    let at = Pose::from_translation(Vector::new(p.x, p.y, p.z));
                    for (shape_at, shape) in placed(e) {
                        least = least.min(between(&shape_at, shape, &at, &ball));
                    }
                }
            }
            Pair::Links(e, f) => {
                for (at, shape) in placed(e) {
                    for (other_at, other) in placed(f) {
                        least = least.min(between(&at, shape, &other_at, other));
                    }
                }
            }
        }
        least.max(0.0)
    }
}

/// A nalgebra pose as parry's.
fn pose(iso: &Isometry3<f64>) -> Pose {
    let t = iso.translation.vector;
    let q = iso.rotation.quaternion();
    Pose::from_parts(Vector::new(t.x, t.y, t.z), Rotation::from_xyzw(q.i, q.j, q.k, q.w))
}

/// `pose`, turned so that a shape along parry's y axis (its cylinders) lies along z (URDF's
/// and MoveIt's cylinders) when `turn`.
fn along_z(pose: Pose, turn: bool) -> Pose {
    if turn {
        pose * Pose::from_parts(Vector::ZERO, Rotation::from_rotation_x(std::f64::consts::FRAC_PI_2))
    } else {
        pose
    }
}
