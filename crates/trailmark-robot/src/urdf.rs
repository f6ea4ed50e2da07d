//! URDF files read into a typed model: links with their collision geometry, joints with their
//! kind, frame, axis, limits and mimic. Everything the planner does not use (inertia, visuals,
//! materials, transmissions, Gazebo tags) is passed over; everything it uses is checked.
//!
//! ```
//! use trailmark_robot::urdf::{Geometry, JointKind, Urdf};
//!
//! let urdf = Urdf::parse(r#"
//!   <robot name="pendulum">
//!     <link name="base"/>
//!     <link name="arm"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
//!     <joint name="swing" type="revolute">
//!       <parent link="base"/><child link="arm"/>
//!       <origin xyz="0 0 1" rpy="0 0 0"/><axis xyz="0 1 0"/>
//!       <limit lower="-1.5" upper="1.5"/>
//!     </joint>
//!   </robot>"#)?;
//! assert_eq!(urdf.joints[0].kind, JointKind::Revolute);
//! assert_eq!(urdf.links[1].collisions[0].geometry, Geometry::Sphere { radius: 0.1 });
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use nalgebra::{Isometry3, Translation3, Unit, UnitQuaternion, Vector3};
use roxmltree::{Document, Node};

use trailmark_core::read::{MAX_DOCUMENT_BYTES, read_to_string_capped};

use crate::error::RobotError;

/// The most links, joints or collision shapes one file may have: a real robot has tens to
/// hundreds; a file past this is refused before anything is built from it.
pub const MAX_ELEMENTS: usize = 100_000;

/// A robot as its URDF describes it.
#[derive(Debug, Clone, PartialEq)]
pub struct Urdf {
    /// The robot's name.
    pub name: String,
    /// Its links, in the file's order.
    pub links: Vec<Link>,
    /// Its joints, in the file's order.
    pub joints: Vec<Joint>,
}

/// A rigid body of the robot.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Its name.
    pub name: String,
    /// The shapes it collides with, in its own frame.
    pub collisions: Vec<Collision>,
}

/// One collision shape of a link.
#[derive(Debug, Clone, PartialEq)]
pub struct Collision {
    /// Where the shape sits in the link's frame.
    pub origin: Isometry3<f64>,
    /// The shape.
    pub geometry: Geometry,
}

/// A collision shape, about its own origin (cylinders and capsules along their z axis).
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// A ball.
    Sphere {
        /// Its radius (positive).
        radius: f64,
    },
    /// A box.
    Box {
        /// Its side lengths along x, y and z (positive).
        size: Vector3<f64>,
    },
    /// A cylinder along z, centred on the origin.
    Cylinder {
        /// Its radius (positive).
        radius: f64,
        /// Its length (positive).
        length: f64,
    },
    /// A capsule along z: a cylinder of this length with a half ball at each end.
    Capsule {
        /// Its radius (positive).
        radius: f64,
        /// The length of its cylinder (not negative).
        length: f64,
    },
    /// A triangle mesh in a file (OBJ or STL), scaled.
    Mesh {
        /// The file name as written (`package://...` or a path).
        filename: String,
        /// The scale along x, y and z.
        scale: Vector3<f64>,
    },
}

impl Geometry {
    /// The radius of the smallest ball about the shape's origin that contains it; `None` for a
    /// mesh, whose vertices are in its file.
    pub fn bounding_radius(&self) -> Option<f64> {
        match self {
            Geometry::Sphere { radius } => Some(*radius),
            Geometry::Box { size } => Some(size.norm() / 2.0),
            Geometry::Cylinder { radius, length } => Some(radius.hypot(length / 2.0)),
            Geometry::Capsule { radius, length } => Some(radius + length / 2.0),
            Geometry::Mesh { .. } => None,
        }
    }

    /// The shape's name, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Geometry::Sphere { .. } => "sphere",
            Geometry::Box { .. } => "box",
            Geometry::Cylinder { .. } => "cylinder",
            Geometry::Capsule { .. } => "capsule",
            Geometry::Mesh { .. } => "mesh",
        }
    }
}

/// How a joint moves its child link.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// A rotation about the axis, within limits.
    Revolute,
    /// A rotation about the axis without limits.
    Continuous,
    /// A translation along the axis, within limits.
    Prismatic,
    /// No motion.
    Fixed,
    /// Six degrees of freedom.
    Floating,
    /// A motion in the plane normal to the axis.
    Planar,
}

impl JointKind {
    /// The kind's URDF name.
    pub fn name(self) -> &'static str {
        match self {
            JointKind::Revolute => "revolute",
            JointKind::Continuous => "continuous",
            JointKind::Prismatic => "prismatic",
            JointKind::Fixed => "fixed",
            JointKind::Floating => "floating",
            JointKind::Planar => "planar",
        }
    }
}

/// A joint: its child link moves relative to its parent.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Its name.
    pub name: String,
    /// How it moves.
    pub kind: JointKind,
    /// The parent link's name.
    pub parent: String,
    /// The child link's name.
    pub child: String,
    /// The joint frame in the parent link's frame (the child's frame at value 0).
    pub origin: Isometry3<f64>,
    /// The axis, in the joint frame (unit length; `x` when the file gives none).
    pub axis: Unit<Vector3<f64>>,
    /// The position limits, for revolute and prismatic joints.
    pub limits: Option<Limits>,
    /// The joint it follows, if it mimics one.
    pub mimic: Option<Mimic>,
}

/// A joint's position limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// The least value.
    pub lower: f64,
    /// The greatest value.
    pub upper: f64,
}

/// A joint that follows another: `value = multiplier × other + offset`.
#[derive(Debug, Clone, PartialEq)]
pub struct Mimic {
    /// The joint followed.
    pub joint: String,
    /// Its factor (1 when not given).
    pub multiplier: f64,
    /// The offset (0 when not given).
    pub offset: f64,
}

impl Urdf {
    /// Reads a URDF document. Errors on XML that is not well formed, a root other than
    /// `<robot>`, a missing name or link, a number that is not finite, a shape of zero or
    /// negative size, an unknown joint type, or limits with `lower > upper`; the links and
    /// joints are checked as a tree by [`Robot::new`](crate::Robot::new).
    pub fn parse(text: &str) -> Result<Urdf, RobotError> {
        let document = robot_document(text, "the robot's XML")?;
        let root = document.root_element();
        let mut links = Vec::new();
        let mut joints = Vec::new();
        for node in root.children().filter(Node::is_element) {
            match node.tag_name().name() {
                "link" => links.push(link(node)?),
                "joint" => joints.push(joint(node)?),
                _ => {}
            }
        }
        Ok(Urdf { name: attribute(root, "name")?.to_string(), links, joints })
    }
}

/// `text` as XML whose root is `<robot>` with at most [`MAX_ELEMENTS`] elements (URDF and SRDF
/// alike); `what` names it in the error.
pub(crate) fn robot_document<'a>(text: &'a str, what: &'static str) -> Result<Document<'a>, RobotError> {
    let document = Document::parse(text).map_err(|e| RobotError::Xml(e.to_string()))?;
    let root = document.root_element();
    if root.tag_name().name() != "robot" {
        return Err(RobotError::Root { expected: "robot", found: root.tag_name().name().to_string() });
    }
    let count = root.descendants().filter(Node::is_element).count();
    if count > MAX_ELEMENTS {
        return Err(RobotError::TooLarge { what, count, max: MAX_ELEMENTS });
    }
    Ok(document)
}

fn link(node: Node<'_, '_>) -> Result<Link, RobotError> {
    let name = attribute(node, "name")?.to_string();
    let collisions = node
        .children()
        .filter(|c| c.has_tag_name("collision"))
        .map(|c| {
            let origin = origin(c)?;
            let shape = child(c, "geometry")?
                .children()
                .find(Node::is_element)
                .ok_or_else(|| missing(c, "a shape in <geometry>"))?;
            Ok(Collision { origin, geometry: geometry(shape)? })
        })
        .collect::<Result<_, RobotError>>()?;
    Ok(Link { name, collisions })
}

fn geometry(node: Node<'_, '_>) -> Result<Geometry, RobotError> {
    let positive = |name: &'static str| number(node, name, Check::Positive);
    Ok(match node.tag_name().name() {
        "sphere" => Geometry::Sphere { radius: positive("radius")? },
        "box" => {
            let size = vector(node, "size")?.ok_or_else(|| missing(node, "size"))?;
            if !size.iter().all(|&s| s > 0.0) {
                return Err(invalid(node, "size", "three positive lengths", format!("{size:?}")));
            }
            Geometry::Box { size }
        }
        "cylinder" => Geometry::Cylinder { radius: positive("radius")?, length: positive("length")? },
        "capsule" => Geometry::Capsule {
            radius: positive("radius")?,
            length: number(node, "length", Check::NotNegative)?,
        },
        "mesh" => Geometry::Mesh {
            filename: attribute(node, "filename")?.to_string(),
            scale: vector(node, "scale")?.unwrap_or_else(|| Vector3::new(1.0, 1.0, 1.0)),
        },
        other => {
            return Err(invalid(node, "shape", "sphere, box, cylinder, capsule or mesh", other.to_string()));
        }
    })
}

fn joint(node: Node<'_, '_>) -> Result<Joint, RobotError> {
    let name = attribute(node, "name")?.to_string();
    let kind = match attribute(node, "type")? {
        "revolute" => JointKind::Revolute,
        "continuous" => JointKind::Continuous,
        "prismatic" => JointKind::Prismatic,
        "fixed" => JointKind::Fixed,
        "floating" => JointKind::Floating,
        "planar" => JointKind::Planar,
        other => {
            return Err(invalid(
                node,
                "type",
                "revolute, continuous, prismatic, fixed, floating or planar",
                other.to_string(),
            ));
        }
    };
    let parent = attribute(child(node, "parent")?, "link")?.to_string();
    let child_link = attribute(child(node, "child")?, "link")?.to_string();
    let axis = match node.children().find(|c| c.has_tag_name("axis")) {
        Some(a) => {
            let xyz = vector(a, "xyz")?.ok_or_else(|| missing(a, "xyz"))?;
            // A fixed joint's axis is not used (and files write "0 0 0" there).
            match Unit::try_new(xyz, 1e-12) {
                Some(axis) => axis,
                None if kind == JointKind::Fixed => Vector3::x_axis(),
                None => return Err(invalid(a, "xyz", "a non-zero axis", format!("{xyz:?}"))),
            }
        }
        None => Vector3::x_axis(),
    };
    let limits = match (kind, node.children().find(|c| c.has_tag_name("limit"))) {
        (JointKind::Revolute | JointKind::Prismatic, None) => return Err(missing(node, "<limit>")),
        (JointKind::Revolute | JointKind::Prismatic, Some(l)) => {
            let (lower, upper) = (number(l, "lower", Check::Finite)?, number(l, "upper", Check::Finite)?);
            if lower > upper {
                return Err(invalid(l, "lower", "at most upper", lower.to_string()));
            }
            Some(Limits { lower, upper })
        }
        _ => None,
    };
    let mimic = match node.children().find(|c| c.has_tag_name("mimic")) {
        Some(m) => Some(Mimic {
            joint: attribute(m, "joint")?.to_string(),
            multiplier: optional_number(m, "multiplier")?.unwrap_or(1.0),
            offset: optional_number(m, "offset")?.unwrap_or(0.0),
        }),
        None => None,
    };
    Ok(Joint { name, kind, parent, child: child_link, origin: origin(node)?, axis, limits, mimic })
}

/// The `<origin xyz rpy>` child of `node`, identity when absent; `rpy` is roll, pitch and yaw
/// about the fixed x, y and z axes (the rotation `Rz(yaw) Ry(pitch) Rx(roll)`).
fn origin(node: Node<'_, '_>) -> Result<Isometry3<f64>, RobotError> {
    let Some(o) = node.children().find(|c| c.has_tag_name("origin")) else {
        return Ok(Isometry3::identity());
    };
    let xyz = vector(o, "xyz")?.unwrap_or_else(Vector3::zeros);
    let rpy = vector(o, "rpy")?.unwrap_or_else(Vector3::zeros);
    let rotation = UnitQuaternion::from_euler_angles(rpy.x, rpy.y, rpy.z);
    Ok(Isometry3::from_parts(Translation3::from(xyz), rotation))
}

#[derive(Clone, Copy)]
enum Check {
    Finite,
    NotNegative,
    Positive,
}

fn number(node: Node<'_, '_>, name: &'static str, check: Check) -> Result<f64, RobotError> {
    let text = attribute(node, name)?;
    let value: f64 = text.trim().parse().map_err(|_| invalid(node, name, "a number", text.to_string()))?;
    let (ok, reason) = match check {
        Check::Finite => (value.is_finite(), "a finite number"),
        Check::NotNegative => (value.is_finite() && value >= 0.0, "a finite number, not negative"),
        Check::Positive => (value.is_finite() && value > 0.0, "a positive finite number"),
    };
    if ok { Ok(value) } else { Err(invalid(node, name, reason, text.to_string())) }
}

fn optional_number(node: Node<'_, '_>, name: &'static str) -> Result<Option<f64>, RobotError> {
    if node.attribute(name).is_none() {
        return Ok(None);
    }
    number(node, name, Check::Finite).map(Some)
}

/// Three finite numbers separated by white space, `None` when the attribute is absent.
fn vector(node: Node<'_, '_>, name: &'static str) -> Result<Option<Vector3<f64>>, RobotError> {
    let Some(text) = node.attribute(name) else { return Ok(None) };
    let values: Vec<f64> = text
        .split_whitespace()
        .map(|t| t.parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| invalid(node, name, "three numbers", text.to_string()))?;
    match values[..] {
        [x, y, z] if values.iter().all(|v| v.is_finite()) => Ok(Some(Vector3::new(x, y, z))),
        _ => Err(invalid(node, name, "three finite numbers", text.to_string())),
    }
}

fn attribute<'a>(node: Node<'a, '_>, name: &'static str) -> Result<&'a str, RobotError> {
    node.attribute(name).ok_or_else(|| missing(node, name))
}

fn child<'a, 'i>(node: Node<'a, 'i>, name: &'static str) -> Result<Node<'a, 'i>, RobotError> {
    node.children().find(|c| c.has_tag_name(name)).ok_or_else(|| missing(node, name))
}

pub(crate) fn missing(node: Node<'_, '_>, what: &'static str) -> RobotError {
    RobotError::Missing { element: described(node), what }
}

pub(crate) fn invalid(
    node: Node<'_, '_>,
    attribute: &'static str,
    reason: &'static str,
    value: String,
) -> RobotError {
    RobotError::Invalid { element: described(node), attribute, reason, value }
}

/// `tag name="..."`, or the tag alone, for messages.
fn described(node: Node<'_, '_>) -> String {
    match node.attribute("name") {
        Some(name) => format!("{} name={name:?}", node.tag_name().name()),
        None => node.tag_name().name().to_string(),
    }
}

/// The text of the file at `path`, at most [`MAX_DOCUMENT_BYTES`] long (core's capped reader, as
/// every other reader of user files uses).
pub(crate) fn read(path: &std::path::Path) -> Result<String, RobotError> {
    read_to_string_capped(path, MAX_DOCUMENT_BYTES)
        .map_err(|e| RobotError::Io { path: path.display().to_string(), reason: e.to_string() })
}
