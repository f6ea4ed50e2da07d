//! MoveIt motion plan requests (`moveit_msgs/MotionPlanRequest` as YAML): the group, the start
//! joint state and the goal's joint constraints.
//!
//! ```
//! use trailmark_robot::request::Request;
//!
//! let request = Request::parse("
//! group_name: arm
//! start_state: {joint_state: {name: [a, b], position: [0.0, 0.5]}}
//! goal_constraints:
//!   - joint_constraints: [{joint_name: a, position: 1.0}, {joint_name: b, position: -0.5}]
//! ")?;
//! assert_eq!(request.group, "arm");
//! assert_eq!(request.goal, [("a".to_string(), 1.0), ("b".to_string(), -0.5)]);
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use std::path::Path;

use trailmark_core::yaml::{self, Yaml};

use crate::error::RobotError;
use crate::robot::{Group, Robot};
use crate::urdf::read;

/// How far outside a joint's limits a request's value may be and still be taken, on the limit:
/// files write `3.14159265` where the URDF says `3.14159`, or round `±π` the other way.
pub const BOUNDS_TOLERANCE: f64 = 1e-4;

/// A motion plan request.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Request {
    /// The planning group.
    pub group: String,
    /// The start state's joint values, by name.
    pub start: Vec<(String, f64)>,
    /// The goal's joint values, by name (the first goal constraint's joint constraints).
    pub goal: Vec<(String, f64)>,
}

impl Request {
    /// Reads a request's YAML text. Errors on YAML that is not well formed, anchors and
    /// aliases, names and positions of different lengths, and values that are not finite.
    pub fn parse(text: &str) -> Result<Request, RobotError> {
        let doc = yaml::load(text, "request files").map_err(RobotError::Yaml)?;
        let group = doc["group_name"].as_str().unwrap_or("").to_string();
        let state = &doc["start_state"]["joint_state"];
        let names = state["name"].as_vec().map_or(&[][..], Vec::as_slice);
        let positions = state["position"].as_vec().map_or(&[][..], Vec::as_slice);
        if names.len() != positions.len() {
            return Err(invalid("start_state", "a position per name"));
        }
        let start = names.iter().zip(positions).map(|(n, p)| named(n, p)).collect::<Result<_, _>>()?;
        let constraints =
            doc["goal_constraints"][0]["joint_constraints"].as_vec().map_or(&[][..], Vec::as_slice);
        let goal =
            constraints.iter().map(|c| named(&c["joint_name"], &c["position"])).collect::<Result<_, _>>()?;
        Ok(Request { group, start, goal })
    }

    /// Reads the request file at `path`.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Request, RobotError> {
        Request::parse(&read(path.as_ref())?)
    }

    /// A value for every joint of `robot` (in the URDF's order): the start state's where it
    /// names the joint, else the joint's default as MoveIt sets it (0 when within its limits,
    /// else the middle of them). Errors on a name that is not a joint of the robot.
    pub fn start_values(&self, robot: &Robot) -> Result<Vec<f64>, RobotError> {
        let mut values: Vec<f64> = robot
            .urdf()
            .joints
            .iter()
            .map(|joint| match joint.limits {
                Some(l) if l.lower > 0.0 || l.upper < 0.0 => l.lower + (l.upper - l.lower) / 2.0,
                _ => 0.0,
            })
            .collect();
        for (name, value) in &self.start {
            values[robot.joint_index(name).ok_or_else(|| RobotError::UnknownJoint(name.clone()))?] = *value;
        }
        Ok(values)
    }

    /// The start and the goal of `group`, one value per group joint in its order: from the
    /// start state and the goal constraints, each within the joint's limits or at most
    /// [`BOUNDS_TOLERANCE`] outside them (then taken on the limit); a continuous joint's any
    /// finite angle, brought into `[-π, π]` by whole turns. Errors on a group joint either
    /// leaves out or a value further outside.
    pub fn ends(&self, group: &Group) -> Result<(Vec<f64>, Vec<f64>), RobotError> {
        Ok((group_values(group, &self.start)?, group_values(group, &self.goal)?))
    }
}

fn group_values(group: &Group, values: &[(String, f64)]) -> Result<Vec<f64>, RobotError> {
    group
        .names
        .iter()
        .zip(&group.bounds)
        .zip(&group.wraps)
        .map(|((name, &(lower, upper)), &wraps)| {
            let value = values.iter().find(|(n, _)| n == name).map(|&(_, v)| v).ok_or_else(|| {
                RobotError::JointValue {
                    joint: name.clone(),
                    reason: "the request gives no value",
                    value: f64::NAN,
                }
            })?;
            if wraps && value.is_finite() {
                let turns = ((value + std::f64::consts::PI) / std::f64::consts::TAU).floor();
                return Ok((value - turns * std::f64::consts::TAU).clamp(lower, upper));
            }
            if value < lower - BOUNDS_TOLERANCE || value > upper + BOUNDS_TOLERANCE {
                return Err(RobotError::JointValue {
                    joint: name.clone(),
                    reason: "outside the joint's limits",
                    value,
                });
            }
            Ok(value.clamp(lower, upper))
        })
        .collect()
}

fn named(name: &Yaml, position: &Yaml) -> Result<(String, f64), RobotError> {
    let name = name.as_str().ok_or_else(|| invalid("joint", "a joint name"))?;
    let value = yaml::number(position).filter(|v| v.is_finite());
    let value = value.ok_or_else(|| RobotError::JointValue {
        joint: name.to_string(),
        reason: "not a finite number",
        value: f64::NAN,
    })?;
    Ok((name.to_string(), value))
}

fn invalid(element: &str, reason: &'static str) -> RobotError {
    RobotError::Invalid { element: element.to_string(), attribute: "value", reason, value: String::new() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::urdf::Urdf;

    #[test]
    fn joints_the_start_state_leaves_out_take_moveits_default() {
        let urdf = Urdf::parse(
            r#"<robot name="r">
              <link name="a"/><link name="b"/><link name="c"/><link name="d"/>
              <joint name="free" type="revolute"><parent link="a"/><child link="b"/><limit lower="-1" upper="1"/></joint>
              <joint name="bent" type="revolute"><parent link="b"/><child link="c"/><limit lower="-3" upper="-1"/></joint>
              <joint name="named" type="prismatic"><parent link="c"/><child link="d"/><limit lower="0.5" upper="0.7"/></joint>
            </robot>"#,
        )
        .unwrap();
        let robot = Robot::new(urdf).unwrap();
        let request = Request { start: vec![("named".into(), 0.6)], ..Request::default() };
        // 0 within the limits; the middle of limits that exclude 0; the state's own value.
        assert_eq!(request.start_values(&robot).unwrap(), [0.0, -2.0, 0.6]);
        let unknown = Request { start: vec![("elbow".into(), 0.0)], ..Request::default() };
        assert_eq!(unknown.start_values(&robot), Err(RobotError::UnknownJoint("elbow".into())));
    }
}
