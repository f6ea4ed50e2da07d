//! What can go wrong reading a robot, its semantic description, a scene or a request, and
//! building a planning group from them.

use thiserror::Error;

/// Why a robot file, a scene or a request was refused, or a group could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RobotError {
    /// The text is not well-formed XML.
    #[error("not well-formed XML: {0}")]
    Xml(String),
    /// The text is not well-formed YAML.
    #[error("not well-formed YAML: {0}")]
    Yaml(String),
    /// A file could not be read.
    #[error("could not read {path}: {reason}")]
    Io {
        /// The file.
        path: String,
        /// What the system said.
        reason: String,
    },
    /// The document's root element is not the one expected.
    #[error("the root element is <{found}>, expected <{expected}>")]
    Root {
        /// What the format's root is.
        expected: &'static str,
        /// What the document has.
        found: String,
    },
    /// An element lacks an attribute or a child it must have.
    #[error("<{element}> needs {what}")]
    Missing {
        /// The element.
        element: String,
        /// The attribute or child.
        what: &'static str,
    },
    /// A value is not what its place requires (a number, a finite number, a known word).
    #[error("<{element}> {attribute}: {reason}, got {value:?}")]
    Invalid {
        /// The element.
        element: String,
        /// The attribute or field.
        attribute: &'static str,
        /// What it must be.
        reason: &'static str,
        /// What it was.
        value: String,
    },
    /// Two links or two joints share a name.
    #[error("two {kind}s are named {name:?}")]
    Duplicate {
        /// `link` or `joint`.
        kind: &'static str,
        /// The name.
        name: String,
    },
    /// A name refers to no link of the robot.
    #[error("no link is named {0:?}")]
    UnknownLink(String),
    /// A name refers to no joint of the robot.
    #[error("no joint is named {0:?}")]
    UnknownJoint(String),
    /// A name refers to no group of the semantic description.
    #[error("no group is named {0:?}")]
    UnknownGroup(String),
    /// The links and joints do not form one tree: a link with two parents, a cycle, or not one
    /// root.
    #[error("the links and joints are not one tree: {0}")]
    NotATree(String),
    /// A mimic joint follows a joint that mimics another, or itself.
    #[error("joint {0:?} mimics a joint that is itself a mimic")]
    MimicChain(String),
    /// A group's chain does not lead from its base down to its tip.
    #[error("no chain leads from {base:?} down to {tip:?}")]
    NoChain {
        /// The base link.
        base: String,
        /// The tip link.
        tip: String,
    },
    /// Groups include each other.
    #[error("group {0:?} includes itself")]
    GroupCycle(String),
    /// A group has a joint the planner cannot move (floating, planar, or a revolute or
    /// prismatic joint without limits); or a continuous joint where the joint space asked for
    /// is a box ([`ArmChecker::space`](crate::ArmChecker::space); use
    /// [`ArmChecker::joint_space`](crate::ArmChecker::joint_space)).
    #[error("joint {joint:?} of the group is {kind}, which the joint space does not take")]
    UnsupportedJoint {
        /// The joint.
        joint: String,
        /// Its kind.
        kind: &'static str,
    },
    /// The group has another number of joints than the space asked for.
    #[error("the group has {found} joints, the space {expected}")]
    Dimension {
        /// The space's dimension.
        expected: usize,
        /// The group's joints.
        found: usize,
    },
    /// A link's collision geometry has no sphere cover here (meshes are covered by a spherized
    /// URDF).
    #[error("link {link:?} has a {shape} collision with no sphere cover: use a spherized URDF")]
    NoSphereCover {
        /// The link.
        link: String,
        /// Its shape.
        shape: &'static str,
    },
    /// A joint value is missing, not finite, or outside its limits (by more than the tolerance).
    #[error("joint {joint:?}: {reason}, got {value}")]
    JointValue {
        /// The joint.
        joint: String,
        /// What is wrong.
        reason: &'static str,
        /// The value.
        value: f64,
    },
    /// The file is larger than a reader takes.
    #[error("{what} has {count} items, more than the {max} taken")]
    TooLarge {
        /// What was counted.
        what: &'static str,
        /// How many.
        count: usize,
        /// The most taken.
        max: usize,
    },
    /// A mesh file could not be found, read or parsed, or is not a mesh.
    #[error("mesh {file:?}: {reason}")]
    Mesh {
        /// The file as the URDF names it, or as found.
        file: String,
        /// What is wrong.
        reason: String,
    },
}
