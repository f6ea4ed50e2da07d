//! The car section: planning for a car of turning radius 1 (a disc robot of radius 0.25) on
//! generated polygon worlds, in the Reeds-Shepp space (forward and reverse) and the Dubins space
//! (forward only). Hybrid A* on the world laid on cells, RRT-Connect and RRT* in the car's space,
//! and with `--with-ompl` OMPL's RRTConnect and RRTstar in its own `ReedsSheppStateSpace` and
//! `DubinsStateSpace`, their motions checked by trailmark's exact curve test.
//!
//! Every path is re-checked by [`world`]; one that fails is an error that fails the run. Lengths
//! are compared with the shortest any planner found for the same query in the same space.

mod world;

use std::time::{Duration, Instant};

use serde::Serialize;
use trailmark::car::{CarError, CarMap, HybridAStar, HybridOptions};
use trailmark::core::footprint::Footprint;
use trailmark::core::geometry::{Pose, Vector};
use trailmark::core::reeds_shepp::ReedsSheppPath;
use trailmark::core::termination::Termination;
use trailmark::sample::space::{Car, CarCurves, DubinsCurves, ReedsSheppCurves};
use trailmark::sample::{KdNearest, Planner, Problem, RrtConnect, RrtStar};

use crate::bench::ompl::{OmplDriver, OmplInput};
use crate::bench::progress::SectionProgress;
use crate::bench::report::table;
use crate::bench::stats::{median, quantile, sorted};
use crate::bench::suite::Suite;
use world::{CarWorld, ROBOT_RADIUS, SIZE, TURNING_RADIUS, ompl_pose, worlds};

/// The cells Hybrid A* lays the worlds on: an eighth of the turning radius.
/// The registry's planners this section measures in the car spaces.
pub const MEASURED: [trailmark::solve::PlannerName; 3] = [
    trailmark::solve::PlannerName::HybridAStar,
    trailmark::solve::PlannerName::RrtConnect,
    trailmark::solve::PlannerName::RrtStar,
];

const RESOLUTION: f64 = TURNING_RADIUS / 8.0;
/// Hybrid A*'s time limit per query.
const HYBRID_LIMIT: Duration = Duration::from_secs(2);
/// RRT-Connect's iteration limit.
const CONNECT_ITERATIONS: u64 = 10_000;

/// How much the section runs: queries per world, of which RRT* runs on the first `star`, each
/// for `star_time`.
struct Sizes {
    queries: usize,
    star: usize,
    star_time: Duration,
}

impl Sizes {
    fn of(suite: Suite) -> Sizes {
        match suite {
            Suite::Quick => Sizes { queries: 12, star: 3, star_time: Duration::from_millis(500) },
            Suite::Full => Sizes { queries: 50, star: 10, star_time: Duration::from_secs(2) },
        }
    }
}

/// One planner in one space on one world.
#[derive(Debug, Clone, Serialize)]
pub struct CarRow {
    /// The world.
    pub world: String,
    /// The planner, as the report names it.
    pub planner: String,
    /// `reeds_shepp` or `dubins`.
    pub space: &'static str,
    /// Queries run.
    pub queries: usize,
    /// Queries solved with a path that passed the re-check.
    pub solved: usize,
    /// Median time per query, milliseconds (unsolved ones included).
    pub median_ms: f64,
    /// 90th percentile of the time per query, milliseconds.
    pub p90_ms: f64,
    /// Median over solved queries of the length over the shortest any planner found for it.
    pub median_length_ratio: f64,
    /// Median changes of gear per solved path.
    pub median_cusps: f64,
    /// Paths that failed the re-check.
    pub invalid: usize,
}

/// What one run of a planner gave: its time, and the length and cusps of a path that passed.
#[derive(Debug, Clone, Copy)]
struct Run {
    ms: f64,
    path: Option<(f64, usize)>,
    invalid: bool,
}

/// The runs of one planner in one space on one world, query by query.
struct Runs {
    planner: String,
    space: &'static str,
    runs: Vec<Run>,
}

/// The section's results.
#[derive(Debug, Clone, Serialize)]
pub struct CarReport {
    /// One row per world, planner and space.
    pub rows: Vec<CarRow>,
    /// Per world: the time of laying it on cells for Hybrid A*, milliseconds.
    pub map_ms: Vec<(String, f64)>,
    /// Per space: Hybrid A*'s length over RRT*'s on the queries both solved (median, largest).
    pub hybrid_over_star: Vec<(&'static str, f64, f64, usize)>,
    /// The OMPL version measured (with `--with-ompl`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ompl_version: Option<String>,
}

impl CarReport {
    /// Paths that failed their re-check.
    pub fn errors(&self) -> usize {
        self.rows.iter().map(|r| r.invalid).sum()
    }
}

/// Runs the section, beside OMPL's planners when `ompl` is given.
pub fn bench(suite: Suite, seed: u64, ompl: Option<&OmplDriver>) -> Result<CarReport, String> {
    let size = Sizes::of(suite);
    let worlds = worlds(seed)?;
    let mut progress = SectionProgress::new("cars", worlds.len());
    let mut report =
        CarReport { rows: Vec::new(), map_ms: Vec::new(), hybrid_over_star: Vec::new(), ompl_version: None };
    let mut pairs: Vec<(&'static str, f64)> = Vec::new();
    for w in &worlds {
        progress.step(format!("{}: laying the world on cells", w.name));
        let clock = Instant::now();
        let map = CarMap::from_world(&w.world, RESOLUTION).map_err(|e| format!("{}: {e}", w.name))?;
        report.map_ms.push((w.name.clone(), clock.elapsed().as_secs_f64() * 1e3));
        let disc = Footprint::Radius(ROBOT_RADIUS);
        let settings =
            |reverse| HybridOptions { turning_radius: TURNING_RADIUS, reverse, ..HybridOptions::default() };
        let hybrid_rs = HybridAStar::new(&map, &disc, settings(true)).map_err(|e| e.to_string())?;
        let hybrid_dubins = HybridAStar::new(&map, &disc, settings(false)).map_err(|e| e.to_string())?;
        let queries = w.queries(size.queries, seed ^ 0xca5, |p| hybrid_rs.is_free(p));
        let mut all: Vec<Runs> = Vec::new();
        for (space, hybrid) in [("reeds_shepp", &hybrid_rs), ("dubins", &hybrid_dubins)] {
            progress.note(format!("{}: Hybrid A* ({space}), {} queries", w.name, queries.len()));
            all.push(Runs { planner: "Hybrid A*".into(), space, runs: hybrid_runs(w, hybrid, &queries)? });
        }
        progress.note(format!("{}: RRT-Connect and RRT* in both spaces", w.name));
        let rs_cusps: fn(&ReedsSheppPath) -> Vec<f64> = ReedsSheppPath::cusps;
        all.extend(sampling_runs::<ReedsSheppCurves>(w, &queries, &size, seed, "reeds_shepp", rs_cusps)?);
        all.extend(sampling_runs::<DubinsCurves>(w, &queries, &size, seed, "dubins", |_| Vec::new())?);
        // OMPL in its Reeds-Shepp space only: in Debian's OMPL 1.5.2 an assertion inside
        // DubinsStateSpace's LSL word aborts the driver on some pairs of poses.
        if let Some(driver) = ompl {
            progress.note(format!("{}: OMPL's RRTConnect and RRTstar in its Reeds-Shepp space", w.name));
            all.extend(ompl_runs(w, &queries, &size, seed, "reeds_shepp", driver)?);
            report.ompl_version = Some(driver.version.clone());
        }
        for space in ["reeds_shepp", "dubins"] {
            let hybrid = all.iter().find(|r| r.planner == "Hybrid A*" && r.space == space);
            let star = all.iter().find(|r| r.planner == "RRT*" && r.space == space);
            if let (Some(h), Some(s)) = (hybrid, star) {
                for (a, b) in h.runs.iter().zip(&s.runs) {
                    if let (Some((x, _)), Some((y, _))) = (a.path, b.path) {
                        pairs.push((space, x / y));
                    }
                }
            }
        }
        report.rows.extend(rows(&w.name, &all));
    }
    for space in ["reeds_shepp", "dubins"] {
        let ratios = sorted(pairs.iter().filter(|p| p.0 == space).map(|p| p.1).collect());
        if let Some(&largest) = ratios.last() {
            report.hybrid_over_star.push((space, median(&ratios), largest, ratios.len()));
        }
    }
    Ok(report)
}

/// Hybrid A* on every query.
fn hybrid_runs(
    w: &CarWorld,
    planner: &HybridAStar<'_>,
    queries: &[(Pose, Pose)],
) -> Result<Vec<Run>, String> {
    let limit = Termination::time(HYBRID_LIMIT);
    let mut runs = Vec::new();
    for (a, b) in queries {
        let clock = Instant::now();
        let plan = planner.plan(a, b, &limit);
        let ms = clock.elapsed().as_secs_f64() * 1e3;
        let run = match plan {
            Ok(plan) => {
                let path = w.check_car_path(&plan.path, a, b);
                Run { ms, path, invalid: path.is_none() }
            }
            Err(CarError::NoPath { .. }) => Run { ms, path: None, invalid: false },
            Err(e) => return Err(format!("{}: Hybrid A*: {e}", w.name)),
        };
        runs.push(run);
    }
    Ok(runs)
}

/// RRT-Connect on every query and RRT* on the first ones, in the space of the curves `C`.
fn sampling_runs<C: CarCurves>(
    w: &CarWorld,
    queries: &[(Pose, Pose)],
    size: &Sizes,
    seed: u64,
    space_name: &'static str,
    cusps_of: fn(&C::Path) -> Vec<f64>,
) -> Result<[Runs; 2], String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {space_name}: {e}", w.name);
    let space = Car::<C>::new(w.world.bounds(), TURNING_RADIUS).map_err(|e| err(&e))?;
    let nearest = KdNearest::<Car<C>, 2>::new(&space).map_err(|e| err(&e))?;
    let mut connect = Vec::new();
    let mut star = Vec::new();
    for (i, (a, b)) in queries.iter().enumerate() {
        let problem = Problem::new(&space, &w.checker, *a, *b);
        let run = |planner: &mut dyn Planner<Car<C>, _>, limit: &Termination| -> Result<Run, String> {
            let clock = Instant::now();
            let plan = planner.solve(&problem, limit).map_err(|e| err(&e))?;
            let ms = clock.elapsed().as_secs_f64() * 1e3;
            let path = plan.path().map(|p| w.check_curves::<C>(p, a, b, &cusps_of));
            Ok(Run { ms, path: path.flatten(), invalid: path.is_some_and(|p| p.is_none()) })
        };
        let seed = seed + i as u64;
        connect.push(run(
            &mut RrtConnect::new(nearest.clone()).with_seed(seed),
            &Termination::iterations(CONNECT_ITERATIONS),
        )?);
        if i < size.star {
            star.push(run(
                &mut RrtStar::new(nearest.clone()).with_seed(seed),
                &Termination::time(size.star_time),
            )?);
        }
    }
    Ok([
        Runs { planner: "RRT-Connect".into(), space: space_name, runs: connect },
        Runs { planner: "RRT*".into(), space: space_name, runs: star },
    ])
}

/// OMPL's RRTConnect on every query and RRTstar on the first ones, in its space `space`.
fn ompl_runs(
    w: &CarWorld,
    queries: &[(Pose, Pose)],
    size: &Sizes,
    seed: u64,
    space: &'static str,
    driver: &OmplDriver,
) -> Result<[Runs; 2], String> {
    let ends: Vec<Vec<f64>> =
        queries.iter().map(|(a, b)| ompl_pose(a).into_iter().chain(ompl_pose(b)).collect()).collect();
    let mut out = Vec::new();
    for (planner, label, n, limit) in [
        ("rrt_connect", "OMPL RRTConnect", queries.len(), (CONNECT_ITERATIONS, 10.0)),
        ("rrt_star", "OMPL RRTstar", size.star.min(queries.len()), (0, size.star_time.as_secs_f64())),
    ] {
        let input = OmplInput {
            world: Some(&w.world),
            boxes: None,
            space: Some(space),
            turning_radius: Some(TURNING_RADIUS),
            planner,
            queries: ends[..n].to_vec(),
            runs: 1,
            seed,
            max_iterations: limit.0,
            time_limit_s: limit.1,
            roadmap_size: 0,
        };
        let runs = driver
            .run(&input)?
            .into_iter()
            .map(|r| {
                let (a, b) = &queries[r.query];
                let path: Vec<Pose> =
                    r.path.iter().map(|p| Pose::new(Vector::new(p[0], p[1]), p[2])).collect();
                let checked =
                    r.exact().then(|| w.check_curves::<ReedsSheppCurves>(&path, a, b, |c| c.cusps()));
                Run {
                    ms: r.time_s * 1e3,
                    path: checked.flatten(),
                    invalid: checked.is_some_and(|c| c.is_none()),
                }
            })
            .collect();
        out.push(Runs { planner: label.into(), space, runs });
    }
    out.try_into().map_err(|_| "two OMPL planners".to_string())
}

/// The rows of one world's runs, lengths over the shortest path of the same query and space.
fn rows(world: &str, all: &[Runs]) -> Vec<CarRow> {
    let best = |space: &str, q: usize| {
        all.iter()
            .filter(|r| r.space == space)
            .filter_map(|r| r.runs.get(q).and_then(|run| run.path))
            .map(|p| p.0)
            .fold(f64::INFINITY, f64::min)
    };
    all.iter()
        .map(|r| {
            let solved: Vec<(usize, (f64, usize))> =
                r.runs.iter().enumerate().filter_map(|(q, run)| run.path.map(|p| (q, p))).collect();
            let times = sorted(r.runs.iter().map(|run| run.ms).collect());
            let ratios = sorted(solved.iter().map(|&(q, (length, _))| length / best(r.space, q)).collect());
            let cusps = sorted(solved.iter().map(|&(_, (_, c))| c as f64).collect());
            CarRow {
                world: world.into(),
                planner: r.planner.clone(),
                space: r.space,
                queries: r.runs.len(),
                solved: solved.len(),
                median_ms: median(&times),
                p90_ms: quantile(&times, 0.9),
                median_length_ratio: median(&ratios),
                median_cusps: median(&cusps),
                invalid: r.runs.iter().filter(|run| run.invalid).count(),
            }
        })
        .collect()
}

/// The section's part of the report.
pub fn markdown(report: &CarReport) -> String {
    if report.rows.is_empty() {
        return String::new();
    }
    let maps: Vec<String> = report.map_ms.iter().map(|(w, ms)| format!("{w} {ms:.0} ms")).collect();
    let mut s = format!(
        "## Car-like robots\n\n\
         A car of turning radius {TURNING_RADIUS} with a disc footprint of radius {ROBOT_RADIUS}, on {SIZE} x {SIZE} \
         polygon worlds, between seeded poses from which it can drive a full circle. **Reeds-Shepp**: forward and \
         in reverse; **Dubins**: forward only. Hybrid A* plans on the world laid on cells of {RESOLUTION} (a cell \
         touched by an obstacle is one; laying out: {}), with Nav2 Smac's defaults (72 headings, reverse penalty 2, \
         turning penalty 1.2) and a {} s limit; RRT-Connect runs {CONNECT_ITERATIONS} iterations at most, RRT* a fixed \
         time on the first queries of each world. OMPL's planners (with `--with-ompl`) run in OMPL's own \
         `ReedsSheppStateSpace` (not in its `DubinsStateSpace`: in Debian's OMPL 1.5.2 an assertion in its LSL word \
         aborts on some pairs of poses), \
         states checked by the same point test and motions by trailmark's exact test of the same curve. Every \
         path is re-checked every 0.001 (poses free, the heading turning no tighter than the radius, ends exact). \
         Length is over the shortest path any planner found for the query in the same space; Hybrid A* weighs \
         reversing and turning, so its paths are not the shortest it could find.\n\n",
        maps.join(", "),
        HYBRID_LIMIT.as_secs()
    );
    s.push_str(&table(
        "| world | planner | space | queries | solved | median ms | p90 ms | median length / shortest | median cusps | invalid |",
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|",
        &report.rows,
        |r| {
            format!(
                "| {} | {} | {} | {} | {} | {:.2} | {:.2} | {:.3} | {:.0} | {} |",
                r.world,
                r.planner,
                r.space,
                r.queries,
                r.solved,
                r.median_ms,
                r.p90_ms,
                r.median_length_ratio,
                r.median_cusps,
                r.invalid
            )
        },
    ));
    let row = |world: &str, planner: &str| {
        report.rows.iter().find(|r| r.world == world && r.planner == planner && r.space == "reeds_shepp")
    };
    let mut side = String::new();
    for (world, _) in &report.map_ms {
        if let (Some(ours), Some(theirs)) = (row(world, "RRT-Connect"), row(world, "OMPL RRTConnect")) {
            side.push_str(&format!(
                "| {world} | {:.1}x | {} / {} of {} |",
                theirs.median_ms / ours.median_ms,
                ours.solved,
                theirs.solved,
                ours.queries
            ));
            match (row(world, "RRT*"), row(world, "OMPL RRTstar")) {
                (Some(ours), Some(theirs)) => side.push_str(&format!(
                    " {:.3} / {:.3} |\n",
                    ours.median_length_ratio, theirs.median_length_ratio
                )),
                _ => side.push_str(" - |\n"),
            }
        }
    }
    if !side.is_empty() {
        s.push_str(&format!(
            "\nIn the Reeds-Shepp space beside OMPL {}: RRT-Connect's speedup (OMPL's median time over trailmark's) \
             with both libraries' solved queries, and RRT*'s median length over the shortest after the same time \
             (trailmark / OMPL).\n\n| world | RRT-Connect speedup | solved (trailmark / OMPL) | RRT* length (trailmark / OMPL) |\n\
             |---|---:|---:|---:|\n{side}",
            report.ompl_version.as_deref().unwrap_or("")
        ));
    }
    for (space, med, largest, n) in &report.hybrid_over_star {
        s.push_str(&format!(
            "\nHybrid A*'s length over RRT*'s ({space}, {n} queries both solved): median {med:.3}, largest {largest:.3}.\n"
        ));
    }
    s
}
