//! Robot worlds as documents give them: the robot's URDF and SRDF, the planning group, the
//! scene around it, and the start and goal, as joint vectors or from a MoveIt request.

use std::path::Path;

use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::{ArmChecker, DEFAULT_STEP, Robot};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{ProblemSpec, RobotWorldSpec};

/// The most joints of a group a robot world plans for (each count is its own state type).
pub const MAX_GROUP_JOINTS: usize = 12;

/// A robot world read: the checker of its group among the scene (the joints outside the group
/// at the start state's values), and the group's start and goal.
pub(crate) struct RobotWorld {
    pub checker: ArmChecker,
    pub start: Vec<f64>,
    pub goal: Vec<f64>,
}

/// Reads the robot, the scene and the request of `problem`, their paths relative to
/// `base_dir` unless absolute, and checks the start and goal against the group.
pub(crate) fn robot_world(
    problem: &ProblemSpec,
    world: &RobotWorldSpec,
    base_dir: &Path,
) -> Result<RobotWorld, SolveError> {
    let request = match &problem.request {
        Some(_) if !problem.start.is_empty() || !problem.goal.is_empty() => {
            return Err(DocumentError::RequestAndEnds.into());
        }
        Some(path) => Some(Request::from_file(base_dir.join(path))?),
        None => None,
    };
    let group_name = match (&world.robot.group, &request) {
        (Some(world), Some(request)) if *world != request.group => {
            return Err(DocumentError::GroupMismatch {
                world: world.clone(),
                request: request.group.clone(),
            }
            .into());
        }
        (Some(name), _) => name.clone(),
        (None, Some(request)) => request.group.clone(),
        (None, None) => return Err(DocumentError::NoGroup.into()),
    };
    let robot = Robot::from_file(base_dir.join(&world.robot.urdf))?;
    let srdf = Srdf::from_file(base_dir.join(&world.robot.srdf))?;
    let scene = match &world.scene {
        Some(path) => Scene::from_file(base_dir.join(path))?,
        None => Scene::default(),
    };
    let group = robot.group(&srdf, &group_name)?;
    if group.joints.len() > MAX_GROUP_JOINTS {
        return Err(DocumentError::TooManyJoints { found: group.joints.len() }.into());
    }
    // Joint vectors become a request of the group's joints, so that both forms are checked
    // alike: limits with the request's tolerance, continuous joints brought into [-π, π].
    let request = match request {
        Some(request) => request,
        None => {
            let named = |which, values: &[f64]| {
                if values.is_empty() {
                    return Err(DocumentError::NoEnd(which));
                }
                if values.len() != group.names.len() || values.iter().any(|v| !v.is_finite()) {
                    return Err(DocumentError::NotAState { which, value: values.to_vec(), space: "joints" });
                }
                Ok(group.names.iter().cloned().zip(values.iter().copied()).collect())
            };
            let start = named("start", &problem.start)?;
            let goal = named("goal", &problem.goal)?;
            Request { group: group_name, start, goal }
        }
    };
    let template = request.start_values(&robot)?;
    let (start, goal) = request.ends(&group)?;
    let checker = ArmChecker::new(robot, &srdf, group, &scene, template, DEFAULT_STEP)?;
    Ok(RobotWorld { checker, start, goal })
}
