//! The anytime section: on the suite's large maps, the time ARA* and AD* take to their first
//! solution at epsilon = 3, against the time of an optimal A*; and the cost of each iteration
//! over time on one query, as a plot.

use plotters::prelude::*;
use serde::Serialize;
use trailmark::core::termination::Termination;
use trailmark::prelude::*;
use trailmark::search::{AdStar, EpsilonSchedule};

use crate::bench::progress::SectionProgress;
use crate::bench::report::{Figure, table};
use crate::bench::stats::median;
use crate::bench::suite::{Suite, SuiteMap};

/// The anytime planners against optimal A* on one map.
#[derive(Debug, Clone, Serialize)]
pub struct AnytimeRow {
    /// The map.
    pub map: String,
    /// Queries measured.
    pub queries: usize,
    /// Median time of an optimal A* query, milliseconds.
    pub astar_ms: f64,
    /// Median time of ARA*'s first solution (epsilon 3), milliseconds.
    pub ara_first_ms: f64,
    /// Median time of ARA* down to epsilon 1, milliseconds.
    pub ara_optimal_ms: f64,
    /// Median time of AD*'s first solution (epsilon 3, a planner reset for each query),
    /// milliseconds.
    pub ad_first_ms: f64,
    /// Mean cost of ARA*'s first solution over the optimum.
    pub ara_first_cost_ratio: f64,
    /// A* median time / ARA* first-solution median time.
    pub ara_speedup: f64,
    /// A* median time / AD* first-solution median time.
    pub ad_speedup: f64,
}

/// The registry's planners this section measures.
pub const MEASURED: [trailmark::solve::PlannerName; 2] =
    [trailmark::solve::PlannerName::AraStar, trailmark::solve::PlannerName::AdStar];

const ANYTIME: EpsilonSchedule = EpsilonSchedule { initial: 3.0, step: 0.5 };

/// The section's results: the table's rows, and the cost-over-time plot with the sentence that
/// gives its figures (`None` without the random map; an error when it could not be drawn).
pub struct AnytimePart {
    /// One row per large map.
    pub rows: Vec<AnytimeRow>,
    /// The plot and its sentence.
    cost_time: Option<Result<(String, String), String>>,
}

/// Runs the section on the suite's maps of 512 x 512 cells or more.
pub fn bench(maps: &[SuiteMap], suite: Suite, runs: u32) -> AnytimePart {
    let large: Vec<&SuiteMap> = maps.iter().filter(|m| m.grid.len() >= 512 * 512).collect();
    let n = match suite {
        Suite::Quick => 10,
        Suite::Full => 50,
    };
    let rows = bench_anytime(&large, n, runs);
    let cost_time = maps.iter().find(|m| m.name.starts_with("random512-25")).map(cost_time_svg);
    AnytimePart { rows, cost_time }
}

impl AnytimePart {
    /// The cost-over-time plot (a warning when it could not be drawn).
    pub fn figures(&self) -> Vec<Figure> {
        match &self.cost_time {
            Some(Ok((svg, _))) => vec![("anytime-cost-time.svg", svg.clone())],
            Some(Err(e)) => {
                errln!("warning: no cost-over-time plot: {e}");
                Vec::new()
            }
            None => Vec::new(),
        }
    }

    /// The report's part on the plot, which follows the table of maps.
    pub fn cost_time_markdown(&self) -> String {
        match &self.cost_time {
            Some(Ok((_, summary))) => format!(
                "\n## Path cost over time\n\n![path cost over time](anytime-cost-time.svg)\n\n{summary}\n"
            ),
            _ => String::new(),
        }
    }
}

/// ARA* and AD* on `n` queries of each of `maps` (spread over the shorter half of its list),
/// against A*.
fn bench_anytime(maps: &[&SuiteMap], n: usize, runs: u32) -> Vec<AnytimeRow> {
    let mut rows = Vec::new();
    let mut progress = SectionProgress::new("anytime", maps.len());
    for map in maps {
        progress.step(&map.name);
        let graph = GridGraph::new(&map.grid, Connectivity::Eight);
        let between = graph.heuristic_between(GridHeuristic::Octile);
        let mut search = Search::new();
        let (mut astar_t, mut first_t, mut full_t, mut ad_t, mut ratio) =
            (vec![], vec![], vec![], vec![], 0.0);
        let queries = map.shorter_half(n);
        // One AD* planner per map, reset for each query, as A* and ARA* reuse their workspace.
        let Some(first) = queries.first() else { continue };
        let mut ad = AdStar::new(&graph, first.start, first.goal, between, ANYTIME).expect("valid query");
        for q in &queries {
            let h = graph.heuristic(GridHeuristic::Octile, q.goal);
            let timed = |f: &mut dyn FnMut() -> f64| {
                let mut t: Vec<f64> = (0..runs).map(|_| f()).collect();
                t.sort_by(f64::total_cmp);
                median(&t)
            };
            astar_t.push(timed(&mut || {
                let found = search.astar(&graph, q.start, q.goal, h).expect("valid query");
                found.stats.elapsed.as_secs_f64() * 1e3
            }));
            let mut first_cost = 0.0;
            first_t.push(timed(&mut || {
                let found = search
                    .ara_star(&graph, q.start, q.goal, h, ANYTIME, Termination::unlimited(), |_| {
                        std::ops::ControlFlow::Break(())
                    })
                    .expect("valid query");
                first_cost = found.cost().unwrap_or(f64::INFINITY);
                found.iterations[0].elapsed.as_secs_f64() * 1e3
            }));
            ratio += first_cost / q.optimal.max(1e-9);
            full_t.push(timed(&mut || {
                let found =
                    search.ara_star(&graph, q.start, q.goal, h, ANYTIME, Termination::unlimited(), |_| {
                        std::ops::ControlFlow::Continue(())
                    });
                found.expect("valid query").stats.elapsed.as_secs_f64() * 1e3
            }));
            ad_t.push(timed(&mut || {
                let clock = std::time::Instant::now();
                ad.reset(&graph, q.start, q.goal).expect("valid query");
                ad.improve_once(&graph).expect("valid query");
                clock.elapsed().as_secs_f64() * 1e3
            }));
        }
        for v in [&mut astar_t, &mut first_t, &mut full_t, &mut ad_t] {
            v.sort_by(f64::total_cmp);
        }
        let (a, f, d) = (median(&astar_t), median(&first_t), median(&ad_t));
        rows.push(AnytimeRow {
            map: map.name.clone(),
            queries: queries.len(),
            astar_ms: a,
            ara_first_ms: f,
            ara_optimal_ms: median(&full_t),
            ad_first_ms: d,
            ara_first_cost_ratio: ratio / queries.len().max(1) as f64,
            ara_speedup: a / f.max(1e-9),
            ad_speedup: a / d.max(1e-9),
        });
    }
    rows
}

/// A plot of path cost against time for ARA* and AD* on the query of `map` with the longest
/// optimal path, with optimal A* as a point: an SVG document, and a sentence that gives the
/// plotted figures.
fn cost_time_svg(map: &SuiteMap) -> Result<(String, String), String> {
    let q = map.queries.iter().max_by(|a, b| a.optimal.total_cmp(&b.optimal)).ok_or("no query")?;
    let graph = GridGraph::new(&map.grid, Connectivity::Eight);
    let h = graph.heuristic(GridHeuristic::Octile, q.goal);
    let fine = EpsilonSchedule::new(3.0, 0.1);
    let ara = trailmark::search::ara_star(&graph, q.start, q.goal, h, fine, Termination::unlimited())
        .map_err(|e| e.to_string())?;
    let mut planner =
        AdStar::new(&graph, q.start, q.goal, graph.heuristic_between(GridHeuristic::Octile), fine)
            .map_err(|e| e.to_string())?;
    let ad = planner.improve(&graph, Termination::unlimited()).map_err(|e| e.to_string())?;
    let astar = Search::new().astar(&graph, q.start, q.goal, h).map_err(|e| e.to_string())?;
    let points = |it: &[trailmark::search::Iteration]| -> Vec<(f64, f64)> {
        it.iter().filter_map(|i| Some((i.elapsed.as_secs_f64() * 1e3, i.cost?))).collect()
    };
    let (ara_pts, ad_pts) = (points(&ara.iterations), points(&ad.iterations));
    let astar_pt = (astar.stats.elapsed.as_secs_f64() * 1e3, astar.cost().ok_or("unreachable")?);
    let summary = match (ara_pts.first(), ara_pts.last(), ad_pts.first(), ad_pts.last()) {
        (Some(a0), Some(a1), Some(d0), Some(d1)) => format!(
            "Query ({}, {}) -> ({}, {}) on {}: A* finds the optimum {:.2} in {:.2} ms. ARA*'s first path \
             comes in {:.2} ms at {:.1}% above it, its last (epsilon 1) at {:.2} ms; AD*'s first in \
             {:.2} ms ({:.1}% above), its last at {:.2} ms.",
            q.start.x,
            q.start.y,
            q.goal.x,
            q.goal.y,
            map.name,
            astar_pt.1,
            astar_pt.0,
            a0.0,
            (a0.1 / astar_pt.1 - 1.0) * 100.0,
            a1.0,
            d0.0,
            (d0.1 / astar_pt.1 - 1.0) * 100.0,
            d1.0,
        ),
        _ => "No anytime path found.".to_string(),
    };
    let all: Vec<(f64, f64)> = ara_pts.iter().chain(&ad_pts).chain([&astar_pt]).copied().collect();
    let t_max = all.iter().map(|p| p.0).fold(0.0, f64::max) * 1.05;
    let c_min = all.iter().map(|p| p.1).fold(f64::INFINITY, f64::min) * 0.98;
    let c_max = all.iter().map(|p| p.1).fold(0.0, f64::max) * 1.02;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (720, 420)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!("{}: path cost over time (query {} -> {})", map.name, q.start, q.goal),
                ("sans-serif", 16),
            )
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d(0.0..t_max, c_min..c_max)
            .map_err(|e| e.to_string())?;
        chart.configure_mesh().x_desc("time (ms)").y_desc("path cost").draw().map_err(|e| e.to_string())?;
        let step = |pts: &[(f64, f64)]| -> Vec<(f64, f64)> {
            let mut out = Vec::new();
            for (i, &(t, c)) in pts.iter().enumerate() {
                if i > 0 {
                    out.push((t, pts[i - 1].1));
                }
                out.push((t, c));
            }
            if let Some(&(_, c)) = pts.last() {
                out.push((t_max, c));
            }
            out
        };
        let ara_colour = RGBColor(225, 48, 108);
        let ad_colour = RGBColor(22, 160, 133);
        chart
            .draw_series(LineSeries::new(step(&ara_pts), ara_colour.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("ARA* (epsilon 3 down by 0.1)")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], ara_colour.stroke_width(2)));
        chart
            .draw_series(LineSeries::new(step(&ad_pts), ad_colour.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("AD* (epsilon 3 down by 0.1)")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], ad_colour.stroke_width(2)));
        chart
            .draw_series(std::iter::once(Circle::new(astar_pt, 5, BLACK.filled())))
            .map_err(|e| e.to_string())?
            .label("A* (optimal)")
            .legend(|(x, y)| Circle::new((x + 9, y), 4, BLACK.filled()));
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok((svg, summary))
}

/// The section's table.
pub fn markdown(anytime: &[AnytimeRow]) -> String {
    let mut out = String::new();
    if !anytime.is_empty() {
        out.push_str("## Anytime planners: time to the first solution (goal: 5x below optimal A*)\n\n");
        out.push_str(&table(
            "| map | queries | A* ms | ARA* first ms | speedup | first cost / optimal | ARA* to optimal ms | AD* first ms | speedup |",
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|",
            anytime,
            |r| {
                format!(
                    "| {} | {} | {:.2} | {:.2} | {:.1}x | {:.3} | {:.2} | {:.2} | {:.1}x |",
                    r.map,
                    r.queries,
                    r.astar_ms,
                    r.ara_first_ms,
                    r.ara_speedup,
                    r.ara_first_cost_ratio,
                    r.ara_optimal_ms,
                    r.ad_first_ms,
                    r.ad_speedup
                )
            },
        ));
        out.push('\n');
    }
    out
}
