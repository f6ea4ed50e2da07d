//! `cargo xtask bench`: the planners on generated and MovingAI maps and generated worlds, beside
//! peer libraries, with a report in `target/bench/<suite>-<date>/`.
//!
//! The harness in three floors, arrows pointing down only. At the bottom, what every section
//! uses: the suite and its maps ([`suite`]), the statistics ([`stats`]), the report's writing
//! ([`report`], [`plots`]), the progress display and the peers (OMPL, [`peer`] for
//! `pathfinding`). Above it, one module per
//! section ([`grid`], [`navigation`], [`anytime`], [`roadmaps`], [`sampling`], [`cars`],
//! [`contingency`], [`rosmaps`], [`arms`]),
//! none of which uses another. At the top, this module: the options, which sections run, and the
//! report assembled from each section's part.
//!
//! Timed sections run one at a time on the main thread; untimed work (the suite's maps and
//! reference costs, the contingency section's checks) runs beside them on a thread of its own,
//! and [`times`] records both for the report's time line.

mod all_pairs;
mod anytime;
mod arms;
mod cars;
mod contingency;
mod grid;
mod lattice;
mod navigation;
mod ompl;
mod ompl_arm;
mod peer;
mod plots;
mod progress;
mod report;
mod roadmaps;
mod rosmaps;
mod sampling;
mod stats;
mod suite;
mod times;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use serde::Serialize;

use all_pairs::AllPairsRow;
use anytime::{AnytimePart, AnytimeRow};
use arms::ArmReport;
use cars::CarReport;
use contingency::ContingencyRow;
use grid::{GridPlanner, GridRow, PeerRatio};
use navigation::{NavRatio, NavRow, ReplannerRatio};
use ompl::OmplDriver;
use ompl_arm::OmplArmDriver;
use report::{Figure, GoalRow};
use roadmaps::RoadmapReport;
use rosmaps::RosMapRow;
use sampling::SamplingReport;
use suite::{Suite, SuiteMap};
use times::RunTimes;

/// Options of `cargo xtask bench`.
#[derive(clap::Args)]
pub struct Args {
    /// `quick` (the default, a few minutes) or `full` (more queries per map).
    #[arg(long, value_enum, default_value = "quick")]
    suite: Suite,
    /// The seed of the generated maps and their queries.
    #[arg(allow_negative_numbers = true, long, default_value_t = 1)]
    seed: u64,
    /// Rounds over each map's queries; each query's time is its median over the rounds.
    #[arg(allow_negative_numbers = true, long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    runs: u32,
    /// The MovingAI folder (default: ../shared/movingai beside the project, when it exists).
    #[arg(long)]
    movingai: Option<PathBuf>,
    /// Skip the MovingAI maps even when the folder exists.
    #[arg(long)]
    no_movingai: bool,
    /// Run only these planners (comma-separated names from the report: the grid planners, and
    /// the sampling section's; an unknown name gets the list of them all).
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Print the results as JSON on standard output instead of the table.
    #[arg(long)]
    json: bool,
    /// The sections to run: grid search beside the peers, unknown-terrain navigation
    /// (incremental planners), anytime planners, geometric roadmaps, sampling planners,
    /// car-like robots, contingency plans over choke points, ROS maps, robot arms
    /// (comma-separated).
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "grid,navigation,all-pairs,anytime,roadmaps,sampling,cars,contingency,rosmaps,arms"
    )]
    sections: Vec<Section>,
    /// Also run OMPL's planners on the sampling, car and arm sections' problems (needs
    /// libompl-dev and nlohmann-json3-dev, and for the arms libfcl-dev and libeigen3-dev;
    /// compiles benches/ompl/driver.cpp and arm_driver.cpp). Without them: a message, and the
    /// OMPL runs are skipped.
    #[arg(long)]
    with_ompl: bool,
}

/// A section of the benchmark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Section {
    /// One-shot grid search beside `pathfinding`.
    Grid,
    /// Replanning in unknown terrain: A*, LPA*, D* Lite, AD*.
    Navigation,
    /// Shortest distances between every pair of nodes kept right as edges change, beside
    /// recomputing them.
    AllPairs,
    /// ARA* and AD*: time to the first solution, cost over time.
    Anytime,
    /// Visibility graphs, trapezoidal decompositions, PRM* and Dubins curves on polygon worlds.
    Roadmaps,
    /// RRT's and RRT-Connect's success and speed, RRT*'s convergence, on generated polygon worlds.
    Sampling,
    /// Car-like robots: Hybrid A*, RRT-Connect and RRT* in the Reeds-Shepp and Dubins spaces.
    Cars,
    /// Contingency plans over choke points against D* Lite replanning, on river terrains and a
    /// MovingAI rooms map.
    Contingency,
    /// ROS maps: loading, inflation, A* beside `pathfinding` on the costmap, Theta*.
    Rosmaps,
    /// The Panda arm on MotionBenchMaker's problems: the batch and scalar checkers, beside OMPL
    /// with FCL.
    Arms,
}

/// What the report holds, in the order of `results.json`.
#[derive(Serialize)]
struct BenchReport {
    suite: Suite,
    /// The versions of the libraries measured, as locked in Cargo.lock.
    versions: Vec<(String, String)>,
    date: String,
    seed: u64,
    runs: u32,
    cores: usize,
    maps: Vec<MapInfo>,
    results: Vec<GridRow>,
    ratios: Vec<PeerRatio>,
    navigation: Vec<NavRow>,
    navigation_own: Vec<NavRow>,
    navigation_ratios: Vec<NavRatio>,
    replanner_ratios: Vec<ReplannerRatio>,
    all_pairs: Vec<AllPairsRow>,
    anytime: Vec<AnytimeRow>,
    #[serde(skip_serializing_if = "Option::is_none")]
    roadmaps: Option<RoadmapReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sampling: Option<SamplingReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cars: Option<CarReport>,
    contingency: Vec<ContingencyRow>,
    rosmaps: Vec<RosMapRow>,
    #[serde(skip_serializing_if = "Option::is_none")]
    arms: Option<ArmReport>,
}

/// A map of the suite in the report.
#[derive(Serialize)]
struct MapInfo {
    name: String,
    source: &'static str,
    width: u32,
    height: u32,
    passable: usize,
    queries: usize,
}

impl MapInfo {
    fn of(m: &SuiteMap) -> MapInfo {
        MapInfo {
            name: m.name.clone(),
            source: m.source,
            width: m.grid.width(),
            height: m.grid.height(),
            passable: m.grid.passable_count(),
            queries: m.queries.len(),
        }
    }
}

impl BenchReport {
    /// The goals table's rows, each from its section.
    fn goals(&self) -> Vec<GoalRow> {
        let mut goals = grid::goals(&self.ratios, &self.results);
        goals.extend(navigation::goals(&self.navigation_ratios));
        goals.extend(navigation::best_goals(&self.replanner_ratios));
        goals.extend(rosmaps::goals(&self.rosmaps));
        goals.push(lattice::goal(self.roadmaps.as_ref().map_or(&[][..], |r| &r.lattice)));
        goals.extend(sampling::goals(self.sampling.as_ref()));
        goals.extend(arms::goals(self.arms.as_ref()));
        goals
    }

    /// Queries and paths that broke their planner's bound or failed a re-check.
    fn errors(&self) -> usize {
        self.results.iter().filter(|r| !r.known_flaw).map(|r| r.cost_errors).sum::<usize>()
            + self.roadmaps.iter().flat_map(|r| &r.rows).map(|r| r.cost_errors).sum::<usize>()
            + self.roadmaps.iter().flat_map(|r| &r.lattice).filter(|r| r.cost_error).count()
            + self.sampling.as_ref().map_or(0, |s| s.errors())
            + self.cars.as_ref().map_or(0, |c| c.errors())
            + self.contingency.iter().filter(|r| r.error).count()
            + self.rosmaps.iter().map(|r| r.cost_errors).sum::<usize>()
            + self.all_pairs.iter().map(|r| r.errors).sum::<usize>()
            + self.arms.as_ref().map_or(0, |a| a.errors())
    }

    /// The report: `time_line` after the versions, `anytime_plot` (the anytime section's plot
    /// and its sentence) after the table of maps.
    fn markdown(&self, time_line: &str, anytime_plot: &str) -> String {
        let mut out = format!(
            "# trailmark benchmark: suite `{}`, {}\n\nSeed {}, {} round(s) per query (each query's time is its median over rounds), {} core(s). \
             8-connected grids, no corner cutting, octile heuristic; weighted A* with w = {}.\n\n",
            self.suite.name(),
            self.date,
            self.seed,
            self.runs,
            self.cores,
            grid::WEIGHT
        );
        let versions: Vec<String> = self.versions.iter().map(|(n, v)| format!("{n} {v}")).collect();
        out.push_str(&format!("Versions: {}.\n\n", versions.join(", ")));
        let measured: Vec<&str> = measured_planners().iter().map(|p| p.name()).collect();
        out.push_str(&format!(
            "Planners of the registry the sections measure: {} of {} ({}).\n\n",
            measured.len(),
            trailmark::solve::PlannerName::ALL.len(),
            measured.join(", ")
        ));
        out.push_str(time_line);
        out.push_str(&report::goals_markdown(&self.goals()));
        out.push_str(&grid::markdown(&self.results, &self.ratios));
        out.push_str(&navigation::markdown(
            &self.navigation,
            &self.navigation_own,
            &self.navigation_ratios,
            &self.replanner_ratios,
        ));
        out.push_str(&all_pairs::markdown(&self.all_pairs));
        out.push_str(&anytime::markdown(&self.anytime));
        out.push_str("\n## Maps\n\n| map | source | size | passable | queries |\n|---|---|---|---:|---:|\n");
        for m in &self.maps {
            out.push_str(&format!(
                "| {} | {} | {}x{} | {} | {} |\n",
                m.name, m.source, m.width, m.height, m.passable, m.queries
            ));
        }
        out.push_str(anytime_plot);
        if let Some(roadmaps) = &self.roadmaps {
            out.push('\n');
            out.push_str(&roadmaps::markdown(roadmaps));
        }
        if let Some(sampling) = &self.sampling {
            out.push('\n');
            out.push_str(&sampling::markdown(sampling));
        }
        if let Some(cars) = &self.cars {
            out.push('\n');
            out.push_str(&cars::markdown(cars));
        }
        if !self.contingency.is_empty() {
            out.push('\n');
            out.push_str(&contingency::markdown(&self.contingency));
        }
        out.push_str(&rosmaps::markdown(&self.rosmaps));
        if let Some(arms) = &self.arms {
            out.push_str(&arms::markdown(arms));
        }
        out
    }
}

/// The OMPL driver when `--with-ompl` asks for it and it builds.
fn ompl_driver(args: &Args) -> Option<OmplDriver> {
    if !args.with_ompl {
        return None;
    }
    match OmplDriver::build() {
        Ok(d) => Some(d),
        Err(e) => {
            errln!("OMPL runs skipped: {e}");
            None
        }
    }
}

/// The suite's maps: the generated ones and, unless skipped, those of the MovingAI folder.
fn suite_maps(args: &Args, dir: &Path) -> Result<Vec<SuiteMap>, String> {
    let (generated_n, movingai_n) = args.suite.queries();
    errln!("generating maps and reference costs (seed {})...", args.seed);
    let mut maps = suite::generated_maps(args.seed, generated_n);
    if args.no_movingai {
        errln!("MovingAI maps skipped (--no-movingai)");
    } else if dir.is_dir() {
        maps.extend(suite::movingai_maps(dir, movingai_n)?);
    } else {
        errln!("MovingAI maps skipped: {} not found", dir.display());
    }
    Ok(maps)
}

/// What the sections measured, before the report is assembled.
struct Parts {
    maps: Vec<SuiteMap>,
    results: Vec<GridRow>,
    navigation: Vec<NavRow>,
    navigation_own: Vec<NavRow>,
    all_pairs: Vec<AllPairsRow>,
    anytime: Option<AnytimePart>,
    roadmaps: Option<RoadmapReport>,
    sampling: Option<SamplingReport>,
    cars: Option<CarReport>,
    contingency: Vec<ContingencyRow>,
    rosmaps: Vec<RosMapRow>,
    arms: Option<ArmReport>,
    date: String,
}

/// Runs the chosen sections one after the other on this thread, and the untimed work that does
/// not need them (the suite's maps, the contingency section's checks) beside them on threads of
/// `scope`. Timed sections never run side by side (on 2 cores they would slow each other), and
/// nothing runs beside the roadmaps section, which times builds on every core.
fn run_parts<'scope>(
    scope: &'scope std::thread::Scope<'scope, '_>,
    args: &'scope Args,
    planners: &[&GridPlanner],
    sampling_named: bool,
    times: &mut RunTimes,
) -> Result<Parts, String> {
    let wants = |section| args.sections.contains(&section);
    // The grid and anytime sections search the maps; the others do not need them.
    let needs_maps = wants(Section::Grid) || wants(Section::Anytime);
    let dir = args.movingai.clone().unwrap_or_else(|| crate::workspace::root().join("../shared/movingai"));
    let movingai_dir = (!args.no_movingai && dir.is_dir()).then(|| dir.clone());
    let maps = needs_maps
        .then(|| RunTimes::beside(scope, "maps and reference costs", move || suite_maps(args, &dir)));
    // The contingency section plans first, so that its checks run beside the sections after it.
    let mut contingency = None;
    if wants(Section::Contingency) && args.only.is_empty() {
        let planned = times.section("contingency", || {
            contingency::plan_terrains(args.suite, args.runs, movingai_dir.as_deref())
        })?;
        let seed = args.seed;
        contingency =
            Some(RunTimes::beside(scope, "contingency checks", move || contingency::check(&planned, seed)));
    }
    let maps = match maps {
        Some(job) => times.join(job)??,
        None => Vec::new(),
    };
    let date = report::today();
    let mut results = Vec::new();
    if wants(Section::Grid) && !planners.is_empty() {
        results = times.section("grid", || grid::bench_grid(&maps, planners, args.runs));
    }
    let (mut navigation, mut navigation_own) = (Vec::new(), Vec::new());
    if wants(Section::Navigation) {
        (navigation, navigation_own) = times.section("navigation", || {
            let cases = navigation::nav_cases(args.suite, args.seed, movingai_dir.as_deref())?;
            navigation::bench_navigation(&cases, args.runs)
        })?;
    }
    let mut all_pairs = Vec::new();
    if wants(Section::AllPairs) && args.only.is_empty() {
        all_pairs = times.section("all-pairs", || all_pairs::bench(args.suite, args.seed))?;
    }
    let anytime = wants(Section::Anytime)
        .then(|| times.section("anytime", || anytime::bench(&maps, args.suite, args.runs)));
    let contingency = match contingency {
        Some(job) => times.join(job)??,
        None => Vec::new(),
    };
    let mut roadmaps = None;
    if wants(Section::Roadmaps) {
        roadmaps =
            Some(times.section("roadmaps", || roadmaps::bench_roadmaps(args.suite, args.seed, args.runs))?);
    }
    let driver = (wants(Section::Sampling) && sampling_named || wants(Section::Cars) && args.only.is_empty())
        .then(|| ompl_driver(args))
        .flatten();
    let mut sampling = None;
    if wants(Section::Sampling) && sampling_named {
        sampling = Some(times.section("sampling", || {
            sampling::bench(args.suite, args.seed, driver.as_ref(), &date, &args.only)
        })?);
    }
    let mut cars = None;
    if wants(Section::Cars) && args.only.is_empty() {
        cars = Some(times.section("cars", || cars::bench(args.suite, args.seed, driver.as_ref()))?);
    }
    let mut rosmaps = Vec::new();
    if wants(Section::Rosmaps) && args.only.is_empty() {
        rosmaps = times.section("rosmaps", || rosmaps::bench(args.suite, args.seed, args.runs))?;
    }
    let mut arms = None;
    if wants(Section::Arms) && args.only.is_empty() {
        let driver = args.with_ompl.then(|| match OmplArmDriver::build() {
            Ok(d) => Some(d),
            Err(e) => {
                errln!("OMPL arm runs skipped: {e}");
                None
            }
        });
        arms = Some(times.section("arms", || arms::bench(args.suite, args.seed, driver.flatten().as_ref()))?);
    }
    Ok(Parts {
        maps,
        results,
        navigation,
        navigation_own,
        all_pairs,
        anytime,
        roadmaps,
        sampling,
        cars,
        contingency,
        rosmaps,
        arms,
        date,
    })
}

/// Runs the benchmark and writes its report; exit 1 when a planner broke its cost bound.
pub fn run(args: &Args) -> ExitCode {
    match run_sections(args) {
        Ok(code) => code,
        Err(e) => {
            errln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run_sections(args: &Args) -> Result<ExitCode, String> {
    let planners = grid::chosen(&args.only);
    let sampling_names = sampling::planner_names();
    let grid_names = grid::PLANNERS.map(|p| p.name);
    let unknown: Vec<&String> = args
        .only
        .iter()
        .filter(|o| !grid_names.contains(&o.as_str()) && !sampling_names.contains(&o.as_str()))
        .collect();
    if !unknown.is_empty() {
        let names: Vec<&str> = grid_names.into_iter().chain(sampling_names).collect();
        errln!("error: no planner is called {unknown:?}; planners: {}", names.join(", "));
        return Ok(ExitCode::from(2));
    }
    // With `--only`, the sections of planners not named have nothing to run.
    let sampling_named =
        args.only.is_empty() || args.only.iter().any(|o| sampling_names.contains(&o.as_str()));
    let mut times = RunTimes::start();
    let mut parts =
        std::thread::scope(|scope| run_parts(scope, args, &planners, sampling_named, &mut times))?;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let report = BenchReport {
        suite: args.suite,
        versions: report::locked_versions(&["trailmark", "pathfinding", "grid_pathfinding"]),
        date: parts.date,
        seed: args.seed,
        runs: args.runs,
        cores,
        maps: parts.maps.iter().map(MapInfo::of).collect(),
        ratios: grid::ratios(&parts.results),
        results: parts.results,
        navigation_ratios: navigation::nav_ratios(&parts.navigation),
        replanner_ratios: navigation::replanner_ratios(&parts.navigation),
        navigation: parts.navigation,
        navigation_own: parts.navigation_own,
        all_pairs: parts.all_pairs,
        anytime: parts.anytime.as_mut().map_or(Vec::new(), |a| std::mem::take(&mut a.rows)),
        roadmaps: parts.roadmaps,
        sampling: parts.sampling,
        cars: parts.cars,
        contingency: parts.contingency,
        rosmaps: parts.rosmaps,
        arms: parts.arms,
    };
    let mut figures: Vec<Figure> = Vec::new();
    if !report.results.is_empty() {
        let names: Vec<String> = report.maps.iter().map(|m| m.name.clone()).collect();
        match grid::time_svg(&names, &report.results) {
            Ok(svg) => figures.push(("grid-time.svg", svg)),
            Err(e) => errln!("warning: no grid time plot: {e}"),
        }
    }
    if !report.navigation.is_empty() {
        match navigation::time_svg(&report.navigation) {
            Ok(svg) => figures.push(("navigation-time.svg", svg)),
            Err(e) => errln!("warning: no navigation time plot: {e}"),
        }
    }
    let anytime_plot = parts.anytime.as_ref().map_or(String::new(), |a| a.cost_time_markdown());
    let text = report.markdown(&times.markdown(cores), &anytime_plot);
    figures.extend(parts.anytime.iter().flat_map(|a| a.figures()));
    figures.extend(report.sampling.iter().flat_map(|s| s.figures.iter().cloned()));
    let json = serde_json::to_string_pretty(&report).expect("serializable");
    let folder =
        crate::workspace::root().join("target/bench").join(format!("{}-{}", args.suite.name(), report.date));
    let logs = report.sampling.as_ref().map_or(&[][..], |s| &s.logs[..]);
    let written = report::write_folder(&folder, &text, &figures, logs, &json);
    if args.json {
        outln!("{json}");
    } else {
        outln!("{text}");
    }
    if let Err(e) = written {
        return Err(format!("cannot write the report to {}: {e}", folder.display()));
    }
    errln!("report written to {} ({:.0} s)", folder.display(), times.elapsed());
    let errors = report.errors();
    if errors > 0 {
        errln!("error: {errors} queries broke their planner's cost bound (see the cost errors column)");
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// The registry's planners the sections measure, each section's list read from what it runs.
fn measured_planners() -> std::collections::BTreeSet<trailmark::solve::PlannerName> {
    grid::measured()
        .chain(navigation::measured())
        .chain(anytime::MEASURED)
        .chain(sampling::measured())
        .chain(cars::MEASURED)
        .chain(rosmaps::MEASURED)
        .collect()
}

#[cfg(test)]
mod tests {
    use trailmark::solve::PlannerName;

    /// Every planner of the registry runs in some section of the harness: a planner registered
    /// but measured nowhere fails here.
    #[test]
    fn every_registered_planner_is_measured() {
        let measured = super::measured_planners();
        let missing: Vec<&str> =
            PlannerName::ALL.iter().filter(|p| !measured.contains(p)).map(|p| p.name()).collect();
        assert!(missing.is_empty(), "registered but measured in no section of the harness: {missing:?}");
    }
}
