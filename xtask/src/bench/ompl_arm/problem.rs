//! OMPL's planners with FCL on one MotionBenchMaker problem, the outcome in the form of
//! trailmark's (`mbm::Outcome`), its path checked again by the same `f64` checker.

use std::time::Duration;

use crate::bench::ompl_arm::{ArmWorld, OmplArmDriver, OmplArmSettings};
use crate::mbm::{self, Arm, MbmProblem, Outcome, Prepared};

/// How OMPL plans a problem.
pub struct PeerRun {
    /// The driver's planner name.
    pub planner: &'static str,
    pub limit: Duration,
    /// The longest motion checked without a state between (`None`: MoveIt's).
    pub resolution: Option<f64>,
    pub simplify: bool,
    pub seed: u64,
    /// `prm_star`'s milestones (0 for the others).
    pub roadmap_size: usize,
}

/// OMPL's planner with FCL on `problem`, as MoveIt plans (its default motion resolution,
/// unless the run says another), with a range of 1 for RRTConnect like trailmark's runs (the
/// optimizing planners' default range otherwise); the path returned (simplified when asked)
/// checked again by the `f64` checker.
pub fn solve(driver: &OmplArmDriver, arm: &Arm, problem: &MbmProblem, run: PeerRun) -> Outcome {
    let prepared = match Prepared::new(arm, problem) {
        Ok(p) => p,
        Err(e) => return Outcome::failed(e.to_string()),
    };
    let group = prepared.scalar.group();
    let world = ArmWorld {
        robot: &arm.robot,
        srdf: &arm.srdf,
        group: &group.name,
        scene: &prepared.scene,
        template: &prepared.template,
    };
    let moveit = OmplArmSettings::moveit(group);
    let settings = OmplArmSettings {
        planner: run.planner,
        seed: run.seed,
        time_limit_s: run.limit.as_secs_f64(),
        simplify: run.simplify,
        resolution: run.resolution.unwrap_or(moveit.resolution),
        range: if run.planner == "rrt_connect" { moveit.range } else { 0.0 },
        roadmap_size: run.roadmap_size,
        ..moveit
    };
    let run = match driver.plan(&world, &prepared.start, &prepared.goal, settings.clone()) {
        Ok(runs) => match runs.into_iter().next() {
            Some(run) => run,
            None => return Outcome::failed("the driver returned no run".into()),
        },
        Err(e) => return Outcome::failed(e),
    };
    let exact = run.exact();
    let path = if run.simplified.is_empty() { run.path.clone() } else { run.simplified.clone() };
    let built = run.planner_built(settings.roadmap_size);
    Outcome {
        status: if exact {
            "solved"
        } else if built {
            "built"
        } else {
            "stopped"
        },
        time: Duration::from_secs_f64(run.time_s),
        simplify_time: Duration::from_secs_f64(run.simplify_time_s.unwrap_or(0.0)),
        planned_length: run.length.unwrap_or(0.0),
        length: run.simplified_length.or(run.length).unwrap_or(0.0),
        failure: exact
            .then(|| mbm::check_path(&prepared.reference, &path, &prepared.start, &prepared.goal))
            .flatten(),
        path,
        checks: run.checks,
        states: run.checks,
        joints: group.names.clone(),
    }
}
