//! The arms section: the Panda arm on MotionBenchMaker's problems (`../shared/mbm/panda`, when
//! present), planned by RRT-Connect with the batch checker and with the scalar one, each path
//! simplified and checked again by the `f64` checker at a tenth of the step; beside OMPL's
//! RRTConnect with FCL on the same spheres and primitives when `--with-ompl` builds it.
//! The quick suite plans four problems a set, the full one all 700.

mod optimal;

use std::path::PathBuf;
use std::time::Duration;

use serde::Serialize;

use crate::bench::ompl_arm::OmplArmDriver;
use crate::bench::ompl_arm::problem::{self, PeerRun};
use crate::bench::progress::SectionProgress;
use crate::bench::report::{GoalRow, table};
use crate::bench::stats::{median, quantile, sorted};
use crate::bench::suite::Suite;
use crate::mbm::{self, Arm, ArmPlanner, CheckerKind, MbmProblem, Outcome, Settings};
use optimal::{ArmRoadmapRow, OptimalArmRow};

/// Each problem's time limit, in both libraries.
const LIMIT: Duration = Duration::from_secs(1);

/// The Panda's files and problems, beside the project.
fn panda() -> PathBuf {
    crate::workspace::root().join("../shared/mbm/panda")
}

/// One planner and checker over the problems planned.
#[derive(Debug, Clone, Serialize)]
pub struct ArmRow {
    /// `trailmark batch`, `trailmark scalar` or `OMPL RRTConnect + FCL`.
    planner: String,
    problems: usize,
    /// Solved within the time limit, the path passing the independent check.
    solved: usize,
    /// Paths returned that failed the independent check (must be 0 for trailmark's; OMPL's
    /// discrete motion checks may pass through obstacles between their states).
    pub check_failures: usize,
    /// Planning time, µs: median and 95th percentile over the problems (those not solved, or
    /// whose path fails the check, at the time limit).
    median_us: f64,
    p95_us: f64,
    /// The median of the planning times as measured, every problem at its own time (what the
    /// goal compares: a returned path that fails the check is not charged the limit).
    timed_median_us: f64,
    /// Planning and simplifying, µs.
    simplified_median_us: f64,
    simplified_p95_us: f64,
    /// trailmark's validity calls (states and motions) per second of planning.
    checks_per_s: Option<f64>,
    /// States tested per second of planning (`None` where not counted).
    states_per_s: Option<f64>,
    /// Median joint-space path length, radians: as planned, and simplified.
    length: f64,
    simplified_length: f64,
}

/// One set's figures with the batch checker.
#[derive(Debug, Clone, Serialize)]
pub struct ArmSetRow {
    set: String,
    problems: usize,
    solved: usize,
    median_us: f64,
    simplified_median_us: f64,
}

/// The section's figures.
#[derive(Debug, Clone, Serialize, Default)]
pub struct ArmReport {
    pub rows: Vec<ArmRow>,
    sets: Vec<ArmSetRow>,
    /// The optimizing planners beside OMPL's (with `--with-ompl`).
    optimal: Vec<OptimalArmRow>,
    /// PRM*'s roadmaps beside OMPL's (with `--with-ompl`).
    roadmaps: Vec<ArmRoadmapRow>,
    /// Why the section did not run, when it did not.
    skipped: Option<String>,
    /// The versions of OMPL and FCL, when they ran.
    peer: Option<String>,
}

impl ArmReport {
    /// trailmark's paths that failed the independent check.
    pub fn errors(&self) -> usize {
        let tree: usize =
            self.rows.iter().filter(|r| r.planner.starts_with("trailmark")).map(|r| r.check_failures).sum();
        let optimal: usize = self.optimal.iter().filter(|r| r.is_trailmark()).map(|r| r.check_failures).sum();
        tree + optimal + self.roadmaps.first().map_or(0, |r| r.check_failures)
    }
}

/// The problems of the suite: every 25th of each set in the quick suite, all in the full one.
fn chosen(suite: Suite, all: Vec<MbmProblem>) -> Vec<MbmProblem> {
    let every = match suite {
        Suite::Quick => 25,
        Suite::Full => 1,
    };
    all.into_iter().enumerate().filter(|(i, _)| i % every == 0).map(|(_, p)| p).collect()
}

/// The name of the OMPL rows: checking motions every 0.5 % of the extent (MoveIt's fraction),
/// and every 5 mrad.
const OMPL: &str = "OMPL RRTConnect + FCL";
const OMPL_FINE: &str = "OMPL RRTConnect + FCL, 5 mrad";
/// The finer resolution of OMPL's motion checks, radians.
const FINE: f64 = 0.005;

/// Plans the suite's problems with both checkers, and with OMPL and FCL when `driver` is given;
/// a report that says why when the data is missing.
pub fn bench(suite: Suite, seed: u64, driver: Option<&OmplArmDriver>) -> Result<ArmReport, String> {
    let dir = panda();
    let (urdf, srdf) = (dir.join("panda_spherized.urdf"), dir.join("panda.srdf"));
    if !urdf.is_file() {
        let why = format!("{} not found", dir.display());
        errln!("arms section skipped: {why}");
        return Ok(ArmReport { skipped: Some(why), ..ArmReport::default() });
    }
    let arm = Arm::read(&urdf, &srdf).map_err(|e| e.to_string())?;
    let all = mbm::problems(&dir.join("problems"))?;
    let optimal_problems = optimal::chosen(suite, &all);
    let problems = chosen(suite, all);
    let runs = if driver.is_some() { 4 } else { 2 };
    let optimal_runs = if driver.is_some() { optimal::runs(optimal_problems.len()) } else { 0 };
    let mut progress = SectionProgress::new("arms", runs * problems.len() + optimal_runs);
    let mut rows = Vec::new();
    let mut batch_outcomes = Vec::new();
    for (checker, name) in
        [(CheckerKind::Batch, "trailmark batch"), (CheckerKind::Scalar, "trailmark scalar")]
    {
        let settings = Settings {
            planner: ArmPlanner::RrtConnect,
            checker,
            limit: LIMIT,
            seed,
            range: Some(1.0),
            simplify: true,
        };
        let outcomes: Vec<Outcome> = problems
            .iter()
            .map(|p| {
                progress.step(format!("{name}: {}", p.name));
                mbm::solve(&arm, p, settings)
            })
            .collect();
        rows.push(row(name, &outcomes));
        if checker == CheckerKind::Batch {
            batch_outcomes = outcomes;
        }
    }
    if let Some(driver) = driver {
        for (name, resolution) in [(OMPL, None), (OMPL_FINE, Some(FINE))] {
            let outcomes: Vec<Outcome> = problems
                .iter()
                .map(|p| {
                    progress.step(format!("{name}: {}", p.name));
                    let run = PeerRun {
                        planner: "rrt_connect",
                        limit: LIMIT,
                        resolution,
                        simplify: true,
                        seed,
                        roadmap_size: 0,
                    };
                    problem::solve(driver, &arm, p, run)
                })
                .collect();
            rows.push(row(name, &outcomes));
        }
    }
    let optimal =
        driver.map(|d| optimal::bench(&arm, &optimal_problems, seed, d, &mut progress)).unwrap_or_default();
    let roadmaps = driver
        .map(|d| optimal::roadmaps(&arm, &optimal_problems, seed, d, &mut progress))
        .unwrap_or_default();
    let set_of = |p: &MbmProblem| p.name.split('/').next().unwrap_or_default().to_string();
    let mut names: Vec<String> = problems.iter().map(set_of).collect();
    names.dedup();
    let sets = names
        .into_iter()
        .map(|set| {
            let of_set: Vec<&Outcome> = problems
                .iter()
                .zip(&batch_outcomes)
                .filter(|(p, _)| set_of(p) == set)
                .map(|(_, o)| o)
                .collect();
            let charged = |o: &Outcome, t: Duration| if passed(o) { t } else { LIMIT.max(o.time) };
            let times = sorted(of_set.iter().map(|o| charged(o, o.time).as_secs_f64() * 1e6).collect());
            let simplified = sorted(
                of_set.iter().map(|o| charged(o, o.time + o.simplify_time).as_secs_f64() * 1e6).collect(),
            );
            ArmSetRow {
                set,
                problems: of_set.len(),
                solved: of_set.iter().filter(|o| passed(o)).count(),
                median_us: median(&times),
                simplified_median_us: median(&simplified),
            }
        })
        .collect();
    let peer = driver.map(|d| format!("OMPL {}, FCL {}", d.ompl_version, d.fcl_version));
    Ok(ArmReport { rows, sets, optimal, roadmaps, skipped: None, peer })
}

/// Whether the problem was solved and its path passed the independent check.
fn passed(o: &Outcome) -> bool {
    o.status == "solved" && o.failure.is_none()
}

fn row(planner: &str, outcomes: &[Outcome]) -> ArmRow {
    // OMPL counts the states it checks; trailmark its validity calls, and the batch checker
    // the states it tested.
    let ompl = planner.starts_with("OMPL");
    // Problems not solved, or whose path fails the check, count at the time limit.
    let charged = |o: &Outcome, t: Duration| if passed(o) { t } else { LIMIT.max(o.time) };
    let times = sorted(outcomes.iter().map(|o| charged(o, o.time).as_secs_f64() * 1e6).collect());
    let simplified =
        sorted(outcomes.iter().map(|o| charged(o, o.time + o.simplify_time).as_secs_f64() * 1e6).collect());
    let planning: f64 = outcomes.iter().map(|o| o.time.as_secs_f64()).sum();
    let checks: u64 = outcomes.iter().map(|o| o.checks).sum();
    let states: u64 = outcomes.iter().map(|o| o.states).sum();
    let solved: Vec<&Outcome> = outcomes.iter().filter(|o| passed(o)).collect();
    ArmRow {
        planner: planner.to_string(),
        problems: outcomes.len(),
        solved: solved.len(),
        check_failures: outcomes.iter().filter(|o| o.status == "solved" && o.failure.is_some()).count(),
        median_us: median(&times),
        p95_us: quantile(&times, 0.95),
        timed_median_us: median(&sorted(outcomes.iter().map(|o| o.time.as_secs_f64() * 1e6).collect())),
        simplified_median_us: median(&simplified),
        simplified_p95_us: quantile(&simplified, 0.95),
        checks_per_s: (!ompl).then(|| checks as f64 / planning.max(1e-9)),
        states_per_s: (states > 0).then(|| states as f64 / planning.max(1e-9)),
        length: median(&sorted(solved.iter().map(|o| o.planned_length).collect())),
        simplified_length: median(&sorted(solved.iter().map(|o| o.length).collect())),
    }
}

/// The section's goals: the median against 100 µs, and the batch checker against the others.
pub fn goals(report: Option<&ArmReport>) -> Vec<GoalRow> {
    let rows = report.map_or(&[][..], |r| &r.rows[..]);
    let batch = rows.iter().find(|r| r.planner == "trailmark batch");
    let mut figures = Vec::new();
    let mut speedups = Vec::new();
    if let Some(b) = batch {
        figures.push(("Panda, median over the problems".to_string(), 100.0 / b.median_us));
        for other in rows.iter().filter(|r| r.planner != b.planner) {
            speedups.push((other.planner.clone(), other.timed_median_us / b.timed_median_us));
        }
    }
    let mut goals = vec![
        GoalRow {
            goal: "A Panda MotionBenchMaker problem planned in at most 100 µs (median; 100 µs / median)",
            figures,
            target: 1.0,
            unit: "x",
            missing: "the arms section did not run (needs ../shared/mbm)",
        },
        GoalRow {
            goal: "The batch checker's RRT-Connect at least 100x OMPL RRTConnect with FCL (median planning time as measured)",
            figures: speedups.into_iter().filter(|(name, _)| name == OMPL).collect(),
            target: 100.0,
            unit: "x",
            missing: "run with --with-ompl (libompl-dev, libfcl-dev)",
        },
    ];
    goals.extend(optimal::goals(
        report.map_or(&[][..], |r| &r.optimal[..]),
        report.map_or(&[][..], |r| &r.roadmaps[..]),
    ));
    goals
}

/// The section of the report.
pub fn markdown(report: &ArmReport) -> String {
    if let Some(why) = &report.skipped {
        return format!("\n## Robot arms\n\nSkipped: {why}.\n");
    }
    let mut out = String::from(
        "\n## Robot arms\n\nThe Panda (59 spheres) on MotionBenchMaker's problems, RRT-Connect (range 1 rad, 1 s limit per \
         problem), each path checked again by the `f64` sphere checker at a tenth of the 1 mm step; times on one core, the \
         simplified ones including the planning, problems not solved or whose path fails the check at the limit (\"as \
         timed\": each at its own time). Checks are validity calls (states and motions), states the configurations \
         tested. OMPL (with `--with-ompl`): RRTConnect with FCL on the same spheres and primitives, motions checked at \
         states every 0.5% of the joint space's Euclidean extent (MoveIt's fraction, 0.067 rad for the Panda; MoveIt \
         measures the extent as a sum over the joints, a coarser step) and every 5 mrad; a motion may cross an obstacle \
         between its states, which the check failures count; simplified by `simplifySolution`. The goal is measured \
         against the first.\n\n",
    );
    if let Some(peer) = &report.peer {
        out.push_str(&format!("Peer: {peer}.\n\n"));
    }
    out.push_str(&table(
        "| planner | problems | solved | check failures | median µs | p95 µs | median µs as timed | simplified median µs | simplified p95 µs | checks/s | states/s | length (rad) | simplified length |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
        &report.rows,
        |r| {
            format!(
                "| {} | {} | {} | {} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} | {} | {} | {:.2} | {:.2} |",
                r.planner,
                r.problems,
                r.solved,
                r.check_failures,
                r.median_us,
                r.p95_us,
                r.timed_median_us,
                r.simplified_median_us,
                r.simplified_p95_us,
                r.checks_per_s.map_or("-".to_string(), |c| format!("{c:.0}")),
                r.states_per_s.map_or("-".to_string(), |s| format!("{s:.0}")),
                r.length,
                r.simplified_length
            )
        },
    ));
    out.push_str("\nPer set, the batch checker:\n\n");
    out.push_str(&table(
        "| set | problems | solved | median µs | simplified median µs |",
        "|---|---:|---:|---:|---:|",
        &report.sets,
        |s| {
            format!(
                "| {} | {} | {} | {:.0} | {:.0} |",
                s.set, s.problems, s.solved, s.median_us, s.simplified_median_us
            )
        },
    ));
    out.push_str(&optimal::markdown(&report.optimal, &report.roadmaps));
    out
}
