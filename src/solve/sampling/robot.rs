//! The sampling planners over a robot world: the group's joint space (continuous joints
//! wrapping), checked by the batch or the scalar sphere checker.

use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use trailmark_core::geometry::SVector;
use trailmark_sample::{Joints, KdNearest, Validity};

use super::SamplingRun;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::PlannerSpec;
use crate::solve::problem::{ProblemSpec, RobotWorldSpec};
use crate::solve::result::SolveResult;
use crate::solve::settings::SamplingSpec;
use crate::solve::world::robot::{Checker, RobotWorld, robot_world};

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
    check_settings(spec)?;
    let (loaded, start, goal) = robot_world(problem, world, base_dir)?;
    loaded.plan_from(&problem.planner, spec, (&start, &goal), problem.seed.unwrap_or(0), None)
}

/// The settings a robot world refuses.
fn check_settings(spec: &SamplingSpec) -> Result<(), SolveError> {
    if spec.smooth.is_some() {
        return Err(DocumentError::NotForRobots { field: "smooth" }.into());
    }
    Ok(())
}

impl RobotWorld {
    /// Plans from `start` to `goal` (a value per group joint, checked by
    /// [`RobotWorld::ends`]) with the sampling planner `planner` and `seed`, as a document of
    /// this world would; setting `stop` (when given) stops the planner at its next iteration,
    /// as its limit would.
    ///
    /// ```
    /// use std::path::PathBuf;
    /// use trailmark::solve::{PlannerSpec, RobotSpec, RobotWorld, RobotWorldSpec, Status};
    ///
    /// let robot = RobotSpec {
    ///     urdf: "robot/arm.urdf".into(),
    ///     srdf: "robot/arm.srdf".into(),
    ///     group: Some("arm".into()),
    ///     checker: None,
    /// };
    /// let spec = RobotWorldSpec { robot, scene: Some(PathBuf::from("robot/shelf.yaml")) };
    /// let arm = RobotWorld::load(&spec, concat!(env!("CARGO_MANIFEST_DIR"), "/examples/problems"))?;
    /// let planner: PlannerSpec = serde_json::from_str(r#"{"name": "rrt_connect"}"#)?;
    /// let (start, goal) = ([1.2, 0.6, 1.2, 0.8], [-0.5, 0.9, 0.9, 0.3]);
    /// let plan = arm.plan(&planner, &start, &goal, 3, None)?;
    /// assert_eq!(plan.status, Status::Solved);
    /// // The forearm folded into the table:
    /// assert!(arm.checker().is_free(&start) && !arm.checker().is_free(&[0.0, 1.6, 0.0, 0.0]));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn plan(
        &self,
        planner: &PlannerSpec,
        start: &[f64],
        goal: &[f64],
        seed: u64,
        stop: Option<Arc<AtomicBool>>,
    ) -> Result<SolveResult, SolveError> {
        planner.check_limits()?;
        let spec =
            planner.sampling().ok_or(DocumentError::NotASamplingPlanner { planner: planner.name() })?;
        check_settings(spec)?;
        let (start, goal) = self.ends(start, goal)?;
        self.plan_from(planner, spec, (&start, &goal), seed, stop)
    }

    /// [`RobotWorld::plan`] between checked ends.
    fn plan_from(
        &self,
        planner: &PlannerSpec,
        spec: &SamplingSpec,
        ends: (&[f64], &[f64]),
        seed: u64,
        stop: Option<Arc<AtomicBool>>,
    ) -> Result<SolveResult, SolveError> {
        // A k-d tree over the joints' positions, 2N coordinates: a continuous joint's cosine
        // and sine, zeros after the others' values. One tree a joint count keeps the planners
        // compiled here to one for each.
        macro_rules! by_joints {
            ($($n:literal)*) => {
                match self.checker().group().joints.len() {
                    $($n => self.plan_in::<$n, { 2 * $n }>(planner, spec, ends, seed, stop),)*
                    found => Err(DocumentError::TooManyJoints { found }.into()),
                }
            };
        }
        by_joints!(1 2 3 4 5 6 7 8 9 10 11 12)
    }

    /// [`RobotWorld::plan_from`] for a group of `N` joints, its k-d positions in `D`
    /// coordinates.
    fn plan_in<const N: usize, const D: usize>(
        &self,
        planner: &PlannerSpec,
        spec: &SamplingSpec,
        (start, goal): (&[f64], &[f64]),
        seed: u64,
        stop: Option<Arc<AtomicBool>>,
    ) -> Result<SolveResult, SolveError> {
        let space = self.checker().joint_space::<N>()?;
        let nearest = KdNearest::<Joints<N>, D>::new(&space)?;
        let (start, goal) = (SVector::from_column_slice(start), SVector::from_column_slice(goal));
        // One planner for both checkers: a motion check takes microseconds, its call through
        // `dyn` nanoseconds.
        let checker: &dyn Validity<Joints<N>> = match &self.checker {
            Checker::Batch(batch) => batch,
            Checker::Scalar(checker) => checker,
        };
        let run =
            SamplingRun { planner, spec, checker: &checker, seed, smoothing_passes: SMOOTHING_PASSES, stop };
        let (result, _) = run.plan(&space, nearest, start, goal)?;
        Ok(result)
    }
}
