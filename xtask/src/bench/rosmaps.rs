//! The ROS maps section: load, inflate and plan on the Nav2 example maps (`../shared/rosmaps`,
//! when present) and the project's own office map. On seeded start and goal pairs in metres,
//! trailmark's A* beside `pathfinding`'s A* on the same costmap graph (both checked against a
//! Dijkstra reference), Theta*, and A* followed by shortcutting; the load and inflation times.

use std::path::{Path, PathBuf};
use std::time::Instant;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::map::{Costmap, INSCRIBED};
use trailmark::prelude::*;
use trailmark::solve::{RosMapSpec, ros_costmap, ros_travel_cost};

use crate::bench::peer::{neighbours, octile};
use crate::bench::progress::SectionProgress;
use crate::bench::report::GoalRow;
use crate::bench::stats::{geometric_mean, median};
use crate::bench::suite::Suite;
use crate::reference::tolerance;

/// The registry's planners this section measures on costmaps.
pub const MEASURED: [trailmark::solve::PlannerName; 2] =
    [trailmark::solve::PlannerName::AStar, trailmark::solve::PlannerName::ThetaStar];

/// One map's figures.
#[derive(Debug, Clone, Serialize)]
pub struct RosMapRow {
    map: String,
    width: u32,
    height: u32,
    resolution: f64,
    /// Reading the YAML and the image and the occupancy values, ms (median over rounds).
    load_ms: f64,
    /// The costmap from the occupancy (static layer and inflation), ms.
    inflate_ms: f64,
    /// `inflate_ms` per million cells.
    inflate_ms_per_mcell: f64,
    queries: usize,
    /// Median per query, µs: trailmark A*, `pathfinding` A*, Theta* (with the Euclidean
    /// heuristic, and with the octile one), A* then shortcut.
    astar_us: f64,
    pathfinding_us: f64,
    theta_us: f64,
    theta_octile_us: f64,
    shortcut_us: f64,
    /// `pathfinding` median / trailmark median.
    speedup: f64,
    /// Mean cost of Theta* and of the shortcut A* path over A*'s (least) cost.
    theta_cost_ratio: f64,
    theta_octile_cost_ratio: f64,
    shortcut_cost_ratio: f64,
    /// Mean length in metres of the A*, Theta* and shortcut paths over the straight line.
    astar_length_ratio: f64,
    theta_length_ratio: f64,
    shortcut_length_ratio: f64,
    /// Queries where a cost disagreed with the reference or a path was not clear (must be 0).
    pub cost_errors: usize,
}

/// The maps: the office example, then the Nav2 maps when the folder exists.
fn maps() -> Vec<(String, PathBuf)> {
    let root = crate::workspace::root();
    let mut out = vec![("office".to_string(), root.join("examples/maps/office.yaml"))];
    let shared = root.join("../shared/rosmaps");
    if shared.is_dir() {
        for name in ["warehouse", "depot", "tb3_sandbox"] {
            out.push((name.to_string(), shared.join(format!("{name}.yaml"))));
        }
    } else {
        errln!("ROS maps: {} not found, the office map only", shared.display());
    }
    out
}

/// The robot and costmap of the section: Nav2's defaults with a 0.2 m robot.
fn spec(yaml: &Path) -> RosMapSpec {
    RosMapSpec {
        yaml: yaml.to_path_buf(),
        robot_radius: Some(0.2),
        footprint: None,
        inflation_radius: Some(0.55),
        cost_scaling_factor: Some(10.0),
        unknown: None,
        cost_factor: None,
    }
}

/// Runs the section.
pub fn bench(suite: Suite, seed: u64, runs: u32) -> Result<Vec<RosMapRow>, String> {
    let n = match suite {
        Suite::Quick => 12,
        Suite::Full => 100,
    };
    let maps = maps();
    let mut progress = SectionProgress::new("rosmaps", maps.len());
    let mut rows = Vec::new();
    for (name, yaml) in maps {
        progress.step(&name);
        rows.push(bench_map(&name, &yaml, n, seed, runs)?);
    }
    Ok(rows)
}

fn timed<T>(runs: u32, mut f: impl FnMut() -> T) -> (T, f64) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs {
        let clock = Instant::now();
        last = Some(f());
        times.push(clock.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (last.expect("at least one run"), median(&times))
}

fn bench_map(name: &str, yaml: &Path, n: usize, seed: u64, runs: u32) -> Result<RosMapRow, String> {
    let spec = spec(yaml);
    let fail = |e: &dyn std::fmt::Display| format!("{name}: {e}");
    let (map, load_s) = timed(runs, || trailmark::map::load_map(yaml));
    let map = map.map_err(|e| fail(&e))?;
    // The costmap as solve makes it (loading included), less the load alone.
    let (costmap, both_s) = timed(runs, || ros_costmap(&spec, "."));
    let costmap = costmap.map_err(|e| fail(&e))?;
    let inflate_s = (both_s - load_s).max(0.0);
    let frame = *costmap.frame();
    let grid = costmap.to_grid(&ros_travel_cost(&spec, frame.resolution())).map_err(|e| fail(&e))?;
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut search = Search::new();
    let queries = queries(&costmap, &graph, &mut search, n, seed);
    let scale = graph.min_cost();
    let (mut t_astar, mut t_peer, mut t_theta, mut t_short) = (vec![], vec![], vec![], vec![]);
    let mut t_theta_octile = vec![];
    let (mut theta_ratio, mut theta_octile_ratio, mut short_ratio) = (0.0, 0.0, 0.0);
    let (mut astar_len, mut theta_len, mut short_len) = (0.0, 0.0, 0.0);
    let mut cost_errors = 0;
    let metres = |cells: &[Cell]| -> f64 {
        cells.windows(2).map(|w| (frame.centre(w[1]) - frame.centre(w[0])).norm()).sum()
    };
    for &(start, goal, optimal) in &queries {
        let h = graph.heuristic(GridHeuristic::Octile, goal);
        let (astar, t) = timed(runs, || search.astar(&graph, start, goal, h).expect("a valid query"));
        t_astar.push(t);
        let (peer, t) = timed(runs, || {
            pathfinding::prelude::astar(
                &start,
                |&p| neighbours(&graph, p),
                |p| octile(p, goal, scale),
                |&p| p == goal,
            )
        });
        t_peer.push(t);
        let theta_h = graph.heuristic(GridHeuristic::Euclidean, goal);
        let (theta, t) =
            timed(runs, || search.theta_star(&graph, start, goal, theta_h, &graph).expect("a valid query"));
        t_theta.push(t);
        // The octile heuristic overestimates lines but is consistent along the grid's moves:
        // the path still costs no more than A*'s, and far fewer nodes are expanded.
        let (theta_octile, t) =
            timed(runs, || search.theta_star(&graph, start, goal, h, &graph).expect("a valid query"));
        t_theta_octile.push(t);
        let (short, t) = timed(runs, || {
            let path = search.astar(&graph, start, goal, h).expect("a valid query").path.expect("connected");
            graph.shortcut(&path.nodes)
        });
        t_short.push(t);
        let tol = tolerance(optimal);
        let (Some(a), Some((_, p)), Some(th), Some(tho)) = (astar.path, peer, theta.path, theta_octile.path)
        else {
            cost_errors += 1;
            continue;
        };
        let short_cost: f64 =
            short.windows(2).map(|w| graph.line_cost(w[0], w[1]).unwrap_or(f64::INFINITY)).sum();
        let clear = |cells: &[Cell]| {
            cells.windows(2).all(|w| {
                graph
                    .line_cells(w[0], w[1])
                    .is_some_and(|c| c.iter().all(|(c, _)| costmap.cost(*c).is_some_and(|v| v < INSCRIBED)))
            })
        };
        if (a.cost - optimal).abs() > tol
            || (p.0 - optimal).abs() > tol
            || th.cost > optimal + tol
            || tho.cost > optimal + tol
            || !clear(&tho.nodes)
            || short_cost > a.cost + tol
            || !clear(&th.nodes)
            || !clear(&short)
        {
            cost_errors += 1;
        }
        theta_ratio += th.cost / optimal;
        theta_octile_ratio += tho.cost / optimal;
        short_ratio += short_cost / optimal;
        let straight = (frame.centre(goal) - frame.centre(start)).norm().max(1e-9);
        astar_len += metres(&a.nodes) / straight;
        theta_len += metres(&th.nodes) / straight;
        short_len += metres(&short) / straight;
    }
    let q = queries.len().max(1) as f64;
    let med = |t: &mut Vec<f64>| {
        t.sort_by(f64::total_cmp);
        median(t) * 1e6
    };
    let (astar_us, pathfinding_us) = (med(&mut t_astar), med(&mut t_peer));
    let cells = f64::from(frame.width()) * f64::from(frame.height());
    Ok(RosMapRow {
        map: name.to_string(),
        width: frame.width(),
        height: frame.height(),
        resolution: frame.resolution(),
        load_ms: load_s * 1e3,
        inflate_ms: inflate_s * 1e3,
        inflate_ms_per_mcell: inflate_s * 1e3 / (cells / 1e6),
        queries: queries.len(),
        astar_us,
        pathfinding_us,
        theta_us: med(&mut t_theta),
        theta_octile_us: med(&mut t_theta_octile),
        shortcut_us: med(&mut t_short),
        speedup: pathfinding_us / astar_us,
        theta_cost_ratio: theta_ratio / q,
        theta_octile_cost_ratio: theta_octile_ratio / q,
        shortcut_cost_ratio: short_ratio / q,
        astar_length_ratio: astar_len / q,
        theta_length_ratio: theta_len / q,
        shortcut_length_ratio: short_len / q,
        cost_errors: cost_errors + usize::from(map.frame() != costmap.frame()),
    })
}

/// `n` seeded pairs of cells the robot may occupy, joined by a path, with its least cost
/// (Dijkstra, the reference).
fn queries(
    costmap: &Costmap,
    graph: &GridGraph,
    search: &mut Search,
    n: usize,
    seed: u64,
) -> Vec<(Cell, Cell, f64)> {
    let frame = costmap.frame();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut free = || loop {
        let cell = Cell::new(rng.random_range(0..frame.width()), rng.random_range(0..frame.height()));
        if costmap.cost(cell).is_some_and(|c| c < INSCRIBED) {
            return cell;
        }
    };
    let mut out = Vec::new();
    let mut attempts = 0;
    while out.len() < n && attempts < 20 * n {
        attempts += 1;
        let (s, g) = (free(), free());
        if let Some(cost) = search.dijkstra(graph, s, g).expect("a valid query").cost() {
            out.push((s, g, cost));
        }
    }
    out
}

/// The section's goal for the report's goals table.
pub fn goals(rows: &[RosMapRow]) -> Vec<GoalRow> {
    vec![
        GoalRow {
            goal: "A* on a ROS costmap at least 3x faster than `pathfinding` A*",
            figures: rows.iter().map(|r| (r.map.clone(), r.speedup)).collect(),
            target: 3.0,
            unit: "x",
            missing: "the rosmaps section did not run",
        },
        GoalRow {
            goal: "Theta* (Euclidean heuristic) within 3x of A*'s time on every costmap (3 x A* µs / Theta* µs)",
            figures: rows.iter().map(|r| (r.map.clone(), 3.0 * r.astar_us / r.theta_us)).collect(),
            target: 1.0,
            unit: "x",
            missing: "the rosmaps section did not run",
        },
        GoalRow {
            goal: "Theta* (octile heuristic) within 3x of A*'s time on every costmap (3 x A* µs / Theta* µs)",
            figures: rows.iter().map(|r| (r.map.clone(), 3.0 * r.astar_us / r.theta_octile_us)).collect(),
            target: 1.0,
            unit: "x",
            missing: "the rosmaps section did not run",
        },
    ]
}

/// The section of the report.
pub fn markdown(rows: &[RosMapRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = String::from(
        "\n## ROS maps\n\nEach map loaded (map_server's rules), made a costmap (unknown lethal, robot radius 0.2 m, inflation 0.55 m, \
         cost scaling 10) and searched 8-connected with travel cost 1 + 2 x cost / 252 per metre; lethal and inscribed cells blocked. \
         Costs checked against Dijkstra. Theta* with the Euclidean heuristic (a lower bound for lines) and with the octile one \
         (consistent along the grid's moves, so its paths still cost no more than A*'s).\n\n\
         | map | size | load ms | inflate ms | ms / M cells | queries | A* µs | pathfinding µs | speedup | Theta* µs | Theta* octile h µs | A*+shortcut µs | Theta* cost / A* | Theta* octile h cost / A* | shortcut cost / A* | length / straight (A*, Theta*, shortcut) | errors |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n",
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {}x{} @ {} m | {:.1} | {:.1} | {:.1} | {} | {:.0} | {:.0} | {:.2}x | {:.0} | {:.0} | {:.0} | {:.4} | {:.4} | {:.4} | {:.3}, {:.3}, {:.3} | {} |\n",
            r.map, r.width, r.height, r.resolution, r.load_ms, r.inflate_ms, r.inflate_ms_per_mcell, r.queries,
            r.astar_us, r.pathfinding_us, r.speedup, r.theta_us, r.theta_octile_us, r.shortcut_us, r.theta_cost_ratio,
            r.theta_octile_cost_ratio, r.shortcut_cost_ratio, r.astar_length_ratio, r.theta_length_ratio, r.shortcut_length_ratio, r.cost_errors
        ));
    }
    let speedups: Vec<f64> = rows.iter().map(|r| r.speedup).collect();
    out.push_str(&format!(
        "\nA* against `pathfinding` A* on the costmaps: geometric mean {:.2}x over {} maps.\n",
        geometric_mean(speedups.iter().copied()),
        speedups.len()
    ));
    out
}
