//! SRDF files (MoveIt's semantic description of a robot) read into a typed model: the planning
//! groups, as lists of joints, links, chains and subgroups, and the pairs of links never checked
//! against each other.
//!
//! ```
//! use trailmark_robot::srdf::Srdf;
//!
//! let srdf = Srdf::parse(r#"
//!   <robot name="pendulum">
//!     <group name="arm"><chain base_link="base" tip_link="arm"/></group>
//!     <disable_collisions link1="base" link2="arm" reason="Adjacent"/>
//!   </robot>"#)?;
//! assert_eq!(srdf.groups[0].chains, [("base".to_string(), "arm".to_string())]);
//! assert_eq!(srdf.disabled, [("base".to_string(), "arm".to_string())]);
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use roxmltree::Node;

use crate::error::RobotError;
use crate::urdf::{missing, robot_document};

/// A robot's semantic description.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Srdf {
    /// The planning groups, in the file's order.
    pub groups: Vec<GroupSpec>,
    /// Pairs of links never checked against each other (adjacent, or never in contact).
    pub disabled: Vec<(String, String)>,
}

/// A planning group as the file writes it; [`Robot::group`](crate::Robot::group) resolves it
/// into joints.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GroupSpec {
    /// Its name.
    pub name: String,
    /// Joints named one by one.
    pub joints: Vec<String>,
    /// Links named one by one (each brings the joint above it).
    pub links: Vec<String>,
    /// Chains from a base link down to a tip link (each brings the joints between them).
    pub chains: Vec<(String, String)>,
    /// Groups it includes.
    pub subgroups: Vec<String>,
}

impl Srdf {
    /// Reads an SRDF document. Errors on XML that is not well formed, a root other than
    /// `<robot>`, or an element without the names it needs.
    pub fn parse(text: &str) -> Result<Srdf, RobotError> {
        let document = robot_document(text, "the semantic description's XML")?;
        let root = document.root_element();
        let mut srdf = Srdf::default();
        for node in root.children().filter(Node::is_element) {
            match node.tag_name().name() {
                "group" => srdf.groups.push(group(node)?),
                "disable_collisions" => {
                    srdf.disabled.push((name(node, "link1")?, name(node, "link2")?));
                }
                _ => {}
            }
        }
        Ok(srdf)
    }

    /// Reads the SRDF file at `path`.
    pub fn from_file(path: impl AsRef<std::path::Path>) -> Result<Srdf, RobotError> {
        Srdf::parse(&crate::urdf::read(path.as_ref())?)
    }

    /// The group named `name`.
    pub fn group(&self, name: &str) -> Option<&GroupSpec> {
        self.groups.iter().find(|g| g.name == name)
    }
}

fn group(node: Node<'_, '_>) -> Result<GroupSpec, RobotError> {
    let mut spec = GroupSpec { name: name(node, "name")?, ..GroupSpec::default() };
    for part in node.children().filter(Node::is_element) {
        match part.tag_name().name() {
            "joint" => spec.joints.push(name(part, "name")?),
            "link" => spec.links.push(name(part, "name")?),
            "chain" => spec.chains.push((name(part, "base_link")?, name(part, "tip_link")?)),
            "group" => spec.subgroups.push(name(part, "name")?),
            // Passive joints are not planned for; nothing else is part of a group.
            _ => {}
        }
    }
    Ok(spec)
}

fn name(node: Node<'_, '_>, attribute: &'static str) -> Result<String, RobotError> {
    node.attribute(attribute).map(str::to_string).ok_or_else(|| missing(node, attribute))
}
