//! The sampling section: RRT's and RRT-Connect's success rate and speed, RRT*'s convergence and
//! PRM*'s roadmaps on generated polygon worlds, each path checked against the visibility graph's
//! shortest one (see [`world`]); RRT-Connect for a planar arm; Rⁿ among random
//! boxes; and how far past a time limit every planner returns. With `--with-ompl`, OMPL's
//! planners beside trailmark's on the same problems.
//!
//! A path that fails its re-check is an error that fails the run.

mod boxes;
mod connect;
mod limits;
mod nearest;
mod optimal;
mod prm;
mod spaces;
mod star;
mod tally;
mod world;

use std::time::Duration;

use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::sample::benchmark::{Experiment, PlannerRuns};

use crate::bench::ompl::OmplDriver;
use crate::bench::progress::SectionProgress;
use crate::bench::report::{Figure, GoalRow};
use crate::bench::suite::Suite;
use boxes::BoxRow;
use connect::{CONNECT_ITERATIONS, ConnectRow, SingleQuery};
use limits::LimitRow;
use nearest::NearestRow;
use optimal::OptimalRow;
use prm::PrmRow;
use spaces::SpaceRow;
use star::{EqualTimeRow, STAR_ITERATIONS, StarRow};
use world::{DOOR, ROBOT_RADIUS, SIZE, SamplingWorld, worlds};

/// The names `--only` can give the section: its single-query planners, RRT*, PRM*, `boxes` for
/// the Rⁿ box worlds, and `nearest` for nearest neighbours alone.
pub fn planner_names() -> Vec<&'static str> {
    SingleQuery::ALL
        .iter()
        .map(|p| p.name())
        .chain([star::NAME, prm::NAME, boxes::NAME, nearest::NAME])
        .collect()
}

/// The registry's planners this section measures: its single-query planners, RRT*, PRM* (its
/// own rows and the box worlds'), PRM, Lazy PRM and Lazy PRM* (the time limits' rows; Lazy
/// PRM* also the box worlds') and the optimizing planners at equal time.
pub fn measured() -> impl Iterator<Item = trailmark::solve::PlannerName> {
    use trailmark::solve::PlannerName;
    let named = [star::NAME, prm::NAME].into_iter().filter_map(PlannerName::from_name);
    SingleQuery::ALL
        .iter()
        .map(|p| p.planner())
        .chain(named)
        .chain([PlannerName::Prm, PlannerName::LazyPrm, PlannerName::LazyPrmStar])
        .chain(optimal::MEASURED)
}

/// The sampling section's results.
#[derive(Debug, Clone, Serialize)]
pub struct SamplingReport {
    /// RRT-Connect per world.
    pub connect: Vec<ConnectRow>,
    /// RRT* per world.
    pub star: Vec<StarRow>,
    /// PRM* per world.
    pub prm: Vec<PrmRow>,
    /// RRT-Connect for the arm.
    pub spaces: Vec<SpaceRow>,
    /// RRT* of trailmark and OMPL with equal time (with `--with-ompl`).
    pub equal_time: Vec<EqualTimeRow>,
    /// The optimizing planners at equal time.
    pub optimal: Vec<OptimalRow>,
    /// How far past a time limit each planner returns.
    pub limits: Vec<LimitRow>,
    /// Rⁿ among random boxes.
    pub boxes: Vec<BoxRow>,
    /// Nearest neighbours in a connect phase's order.
    pub nearest: Vec<NearestRow>,
    /// The OMPL version measured (with `--with-ompl`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ompl_version: Option<String>,
    /// The section's plots: file name and SVG (not serialized).
    #[serde(skip)]
    pub figures: Vec<Figure>,
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
            + self.optimal.iter().map(|r| r.invalid).sum::<usize>()
            + self.spaces.iter().map(|r| r.stats.invalid).sum::<usize>()
            + self.boxes.iter().map(|r| r.invalid).sum::<usize>()
            + self
                .prm
                .iter()
                .map(|r| r.trailmark.invalid + r.ompl.as_ref().map_or(0, |o| o.invalid))
                .sum::<usize>()
    }
}

/// The section's goals against OMPL for the report's goals table (unmeasured without it).
pub fn goals(report: Option<&SamplingReport>) -> [GoalRow; 4] {
    [
        connect::goal(report.map_or(&[], |r| &r.connect)),
        nearest::goal(report.map_or(&[], |r| &r.nearest)),
        star::goal(report.map_or(&[], |r| &r.equal_time)),
        optimal::goal(report.map_or(&[], |r| &r.optimal)),
    ]
}

/// How much the section runs: seeded queries per world, RRT* runs per world, the time of each
/// equal-time RRT* run, PRM* samples, queries in the other state spaces, box-world queries.
struct Sizes {
    queries: usize,
    star_runs: usize,
    equal_time: Duration,
    prm_samples: usize,
    space_queries: usize,
    box_queries: usize,
    /// Whether the nearest-neighbour peers also run 100,000 states along a line (seconds each).
    peers_on_long_lines: bool,
}

impl Sizes {
    fn of(suite: Suite) -> Sizes {
        match suite {
            Suite::Quick => Sizes {
                queries: 200,
                star_runs: 5,
                equal_time: Duration::from_millis(500),
                prm_samples: 2000,
                space_queries: 100,
                box_queries: 50,
                peers_on_long_lines: false,
            },
            Suite::Full => Sizes {
                queries: 1000,
                star_runs: 15,
                equal_time: Duration::from_secs(2),
                prm_samples: 5000,
                space_queries: 500,
                box_queries: 200,
                peers_on_long_lines: true,
            },
        }
    }
}

/// Runs the section: the planners `only` names (all of them when it names none), beside OMPL's
/// when `ompl` is given; `date` goes into the OMPL-format logs.
pub fn bench(
    suite: Suite,
    seed: u64,
    ompl: Option<&OmplDriver>,
    date: &str,
    only: &[String],
) -> Result<SamplingReport, String> {
    let size = Sizes::of(suite);
    let queries = size.queries;
    let worlds = worlds(seed)?;
    let wanted = |name: &str| only.is_empty() || only.iter().any(|o| o == name);
    let singles: Vec<SingleQuery> = SingleQuery::ALL.into_iter().filter(|p| wanted(p.name())).collect();
    let with_star = wanted(star::NAME);
    let with_prm = wanted(prm::NAME);
    let mut prm = Vec::new();
    let mut spaces = Vec::new();
    let mut connect = Vec::new();
    let mut star = Vec::new();
    let mut equal_times = Vec::new();
    let mut optimal = Vec::new();
    let mut logs = Vec::new();
    let mut progress = SectionProgress::new("sampling", worlds.len());
    for w in &worlds {
        progress.step(format!("{}: {queries} queries", w.name));
        let qs = w.queries(queries, seed ^ 0x5a5a)?;
        let mut planners = Vec::new();
        for &planner in &singles {
            progress.note(format!("{}: {}, {queries} queries", w.name, planner.label()));
            let mut row = connect::bench_connect(planner, w, &qs, seed, &mut planners)?;
            if let Some(driver) = ompl.filter(|_| planner.in_ompl()) {
                progress.note(format!("{}: OMPL {}, {queries} queries", w.name, planner.ompl_label()));
                row.ompl = Some(connect::ompl_connect(planner, w, &qs, seed, driver, &mut planners)?);
            }
            connect.push(row);
        }
        if with_prm {
            progress.note(format!("{}: PRM*, {} samples, {queries} queries", w.name, size.prm_samples));
            prm.push(prm::bench_prm(w, &qs, size.prm_samples, seed, ompl)?);
        }
        if !with_star {
            logs.push(experiment(w, planners, queries, seed, date, None));
            continue;
        }
        let star_runs = size.star_runs;
        progress.note(format!("{}: RRT*, {star_runs} runs of {STAR_ITERATIONS}", w.name));
        let (a, b, best) = star::star_query(w, &qs)?;
        star.push(star::bench_star(w, a, b, best, star_runs, seed, &mut planners)?);
        progress.note(format!("{}: the optimizing planners, {star_runs} runs of 0.1 s each", w.name));
        optimal.extend(optimal::bench_optimal(w, (a, b, best), star_runs, seed, &mut planners)?);
        if let Some(driver) = ompl {
            let equal_time = size.equal_time;
            progress.note(format!(
                "{}: RRT* of both libraries, {star_runs} runs of {:.1} s each",
                w.name,
                equal_time.as_secs_f64()
            ));
            let row =
                star::star_equal_time(w, (a, b, best), star_runs, equal_time, seed, driver, &mut planners)?;
            equal_times.push(row);
        }
        logs.push(experiment(w, planners, queries, seed, date, Some((a, b, best))));
    }
    if wanted(SingleQuery::RrtConnect.name()) {
        progress.note(format!("RRT-Connect for the 3-link arm, {} queries", size.space_queries));
        spaces.push(spaces::bench_arm(size.space_queries, seed)?);
    }
    let limits = if only.is_empty() {
        progress.note(format!("time limits: every planner, {} ms each", limits::LIMIT.as_millis()));
        limits::bench_limits(seed)?
    } else {
        Vec::new()
    };
    let boxes = if wanted(boxes::NAME) {
        progress.note("R4 and R8 among random boxes");
        boxes::bench_boxes((size.box_queries, size.star_runs, Duration::from_millis(250)), seed, ompl)?
    } else {
        Vec::new()
    };
    let nearest = if wanted(nearest::NAME) {
        progress.note("nearest neighbours in a connect phase's order");
        nearest::bench_nearest(seed, ompl, size.peers_on_long_lines)?
    } else {
        Vec::new()
    };
    let mut figures = Vec::new();
    if !star.is_empty() {
        figures.push(("sampling-convergence.svg", star::convergence_svg(&star)?));
    }
    if !connect.is_empty() {
        figures.extend(connect::figures(&connect)?);
    }
    if !optimal.is_empty() {
        figures.push(("sampling-optimal.svg", optimal::svg(&optimal)?));
    }
    if !equal_times.is_empty() {
        match star::cost_time_svg(&equal_times) {
            Ok(svg) => figures.push(("sampling-cost-time.svg", svg)),
            Err(e) => errln!("warning: no RRT* cost-over-time plot: {e}"),
        }
    }
    Ok(SamplingReport {
        connect,
        star,
        prm,
        spaces,
        equal_time: equal_times,
        optimal,
        limits,
        boxes,
        nearest,
        ompl_version: ompl.map(|d| d.version.clone()),
        figures,
        logs,
    })
}

/// One world's runs as an experiment of the OMPL log; `star` is RRT*'s query and optimum
/// when it ran.
fn experiment(
    w: &SamplingWorld,
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
        s.push_str(&connect::markdown(&report.connect, report.ompl_version.as_deref()));
    }
    s.push_str(&spaces::markdown(&report.spaces));
    s.push_str(&prm::markdown(&report.prm, report.ompl_version.as_deref()));
    if !report.star.is_empty() {
        s.push_str(&star::markdown(&report.star));
    }
    if !report.equal_time.is_empty() {
        s.push_str(&star::equal_time_markdown(&report.equal_time, report.ompl_version.as_deref()));
    }
    s.push_str(&optimal::markdown(&report.optimal));
    s.push_str(&boxes::markdown(&report.boxes));
    s.push_str(&nearest::markdown(&report.nearest));
    s.push_str(&limits::markdown(&report.limits));
    s
}
