//! `cargo xtask bench`: the grid planners on generated and MovingAI maps, beside the
//! `pathfinding` crate, with a report in `target/bench/<suite>-<date>/`.
//!
//! Every planner solves the same queries on the same graph semantics (8-connected, no corner
//! cutting, costs 1 and sqrt(2)). Optimal planners are checked against the reference cost (the
//! published optimum on MovingAI maps, trailmark's Dijkstra on generated ones) and any
//! disagreement fails the run: a benchmark of wrong answers measures nothing.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use ordered_float::OrderedFloat;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::generate;
use trailmark::movingai;
use trailmark::prelude::*;

use crate::verify::tolerance;

/// Options of `cargo xtask bench`.
#[derive(clap::Args)]
pub struct Args {
    /// `quick` (the default, a few minutes) or `full` (more queries per map).
    #[arg(long, value_enum, default_value = "quick")]
    suite: Suite,
    /// The seed of the generated maps and their queries.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Rounds over each map's queries; each query's time is its median over the rounds.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    runs: u32,
    /// The MovingAI folder (default: ../shared/movingai beside the project, when it exists).
    #[arg(long)]
    movingai: Option<PathBuf>,
    /// Skip the MovingAI maps even when the folder exists.
    #[arg(long)]
    no_movingai: bool,
    /// Run only these planners (comma-separated names from the report: the grid planners, and
    /// `rrt`, `rrt_connect`, `rrt_connect_bridge`, `rrt_star`, `prm_star` of the sampling section).
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Print the results as JSON on standard output instead of the table.
    #[arg(long)]
    json: bool,
    /// The sections to run: grid search beside the peers, unknown-terrain navigation
    /// (incremental planners), anytime planners, geometric roadmaps, sampling planners,
    /// contingency plans over choke points (comma-separated).
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "grid,navigation,anytime,roadmaps,sampling,contingency"
    )]
    sections: Vec<Section>,
    /// Also run OMPL's planners on the sampling section's problems (needs libompl-dev and
    /// nlohmann-json3-dev; compiles benches/ompl/driver.cpp). Without them: a message, and
    /// the OMPL runs are skipped.
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
    /// ARA* and AD*: time to the first solution, cost over time.
    Anytime,
    /// Visibility graphs, trapezoidal decompositions, PRM* and Dubins curves on polygon worlds.
    Roadmaps,
    /// RRT's and RRT-Connect's success and speed, RRT*'s convergence, on generated polygon worlds.
    Sampling,
    /// Contingency plans over choke points against D* Lite replanning, on river terrains and a
    /// MovingAI rooms map.
    Contingency,
}

/// A benchmark suite.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Suite {
    /// Generated maps with 100 queries each; MovingAI maps with 20 queries each.
    Quick,
    /// Generated maps with 400 queries each; MovingAI maps with 100 queries each.
    Full,
}

impl Suite {
    fn name(self) -> &'static str {
        match self {
            Suite::Quick => "quick",
            Suite::Full => "full",
        }
    }

    /// Queries per generated map, queries per MovingAI map.
    fn queries(self) -> (usize, usize) {
        match self {
            Suite::Quick => (100, 20),
            Suite::Full => (400, 100),
        }
    }
}

/// A planner of the benchmark.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Planner {
    Astar,
    WeightedAstar,
    Dijkstra,
    Bfs,
    Dfs,
    PathfindingAstar,
    PathfindingDijkstra,
    PathfindingFringe,
}

/// The weight of the benchmarked weighted A*.
const WEIGHT: f64 = 2.0;

impl Planner {
    const ALL: [Planner; 8] = [
        Planner::Astar,
        Planner::PathfindingAstar,
        Planner::PathfindingFringe,
        Planner::WeightedAstar,
        Planner::Dijkstra,
        Planner::PathfindingDijkstra,
        Planner::Bfs,
        Planner::Dfs,
    ];

    fn name(self) -> &'static str {
        match self {
            Planner::Astar => "astar",
            Planner::WeightedAstar => "weighted_astar",
            Planner::Dijkstra => "dijkstra",
            Planner::Bfs => "bfs",
            Planner::Dfs => "dfs",
            Planner::PathfindingAstar => "pathfinding_astar",
            Planner::PathfindingDijkstra => "pathfinding_dijkstra",
            Planner::PathfindingFringe => "pathfinding_fringe",
        }
    }

    fn library(self) -> &'static str {
        match self {
            Planner::PathfindingAstar | Planner::PathfindingDijkstra | Planner::PathfindingFringe => {
                "pathfinding 4"
            }
            _ => "trailmark",
        }
    }

    /// The factor the cost may exceed the optimum by (`None`: no bound, BFS and DFS).
    fn bound(self) -> Option<f64> {
        match self {
            Planner::WeightedAstar => Some(WEIGHT),
            Planner::Bfs | Planner::Dfs => None,
            _ => Some(1.0),
        }
    }

    /// The planner this one is compared with in the report.
    fn peer(self) -> Option<Planner> {
        match self {
            Planner::Astar => Some(Planner::PathfindingAstar),
            Planner::Dijkstra => Some(Planner::PathfindingDijkstra),
            _ => None,
        }
    }
}

/// A query with its reference cost.
pub struct Query {
    pub start: Cell,
    pub goal: Cell,
    pub optimal: f64,
}

/// A map and its queries.
pub struct Map {
    pub name: String,
    pub source: &'static str,
    pub grid: Grid,
    pub queries: Vec<Query>,
}

/// The results of one planner on one map.
#[derive(Debug, Clone, Serialize)]
struct Row {
    map: String,
    planner: &'static str,
    library: &'static str,
    queries: usize,
    solved: usize,
    /// Median over queries of the per-query time (itself a median over the rounds), µs.
    median_us: f64,
    mean_us: f64,
    p90_us: f64,
    /// Expansions summed over the queries (trailmark planners only).
    expansions: Option<u64>,
    /// Millions of expansions per second of search time.
    mexp_per_s: Option<f64>,
    /// Mean of cost / reference cost over solved queries.
    mean_cost_ratio: f64,
    /// Queries whose cost broke the planner's bound (must be 0).
    cost_errors: usize,
    /// Bytes held by the search workspace after the map (trailmark planners only).
    workspace_bytes: Option<usize>,
    /// Each query's time (its median over the rounds), µs, sorted (for the plots; not
    /// serialized).
    #[serde(skip)]
    times_us: Vec<f64>,
}

/// The speed of a trailmark planner against its peer on one map.
#[derive(Debug, Clone, Serialize)]
struct Ratio {
    map: String,
    planner: &'static str,
    peer: &'static str,
    /// Peer median time per query / trailmark median time per query.
    speedup: f64,
}

#[derive(Serialize)]
struct Report {
    suite: Suite,
    /// The versions of the libraries measured, as locked in Cargo.lock.
    versions: Vec<(String, String)>,
    date: String,
    seed: u64,
    runs: u32,
    cores: usize,
    maps: Vec<MapInfo>,
    results: Vec<Row>,
    ratios: Vec<Ratio>,
    navigation: Vec<crate::bench_replan::NavRow>,
    navigation_ratios: Vec<crate::bench_replan::NavRatio>,
    anytime: Vec<crate::bench_replan::AnytimeRow>,
    #[serde(skip_serializing_if = "Option::is_none")]
    roadmaps: Option<crate::bench_roadmap::RoadmapReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sampling: Option<crate::bench_sampling::SamplingReport>,
    contingency: Vec<crate::bench_contingency::ContingencyRow>,
}

#[derive(Serialize)]
struct MapInfo {
    name: String,
    source: &'static str,
    width: u32,
    height: u32,
    passable: usize,
    queries: usize,
}

/// Seeded queries between cells of the largest reachable region, with Dijkstra's cost.
fn generated_queries(grid: &Grid, n: usize, rng: &mut ChaCha8Rng) -> Vec<Query> {
    let graph = GridGraph::new(grid, Connectivity::Eight);
    let mut search = Search::new();
    let region = largest_region(grid, &graph, &mut search, rng).expect("a map with passable cells");
    (0..n)
        .map(|_| {
            let start = region[rng.random_range(0..region.len())];
            let goal = region[rng.random_range(0..region.len())];
            let optimal = search.dijkstra(&graph, start, goal).expect("valid").cost().expect("one region");
            Query { start, goal, optimal }
        })
        .collect()
}

/// The largest of the regions reached from five seeded passable cells, `None` without any
/// passable cell. Leaves `search` holding the last of those searches.
pub fn largest_region(
    grid: &Grid,
    graph: &GridGraph,
    search: &mut Search,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<Cell>> {
    let passable: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    if passable.is_empty() {
        return None;
    }
    let mut region: Vec<Cell> = Vec::new();
    for _ in 0..5 {
        let from = passable[rng.random_range(0..passable.len())];
        search.dijkstra_all(graph, from).ok()?;
        let reached: Vec<Cell> = search.reached(graph).collect();
        if reached.len() > region.len() {
            region = reached;
        }
    }
    Some(region)
}

fn generated_maps(seed: u64, n: usize) -> Vec<Map> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let grids = [
        ("random512-25", generate::random(512, 512, 0.25, seed)),
        ("maze512-4", generate::maze(512, 512, 4, seed)),
        ("rooms512-31", generate::rooms(512, 512, 31, seed)),
    ];
    grids
        .into_iter()
        .map(|(name, grid)| {
            let grid = grid.expect("valid generator arguments");
            let queries = generated_queries(&grid, n, &mut rng);
            Map { name: format!("{name}-s{seed}"), source: "generated", grid, queries }
        })
        .collect()
}

/// `n` scenarios of each map of a MovingAI folder, spread over each file.
fn movingai_maps(dir: &Path, n: usize) -> Result<Vec<Map>, String> {
    let mut maps = Vec::new();
    let scenarios = dir.join("scenarios");
    let mut sets: Vec<PathBuf> = std::fs::read_dir(&scenarios)
        .map_err(|e| format!("cannot list {}: {e}", scenarios.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir())
        .collect();
    sets.sort();
    for set in sets {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&set)
            .map_err(|e| e.to_string())?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        files.sort();
        for scen in files {
            let file = scen.file_name().unwrap_or_default().to_string_lossy().into_owned();
            let Some(map_file) = file.strip_suffix(".scen") else { continue };
            let map = dir.join("maps").join(set.file_name().unwrap_or_default()).join(map_file);
            let grid = movingai::read_map(&map).map_err(|e| e.to_string())?;
            let all = movingai::read_scenarios(&scen).map_err(|e| e.to_string())?;
            let step = (all.len() / n).max(1);
            let queries = all
                .iter()
                .step_by(step)
                .take(n)
                .map(|s| Query { start: s.start, goal: s.goal, optimal: s.optimal_length })
                .collect();
            let name = map_file.trim_end_matches(".map").to_string();
            maps.push(Map { name, source: "movingai", grid, queries });
        }
    }
    Ok(maps)
}

/// The graph's moves out of `c`, as the `pathfinding` crate takes them (no allocation).
fn neighbours(graph: &GridGraph, c: Cell) -> impl Iterator<Item = (Cell, OrderedFloat<f64>)> + '_ {
    graph.neighbours(c).map(|(next, cost)| (next, OrderedFloat(cost)))
}

/// Solves one query: the cost and, for trailmark, the expansions.
fn solve(planner: Planner, graph: &GridGraph, search: &mut Search, q: &Query) -> (Option<f64>, Option<u64>) {
    let (s, t) = (q.start, q.goal);
    let octile = |p: &Cell| OrderedFloat(trailmark::core::cost::octile(p.x.abs_diff(t.x), p.y.abs_diff(t.y)));
    let ours = |r: Result<SearchResult<Cell>, SearchError<Cell>>| {
        let r = r.expect("benchmark queries are valid");
        (r.cost(), Some(r.stats.expansions))
    };
    let h = graph.heuristic(GridHeuristic::Octile, t);
    match planner {
        Planner::Astar => ours(search.astar(graph, s, t, h)),
        Planner::WeightedAstar => ours(search.weighted_astar(graph, s, t, h, WEIGHT)),
        Planner::Dijkstra => ours(search.dijkstra(graph, s, t)),
        Planner::Bfs => ours(search.bfs(graph, s, t)),
        Planner::Dfs => ours(search.dfs(graph, s, t)),
        Planner::PathfindingAstar => {
            let r = pathfinding::prelude::astar(&s, |&p| neighbours(graph, p), octile, |&p| p == t);
            (r.map(|(_, c)| c.0), None)
        }
        Planner::PathfindingDijkstra => {
            let r = pathfinding::prelude::dijkstra(&s, |&p| neighbours(graph, p), |&p| p == t);
            (r.map(|(_, c)| c.0), None)
        }
        Planner::PathfindingFringe => {
            let r = pathfinding::prelude::fringe(&s, |&p| neighbours(graph, p), octile, |&p| p == t);
            (r.map(|(_, c)| c.0), None)
        }
    }
}

pub fn median(sorted: &[f64]) -> f64 {
    match sorted.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => sorted[n / 2],
        n => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

/// Runs every planner on `map`: `runs` rounds, planners alternating within each round.
fn bench_map(map: &Map, planners: &[Planner], runs: u32) -> Vec<Row> {
    let graph = GridGraph::new(&map.grid, Connectivity::Eight);
    let n = map.queries.len();
    let mut times = vec![vec![Vec::with_capacity(runs as usize); n]; planners.len()];
    let mut outcomes = vec![vec![(None, None); n]; planners.len()];
    let mut searches: Vec<Search> = planners.iter().map(|_| Search::new()).collect();
    for _ in 0..runs {
        for (k, &planner) in planners.iter().enumerate() {
            for (i, q) in map.queries.iter().enumerate() {
                let clock = Instant::now();
                let outcome = solve(planner, &graph, &mut searches[k], q);
                times[k][i].push(clock.elapsed().as_secs_f64());
                outcomes[k][i] = outcome;
            }
        }
    }
    planners
        .iter()
        .enumerate()
        .map(|(k, &planner)| {
            let mut per_query: Vec<f64> = times[k]
                .iter_mut()
                .map(|t| {
                    t.sort_by(f64::total_cmp);
                    median(t)
                })
                .collect();
            let total: f64 = per_query.iter().sum();
            per_query.sort_by(f64::total_cmp);
            let mut solved = 0;
            let mut ratio_sum = 0.0;
            let mut cost_errors = 0;
            let mut expansions = Some(0u64);
            for (q, &(cost, exp)) in map.queries.iter().zip(&outcomes[k]) {
                expansions = expansions.zip(exp).map(|(a, b)| a + b);
                let Some(cost) = cost else {
                    cost_errors += 1; // every query is solvable
                    continue;
                };
                solved += 1;
                ratio_sum += if q.optimal > 0.0 { cost / q.optimal } else { 1.0 };
                // No path beats the optimum; bounded planners stay within their bound.
                let tol = tolerance(q.optimal);
                let above_bound = planner.bound().is_some_and(|b| cost > b * q.optimal + tol);
                if cost < q.optimal - tol || above_bound {
                    cost_errors += 1;
                }
            }
            let tm = planner.library() == "trailmark";
            Row {
                map: map.name.clone(),
                planner: planner.name(),
                library: planner.library(),
                queries: n,
                solved,
                median_us: median(&per_query) * 1e6,
                mean_us: total / n as f64 * 1e6,
                p90_us: per_query.get(n * 9 / 10).copied().unwrap_or(f64::NAN) * 1e6,
                mexp_per_s: expansions.map(|e| e as f64 / total / 1e6),
                expansions,
                mean_cost_ratio: ratio_sum / solved.max(1) as f64,
                cost_errors,
                workspace_bytes: tm.then(|| searches[k].memory_bytes()),
                times_us: per_query.iter().map(|t| t * 1e6).collect(),
            }
        })
        .collect()
}

/// The locked versions of `names`, read from the workspace's Cargo.lock.
fn locked_versions(names: &[&str]) -> Vec<(String, String)> {
    let lock = std::fs::read_to_string(crate::workspace_root().join("Cargo.lock")).unwrap_or_default();
    let mut lines = lock.lines();
    let mut out = Vec::new();
    while let Some(line) = lines.next() {
        let Some(name) = line.strip_prefix("name = \"").and_then(|l| l.strip_suffix('"')) else { continue };
        if names.contains(&name) {
            let version =
                lines.next().and_then(|l| l.strip_prefix("version = \"")).map(|v| v.trim_end_matches('"'));
            out.push((name.to_string(), version.unwrap_or("?").to_string()));
        }
    }
    out
}

/// Today's date (UTC) as YYYY-MM-DD, from the days since 1970 (Hinnant's civil-from-days).
fn today() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

fn ratios(rows: &[Row]) -> Vec<Ratio> {
    let mut out = Vec::new();
    for row in rows {
        let Some(planner) = Planner::ALL.iter().find(|p| p.name() == row.planner) else { continue };
        let Some(peer) = planner.peer() else { continue };
        if let Some(other) = rows.iter().find(|r| r.map == row.map && r.planner == peer.name()) {
            out.push(Ratio {
                map: row.map.clone(),
                planner: row.planner,
                peer: other.planner,
                speedup: other.median_us / row.median_us,
            });
        }
    }
    out
}

fn geometric_mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0), |(s, n), v| (s + v.ln(), n + 1));
    (sum / n.max(1) as f64).exp()
}

/// One goal of the report: what, the figures measured (none: not measured in this run, and
/// `missing` says how to measure it), and whether the lowest reaches `target`.
fn goal_row(goal: &str, figures: &[(String, f64)], target: f64, unit: &str, missing: &str) -> String {
    if figures.is_empty() {
        return format!("| {goal} | not measured: {missing} | - |\n");
    }
    let lowest = figures.iter().min_by(|a, b| a.1.total_cmp(&b.1)).expect("not empty");
    let mean = geometric_mean(figures.iter().map(|f| f.1));
    let met = lowest.1 >= target;
    format!(
        "| {goal} | geometric mean {mean:.2}{unit} over {} cases; lowest {:.2}{unit} ({}) | {} |\n",
        figures.len(),
        lowest.1,
        lowest.0,
        if met { "**met**" } else { "**not met**" }
    )
}

/// The goals of the benchmark with the measured figure beside each.
fn goals_markdown(report: &Report) -> String {
    let mut s = String::from("## Goals\n\n| goal | measured | status |\n|---|---|---|\n");
    let astar: Vec<(String, f64)> =
        report.ratios.iter().filter(|r| r.planner == "astar").map(|r| (r.map.clone(), r.speedup)).collect();
    s.push_str(&goal_row(
        "grid A* at least 3x faster than `pathfinding` A*",
        &astar,
        3.0,
        "x",
        "the grid section did not run",
    ));
    let dstar: Vec<(String, f64)> =
        report.navigation_ratios.iter().map(|r| (format!("{} radius {}", r.map, r.radius), r.time)).collect();
    s.push_str(&goal_row(
        "D* Lite at least 5x less planning time than A* from scratch in unknown terrain",
        &dstar,
        5.0,
        "x",
        "the navigation section did not run",
    ));
    let sampling = report.sampling.as_ref();
    let connect: Vec<(String, f64)> = sampling
        .map(|s| {
            let connect =
                s.connect.iter().filter(|r| r.planner == crate::bench_sampling::SingleQuery::RrtConnect);
            connect.filter_map(|r| r.speedup().map(|x| (r.world.clone(), x))).collect()
        })
        .unwrap_or_default();
    s.push_str(&goal_row(
        "RRT-Connect at least 2x faster than OMPL RRTConnect (same queries, same checks)",
        &connect,
        2.0,
        "x",
        "run with `--with-ompl`",
    ));
    // OMPL's median cost over trailmark's: at least 1 where trailmark's is no higher.
    let star: Vec<(String, f64)> = sampling
        .map(|s| s.equal_time.iter().map(|r| (r.world.clone(), r.ompl_ratio / r.trailmark_ratio)).collect())
        .unwrap_or_default();
    s.push_str(&goal_row(
        "RRT* cost at equal time no higher than OMPL RRTstar's (OMPL median cost / trailmark median cost >= 1)",
        &star,
        1.0,
        "",
        "run with `--with-ompl`",
    ));
    s.push_str(
        "\nA goal is met when its lowest case reaches it. Where one is not, the sections below give the \
         figures behind it (expansions, iterations, collision checks per query), and docs/benchmarks.md \
         the profile.\n\n",
    );
    s
}

/// The one-shot optimal planners' time per query on every map, trailmark's A* beside the
/// `pathfinding` crate's A* and fringe search, as box plots.
fn grid_time_svg(report: &Report) -> Result<String, String> {
    let maps: Vec<String> = report.maps.iter().map(|m| m.name.clone()).collect();
    let colours = crate::plots::COLOURS;
    let planners = [
        (Planner::Astar, colours[0]),
        (Planner::PathfindingAstar, colours[2]),
        (Planner::PathfindingFringe, colours[3]),
    ];
    let series: Vec<crate::plots::BoxSeries> = planners
        .iter()
        .filter(|(p, _)| report.results.iter().any(|r| r.planner == p.name()))
        .map(|&(p, colour)| crate::plots::BoxSeries {
            name: p.name().to_string(),
            colour,
            values: maps
                .iter()
                .map(|m| {
                    let row = report.results.iter().find(|r| &r.map == m && r.planner == p.name());
                    row.map_or(Vec::new(), |r| r.times_us.clone())
                })
                .collect(),
        })
        .collect();
    crate::plots::box_plot_svg(
        "Grid search: time per query (box: quartiles; whiskers: 1.5 IQR)",
        "microseconds",
        &maps,
        &series,
    )
}

fn markdown(report: &Report) -> String {
    let mut out = format!(
        "# trailmark benchmark: suite `{}`, {}\n\nSeed {}, {} round(s) per query (each query's time is its median over rounds), {} core(s). \
         8-connected grids, no corner cutting, octile heuristic; weighted A* with w = {WEIGHT}.\n\n",
        report.suite.name(),
        report.date,
        report.seed,
        report.runs,
        report.cores
    );
    let versions: Vec<String> = report.versions.iter().map(|(n, v)| format!("{n} {v}")).collect();
    out.push_str(&format!("Versions: {}.\n\n", versions.join(", ")));
    out.push_str(&goals_markdown(report));
    out.push_str("## Speed against `pathfinding`\n\n| map | planner | peer | speedup (peer median / trailmark median) |\n|---|---|---|---:|\n");
    for r in &report.ratios {
        out.push_str(&format!("| {} | {} | {} | {:.2}x |\n", r.map, r.planner, r.peer, r.speedup));
    }
    for planner in ["astar", "dijkstra"] {
        let speedups: Vec<f64> =
            report.ratios.iter().filter(|r| r.planner == planner).map(|r| r.speedup).collect();
        if !speedups.is_empty() {
            let worst = speedups.iter().copied().fold(f64::INFINITY, f64::min);
            out.push_str(&format!(
                "\n**{planner}**: geometric mean speedup {:.2}x over {} maps (lowest {:.2}x).",
                geometric_mean(speedups.iter().copied()),
                speedups.len(),
                worst
            ));
        }
    }
    if !report.results.is_empty() {
        out.push_str("\n\n![time per query of the optimal one-shot planners](grid-time.svg)");
    }
    out.push_str("\n\n## All results\n\n| map | planner | solved | median µs | mean µs | p90 µs | Mexp/s | cost / optimal | cost errors |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for r in &report.results {
        out.push_str(&format!(
            "| {} | {} | {}/{} | {:.1} | {:.1} | {:.1} | {} | {:.4} | {} |\n",
            r.map,
            r.planner,
            r.solved,
            r.queries,
            r.median_us,
            r.mean_us,
            r.p90_us,
            r.mexp_per_s.map_or("-".into(), |m| format!("{m:.1}")),
            r.mean_cost_ratio,
            r.cost_errors
        ));
    }
    out.push('\n');
    out.push_str(&crate::bench_replan::markdown(
        &report.navigation,
        &report.navigation_ratios,
        &report.anytime,
    ));
    out.push_str("\n## Maps\n\n| map | source | size | passable | queries |\n|---|---|---|---:|---:|\n");
    for m in &report.maps {
        out.push_str(&format!(
            "| {} | {} | {}x{} | {} | {} |\n",
            m.name, m.source, m.width, m.height, m.passable, m.queries
        ));
    }
    out
}

/// Runs the benchmark and writes its report; exit 1 when a planner broke its cost bound.
pub fn run(args: &Args) -> ExitCode {
    let planners: Vec<Planner> = Planner::ALL
        .iter()
        .copied()
        .filter(|p| args.only.is_empty() || args.only.iter().any(|o| o == p.name()))
        .collect();
    let sampling_names = crate::bench_sampling::PLANNERS;
    let unknown: Vec<&String> = args
        .only
        .iter()
        .filter(|o| {
            !Planner::ALL.iter().any(|p| p.name() == o.as_str()) && !sampling_names.contains(&o.as_str())
        })
        .collect();
    if !unknown.is_empty() {
        let names: Vec<&str> = Planner::ALL.iter().map(|p| p.name()).chain(sampling_names).collect();
        errln!("error: no planner is called {unknown:?}; planners: {}", names.join(", "));
        return ExitCode::from(2);
    }
    // With `--only`, the sections of planners not named have nothing to run.
    let sampling_named =
        args.only.is_empty() || args.only.iter().any(|o| sampling_names.contains(&o.as_str()));
    let (generated_n, movingai_n) = args.suite.queries();
    let clock = Instant::now();
    // The grid and anytime sections search the maps; the others do not need them.
    let needs_maps = args.sections.iter().any(|s| matches!(s, Section::Grid | Section::Anytime));
    let mut maps = Vec::new();
    let default_dir = crate::workspace_root().join("../shared/movingai");
    let dir = args.movingai.clone().unwrap_or(default_dir);
    if needs_maps {
        errln!("generating maps and reference costs (seed {})...", args.seed);
        maps = generated_maps(args.seed, generated_n);
        if args.no_movingai {
            errln!("MovingAI maps skipped (--no-movingai)");
        } else if dir.is_dir() {
            match movingai_maps(&dir, movingai_n) {
                Ok(m) => maps.extend(m),
                Err(e) => {
                    errln!("error: {e}");
                    return ExitCode::from(2);
                }
            }
        } else {
            errln!("MovingAI maps skipped: {} not found", dir.display());
        }
    }
    let mut rows = Vec::new();
    if args.sections.contains(&Section::Grid) && !planners.is_empty() {
        let mut progress = crate::progress::Progress::new("grid", maps.len());
        for map in &maps {
            progress.step(format!("{} ({} queries)", map.name, map.queries.len()));
            rows.extend(bench_map(map, &planners, args.runs));
        }
    }
    let movingai_dir = (!args.no_movingai && dir.is_dir()).then_some(dir.as_path());
    let mut navigation = Vec::new();
    if args.sections.contains(&Section::Navigation) {
        let cases = match crate::bench_replan::nav_cases(args.suite, args.seed, movingai_dir) {
            Ok(cases) => cases,
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        };
        match crate::bench_replan::bench_navigation(&cases, args.runs) {
            Ok(r) => navigation = r,
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let mut anytime = Vec::new();
    let mut cost_time = None;
    if args.sections.contains(&Section::Anytime) {
        let large: Vec<&Map> = maps.iter().filter(|m| m.grid.len() >= 512 * 512).collect();
        let n = match args.suite {
            Suite::Quick => 10,
            Suite::Full => 50,
        };
        anytime = crate::bench_replan::bench_anytime(&large, n, args.runs);
        if let Some(map) = maps.iter().find(|m| m.name.starts_with("random512-25")) {
            cost_time = Some(crate::bench_replan::cost_time_svg(map));
        }
    }
    let mut roadmaps = None;
    if args.sections.contains(&Section::Roadmaps) {
        match crate::bench_roadmap::bench_roadmaps(args.suite, args.seed, args.runs) {
            Ok(r) => roadmaps = Some(r),
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let mut sampling = None;
    if args.sections.contains(&Section::Sampling) && sampling_named {
        let driver = if args.with_ompl {
            match crate::ompl::Driver::build() {
                Ok(d) => Some(d),
                Err(e) => {
                    errln!("OMPL runs skipped: {e}");
                    None
                }
            }
        } else {
            None
        };
        match crate::bench_sampling::bench_sampling(
            args.suite,
            args.seed,
            driver.as_ref(),
            &today(),
            &args.only,
        ) {
            Ok(r) => sampling = Some(r),
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let mut contingency = Vec::new();
    if args.sections.contains(&Section::Contingency) && args.only.is_empty() {
        match crate::bench_contingency::bench_contingency(args.suite, args.seed, args.runs, movingai_dir) {
            Ok(r) => contingency = r,
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let report = Report {
        suite: args.suite,
        versions: locked_versions(&["trailmark", "pathfinding"]),
        date: today(),
        seed: args.seed,
        runs: args.runs,
        cores: std::thread::available_parallelism().map_or(1, |n| n.get()),
        maps: maps
            .iter()
            .map(|m| MapInfo {
                name: m.name.clone(),
                source: m.source,
                width: m.grid.width(),
                height: m.grid.height(),
                passable: m.grid.passable_count(),
                queries: m.queries.len(),
            })
            .collect(),
        ratios: ratios(&rows),
        results: rows,
        navigation_ratios: crate::bench_replan::nav_ratios(&navigation),
        navigation,
        anytime,
        roadmaps,
        sampling,
        contingency,
    };
    let mut figures = Vec::new();
    if !report.results.is_empty() {
        match grid_time_svg(&report) {
            Ok(svg) => figures.push(("grid-time.svg", svg)),
            Err(e) => errln!("warning: no grid time plot: {e}"),
        }
    }
    let mut text = markdown(&report);
    if let Some(Ok((_, summary))) = &cost_time {
        text.push_str(&format!(
            "\n## Path cost over time\n\n![path cost over time](anytime-cost-time.svg)\n\n{summary}\n"
        ));
    }
    if let Some(roadmaps) = &report.roadmaps {
        text.push('\n');
        text.push_str(&crate::bench_roadmap::markdown(roadmaps));
    }
    if let Some(sampling) = &report.sampling {
        text.push('\n');
        text.push_str(&crate::bench_sampling::markdown(sampling));
    }
    if !report.contingency.is_empty() {
        text.push('\n');
        text.push_str(&crate::bench_contingency::markdown(&report.contingency));
    }
    let folder =
        crate::workspace_root().join("target/bench").join(format!("{}-{}", args.suite.name(), report.date));
    let written = std::fs::create_dir_all(&folder)
        .and_then(|()| std::fs::write(folder.join("report.md"), &text))
        .and_then(|()| match &cost_time {
            Some(Ok((svg, _))) => std::fs::write(folder.join("anytime-cost-time.svg"), svg),
            Some(Err(e)) => {
                errln!("warning: no cost-over-time plot: {e}");
                Ok(())
            }
            None => Ok(()),
        })
        .and_then(|()| {
            let sampling = report.sampling.iter().flat_map(|s| &s.figures);
            for (name, svg) in figures.iter().chain(sampling) {
                std::fs::write(folder.join(name), svg)?;
            }
            Ok(())
        })
        .and_then(|()| {
            // One OMPL benchmark log per sampling world, for ompl_benchmark_statistics and
            // Planner Arena.
            let logs = report.sampling.iter().flat_map(|s| &s.logs);
            let folder = folder.join("ompl");
            std::fs::create_dir_all(&folder)?;
            for e in logs {
                std::fs::write(
                    folder.join(format!("{}.log", e.name)),
                    trailmark::sample::benchmark::log::write(e),
                )?;
            }
            Ok(())
        })
        .and_then(|()| match report.sampling.as_ref().filter(|s| !s.equal_time.is_empty()) {
            Some(s) => match crate::bench_sampling::cost_time_svg(&s.equal_time) {
                Ok(svg) => std::fs::write(folder.join("sampling-cost-time.svg"), svg),
                Err(e) => {
                    errln!("warning: no RRT* cost-over-time plot: {e}");
                    Ok(())
                }
            },
            None => Ok(()),
        })
        .and_then(|()| {
            std::fs::write(
                folder.join("results.json"),
                serde_json::to_string_pretty(&report).expect("serializable"),
            )
        });
    if args.json {
        outln!("{}", serde_json::to_string_pretty(&report).expect("serializable"));
    } else {
        outln!("{text}");
    }
    match written {
        Ok(()) => {
            errln!("report written to {} ({:.0} s)", folder.display(), clock.elapsed().as_secs_f64())
        }
        Err(e) => {
            errln!("error: cannot write the report to {}: {e}", folder.display());
            return ExitCode::from(2);
        }
    }
    let errors: usize = report.results.iter().map(|r| r.cost_errors).sum::<usize>()
        + report.roadmaps.iter().flat_map(|r| &r.rows).map(|r| r.cost_errors).sum::<usize>()
        + report.sampling.as_ref().map_or(0, |s| s.errors())
        + report.contingency.iter().filter(|r| r.error).count();
    if errors > 0 {
        errln!("error: {errors} queries broke their planner's cost bound (see the cost errors column)");
        return ExitCode::from(1);
    }
    ExitCode::SUCCESS
}
