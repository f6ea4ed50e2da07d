//! Robot worlds as documents give them: the robot's URDF and SRDF, the planning group, the
//! scene around it, and the start and goal, as joint vectors or from a MoveIt request.

use std::path::Path;

use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::{ArmChecker, BatchChecker, DEFAULT_STEP, Robot};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{ArmCheckerKind, ProblemSpec, RobotWorldSpec};

/// The most joints of a group a robot world plans for (each count is its own state type).
pub const MAX_GROUP_JOINTS: usize = 12;

/// A robot world made ready for plans: the checker of its group among the scene, the joints
/// outside the group at their start values. A document builds it before its one plan; a
/// program that plans (or checks states) many times builds it once ([`RobotWorld::load`], then
/// [`RobotWorld::plan`]).
#[derive(Debug, Clone)]
pub struct RobotWorld {
    pub(crate) checker: BatchChecker,
    pub(crate) kind: ArmCheckerKind,
}

impl RobotWorld {
    /// The world of `spec` (its `group` required), its files read relative to `base_dir` unless
    /// absolute; the joints outside the group at their defaults (zero, or their limits' middle
    /// where zero is outside them).
    pub fn load(spec: &RobotWorldSpec, base_dir: impl AsRef<Path>) -> Result<Self, SolveError> {
        let group = spec.robot.group.as_ref().ok_or(DocumentError::NoGroup)?;
        RobotWorld::read(spec, base_dir.as_ref(), group, &[])
    }

    /// The world of `spec` for the group `group_name`, the joints outside it at the values of
    /// `start_state` or their defaults.
    fn read(
        spec: &RobotWorldSpec,
        base_dir: &Path,
        group_name: &str,
        start_state: &[(String, f64)],
    ) -> Result<Self, SolveError> {
        let robot = Robot::from_file(base_dir.join(&spec.robot.urdf))?;
        let srdf = Srdf::from_file(base_dir.join(&spec.robot.srdf))?;
        let scene = match &spec.scene {
            Some(path) => Scene::from_file(base_dir.join(path))?,
            None => Scene::default(),
        };
        let group = robot.group(&srdf, group_name)?;
        if group.joints.len() > MAX_GROUP_JOINTS {
            return Err(DocumentError::TooManyJoints { found: group.joints.len() }.into());
        }
        let template =
            Request { group: group_name.to_owned(), start: start_state.to_vec(), goal: Vec::new() }
                .start_values(&robot)?;
        let checker = ArmChecker::new(robot, &srdf, group, &scene, template, DEFAULT_STEP)?;
        Ok(RobotWorld { checker: BatchChecker::new(checker), kind: spec.robot.checker.unwrap_or_default() })
    }

    /// The checker of its group (one state or motion at a time).
    pub fn checker(&self) -> &ArmChecker {
        self.checker.checker()
    }

    /// The same checker over eight states at once (SIMD lanes where the processor has them).
    pub fn batch_checker(&self) -> &BatchChecker {
        &self.checker
    }

    /// Whether the group at `q` (a value per group joint) is free, by the checker this world
    /// plans with; `false` for a `q` of another length or not finite.
    pub fn is_free(&self, q: &[f64]) -> bool {
        match self.kind {
            ArmCheckerKind::Batch => self.checker.is_free(q),
            ArmCheckerKind::Scalar => self.checker().is_free(q),
        }
    }

    /// Whether the straight motion in joint space from `a` to `b` is free (continuous joints
    /// turning the short way), proven as the planners prove theirs, by the checker this world
    /// plans with.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        match self.kind {
            ArmCheckerKind::Batch => self.checker.motion_is_free(a, b),
            ArmCheckerKind::Scalar => self.checker().motion_is_free(a, b),
        }
    }

    /// `start` and `goal` (a value per group joint, in the group's order) checked as a request's
    /// are: within the limits or at most `trailmark_robot::request::BOUNDS_TOLERANCE` outside
    /// them, a continuous joint's angle brought into `[-π, π]`.
    pub fn ends(&self, start: &[f64], goal: &[f64]) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let group = self.checker().group();
        let named = |which, values: &[f64]| {
            if values.is_empty() {
                return Err(DocumentError::NoEnd(which));
            }
            if values.len() != group.names.len() || values.iter().any(|v| !v.is_finite()) {
                return Err(DocumentError::NotAState { which, value: values.to_vec(), space: "joints" });
            }
            Ok(group.names.iter().cloned().zip(values.iter().copied()).collect())
        };
        let request =
            Request { group: group.name.clone(), start: named("start", start)?, goal: named("goal", goal)? };
        Ok(request.ends(group)?)
    }
}

/// Reads the robot, the scene and the request of `problem`, their paths relative to
/// `base_dir` unless absolute, and checks the start and goal against the group: the world,
/// the start and the goal.
pub(crate) fn robot_world(
    problem: &ProblemSpec,
    world: &RobotWorldSpec,
    base_dir: &Path,
) -> Result<(RobotWorld, Vec<f64>, Vec<f64>), SolveError> {
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
    let start_state = request.as_ref().map_or(&[][..], |r| &r.start[..]);
    let loaded = RobotWorld::read(world, base_dir, &group_name, start_state)?;
    let (start, goal) = match request {
        Some(request) => request.ends(loaded.checker().group())?,
        None => loaded.ends(&problem.start, &problem.goal)?,
    };
    Ok((loaded, start, goal))
}
