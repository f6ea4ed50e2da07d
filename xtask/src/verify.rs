//! `cargo xtask verify movingai DIR`: every scenario against its published optimal length;
//! `cargo xtask verify anyangle DIR`: the GPPC any-angle scenarios on the visibility graph.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use trailmark::core::freespace::FreeSpace;
use trailmark::core::geometry::Point;
use trailmark::graph::CornerGraph;
use trailmark::graph::trapezoid::Trapezoids;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::movingai::{self, Scenario};
use trailmark::prelude::*;
use trailmark::search::{Jps, JpsPlus};

use crate::reference::tolerance;

/// An optimal algorithm that `verify` checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum VerifyAlgo {
    /// A* with the octile heuristic.
    Astar,
    /// Dijkstra's algorithm.
    Dijkstra,
    /// Jump point search.
    Jps,
    /// JPS+, its table made once per map.
    #[value(name = "jps_plus")]
    JpsPlus,
}

/// One map and its scenario file.
struct ScenarioFile {
    name: String,
    map: PathBuf,
    scen: PathBuf,
}

/// What checking one map gave.
struct MapCheck {
    name: String,
    passed: u64,
    failed: u64,
    messages: Vec<String>,
    seconds: f64,
}

/// Lists `DIR/scenarios/<set>/<name>.map.scen` with their maps `DIR/maps/<set>/<name>.map`.
fn jobs(dir: &Path) -> Result<Vec<ScenarioFile>, String> {
    let scenarios = dir.join("scenarios");
    let read = |d: &Path| std::fs::read_dir(d).map_err(|e| format!("cannot list {}: {e}", d.display()));
    let mut jobs = Vec::new();
    for set in read(&scenarios)? {
        let set = set.map_err(|e| e.to_string())?.path();
        if !set.is_dir() {
            continue;
        }
        let set_name = set.file_name().unwrap_or_default().to_string_lossy().into_owned();
        for file in read(&set)? {
            let scen = file.map_err(|e| e.to_string())?.path();
            let file_name = scen.file_name().unwrap_or_default().to_string_lossy().into_owned();
            let Some(map_name) = file_name.strip_suffix(".scen").filter(|m| m.ends_with(".map")) else {
                continue;
            };
            let map = dir.join("maps").join(&set_name).join(map_name);
            let name = format!("{set_name}/{}", map_name.trim_end_matches(".map"));
            jobs.push(ScenarioFile { name, map, scen });
        }
    }
    jobs.sort_by(|a, b| a.name.cmp(&b.name));
    if jobs.is_empty() {
        return Err(format!("no scenario files (*.map.scen) under {}", scenarios.display()));
    }
    Ok(jobs)
}

fn check(job: &ScenarioFile, algos: &[VerifyAlgo], every: u64) -> MapCheck {
    let clock = Instant::now();
    let mut out =
        MapCheck { name: job.name.clone(), passed: 0, failed: 0, messages: Vec::new(), seconds: 0.0 };
    let loaded = movingai::read_map(&job.map)
        .map_err(|e| e.to_string())
        .and_then(|g| movingai::read_scenarios(&job.scen).map(|s| (g, s)).map_err(|e| e.to_string()));
    let (grid, scenarios) = match loaded {
        Ok(x) => x,
        Err(e) => {
            out.failed += 1;
            out.messages.push(e);
            return out;
        }
    };
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut search = Search::new();
    let (mut jps, mut plus) = match jump_searches(&grid, algos) {
        Ok(made) => made,
        Err(e) => {
            out.failed += 1;
            out.messages.push(format!("jump point search: {e}"));
            return out;
        }
    };
    for (i, scenario) in scenarios.iter().enumerate().filter(|(i, _)| (*i as u64).is_multiple_of(every)) {
        for &algo in algos {
            let jumps = Jumps { jps: jps.as_mut(), plus: plus.as_mut() };
            match solve_one(&graph, &grid, &mut search, jumps, scenario, algo) {
                Ok(()) => out.passed += 1,
                Err(why) => {
                    out.failed += 1;
                    out.messages.push(format!("scenario {} ({algo:?}): {why}", i + 1));
                }
            }
        }
    }
    out.seconds = clock.elapsed().as_secs_f64();
    out
}

/// The jump point searches `algos` asks for, made for `grid` under the MovingAI rule.
fn jump_searches(
    grid: &Grid,
    algos: &[VerifyAlgo],
) -> Result<(Option<Jps>, Option<JpsPlus>), SearchError<Cell>> {
    let rule = CornerCutting::Forbidden;
    let jps = if algos.contains(&VerifyAlgo::Jps) { Some(Jps::new(grid, rule)?) } else { None };
    let plus = if algos.contains(&VerifyAlgo::JpsPlus) { Some(JpsPlus::new(grid, rule)?) } else { None };
    Ok((jps, plus))
}

/// The jump point searches made for a map, if asked for.
struct Jumps<'a> {
    jps: Option<&'a mut Jps>,
    plus: Option<&'a mut JpsPlus>,
}

fn solve_one(
    graph: &GridGraph,
    grid: &Grid,
    search: &mut Search,
    jumps: Jumps<'_>,
    s: &Scenario,
    algo: VerifyAlgo,
) -> Result<(), String> {
    if (s.map_width, s.map_height) != (grid.width(), grid.height()) {
        return Err(format!(
            "made for a {} x {} map, but the map is {} x {}",
            s.map_width,
            s.map_height,
            grid.width(),
            grid.height()
        ));
    }
    let found = match algo {
        VerifyAlgo::Astar => {
            search.astar(graph, s.start, s.goal, graph.heuristic(GridHeuristic::Octile, s.goal))
        }
        VerifyAlgo::Dijkstra => search.dijkstra(graph, s.start, s.goal),
        VerifyAlgo::Jps => jumps.jps.ok_or("no jump point search for this map")?.search(s.start, s.goal),
        VerifyAlgo::JpsPlus => jumps.plus.ok_or("no JPS+ table for this map")?.search(s.start, s.goal),
    }
    .map_err(|e| e.to_string())?;
    let path = found.path.as_ref().ok_or_else(|| format!("{} -> {}: no path found", s.start, s.goal))?;
    let cost = path.cost;
    // The path itself: moves of the grid graph whose costs add up to the cost reported.
    let mut sum = 0.0;
    for pair in path.nodes.windows(2) {
        sum += graph.edge_cost(pair[0], pair[1]).ok_or_else(|| {
            format!("{} -> {}: the path's step {} -> {} is no move", s.start, s.goal, pair[0], pair[1])
        })?;
    }
    if (sum - cost).abs() > tolerance(cost) {
        return Err(format!(
            "{} -> {}: the path's moves add up to {sum}, its cost is {cost}",
            s.start, s.goal
        ));
    }
    let diff = (cost - s.optimal_length).abs();
    if diff > tolerance(s.optimal_length) {
        return Err(format!("{} -> {}: cost {cost:.6}, published {}", s.start, s.goal, s.optimal_length));
    }
    Ok(())
}

/// Prints the first ten failure messages of a map, and how many more there were.
fn print_messages(messages: &[String]) {
    for m in messages.iter().take(10) {
        outln!("    {m}");
    }
    if messages.len() > 10 {
        outln!("    ... and {} more", messages.len() - 10);
    }
}

/// Runs the check over every scenario file of `dir`, maps in parallel, and prints one line per
/// map and the total.
pub fn movingai(dir: &Path, algos: &[VerifyAlgo], every: u64) -> ExitCode {
    let jobs = match jobs(dir) {
        Ok(j) => j,
        Err(e) => return crate::output::error_report(e),
    };
    let clock = Instant::now();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(jobs.len());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut outcomes: Vec<Option<MapCheck>> = (0..jobs.len()).map(|_| None).collect();
    let done = std::sync::Mutex::new(&mut outcomes);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(job) = jobs.get(i) else { break };
                    let outcome = check(job, algos, every);
                    done.lock().expect("no thread panics holding the lock")[i] = Some(outcome);
                }
            });
        }
    });
    let (mut passed, mut failed) = (0, 0);
    for o in outcomes.into_iter().flatten() {
        outln!("{:<24} {:>6} passed {:>4} failed  {:>7.2}s", o.name, o.passed, o.failed, o.seconds);
        print_messages(&o.messages);
        passed += o.passed;
        failed += o.failed;
    }
    let algos: Vec<String> = algos
        .iter()
        .filter_map(clap::ValueEnum::to_possible_value)
        .map(|v| v.get_name().to_string())
        .collect();
    outln!(
        "checked every {} scenario(s) with {} in {:.1}s",
        if every == 1 { "1".to_string() } else { format!("{every}th") },
        algos.join(" and "),
        clock.elapsed().as_secs_f64()
    );
    outln!("{passed} passed, {failed} failed");
    if failed > 0 { ExitCode::from(1) } else { ExitCode::SUCCESS }
}

/// `cargo xtask verify anyangle DIR`: every `DIR/*.map.scen` of the GPPC any-angle track solved
/// on the visibility graph of its map (blocked cells as unit squares), against the published
/// Euclidean optimum within `rel` relative error.
pub fn anyangle(dir: &Path, every: u64, rel: f64, edges: Edges) -> ExitCode {
    let listing = match std::fs::read_dir(dir) {
        Ok(l) => l,
        Err(e) => return crate::output::error_report(format!("cannot list {}: {e}", dir.display())),
    };
    let mut scens: Vec<PathBuf> = listing
        .filter_map(|f| f.ok().map(|f| f.path()))
        .filter(|p| p.to_string_lossy().ends_with(".map.scen"))
        .collect();
    scens.sort();
    if scens.is_empty() {
        return crate::output::error_report(format!("no scenario files (*.map.scen) in {}", dir.display()));
    }
    let clock = Instant::now();
    let (mut passed, mut failed) = (0u64, 0u64);
    for scen in &scens {
        let map = scen.with_extension("");
        let name = map.file_stem().unwrap_or_default().to_string_lossy().into_owned();
        let loaded = movingai::read_map(&map)
            .map_err(|e| e.to_string())
            .and_then(|g| movingai::read_scenarios(scen).map(|s| (g, s)).map_err(|e| e.to_string()));
        let (grid, scenarios) = match loaded {
            Ok(x) => x,
            Err(e) => {
                outln!("{name}: {e}");
                failed += 1;
                continue;
            }
        };
        let build = Instant::now();
        let graph = VisibilityGraph::with_edges(FreeSpace::from_grid(&grid), edges);
        let build_seconds = build.elapsed().as_secs_f64();
        let solve = Instant::now();
        let mut search = Search::new();
        let (mut ok, mut bad, mut messages) = (0u64, 0u64, Vec::new());
        // The trapezoidal decomposition of the same map: its cells tile exactly the free cells,
        // and its paths exist wherever the published ones do and are no shorter.
        let cells = Trapezoids::new(graph.space());
        let free = grid.cells().filter(|&c| grid.is_passable(c)).count() as f64;
        let area: f64 = (0..cells.cell_count()).map(|c| cells.cell(c).area()).sum();
        if (area - free).abs() > 1e-9 * free {
            bad += 1;
            messages.push(format!("trapezoid cells cover {area}, the map has {free} free cells"));
        }
        let mut detour = Vec::new();
        // Theta* on the map's corners: never shorter than the published optimum.
        let corners = CornerGraph::new(&grid);
        let (mut theta_ratios, mut theta_seconds) = (Vec::new(), 0.0);
        for (i, s) in scenarios.iter().enumerate().filter(|(i, _)| (*i as u64).is_multiple_of(every)) {
            let h = |c: Cell| f64::from(c.x.abs_diff(s.goal.x)).hypot(f64::from(c.y.abs_diff(s.goal.y)));
            let clock = Instant::now();
            let theta = search.theta_star(&corners, s.start, s.goal, h, &corners);
            theta_seconds += clock.elapsed().as_secs_f64();
            match theta.map(|found| found.cost()) {
                Ok(Some(cost)) if cost >= s.optimal_length * (1.0 - rel) - rel => {
                    theta_ratios.push(cost / s.optimal_length.max(1e-300));
                }
                Ok(Some(cost)) => {
                    bad += 1;
                    messages.push(format!(
                        "scenario {}: Theta* path {cost} below the optimum {}",
                        i + 1,
                        s.optimal_length
                    ));
                }
                Ok(None) => {
                    bad += 1;
                    messages.push(format!(
                        "scenario {} {} -> {}: Theta* found no path",
                        i + 1,
                        s.start,
                        s.goal
                    ));
                }
                Err(e) => {
                    bad += 1;
                    messages.push(format!("scenario {} {} -> {}: Theta*: {e}", i + 1, s.start, s.goal));
                }
            }
            let corner = |c: Cell| Point::new(f64::from(c.x), f64::from(c.y));
            let (start, goal) = (corner(s.start), corner(s.goal));
            let through_cells = cells
                .query(start, goal)
                .map_err(|e| e.to_string())
                .and_then(|q| search.dijkstra(&q, q.start(), q.goal()).map_err(|e| e.to_string()))
                .and_then(|found| found.cost().ok_or_else(|| "no path through the cells".to_string()));
            match through_cells {
                Ok(cost) if cost >= s.optimal_length * (1.0 - rel) => {
                    detour.push(cost / s.optimal_length.max(1e-300))
                }
                Ok(cost) => {
                    bad += 1;
                    messages.push(format!(
                        "scenario {}: trapezoid path {cost} below the optimum {}",
                        i + 1,
                        s.optimal_length
                    ));
                }
                Err(e) => {
                    bad += 1;
                    messages.push(format!("scenario {} {} -> {}: trapezoids: {e}", i + 1, s.start, s.goal));
                }
            }
            let outcome = graph
                .query(start, goal)
                .map_err(|e| e.to_string())
                .and_then(|q| search.astar(&q, q.start(), q.goal(), q.heuristic()).map_err(|e| e.to_string()))
                .and_then(|found| found.cost().ok_or_else(|| "no path found".to_string()));
            match outcome {
                Ok(cost) if (cost - s.optimal_length).abs() <= rel * s.optimal_length.max(1.0) => ok += 1,
                Ok(cost) => {
                    bad += 1;
                    messages.push(format!(
                        "scenario {} {} -> {}: cost {cost:.9}, published {}",
                        i + 1,
                        s.start,
                        s.goal,
                        s.optimal_length
                    ));
                }
                Err(e) => {
                    bad += 1;
                    messages.push(format!("scenario {} {} -> {}: {e}", i + 1, s.start, s.goal));
                }
            }
        }
        outln!(
            "{name:<24} {ok:>6} passed {bad:>4} failed  graph {} nodes {} edges in {build_seconds:.2}s, queries {:.2}s",
            graph.node_count(),
            graph.edge_count(),
            solve.elapsed().as_secs_f64()
        );
        detour.retain(|r| r.is_finite());
        detour.sort_by(f64::total_cmp);
        if let Some(&median) = detour.get(detour.len() / 2) {
            outln!(
                "{:<24} trapezoids: {} cells, {} portals, area {area} = {free} free cells; median path / optimum {median:.3}",
                "",
                cells.cell_count(),
                cells.portals().len()
            );
        }
        let finite: Vec<f64> = theta_ratios.iter().copied().filter(|r| r.is_finite() && *r > 0.0).collect();
        if !finite.is_empty() {
            let mean = finite.iter().sum::<f64>() / finite.len() as f64;
            let worst = finite.iter().copied().fold(1.0, f64::max);
            outln!(
                "{:<24} Theta* on the corners: {} paths, length / optimum mean {mean:.5}, worst {worst:.5}, {:.1} ms per query",
                "",
                finite.len(),
                theta_seconds * 1e3 / theta_ratios.len().max(1) as f64
            );
        }
        print_messages(&messages);
        passed += ok;
        failed += bad;
    }
    outln!("checked in {:.1}s (relative tolerance {rel:e})", clock.elapsed().as_secs_f64());
    outln!("{passed} passed, {failed} failed");
    if failed > 0 { ExitCode::from(1) } else { ExitCode::SUCCESS }
}
