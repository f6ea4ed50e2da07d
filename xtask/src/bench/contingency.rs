//! The contingency section: contingency plans over choke points against following the shortest
//! path and replanning with D* Lite.
//!
//! The terrains: seeded river terrains (bridges, fords, forest roads; 64 x 48), and, when the
//! MovingAI folder is there, the rooms map of `docs/contingency-rooms.json` with its 16 detected
//! doors. For each: the planning time (median over the rounds), its states, expansions and peak
//! memory; the plan's expected cost beside D* Lite replanning's exact expected cost (both
//! computed exactly, so their difference is the saving with no sampling error); and the Monte
//! Carlo mean of driving the plan over seeded worlds, as a check of the expected cost. A plan
//! dearer than replanning breaks a bound the planner guarantees and counts as an error.
//!
//! The section comes in two halves: the timed planning ([`plan_terrains`]), and the untimed
//! replanning costs and Monte Carlo ([`check`]), which may run beside other sections.

use std::path::Path;
use std::time::Instant;

use serde::Serialize;
use trailmark::contingency::generate::{RiverOptions, river_terrain};
use trailmark::contingency::simulate::{monte_carlo, naive_expected_cost};
use trailmark::contingency::{ContingencyPlan, PlannerOptions, Terrain, plan};

use crate::bench::progress::SectionProgress;
use crate::bench::stats::median;
use crate::bench::suite::Suite;
use crate::terrain_file::read_spec;

/// Monte Carlo worlds per terrain.
const SAMPLES: usize = 1000;

/// One terrain and what the planner and replanning made of it.
#[derive(Debug, Clone, Serialize)]
pub struct ContingencyRow {
    /// The terrain.
    pub terrain: String,
    /// Its width and height in cells.
    pub size: (u32, u32),
    /// Its choke points.
    pub choke_points: usize,
    /// Planning time, milliseconds (median over the rounds).
    pub plan_ms: f64,
    /// AND-OR states the planner created.
    pub states: usize,
    /// States it expanded.
    pub expansions: usize,
    /// Peak heap held while planning, bytes.
    pub peak_bytes: usize,
    /// Points of the plan tree.
    pub plan_points: usize,
    /// The plan's expected cost.
    pub expected_cost: f64,
    /// The probability that the plan ends stuck.
    pub stuck_probability: f64,
    /// D* Lite replanning's exact expected cost.
    pub replanning_cost: f64,
    /// What the plan saves, in percent of replanning's expected cost.
    pub saving_percent: f64,
    /// D* Lite drives it took to compute replanning's expected cost.
    pub replanning_drives: usize,
    /// The Monte Carlo mean of driving the plan, over its expected cost.
    pub monte_carlo_ratio: f64,
    /// The standard error of that ratio.
    pub monte_carlo_std_error: f64,
    /// Whether the plan is dearer than replanning (a broken guarantee).
    pub error: bool,
}

/// The terrains of the suite, by name.
fn terrains(suite: Suite, movingai: Option<&Path>) -> Result<Vec<(String, Terrain)>, String> {
    let seeds = match suite {
        Suite::Quick => 1..=8,
        Suite::Full => 1..=32,
    };
    let mut out = Vec::new();
    for seed in seeds {
        let terrain =
            river_terrain(seed, &RiverOptions::default()).map_err(|e| format!("river {seed}: {e}"))?;
        out.push((format!("river-{seed}"), terrain));
    }
    match movingai {
        Some(dir) => {
            let file = crate::workspace::root().join("docs/contingency-rooms.json");
            let mut spec = read_spec(&file)?;
            let map = dir.join("maps/rooms/64room_000.map");
            spec.movingai = Some(map.to_string_lossy().into_owned());
            let terrain = spec.build(Path::new(".")).map_err(|e| format!("{}: {e}", file.display()))?;
            out.push(("rooms/64room_000".into(), terrain));
        }
        None => errln!("contingency: the MovingAI rooms map skipped (no MovingAI folder)"),
    }
    Ok(out)
}

/// A terrain of the section and what the timed planner made of it.
pub struct PlannedTerrain {
    name: String,
    terrain: Terrain,
    planned: ContingencyPlan,
    /// Planning time, milliseconds (median over the rounds).
    plan_ms: f64,
    /// Peak heap held while planning, bytes.
    peak_bytes: usize,
}

/// The timed half of the section: the suite's terrains, each planned `runs` times.
pub fn plan_terrains(
    suite: Suite,
    runs: u32,
    movingai: Option<&Path>,
) -> Result<Vec<PlannedTerrain>, String> {
    let terrains = terrains(suite, movingai)?;
    let mut progress = SectionProgress::new("contingency", terrains.len());
    let mut out = Vec::new();
    for (name, terrain) in terrains {
        progress.step(name.clone());
        let mut times = Vec::new();
        let mut planned = None;
        let mut peak_bytes = 0;
        for _ in 0..runs {
            let memory = crate::memory::mark();
            let started = Instant::now();
            let p = plan(&terrain, &PlannerOptions::default()).map_err(|e| format!("{name}: {e}"))?;
            times.push(started.elapsed().as_secs_f64() * 1e3);
            peak_bytes = crate::memory::peak_since(memory);
            planned = Some(p);
        }
        let planned = planned.ok_or("no rounds")?;
        times.sort_by(f64::total_cmp);
        out.push(PlannedTerrain { name, terrain, planned, plan_ms: median(&times), peak_bytes });
    }
    Ok(out)
}

/// The untimed half: D* Lite replanning's exact expected cost on each terrain, and the Monte
/// Carlo check of each plan (`seed`). Nothing in it is timed, so it may run beside the timed
/// sections; it is the section's longest part (on the rooms map, over a thousand D* Lite drives
/// for each).
pub fn check(planned: &[PlannedTerrain], seed: u64) -> Result<Vec<ContingencyRow>, String> {
    let mut rows = Vec::new();
    for PlannedTerrain { name, terrain, planned, plan_ms, peak_bytes } in planned {
        let naive = naive_expected_cost(terrain).map_err(|e| format!("{name}: {e}"))?;
        let mc = monte_carlo(terrain, &planned.plan, SAMPLES, seed).map_err(|e| format!("{name}: {e}"))?;
        let expected = planned.expected_cost;
        rows.push(ContingencyRow {
            terrain: name.clone(),
            size: (terrain.grid().width(), terrain.grid().height()),
            choke_points: terrain.choke_points().len(),
            plan_ms: *plan_ms,
            states: planned.stats.states,
            expansions: planned.stats.expansions,
            peak_bytes: *peak_bytes,
            plan_points: planned.plan.size(),
            expected_cost: expected,
            stuck_probability: planned.stuck_probability,
            replanning_cost: naive.expected_cost,
            saving_percent: 100.0 * (naive.expected_cost - expected) / naive.expected_cost,
            replanning_drives: naive.drives,
            monte_carlo_ratio: mc.plan.mean / expected,
            monte_carlo_std_error: mc.plan.std_error / expected,
            error: expected > naive.expected_cost + 1e-9 * naive.expected_cost.abs().max(1.0),
        });
    }
    Ok(rows)
}

/// The section of the report.
pub fn markdown(rows: &[ContingencyRow]) -> String {
    let mut out = String::from("## Contingency plans against D* Lite replanning\n\n");
    out.push_str(&format!(
        "Each choke point blocked independently with its probability; the vehicle sees one from any cell \
         beside it. The plan prepares for up to 3 blockages per branch (the default). Expected costs are \
         exact for both strategies: the plan's by its tree, replanning's by driving D* Lite once per distinct \
         sequence of what it sees. Monte Carlo: the mean of driving the plan in {SAMPLES} seeded worlds, over \
         the expected cost (± one standard error). Planning time: median over rounds.\n\n"
    ));
    out.push_str(
        "| terrain | size | choke points | plan ms | states | expansions | peak MiB | plan points | expected cost | replanning | saving | stuck | Monte Carlo / expected |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {}x{} | {} | {:.1} | {} | {} | {:.1} | {} | {:.3} | {:.3} | {:.2}%{} | {:.3} | {:.4} ± {:.4} |\n",
            r.terrain,
            r.size.0,
            r.size.1,
            r.choke_points,
            r.plan_ms,
            r.states,
            r.expansions,
            r.peak_bytes as f64 / (1024.0 * 1024.0),
            r.plan_points,
            r.expected_cost,
            r.replanning_cost,
            r.saving_percent,
            if r.error { " **error**" } else { "" },
            r.stuck_probability,
            r.monte_carlo_ratio,
            r.monte_carlo_std_error
        ));
    }
    if !rows.is_empty() {
        let savings: Vec<f64> = rows.iter().map(|r| r.saving_percent).collect();
        let mean = savings.iter().sum::<f64>() / savings.len() as f64;
        let lowest = savings.iter().copied().fold(f64::INFINITY, f64::min);
        let highest = savings.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        out.push_str(&format!(
            "\nThe plan saves {mean:.2}% on average over {} terrains (lowest {lowest:.2}%, highest {highest:.2}%); \
             {} terrain(s) where it is dearer than replanning.\n",
            rows.len(),
            rows.iter().filter(|r| r.error).count()
        ));
    }
    out
}
