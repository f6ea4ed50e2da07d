//! A robot: its URDF checked as one tree of links and joints, with forward kinematics, and its
//! planning groups resolved from the SRDF.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Isometry3, Translation3, UnitQuaternion};

use crate::error::RobotError;
use crate::srdf::Srdf;
use crate::urdf::{JointKind, Urdf, read};

/// A robot whose links and joints form one tree, ready for forward kinematics.
///
/// Joint values are given per joint of the URDF, in its order ([`Robot::joint_index`]); fixed
/// joints ignore theirs, a mimic joint takes `multiplier × value of the joint it follows +
/// offset`.
#[derive(Debug, Clone)]
pub struct Robot {
    urdf: Urdf,
    link_names: HashMap<String, usize>,
    joint_names: HashMap<String, usize>,
    /// The joint above each link (`None` for the root).
    parent_joint: Vec<Option<usize>>,
    /// The link of each joint's parent and child.
    ends: Vec<(usize, usize)>,
    /// The joints in an order where every joint's parent link is placed before it.
    order: Vec<usize>,
    root: usize,
    /// For a mimic joint: the joint it follows, the multiplier and the offset.
    mimic: Vec<Option<(usize, f64, f64)>>,
}

/// A planning group: the joints a planner moves, in the tree's order, with their limits.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Its name.
    pub name: String,
    /// The URDF index of each joint, in the order of the group's states.
    pub joints: Vec<usize>,
    /// Their names.
    pub names: Vec<String>,
    /// Their limits, `(lower, upper)`; `(-π, π)` for a continuous joint.
    pub bounds: Vec<(f64, f64)>,
    /// Which of them are continuous: angles that wrap around, moved the short way round.
    pub wraps: Vec<bool>,
}

impl Group {
    /// Whether `q` has a finite value per group joint, each within the joint's limits (`[-π,
    /// π]` for a continuous joint, within rounding: a motion then turns it within ±2π, the
    /// extension its bounds allow for; the pair floors, taken over a whole turn, hold for
    /// every angle).
    pub fn within_limits(&self, q: &[f64]) -> bool {
        q.len() == self.bounds.len()
            && q.iter().zip(&self.bounds).zip(&self.wraps).all(|((v, (low, high)), &wraps)| {
                if wraps { v.abs() <= std::f64::consts::PI * (1.0 + 1e-12) } else { low <= v && v <= high }
            })
    }
}

impl Robot {
    /// Checks `urdf` as one tree: link and joint names unique, every joint between two known
    /// links, every link but one (the root) the child of exactly one joint, no cycle, and every
    /// mimic joint following a joint that is not itself a mimic.
    pub fn new(urdf: Urdf) -> Result<Robot, RobotError> {
        let mut link_names = HashMap::new();
        for (i, link) in urdf.links.iter().enumerate() {
            if link_names.insert(link.name.clone(), i).is_some() {
                return Err(RobotError::Duplicate { kind: "link", name: link.name.clone() });
            }
        }
        let mut joint_names = HashMap::new();
        let mut parent_joint = vec![None; urdf.links.len()];
        let mut ends = Vec::with_capacity(urdf.joints.len());
        for (j, joint) in urdf.joints.iter().enumerate() {
            if joint_names.insert(joint.name.clone(), j).is_some() {
                return Err(RobotError::Duplicate { kind: "joint", name: joint.name.clone() });
            }
            let find = |name: &str| {
                link_names.get(name).copied().ok_or_else(|| RobotError::UnknownLink(name.into()))
            };
            let (parent, child) = (find(&joint.parent)?, find(&joint.child)?);
            if parent_joint[child].replace(j).is_some() {
                return Err(RobotError::NotATree(format!("link {:?} has two parent joints", joint.child)));
            }
            ends.push((parent, child));
        }
        let roots: Vec<usize> = (0..urdf.links.len()).filter(|&l| parent_joint[l].is_none()).collect();
        let &[root] = roots.as_slice() else {
            return Err(RobotError::NotATree(format!(
                "{} links have no parent joint, one must",
                roots.len()
            )));
        };
        // Breadth first from the root: a link never reached is on a cycle.
        let mut children = vec![Vec::new(); urdf.links.len()];
        for (j, &(parent, _)) in ends.iter().enumerate() {
            children[parent].push(j);
        }
        let mut order = Vec::with_capacity(urdf.joints.len());
        let mut frontier = vec![root];
        while let Some(link) = frontier.pop() {
            for &j in &children[link] {
                order.push(j);
                frontier.push(ends[j].1);
            }
        }
        if order.len() != urdf.joints.len() {
            return Err(RobotError::NotATree("the joints form a cycle".into()));
        }
        let mut mimic = vec![None; urdf.joints.len()];
        for (j, joint) in urdf.joints.iter().enumerate() {
            if let Some(m) = &joint.mimic {
                let followed = joint_names
                    .get(&m.joint)
                    .copied()
                    .ok_or_else(|| RobotError::UnknownJoint(m.joint.clone()))?;
                if followed == j || urdf.joints[followed].mimic.is_some() {
                    return Err(RobotError::MimicChain(joint.name.clone()));
                }
                mimic[j] = Some((followed, m.multiplier, m.offset));
            }
        }
        Ok(Robot { urdf, link_names, joint_names, parent_joint, ends, order, root, mimic })
    }

    /// Reads and checks the URDF file at `path`.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Robot, RobotError> {
        Robot::new(Urdf::parse(&read(path.as_ref())?)?)
    }

    /// The URDF it was built from.
    pub fn urdf(&self) -> &Urdf {
        &self.urdf
    }

    /// The root link's index.
    pub fn root(&self) -> usize {
        self.root
    }

    /// The index of the link named `name`.
    pub fn link_index(&self, name: &str) -> Option<usize> {
        self.link_names.get(name).copied()
    }

    /// The index of the joint named `name`.
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joint_names.get(name).copied()
    }

    /// The parent and child link of joint `joint`.
    pub fn joint_links(&self, joint: usize) -> (usize, usize) {
        self.ends[joint]
    }

    /// The joint above link `link`, `None` for the root.
    pub fn parent_joint(&self, link: usize) -> Option<usize> {
        self.parent_joint[link]
    }

    /// The joints from the root down, each after its parent link's joint.
    pub fn joints_in_order(&self) -> &[usize] {
        &self.order
    }

    /// The joint `joint` follows and how, if it is a mimic joint: `(followed, multiplier,
    /// offset)`.
    pub fn mimic(&self, joint: usize) -> Option<(usize, f64, f64)> {
        self.mimic[joint]
    }

    /// The pose of every link in the root link's frame, for `values` (one per joint of the
    /// URDF, in its order). Errors when `values` has another length or a value is not finite.
    pub fn link_poses(&self, values: &[f64]) -> Result<Vec<Isometry3<f64>>, RobotError> {
        if values.len() != self.urdf.joints.len() {
            return Err(RobotError::Dimension { expected: self.urdf.joints.len(), found: values.len() });
        }
        if let Some(j) = values.iter().position(|v| !v.is_finite()) {
            let joint = self.urdf.joints[j].name.clone();
            return Err(RobotError::JointValue { joint, reason: "not finite", value: values[j] });
        }
        let mut poses = Vec::new();
        self.poses_into(values, &mut poses);
        Ok(poses)
    }

    /// [`link_poses`](Self::link_poses) into `poses`, for `values` already checked.
    pub(crate) fn poses_into(&self, values: &[f64], poses: &mut Vec<Isometry3<f64>>) {
        poses.clear();
        poses.resize(self.urdf.links.len(), Isometry3::identity());
        for &j in &self.order {
            let (parent, child) = self.ends[j];
            poses[child] = poses[parent] * self.joint_transform(j, values);
        }
    }

    /// The child link's frame in the parent link's frame at `values` (one per joint).
    pub(crate) fn joint_transform(&self, joint: usize, values: &[f64]) -> Isometry3<f64> {
        let j = &self.urdf.joints[joint];
        let q = match self.mimic[joint] {
            Some((followed, multiplier, offset)) => multiplier * values[followed] + offset,
            None => values[joint],
        };
        let motion = match j.kind {
            JointKind::Revolute | JointKind::Continuous => {
                Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&j.axis, q))
            }
            JointKind::Prismatic => {
                Isometry3::from_parts(Translation3::from(j.axis.into_inner() * q), UnitQuaternion::identity())
            }
            JointKind::Fixed | JointKind::Floating | JointKind::Planar => Isometry3::identity(),
        };
        j.origin * motion
    }

    /// The group joint that drives joint `joint`: `(its index in the group, multiplier,
    /// offset)`: `(index, 1, 0)` for a joint of the group, the mimic's factors for a joint
    /// that mimics one; `None` for a joint the group does not move.
    pub fn driver(&self, group: &Group, joint: usize) -> Option<(usize, f64, f64)> {
        if let Some(v) = group.joints.iter().position(|&g| g == joint) {
            return Some((v, 1.0, 0.0));
        }
        let (followed, multiplier, offset) = self.mimic(joint)?;
        group.joints.iter().position(|&g| g == followed).map(|v| (v, multiplier, offset))
    }

    /// The group `name` of `srdf`, resolved as MoveIt does: its joints, the joint above each of
    /// its links, the joints of each chain from its base link down to its tip, and its
    /// subgroups'; planned are the revolute, continuous and prismatic ones that mimic no other,
    /// in the tree's order. Errors on unknown names, a chain that does not lead down from base
    /// to tip, groups that include themselves, a group joint that is floating or planar, and a
    /// continuous group joint that another joint mimics by other than whole turns (a
    /// prismatic joint, or a fractional multiplier: the robot would not look the same a turn
    /// later).
    pub fn group(&self, srdf: &Srdf, name: &str) -> Result<Group, RobotError> {
        let mut members = vec![false; self.urdf.joints.len()];
        self.collect(srdf, name, &mut members, &mut Vec::new())?;
        let mut joints = Vec::new();
        for &j in &self.order {
            let joint = &self.urdf.joints[j];
            if !members[j] || joint.kind == JointKind::Fixed || self.mimic[j].is_some() {
                continue;
            }
            let bounds = match (joint.kind, joint.limits) {
                (JointKind::Continuous, _) => (-std::f64::consts::PI, std::f64::consts::PI),
                (JointKind::Revolute | JointKind::Prismatic, Some(l)) => (l.lower, l.upper),
                _ => {
                    return Err(RobotError::UnsupportedJoint {
                        joint: joint.name.clone(),
                        kind: joint.kind.name(),
                    });
                }
            };
            joints.push((j, bounds));
        }
        // A continuous joint wraps only if the robot looks the same a turn later: a joint that
        // mimics it must turn by whole turns too.
        for (j, mimic) in self.mimic.iter().enumerate() {
            let Some((leader, multiplier, _)) = *mimic else { continue };
            let wrapped = joints.iter().any(|&(g, _)| g == leader)
                && self.urdf.joints[leader].kind == JointKind::Continuous;
            let turns = matches!(self.urdf.joints[j].kind, JointKind::Revolute | JointKind::Continuous)
                && multiplier == multiplier.round();
            if wrapped && !turns && self.urdf.joints[j].kind != JointKind::Fixed {
                return Err(RobotError::UnsupportedJoint {
                    joint: self.urdf.joints[leader].name.clone(),
                    kind: "continuous, and a joint mimics it by other than whole turns",
                });
            }
        }
        Ok(Group {
            name: name.to_string(),
            names: joints.iter().map(|&(j, _)| self.urdf.joints[j].name.clone()).collect(),
            bounds: joints.iter().map(|&(_, b)| b).collect(),
            wraps: joints.iter().map(|&(j, _)| self.urdf.joints[j].kind == JointKind::Continuous).collect(),
            joints: joints.into_iter().map(|(j, _)| j).collect(),
        })
    }

    fn collect(
        &self,
        srdf: &Srdf,
        name: &str,
        members: &mut [bool],
        visiting: &mut Vec<String>,
    ) -> Result<(), RobotError> {
        if visiting.iter().any(|v| v == name) {
            return Err(RobotError::GroupCycle(name.to_string()));
        }
        let spec = srdf.group(name).ok_or_else(|| RobotError::UnknownGroup(name.to_string()))?;
        visiting.push(name.to_string());
        for joint in &spec.joints {
            members[self.joint_index(joint).ok_or_else(|| RobotError::UnknownJoint(joint.clone()))?] = true;
        }
        let link = |name: &String| self.link_index(name).ok_or_else(|| RobotError::UnknownLink(name.clone()));
        for l in &spec.links {
            if let Some(j) = self.parent_joint[link(l)?] {
                members[j] = true;
            }
        }
        for (base, tip) in &spec.chains {
            let (base_link, mut at) = (link(base)?, link(tip)?);
            while at != base_link {
                let j = self.parent_joint[at]
                    .ok_or_else(|| RobotError::NoChain { base: base.clone(), tip: tip.clone() })?;
                members[j] = true;
                at = self.ends[j].0;
            }
        }
        for sub in &spec.subgroups {
            self.collect(srdf, sub, members, visiting)?;
        }
        visiting.pop();
        Ok(())
    }
}
