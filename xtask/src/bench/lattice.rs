//! The lattice table of the roadmaps section: one visibility query among thousands of unit
//! squares (a square world with a block at every odd cell), by the lazy visibility graph's
//! rounds, beside building the full tangent graph once and searching it (up to 2,500 squares:
//! beyond, the build takes minutes). Lengths must agree.

use std::time::Instant;

use serde::Serialize;
use trailmark::core::freespace::FreeSpace;
use trailmark::core::generate;
use trailmark::core::geometry::Point;
use trailmark::graph::LazyVisibilityGraph;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::prelude::*;

use crate::bench::report::GoalRow;
use crate::bench::stats::median;
use crate::bench::suite::Suite;

/// The goal for one query among 2,500 squares, in seconds.
const LATTICE_GOAL_S: f64 = 1.0;
/// The largest lattice whose full graph is built beside (2,500 squares: seconds; 10,000: minutes).
const FULL_UP_TO: usize = 2500;

/// One query on one lattice.
#[derive(Debug, Clone, Serialize)]
pub struct LatticeRow {
    /// Unit squares (blocks) in the world.
    pub squares: usize,
    /// Visibility nodes (convex corners).
    pub nodes: usize,
    /// What the query is.
    pub query: &'static str,
    /// The shortest length.
    pub length: f64,
    /// The length over the straight line.
    pub detour: f64,
    /// Rounds of the lazy search.
    pub rounds: usize,
    /// Nodes swept in the last round.
    pub swept: usize,
    /// The lazy query, node table included, median milliseconds.
    pub lazy_ms: f64,
    /// The full tangent graph's build, every core, milliseconds (none where too large; once
    /// per lattice).
    pub full_build_ms: Option<f64>,
    /// The full graph's query (joining the ends and A*), milliseconds.
    pub full_query_ms: Option<f64>,
    /// Whether the full graph's length differs (must not).
    pub cost_error: bool,
}

/// The lazy rounds from `start` to `goal`: the length, the rounds, the nodes swept last.
fn lazy_query(
    graph: &LazyVisibilityGraph,
    start: Point,
    goal: Point,
) -> Result<(Option<f64>, usize, usize), String> {
    let mut bound = LazyVisibilityGraph::first_bound(start, goal);
    for round in 1.. {
        let bounded = graph.within(start, goal, bound).map_err(|e| e.to_string())?;
        let q = bounded.query();
        let cost = astar(&q, q.start(), q.goal(), q.heuristic()).map_err(|e| e.to_string())?.cost();
        match bounded.next_bound(cost) {
            Some(next) => bound = next,
            None => return Ok((cost, round, bounded.swept())),
        }
    }
    unreachable!("the rounds end at the unbounded one")
}

/// Runs the table: lattices of 100 and 400 squares (beside the full graph) and 2,500 (the full
/// suite adds 10,000), three queries each.
pub fn bench_lattices(suite: Suite, runs: u32) -> Result<Vec<LatticeRow>, String> {
    let sizes: &[usize] = match suite {
        Suite::Quick => &[10, 20, 50],
        Suite::Full => &[10, 20, 50, 100],
    };
    let mut rows = Vec::new();
    for &k in sizes {
        let space = FreeSpace::from_grid(&generate::lattice(k).map_err(|e| e.to_string())?);
        let full = (k * k <= FULL_UP_TO).then(|| {
            let clock = Instant::now();
            let graph = VisibilityGraph::with_edges(space.clone(), Edges::Tangent);
            (graph, clock.elapsed().as_secs_f64() * 1e3)
        });
        let s = (2 * k + 1) as f64;
        let queries = [
            ("corner to corner", Point::new(0.5, 0.5), Point::new(s - 0.5, s - 0.5)),
            ("across, 1 in 10 up", Point::new(0.5, s / 2.0), Point::new(s - 0.5, s / 2.0 + s / 10.0)),
            ("corner to side, 3 in 10 up", Point::new(0.0, 0.0), Point::new(s, 0.3 * s)),
        ];
        for (query, start, goal) in queries {
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..runs.max(1) {
                let clock = Instant::now();
                let graph = LazyVisibilityGraph::new(space.clone());
                let found = lazy_query(&graph, start, goal)?;
                times.push(clock.elapsed().as_secs_f64() * 1e3);
                last = Some((found, graph.node_count()));
            }
            times.sort_by(f64::total_cmp);
            let ((length, rounds, swept), nodes) = last.expect("at least one run");
            let length = length.ok_or_else(|| format!("{query} on {} squares: no path", k * k))?;
            let (mut full_query_ms, mut cost_error) = (None, false);
            if let Some((graph, _)) = &full {
                let clock = Instant::now();
                let q = graph.query(start, goal).map_err(|e| e.to_string())?;
                let cost = astar(&q, q.start(), q.goal(), q.heuristic()).map_err(|e| e.to_string())?.cost();
                full_query_ms = Some(clock.elapsed().as_secs_f64() * 1e3);
                cost_error = cost.is_none_or(|f| (f - length).abs() > 1e-9 * f);
            }
            rows.push(LatticeRow {
                squares: k * k,
                nodes,
                query,
                length,
                detour: length / (goal - start).norm(),
                rounds,
                swept,
                lazy_ms: median(&times),
                full_build_ms: full.as_ref().map(|f| f.1),
                full_query_ms,
                cost_error,
            });
        }
    }
    Ok(rows)
}

/// The goal row: every query among 2,500 squares under a second (the figure: a second over
/// the time).
pub fn goal(rows: &[LatticeRow]) -> GoalRow {
    GoalRow {
        goal: "A visibility query among 2,500 unit squares under 1 s (figure: 1 s / the query's time)",
        figures: rows
            .iter()
            .filter(|r| r.squares == 2500)
            .map(|r| (r.query.to_string(), LATTICE_GOAL_S * 1e3 / r.lazy_ms))
            .collect(),
        target: 1.0,
        unit: "x",
        missing: "the roadmaps section did not run",
    }
}

/// The table of the report.
pub fn markdown(rows: &[LatticeRow]) -> String {
    let mut out = String::from(
        "\n### One query among thousands of squares\n\nA square world of side 2k + 1 with a unit block at every odd \
         cell (k² blocks, 4k² visibility nodes). The lazy visibility graph sweeps a node when A* first expands it, \
         looking only at the boundary near the ellipse its round's bound allows (rounds: the straight line + 1/128, \
         then the length a round found, growing to infinity); its time includes the node table; nodes swept in \
         its last round. The full tangent graph beside it up to 2,500 squares: built once on every core (one run), \
         then each query joined and searched. Lengths must agree.\n\n\
         | squares | nodes | query | length | / straight | rounds | nodes swept | lazy | full graph: build | full: query |\n\
         |---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let ms = |t: Option<f64>| t.map_or("–".to_string(), |ms| format!("{ms:.1} ms"));
        let error = if r.cost_error { " **length differs**" } else { "" };
        out.push_str(&format!(
            "| {} | {} | {} | {:.4}{error} | {:.4} | {} | {} | {:.1} ms | {} | {} |\n",
            r.squares,
            r.nodes,
            r.query,
            r.length,
            r.detour,
            r.rounds,
            r.swept,
            r.lazy_ms,
            ms(r.full_build_ms),
            ms(r.full_query_ms)
        ));
    }
    out
}
