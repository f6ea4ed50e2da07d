//! The sampling planners over a robot world: the group's joint space (continuous joints
//! wrapping), checked by the batch or the scalar sphere checker.

use std::path::Path;

use trailmark_core::geometry::SVector;
use trailmark_robot::BatchChecker;
use trailmark_sample::{Joints, KdNearest, Validity};

use super::SamplingRun;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::SamplingSpec;
use crate::solve::problem::{ArmCheckerKind, ProblemSpec, RobotWorldSpec};
use crate::solve::result::SolveResult;
use crate::solve::world::robot::{RobotWorld, robot_world};

/// Corner-cutting passes after shortcutting when `simplify` is asked for: on the Panda's
/// problems two take most of what more would (docs/arms.md).
pub const SMOOTHING_PASSES: usize = 2;

/// Solves a sampling-planner problem over a robot world.
pub(in crate::solve) fn solve_robot(
    problem: &ProblemSpec,
    world: &RobotWorldSpec,
    spec: &SamplingSpec,
    base_dir: &Path,
) -> Result<SolveResult, SolveError> {
    let planner = problem.planner.name();
    if let Some(&field) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForPlanner { field, planner }.into());
    }
    if problem.space.is_some() {
        return Err(DocumentError::NotForRobots { field: "space" }.into());
    }
    if spec.smooth.is_some() {
        return Err(DocumentError::NotForRobots { field: "smooth" }.into());
    }
    let loaded = robot_world(problem, world, base_dir)?;
    let kind = world.robot.checker.unwrap_or_default();
    let group = loaded.checker.group();
    // A k-d tree over the joints' positions, 2N coordinates: a continuous joint's cosine and
    // sine, zeros after the others' values. One tree a joint count keeps the planners compiled
    // here to one for each.
    macro_rules! by_joints {
        ($($n:literal)*) => {
            match group.joints.len() {
                $($n => plan::<$n, { 2 * $n }>(problem, spec, &loaded, kind),)*
                found => Err(DocumentError::TooManyJoints { found }.into()),
            }
        };
    }
    by_joints!(1 2 3 4 5 6 7 8 9 10 11 12)
}

/// [`solve_robot`] for a group of `N` joints, its k-d positions in `D` coordinates.
fn plan<const N: usize, const D: usize>(
    problem: &ProblemSpec,
    spec: &SamplingSpec,
    world: &RobotWorld,
    kind: ArmCheckerKind,
) -> Result<SolveResult, SolveError> {
    let space = world.checker.joint_space::<N>()?;
    let nearest = KdNearest::<Joints<N>, D>::new(&space)?;
    let (start, goal) = (SVector::from_column_slice(&world.start), SVector::from_column_slice(&world.goal));
    let seed = problem.seed.unwrap_or(0);
    // One planner for both checkers: a motion check takes microseconds, its call through
    // `dyn` nanoseconds.
    let batch;
    let checker: &dyn Validity<Joints<N>> = match kind {
        ArmCheckerKind::Batch => {
            batch = BatchChecker::new(world.checker.clone());
            &batch
        }
        ArmCheckerKind::Scalar => &world.checker,
    };
    let run = SamplingRun {
        problem,
        spec,
        checker: &checker,
        seed,
        smoothing_passes: SMOOTHING_PASSES,
        stop: None,
    };
    let (result, _) = run.plan(&space, nearest, start, goal)?;
    Ok(result)
}
