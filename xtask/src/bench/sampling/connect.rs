//! RRT and RRT-Connect in the sampling section: each planner on every world's seeded queries
//! (at most [`CONNECT_ITERATIONS`] iterations each), trailmark's beside OMPL's with
//! `--with-ompl`, every path re-checked; their success rates, times and costs.

use serde::Serialize;
use trailmark::core::termination::Termination;
use trailmark::core::world::CollisionChecker;
use trailmark::sample::benchmark::{PlannerRuns, benchmark};
use trailmark::sample::{Bridge, KdNearest, Planner, Problem, R2, Rrt, RrtConnect};

use crate::bench::ompl::{OmplDriver, OmplInput, OmplRun};
use crate::bench::plots::{BoxSeries, COLOURS, SuccessLine, box_plot_svg, success_svg};
use crate::bench::report::{Figure, GoalRow};
use crate::bench::sampling::tally::{ConnectStats, ConnectTally};
use crate::bench::sampling::world::{PlaneQuery, SamplingWorld, ompl_queries, points};

/// RRT-Connect's iteration limit per query (the figure).
pub const CONNECT_ITERATIONS: u64 = 10_000;
/// The least share of solvable queries RRT-Connect must solve.
const CONNECT_GOAL: f64 = 0.99;
/// The bridge-test sampler's partner distance for RRT-Connect (bridge): about the distance
/// across a door from wall to wall (1.0 free, 1.3 of grown wall each side). Chosen by a sweep
/// on narrow-6 (1,000 queries: 0.5 -> 93.5% of 200, 1.0 -> 99.9%, 2.0 -> 100%, 3.0 -> 99.8%);
/// `docs/sample.md` has the figures.
const BRIDGE_STD_DEV: f64 = 2.0;
/// The goal for RRT-Connect against OMPL's RRTConnect: at least this much faster.
const CONNECT_SPEEDUP_GOAL: f64 = 2.0;

/// The single-query planners of the section, run on every world's seeded queries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SingleQuery {
    Rrt,
    RrtConnect,
    /// RRT-Connect drawing half its samples by the bridge test (no OMPL counterpart run).
    RrtConnectBridge,
}

impl SingleQuery {
    /// Every one, in the order they run and are reported.
    pub const ALL: [SingleQuery; 3] =
        [SingleQuery::RrtConnect, SingleQuery::RrtConnectBridge, SingleQuery::Rrt];

    /// The registry's planner it runs.
    pub fn planner(self) -> trailmark::solve::PlannerName {
        match self {
            SingleQuery::Rrt => trailmark::solve::PlannerName::Rrt,
            SingleQuery::RrtConnect | SingleQuery::RrtConnectBridge => {
                trailmark::solve::PlannerName::RrtConnect
            }
        }
    }

    /// The name in `--only`, the JSON results and the OMPL driver's input.
    pub fn name(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "rrt",
            SingleQuery::RrtConnect => "rrt_connect",
            SingleQuery::RrtConnectBridge => "rrt_connect_bridge",
        }
    }

    /// The name in text, and (without the dash) in the OMPL logs.
    pub fn label(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "RRT",
            SingleQuery::RrtConnect => "RRT-Connect",
            SingleQuery::RrtConnectBridge => "RRT-Connect (bridge)",
        }
    }

    pub fn ompl_label(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "RRT",
            SingleQuery::RrtConnect => "RRTConnect",
            SingleQuery::RrtConnectBridge => "RRTConnectBridge",
        }
    }

    /// Whether OMPL runs the same planner beside it.
    pub fn in_ompl(self) -> bool {
        self != SingleQuery::RrtConnectBridge
    }
}

/// A single-query planner on one world, trailmark's and (with `--with-ompl`) OMPL's.
#[derive(Debug, Clone, Serialize)]
pub struct ConnectRow {
    /// The planner.
    pub planner: SingleQuery,
    /// The world.
    pub world: String,
    /// Seeded queries run.
    pub queries: usize,
    /// Queries with a path (by the visibility graph).
    pub solvable: usize,
    /// trailmark's RRT-Connect.
    pub trailmark: ConnectStats,
    /// OMPL's RRTConnect on the same queries, with the same limits and collision checks.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ompl: Option<ConnectStats>,
}

impl ConnectRow {
    /// OMPL's median time over trailmark's.
    pub fn speedup(&self) -> Option<f64> {
        self.ompl.as_ref().map(|o| o.median_ms / self.trailmark.median_ms)
    }
}

/// One planner on a world's queries, one seeded run each; every run's record goes to `log`.
pub fn bench_connect(
    planner: SingleQuery,
    w: &SamplingWorld,
    queries: &[PlaneQuery],
    seed: u64,
    log: &mut Vec<PlannerRuns>,
) -> Result<ConnectRow, String> {
    let space = R2::new(w.world.bounds());
    let checker = &w.checker;
    let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
    let limit = Termination::iterations(CONNECT_ITERATIONS);
    let bridge = Bridge::new(BRIDGE_STD_DEV).map_err(|e| e.to_string())?;
    let mut tally = ConnectTally::default();
    let mut runs = Vec::with_capacity(queries.len());
    for (i, &(a, b, best)) in queries.iter().enumerate() {
        let problem = Problem::new(&space, checker, a, b);
        let mut ours: Box<dyn Planner<R2, CollisionChecker>> = match planner {
            SingleQuery::Rrt => Box::new(Rrt::new(nearest.clone())),
            SingleQuery::RrtConnect => Box::new(RrtConnect::new(nearest.clone())),
            SingleQuery::RrtConnectBridge => Box::new(RrtConnect::new(nearest.clone()).with_sampler(bridge)),
        };
        let probe = crate::memory::Probe::default();
        let mut measured = benchmark(ours.as_mut(), &problem, &limit, 1, seed + i as u64, Some(&probe))
            .map_err(|e| format!("{}: {e}", w.name))?;
        let (plan, record) = (measured.plans.remove(0), measured.runs.remove(0));
        let ms = record.time_s * 1e3;
        runs.push(record);
        let counts = (ms, plan.stats.iterations, plan.stats.collision_checks);
        tally.add(best, counts, plan.is_exact(), |best| {
            w.checks(&plan, a, b, best).then(|| plan.cost().unwrap_or(f64::NAN))
        });
    }
    log.push(PlannerRuns { name: format!("trailmark_{}", planner.ompl_label()), optimizing: false, runs });
    Ok(ConnectRow {
        planner,
        world: w.name.clone(),
        queries: queries.len(),
        solvable: tally.solvable,
        trailmark: tally.stats(),
        ompl: None,
    })
}

/// OMPL's RRTConnect on the same queries, with the same iteration limit, each path re-checked
/// as trailmark's are.
pub fn ompl_connect(
    planner: SingleQuery,
    w: &SamplingWorld,
    queries: &[PlaneQuery],
    seed: u64,
    driver: &OmplDriver,
    log: &mut Vec<PlannerRuns>,
) -> Result<ConnectStats, String> {
    let input = OmplInput {
        space: None,
        turning_radius: None,
        world: Some(&w.world),
        boxes: None,
        planner: planner.name(),
        queries: ompl_queries(queries),
        runs: 1,
        seed,
        max_iterations: CONNECT_ITERATIONS,
        time_limit_s: 60.0,
        roadmap_size: 0,
    };
    let mut tally = ConnectTally::default();
    let runs = driver.run(&input).map_err(|e| format!("{}: {e}", w.name))?;
    log.push(PlannerRuns {
        name: format!("OMPL_{}", planner.ompl_label()),
        optimizing: false,
        runs: runs.iter().map(OmplRun::record).collect(),
    });
    for run in runs {
        let &(a, b, best) = queries.get(run.query).ok_or("the OMPL driver answered an unknown query")?;
        let counts = (run.time_s * 1e3, run.iterations, run.collision_checks);
        tally.add(best, counts, run.exact(), |best| {
            w.checks_path(&points(&run.path), a, b, best).then(|| run.cost.unwrap_or(f64::NAN))
        });
    }
    Ok(tally.stats())
}

/// RRT-Connect's goal against OMPL for the report's goals table.
pub fn goal(rows: &[ConnectRow]) -> GoalRow {
    let connect = rows.iter().filter(|r| r.planner == SingleQuery::RrtConnect);
    GoalRow {
        goal: "RRT-Connect at least 2x faster than OMPL RRTConnect (same queries, same checks)",
        figures: connect.filter_map(|r| r.speedup().map(|x| (r.world.clone(), x))).collect(),
        target: CONNECT_SPEEDUP_GOAL,
        unit: "x",
        missing: "run with `--with-ompl`",
    }
}

/// RRT-Connect's time per query as box plots, and its success by time, trailmark's beside
/// OMPL's when it ran.
pub fn figures(rows: &[ConnectRow]) -> Result<Vec<Figure>, String> {
    let worlds: Vec<String> = rows.iter().map(|r| format!("{} {}", r.world, r.planner.label())).collect();
    let mut series = vec![BoxSeries {
        name: "trailmark".into(),
        colour: COLOURS[0],
        values: rows.iter().map(|r| r.trailmark.times_ms.clone()).collect(),
    }];
    if rows.iter().any(|r| r.ompl.is_some()) {
        series.push(BoxSeries {
            name: "OMPL".into(),
            colour: COLOURS[2],
            values: rows.iter().map(|r| r.ompl.as_ref().map_or(Vec::new(), |o| o.times_ms.clone())).collect(),
        });
    }
    let boxes = box_plot_svg(
        "RRT and RRT-Connect: time per solvable query (box: quartiles; whiskers: 1.5 IQR)",
        "milliseconds",
        &worlds,
        &series,
    )?;
    let mut lines = Vec::new();
    let connect = rows.iter().filter(|r| r.planner == SingleQuery::RrtConnect);
    for (r, &colour) in connect.zip(COLOURS.iter().cycle()) {
        let libraries = [("trailmark", Some(&r.trailmark), false), ("OMPL", r.ompl.as_ref(), true)];
        for (library, stats, dashed) in libraries {
            let Some(stats) = stats else { continue };
            lines.push(SuccessLine {
                label: format!("{} {library}", r.world),
                colour,
                dashed,
                solved_at: stats.solved_ms.clone(),
                total: r.solvable,
            });
        }
    }
    let mut figures = vec![("sampling-connect-time.svg", boxes)];
    if lines.iter().any(|l| !l.solved_at.is_empty()) {
        let caption = format!(
            "RRT-Connect: solvable queries solved by each time ({CONNECT_ITERATIONS} iterations at most); OMPL dashed"
        );
        figures.push(("sampling-connect-success.svg", success_svg(&caption, "milliseconds", &lines)?));
    }
    Ok(figures)
}

/// The RRT-Connect table, OMPL's rows beside trailmark's when it ran, and the goals.
pub fn markdown(rows: &[ConnectRow], ompl_version: Option<&str>) -> String {
    let with_ompl = rows.iter().any(|r| r.ompl.is_some());
    let mut s =
        format!("### RRT and RRT-Connect ({CONNECT_ITERATIONS} iterations at most, default range)\n\n");
    if with_ompl {
        s.push_str(&format!(
            "Beside OMPL {} RRT and RRTConnect: the same queries, the same iteration limit, default ranges \
             (0.2 x the space's extent in both), both validating states and motions with trailmark's \
             exact checker (OMPL through a C interface, so each collision question costs both the same). \
             OMPL's time is `Planner::solve` alone; trailmark's includes building its trees.\n\n",
            ompl_version.unwrap_or("?")
        ));
    }
    s.push_str(
        "| world | planner | library | queries | solvable | solved | median ms | median iterations | median checks | median cost / optimum | invalid | speedup (OMPL / trailmark) |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let rows = [("trailmark", Some(&r.trailmark)), ("OMPL", r.ompl.as_ref())];
        for (library, stats) in rows {
            let Some(o) = stats else { continue };
            let speedup = match (library, r.speedup()) {
                ("trailmark", Some(x)) => format!("**{x:.2}x**"),
                _ => String::new(),
            };
            s.push_str(&format!(
                "| {} | {} | {library} | {} | {} | {} ({:.1}%) | {:.3} | {:.0} | {:.0} | {:.3} | {} | {speedup} |\n",
                r.world,
                r.planner.label(),
                r.queries,
                r.solvable,
                o.solved,
                100.0 * o.solved as f64 / r.solvable.max(1) as f64,
                o.median_ms,
                o.median_iterations,
                o.median_checks,
                o.median_cost_ratio,
                o.invalid,
            ));
        }
    }
    s.push_str(
        "\n![RRT and RRT-Connect time per query](sampling-connect-time.svg)\n\n\
         ![RRT-Connect success by time](sampling-connect-success.svg)\n",
    );
    let share = |o: &ConnectStats, r: &ConnectRow| o.solved as f64 / r.solvable.max(1) as f64;
    let of_planner = |planner| rows.iter().filter(move |r: &&ConnectRow| r.planner == planner);
    let connect: Vec<&ConnectRow> = of_planner(SingleQuery::RrtConnect).collect();
    for planner in [SingleQuery::RrtConnect, SingleQuery::RrtConnectBridge] {
        let of: Vec<&ConnectRow> = of_planner(planner).collect();
        if of.is_empty() {
            continue;
        }
        let missed: Vec<String> = of
            .iter()
            .filter(|r| share(&r.trailmark, r) < CONNECT_GOAL)
            .map(|r| {
                let ompl =
                    r.ompl.as_ref().map_or(String::new(), |o| format!("; OMPL {:.1}%", share(o, r) * 100.0));
                format!(
                    "{} ({:.1}%, median {:.0} iterations{ompl})",
                    r.world,
                    share(&r.trailmark, r) * 100.0,
                    r.trailmark.median_iterations
                )
            })
            .collect();
        s.push_str(&format!(
            "\nGoal: {} solves at least {:.0}% of the solvable queries of each world within \
             {CONNECT_ITERATIONS} iterations. Measured: met on {} of {} worlds{}.\n",
            planner.label(),
            CONNECT_GOAL * 100.0,
            of.len() - missed.len(),
            of.len(),
            if missed.is_empty() { String::new() } else { format!("; not met on {}", missed.join(", ")) }
        ));
    }
    if with_ompl {
        let slow: Vec<String> = connect
            .iter()
            .filter_map(|r| {
                r.speedup().filter(|&x| x < CONNECT_SPEEDUP_GOAL).map(|x| format!("{} ({x:.2}x)", r.world))
            })
            .collect();
        s.push_str(&format!(
            "\nGoal: RRT-Connect at least {CONNECT_SPEEDUP_GOAL}x faster than OMPL's. Measured: {}.\n",
            if slow.is_empty() {
                "met on every world".to_string()
            } else {
                format!("not met on {}", slow.join(", "))
            }
        ));
    }
    s.push('\n');
    s
}
