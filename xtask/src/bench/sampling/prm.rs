//! PRM* in the sampling section: on each world, one roadmap shared by all the world's queries,
//! trailmark's [`PolygonPrm`] beside OMPL's PRMstar (with `--with-ompl`).
//!
//! Both grow a roadmap of the same number of uniform samples, each joined to its
//! `⌈e (1 + 1/d) ln n⌉` nearest neighbours, validating states and motions with the same exact
//! checker; then each query joins its start and goal to the roadmap and searches it with A*.
//! trailmark's query leaves the roadmap as it was; OMPL's, like its `PRM::solve`, keeps the
//! start and goal as milestones, so its roadmap grows by two per query. Every path is re-checked
//! exactly and compared with the visibility graph's optimum, as in the rest of the section.

use std::time::Instant;

use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::prelude::*;
use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

use crate::bench::ompl::{OmplDriver, OmplInput};
use crate::bench::sampling::world::{PlaneQuery, SamplingWorld, ompl_queries, points};
use crate::bench::stats::median;

/// The name in `--only`, the JSON results and the OMPL driver's input.
pub const NAME: &str = trailmark::solve::PlannerName::PrmStar.name();

/// PRM* of trailmark and (with `--with-ompl`) OMPL on one world.
#[derive(Debug, Clone, Serialize)]
pub struct PrmRow {
    /// The world.
    pub world: String,
    /// Samples in each roadmap.
    pub samples: usize,
    /// Seeded queries run.
    pub queries: usize,
    /// Queries with a path (by the visibility graph).
    pub solvable: usize,
    /// trailmark's PRM*.
    pub trailmark: PrmStats,
    /// OMPL's PRMstar on the same world and queries.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ompl: Option<PrmStats>,
}

impl PrmRow {
    /// OMPL's build time over trailmark's.
    pub fn build_speedup(&self) -> Option<f64> {
        self.ompl.as_ref().map(|o| o.build_ms / self.trailmark.build_ms)
    }

    /// OMPL's median query time over trailmark's.
    pub fn query_speedup(&self) -> Option<f64> {
        self.ompl.as_ref().map(|o| o.median_query_us / self.trailmark.median_query_us)
    }
}

/// One library's roadmap and its queries on a world.
#[derive(Debug, Clone, Serialize)]
pub struct PrmStats {
    /// The time of growing the roadmap, milliseconds.
    pub build_ms: f64,
    /// Its nodes.
    pub nodes: usize,
    /// Its edges.
    pub edges: usize,
    /// State and motion checks while growing it.
    pub build_checks: u64,
    /// Solvable queries solved.
    pub solved: usize,
    /// Median time per solvable query (joining the ends and searching), microseconds.
    pub median_query_us: f64,
    /// Median path cost over the optimum, over the solved queries.
    pub median_cost_ratio: f64,
    /// Paths that failed the re-check, or solutions where the visibility graph has no path
    /// (must be 0).
    pub invalid: usize,
}

/// Per-query results as they come.
#[derive(Default)]
struct PrmTally {
    times_us: Vec<f64>,
    ratios: Vec<f64>,
    solvable: usize,
    solved: usize,
    invalid: usize,
}

impl PrmTally {
    /// One query of optimum `best` (`None`: no path) answered in `us` with `path` (`None`:
    /// not connected).
    fn add(&mut self, w: &SamplingWorld, (a, b, best): PlaneQuery, us: f64, path: Option<&[Point]>) {
        let Some(best) = best else {
            self.invalid += usize::from(path.is_some());
            return;
        };
        self.solvable += 1;
        self.times_us.push(us);
        let Some(path) = path else { return };
        self.solved += 1;
        match w.checked_cost(path, a, b, best) {
            Some(cost) => self.ratios.push(cost / best),
            None => self.invalid += 1,
        }
    }

    fn stats(mut self, build_ms: f64, nodes: usize, edges: usize, build_checks: u64) -> PrmStats {
        self.times_us.sort_by(f64::total_cmp);
        self.ratios.sort_by(f64::total_cmp);
        PrmStats {
            build_ms,
            nodes,
            edges,
            build_checks,
            solved: self.solved,
            median_query_us: median(&self.times_us),
            median_cost_ratio: median(&self.ratios),
            invalid: self.invalid,
        }
    }
}

/// Builds trailmark's roadmap of `samples` on `w`, answers `queries` on it, and does the same
/// with OMPL's when `ompl` is given.
pub fn bench_prm(
    w: &SamplingWorld,
    queries: &[PlaneQuery],
    samples: usize,
    seed: u64,
    ompl: Option<&OmplDriver>,
) -> Result<PrmRow, String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: PRM*: {e}", w.name);
    let options = PrmOptions {
        sampler: PrmSampler::Uniform { seed },
        connection: Connection::PrmStar,
        ..PrmOptions::default()
    };
    let clock = Instant::now();
    let mut prm = PolygonPrm::new(w.world.clone(), options).map_err(|e| err(&e))?;
    prm.grow(samples).map_err(|e| err(&e))?;
    let build_ms = clock.elapsed().as_secs_f64() * 1e3;
    let mut tally = PrmTally::default();
    for &(a, b, best) in queries {
        let clock = Instant::now();
        let q = prm.query(a, b).map_err(|e| err(&e))?;
        let found = astar(&q, q.start(), q.goal(), q.heuristic()).map_err(|e| err(&e))?;
        let path = found.path.map(|p| q.positions(&p.nodes));
        let us = clock.elapsed().as_secs_f64() * 1e6;
        tally.add(w, (a, b, best), us, path.as_deref());
    }
    let solvable = tally.solvable;
    let checks = prm.attempts() + prm.local_paths_checked();
    let trailmark = tally.stats(build_ms, prm.node_count(), prm.edge_count(), checks);
    let ompl = match ompl {
        Some(driver) => Some(ompl_prm(w, queries, samples, seed, driver)?),
        None => None,
    };
    Ok(PrmRow { world: w.name.clone(), samples, queries: queries.len(), solvable, trailmark, ompl })
}

fn ompl_prm(
    w: &SamplingWorld,
    queries: &[PlaneQuery],
    samples: usize,
    seed: u64,
    driver: &OmplDriver,
) -> Result<PrmStats, String> {
    let input = OmplInput {
        space: None,
        turning_radius: None,
        world: Some(&w.world),
        boxes: None,
        planner: NAME,
        queries: ompl_queries(queries),
        runs: 1,
        seed,
        max_iterations: 0,
        time_limit_s: 60.0,
        roadmap_size: samples,
    };
    let (build, runs) = driver.run_roadmap(&input).map_err(|e| format!("{}: {e}", w.name))?;
    if build.milestones < samples as u64 {
        return Err(format!("{}: OMPL's PRMstar grew {} of {samples} milestones", w.name, build.milestones));
    }
    let mut tally = PrmTally::default();
    for run in &runs {
        let query =
            *queries.get(run.query).ok_or_else(|| format!("{}: OMPL ran an unknown query", w.name))?;
        let path: Option<Vec<Point>> = run.exact().then(|| points(&run.path));
        tally.add(w, query, run.time_s * 1e6, path.as_deref());
    }
    let (nodes, edges) = (build.milestones as usize, build.edges as usize);
    Ok(tally.stats(build.time_s * 1e3, nodes, edges, build.collision_checks))
}

/// The PRM* table.
pub fn markdown(rows: &[PrmRow], ompl_version: Option<&str>) -> String {
    let Some(first) = rows.first() else { return String::new() };
    let mut s = format!(
        "### PRM* ({} uniform samples, one roadmap per world for all its queries)\n\n\
         Each sample is joined to its ⌈e (1 + 1/d) ln n⌉ nearest neighbours. A query joins its start and \
         goal to the roadmap the same way and searches it with A*; its time includes both. Every path is \
         re-checked exactly.",
        first.samples
    );
    if let Some(version) = ompl_version.filter(|_| rows.iter().any(|r| r.ompl.is_some())) {
        s.push_str(&format!(
            " Beside OMPL {version} PRMstar: the same number of milestones (grown with `growRoadmap`), the \
             same checker through its C interface, and each query as `PRM::solve` answers it (`addMilestone` \
             for the start and the goal, which stay in OMPL's roadmap, then PRM's A*) without `solve`'s \
             polling thread."
        ));
    }
    s.push_str(
        "\n\n| world | library | nodes / edges | build ms | build checks | solved | median query µs | median cost / optimum | invalid | build speedup | query speedup |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        for (library, stats) in [("trailmark", Some(&r.trailmark)), ("OMPL", r.ompl.as_ref())] {
            let Some(o) = stats else { continue };
            let speedup = |x: Option<f64>| match (library, x) {
                ("trailmark", Some(x)) => format!("**{x:.2}x**"),
                _ => String::new(),
            };
            s.push_str(&format!(
                "| {} | {library} | {} / {} | {:.1} | {} | {}/{} | {:.1} | {:.3} | {} | {} | {} |\n",
                r.world,
                o.nodes,
                o.edges,
                o.build_ms,
                o.build_checks,
                o.solved,
                r.solvable,
                o.median_query_us,
                o.median_cost_ratio,
                o.invalid,
                speedup(r.build_speedup()),
                speedup(r.query_speedup()),
            ));
        }
    }
    s.push_str("\nSpeedups are OMPL's time over trailmark's.\n\n");
    s
}
