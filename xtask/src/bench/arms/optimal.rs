//! The optimizing planners on the arm problems (with `--with-ompl`): trailmark's Informed RRT*
//! and BIT* with the batch checker beside OMPL's InformedRRTstar and BITstar with FCL, each
//! run for the same time on the same problems (spread over MotionBenchMaker's sets), without
//! simplification; the joint-space length each reaches, every path checked again by the `f64`
//! checker at a tenth of the step (a path that fails it counts as none). And PRM*'s roadmap
//! built in each problem's scene beside OMPL's PRMstar's.

use std::time::Duration;

use serde::Serialize;

use crate::bench::ompl_arm::OmplArmDriver;
use crate::bench::ompl_arm::problem::{self, PeerRun};
use crate::bench::progress::SectionProgress;
use crate::bench::report::{GoalRow, table};
use crate::bench::stats::{median, sorted};
use crate::bench::suite::Suite;
use crate::mbm::{self, Arm, ArmPlanner, CheckerKind, MbmProblem, Outcome, ROADMAP_SIZE, Settings};

/// Each run's time, in both libraries.
pub const LIMIT: Duration = Duration::from_secs(1);

/// The planners compared: trailmark's, the driver's name, trailmark's label, OMPL's label.
const PLANNERS: [(ArmPlanner, &str, &str, &str); 2] = [
    (ArmPlanner::InformedRrtStar, "informed_rrt_star", "Informed RRT*", "InformedRRTstar"),
    (ArmPlanner::BitStar, "bit_star", "BIT*", "BITstar"),
];

/// One planner of one library over the problems.
#[derive(Debug, Clone, Serialize)]
pub struct OptimalArmRow {
    /// `Informed RRT*` or `BIT*`.
    planner: String,
    /// `trailmark batch` or `OMPL + FCL`.
    library: String,
    problems: usize,
    /// Problems with a path by the limit that passed the independent check.
    solved: usize,
    /// Paths returned that failed the independent check.
    pub check_failures: usize,
    /// Median joint-space length over the problems both libraries solved, radians.
    median_length: f64,
    /// trailmark's rows: the median over the problems of OMPL's length over trailmark's (a
    /// problem one library did not solve at an infinite length; those neither solved left
    /// out); at least 1 when trailmark's paths are no longer.
    ratio: Option<f64>,
}

impl OptimalArmRow {
    /// Whether the row is trailmark's.
    pub fn is_trailmark(&self) -> bool {
        self.ratio.is_some() || self.library.starts_with("trailmark")
    }
}

/// The problems planned: every 100th of the 700 in the quick suite (one of each set), every
/// 20th in the full one.
pub fn chosen(suite: Suite, all: &[MbmProblem]) -> Vec<MbmProblem> {
    let every = match suite {
        Suite::Quick => 100,
        Suite::Full => 20,
    };
    all.iter().step_by(every).cloned().collect()
}

/// How many runs [`bench()`] makes: two libraries, each planner and PRM*, each problem.
pub fn runs(problems: usize) -> usize {
    2 * (PLANNERS.len() + 1) * problems
}

/// The longest a roadmap's build may take, in both libraries.
const BUILD_LIMIT: Duration = Duration::from_secs(20);

/// PRM*'s roadmap of [`ROADMAP_SIZE`] milestones in each problem's scene, by one library.
#[derive(Debug, Clone, Serialize)]
pub struct ArmRoadmapRow {
    /// `trailmark batch` or `OMPL + FCL`.
    library: String,
    problems: usize,
    /// Roadmaps with every milestone within the limit.
    built: usize,
    /// trailmark's roadmaps whose path between the problem's ends failed the check.
    pub check_failures: usize,
    /// Median build time, ms (a build stopped by the limit at the limit).
    median_ms: f64,
    /// trailmark's row: the median over the problems of OMPL's build time over trailmark's.
    speedup: Option<f64>,
}

/// Whether a roadmap was built whole (and its path, when it holds one, passed the check).
fn built(o: &Outcome) -> bool {
    (o.status == "built" || o.status == "solved") && o.failure.is_none()
}

/// The build time charged: the limit when the roadmap was not built whole.
fn build_ms(o: &Outcome) -> f64 {
    if built(o) { o.time.as_secs_f64() * 1e3 } else { BUILD_LIMIT.as_secs_f64() * 1e3 }
}

/// What [`run_both`] runs: trailmark's planner and OMPL's, their labels, the limit of each
/// run and PRMstar's milestones (0 for the others).
struct Both {
    planner: ArmPlanner,
    peer: &'static str,
    label: &'static str,
    peer_label: &'static str,
    limit: Duration,
    roadmap_size: usize,
}

/// trailmark's runs (batch checker, no simplification) and then OMPL's, problem by problem.
fn run_both(
    (arm, problems, seed, driver): (&Arm, &[MbmProblem], u64, &OmplArmDriver),
    progress: &mut SectionProgress,
    both: Both,
) -> (Vec<Outcome>, Vec<Outcome>) {
    let settings = Settings {
        planner: both.planner,
        checker: CheckerKind::Batch,
        limit: both.limit,
        seed,
        range: None,
        simplify: false,
    };
    let ours = problems
        .iter()
        .map(|p| {
            progress.step(format!("{}: {}", both.label, p.name));
            mbm::solve(arm, p, settings)
        })
        .collect();
    let theirs = problems
        .iter()
        .map(|p| {
            progress.step(format!("OMPL {}: {}", both.peer_label, p.name));
            let run = PeerRun {
                planner: both.peer,
                limit: both.limit,
                resolution: None,
                simplify: false,
                seed,
                roadmap_size: both.roadmap_size,
            };
            problem::solve(driver, arm, p, run)
        })
        .collect();
    (ours, theirs)
}

/// PRM*'s roadmaps in both libraries, problem by problem.
pub fn roadmaps(
    arm: &Arm,
    problems: &[MbmProblem],
    seed: u64,
    driver: &OmplArmDriver,
    progress: &mut SectionProgress,
) -> Vec<ArmRoadmapRow> {
    let (ours, theirs) = run_both(
        (arm, problems, seed, driver),
        progress,
        Both {
            planner: ArmPlanner::PrmStar,
            peer: "prm_star",
            label: "PRM* roadmap",
            peer_label: "PRMstar roadmap",
            limit: BUILD_LIMIT,
            roadmap_size: ROADMAP_SIZE,
        },
    );
    let speedups = sorted(ours.iter().zip(&theirs).map(|(a, b)| build_ms(b) / build_ms(a)).collect());
    let row = |library: &str, outcomes: &[Outcome], speedup: Option<f64>| ArmRoadmapRow {
        library: library.to_string(),
        problems: outcomes.len(),
        built: outcomes.iter().filter(|o| built(o)).count(),
        check_failures: outcomes.iter().filter(|o| o.status == "solved" && o.failure.is_some()).count(),
        median_ms: median(&sorted(outcomes.iter().map(build_ms).collect())),
        speedup,
    };
    let speedup = (!speedups.is_empty()).then(|| median(&speedups));
    vec![row("trailmark batch", &ours, speedup), row("OMPL + FCL", &theirs, None)]
}

/// The length a run reached, infinite without a checked path.
fn reached(o: &Outcome) -> f64 {
    if o.status == "solved" && o.failure.is_none() { o.planned_length } else { f64::INFINITY }
}

/// Both libraries' optimizing planners on `problems`, each run for [`LIMIT`].
pub fn bench(
    arm: &Arm,
    problems: &[MbmProblem],
    seed: u64,
    driver: &OmplArmDriver,
    progress: &mut SectionProgress,
) -> Vec<OptimalArmRow> {
    let mut rows = Vec::new();
    for (planner, name, label, peer_label) in PLANNERS {
        let (ours, theirs) = run_both(
            (arm, problems, seed, driver),
            progress,
            Both { planner, peer: name, label, peer_label, limit: LIMIT, roadmap_size: 0 },
        );
        let ratios: Vec<f64> = ours
            .iter()
            .zip(&theirs)
            .map(|(a, b)| (reached(b), reached(a)))
            .filter(|(b, a)| a.is_finite() || b.is_finite())
            .map(|(b, a)| b / a)
            .collect();
        let ratio = (!ratios.is_empty()).then(|| median(&sorted(ratios)));
        // Lengths compared over the same problems: those both solved.
        let both: Vec<(f64, f64)> = ours
            .iter()
            .zip(&theirs)
            .map(|(a, b)| (reached(a), reached(b)))
            .filter(|(a, b)| a.is_finite() && b.is_finite())
            .collect();
        let (mine, peer): (Vec<f64>, Vec<f64>) = both.into_iter().unzip();
        rows.push(row(label, "trailmark batch", &ours, mine, ratio));
        rows.push(row(peer_label, "OMPL + FCL", &theirs, peer, None));
    }
    rows
}

fn row(
    planner: &str,
    library: &str,
    outcomes: &[Outcome],
    common: Vec<f64>,
    ratio: Option<f64>,
) -> OptimalArmRow {
    OptimalArmRow {
        planner: planner.to_string(),
        library: library.to_string(),
        problems: outcomes.len(),
        solved: outcomes.iter().filter(|o| reached(o).is_finite()).count(),
        check_failures: outcomes.iter().filter(|o| o.status == "solved" && o.failure.is_some()).count(),
        median_length: if common.is_empty() { f64::NAN } else { median(&sorted(common)) },
        ratio,
    }
}

/// The goals: each planner's length at equal time no worse than OMPL's; PRM*'s build at least
/// twice as fast.
pub fn goals(rows: &[OptimalArmRow], roadmaps: &[ArmRoadmapRow]) -> Vec<GoalRow> {
    let figure = |planner: &str| -> Vec<(String, f64)> {
        rows.iter()
            .filter(|r| r.planner == planner)
            .filter_map(|r| r.ratio.map(|x| (format!("Panda, {} problems", r.problems), x)))
            .collect()
    };
    vec![
        GoalRow {
            goal: "Informed RRT*'s path on the Panda problems no longer than OMPL InformedRRTstar's with FCL at equal time (median of OMPL's length / trailmark's)",
            figures: figure("Informed RRT*"),
            target: 1.0,
            unit: "x",
            missing: "run with --with-ompl (libompl-dev, libfcl-dev) and ../shared/mbm",
        },
        GoalRow {
            goal: "BIT*'s path on the Panda problems no longer than OMPL BITstar's with FCL at equal time (median of OMPL's length / trailmark's)",
            figures: figure("BIT*"),
            target: 1.0,
            unit: "x",
            missing: "run with --with-ompl (libompl-dev, libfcl-dev) and ../shared/mbm",
        },
        GoalRow {
            goal: "PRM*'s roadmap in the Panda's scenes built at least 2x faster than OMPL PRMstar's with FCL (median over the problems)",
            figures: roadmaps
                .iter()
                .filter_map(|r| r.speedup.map(|x| (format!("Panda, {} problems", r.problems), x)))
                .collect(),
            target: 2.0,
            unit: "x",
            missing: "run with --with-ompl (libompl-dev, libfcl-dev) and ../shared/mbm",
        },
    ]
}

/// The tables, empty without rows.
pub fn markdown(rows: &[OptimalArmRow], roadmaps: &[ArmRoadmapRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = format!(
        "\nThe optimizing planners, each run for {} s on the same problems (spread over the sets), paths not \
         simplified, trailmark with the batch checker, OMPL with FCL (motions checked at MoveIt's resolution), both at \
         their default range (a fifth of the extent) and batch size (100); median lengths in radians over the \
         problems both solved. OMPL / trailmark is the median over the problems of OMPL's length over trailmark's (a problem not \
         solved at an infinite length).\n\n",
        LIMIT.as_secs_f64()
    );
    out.push_str(&table(
        "| planner | library | problems | solved | check failures | median length, both solved (rad) | OMPL / trailmark |",
        "|---|---|---:|---:|---:|---:|---:|",
        rows,
        |r| {
            format!(
                "| {} | {} | {} | {} | {} | {:.3} | {} |",
                r.planner,
                r.library,
                r.problems,
                r.solved,
                r.check_failures,
                r.median_length,
                r.ratio.map_or("-".to_string(), |x| format!("{x:.3}"))
            )
        },
    ));
    out.push_str(&format!(
        "\nPRM*'s roadmap of {ROADMAP_SIZE} milestones in each problem's scene (at most {} s), built from the same \
         checkers; trailmark's then asked the problem's query, its path checked. OMPL / trailmark is the median over \
         the problems of OMPL's build time over trailmark's.\n\n",
        BUILD_LIMIT.as_secs()
    ));
    out.push_str(&table(
        "| library | problems | built | check failures | median build ms | OMPL / trailmark |",
        "|---|---:|---:|---:|---:|---:|",
        roadmaps,
        |r| {
            format!(
                "| {} | {} | {} | {} | {:.1} | {} |",
                r.library,
                r.problems,
                r.built,
                r.check_failures,
                r.median_ms,
                r.speedup.map_or("-".to_string(), |x| format!("{x:.2}x"))
            )
        },
    ));
    out
}
