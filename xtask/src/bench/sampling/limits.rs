//! Time limits kept: every sampling planner on problems it cannot solve, under a time limit,
//! and how far past the limit each run returned (the goal: under 1 ms). The problems make each
//! inner loop long: a goal walled off in the plane (RRT-Connect's connect phase, RRT*'s
//! rewiring, a bridge sampler that tries up to 100,000 times per sample), a 6-joint arm space
//! whose motions are checked densely (long motion checks, RRT*'s hundreds of neighbours), and a
//! start far outside the joint limits (refused before planning).

use std::f64::consts::PI;
use std::time::{Duration, Instant};

use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::core::world::CollisionChecker;
use trailmark::sample::benchmark::benchmark;
use trailmark::sample::{
    BitStar, Bridge, InformedRrtStar, KdNearest, Planner, Prm, Problem, R2, Rn, Rrt, RrtConnect, RrtStar,
    Sampled, StateSpace, Validity,
};

use crate::bench::stats::upper_median;

/// A configuration of the six joints.
type Joints = <Rn<6> as StateSpace>::State;

/// The time limit of every run.
pub const LIMIT: Duration = Duration::from_millis(25);

/// Runs per planner and problem.
const RUNS: usize = 5;

/// One planner on one problem.
#[derive(Debug, Clone, Serialize)]
pub struct LimitRow {
    /// The problem.
    pub problem: String,
    /// The planner.
    pub planner: String,
    /// Runs.
    pub runs: usize,
    /// The median time of a run, ms.
    pub median_ms: f64,
    /// The largest time past the limit, ms.
    pub largest_overshoot_ms: f64,
    /// What the runs ended with: `time limit`, or the error that refused the problem.
    pub ended: String,
}

/// `planners` on `problem`, each measured.
fn measure<S, V>(
    name: &str,
    problem: &Problem<'_, S, V>,
    planners: Vec<Box<dyn Planner<S, V> + '_>>,
    seed: u64,
) -> Vec<LimitRow>
where
    S: StateSpace,
    V: Validity<S>,
{
    let limit = Termination::time(LIMIT);
    let mut rows = Vec::new();
    for mut planner in planners {
        let label = planner.name().to_string();
        let clock = Instant::now();
        let row = match benchmark(planner.as_mut(), problem, &limit, RUNS, seed, None) {
            Ok(runs) => LimitRow {
                problem: name.into(),
                planner: label,
                runs: RUNS,
                median_ms: upper_median(runs.runs.iter().map(|r| r.time_s * 1e3).collect()),
                largest_overshoot_ms: runs.largest_overshoot_s() * 1e3,
                ended: if runs.runs.iter().any(|r| r.solved) { "solved".into() } else { "time limit".into() },
            },
            Err(e) => LimitRow {
                problem: name.into(),
                planner: label,
                runs: 1,
                median_ms: clock.elapsed().as_secs_f64() * 1e3,
                largest_overshoot_ms: 0.0,
                ended: format!("refused: {e}"),
            },
        };
        rows.push(row);
    }
    rows
}

/// Every planner on the three problems.
pub fn bench_limits(seed: u64) -> Result<Vec<LimitRow>, String> {
    let err = |e: &dyn std::fmt::Display| format!("limits: {e}");
    let mut rows = Vec::new();
    // The plane: the goal walled off.
    let (world, _) = trailmark::core::generate::walled_goal(0.2).map_err(|e| err(&e))?;
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let kd = KdNearest::<R2, 2>::new(&space).map_err(|e| err(&e))?;
    let bridge = Bridge::new(1.0)
        .and_then(|b| b.with_share(1.0))
        .and_then(|b| b.with_attempts(trailmark::sample::sampler::MAX_ATTEMPTS))
        .map_err(|e| err(&e))?;
    let problem = Problem::new(&space, &checker, Point::new(2.0, 2.0), Point::new(15.0, 15.0));
    let planners: Vec<Box<dyn Planner<R2, CollisionChecker>>> = vec![
        Box::new(Rrt::new(kd.clone())),
        Box::new(RrtConnect::new(kd.clone())),
        Box::new(RrtConnect::new(kd.clone()).with_sampler(bridge)),
        Box::new(RrtStar::new(kd.clone())),
        Box::new(InformedRrtStar::new(kd.clone())),
        Box::new(BitStar::new(kd.clone())),
        Box::new(Prm::new(kd.clone())),
        Box::new(Prm::star(kd.clone())),
        Box::new(Prm::lazy(kd.clone())),
        Box::new(Prm::lazy_star(kd)),
    ];
    let mut plane = measure("R2, goal walled off", &problem, planners, seed);
    // The bridge RRT-Connect is named apart from the uniform one.
    plane[2].planner = "RRT-Connect (bridge, 100,000 attempts)".into();
    rows.extend(plane);
    // Six joints with limits of ±π; the first joint may not cross [-0.1, 0.1], so the goal on
    // the other side is out of reach; motions checked every 1e-4 of the extent.
    let arm = Rn::<6>::new([-PI; 6], [PI; 6]).map_err(|e| err(&e))?;
    let validity = Sampled::new(|q: &Joints| q[0].abs() > 0.1, 1e-4).map_err(|e| err(&e))?;
    let kd = KdNearest::<Rn<6>, 6>::new(&arm).map_err(|e| err(&e))?;
    let planners = || -> Vec<Box<dyn Planner<Rn<6>, _>>> {
        vec![
            Box::new(Rrt::new(kd.clone())),
            Box::new(RrtConnect::new(kd.clone())),
            Box::new(RrtStar::new(kd.clone())),
            Box::new(InformedRrtStar::new(kd.clone())),
            Box::new(BitStar::new(kd.clone())),
            Box::new(Prm::new(kd.clone())),
            Box::new(Prm::star(kd.clone())),
            Box::new(Prm::lazy(kd.clone())),
            Box::new(Prm::lazy_star(kd.clone())),
        ]
    };
    let (start, goal) = (Joints::from([-1.0; 6]), Joints::from([1.0; 6]));
    let problem = Problem::new(&arm, &validity, start, goal);
    rows.extend(measure("R6 arm, joint 1 walled, motions every 1e-4", &problem, planners(), seed));
    // The start of the defect report: [1e6; 6] with joint limits of ±π.
    let problem = Problem::new(&arm, &validity, Joints::from([1e6; 6]), goal);
    rows.extend(measure("R6 arm, start [1e6; 6]", &problem, planners(), seed));
    Ok(rows)
}

/// The table.
pub fn markdown(rows: &[LimitRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "### Time limits kept ({} ms limit, {RUNS} runs each)\n\n\
         Problems without a solution, so every run lasts until the limit; the overshoot is the time \
         past the limit, measured around `solve`. Goal: under 1 ms.\n\n\
         | problem | planner | runs | median run (ms) | largest overshoot (ms) | ended |\n|---|---|---:|---:|---:|---|\n",
        LIMIT.as_millis()
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {:.2} | {:.3} | {} |\n",
            r.problem, r.planner, r.runs, r.median_ms, r.largest_overshoot_ms, r.ended
        ));
    }
    let worst = rows.iter().map(|r| r.largest_overshoot_ms).fold(0.0, f64::max);
    s.push_str(&format!(
        "\nLargest overshoot over all runs: {worst:.3} ms (goal: under 1 ms): {}.\n\n",
        if worst < 1.0 { "met" } else { "not met" }
    ));
    s
}
