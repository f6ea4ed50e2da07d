//! The grid section: every one-shot grid planner on the suite's maps beside the `pathfinding`
//! crate, each cost checked against the reference (the published optimum on MovingAI maps,
//! trailmark's Dijkstra on generated ones).
//!
//! Every planner solves the same queries on the same graph semantics (8-connected, no corner
//! cutting, costs 1 and sqrt(2)); a disagreement with the reference fails the run: a benchmark of
//! wrong answers measures nothing.

use std::time::Instant;

use serde::Serialize;
use trailmark::prelude::*;

use crate::bench::peer::{neighbours, octile};
use crate::bench::plots::{BoxSeries, COLOURS, box_plot_svg};
use crate::bench::progress::SectionProgress;
use crate::bench::report::GoalRow;
use crate::bench::stats::{geometric_mean, median};
use crate::bench::suite::{GridQuery, SuiteMap};
use crate::reference::tolerance;

/// The weight of the benchmarked weighted A*.
pub const WEIGHT: f64 = 2.0;

/// What one query gave: the cost (`None`: no path) and, for trailmark, the expansions.
type Solved = (Option<f64>, Option<u64>);

/// A planner of the section: everything the harness needs to know of it, in one entry of
/// [`PLANNERS`].
pub struct GridPlanner {
    /// The name in `--only` and the report.
    pub name: &'static str,
    /// The library it comes from.
    library: &'static str,
    /// The factor the cost may exceed the optimum by (`None`: no bound, BFS and DFS).
    bound: Option<f64>,
    /// Whether its paths are any-angle lines, which may be shorter than the grid's optimum
    /// (but never shorter than the straight line from start to goal).
    any_angle: bool,
    /// The planner this one is compared with in the report.
    peer: Option<&'static str>,
    /// Its colour in the time plot (`None`: not plotted).
    plot_colour: Option<usize>,
    /// Solves one query.
    solve: fn(&GridGraph, &mut Search, &GridQuery) -> Solved,
}

/// The planners, in the order they run and are reported.
pub const PLANNERS: [GridPlanner; 9] = [
    GridPlanner {
        name: "astar",
        library: TRAILMARK,
        bound: Some(1.0),
        any_angle: false,
        peer: Some("pathfinding_astar"),
        plot_colour: Some(0),
        solve: |graph, search, q| {
            ours(search.astar(graph, q.start, q.goal, graph.heuristic(GridHeuristic::Octile, q.goal)))
        },
    },
    GridPlanner {
        name: "pathfinding_astar",
        library: PATHFINDING,
        bound: Some(1.0),
        any_angle: false,
        peer: None,
        plot_colour: Some(2),
        solve: |graph, _, q| {
            let h = |p: &Cell| octile(p, q.goal, 1.0);
            let r = pathfinding::prelude::astar(&q.start, |&p| neighbours(graph, p), h, |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        },
    },
    GridPlanner {
        name: "pathfinding_fringe",
        library: PATHFINDING,
        bound: Some(1.0),
        any_angle: false,
        peer: None,
        plot_colour: Some(3),
        solve: |graph, _, q| {
            let h = |p: &Cell| octile(p, q.goal, 1.0);
            let r = pathfinding::prelude::fringe(&q.start, |&p| neighbours(graph, p), h, |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        },
    },
    GridPlanner {
        name: "weighted_astar",
        library: TRAILMARK,
        bound: Some(WEIGHT),
        any_angle: false,
        peer: None,
        plot_colour: None,
        solve: |graph, search, q| {
            ours(search.weighted_astar(
                graph,
                q.start,
                q.goal,
                graph.heuristic(GridHeuristic::Octile, q.goal),
                WEIGHT,
            ))
        },
    },
    GridPlanner {
        name: "dijkstra",
        library: TRAILMARK,
        bound: Some(1.0),
        any_angle: false,
        peer: Some("pathfinding_dijkstra"),
        plot_colour: None,
        solve: |graph, search, q| ours(search.dijkstra(graph, q.start, q.goal)),
    },
    GridPlanner {
        name: "pathfinding_dijkstra",
        library: PATHFINDING,
        bound: Some(1.0),
        any_angle: false,
        peer: None,
        plot_colour: None,
        solve: |graph, _, q| {
            let r = pathfinding::prelude::dijkstra(&q.start, |&p| neighbours(graph, p), |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        },
    },
    GridPlanner {
        name: "theta_star",
        library: TRAILMARK,
        bound: Some(1.0),
        any_angle: true,
        peer: None,
        plot_colour: None,
        solve: |graph, search, q| {
            let h = graph.heuristic(GridHeuristic::Euclidean, q.goal);
            ours(search.theta_star(graph, q.start, q.goal, h, graph))
        },
    },
    GridPlanner {
        name: "bfs",
        library: TRAILMARK,
        bound: None,
        any_angle: false,
        peer: None,
        plot_colour: None,
        solve: |graph, search, q| ours(search.bfs(graph, q.start, q.goal)),
    },
    GridPlanner {
        name: "dfs",
        library: TRAILMARK,
        bound: None,
        any_angle: false,
        peer: None,
        plot_colour: None,
        solve: |graph, search, q| ours(search.dfs(graph, q.start, q.goal)),
    },
];

const TRAILMARK: &str = "trailmark";
const PATHFINDING: &str = "pathfinding 4";

/// A trailmark search's cost and expansions.
fn ours(r: Result<SearchResult<Cell>, SearchError<Cell>>) -> Solved {
    let r = r.expect("benchmark queries are valid");
    (r.cost(), Some(r.stats.expansions))
}

/// The planners `only` names (all of them when it names none).
pub fn chosen(only: &[String]) -> Vec<&'static GridPlanner> {
    PLANNERS.iter().filter(|p| only.is_empty() || only.iter().any(|o| o == p.name)).collect()
}

/// The results of one planner on one map.
#[derive(Debug, Clone, Serialize)]
pub struct GridRow {
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
    pub cost_errors: usize,
    /// Bytes held by the search workspace after the map (trailmark planners only).
    workspace_bytes: Option<usize>,
    /// Each query's time (its median over the rounds), µs, sorted (for the plots; not
    /// serialized).
    #[serde(skip)]
    times_us: Vec<f64>,
}

/// The speed of a trailmark planner against its peer on one map.
#[derive(Debug, Clone, Serialize)]
pub struct PeerRatio {
    map: String,
    planner: &'static str,
    peer: &'static str,
    /// Peer median time per query / trailmark median time per query.
    speedup: f64,
}

/// Runs `planners` on every map, `runs` rounds each.
pub fn bench_grid(maps: &[SuiteMap], planners: &[&GridPlanner], runs: u32) -> Vec<GridRow> {
    let mut rows = Vec::new();
    let mut progress = SectionProgress::new("grid", maps.len());
    for map in maps {
        progress.step(format!("{} ({} queries)", map.name, map.queries.len()));
        rows.extend(bench_map(map, planners, runs));
    }
    rows
}

/// Runs every planner on `map`: `runs` rounds, planners alternating within each round.
fn bench_map(map: &SuiteMap, planners: &[&GridPlanner], runs: u32) -> Vec<GridRow> {
    let graph = GridGraph::new(&map.grid, Connectivity::Eight);
    let n = map.queries.len();
    let mut times = vec![vec![Vec::with_capacity(runs as usize); n]; planners.len()];
    let mut outcomes = vec![vec![(None, None); n]; planners.len()];
    let mut searches: Vec<Search> = planners.iter().map(|_| Search::new()).collect();
    for _ in 0..runs {
        for (k, planner) in planners.iter().enumerate() {
            for (i, q) in map.queries.iter().enumerate() {
                let clock = Instant::now();
                let outcome = (planner.solve)(&graph, &mut searches[k], q);
                times[k][i].push(clock.elapsed().as_secs_f64());
                outcomes[k][i] = outcome;
            }
        }
    }
    planners
        .iter()
        .enumerate()
        .map(|(k, planner)| {
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
                // No grid path beats the optimum (no any-angle path the straight line); bounded
                // planners stay within their bound.
                let tol = tolerance(q.optimal);
                let above_bound = planner.bound.is_some_and(|b| cost > b * q.optimal + tol);
                let floor = if planner.any_angle {
                    f64::from(q.start.x.abs_diff(q.goal.x)).hypot(f64::from(q.start.y.abs_diff(q.goal.y)))
                } else {
                    q.optimal
                };
                if cost < floor - tol || above_bound {
                    cost_errors += 1;
                }
            }
            let tm = planner.library == TRAILMARK;
            GridRow {
                map: map.name.clone(),
                planner: planner.name,
                library: planner.library,
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

/// Each trailmark planner's speed against its peer, map by map.
pub fn ratios(rows: &[GridRow]) -> Vec<PeerRatio> {
    let mut out = Vec::new();
    for row in rows {
        let Some(planner) = PLANNERS.iter().find(|p| p.name == row.planner) else { continue };
        let Some(peer) = planner.peer else { continue };
        if let Some(other) = rows.iter().find(|r| r.map == row.map && r.planner == peer) {
            out.push(PeerRatio {
                map: row.map.clone(),
                planner: row.planner,
                peer: other.planner,
                speedup: other.median_us / row.median_us,
            });
        }
    }
    out
}

/// The goal of the section for the report's goals table.
pub fn goal(ratios: &[PeerRatio]) -> GoalRow {
    GoalRow {
        goal: "grid A* at least 3x faster than `pathfinding` A*",
        figures: ratios.iter().filter(|r| r.planner == "astar").map(|r| (r.map.clone(), r.speedup)).collect(),
        target: 3.0,
        unit: "x",
        missing: "the grid section did not run",
    }
}

/// The one-shot optimal planners' time per query on every map, trailmark's A* beside the
/// `pathfinding` crate's A* and fringe search, as box plots.
pub fn time_svg(maps: &[String], rows: &[GridRow]) -> Result<String, String> {
    let series: Vec<BoxSeries> = PLANNERS
        .iter()
        .filter_map(|p| Some((p, p.plot_colour?)))
        .filter(|(p, _)| rows.iter().any(|r| r.planner == p.name))
        .map(|(p, colour)| BoxSeries {
            name: p.name.to_string(),
            colour: COLOURS[colour],
            values: maps
                .iter()
                .map(|m| {
                    let row = rows.iter().find(|r| &r.map == m && r.planner == p.name);
                    row.map_or(Vec::new(), |r| r.times_us.clone())
                })
                .collect(),
        })
        .collect();
    box_plot_svg(
        "Grid search: time per query (box: quartiles; whiskers: 1.5 IQR)",
        "microseconds",
        maps,
        &series,
    )
}

/// The section of the report: the speed against the peers and every result.
pub fn markdown(rows: &[GridRow], ratios: &[PeerRatio]) -> String {
    let mut out = String::from(
        "## Speed against `pathfinding`\n\n| map | planner | peer | speedup (peer median / trailmark median) |\n|---|---|---|---:|\n",
    );
    for r in ratios {
        out.push_str(&format!("| {} | {} | {} | {:.2}x |\n", r.map, r.planner, r.peer, r.speedup));
    }
    for planner in PLANNERS.iter().filter(|p| p.peer.is_some()).map(|p| p.name) {
        let speedups: Vec<f64> = ratios.iter().filter(|r| r.planner == planner).map(|r| r.speedup).collect();
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
    if !rows.is_empty() {
        out.push_str("\n\n![time per query of the optimal one-shot planners](grid-time.svg)");
    }
    out.push_str("\n\n## All results\n\n| map | planner | solved | median µs | mean µs | p90 µs | Mexp/s | cost / optimal | cost errors |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for r in rows {
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
    out
}
