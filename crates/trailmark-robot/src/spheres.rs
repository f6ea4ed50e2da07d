//! A robot's collision geometry as spheres in its links' frames, and which links are never
//! checked against each other.
//!
//! A spherized URDF gives its spheres directly. A box, cylinder or capsule is covered by the one
//! sphere about its centre that contains it (conservative: never free where the shape is not);
//! a mesh needs a spherized URDF.
//!
//! Links are not checked against each other when the semantic description disables the pair,
//! when a scene's allowed collision matrix allows it, or when a sphere cover makes them overlap
//! by construction: links joined by fixed joints (one rigid body), and bodies one movable joint
//! apart.

use std::collections::HashSet;

use nalgebra::Vector3;
use trailmark_core::UnionFind;

use crate::error::RobotError;
use crate::robot::Robot;
use crate::srdf::Srdf;
use crate::urdf::JointKind;

/// One sphere of a link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkSphere {
    /// The link's index.
    pub link: usize,
    /// The centre in the link's frame.
    pub centre: Vector3<f64>,
    /// The radius.
    pub radius: f64,
}

/// A robot's spheres and the link pairs never checked.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereModel {
    /// Every sphere, link by link.
    pub spheres: Vec<LinkSphere>,
    /// Pairs of link indices never checked against each other, the smaller first.
    pub excluded: HashSet<(usize, usize)>,
}

impl SphereModel {
    /// The spheres of `robot`'s collision geometry, with the pairs `srdf` disables and the pairs
    /// of `allowed` (link names; names of no link are passed over, as a scene's objects are
    /// there). Errors on a mesh, and on a disabled pair naming no link.
    pub fn new(robot: &Robot, srdf: &Srdf, allowed: &[(String, String)]) -> Result<SphereModel, RobotError> {
        let urdf = robot.urdf();
        let mut spheres = Vec::new();
        for (link, l) in urdf.links.iter().enumerate() {
            for c in &l.collisions {
                let radius = c.geometry.bounding_radius().ok_or_else(|| RobotError::NoSphereCover {
                    link: l.name.clone(),
                    shape: c.geometry.kind(),
                })?;
                spheres.push(LinkSphere { link, centre: c.origin.translation.vector, radius });
            }
        }
        let excluded = excluded_pairs(robot, srdf, allowed)?;
        Ok(SphereModel { spheres, excluded })
    }

    /// Whether links `a` and `b` are checked against each other.
    pub fn checks(&self, a: usize, b: usize) -> bool {
        a != b && !self.excluded.contains(&ordered(a, b))
    }
}

/// The link pairs never checked against each other (the smaller index first): links of one
/// rigid body (joined by fixed joints), bodies one movable joint apart, the pairs `srdf`
/// disables and those `allowed` names (names of no link passed over). Errors on a disabled
/// pair naming no link.
pub(crate) fn excluded_pairs(
    robot: &Robot,
    srdf: &Srdf,
    allowed: &[(String, String)],
) -> Result<HashSet<(usize, usize)>, RobotError> {
    let urdf = robot.urdf();
    // Rigid bodies: links joined by fixed joints.
    let mut bodies = UnionFind::new(urdf.links.len());
    for (j, joint) in urdf.joints.iter().enumerate() {
        if joint.kind == JointKind::Fixed {
            let (parent, child) = robot.joint_links(j);
            bodies.union(parent as u32, child as u32);
        }
    }
    let body = |link: usize| bodies.root(link as u32);
    let mut adjacent = HashSet::new();
    for (j, joint) in urdf.joints.iter().enumerate() {
        if joint.kind != JointKind::Fixed {
            let (parent, child) = robot.joint_links(j);
            adjacent.insert(ordered(body(parent) as usize, body(child) as usize));
        }
    }
    let mut excluded = HashSet::new();
    for a in 0..urdf.links.len() {
        for b in a + 1..urdf.links.len() {
            let (x, y) = (body(a), body(b));
            if x == y || adjacent.contains(&ordered(x as usize, y as usize)) {
                excluded.insert((a, b));
            }
        }
    }
    for (a, b) in &srdf.disabled {
        let find =
            |name: &String| robot.link_index(name).ok_or_else(|| RobotError::UnknownLink(name.clone()));
        excluded.insert(ordered(find(a)?, find(b)?));
    }
    for (a, b) in allowed {
        if let (Some(a), Some(b)) = (robot.link_index(a), robot.link_index(b)) {
            excluded.insert(ordered(a, b));
        }
    }
    Ok(excluded)
}

fn ordered(a: usize, b: usize) -> (usize, usize) {
    if a <= b { (a, b) } else { (b, a) }
}
