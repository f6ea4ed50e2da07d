//! The roadmaps section: the geometric builders on generated polygon worlds of 10 to 500 random
//! convex hexagons.
//!
//! For each world: the visibility graph's build time on one thread and on every core (and the
//! exponent of the fitted power law in the number of boundary vertices: Lee's sweep is
//! O(n² log n)), the trapezoidal decomposition's, and PRM*'s (1,000 Halton samples); then
//! seeded queries on each roadmap, whose costs are checked against the visibility graph's (the
//! shortest paths: no roadmap may beat them) and reported as ratios. Last, Dubins and Reeds-Shepp shortest-path
//! queries per second on one core.

use std::time::Instant;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::dubins::DubinsPath;
use trailmark::core::freespace::Location;
use trailmark::core::generate;
use trailmark::core::geometry::{Point, Pose, Vector};
use trailmark::core::reeds_shepp::ReedsSheppPath;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::graph::{RoadmapQuery, Trapezoids};
use trailmark::prelude::*;
use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

use crate::bench::lattice::{self, LatticeRow, bench_lattices};
use crate::bench::progress::SectionProgress;
use crate::bench::report::table;
use crate::bench::stats::{fitted_exponent, median};
use crate::bench::suite::Suite;

/// The side of the square worlds.
const SIZE: f64 = 1000.0;
/// The radius of the PRM's robot (the visibility graph's is a point, as in the goal).
const PRM_RADIUS: f64 = 2.0;
/// PRM* samples per world.
const PRM_SAMPLES: usize = 1000;
/// The goal for one world of 500 obstacles, in seconds.
const VISIBILITY_GOAL_S: f64 = 1.0;
/// The goal for Dubins queries per second on one core.
const DUBINS_GOAL: f64 = 5e6;

/// One generated world and what each builder made of it (times: medians over the rounds).
#[derive(Debug, Clone, Serialize)]
pub struct RoadmapRow {
    /// Obstacles in the world.
    pub obstacles: usize,
    /// Boundary vertices of the free space.
    pub vertices: usize,
    /// Visibility-graph nodes (convex corners).
    pub visibility_nodes: usize,
    /// Visibility-graph edges, full graph.
    pub visibility_edges: usize,
    /// Full visibility graph, one thread, milliseconds.
    pub visibility_ms_one_thread: f64,
    /// Full visibility graph, every core, milliseconds.
    pub visibility_ms_all_cores: f64,
    /// Tangent edges only (the reduced visibility graph: the same shortest paths), every core,
    /// milliseconds.
    pub tangent_ms_all_cores: f64,
    /// Tangent edges.
    pub tangent_edges: usize,
    /// Trapezoidal cells.
    pub trapezoid_cells: usize,
    /// Trapezoidal decomposition, milliseconds.
    pub trapezoid_ms: f64,
    /// PRM* edges.
    pub prm_edges: usize,
    /// PRM* build, milliseconds.
    pub prm_ms: f64,
    /// Queries run on each roadmap.
    pub queries: usize,
    /// Queries the PRM solved.
    pub prm_solved: usize,
    /// Median PRM cost / shortest cost over solved queries.
    pub prm_cost_ratio: f64,
    /// Median trapezoid cost / shortest cost.
    pub trapezoid_cost_ratio: f64,
    /// Queries where a roadmap beat the visibility graph (must be 0).
    pub cost_errors: usize,
}

/// The roadmap section's results.
#[derive(Debug, Clone, Serialize)]
pub struct RoadmapReport {
    /// One row per world.
    pub rows: Vec<RoadmapRow>,
    /// One visibility query among thousands of squares, lazy beside full.
    pub lattice: Vec<LatticeRow>,
    /// The fitted exponent k of `time ~ vertices^k`, full visibility graph on one thread.
    pub visibility_exponent: f64,
    /// Dubins shortest paths per second on one core.
    pub dubins_paths_per_s: f64,
    /// Dubins shortest lengths per second on one core.
    pub dubins_lengths_per_s: f64,
    /// Reeds-Shepp shortest paths per second on one core (the same pose pairs).
    pub reeds_shepp_paths_per_s: f64,
    /// Reeds-Shepp shortest lengths per second on one core.
    pub reeds_shepp_lengths_per_s: f64,
}

/// The median of `runs` timings of `f`, in milliseconds, and its last output.
fn timed<T>(runs: u32, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs {
        let clock = Instant::now();
        let out = f();
        times.push(clock.elapsed().as_secs_f64() * 1e3);
        last = Some(out);
    }
    times.sort_by(f64::total_cmp);
    (median(&times), last.expect("at least one run"))
}

/// Runs the section.
pub fn bench_roadmaps(suite: Suite, seed: u64, runs: u32) -> Result<RoadmapReport, String> {
    let (counts, queries): (&[usize], usize) = match suite {
        Suite::Quick => (&[10, 50, 100, 200, 500], 20),
        Suite::Full => (&[10, 20, 50, 100, 200, 300, 500], 100),
    };
    let mut rows = Vec::new();
    let mut progress = SectionProgress::new("roadmaps", counts.len());
    for &count in counts {
        progress.step(format!("{count} obstacles"));
        rows.push(bench_world(count, seed, runs, queries)?);
    }
    let samples: Vec<(f64, f64)> =
        rows.iter().map(|r| (r.vertices as f64, r.visibility_ms_one_thread)).collect();
    let [dubins_paths_per_s, dubins_lengths_per_s, reeds_shepp_paths_per_s, reeds_shepp_lengths_per_s] =
        curve_rates(seed, runs)?;
    Ok(RoadmapReport {
        visibility_exponent: fitted_exponent(&samples),
        rows,
        lattice: bench_lattices(suite, runs)?,
        dubins_paths_per_s,
        dubins_lengths_per_s,
        reeds_shepp_paths_per_s,
        reeds_shepp_lengths_per_s,
    })
}

fn bench_world(count: usize, seed: u64, runs: u32, queries: usize) -> Result<RoadmapRow, String> {
    let err = |e: &dyn std::fmt::Display| format!("{count} obstacles: {e}");
    let world = generate::convex_obstacles(SIZE, count, 6, 0.0, seed).map_err(|e| err(&e))?;
    let space = world.free_space();
    let vertices = space.positions().len();
    let (one, _) = timed(runs, || VisibilityGraph::with_options(space.clone(), Edges::All, 1));
    let (all, visibility) = timed(runs, || VisibilityGraph::with_options(space.clone(), Edges::All, 0));
    let (tangent_ms_all_cores, tangent) =
        timed(runs, || VisibilityGraph::with_options(space.clone(), Edges::Tangent, 0));
    let (trapezoid_ms, cells) = timed(runs, || Trapezoids::new(&space));
    let grown = generate::convex_obstacles(SIZE, count, 6, PRM_RADIUS, seed).map_err(|e| err(&e))?;
    // The grown corners are chords around the exact discs the PRM's checker tests against, in
    // steps of π/8: a path around them is at most 1 / cos(π/16) (2%) longer than around the discs.
    let grown_visibility = VisibilityGraph::with_edges(grown.free_space(), Edges::Tangent);
    let options =
        PrmOptions { sampler: PrmSampler::Halton, connection: Connection::PrmStar, ..PrmOptions::default() };
    let (prm_ms, prm) = timed(runs, || {
        let mut prm = PolygonPrm::new(grown.clone(), options).map_err(|e| err(&e))?;
        prm.grow(PRM_SAMPLES).map_err(|e| err(&e))?;
        Ok::<_, String>(prm)
    });
    let prm = prm?;

    // Seeded queries between points free for the disc robot (and so for the point robot).
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ count as u64);
    let checker = grown.checker();
    let grown_space = grown_visibility.space();
    let mut free_point = || loop {
        let p = Point::new(rng.random_range(0.0..SIZE), rng.random_range(0.0..SIZE));
        if checker.point_is_free(p) && grown_space.locate(p) != Location::Blocked {
            return p;
        }
    };
    let (mut prm_ratios, mut trapezoid_ratios, mut cost_errors) = (Vec::new(), Vec::new(), 0);
    for _ in 0..queries {
        let (a, b) = (free_point(), free_point());
        let shortest =
            |q: &RoadmapQuery<'_, VisibilityGraph>| dijkstra(q, q.start(), q.goal()).map(|f| f.cost());
        let point_best = shortest(&visibility.query(a, b).map_err(|e| err(&e))?).map_err(|e| err(&e))?;
        let disc_best = shortest(&grown_visibility.query(a, b).map_err(|e| err(&e))?).map_err(|e| err(&e))?;
        let q = cells.query(a, b).map_err(|e| err(&e))?;
        if let (Some(best), Some(cost)) =
            (point_best, dijkstra(&q, q.start(), q.goal()).map_err(|e| err(&e))?.cost())
        {
            cost_errors += usize::from(cost < best * (1.0 - 1e-9));
            trapezoid_ratios.push(cost / best);
        }
        let q = prm.query(a, b).map_err(|e| err(&e))?;
        if let Some(cost) = astar(&q, q.start(), q.goal(), q.heuristic()).map_err(|e| err(&e))?.cost() {
            let best =
                disc_best.ok_or_else(|| err(&"the PRM joined points the visibility graph does not"))?;
            cost_errors += usize::from(cost < best * (std::f64::consts::PI / 16.0).cos());
            prm_ratios.push(cost / best);
        }
    }
    prm_ratios.sort_by(f64::total_cmp);
    trapezoid_ratios.sort_by(f64::total_cmp);
    Ok(RoadmapRow {
        obstacles: count,
        vertices,
        visibility_nodes: visibility.node_count(),
        visibility_edges: visibility.edge_count(),
        visibility_ms_one_thread: one,
        visibility_ms_all_cores: all,
        tangent_ms_all_cores,
        tangent_edges: tangent.edge_count(),
        trapezoid_cells: cells.cell_count(),
        trapezoid_ms,
        prm_edges: prm.edge_count(),
        prm_ms,
        queries,
        prm_solved: prm_ratios.len(),
        prm_cost_ratio: median(&prm_ratios),
        trapezoid_cost_ratio: median(&trapezoid_ratios),
        cost_errors,
    })
}

/// Dubins, then Reeds-Shepp, shortest paths and lengths per second on one core: 100,000 seeded
/// pose pairs in a 20 x 20 square, turning radius 1 (the best of the rounds).
fn curve_rates(seed: u64, runs: u32) -> Result<[f64; 4], String> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut pose = || {
        let (x, y, h) =
            (rng.random_range(0.0..20.0), rng.random_range(0.0..20.0), rng.random_range(-3.2..3.2));
        Pose::new(Vector::new(x, y), h)
    };
    let pairs: Vec<(Pose, Pose)> = (0..100_000).map(|_| (pose(), pose())).collect();
    fn rate(pairs: &[(Pose, Pose)], runs: u32, f: impl Fn(&Pose, &Pose) -> f64) -> (f64, f64) {
        let mut best = f64::INFINITY;
        let mut sum = 0.0;
        for _ in 0..runs.max(3) {
            let clock = Instant::now();
            sum = pairs.iter().map(|(a, b)| f(std::hint::black_box(a), b)).sum::<f64>();
            best = best.min(clock.elapsed().as_secs_f64());
        }
        (pairs.len() as f64 / best, sum)
    }
    let (paths, a) =
        rate(&pairs, runs, |a, b| DubinsPath::shortest(a, b, 1.0).map_or(f64::NAN, |p| p.length()));
    let (lengths, b) = rate(&pairs, runs, |a, b| DubinsPath::shortest_length(a, b, 1.0).unwrap_or(f64::NAN));
    if !(a.is_finite() && (a - b).abs() <= 1e-9 * a) {
        return Err(format!("Dubins lengths disagree: paths sum to {a}, lengths to {b}"));
    }
    let (rs_paths, c) =
        rate(&pairs, runs, |a, b| ReedsSheppPath::shortest(a, b, 1.0).map_or(f64::NAN, |p| p.length()));
    let (rs_lengths, d) =
        rate(&pairs, runs, |a, b| ReedsSheppPath::shortest_length(a, b, 1.0).unwrap_or(f64::NAN));
    // Reversing never lengthens a path: the Reeds-Shepp sum is at most the Dubins one.
    if !(c.is_finite() && (c - d).abs() <= 1e-9 * c && c <= a * (1.0 + 1e-9)) {
        return Err(format!("Reeds-Shepp lengths disagree: paths sum to {c}, lengths to {d}, Dubins {a}"));
    }
    Ok([paths, lengths, rs_paths, rs_lengths])
}

/// The section of the report.
pub fn markdown(report: &RoadmapReport) -> String {
    let mut out = String::from(
        "## Roadmaps\n\nGenerated worlds of random convex hexagons in a 1000 x 1000 square (seeded). Visibility graph \
         (full, point robot), trapezoidal decomposition, PRM* (1,000 Halton samples, robot radius 2). Costs are \
         medians over seeded queries, divided by the visibility graph's shortest path for the same robot (for the \
         PRM's disc robot, around corners grown as chords in steps of π/8, so a PRM path may come out up to 2% \
         shorter; a cost error is a path shorter than that, and fails the run).\n\n",
    );
    out.push_str(&table(
        "| obstacles | vertices | visibility nodes / edges | 1 thread | all cores | tangent edges | tangent, all cores | trapezoids | decomposition | PRM* edges | PRM* build | PRM* solved | PRM* cost | trapezoid cost | cost errors |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
        &report.rows,
        |r| {
            format!(
                "| {} | {} | {} / {} | {:.1} ms | {:.1} ms | {} | {:.1} ms | {} | {:.2} ms | {} | {:.1} ms | {}/{} | {:.3} | {:.3} | {} |",
                r.obstacles,
                r.vertices,
                r.visibility_nodes,
                r.visibility_edges,
                r.visibility_ms_one_thread,
                r.visibility_ms_all_cores,
                r.tangent_edges,
                r.tangent_ms_all_cores,
                r.trapezoid_cells,
                r.trapezoid_ms,
                r.prm_edges,
                r.prm_ms,
                r.prm_solved,
                r.queries,
                r.prm_cost_ratio,
                r.trapezoid_cost_ratio,
                r.cost_errors
            )
        },
    ));
    out.push_str(&lattice::markdown(&report.lattice));
    out.push_str(&format!(
        "\nVisibility-graph build time grows like n^{:.2} in the number of boundary vertices n (one thread; \
         Lee's sweep is O(n² log n)).\n\n",
        report.visibility_exponent
    ));
    let met = |ok: bool| if ok { "met" } else { "**not met**" };
    if let Some(largest) = report.rows.iter().find(|r| r.obstacles == 500) {
        let best = largest.visibility_ms_all_cores.min(largest.visibility_ms_one_thread) / 1e3;
        out.push_str(&format!(
            "- Goal: 500 obstacles ({} vertices) built in under {VISIBILITY_GOAL_S} s: {:.2} s on all cores, {:.2} s \
             on one thread: {}.\n",
            largest.vertices,
            largest.visibility_ms_all_cores / 1e3,
            largest.visibility_ms_one_thread / 1e3,
            met(best < VISIBILITY_GOAL_S)
        ));
    }
    out.push_str(&format!(
        "- Goal: Dubins shortest path at least {:.0} M queries per second on one core: {:.2} M paths/s ({:.2}x the \
         goal), {:.2} M lengths/s: {}.\n",
        DUBINS_GOAL / 1e6,
        report.dubins_paths_per_s / 1e6,
        report.dubins_paths_per_s / DUBINS_GOAL,
        report.dubins_lengths_per_s / 1e6,
        met(report.dubins_paths_per_s >= DUBINS_GOAL)
    ));
    out.push_str(&format!(
        "- Reeds-Shepp shortest paths on the same pose pairs: {:.2} M paths/s, {:.2} M lengths/s on one core.\n",
        report.reeds_shepp_paths_per_s / 1e6,
        report.reeds_shepp_lengths_per_s / 1e6,
    ));
    out
}
