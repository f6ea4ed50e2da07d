//! Robot worlds as documents give them: the robot's URDF and SRDF, the planning group, the
//! scene around it, and the start and goal, as joint vectors or from a MoveIt request.

use std::path::Path;

use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::{ArmChecker, BatchChecker, DEFAULT_STEP, Group, Robot};

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
    pub(crate) checker: Checker,
}

/// The checker a robot world plans with, as its document names it.
#[derive(Debug, Clone)]
pub(crate) enum Checker {
    /// Eight states at once in `f32` lanes.
    Batch(BatchChecker),
    /// One state at a time in `f64`.
    Scalar(ArmChecker),
}

/// What a robot world is read from: the robot, its SRDF, the scene and the planning group.
struct Parts {
    robot: Robot,
    srdf: Srdf,
    scene: Scene,
    group: Group,
}

impl Parts {
    /// The files of `spec`, relative to `base_dir` unless absolute, and the group `group_name`.
    fn read(spec: &RobotWorldSpec, base_dir: &Path, group_name: &str) -> Result<Self, SolveError> {
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
        Ok(Parts { robot, srdf, scene, group })
    }

    /// The world, the joints outside the group at the values of `start_state` or their
    /// defaults, checked by `kind`.
    fn build(self, kind: ArmCheckerKind, start_state: &[(String, f64)]) -> Result<RobotWorld, SolveError> {
        let Parts { robot, srdf, scene, group } = self;
        let template = Request { group: group.name.clone(), start: start_state.to_vec(), goal: Vec::new() }
            .start_values(&robot)?;
        let checker = ArmChecker::new(robot, &srdf, group, &scene, template, DEFAULT_STEP)?;
        let checker = match kind {
            ArmCheckerKind::Batch => Checker::Batch(BatchChecker::new(checker)),
            ArmCheckerKind::Scalar => Checker::Scalar(checker),
        };
        Ok(RobotWorld { checker })
    }
}

impl RobotWorld {
    /// The world of `spec` (its `group` required), its files read relative to `base_dir` unless
    /// absolute; the joints outside the group at their defaults (zero, or their limits' middle
    /// where zero is outside them).
    pub fn load(spec: &RobotWorldSpec, base_dir: impl AsRef<Path>) -> Result<Self, SolveError> {
        let group = spec.robot.group.as_ref().ok_or(DocumentError::NoGroup)?;
        Parts::read(spec, base_dir.as_ref(), group)?.build(spec.robot.checker.unwrap_or_default(), &[])
    }

    /// The `f64` checker of its group (the batch checker, where the world plans with it, is
    /// compiled from this one).
    pub fn checker(&self) -> &ArmChecker {
        match &self.checker {
            Checker::Batch(batch) => batch.checker(),
            Checker::Scalar(checker) => checker,
        }
    }

    /// Whether the group at `q` (a value per group joint) is free, by the checker this world
    /// plans with; `false` for a `q` of another length, not finite, or beyond the joints'
    /// limits (a continuous joint's are `[-π, π]`).
    pub fn is_free(&self, q: &[f64]) -> bool {
        match &self.checker {
            // The batch checker refuses states beyond the limits itself.
            Checker::Batch(batch) => batch.is_free(q),
            Checker::Scalar(checker) => checker.group().within_limits(q) && checker.is_free(q),
        }
    }

    /// [`RobotWorld::is_free`] for each of `states`, into `free` (the batch checker tests
    /// eight different states at once).
    pub fn are_free<'a>(&self, states: impl IntoIterator<Item = &'a [f64]>, free: &mut Vec<bool>) {
        match &self.checker {
            Checker::Batch(batch) => batch.are_free(states, free),
            Checker::Scalar(_) => {
                free.clear();
                free.extend(states.into_iter().map(|q| self.is_free(q)));
            }
        }
    }

    /// Whether the straight motion in joint space from `a` to `b` is free (continuous joints
    /// turning the short way), proven as the planners prove theirs, by the checker this world
    /// plans with; `false` when an end is not a state within the limits.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        match &self.checker {
            Checker::Batch(batch) => batch.motion_is_free(a, b),
            Checker::Scalar(checker) => {
                let group = checker.group();
                group.within_limits(a) && group.within_limits(b) && checker.motion_is_free(a, b)
            }
        }
    }

    /// `start` and `goal` (a value per group joint, in the group's order) checked as a request's
    /// are: within the limits or at most `trailmark_robot::request::BOUNDS_TOLERANCE` outside
    /// them, a continuous joint's angle brought into `[-π, π]`.
    pub fn ends(&self, start: &[f64], goal: &[f64]) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let group = self.checker().group();
        Ok(vector_request(group, start, goal)?.ends(group)?)
    }
}

/// The request of joint vectors `start` and `goal` (a value per joint of `group`, in its
/// order), so that both forms of a problem's ends are checked alike.
fn vector_request(group: &Group, start: &[f64], goal: &[f64]) -> Result<Request, DocumentError> {
    let named = |which, values: &[f64]| {
        if values.is_empty() {
            return Err(DocumentError::NoEnd(which));
        }
        if values.len() != group.names.len() || values.iter().any(|v| !v.is_finite()) {
            return Err(DocumentError::NotAState { which, value: values.to_vec(), space: "joints" });
        }
        Ok(group.names.iter().cloned().zip(values.iter().copied()).collect())
    };
    Ok(Request { group: group.name.clone(), start: named("start", start)?, goal: named("goal", goal)? })
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
    let parts = Parts::read(world, base_dir, &group_name)?;
    // The ends before the checker, which takes milliseconds to build.
    let request = match request {
        Some(request) => request,
        None => vector_request(&parts.group, &problem.start, &problem.goal)?,
    };
    let (start, goal) = request.ends(&parts.group)?;
    let loaded = parts.build(world.robot.checker.unwrap_or_default(), &request.start)?;
    Ok((loaded, start, goal))
}
