//! RRT* in the sampling section: on one query per world, seeded runs of a fixed number of
//! iterations (final cost, first solution, convergence over iterations), and with `--with-ompl`
//! runs of trailmark's and OMPL's RRT* for the same time each (cost over time).

use std::time::Duration;

use plotters::prelude::*;
use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::sample::benchmark::{PlannerRuns, RunRecord, benchmark};
use trailmark::sample::{KdNearest, Plan, Problem, R2, RrtStar};

use crate::bench::ompl::{OmplDriver, OmplInput, OmplRun};
use crate::bench::plots::COLOURS;
use crate::bench::report::GoalRow;
use crate::bench::sampling::world::{PlaneQuery, SamplingWorld, points};
use crate::bench::stats::{median, sorted};

/// The name in `--only`.
pub const NAME: &str = trailmark::solve::PlannerName::RrtStar.name();
/// RRT*'s iterations per run (the figure).
pub const STAR_ITERATIONS: u64 = 20_000;
/// The goal for RRT*'s median cost after its iterations, over the optimum.
const STAR_GOAL: f64 = 1.05;
/// The goal's line in RRT*'s plots.
const STAR_LINE: (f64, &str) = (STAR_GOAL, "goal: 5% above the optimum");
/// Where RRT*'s best cost is read for the convergence plot.
const CHECKPOINTS: [u64; 8] = [250, 500, 1_000, 2_000, 5_000, 10_000, 15_000, 20_000];

/// RRT* of both libraries with the same time per run, on one world.
#[derive(Debug, Clone, Serialize)]
pub struct EqualTimeRow {
    /// The world.
    pub world: String,
    /// The time of every run, seconds.
    pub time_limit_s: f64,
    /// Runs per library.
    pub runs: usize,
    /// trailmark's median final cost over the optimum.
    pub trailmark_ratio: f64,
    /// OMPL's median final cost over the optimum.
    pub ompl_ratio: f64,
    /// trailmark's median iterations in the time.
    pub trailmark_iterations: f64,
    /// OMPL's median iterations in the time.
    pub ompl_iterations: f64,
    /// Median best cost over the optimum at each time (seconds): trailmark, OMPL.
    pub over_time: Vec<(f64, f64, f64)>,
    /// Paths of either library that failed the re-check (must be 0).
    pub invalid: usize,
}

/// RRT* on one world.
#[derive(Debug, Clone, Serialize)]
pub struct StarRow {
    /// The world.
    pub world: String,
    /// The query.
    pub start: [f64; 2],
    /// The query.
    pub goal: [f64; 2],
    /// The shortest path's cost.
    pub optimum: f64,
    /// Seeded runs.
    pub runs: usize,
    /// Median final cost over the optimum.
    pub median_ratio: f64,
    /// Worst final cost over the optimum.
    pub worst_ratio: f64,
    /// Median run time, seconds.
    pub median_s: f64,
    /// Median time to the first solution, milliseconds.
    pub median_first_ms: f64,
    /// Median best cost over the optimum at each checkpoint (NaN before every run has one).
    pub convergence: Vec<(u64, f64)>,
    /// Paths that failed the re-check (must be 0).
    pub invalid: usize,
}

/// One seeded RRT* run from `a` to `b` until `termination`, and its record for the log
/// (with the run's peak memory).
fn star_run(
    w: &SamplingWorld,
    a: Point,
    b: Point,
    termination: &Termination,
    seed: u64,
) -> Result<(Plan<Point>, RunRecord), String> {
    let space = R2::new(w.world.bounds());
    let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
    let problem = Problem::new(&space, &w.checker, a, b);
    let probe = crate::memory::Probe::default();
    let mut runs = benchmark(&mut RrtStar::new(nearest), &problem, termination, 1, seed, Some(&probe))
        .map_err(|e| format!("{}: {e}", w.name))?;
    Ok((runs.plans.remove(0), runs.runs.remove(0)))
}

/// The best cost at `t` seconds of a run whose improvements are `(seconds, cost)`.
pub(super) fn cost_at(improvements: &[(f64, f64)], t: f64) -> f64 {
    improvements.iter().take_while(|i| i.0 <= t).last().map_or(f64::INFINITY, |i| i.1)
}

/// The query of RRT* on a world: the longest of the first ten queries that have a path, with
/// its optimum.
pub fn star_query(w: &SamplingWorld, queries: &[PlaneQuery]) -> Result<(Point, Point, f64), String> {
    let &(a, b, best) = queries
        .iter()
        .take(10)
        .filter(|q| q.2.is_some())
        .max_by(|x, y| x.2.unwrap_or(0.0).total_cmp(&y.2.unwrap_or(0.0)))
        .ok_or_else(|| format!("{}: no solvable query", w.name))?;
    Ok((a, b, best.unwrap_or(f64::NAN)))
}

/// RRT* of trailmark and of OMPL on one query, `runs` runs each of `limit`, with the median
/// final cost and the median best cost over time.
pub fn star_equal_time(
    w: &SamplingWorld,
    (a, b, best): (Point, Point, f64),
    runs: usize,
    limit: Duration,
    seed: u64,
    driver: &OmplDriver,
    log: &mut Vec<PlannerRuns>,
) -> Result<EqualTimeRow, String> {
    let termination = Termination::time(limit);
    let mut invalid = 0;
    let mut ours: Vec<(f64, Vec<(f64, f64)>)> = Vec::new();
    let mut our_iterations = Vec::new();
    let mut our_log = Vec::new();
    for run in 0..runs {
        let (plan, logged) = star_run(w, a, b, &termination, seed + run as u64)?;
        invalid += usize::from(plan.is_exact() && !w.checks(&plan, a, b, best));
        our_iterations.push(plan.stats.iterations as f64);
        let cost = plan.cost().unwrap_or(f64::INFINITY);
        ours.push((cost, logged.progress.clone()));
        our_log.push(logged);
    }
    let input = OmplInput {
        space: None,
        turning_radius: None,
        world: Some(&w.world),
        boxes: None,
        planner: "rrt_star",
        queries: vec![vec![a.x, a.y, b.x, b.y]],
        runs,
        seed,
        max_iterations: 0,
        time_limit_s: limit.as_secs_f64(),
        roadmap_size: 0,
    };
    let mut theirs: Vec<(f64, Vec<(f64, f64)>)> = Vec::new();
    let mut their_iterations = Vec::new();
    let their_runs = driver.run(&input).map_err(|e| format!("{}: {e}", w.name))?;
    let name = |library: &str| format!("{library}_RRTstar_{}s", limit.as_secs_f64());
    log.push(PlannerRuns { name: name("trailmark"), optimizing: true, runs: our_log });
    log.push(PlannerRuns {
        name: name("OMPL"),
        optimizing: true,
        runs: their_runs.iter().map(OmplRun::record).collect(),
    });
    for run in their_runs {
        let exact = run.exact();
        invalid += usize::from(exact && !w.checks_path(&points(&run.path), a, b, best));
        their_iterations.push(run.iterations as f64);
        theirs
            .push((if exact { run.cost.unwrap_or(f64::INFINITY) } else { f64::INFINITY }, run.improvements));
    }
    let final_ratio =
        |runs: &[(f64, Vec<(f64, f64)>)]| median(&sorted(runs.iter().map(|r| r.0 / best).collect()));
    let at = |runs: &[(f64, Vec<(f64, f64)>)], t: f64| {
        median(&sorted(runs.iter().map(|r| cost_at(&r.1, t) / best).collect()))
    };
    let end = limit.as_secs_f64();
    let over_time = [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0]
        .into_iter()
        .filter(|&t| t < end)
        .chain([end])
        .map(|t| (t, at(&ours, t), at(&theirs, t)))
        .collect();
    Ok(EqualTimeRow {
        world: w.name.clone(),
        time_limit_s: end,
        runs,
        trailmark_ratio: final_ratio(&ours),
        ompl_ratio: final_ratio(&theirs),
        trailmark_iterations: median(&sorted(our_iterations)),
        ompl_iterations: median(&sorted(their_iterations)),
        over_time,
        invalid,
    })
}

/// RRT* on one query of `w`, `runs` seeded runs of [`STAR_ITERATIONS`] iterations, its cost at
/// each checkpoint; every run's record goes to `log`.
pub fn bench_star(
    w: &SamplingWorld,
    a: Point,
    b: Point,
    best: f64,
    runs: usize,
    seed: u64,
    log: &mut Vec<PlannerRuns>,
) -> Result<StarRow, String> {
    let limit = Termination::iterations(STAR_ITERATIONS);
    let (mut finals, mut times, mut firsts, mut invalid) = (Vec::new(), Vec::new(), Vec::new(), 0);
    let mut at_checkpoints: Vec<Vec<f64>> = vec![Vec::new(); CHECKPOINTS.len()];
    let mut log_runs = Vec::new();
    for run in 0..runs {
        let (plan, logged) = star_run(w, a, b, &limit, seed + run as u64)?;
        log_runs.push(logged);
        times.push(plan.stats.elapsed.as_secs_f64());
        firsts.push(plan.stats.time_to_solution.map_or(f64::INFINITY, |t| t.as_secs_f64() * 1e3));
        if !plan.is_exact() || !w.checks(&plan, a, b, best) {
            invalid += usize::from(plan.is_exact());
            finals.push(f64::INFINITY);
        } else {
            finals.push(plan.cost().unwrap_or(f64::INFINITY) / best);
        }
        for (k, &c) in CHECKPOINTS.iter().enumerate() {
            let cost = plan.history.iter().take_while(|h| h.iteration <= c).last().map(|h| h.cost);
            at_checkpoints[k].push(cost.map_or(f64::INFINITY, |c| c / best));
        }
    }
    log.push(PlannerRuns {
        name: format!("trailmark_RRTstar_{STAR_ITERATIONS}_iterations"),
        optimizing: true,
        runs: log_runs,
    });
    let finals = sorted(finals);
    let convergence = CHECKPOINTS.iter().zip(at_checkpoints).map(|(&c, v)| (c, median(&sorted(v)))).collect();
    Ok(StarRow {
        world: w.name.clone(),
        start: [a.x, a.y],
        goal: [b.x, b.y],
        optimum: best,
        runs,
        median_ratio: median(&finals),
        worst_ratio: finals.last().copied().unwrap_or(f64::NAN),
        median_s: median(&sorted(times)),
        median_first_ms: median(&sorted(firsts)),
        convergence,
        invalid,
    })
}

/// RRT*'s goal against OMPL for the report's goals table: OMPL's median cost over trailmark's,
/// at least 1 where trailmark's is no higher.
pub fn goal(rows: &[EqualTimeRow]) -> GoalRow {
    GoalRow {
        goal: "RRT* cost at equal time no higher than OMPL RRTstar's (OMPL median cost / trailmark median cost >= 1)",
        figures: rows.iter().map(|r| (r.world.clone(), r.ompl_ratio / r.trailmark_ratio)).collect(),
        target: 1.0,
        unit: "",
        missing: "run with `--with-ompl`",
    }
}

/// A line of a plot: its legend, colour, whether dashed, and points.
pub(super) struct CostLine {
    pub(super) label: String,
    pub(super) colour: RGBColor,
    pub(super) dashed: bool,
    pub(super) points: Vec<(f64, f64)>,
}

/// Cost over the optimum against a log-scaled x axis, one line each, with the goal's line
/// (its ratio and legend).
pub(super) fn lines_svg(
    caption: &str,
    x_desc: &str,
    x: (f64, f64),
    goal: (f64, &str),
    lines: &[CostLine],
) -> Result<String, String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let top = lines
        .iter()
        .flat_map(|l| l.points.iter().map(|p| p.1))
        .filter(|c| c.is_finite())
        .fold(1.1f64, f64::max)
        .min(2.0);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (720, 420)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d((x.0..x.1).log_scale(), 0.99..top)
            .map_err(|x| e(&x))?;
        chart.configure_mesh().x_desc(x_desc).y_desc("cost / optimum").draw().map_err(|x| e(&x))?;
        let grey = RGBColor(120, 120, 120);
        chart
            .draw_series(LineSeries::new([(x.0, goal.0), (x.1, goal.0)], grey.stroke_width(1)))
            .map_err(|x| e(&x))?
            .label(goal.1)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], grey.stroke_width(1)));
        for line in lines {
            let points: Vec<(f64, f64)> =
                line.points.iter().filter(|c| c.1.is_finite()).map(|&(x, c)| (x, c.min(top))).collect();
            let style = line.colour.stroke_width(2);
            let colour = line.colour;
            let series = if line.dashed {
                chart.draw_series(DashedLineSeries::new(points.clone(), 6, 4, style))
            } else {
                chart.draw_series(LineSeries::new(points.clone(), style))
            };
            series
                .map_err(|x| e(&x))?
                .label(line.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
            chart
                .draw_series(points.into_iter().map(|p| Circle::new(p, 3, colour.filled())))
                .map_err(|x| e(&x))?;
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .draw()
            .map_err(|x| e(&x))?;
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// Median RRT* cost over the optimum against iterations, one line per world (log x axis).
pub fn convergence_svg(rows: &[StarRow]) -> Result<String, String> {
    let lines: Vec<CostLine> = rows
        .iter()
        .zip(COLOURS.iter().cycle())
        .map(|(row, &colour)| CostLine {
            label: row.world.clone(),
            colour,
            dashed: false,
            points: row.convergence.iter().map(|&(i, c)| (i as f64, c)).collect(),
        })
        .collect();
    let x = (CHECKPOINTS[0] as f64, CHECKPOINTS[CHECKPOINTS.len() - 1] as f64);
    lines_svg("RRT*: median path cost over the optimum, by iterations", "iterations", x, STAR_LINE, &lines)
}

/// Median best cost over the optimum against time, trailmark solid and OMPL dashed.
pub fn cost_time_svg(rows: &[EqualTimeRow]) -> Result<String, String> {
    let mut lines = Vec::new();
    for (row, &colour) in rows.iter().zip(COLOURS.iter().cycle()) {
        let series = |ompl: bool| row.over_time.iter().map(move |&(t, a, b)| (t, if ompl { b } else { a }));
        lines.push(CostLine {
            label: format!("{} trailmark", row.world),
            colour,
            dashed: false,
            points: series(false).collect(),
        });
        lines.push(CostLine {
            label: format!("{} OMPL", row.world),
            colour,
            dashed: true,
            points: series(true).collect(),
        });
    }
    let end = rows.iter().map(|r| r.time_limit_s).fold(0.01, f64::max);
    lines_svg(
        "RRT*: median best cost over the optimum by time, trailmark (solid) and OMPL (dashed)",
        "seconds",
        (0.002, end),
        STAR_LINE,
        &lines,
    )
}

/// The RRT* table and its goal.
pub fn markdown(rows: &[StarRow]) -> String {
    let mut s = String::new();
    s.push_str(&format!(
        "### RRT* ({STAR_ITERATIONS} iterations, default range and k-nearest rewiring)\n\n\
         | world | query | optimum | runs | median cost / optimum | worst | median first solution (ms) | median run (s) | invalid |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|\n"
    ));
    for r in rows {
        s.push_str(&format!(
            "| {} | ({:.1}, {:.1}) → ({:.1}, {:.1}) | {:.3} | {} | {:.4} | {:.4} | {:.2} | {:.2} | {} |\n",
            r.world,
            r.start[0],
            r.start[1],
            r.goal[0],
            r.goal[1],
            r.optimum,
            r.runs,
            r.median_ratio,
            r.worst_ratio,
            r.median_first_ms,
            r.median_s,
            r.invalid
        ));
    }
    let worst = rows.iter().map(|r| r.median_ratio).fold(0.0, f64::max);
    s.push_str(&format!(
        "\nGoal: RRT*'s median cost after {STAR_ITERATIONS} iterations within {:.0}% of the optimum on every \
         world. Measured: at most {:.2}% above: {}.\n\n![RRT* convergence](sampling-convergence.svg)\n",
        (STAR_GOAL - 1.0) * 100.0,
        (worst - 1.0) * 100.0,
        if worst <= STAR_GOAL { "met" } else { "not met" }
    ));
    s
}

/// The RRT* comparison with OMPL at equal time.
pub fn equal_time_markdown(rows: &[EqualTimeRow], ompl_version: Option<&str>) -> String {
    let version = ompl_version.unwrap_or("?");
    let mut s = format!(
        "\n### RRT* beside OMPL {version} RRTstar at equal time\n\nThe query of the table above, the \
         same time for every run of both (default settings: k-nearest rewiring, range 0.2 x extent, \
         goal bias 0.05), the exact checker in both. Cost is the final path's over the optimum.\n\n\
         | world | s/run | runs | trailmark median cost / optimum | OMPL median cost / optimum | trailmark iterations | OMPL iterations | invalid |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|\n"
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {:.2} | {} | {:.4} | {:.4} | {:.0} | {:.0} | {} |\n",
            r.world,
            r.time_limit_s,
            r.runs,
            r.trailmark_ratio,
            r.ompl_ratio,
            r.trailmark_iterations,
            r.ompl_iterations,
            r.invalid
        ));
    }
    s.push_str("\n![RRT* cost over time beside OMPL](sampling-cost-time.svg)\n");
    s
}
