//! The navigation section: a robot crosses a map it does not know (free-space prior), sensing a
//! square window around it, replanning at every step with A* from scratch, LPA*, D* Lite, AD*,
//! Adaptive A* and MPGAA*; the planning work of each is summed over the run, and each plan's
//! time is kept for the latency per step. A "trap" case puts an unseen
//! cup-shaped wall around the goal, the change D* Lite handles worst: it is discovered next to
//! the goal, the root of D* Lite's search.

use std::path::Path;

use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::generate;
use trailmark::movingai;
use trailmark::navigate::{Navigation, NavigationOutcome, NavigationReport, Target, navigate_together};
use trailmark::prelude::*;
use trailmark::solve::{AnytimeSpec, PlannerSpec};

use crate::bench::plots::{BoxSeries, COLOURS, box_plot_svg};
use crate::bench::progress::SectionProgress;
use crate::bench::report::GoalRow;
use crate::bench::stats::{median, quantile, sorted};
use crate::bench::suite::Suite;
use crate::region::endpoints;

/// One navigation problem: a map, a start and a goal, a sensor radius.
pub struct NavCase {
    name: String,
    grid: Grid,
    start: Cell,
    goal: Cell,
    radius: u32,
}

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

/// The planners run along the trajectory of the driver, D* Lite.
const NAV_OTHERS: [PlannerSpec; 5] = [
    PlannerSpec::AStar { heuristic: None },
    PlannerSpec::LpaStar { heuristic: None },
    NAV_AD_STAR,
    PlannerSpec::AdaptiveAStar { heuristic: None },
    PlannerSpec::MpgaaStar { heuristic: None },
];

/// The MovingAI maps of the navigation section: two games (Dragon Age, Baldur's Gate) and a city.
const NAV_MOVINGAI: [(&str, &str); 3] =
    [("dao", "brc202d"), ("bg512", "AR0011SR"), ("cities", "Berlin_0_512")];

/// A map whose goal sits in a cup-shaped wall that opens away from the start: the robot sees
/// the wall only when it arrives next to the goal.
fn trap(size: usize) -> (Grid, Cell, Cell) {
    let mut grid = Grid::new(size, size).expect("a valid size");
    let (c, r) = (size as u32 * 3 / 4, size as u32 / 8);
    let goal = Cell::new(c, size as u32 / 2);
    for d in 0..=2 * r {
        for cell in [
            Cell::new(goal.x - r, goal.y - r + d), // the side facing the start
            Cell::new(goal.x - r + d, goal.y - r), // top
            Cell::new(goal.x - r + d, goal.y + r), // bottom
        ] {
            grid.set_blocked(cell, true).expect("inside");
        }
    }
    (grid, Cell::new(size as u32 / 16, size as u32 / 2), goal)
}

/// The navigation cases of a suite, one map of each family: generated random maps (10%, 25%
/// and 40% obstacles), rooms, mazes with corridors 1, 4 and 32 cells wide (3/8 of the size: a
/// robot in an unknown maze walks far), the trap, and the MovingAI maps when the folder is
/// there; each with sensor radius 1, 5 and 10. The maps of the first version of the section
/// (random 25% and 40%, the trap, the MovingAI maps) keep their start and goal.
pub fn nav_cases(suite: Suite, seed: u64, movingai_dir: Option<&Path>) -> Result<Vec<NavCase>, String> {
    let size = match suite {
        Suite::Quick => 256,
        Suite::Full => 512,
    };
    let mut rng = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed ^ 0x6e61_7669);
    let mut later = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed ^ 0x6661_6d69);
    let mut maps: Vec<(String, Grid, Cell, Cell)> = Vec::new();
    let mut add = |name: String, grid: Result<Grid, generate::GenerateError>, rng: &mut ChaCha8Rng| {
        let grid = grid.map_err(|e| e.to_string())?;
        let (start, goal) = endpoints(&grid, rng).ok_or("an empty map")?;
        maps.push((name, grid, start, goal));
        Ok::<(), String>(())
    };
    for density in [10, 25, 40] {
        let grid = generate::random(size, size, f64::from(density) / 100.0, seed);
        let rng = if density == 10 { &mut later } else { &mut rng };
        add(format!("random{size}-{density}-s{seed}"), grid, rng)?;
    }
    add(format!("rooms{size}-16-s{seed}"), generate::rooms(size, size, 16, seed), &mut later)?;
    let small = size * 3 / 8;
    for corridor in [1, 4, 32] {
        let grid = generate::maze(small, small, corridor, seed);
        add(format!("maze{small}-{corridor}-s{seed}"), grid, &mut later)?;
    }
    let (grid, start, goal) = trap(size);
    maps.push((format!("trap{size}"), grid, start, goal));
    if let Some(dir) = movingai_dir {
        let chosen: &[(&str, &str)] = match suite {
            Suite::Quick => &NAV_MOVINGAI[..1],
            Suite::Full => &NAV_MOVINGAI,
        };
        for (set, name) in chosen {
            let path = dir.join("maps").join(set).join(format!("{name}.map"));
            let grid = movingai::read_map(&path).map_err(|e| e.to_string())?;
            let (start, goal) = endpoints(&grid, &mut rng).ok_or("an empty map")?;
            maps.push((name.to_string(), grid, start, goal));
        }
    }
    let mut cases = Vec::new();
    for (name, grid, start, goal) in maps {
        for radius in [1, 5, 10] {
            cases.push(NavCase { name: name.clone(), grid: grid.clone(), start, goal, radius });
        }
    }
    Ok(cases)
}

/// Runs every planner on every case, `runs` times (the runs are deterministic but for time).
/// D* Lite drives the robot; each other planner is run along its trajectory, planning from the same cells with the
/// same knowledge, so all of them solve exactly the same sequence of problems.
pub fn bench_navigation(cases: &[NavCase], runs: u32) -> Result<Vec<NavRow>, String> {
    let mut rows = Vec::new();
    let mut progress = SectionProgress::new("navigation", cases.len());
    for case in cases {
        progress.step(format!("{} radius {}", case.name, case.radius));
        let prior =
            Grid::new(case.grid.width() as usize, case.grid.height() as usize).map_err(|e| e.to_string())?;
        let config = Navigation {
            planner: PlannerSpec::DStarLite { heuristic: None },
            sensor_radius: case.radius,
            follower_lag: None,
            max_steps: None,
        };
        let mut all: Vec<Vec<NavigationReport>> = Vec::new();
        for _ in 0..runs {
            all.push(
                navigate_together(
                    &case.grid,
                    &prior,
                    case.start,
                    Target::Cell(case.goal),
                    &config,
                    &NAV_OTHERS,
                )
                .map_err(|e| format!("{}: {e}", case.name))?,
            );
        }
        for k in 0..=NAV_OTHERS.len() {
            let reports: Vec<&NavigationReport> = all.iter().map(|run| &run[k]).collect();
            // Each plan's time, its median over the rounds (every round makes the same plans).
            let plan_ms: Vec<f64> = (0..reports[0].plan_times.len())
                .map(|i| {
                    let at: Vec<f64> = reports
                        .iter()
                        .filter_map(|r| r.plan_times.get(i))
                        .map(|t| t.as_secs_f64() * 1e3)
                        .collect();
                    median(&sorted(at))
                })
                .collect();
            let plan_ms = sorted(plan_ms);
            let mut times: Vec<f64> = reports.iter().map(|r| r.planning_time.as_secs_f64() * 1e3).collect();
            times.sort_by(f64::total_cmp);
            let mut worst: Vec<f64> = reports.iter().map(|r| r.max_plan_time.as_secs_f64() * 1e3).collect();
            worst.sort_by(f64::total_cmp);
            let r = reports[0];
            rows.push(NavRow {
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
            });
        }
    }
    Ok(rows)
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
                    rows.iter().filter(|r| &r.map == m && r.planner == planner).map(|r| r.planning_ms).collect()
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

/// The goal of the section for the report's goals table.
pub fn goal(ratios: &[NavRatio]) -> GoalRow {
    GoalRow {
        goal: "D* Lite at least 5x less planning time than A* from scratch in unknown terrain",
        figures: ratios.iter().map(|r| (format!("{} radius {}", r.map, r.radius), r.time)).collect(),
        target: 5.0,
        unit: "x",
        missing: "the navigation section did not run",
    }
}

/// The section of the report.
pub fn markdown(nav: &[NavRow], ratios: &[NavRatio], replanners: &[ReplannerRatio]) -> String {
    let mut out = String::new();
    if !nav.is_empty() {
        out.push_str("## Unknown-terrain navigation\n\n");
        out.push_str(
            "Free-space prior, 8-connected, sensing a square window of the given radius. D* Lite drives the \
             robot; A*, LPA* (restarted at every step, as the start moves), AD* (one iteration per step, \
             epsilon 3 down by 0.5), Adaptive A* and MPGAA* are each run along that trajectory, planning from the same cells with the same knowledge (one planner at a time, so none runs with caches filled by another). Planning work \
             summed over the run (time: median over rounds); the latency of a step is the time of its plan \
             (the first plan includes making the planner).\n\n",
        );
        out.push_str("| map | radius | planner | outcome | steps | distance | expansions | planning ms | median plan µs | p99 plan ms | worst plan ms |\n");
        out.push_str("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for r in nav {
            out.push_str(&format!(
                "| {} | {} | {} | {:?} | {} | {:.1} | {} | {:.2} | {:.1} | {:.3} | {:.3} |\n",
                r.map,
                r.radius,
                r.planner,
                r.outcome,
                r.steps,
                r.distance,
                r.expansions,
                r.planning_ms,
                r.median_plan_us,
                r.p99_plan_ms,
                r.max_plan_ms
            ));
        }
        out.push_str("\n![total planning time of each exact planner per map, over the sensor radii](navigation-time.svg)\n");
        out.push_str("\n### Every replanner against A* from scratch (goal: the best at least 1x everywhere, aim 3x)\n\n");
        out.push_str(
            "Total planning time, 99th-percentile plan and expansions of A* from scratch divided by each \
             replanner's (above 1: the replanner is faster). The best per case is in bold.\n\n",
        );
        out.push_str("| map | radius | planner | time A* / it | p99 plan A* / it | expansions A* / it |\n");
        out.push_str("|---|---:|---|---:|---:|---:|\n");
        let best = best_replanners(replanners);
        for r in replanners {
            let bold = if best.iter().any(|b| std::ptr::eq(*b, r)) { "**" } else { "" };
            out.push_str(&format!(
                "| {} | {} | {bold}{}{bold} | {bold}{:.2}x{bold} | {:.2}x | {:.1}x |\n",
                r.map, r.radius, r.planner, r.time, r.p99, r.expansions
            ));
        }
        out.push_str("\n### D* Lite against A* from scratch (goal: 10x fewer expansions, 5x less time)\n\n");
        out.push_str(
            "Where incremental search loses: the plans for which D* Lite expanded more nodes than A* from \
             scratch, and the worst such plan (D* Lite expansions / A* expansions).\n\n",
        );
        out.push_str("| map | radius | expansions A* / D* Lite | time A* / D* Lite | worst plan time A* / D* Lite | plans D* Lite lost | worst plan D* Lite / A* expansions | goal |\n");
        out.push_str("|---|---:|---:|---:|---:|---:|---:|---|\n");
        for r in ratios {
            let met = if r.expansions >= 10.0 && r.time >= 5.0 { "met" } else { "**not met**" };
            out.push_str(&format!(
                "| {} | {} | {:.1}x | {:.1}x | {:.1}x | {} of {} | {:.1}x | {met} |\n",
                r.map, r.radius, r.expansions, r.time, r.worst_plan, r.steps_lost, r.plans, r.worst_step
            ));
        }
        out.push('\n');
    }
    out
}
