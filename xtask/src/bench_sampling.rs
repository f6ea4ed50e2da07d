//! The sampling section of `cargo xtask bench`: RRT's and RRT-Connect's success rate and
//! speed, and RRT*'s convergence, on generated polygon worlds (random convex obstacles, a bug
//! trap, walls with narrow doors), each path checked against the visibility graph's shortest
//! one.
//!
//! The reference optimum is the visibility graph of the obstacles grown by the robot radius
//! with round corners in steps of π/64 (chords outside the exact discs: at most 0.03% longer
//! than the true optimum around each corner). Every returned path is re-checked exactly (each
//! motion against the grown obstacles), must start and end where asked, and may not beat that
//! optimum by more than its approximation allows; a path that fails either is an error that
//! fails the run.

use std::time::Duration;

use plotters::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::freespace::Location;
use trailmark::core::generate;
use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::core::world::{CollisionChecker, PolygonWorld};
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::prelude::*;
use trailmark::sample::{Bridge, KdNearest, Plan, Planner, Problem, R2, Rrt, RrtConnect, RrtStar};

use crate::bench::{Suite, median};
use crate::ompl::Driver;
use crate::plots::{BoxSeries, COLOURS, SuccessLine, box_plot_svg, success_svg};
use trailmark::sample::benchmark::{Experiment, PlannerRuns, RunRecord, benchmark};

/// The side of the square worlds.
const SIZE: f64 = 40.0;
/// The robot's radius.
const ROBOT_RADIUS: f64 = 0.25;
/// The width of a door of the narrow-passage worlds (free width: 1.0, 2.5% of the side).
const DOOR: f64 = 1.5;
/// RRT-Connect's iteration limit per query (the figure).
const CONNECT_ITERATIONS: u64 = 10_000;
/// The least share of solvable queries RRT-Connect must solve.
const CONNECT_GOAL: f64 = 0.99;
/// The bridge-test sampler's partner distance for RRT-Connect (bridge): about the distance
/// across a door from wall to wall (1.0 free, 1.3 of grown wall each side). Chosen by a sweep
/// on narrow-6 (1,000 queries: 0.5 -> 93.5% of 200, 1.0 -> 99.9%, 2.0 -> 100%, 3.0 -> 99.8%);
/// `docs/sample.md` has the figures.
const BRIDGE_STD_DEV: f64 = 2.0;
/// RRT*'s iterations per run (the figure).
const STAR_ITERATIONS: u64 = 20_000;
/// The goal for RRT*'s median cost after its iterations, over the optimum.
const STAR_GOAL: f64 = 1.05;
/// Where RRT*'s best cost is read for the convergence plot.
const CHECKPOINTS: [u64; 8] = [250, 500, 1_000, 2_000, 5_000, 10_000, 15_000, 20_000];
/// The round corners of the reference free space, in radians per chord.
const ARC_STEP: f64 = std::f64::consts::PI / 64.0;

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
    /// The name in `--only`, the JSON results and the OMPL driver's input.
    pub fn name(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "rrt",
            SingleQuery::RrtConnect => "rrt_connect",
            SingleQuery::RrtConnectBridge => "rrt_connect_bridge",
        }
    }

    /// The name in text, and (without the dash) in the OMPL logs.
    fn label(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "RRT",
            SingleQuery::RrtConnect => "RRT-Connect",
            SingleQuery::RrtConnectBridge => "RRT-Connect (bridge)",
        }
    }

    fn ompl_label(self) -> &'static str {
        match self {
            SingleQuery::Rrt => "RRT",
            SingleQuery::RrtConnect => "RRTConnect",
            SingleQuery::RrtConnectBridge => "RRTConnectBridge",
        }
    }

    /// Whether OMPL runs the same planner beside it.
    fn in_ompl(self) -> bool {
        self != SingleQuery::RrtConnectBridge
    }
}

/// The worlds where RRT-Connect also plans for a Dubins car.
const DUBINS_WORLDS: [&str; 2] = ["convex-30", "bug-trap"];

/// The sampling planners `--only` can name, and `boxes` for the Rⁿ box worlds.
pub const PLANNERS: [&str; 6] =
    ["rrt", "rrt_connect", "rrt_connect_bridge", "rrt_star", crate::bench_prm::NAME, "boxes"];

/// A generated world and how its queries are drawn.
pub(crate) struct World {
    pub(crate) name: String,
    pub(crate) world: PolygonWorld,
    /// The world's exact checker, built once.
    pub(crate) checker: CollisionChecker,
    ends: Ends,
    visibility: VisibilityGraph,
}

/// Where a world's queries start and end.
#[derive(Clone, Copy)]
enum Ends {
    /// Anywhere free.
    Anywhere,
    /// From this point inside the trap to anywhere free outside its square.
    OutOfTrap(Point),
    /// From left of the first wall to right of the last.
    Across { walls: usize },
}

impl World {
    fn new(name: String, world: PolygonWorld, ends: Ends) -> Result<Self, String> {
        let space = world.free_space_with_step(ARC_STEP).map_err(|e| format!("{name}: {e}"))?;
        let visibility = VisibilityGraph::with_edges(space, Edges::Tangent);
        Ok(World { name, checker: world.checker(), world, ends, visibility })
    }

    /// `n` seeded queries whose ends are free, with their shortest cost (`None`: no path).
    fn queries(&self, n: usize, seed: u64) -> Result<Vec<(Point, Point, Option<f64>)>, String> {
        let checker = &self.checker;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut free = |ok: &dyn Fn(Point) -> bool| loop {
            let p = Point::new(rng.random_range(0.0..SIZE), rng.random_range(0.0..SIZE));
            if ok(p) && checker.point_is_free(p) && self.visibility.space().locate(p) != Location::Blocked {
                return p;
            }
        };
        let mut out = Vec::with_capacity(n);
        for _ in 0..n {
            let (a, b) = match self.ends {
                Ends::Anywhere => (free(&|_| true), free(&|_| true)),
                Ends::OutOfTrap(inside) => {
                    let outside = |p: Point| (p.x - inside.x).abs().max((p.y - inside.y).abs()) > SIZE * 0.3;
                    (inside, free(&outside))
                }
                Ends::Across { walls } => {
                    let gap = SIZE / (walls + 1) as f64 - SIZE / 50.0;
                    (free(&|p: Point| p.x < gap), free(&|p: Point| p.x > SIZE - gap))
                }
            };
            let query = self.visibility.query(a, b).map_err(|e| format!("{}: {e}", self.name))?;
            let found = astar(&query, query.start(), query.goal(), query.heuristic())
                .map_err(|e| format!("{}: {e}", self.name))?;
            out.push((a, b, found.cost()));
        }
        Ok(out)
    }

    /// One seeded RRT* run from `a` to `b` until `termination`, and its record for the log
    /// (with the run's peak memory).
    fn star_run(
        &self,
        a: Point,
        b: Point,
        termination: &Termination,
        seed: u64,
    ) -> Result<(Plan<Point>, RunRecord), String> {
        let space = R2::new(self.world.bounds());
        let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
        let problem = Problem::new(&space, &self.checker, a, b);
        let probe = crate::memory::Probe::default();
        let mut runs = benchmark(&mut RrtStar::new(nearest), &problem, termination, 1, seed, Some(&probe))
            .map_err(|e| format!("{}: {e}", self.name))?;
        Ok((runs.plans.remove(0), runs.runs.remove(0)))
    }

    /// Whether `plan` is a valid path from `a` to `b` no shorter than the reference allows.
    fn checks(&self, plan: &Plan<Point>, a: Point, b: Point, best: f64) -> bool {
        plan.path().is_some_and(|path| self.checks_path(path, a, b, best))
    }

    /// Whether `path` runs from `a` to `b`, every motion free, no shorter than the reference
    /// allows (its cost recomputed here).
    fn checks_path(&self, path: &[Point], a: Point, b: Point, best: f64) -> bool {
        self.checked_cost(path, a, b, best).is_some()
    }

    /// The length of `path`, recomputed here, when it passes [`World::checks_path`].
    pub(crate) fn checked_cost(&self, path: &[Point], a: Point, b: Point, best: f64) -> Option<f64> {
        let cost: f64 = path.windows(2).map(|m| (m[1] - m[0]).norm()).sum();
        let valid = path.first() == Some(&a)
            && path.last() == Some(&b)
            && path.windows(2).all(|m| self.checker.segment_is_free(m[0], m[1]))
            && cost >= best * (ARC_STEP / 2.0).cos();
        valid.then_some(cost)
    }
}

/// The worlds of the section.
fn worlds(seed: u64) -> Result<Vec<World>, String> {
    let e = |e: generate::GenerateError| e.to_string();
    let (trap, inside) = generate::bug_trap(SIZE, ROBOT_RADIUS).map_err(e)?;
    let convex =
        |count: usize, s: u64| generate::convex_obstacles(SIZE, count, 6, ROBOT_RADIUS, s).map_err(e);
    Ok(vec![
        World::new("convex-30".into(), convex(30, seed)?, Ends::Anywhere)?,
        World::new("convex-60".into(), convex(60, seed + 1)?, Ends::Anywhere)?,
        World::new("bug-trap".into(), trap, Ends::OutOfTrap(inside))?,
        World::new(
            "narrow-3".into(),
            generate::narrow_passages(SIZE, 3, DOOR, ROBOT_RADIUS, seed).map_err(e)?,
            Ends::Across { walls: 3 },
        )?,
        World::new(
            "narrow-6".into(),
            generate::narrow_passages(SIZE, 6, DOOR, ROBOT_RADIUS, seed + 1).map_err(e)?,
            Ends::Across { walls: 6 },
        )?,
    ])
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

/// One library's RRT-Connect on a world's queries.
#[derive(Debug, Clone, Serialize)]
pub struct ConnectStats {
    /// Solvable queries solved within the iterations.
    pub solved: usize,
    /// Median time per solvable query (failures included), milliseconds.
    pub median_ms: f64,
    /// Median iterations per solvable query.
    pub median_iterations: f64,
    /// Median collision checks per solvable query.
    pub median_checks: f64,
    /// Median path cost over the optimum.
    pub median_cost_ratio: f64,
    /// Paths that failed the re-check, or solutions where the visibility graph has no path
    /// (must be 0).
    pub invalid: usize,
    /// The time of each solvable query, milliseconds, sorted (for the plots; not serialized).
    #[serde(skip)]
    pub times_ms: Vec<f64>,
    /// The time of each solved query, milliseconds (for the plots; not serialized).
    #[serde(skip)]
    pub solved_ms: Vec<f64>,
}

/// Runs of one planner on a world's queries, as they come.
#[derive(Default)]
pub(crate) struct Tally {
    times: Vec<f64>,
    solved_times: Vec<f64>,
    iterations: Vec<f64>,
    checks: Vec<f64>,
    ratios: Vec<f64>,
    pub(crate) solvable: usize,
    solved: usize,
    invalid: usize,
}

impl Tally {
    /// One run on a query of optimum `best` (`None`: no path): its time, iterations and checks,
    /// whether it found an exact path, and `cost_if_valid`, the re-checked path's cost or
    /// `None` when it fails the re-check.
    pub(crate) fn add(
        &mut self,
        best: Option<f64>,
        (ms, iterations, checks): (f64, u64, u64),
        exact: bool,
        cost_if_valid: impl FnOnce(f64) -> Option<f64>,
    ) {
        let Some(best) = best else {
            // No path by the visibility graph: a solution here would be an error of one of them.
            self.invalid += usize::from(exact);
            return;
        };
        self.solvable += 1;
        self.times.push(ms);
        self.iterations.push(iterations as f64);
        self.checks.push(checks as f64);
        if !exact {
            return;
        }
        self.solved += 1;
        self.solved_times.push(ms);
        match cost_if_valid(best) {
            Some(cost) => self.ratios.push(cost / best),
            None => self.invalid += 1,
        }
    }

    pub(crate) fn stats(self) -> ConnectStats {
        let times = sorted(self.times);
        ConnectStats {
            solved: self.solved,
            median_ms: median(&times),
            median_iterations: median(&sorted(self.iterations)),
            median_checks: median(&sorted(self.checks)),
            median_cost_ratio: median(&sorted(self.ratios)),
            invalid: self.invalid,
            times_ms: times,
            solved_ms: self.solved_times,
        }
    }
}

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

/// The sampling section's results.
#[derive(Debug, Clone, Serialize)]
pub struct SamplingReport {
    /// RRT-Connect per world.
    pub connect: Vec<ConnectRow>,
    /// RRT* per world.
    pub star: Vec<StarRow>,
    /// PRM* per world.
    pub prm: Vec<crate::bench_prm::PrmRow>,
    /// RRT-Connect for the Dubins car and the arm.
    pub spaces: Vec<crate::bench_spaces::SpaceRow>,
    /// RRT* of trailmark and OMPL with equal time (with `--with-ompl`).
    pub equal_time: Vec<EqualTimeRow>,
    /// How far past a time limit each planner returns.
    pub limits: Vec<crate::bench_limits::LimitRow>,
    /// Rⁿ among random boxes.
    pub boxes: Vec<crate::bench_boxes::BoxRow>,
    /// The OMPL version measured (with `--with-ompl`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ompl_version: Option<String>,
    /// The section's plots: file name and SVG (not serialized).
    #[serde(skip)]
    pub figures: Vec<(&'static str, String)>,
    /// Every run, one experiment per world, for the OMPL-format logs (not serialized).
    #[serde(skip)]
    pub logs: Vec<Experiment>,
}

impl SamplingReport {
    /// Paths that failed their re-check.
    pub fn errors(&self) -> usize {
        self.connect
            .iter()
            .map(|r| r.trailmark.invalid + r.ompl.as_ref().map_or(0, |o| o.invalid))
            .sum::<usize>()
            + self.star.iter().map(|r| r.invalid).sum::<usize>()
            + self.equal_time.iter().map(|r| r.invalid).sum::<usize>()
            + self.spaces.iter().map(|r| r.stats.invalid).sum::<usize>()
            + self.boxes.iter().map(|r| r.invalid).sum::<usize>()
            + self
                .prm
                .iter()
                .map(|r| r.trailmark.invalid + r.ompl.as_ref().map_or(0, |o| o.invalid))
                .sum::<usize>()
    }
}

fn sorted(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v
}

/// Runs the section.
pub fn bench_sampling(
    suite: Suite,
    seed: u64,
    ompl: Option<&Driver>,
    date: &str,
    only: &[String],
) -> Result<SamplingReport, String> {
    let (queries, star_runs, equal_time, prm_samples, space_queries) = match suite {
        Suite::Quick => (200, 5, Duration::from_millis(500), 2000, 100),
        Suite::Full => (1000, 15, Duration::from_secs(2), 5000, 500),
    };
    let worlds = worlds(seed)?;
    let wanted = |name: &str| only.is_empty() || only.iter().any(|o| o == name);
    let singles: Vec<SingleQuery> =
        [SingleQuery::RrtConnect, SingleQuery::RrtConnectBridge, SingleQuery::Rrt]
            .into_iter()
            .filter(|p| wanted(p.name()))
            .collect();
    let with_star = wanted("rrt_star");
    let with_prm = wanted(crate::bench_prm::NAME);
    let mut prm = Vec::new();
    let mut spaces = Vec::new();
    let mut connect = Vec::new();
    let mut star = Vec::new();
    let mut equal_times = Vec::new();
    let mut logs = Vec::new();
    let mut progress = crate::progress::Progress::new("sampling", worlds.len());
    for w in &worlds {
        progress.step(format!("{}: {queries} queries", w.name));
        let qs = w.queries(queries, seed ^ 0x5a5a)?;
        let mut planners = Vec::new();
        for &planner in &singles {
            progress.note(format!("{}: {}, {queries} queries", w.name, planner.label()));
            let mut row = bench_connect(planner, w, &qs, seed, &mut planners)?;
            if let Some(driver) = ompl.filter(|_| planner.in_ompl()) {
                progress.note(format!("{}: OMPL {}, {queries} queries", w.name, planner.ompl_label()));
                row.ompl = Some(ompl_connect(planner, w, &qs, seed, driver, &mut planners)?);
            }
            connect.push(row);
        }
        if wanted(SingleQuery::RrtConnect.name()) && DUBINS_WORLDS.contains(&w.name.as_str()) {
            progress.note(format!("{}: RRT-Connect for a Dubins car, {space_queries} queries", w.name));
            spaces.push(crate::bench_spaces::bench_dubins(w, &qs[..space_queries.min(qs.len())], seed)?);
        }
        if with_prm {
            progress.note(format!("{}: PRM*, {prm_samples} samples, {queries} queries", w.name));
            prm.push(crate::bench_prm::bench_prm(w, &qs, prm_samples, seed, ompl)?);
        }
        if !with_star {
            logs.push(experiment(w, planners, queries, seed, date, None));
            continue;
        }
        progress.note(format!("{}: RRT*, {star_runs} runs of {STAR_ITERATIONS}", w.name));
        // For RRT*: the longest of the first ten queries that have a path.
        let &(a, b, best) = qs
            .iter()
            .take(10)
            .filter(|q| q.2.is_some())
            .max_by(|x, y| x.2.unwrap_or(0.0).total_cmp(&y.2.unwrap_or(0.0)))
            .ok_or_else(|| format!("{}: no solvable query", w.name))?;
        let best = best.unwrap_or(f64::NAN);
        star.push(bench_star(w, a, b, best, star_runs, seed, &mut planners)?);
        if let Some(driver) = ompl {
            progress.note(format!(
                "{}: RRT* of both libraries, {star_runs} runs of {:.1} s each",
                w.name,
                equal_time.as_secs_f64()
            ));
            equal_times.push(star_equal_time(
                w,
                a,
                b,
                best,
                star_runs,
                equal_time,
                seed,
                driver,
                &mut planners,
            )?);
        }
        logs.push(experiment(w, planners, queries, seed, date, Some((a, b, best))));
    }
    if wanted(SingleQuery::RrtConnect.name()) {
        progress.note(format!("RRT-Connect for the 3-link arm, {space_queries} queries"));
        spaces.push(crate::bench_spaces::bench_arm(space_queries, seed)?);
    }
    let limits = if only.is_empty() {
        progress
            .note(format!("time limits: every planner, {} ms each", crate::bench_limits::LIMIT.as_millis()));
        crate::bench_limits::bench_limits(seed)?
    } else {
        Vec::new()
    };
    let boxes = if wanted("boxes") {
        progress.note("R4 and R8 among random boxes");
        let box_queries = match suite {
            Suite::Quick => 50,
            Suite::Full => 200,
        };
        crate::bench_boxes::bench_boxes((box_queries, star_runs, Duration::from_millis(250)), seed, ompl)?
    } else {
        Vec::new()
    };
    let mut figures = Vec::new();
    if !star.is_empty() {
        figures.push(("sampling-convergence.svg", convergence_svg(&star)?));
    }
    if !connect.is_empty() {
        figures.extend(connect_figures(&connect)?);
    }
    Ok(SamplingReport {
        connect,
        star,
        prm,
        spaces,
        equal_time: equal_times,
        limits,
        boxes,
        ompl_version: ompl.map(|d| d.version.clone()),
        figures,
        logs,
    })
}

/// One world's runs as an experiment of the OMPL log; `star` is RRT*'s query and optimum
/// when it ran.
fn experiment(
    w: &World,
    planners: Vec<PlannerRuns>,
    queries: usize,
    seed: u64,
    date: &str,
    star: Option<(Point, Point, f64)>,
) -> Experiment {
    let star = star.map_or(String::new(), |(a, b, best)| {
        format!(
            "; RRT* on the query ({:.3}, {:.3}) -> ({:.3}, {:.3}) whose shortest path is {best:.6}",
            a.x, a.y, b.x, b.y
        )
    });
    Experiment {
        name: w.name.clone(),
        setup: format!(
            "{}: {SIZE} x {SIZE} polygon world, robot radius {ROBOT_RADIUS}; RRT and RRT-Connect on {queries} \
             seeded queries (at most {CONNECT_ITERATIONS} iterations each){star}",
            w.name
        ),
        seed,
        time_limit_s: 60.0,
        date: date.to_string(),
        planners,
    }
}

fn bench_connect(
    planner: SingleQuery,
    w: &World,
    queries: &[(Point, Point, Option<f64>)],
    seed: u64,
    log: &mut Vec<PlannerRuns>,
) -> Result<ConnectRow, String> {
    let space = R2::new(w.world.bounds());
    let checker = &w.checker;
    let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
    let limit = Termination::iterations(CONNECT_ITERATIONS);
    let bridge = Bridge::new(BRIDGE_STD_DEV).map_err(|e| e.to_string())?;
    let mut tally = Tally::default();
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

/// The points of a path as the OMPL driver prints it.
pub(crate) fn points(path: &[Vec<f64>]) -> Vec<Point> {
    path.iter().map(|p| Point::new(p[0], p[1])).collect()
}

/// The queries as the OMPL driver reads them: `[ax, ay, bx, by]` each.
pub(crate) fn ompl_queries(queries: &[(Point, Point, Option<f64>)]) -> Vec<Vec<f64>> {
    queries.iter().map(|(a, b, _)| vec![a.x, a.y, b.x, b.y]).collect()
}

/// An OMPL run for the OMPL-format log.
fn ompl_log_run(run: &crate::ompl::Run) -> RunRecord {
    RunRecord {
        time_s: run.time_s,
        solved: run.exact(),
        approximate: run.status == "approximate",
        memory_bytes: None,
        graph_states: run.states,
        solution_length: run.cost.filter(|_| run.exact()),
        iterations: run.iterations,
        collision_checks: run.collision_checks,
        progress: run.improvements.clone(),
        ..RunRecord::default()
    }
}

/// OMPL's RRTConnect on the same queries, with the same iteration limit, each path re-checked
/// as trailmark's are.
fn ompl_connect(
    planner: SingleQuery,
    w: &World,
    queries: &[(Point, Point, Option<f64>)],
    seed: u64,
    driver: &Driver,
    log: &mut Vec<PlannerRuns>,
) -> Result<ConnectStats, String> {
    let input = crate::ompl::Input {
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
    let mut tally = Tally::default();
    let runs = driver.run(&input).map_err(|e| format!("{}: {e}", w.name))?;
    log.push(PlannerRuns {
        name: format!("OMPL_{}", planner.ompl_label()),
        optimizing: false,
        runs: runs.iter().map(ompl_log_run).collect(),
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

/// The best cost at `t` seconds of a run whose improvements are `(seconds, cost)`.
fn cost_at(improvements: &[(f64, f64)], t: f64) -> f64 {
    improvements.iter().take_while(|i| i.0 <= t).last().map_or(f64::INFINITY, |i| i.1)
}

/// RRT* of trailmark and of OMPL on one query, `runs` runs each of `limit`, with the median
/// final cost and the median best cost over time.
#[allow(clippy::too_many_arguments)]
fn star_equal_time(
    w: &World,
    a: Point,
    b: Point,
    best: f64,
    runs: usize,
    limit: Duration,
    seed: u64,
    driver: &Driver,
    log: &mut Vec<PlannerRuns>,
) -> Result<EqualTimeRow, String> {
    let termination = Termination::time(limit);
    let mut invalid = 0;
    let mut ours: Vec<(f64, Vec<(f64, f64)>)> = Vec::new();
    let mut our_iterations = Vec::new();
    let mut our_log = Vec::new();
    for run in 0..runs {
        let (plan, logged) = w.star_run(a, b, &termination, seed + run as u64)?;
        invalid += usize::from(plan.is_exact() && !w.checks(&plan, a, b, best));
        our_iterations.push(plan.stats.iterations as f64);
        let cost = plan.cost().unwrap_or(f64::INFINITY);
        ours.push((cost, logged.progress.clone()));
        our_log.push(logged);
    }
    let input = crate::ompl::Input {
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
        runs: their_runs.iter().map(ompl_log_run).collect(),
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

#[allow(clippy::too_many_arguments)]
fn bench_star(
    w: &World,
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
        let (plan, logged) = w.star_run(a, b, &limit, seed + run as u64)?;
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

/// A line of a plot: its legend, colour, whether dashed, and points.
struct Line {
    label: String,
    colour: RGBColor,
    dashed: bool,
    points: Vec<(f64, f64)>,
}

/// Cost over the optimum against a log-scaled x axis, one line each, with the 5% goal.
fn lines_svg(caption: &str, x_desc: &str, x: (f64, f64), lines: &[Line]) -> Result<String, String> {
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
        let goal = RGBColor(120, 120, 120);
        chart
            .draw_series(LineSeries::new([(x.0, STAR_GOAL), (x.1, STAR_GOAL)], goal.stroke_width(1)))
            .map_err(|x| e(&x))?
            .label("goal: 5% above the optimum")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], goal.stroke_width(1)));
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

/// RRT-Connect's time per query as box plots, and its success by time, trailmark's beside
/// OMPL's when it ran.
fn connect_figures(rows: &[ConnectRow]) -> Result<Vec<(&'static str, String)>, String> {
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

/// Median RRT* cost over the optimum against iterations, one line per world (log x axis).
fn convergence_svg(rows: &[StarRow]) -> Result<String, String> {
    let lines: Vec<Line> = rows
        .iter()
        .zip(COLOURS.iter().cycle())
        .map(|(row, &colour)| Line {
            label: row.world.clone(),
            colour,
            dashed: false,
            points: row.convergence.iter().map(|&(i, c)| (i as f64, c)).collect(),
        })
        .collect();
    let x = (CHECKPOINTS[0] as f64, CHECKPOINTS[CHECKPOINTS.len() - 1] as f64);
    lines_svg("RRT*: median path cost over the optimum, by iterations", "iterations", x, &lines)
}

/// Median best cost over the optimum against time, trailmark solid and OMPL dashed.
pub fn cost_time_svg(rows: &[EqualTimeRow]) -> Result<String, String> {
    let mut lines = Vec::new();
    for (row, &colour) in rows.iter().zip(COLOURS.iter().cycle()) {
        let series = |ompl: bool| row.over_time.iter().map(move |&(t, a, b)| (t, if ompl { b } else { a }));
        lines.push(Line {
            label: format!("{} trailmark", row.world),
            colour,
            dashed: false,
            points: series(false).collect(),
        });
        lines.push(Line {
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
        &lines,
    )
}

/// The section of the report.
pub fn markdown(report: &SamplingReport) -> String {
    let mut s = String::from("## Sampling planners\n\n");
    s.push_str(&format!(
        "Generated {SIZE} x {SIZE} worlds, robot radius {ROBOT_RADIUS}: random convex hexagons, a bug \
         trap (queries from inside it), and walls with doors {DOOR} wide (free width {}). Reference \
         costs: the visibility graph with corners in steps of π/64. Every path is re-checked exactly.\n\n",
        DOOR - 2.0 * ROBOT_RADIUS
    ));
    if !report.connect.is_empty() {
        s.push_str(&connect_markdown(report));
    }
    s.push_str(&crate::bench_spaces::markdown(&report.spaces));
    s.push_str(&crate::bench_prm::markdown(&report.prm, report.ompl_version.as_deref()));
    if !report.star.is_empty() {
        s.push_str(&star_markdown(&report.star));
    }
    if !report.equal_time.is_empty() {
        s.push_str(&equal_time_markdown(report));
    }
    s.push_str(&crate::bench_boxes::markdown(&report.boxes));
    s.push_str(&crate::bench_limits::markdown(&report.limits));
    s
}

/// The RRT* table and its goal.
fn star_markdown(rows: &[StarRow]) -> String {
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

/// The goal for RRT-Connect against OMPL's RRTConnect: at least this much faster.
const CONNECT_SPEEDUP_GOAL: f64 = 2.0;

/// The RRT-Connect table, OMPL's rows beside trailmark's when it ran, and the goals.
fn connect_markdown(report: &SamplingReport) -> String {
    let with_ompl = report.connect.iter().any(|r| r.ompl.is_some());
    let mut s =
        format!("### RRT and RRT-Connect ({CONNECT_ITERATIONS} iterations at most, default range)\n\n");
    if with_ompl {
        s.push_str(&format!(
            "Beside OMPL {} RRT and RRTConnect: the same queries, the same iteration limit, default ranges \
             (0.2 x the space's extent in both), both validating states and motions with trailmark's \
             exact checker (OMPL through a C interface, so each collision question costs both the same). \
             OMPL's time is `Planner::solve` alone; trailmark's includes building its trees.\n\n",
            report.ompl_version.as_deref().unwrap_or("?")
        ));
    }
    s.push_str(
        "| world | planner | library | queries | solvable | solved | median ms | median iterations | median checks | median cost / optimum | invalid | speedup (OMPL / trailmark) |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in &report.connect {
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
    let rows = |planner| report.connect.iter().filter(move |r: &&ConnectRow| r.planner == planner);
    let connect: Vec<&ConnectRow> = rows(SingleQuery::RrtConnect).collect();
    for planner in [SingleQuery::RrtConnect, SingleQuery::RrtConnectBridge] {
        let of: Vec<&ConnectRow> = rows(planner).collect();
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

/// The RRT* comparison with OMPL at equal time.
fn equal_time_markdown(report: &SamplingReport) -> String {
    let version = report.ompl_version.as_deref().unwrap_or("?");
    let mut s = format!(
        "\n### RRT* beside OMPL {version} RRTstar at equal time\n\nThe query of the table above, the \
         same time for every run of both (default settings: k-nearest rewiring, range 0.2 x extent, \
         goal bias 0.05), the exact checker in both. Cost is the final path's over the optimum.\n\n\
         | world | s/run | runs | trailmark median cost / optimum | OMPL median cost / optimum | trailmark iterations | OMPL iterations | invalid |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|\n"
    );
    for r in &report.equal_time {
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
