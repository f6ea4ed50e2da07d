//! The asymptotically optimal planners side by side at equal time on each polygon world's
//! RRT* query: RRT*, Informed RRT* and BIT*, seeded runs of [`TIME`] each, their final cost over the
//! optimum and their median best cost over time (the curves of OMPL's Planner Arena). The
//! goal: within 1% of the optimum in 0.1 s.

use std::time::Duration;

use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::core::world::CollisionChecker;
use trailmark::sample::benchmark::{PlannerRuns, benchmark};
use trailmark::sample::{BitStar, InformedRrtStar, KdNearest, Planner, Problem, R2, RrtStar};
use trailmark::solve::PlannerName;

use crate::bench::plots::COLOURS;
use crate::bench::report::GoalRow;
use crate::bench::sampling::star::{CostLine, cost_at, lines_svg};
use crate::bench::sampling::world::SamplingWorld;
use crate::bench::stats::{median, sorted};

/// The planners of the table, in its order.
pub const MEASURED: [PlannerName; 3] =
    [PlannerName::RrtStar, PlannerName::InformedRrtStar, PlannerName::BitStar];
/// The time of every run.
pub const TIME: Duration = Duration::from_millis(100);
/// The goal: the median final cost at most this over the optimum.
const GOAL: f64 = 1.01;
/// Where the curves read the best cost, seconds.
const TIMES: [f64; 6] = [0.002, 0.005, 0.01, 0.02, 0.05, 0.1];

/// One planner on one world's query.
#[derive(Debug, Clone, Serialize)]
pub struct OptimalRow {
    /// The world.
    pub world: String,
    /// The planner's document name.
    pub planner: &'static str,
    /// Seeded runs.
    pub runs: usize,
    /// Runs that ended with a solution.
    pub solved: usize,
    /// Median final cost over the optimum.
    pub median_ratio: f64,
    /// Worst final cost over the optimum.
    pub worst_ratio: f64,
    /// Median iterations in the time.
    pub iterations: f64,
    /// Median best cost over the optimum at each of [`TIMES`].
    pub over_time: Vec<(f64, f64)>,
    /// Paths that failed the re-check (must be 0).
    pub invalid: usize,
}

/// The planner of `name`, with its trees in k-d trees over `space`.
fn planner(name: PlannerName, space: &R2) -> Result<Box<dyn Planner<R2, CollisionChecker>>, String> {
    let kd = KdNearest::<R2, 2>::new(space).map_err(|e| e.to_string())?;
    Ok(match name {
        PlannerName::InformedRrtStar => Box::new(InformedRrtStar::new(kd)),
        PlannerName::BitStar => Box::new(BitStar::new(kd)),
        _ => Box::new(RrtStar::new(kd)),
    })
}

/// Every planner of [`MEASURED`] on the query `(a, b)` of `w` whose optimum is `best`, `runs`
/// seeded runs of [`TIME`] each; the runs go to `log`.
pub fn bench_optimal(
    w: &SamplingWorld,
    (a, b, best): (Point, Point, f64),
    runs: usize,
    seed: u64,
    log: &mut Vec<PlannerRuns>,
) -> Result<Vec<OptimalRow>, String> {
    let space = R2::new(w.world.bounds());
    let problem = Problem::new(&space, &w.checker, a, b);
    let mut rows = Vec::new();
    for name in MEASURED {
        let mut planner = planner(name, &space)?;
        let measured = benchmark(planner.as_mut(), &problem, &Termination::time(TIME), runs, seed, None)
            .map_err(|e| format!("{}: {e}", w.name))?;
        let (mut finals, mut invalid, mut solved) = (Vec::new(), 0, 0);
        for plan in &measured.plans {
            let valid = plan.is_exact() && w.checks(plan, a, b, best);
            invalid += usize::from(plan.is_exact() && !valid);
            solved += usize::from(valid);
            finals.push(if valid { plan.cost().unwrap_or(f64::INFINITY) / best } else { f64::INFINITY });
        }
        let finals = sorted(finals);
        let over_time = TIMES
            .iter()
            .map(|&t| {
                (t, median(&sorted(measured.runs.iter().map(|r| cost_at(&r.progress, t) / best).collect())))
            })
            .collect();
        rows.push(OptimalRow {
            world: w.name.clone(),
            planner: name.name(),
            runs,
            solved,
            median_ratio: median(&finals),
            worst_ratio: finals.last().copied().unwrap_or(f64::NAN),
            iterations: median(&sorted(measured.runs.iter().map(|r| r.iterations as f64).collect())),
            over_time,
            invalid,
        });
        log.push(PlannerRuns {
            name: format!("trailmark_{}_{}ms", measured.planner, TIME.as_millis()),
            optimizing: true,
            runs: measured.runs,
        });
    }
    Ok(rows)
}

/// The goal of the report's goals table: Informed RRT*'s and BIT*'s medians on each world of random
/// obstacles (the bug trap's and the doors' optimal paths wind across the whole world, whose
/// every state a cheaper path could then still pass through).
pub fn goal(rows: &[OptimalRow]) -> GoalRow {
    GoalRow {
        goal: "Informed RRT*'s and BIT*'s median cost in 0.1 s within 1% of the optimum among random obstacles (1.01 x optimum / median cost >= 1)",
        figures: rows
            .iter()
            .filter(|r| r.planner != PlannerName::RrtStar.name() && r.world.starts_with("convex"))
            .map(|r| (format!("{} {}", r.world, r.planner), GOAL / r.median_ratio))
            .collect(),
        target: 1.0,
        unit: "",
        missing: "run the sampling section",
    }
}

/// Median best cost over the optimum against time: one colour per planner, a line per world
/// (RRT*'s dashed).
pub fn svg(rows: &[OptimalRow]) -> Result<String, String> {
    let lines: Vec<CostLine> = rows
        .iter()
        .map(|r| {
            let which = MEASURED.iter().position(|p| p.name() == r.planner).unwrap_or(0);
            CostLine {
                label: format!("{} {}", r.world, r.planner),
                colour: COLOURS[which % COLOURS.len()],
                dashed: r.planner == PlannerName::RrtStar.name(),
                points: r.over_time.clone(),
            }
        })
        .collect();
    lines_svg(
        "Median best cost over the optimum by time, per world: RRT* (dashed), Informed RRT*, BIT*",
        "seconds",
        (TIMES[0], TIMES[TIMES.len() - 1]),
        (GOAL, "goal: 1% above the optimum"),
        &lines,
    )
}

/// The table.
pub fn markdown(rows: &[OptimalRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "\n### The optimizing planners at equal time ({} ms per run)\n\nThe query of the RRT* table, \
         seeded runs of each planner with its default settings; cost is the final path's over the \
         optimum, every path re-checked exactly.\n\n\
         | world | planner | runs | solved | median cost / optimum | worst | median iterations | invalid |\n\
         |---|---|---:|---:|---:|---:|---:|---:|\n",
        TIME.as_millis()
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {:.4} | {:.4} | {:.0} | {} |\n",
            r.world, r.planner, r.runs, r.solved, r.median_ratio, r.worst_ratio, r.iterations, r.invalid
        ));
    }
    s.push_str("\n![Optimizing planners' cost over time](sampling-optimal.svg)\n");
    s
}
