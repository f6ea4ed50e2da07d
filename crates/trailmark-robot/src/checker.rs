//! Whether a group's configurations and motions are free: the robot's spheres against the
//! scene's obstacles and against each other, in `f64`, one configuration at a time.
//!
//! **States** are checked exactly for the spheres: a sphere collides with a box, a cylinder or a
//! sphere when its centre is within its radius of the shape (touching counts), and two spheres
//! of links checked against each other when their centres are within the sum of their radii.
//!
//! **Motions** (straight lines in joint space, `t` from 0 to 1) are covered by checked states
//! with grown spheres, by one rule that the [`BatchChecker`](crate::BatchChecker) follows too:
//!
//! - no sphere moves faster than `rate` metres per unit of `t`, so a state at `t` found free
//!   with its spheres grown by `g` stands for every state within `g / rate` of it: the motion is
//!   free when such windows cover `[0, 1]`;
//! - first, evenly spaced states grown by a coarse `g` (80 times the finest: 4 cm at the
//!   default step), windows just touching;
//! - a state whose grown spheres touch something is replaced by two with half its growth,
//!   covering its window, and is itself checked with no growth (touching there, the motion
//!   collides);
//! - a state that still touches at the finest growth, `step / 2`, makes the motion colliding: a
//!   motion passing closer than that to something may be refused.
//!
//! Each sphere is grown by `g` times its own speed over `rate` (spheres near the base move
//! slowly, spheres that do not move are not grown), and a pair of spheres by `g` times how fast
//! their distance can change over `rate` (joints moving both together change nothing). How fast
//! a sphere moves is bounded per joint: a revolute joint turning by `dq` moves a point at most
//! `dq` times its distance from the joint, and that distance is at most the lengths of the joint
//! frames between the joint and the sphere's link plus the sphere's offset in it (for a
//! prismatic joint, `dq` itself); a sphere's bound over a motion is the sum over the group's
//! joints above it.

use nalgebra::{Point3, SVector};
use trailmark_space::{Joints, Rn, SpaceError, Validity};

use crate::cloud::PointCloud;
use crate::error::RobotError;
use crate::motion;
use crate::robot::{Group, Robot};
use crate::scene::{Obstacle, Scene, Shape};
use crate::spheres::SphereModel;
use crate::srdf::Srdf;
use crate::urdf::JointKind;

/// The default `step`: 1 mm, twice the finest growth of a motion's spheres (a state checked with
/// spheres grown by 0.5 mm that still touches makes its motion colliding).
pub const DEFAULT_STEP: f64 = 0.001;

/// The spheres of one robot's group in one scene, checked as the [module](self) says.
#[derive(Debug, Clone)]
pub struct ArmChecker {
    pub(crate) robot: Robot,
    pub(crate) model: SphereModel,
    pub(crate) obstacles: Vec<Obstacle>,
    /// For each obstacle, the links allowed to touch it.
    pub(crate) allowed_links: Vec<Vec<usize>>,
    /// The scene's point clouds, and for each, the links allowed to touch it.
    pub(crate) clouds: Vec<(PointCloud, Vec<usize>)>,
    pub(crate) group: Group,
    /// A value per joint of the robot: the start state's, for the joints outside the group.
    pub(crate) template: Vec<f64>,
    /// Sphere pairs checked against each other (at least one of them moves with the group).
    pub(crate) pairs: Vec<(u32, u32)>,
    /// Per sphere, per group joint: how far the sphere moves per unit of the joint's value.
    pub(crate) reach: Vec<Vec<f64>>,
    /// Per pair of `pairs`, per group joint: how much the pair's distance changes per unit of
    /// the joint's value (joints moving both spheres together change nothing).
    pub(crate) pair_reach: Vec<Vec<f64>>,
    /// Per joint of the robot, the largest magnitude its value takes ([`extension`]).
    pub(crate) extension: Vec<f64>,
    pub(crate) step: f64,
}

impl ArmChecker {
    /// The checker of `group` of `robot` in `scene`: the robot's spheres
    /// ([`SphereModel::new`], with the scene's allowed pairs), joints outside the group at
    /// `start` (a value per joint of the robot), motions checked down to a growth of `step / 2`
    /// (see the [module](self)). Errors on a mesh without spheres, unknown names, a `start` of
    /// another length or not finite, and a `step` that is not positive and finite.
    pub fn new(
        robot: Robot,
        srdf: &Srdf,
        group: Group,
        scene: &Scene,
        start: Vec<f64>,
        step: f64,
    ) -> Result<ArmChecker, RobotError> {
        check_start_and_step(&robot, &start, step, "checker")?;
        let model = SphereModel::new(&robot, srdf, &scene.allowed)?;
        let moving = moving_links(&robot, &group);
        let spheres = &model.spheres;
        let mut pairs = Vec::new();
        for a in 0..spheres.len() {
            for b in a + 1..spheres.len() {
                let (la, lb) = (spheres[a].link, spheres[b].link);
                if (moving[la] || moving[lb]) && model.checks(la, lb) {
                    pairs.push((a as u32, b as u32));
                }
            }
        }
        // The links the scene's matrix allows to touch the object `id`.
        let allowed = |id: &str| -> Vec<usize> {
            let other = |(a, b): &(String, String)| {
                if a == id {
                    Some(b.clone())
                } else if b == id {
                    Some(a.clone())
                } else {
                    None
                }
            };
            scene.allowed.iter().filter_map(other).filter_map(|name| robot.link_index(&name)).collect()
        };
        let allowed_links = scene.obstacles.iter().map(|o| allowed(&o.id)).collect();
        let clouds = scene.clouds.iter().map(|c| (c.clone(), allowed(c.id()))).collect();
        let extension = extension(&robot, &group, &start);
        let items: Vec<(usize, f64)> = model.spheres.iter().map(|s| (s.link, s.centre.norm())).collect();
        let moved = moved_by(&robot, &group, &items, &extension);
        let reach = reaches(&group, &moved);
        let pair_reach = pair_reaches(&group, &moved, pairs.iter().map(|&(a, b)| (a as usize, b as usize)));
        Ok(ArmChecker {
            robot,
            model,
            obstacles: scene.obstacles.clone(),
            allowed_links,
            clouds,
            group,
            template: start,
            pairs,
            reach,
            pair_reach,
            extension,
            step,
        })
    }

    /// This checker with every sphere of link `l` grown by `growth[l]` (a value per link of
    /// the robot, each not negative and finite): for example by what
    /// [`cover::uncovered`](crate::cover::uncovered) finds, so that the spheres contain the
    /// robot's own geometry and the checker is conservative for it too. Errors on a `growth`
    /// of another length or with a value that is negative or not finite.
    pub fn grown(mut self, growth: &[f64]) -> Result<ArmChecker, RobotError> {
        if growth.len() != self.robot.urdf().links.len() || !growth.iter().all(|g| g.is_finite() && *g >= 0.0)
        {
            return Err(RobotError::Invalid {
                element: "checker".into(),
                attribute: "growth",
                reason: "a length not negative and finite per link of the robot",
                value: format!("{growth:?}"),
            });
        }
        for s in &mut self.model.spheres {
            s.radius += growth[s.link];
        }
        Ok(self)
    }

    /// The group planned for.
    pub fn group(&self) -> &Group {
        &self.group
    }

    /// The robot.
    pub fn robot(&self) -> &Robot {
        &self.robot
    }

    /// Twice the finest growth of a motion's spheres, in metres.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The joint space of the group as a box of its joints' limits, `N` of them. Errors when
    /// the group has another number of joints, or a continuous joint (a box would not wrap it:
    /// [`joint_space`](Self::joint_space) does).
    pub fn space<const N: usize>(&self) -> Result<Rn<N>, RobotError> {
        if self.group.joints.len() != N {
            return Err(RobotError::Dimension { expected: N, found: self.group.joints.len() });
        }
        if let Some(i) = self.group.wraps.iter().position(|&w| w) {
            return Err(RobotError::UnsupportedJoint {
                joint: self.group.names[i].clone(),
                kind: "continuous",
            });
        }
        let low = SVector::<f64, N>::from_fn(|i, _| self.group.bounds[i].0);
        let high = SVector::<f64, N>::from_fn(|i, _| self.group.bounds[i].1);
        Rn::new(low, high).map_err(|e: SpaceError| RobotError::Invalid {
            element: self.group.name.clone(),
            attribute: "limits",
            reason: "a box of positive width on every joint",
            value: e.to_string(),
        })
    }

    /// The joint space of any group, `N` joints: its joints' limits, the continuous joints
    /// wrapping around (moved the short way round, as the checkers move them). A k-d tree over
    /// it needs `N` plus [`Joints::wrapping`] coordinates. Errors when the group has another
    /// number of joints.
    pub fn joint_space<const N: usize>(&self) -> Result<Joints<N>, RobotError> {
        if self.group.joints.len() != N {
            return Err(RobotError::Dimension { expected: N, found: self.group.joints.len() });
        }
        let low = SVector::<f64, N>::from_fn(|i, _| self.group.bounds[i].0);
        let high = SVector::<f64, N>::from_fn(|i, _| self.group.bounds[i].1);
        let wraps = std::array::from_fn(|i| self.group.wraps[i]);
        Joints::new(low, high, wraps).map_err(|e: SpaceError| RobotError::Invalid {
            element: self.group.name.clone(),
            attribute: "limits",
            reason: "a box of positive width on every joint",
            value: e.to_string(),
        })
    }

    /// Whether the group at `q` (a value per group joint) is free: every sphere clear of every
    /// obstacle and of the spheres it is checked against. `false` for a `q` of another length
    /// or not finite.
    pub fn is_free(&self, q: &[f64]) -> bool {
        self.is_free_grown(q, &[], &[])
    }

    /// Whether the straight motion from `a` to `b` in joint space is free, as the
    /// [module](self) says; continuous joints turn the short way round.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        if !is_motion(&self.group, a, b) {
            return false;
        }
        let mut delta = Vec::with_capacity(a.len());
        motion_delta(&self.group, a, b, &mut delta);
        let speeds: Vec<f64> = self.reach.iter().map(|r| speed(r, &delta)).collect();
        let pair_speeds: Vec<f64> = self.pair_reach.iter().map(|r| speed(r, &delta)).collect();
        let rate = speeds.iter().fold(0.0, |m: f64, &v| m.max(v));
        let mut q = vec![0.0; a.len()];
        let (mut grows, mut pair_grows) = (vec![0.0; speeds.len()], vec![0.0; pair_speeds.len()]);
        motion::covered(rate, self.step / 2.0, 1, |batch, _| {
            let s = batch[0];
            for (d, v) in q.iter_mut().enumerate() {
                *v = along(a[d], delta[d], s.t);
            }
            for (g, v) in grows.iter_mut().zip(&speeds).chain(pair_grows.iter_mut().zip(&pair_speeds)) {
                *g = if rate > 0.0 { s.grow * v / rate } else { 0.0 };
            }
            u32::from(!self.is_free_grown(&q, &grows, &pair_grows))
        })
    }

    /// Whether `q` is free with each sphere grown by its entry of `grows` against obstacles, and
    /// each pair's sum of radii by its entry of `pair_grows` (none where empty).
    fn is_free_grown(&self, q: &[f64], grows: &[f64], pair_grows: &[f64]) -> bool {
        let Some(centres) = self.centres(q) else { return false };
        let grow = |s: usize| grows.get(s).copied().unwrap_or(0.0);
        for (k, (s, c)) in self.model.spheres.iter().zip(&centres).enumerate() {
            let r = s.radius + grow(k);
            for (o, allowed) in self.obstacles.iter().zip(&self.allowed_links) {
                if touches(o, c, r) && !allowed.contains(&s.link) {
                    return false;
                }
            }
        }
        let pairs_clear = self.pairs.iter().enumerate().all(|(p, &(a, b))| {
            let (sa, sb) = (&self.model.spheres[a as usize], &self.model.spheres[b as usize]);
            let reach = sa.radius + sb.radius + pair_grows.get(p).copied().unwrap_or(0.0);
            (centres[a as usize] - centres[b as usize]).norm_squared() > reach * reach
        });
        pairs_clear && !self.cloud_hit(&centres, grows)
    }

    /// Whether a sphere at `q`, each grown by its entry of `grows` (none where empty), touches a
    /// point cloud's ball; `true` for a `q` of another length or not finite.
    pub(crate) fn meets_cloud(&self, q: &[f64], grows: &[f64]) -> bool {
        if self.clouds.is_empty() {
            return false;
        }
        self.centres(q).is_none_or(|centres| self.cloud_hit(&centres, grows))
    }

    /// Whether a sphere with its centre in `centres`, grown by its entry of `grows`, touches a
    /// point cloud's ball.
    fn cloud_hit(&self, centres: &[Point3<f64>], grows: &[f64]) -> bool {
        self.clouds.iter().any(|(cloud, allowed)| {
            self.model.spheres.iter().zip(centres).enumerate().any(|(k, (s, c))| {
                !allowed.contains(&s.link)
                    && cloud.clearance(c) <= s.radius + grows.get(k).copied().unwrap_or(0.0)
            })
        })
    }

    /// Every sphere's centre at `q`; `None` for a `q` of another length or not finite.
    fn centres(&self, q: &[f64]) -> Option<Vec<Point3<f64>>> {
        let values = robot_values(&self.group, &self.template, q)?;
        let mut poses = Vec::new();
        self.robot.poses_into(&values, &mut poses);
        Some(self.model.spheres.iter().map(|s| poses[s.link] * Point3::from(s.centre)).collect())
    }

    /// What touches at `q`, for telling why a state is not free: a contact per link and
    /// obstacle, or pair of links, with the deepest overlap of their spheres. Errors on a `q` of
    /// another length or not finite.
    pub fn contacts(&self, q: &[f64]) -> Result<Vec<Contact>, RobotError> {
        let centres = self
            .centres(q)
            .ok_or(RobotError::Dimension { expected: self.group.joints.len(), found: q.len() })?;
        let links = &self.robot.urdf().links;
        let mut found: Vec<Contact> = Vec::new();
        let mut add = |link: usize, with: String, depth: f64| {
            let link = links[link].name.clone();
            match found.iter_mut().find(|c| c.link == link && c.with == with) {
                Some(c) => c.depth = c.depth.max(depth),
                None => found.push(Contact { link, with, depth }),
            }
        };
        for (s, c) in self.model.spheres.iter().zip(&centres) {
            for (o, allowed) in self.obstacles.iter().zip(&self.allowed_links) {
                let depth = s.radius - clearance(o, c);
                if depth >= 0.0 && !allowed.contains(&s.link) {
                    add(s.link, o.id.clone(), depth);
                }
            }
        }
        for (cloud, allowed) in &self.clouds {
            for (s, c) in self.model.spheres.iter().zip(&centres) {
                let depth = s.radius - cloud.clearance(c);
                if depth >= 0.0 && !allowed.contains(&s.link) {
                    add(s.link, cloud.id().to_string(), depth);
                }
            }
        }
        for &(a, b) in &self.pairs {
            let (sa, sb) = (&self.model.spheres[a as usize], &self.model.spheres[b as usize]);
            let depth = sa.radius + sb.radius - (centres[a as usize] - centres[b as usize]).norm();
            if depth >= 0.0 {
                add(sa.link, links[sb.link].name.clone(), depth);
            }
        }
        Ok(found)
    }
}

/// Two things touching: a link and an obstacle (by its id) or another link (by its name).
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    /// The link's name.
    pub link: String,
    /// The obstacle's id or the other link's name.
    pub with: String,
    /// How far their deepest spheres overlap, in metres (0 when they just touch).
    pub depth: f64,
}

/// Whether a sphere at `c` of radius `r` touches obstacle `o`.
fn touches(o: &Obstacle, c: &Point3<f64>, r: f64) -> bool {
    squared_distance(o, c) <= r * r
}

/// How far `c` is from obstacle `o` (0 inside it).
pub(crate) fn clearance(o: &Obstacle, c: &Point3<f64>) -> f64 {
    squared_distance(o, c).sqrt()
}

fn squared_distance(o: &Obstacle, c: &Point3<f64>) -> f64 {
    let p = o.pose.inverse_transform_point(c);
    match o.shape {
        Shape::Box { half } => {
            let d = p.coords.abs() - half;
            d.map(|x| x.max(0.0)).norm_squared()
        }
        Shape::Cylinder { radius, half_height } => {
            let radial = (p.x.hypot(p.y) - radius).max(0.0);
            let axial = (p.z.abs() - half_height).max(0.0);
            radial * radial + axial * axial
        }
        Shape::Sphere { radius } => {
            let d = (p.coords.norm() - radius).max(0.0);
            d * d
        }
    }
}

/// Which links move when the group's joints (or joints mimicking them) move.
pub(crate) fn moving_links(robot: &Robot, group: &Group) -> Vec<bool> {
    let joints = &robot.urdf().joints;
    let mut moving = vec![false; robot.urdf().links.len()];
    let moves = |j: usize| {
        group.joints.contains(&j)
            || robot.mimic(j).is_some_and(|(followed, _, _)| group.joints.contains(&followed))
    };
    for &j in robot.joints_in_order() {
        let (parent, child) = robot.joint_links(j);
        moving[child] = moving[parent] || (joints[j].kind != JointKind::Fixed && moves(j));
    }
    moving
}

/// How far a joint that a group joint drives moves a sphere, per unit of the group joint's
/// value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Moved {
    /// The joint of the robot (the group joint, or one mimicking it).
    pub(crate) joint: usize,
    /// The group joint's index in the group.
    pub(crate) variable: usize,
    /// The distance bound (see the [module](self)) times the mimic's multiplier.
    pub(crate) weight: f64,
}

/// Per item (a link, and the farthest its points are from the link's origin), the driven
/// joints above it and how far each moves it.
pub(crate) fn moved_by(
    robot: &Robot,
    group: &Group,
    items: &[(usize, f64)],
    extension: &[f64],
) -> Vec<Vec<Moved>> {
    let joints = &robot.urdf().joints;
    let driven: Vec<(usize, usize, f64)> = (0..joints.len())
        .filter_map(|j| robot.driver(group, j).map(|(v, multiplier, _)| (j, v, multiplier.abs())))
        .filter(|&(j, _, _)| joints[j].kind != JointKind::Fixed)
        .collect();
    items
        .iter()
        .map(|&(link, offset)| {
            driven
                .iter()
                .filter_map(|&(joint, variable, multiplier)| {
                    let length = chain_length(robot, extension, robot.joint_links(joint).1, link)?;
                    let distance =
                        if joints[joint].kind == JointKind::Prismatic { 1.0 } else { length + offset };
                    Some(Moved { joint, variable, weight: multiplier * distance })
                })
                .collect()
        })
        .collect()
}

/// Per item of `moved`, how far it moves per unit of each group joint's value.
pub(crate) fn reaches(group: &Group, moved: &[Vec<Moved>]) -> Vec<Vec<f64>> {
    moved.iter().map(|m| by_joint(group, &mut m.iter())).collect()
}

/// Per pair of items of `moved`, how much their distance changes per unit of each group
/// joint's value: the joints moving both together change nothing.
pub(crate) fn pair_reaches(
    group: &Group,
    moved: &[Vec<Moved>],
    pairs: impl Iterator<Item = (usize, usize)>,
) -> Vec<Vec<f64>> {
    pairs
        .map(|(a, b)| {
            let (ma, mb) = (&moved[a], &moved[b]);
            let only = |x: &'_ Moved, other: &[Moved]| !other.iter().any(|o| o.joint == x.joint);
            by_joint(group, &mut ma.iter().filter(|x| only(x, mb)).chain(mb.iter().filter(|x| only(x, ma))))
        })
        .collect()
}

fn by_joint(group: &Group, instances: &mut dyn Iterator<Item = &Moved>) -> Vec<f64> {
    let mut r = vec![0.0; group.joints.len()];
    for m in instances {
        r[m.variable] += m.weight;
    }
    r
}

/// Checks what both checkers are built from: `start` a finite value per joint of `robot`,
/// and `step` positive and finite.
pub(crate) fn check_start_and_step(
    robot: &Robot,
    start: &[f64],
    step: f64,
    element: &str,
) -> Result<(), RobotError> {
    robot.link_poses(start)?;
    if !(step.is_finite() && step > 0.0) {
        return Err(RobotError::Invalid {
            element: element.into(),
            attribute: "step",
            reason: "a positive finite length",
            value: step.to_string(),
        });
    }
    Ok(())
}

/// Whether `a` and `b` are finite states of `group` (a value per group joint).
pub(crate) fn is_motion(group: &Group, a: &[f64], b: &[f64]) -> bool {
    let dims = group.joints.len();
    a.len() == dims && b.len() == dims && a.iter().chain(b).all(|v| v.is_finite())
}

/// A value per joint of the robot: `template`'s, with the group's joints at `q`; `None` for a
/// `q` of another length or not finite.
pub(crate) fn robot_values(group: &Group, template: &[f64], q: &[f64]) -> Option<Vec<f64>> {
    if q.len() != group.joints.len() || !q.iter().all(|v| v.is_finite()) {
        return None;
    }
    let mut values = template.to_vec();
    for (&j, &v) in group.joints.iter().zip(q) {
        values[j] = v;
    }
    Some(values)
}

/// How fast something moves along a motion of joint differences `delta` at most, for its
/// `reach` per group joint: `Σ reach[k] |delta[k]|`.
pub(crate) fn speed(reach: &[f64], delta: &[f64]) -> f64 {
    reach.iter().zip(delta).map(|(r, d)| r * d.abs()).sum()
}

/// The motion from `a` to `b` joint by joint into `out`: `b - a`, a continuous joint's the short
/// way round (within `[-π, π]`; its end may then lie beyond ±π, where it is the same angle).
pub(crate) fn motion_delta(group: &Group, a: &[f64], b: &[f64], out: &mut Vec<f64>) {
    out.clear();
    out.extend(a.iter().zip(b).zip(&group.wraps).map(|((x, y), &wraps)| {
        let d = y - x;
        if wraps { d - std::f64::consts::TAU * (d / std::f64::consts::TAU).round() } else { d }
    }));
}

/// The joint value a fraction `t` along its motion from `a` by `delta`: the one formula both
/// checkers check motions at.
pub(crate) fn along(a: f64, delta: f64, t: f64) -> f64 {
    a + delta * t
}

/// The longest `link` can be from `top`'s frame, over every configuration, when `link` is at or
/// below `top`: the lengths of the joint frames between them (prismatic joints at their farthest
/// extension); `None` when it is not below.
pub(crate) fn chain_length(robot: &Robot, extension: &[f64], top: usize, link: usize) -> Option<f64> {
    let joints = &robot.urdf().joints;
    let mut length = 0.0;
    let mut at = link;
    while at != top {
        let j = robot.parent_joint(at)?;
        length += joints[j].origin.translation.vector.norm();
        if joints[j].kind == JointKind::Prismatic {
            length += extension[j];
        }
        at = robot.joint_links(j).0;
    }
    Some(length)
}

/// Per joint of the robot, the largest magnitude its value takes: a group joint's limits (2π
/// for a continuous one: a motion's end turned the short way round from within ±π), a
/// mimic's multiple of its leader's plus its offset, any other joint's value in `template`
/// (the start state's, which it keeps, even beyond its limits).
pub(crate) fn extension(robot: &Robot, group: &Group, template: &[f64]) -> Vec<f64> {
    let own = |j: usize| match group.joints.iter().position(|&g| g == j) {
        Some(v) if group.wraps[v] => std::f64::consts::TAU,
        Some(v) => group.bounds[v].0.abs().max(group.bounds[v].1.abs()),
        None => template[j].abs(),
    };
    (0..robot.urdf().joints.len())
        .map(|j| match robot.mimic(j) {
            Some((leader, multiplier, offset)) => multiplier.abs() * own(leader) + offset.abs(),
            None => own(j),
        })
        .collect()
}

impl<const N: usize> Validity<Rn<N>> for ArmChecker {
    fn state_is_valid(&self, _: &Rn<N>, q: &SVector<f64, N>) -> bool {
        self.is_free(q.as_slice())
    }

    fn motion_is_valid(&self, _: &Rn<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.motion_is_free(a.as_slice(), b.as_slice())
    }
}

impl<const N: usize> Validity<Joints<N>> for ArmChecker {
    fn state_is_valid(&self, _: &Joints<N>, q: &SVector<f64, N>) -> bool {
        self.is_free(q.as_slice())
    }

    fn motion_is_valid(&self, _: &Joints<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.motion_is_free(a.as_slice(), b.as_slice())
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Isometry3;

    use super::*;

    #[test]
    fn a_sphere_touching_a_box_face_collides_and_one_beyond_does_not() {
        let o = Obstacle {
            id: "b".into(),
            shape: Shape::Box { half: nalgebra::Vector3::new(1.0, 1.0, 1.0) },
            pose: Isometry3::identity(),
        };
        assert!(touches(&o, &Point3::new(1.5, 0.0, 0.0), 0.5));
        assert!(!touches(&o, &Point3::new(1.5 + 1e-9, 0.0, 0.0), 0.5));
        // Near a corner the distance is to the corner, not to the faces' planes.
        assert!(!touches(&o, &Point3::new(1.4, 1.4, 0.0), 0.5));
    }

    #[test]
    fn a_sphere_near_a_cylinder_rim_is_measured_to_the_rim() {
        let o = Obstacle {
            id: "c".into(),
            shape: Shape::Cylinder { radius: 1.0, half_height: 1.0 },
            pose: Isometry3::identity(),
        };
        assert!(touches(&o, &Point3::new(0.0, 0.0, 1.5), 0.5));
        assert!(!touches(&o, &Point3::new(1.3, 0.0, 1.3), 0.4)); // 0.42 from the rim
        assert!(touches(&o, &Point3::new(1.3, 0.0, 1.3), 0.43));
    }
}
