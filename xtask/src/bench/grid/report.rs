//! The grid section's report: each planner's speed against its peers, the goals, the time plot
//! and the tables.

use serde::Serialize;

use crate::bench::plots::{BoxSeries, COLOURS, box_plot_svg};
use crate::bench::report::{GoalRow, table};
use crate::bench::stats::geometric_mean;

use super::{GridRow, PLANNERS};

/// The speed of a trailmark planner against its peer on one map.
#[derive(Debug, Clone, Serialize)]
pub struct PeerRatio {
    map: String,
    planner: &'static str,
    peer: &'static str,
    /// Peer median time per query / trailmark median time per query.
    speedup: f64,
}

/// Each trailmark planner's speed against its peers, map by map.
pub fn ratios(rows: &[GridRow]) -> Vec<PeerRatio> {
    let mut out = Vec::new();
    for row in rows {
        let Some(planner) = PLANNERS.iter().find(|p| p.name == row.planner) else { continue };
        for &peer in planner.peers {
            if let Some(other) = rows.iter().find(|r| r.map == row.map && r.planner == peer) {
                out.push(PeerRatio {
                    map: row.map.clone(),
                    planner: row.planner,
                    peer: other.planner,
                    speedup: other.median_us / row.median_us,
                });
            }
        }
    }
    out
}

/// JPS+'s speed over A* in the 2023 Grid-Based Path Planning Competition: A* 23,034.6 s and JPS+
/// 134.3 s over the same 256,000 queries (the entries' published totals).
pub const GPPC_2023_JPS_PLUS_OVER_ASTAR: f64 = 23_034.6 / 134.3;

/// The speedups of `planner` over `peer`, map by map.
fn speedups(ratios: &[PeerRatio], planner: &str, peer: &str) -> Vec<(String, f64)> {
    ratios
        .iter()
        .filter(|r| r.planner == planner && r.peer == peer)
        .map(|r| (r.map.clone(), r.speedup))
        .collect()
}

/// The total time of `peer` over that of `planner` over every query of the maps both ran, as
/// the competition compares entries (`None`: not run).
fn total_time_ratio(rows: &[GridRow], planner: &str, peer: &str) -> Option<f64> {
    let (mut ours, mut theirs) = (0.0, 0.0);
    for row in rows.iter().filter(|r| r.planner == planner) {
        let other = rows.iter().find(|r| r.map == row.map && r.planner == peer)?;
        ours += row.mean_us * row.queries as f64;
        theirs += other.mean_us * other.queries as f64;
    }
    (ours > 0.0).then(|| theirs / ours)
}

/// The goals of the section for the report's goals table.
pub fn goals(ratios: &[PeerRatio], rows: &[GridRow]) -> Vec<GoalRow> {
    let jps = speedups(ratios, "jps", "pathfinding_astar");
    let missing = "the grid section did not run";
    vec![
        GoalRow {
            goal: "grid A* at least 3x faster than `pathfinding` A*",
            figures: speedups(ratios, "astar", "pathfinding_astar"),
            target: 3.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "A* given as closures no slower than `pathfinding` A* on every map",
            figures: speedups(ratios, "closure_astar", "pathfinding_astar"),
            target: 1.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "JPS at least 20x faster than `pathfinding` A* (geometric mean over the maps)",
            figures: if jps.is_empty() {
                Vec::new()
            } else {
                vec![("geometric mean".into(), geometric_mean(jps.iter().map(|f| f.1)))]
            },
            target: 20.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "JPS at least 2x faster than `grid_pathfinding`'s JPS on every map (both with corner cutting)",
            figures: speedups(ratios, "jps_squeeze", "grid_pathfinding_jps"),
            target: 2.0,
            unit: "x",
            missing,
        },
        GoalRow {
            goal: "JPS+ over A* within 2x of GPPC 2023's 171.5x (at least 85.8x; total time over every query)",
            figures: total_time_ratio(rows, "jps_plus", "astar")
                .map(|r| ("total time".into(), r))
                .into_iter()
                .collect(),
            target: GPPC_2023_JPS_PLUS_OVER_ASTAR / 2.0,
            unit: "x",
            missing,
        },
    ]
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
    let mut out = String::from("## Speed against the peers\n\n");
    out.push_str(&table(
        "| map | planner | peer | speedup (peer median / trailmark median) |",
        "|---|---|---|---:|",
        ratios,
        |r| format!("| {} | {} | {} | {:.2}x |", r.map, r.planner, r.peer, r.speedup),
    ));
    for planner in &PLANNERS {
        for &peer in planner.peers {
            let speedups: Vec<f64> = speedups(ratios, planner.name, peer).into_iter().map(|f| f.1).collect();
            if !speedups.is_empty() {
                let worst = speedups.iter().copied().fold(f64::INFINITY, f64::min);
                out.push_str(&format!(
                    "\n**{}** over {peer}: geometric mean speedup {:.2}x over {} maps (lowest {:.2}x).",
                    planner.name,
                    geometric_mean(speedups.iter().copied()),
                    speedups.len(),
                    worst
                ));
            }
        }
    }
    if !rows.is_empty() {
        out.push_str("\n\n![time per query of the optimal one-shot planners](grid-time.svg)");
    }
    out.push_str(
        "\n\nRows named `_squeeze`, and `grid_pathfinding_jps`, allow a diagonal move whenever its target is \
         free (the only rule `grid_pathfinding` 0.3 has); their reference costs are trailmark A*'s on that rule. \
         `grid_pathfinding_jps`'s cost errors are its own (its paths are drawn between jump points that need not \
         lie on one line) and do not fail the run. \
         Made: the time to make the planner for the map (JPS+'s table, `grid_pathfinding`'s grid). \
         Bytes/cell: what a trailmark planner holds between queries, per cell of the map.",
    );
    out.push_str("\n\n## All results\n\n");
    out.push_str(&table(
        "| map | planner | solved | median µs | mean µs | p90 µs | Mexp/s | cost / optimal | cost errors | made ms | bytes/cell |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
        rows,
        |r| {
            format!(
                "| {} | {} | {}/{} | {:.1} | {:.1} | {:.1} | {} | {:.4} | {} | {:.2} | {} |",
                r.map,
                r.planner,
                r.solved,
                r.queries,
                r.median_us,
                r.mean_us,
                r.p90_us,
                r.mexp_per_s.map_or("-".into(), |m| format!("{m:.1}")),
                r.mean_cost_ratio,
                r.cost_errors,
                r.prepare_ms,
                r.bytes_per_cell.map_or("-".into(), |b| format!("{b:.1}")),
            )
        },
    ));
    out.push('\n');
    out
}
