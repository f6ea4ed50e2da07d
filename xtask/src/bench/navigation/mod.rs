//! The navigation section: a robot crosses a map it does not know (free-space prior, or a map
//! with walls wrong, or an obstacle following it; the cases are in `cases`), sensing a
//! square window around it, replanning at every step with A* from scratch, LPA*, D* Lite, AD*,
//! Adaptive A* and MPGAA*; the planning work of each is summed over the run, and each plan's
//! time is kept for the latency per step. A "trap" case puts an unseen
//! cup-shaped wall around the goal, the change D* Lite handles worst: it is discovered next to
//! the goal, the root of D* Lite's search.

use serde::Serialize;
use trailmark::navigate::{
    Navigation, NavigationOutcome, NavigationReport, Target, navigate, navigate_together,
};
use trailmark::solve::{AnytimeSpec, PlannerSpec};

use crate::bench::plots::{BoxSeries, COLOURS, box_plot_svg};
use crate::bench::progress::SectionProgress;
use crate::bench::report::{GoalRow, table};
use crate::bench::stats::{median, quantile, sorted};

mod cases;

pub use cases::{NavCase, nav_cases};

/// One planner's run on a navigation case (time: median over the rounds).
#[derive(Debug, Clone, Serialize)]
pub struct NavRow {
    /// The map.
    pub map: String,
    /// The sensor radius.
    pub radius: u32,
    /// The planner.
    pub planner: String,
    /// How the run ended.
    pub outcome: NavigationOutcome,
    /// Moves made.
    pub steps: usize,
    /// Cost of the trajectory.
    pub distance: f64,
    /// Expansions summed over every plan.
    pub expansions: u64,
    /// Planning time summed over every plan, milliseconds.
    pub planning_ms: f64,
    /// The longest single plan, milliseconds.
    pub max_plan_ms: f64,
    /// The median plan, microseconds.
    pub median_plan_us: f64,
    /// The 99th percentile of the plans, milliseconds.
    pub p99_plan_ms: f64,
    /// Expansions of each plan, in order.
    #[serde(skip)]
    pub plan_expansions: Vec<u64>,
}

/// D* Lite against A* from scratch on one case.
#[derive(Debug, Clone, Serialize)]
pub struct NavRatio {
    /// The map.
    pub map: String,
    /// The sensor radius.
    pub radius: u32,
    /// A* expansions / D* Lite expansions.
    pub expansions: f64,
    /// A* planning time / D* Lite planning time.
    pub time: f64,
    /// A*'s longest plan / D* Lite's longest plan.
    pub worst_plan: f64,
    /// Plans for which D* Lite expanded more nodes than A* from scratch.
    pub steps_lost: usize,
    /// Plans in the run.
    pub plans: usize,
    /// The largest D* Lite / A* expansion ratio of a single plan (above 1: D* Lite lost).
    pub worst_step: f64,
}

/// A replanner against A* from scratch on one case.
#[derive(Debug, Clone, Serialize)]
pub struct ReplannerRatio {
    /// The map.
    pub map: String,
    /// The sensor radius.
    pub radius: u32,
    /// The replanner.
    pub planner: String,
    /// A* planning time / the replanner's.
    pub time: f64,
    /// A*'s 99th-percentile plan / the replanner's.
    pub p99: f64,
    /// A* expansions / the replanner's.
    pub expansions: f64,
}

/// The AD* settings of the navigation runs: one iteration per step from epsilon 3 down.
const NAV_AD_STAR: PlannerSpec = PlannerSpec::AdStar(AnytimeSpec {
    epsilon: Some(3.0),
    epsilon_step: Some(0.5),
    heuristic: None,
    time_limit_s: None,
    max_expansions: Some(0),
});

/// The planner that drives the robot.
const DRIVER: PlannerSpec = PlannerSpec::DStarLite { heuristic: None };

/// The planners run along the trajectory of the driver, D* Lite.
const NAV_OTHERS: [PlannerSpec; 5] = [
    PlannerSpec::AStar { heuristic: None },
    PlannerSpec::LpaStar { heuristic: None },
    NAV_AD_STAR,
    PlannerSpec::AdaptiveAStar { heuristic: None },
    PlannerSpec::MpgaaStar { heuristic: None },
];

/// The registry's planners this section measures: the driver and those run along its trajectory.
pub fn measured() -> impl Iterator<Item = trailmark::solve::PlannerName> {
    std::iter::once(DRIVER).chain(NAV_OTHERS).map(|spec| spec.planner())
}

/// The planning work of the runs of one planner on one case: the rounds' reports, which differ
/// only in their times.
fn row(case: &NavCase, reports: &[&NavigationReport]) -> NavRow {
    // Each plan's time, its median over the rounds (every round makes the same plans).
    let plan_ms: Vec<f64> = (0..reports[0].plan_times.len())
        .map(|i| {
            let at: Vec<f64> =
                reports.iter().filter_map(|r| r.plan_times.get(i)).map(|t| t.as_secs_f64() * 1e3).collect();
            median(&sorted(at))
        })
        .collect();
    let plan_ms = sorted(plan_ms);
    let times = sorted(reports.iter().map(|r| r.planning_time.as_secs_f64() * 1e3).collect());
    let worst = sorted(reports.iter().map(|r| r.max_plan_time.as_secs_f64() * 1e3).collect());
    let r = reports[0];
    NavRow {
        map: case.name.clone(),
        radius: case.radius,
        planner: r.planner.clone(),
        outcome: r.outcome,
        steps: r.steps,
        distance: r.distance,
        expansions: r.expansions,
        planning_ms: median(&times),
        max_plan_ms: median(&worst),
        median_plan_us: median(&plan_ms) * 1e3,
        p99_plan_ms: quantile(&plan_ms, 0.99),
        plan_expansions: r.plan_expansions.clone(),
    }
}

/// The settings of a run of `case` driven by `planner`.
fn config(case: &NavCase, planner: PlannerSpec) -> Navigation {
    Navigation { planner, sensor_radius: case.radius, follower_lag: case.follower_lag, max_steps: None }
}

/// Runs every planner on every case, `runs` times (the runs are deterministic but for time).
/// D* Lite drives the robot; each other planner is run along its trajectory, planning from the
/// same cells with the same knowledge, so all of them solve exactly the same sequence of
/// problems. Then, on the free-space cases (every sensor radius), each planner drives a robot
/// of its own (the second list): among paths of equal cost each picks its own, so the robots
/// may part ways.
pub fn bench_navigation(cases: &[NavCase], runs: u32) -> Result<(Vec<NavRow>, Vec<NavRow>), String> {
    let own_cases: Vec<&NavCase> = cases.iter().filter(|c| !c.name.contains(' ')).collect();
    let mut progress = SectionProgress::new("navigation", cases.len() + own_cases.len());
    let mut rows = Vec::new();
    for case in cases {
        progress.step(format!("{} radius {}", case.name, case.radius));
        let config = config(case, DRIVER);
        let mut all: Vec<Vec<NavigationReport>> = Vec::new();
        for _ in 0..runs {
            let target = Target::Cell(case.goal);
            let run = navigate_together(&case.grid, &case.prior, case.start, target, &config, &NAV_OTHERS);
            all.push(run.map_err(|e| format!("{}: {e}", case.name))?);
        }
        for k in 0..=NAV_OTHERS.len() {
            let reports: Vec<&NavigationReport> = all.iter().map(|run| &run[k]).collect();
            rows.push(row(case, &reports));
        }
    }
    let mut own = Vec::new();
    for case in own_cases {
        progress.step(format!("{} radius {}, a robot each", case.name, case.radius));
        for planner in std::iter::once(DRIVER).chain(NAV_OTHERS) {
            let config = config(case, planner);
            let mut reports = Vec::new();
            for _ in 0..runs {
                let run = navigate(&case.grid, &case.prior, case.start, Target::Cell(case.goal), &config);
                reports.push(run.map_err(|e| format!("{}: {e}", case.name))?);
            }
            own.push(row(case, &reports.iter().collect::<Vec<_>>()));
        }
    }
    Ok((rows, own))
}

/// D* Lite against A* from scratch, per case.
pub fn nav_ratios(rows: &[NavRow]) -> Vec<NavRatio> {
    let find = |map: &str, radius: u32, planner: &str| {
        rows.iter().find(|r| r.map == map && r.radius == radius && r.planner == planner)
    };
    rows.iter()
        .filter(|r| r.planner == "astar")
        .filter_map(|a| {
            let d = find(&a.map, a.radius, "dstar_lite")?;
            let per_step: Vec<f64> = d
                .plan_expansions
                .iter()
                .zip(&a.plan_expansions)
                .map(|(&mine, &scratch)| mine as f64 / scratch.max(1) as f64)
                .collect();
            Some(NavRatio {
                steps_lost: per_step.iter().filter(|&&r| r > 1.0).count(),
                plans: per_step.len(),
                worst_step: per_step.iter().copied().fold(0.0, f64::max),
                map: a.map.clone(),
                radius: a.radius,
                expansions: a.expansions as f64 / d.expansions.max(1) as f64,
                time: a.planning_ms / d.planning_ms.max(1e-9),
                worst_plan: a.max_plan_ms / d.max_plan_ms.max(1e-9),
            })
        })
        .collect()
}

/// Every replanner against A* from scratch, per case.
pub fn replanner_ratios(rows: &[NavRow]) -> Vec<ReplannerRatio> {
    let astar = |map: &str, radius: u32| {
        rows.iter().find(|r| r.map == map && r.radius == radius && r.planner == "astar")
    };
    rows.iter()
        .filter(|r| r.planner != "astar")
        .filter_map(|r| {
            let a = astar(&r.map, r.radius)?;
            Some(ReplannerRatio {
                map: r.map.clone(),
                radius: r.radius,
                planner: r.planner.clone(),
                time: a.planning_ms / r.planning_ms.max(1e-9),
                p99: a.p99_plan_ms / r.p99_plan_ms.max(1e-9),
                expansions: a.expansions as f64 / r.expansions.max(1) as f64,
            })
        })
        .collect()
}

/// The replanner with the least planning time on each case, in the order of the cases.
pub fn best_replanners(ratios: &[ReplannerRatio]) -> Vec<&ReplannerRatio> {
    let mut best: Vec<&ReplannerRatio> = Vec::new();
    for r in ratios {
        match best.iter_mut().find(|b| b.map == r.map && b.radius == r.radius) {
            Some(b) if b.time < r.time => *b = r,
            Some(_) => {}
            None => best.push(r),
        }
    }
    best
}

/// The planners of the time plot (the exact ones), in the order of their colours.
const PLOTTED: [&str; 5] = ["astar", "lpa_star", "dstar_lite", "adaptive_astar", "mpgaa_star"];

/// The plot of total planning time per map family: for each map a box per exact planner over
/// its runs with the sensor radii of the section.
pub fn time_svg(rows: &[NavRow]) -> Result<String, String> {
    let mut maps: Vec<String> = Vec::new();
    for r in rows {
        if !maps.contains(&r.map) {
            maps.push(r.map.clone());
        }
    }
    let series: Vec<BoxSeries> = PLOTTED
        .iter()
        .zip(COLOURS)
        .map(|(&planner, colour)| BoxSeries {
            name: planner.to_string(),
            colour,
            values: maps
                .iter()
                .map(|m| {
                    rows.iter()
                        .filter(|r| &r.map == m && r.planner == planner)
                        .map(|r| r.planning_ms)
                        .collect()
                })
                .collect(),
        })
        .collect();
    box_plot_svg(
        "Unknown terrain: total planning time of a run (box over sensor radii)",
        "milliseconds",
        &maps,
        &series,
    )
}

/// The goals of the best replanner: never slower than A* from scratch, and the aim of 3x.
pub fn best_goals(ratios: &[ReplannerRatio]) -> [GoalRow; 2] {
    let figures: Vec<(String, f64)> = best_replanners(ratios)
        .iter()
        .map(|b| (format!("{} radius {}, {}", b.map, b.radius, b.planner), b.time))
        .collect();
    let missing = "the navigation section did not run";
    [
        GoalRow {
            goal: "the best replanner never slower in total planning time than A* from scratch",
            figures: figures.clone(),
            target: 1.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "the best replanner at least 3x less total planning time than A* from scratch",
            figures,
            target: 3.0,
            unit: "x",
            missing,
        },
    ]
}

/// Whether D* Lite's goal of total time covers the case: the mazes and the trap, with a
/// free-space prior.
fn dstar_lite_family(r: &NavRatio) -> bool {
    (r.map.starts_with("maze") || r.map.starts_with("trap")) && !r.map.contains(' ')
}

/// D* Lite's goals for the report's goals table: at least 5x less total planning time than A*
/// from scratch on the mazes and the trap, and its worst plan within 3x of A*'s worst plan on
/// every map (A*'s worst / D* Lite's worst at least 1/3).
pub fn goals(ratios: &[NavRatio]) -> [GoalRow; 2] {
    let missing = "the navigation section did not run";
    let case = |r: &NavRatio| format!("{} radius {}", r.map, r.radius);
    [
        GoalRow {
            goal: "D* Lite at least 5x less total planning time than A* from scratch on mazes and the trap",
            figures: ratios.iter().filter(|r| dstar_lite_family(r)).map(|r| (case(r), r.time)).collect(),
            target: 5.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "D* Lite's worst plan within 3x of A*'s worst (A*'s worst / D* Lite's at least 0.33)",
            figures: ratios.iter().map(|r| (case(r), r.worst_plan)).collect(),
            target: 1.0 / 3.0,
            unit: "x",
            missing,
        },
    ]
}

/// The header of the columns every table of runs starts with (along the shared trajectory, or
/// each planner driving its own robot).
const RUN_HEADER: &str = "| map | radius | planner | outcome | steps | distance | expansions | planning ms |";
/// Their alignment.
const RUN_ALIGN: &str = "|---|---:|---|---|---:|---:|---:|---:|";

/// A run's cells in those columns.
fn run_cells(r: &NavRow) -> String {
    format!(
        "| {} | {} | {} | {:?} | {} | {:.1} | {} | {:.2} |",
        r.map, r.radius, r.planner, r.outcome, r.steps, r.distance, r.expansions, r.planning_ms
    )
}

/// The section of the report.
pub fn markdown(
    nav: &[NavRow],
    own: &[NavRow],
    ratios: &[NavRatio],
    replanners: &[ReplannerRatio],
) -> String {
    let mut out = String::new();
    if !nav.is_empty() {
        out.push_str("## Unknown-terrain navigation\n\n");
        out.push_str(
            "8-connected, sensing a square window of the given radius; a free-space prior, or (`partial`) the \
             true map with 15% of its walls missing and 3% of its free cells blocked by phantom walls that go \
             when seen, or (`follower`) a free-space prior and an obstacle 3 steps behind the robot. D* Lite drives the \
             robot; A*, LPA* (restarted at every step, as the start moves), AD* (one iteration per step, \
             epsilon 3 down by 0.5), Adaptive A* and MPGAA* are each run along that trajectory, planning from the same cells with the same knowledge (one planner at a time, so none runs with caches filled by another). Planning work \
             summed over the run (time: median over rounds); the latency of a step is the time of its plan \
             (the first plan includes making the planner).\n\n",
        );
        out.push_str(&table(
            &format!("{RUN_HEADER} median plan µs | p99 plan ms | worst plan ms |"),
            &format!("{RUN_ALIGN}---:|---:|---:|"),
            nav,
            |r| {
                format!(
                    "{} {:.1} | {:.3} | {:.3} |",
                    run_cells(r),
                    r.median_plan_us,
                    r.p99_plan_ms,
                    r.max_plan_ms
                )
            },
        ));
        out.push_str("\n![total planning time of each exact planner per map, over the sensor radii](navigation-time.svg)\n");
        out.push_str("\n### Every replanner against A* from scratch (goal: the best at least 1x everywhere, aim 3x)\n\n");
        out.push_str(
            "Total planning time, 99th-percentile plan and expansions of A* from scratch divided by each \
             replanner's (above 1: the replanner is faster). The best per case is in bold.\n\n",
        );
        let best = best_replanners(replanners);
        out.push_str(&table(
            "| map | radius | planner | time A* / it | p99 plan A* / it | expansions A* / it |",
            "|---|---:|---|---:|---:|---:|",
            replanners,
            |r| {
                let bold = if best.iter().any(|b| std::ptr::eq(*b, r)) { "**" } else { "" };
                format!(
                    "| {} | {} | {bold}{}{bold} | {bold}{:.2}x{bold} | {:.2}x | {:.1}x |",
                    r.map, r.radius, r.planner, r.time, r.p99, r.expansions
                )
            },
        ));
        if !own.is_empty() {
            out.push_str("\n### Each planner driving a robot of its own\n\n");
            out.push_str(
                "The free-space cases, each planner moving its own robot along its own \
                 plans: among paths of equal cost each picks its own, so trajectories, distances and the \
                 problems planned may differ.\n\n",
            );
            out.push_str(&table(
                &format!("{RUN_HEADER} p99 plan ms |"),
                &format!("{RUN_ALIGN}---:|"),
                own,
                |r| format!("{} {:.3} |", run_cells(r), r.p99_plan_ms),
            ));
        }
        out.push_str("\n### D* Lite against A* from scratch (goals: 5x less time on mazes and the trap, the worst plan within 3x of A*'s)\n\n");
        out.push_str(
            "Where incremental search loses: the plans for which D* Lite expanded more nodes than A* from \
             scratch, and the worst such plan (D* Lite expansions / A* expansions).\n\n",
        );
        out.push_str(&table(
            "| map | radius | expansions A* / D* Lite | time A* / D* Lite | worst plan time A* / D* Lite | plans D* Lite lost | worst plan D* Lite / A* expansions | 5x time | worst plan |",
            "|---|---:|---:|---:|---:|---:|---:|---|---|",
            ratios,
            |r| {
                let time = if !dstar_lite_family(r) {
                    "-"
                } else if r.time >= 5.0 {
                    "met"
                } else {
                    "**not met**"
                };
                let worst = if r.worst_plan >= 1.0 / 3.0 { "met" } else { "**not met**" };
                format!(
                    "| {} | {} | {:.1}x | {:.1}x | {:.2}x | {} of {} | {:.1}x | {time} | {worst} |",
                    r.map, r.radius, r.expansions, r.time, r.worst_plan, r.steps_lost, r.plans, r.worst_step
                )
            },
        ));
        out.push('\n');
    }
    out
}
