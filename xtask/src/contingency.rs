//! `cargo xtask contingency`: plans with contingencies for a terrain file (or a generated river
//! terrain), prints `{"expected_cost": ..., "plan": ...}` and optionally compares the plan with
//! D* Lite replanning by Monte Carlo and over every world, and draws it.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::Args as ClapArgs;
use serde_json::{Value, json};
use trailmark::contingency::generate::{RiverOptions, river_terrain};
use trailmark::contingency::simulate::{monte_carlo, naive_expected_cost};
use trailmark::contingency::svg::plan_svg;
use trailmark::contingency::{PlannerOptions, Terrain, plan};

use crate::terrain_file::read_spec;

/// The arguments of `cargo xtask contingency`.
#[derive(Debug, ClapArgs)]
pub struct Args {
    /// The terrain JSON file (see `TerrainSpec`); without it, `--generate` is required.
    terrain: Option<PathBuf>,
    /// Generate a river terrain from this seed instead of reading one.
    #[arg(allow_negative_numbers = true, long, conflicts_with = "terrain")]
    generate: Option<u64>,
    /// Write the terrain (read or generated) as JSON to this file.
    #[arg(long)]
    write_terrain: Option<PathBuf>,
    /// How many blocked choke points one branch of the plan prepares for (default 3; "all" for
    /// every combination).
    #[arg(allow_negative_numbers = true, long, default_value = "3", value_parser = parse_depth)]
    max_blockages: usize,
    /// Draw the plan to this SVG file.
    #[arg(long)]
    svg: Option<PathBuf>,
    /// Pixels per cell in the SVG (more than 0, at most 256).
    #[arg(long, default_value_t = 8.0, value_parser = parse_cell_size, allow_negative_numbers = true)]
    cell: f64,
    /// Monte Carlo samples comparing the plan with D* Lite replanning (0: none).
    #[arg(allow_negative_numbers = true, long, default_value_t = 0)]
    samples: usize,
    /// Seed of the Monte Carlo samples.
    #[arg(allow_negative_numbers = true, long, default_value_t = 1)]
    seed: u64,
    /// Also compute D* Lite replanning's exact expected cost (one drive per distinct sequence of
    /// what the vehicle sees, at most 2^n), up to this many choke points (at most 32).
    #[arg(allow_negative_numbers = true, long, default_value_t = 24, value_parser = parse_exact_up_to)]
    exact_up_to: usize,
    /// Leave the plan out of the output (print the figures only).
    #[arg(long)]
    summary: bool,
    /// Fail unless the Monte Carlo mean of the plan is within 2% of its expected cost and the
    /// plan's expected cost is at most D* Lite replanning's (exact when computed, otherwise the
    /// paired Monte Carlo saving at least -2 standard errors).
    #[arg(long)]
    check: bool,
}

fn parse_cell_size(s: &str) -> Result<f64, String> {
    let size: f64 = s.parse().map_err(|e| format!("{s}: {e}"))?;
    if size > 0.0 && size <= 256.0 {
        Ok(size)
    } else {
        Err(format!("{s}: pixels per cell must be in (0, 256]"))
    }
}

fn parse_exact_up_to(s: &str) -> Result<usize, String> {
    let n: usize = s.parse().map_err(|e| format!("{s}: {e}"))?;
    // 2^32 drives is days of work: a larger count would never finish.
    if n <= 32 { Ok(n) } else { Err(format!("{s}: at most 32 choke points (up to 2^32 drives)")) }
}

fn parse_depth(s: &str) -> Result<usize, String> {
    if s == "all" { Ok(usize::MAX) } else { s.parse().map_err(|e| format!("{s}: {e}")) }
}

/// Runs the command.
pub fn run(args: &Args) -> ExitCode {
    match run_inner(args) {
        Ok(out) => {
            outln!("{}", serde_json::to_string_pretty(&out).unwrap_or_default());
            ExitCode::SUCCESS
        }
        Err(e) => crate::output::error_report(e),
    }
}

fn load(args: &Args) -> Result<Terrain, String> {
    match (&args.terrain, args.generate) {
        (Some(path), None) => {
            read_spec(path)?.build(path.parent().unwrap_or(Path::new("."))).map_err(|e| e.to_string())
        }
        (None, Some(seed)) => river_terrain(seed, &RiverOptions::default()).map_err(|e| e.to_string()),
        _ => Err("give a terrain file or --generate SEED".into()),
    }
}

fn run_inner(args: &Args) -> Result<Value, String> {
    let terrain = load(args)?;
    if let Some(path) = &args.write_terrain {
        let spec = terrain.to_spec().ok_or("too many distinct costs to write the terrain")?;
        let text = serde_json::to_string_pretty(&spec).map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let options = PlannerOptions { max_blockages: args.max_blockages, ..PlannerOptions::default() };
    let planned = plan(&terrain, &options).map_err(|e| e.to_string())?;
    let mut out = json!({
        "expected_cost": planned.expected_cost,
        "stuck_probability": planned.stuck_probability,
        "choke_points": terrain.choke_points().iter().map(|c| json!({
            "name": c.name, "probability": c.probability, "cells": c.cells.len(),
        })).collect::<Vec<_>>(),
        "stats": planned.stats,
        "plan_size": planned.plan.size(),
    });
    if args.samples > 0 {
        let started = Instant::now();
        let mc = monte_carlo(&terrain, &planned.plan, args.samples, args.seed).map_err(|e| e.to_string())?;
        out["monte_carlo"] = json!({
            "samples": mc.samples,
            "plan_mean": mc.plan.mean,
            "plan_std_error": mc.plan.std_error,
            "plan_mean_over_expected": mc.plan.mean / planned.expected_cost,
            "naive_mean": mc.naive.mean,
            "naive_std_error": mc.naive.std_error,
            "saving_mean": mc.saving.mean,
            "saving_std_error": mc.saving.std_error,
            "worlds_plan_cheaper": mc.plan_cheaper,
            "worlds_plan_dearer": mc.plan_dearer,
            "time_s": started.elapsed().as_secs_f64(),
        });
    }
    if terrain.choke_points().len() <= args.exact_up_to {
        let started = Instant::now();
        let naive = naive_expected_cost(&terrain).map_err(|e| e.to_string())?;
        let (stuck, drives) = (naive.stuck_probability, naive.drives);
        let naive = naive.expected_cost;
        out["naive_replanning"] = json!({
            "expected_cost": naive,
            "stuck_probability": stuck,
            "drives": drives,
            "time_s": started.elapsed().as_secs_f64(),
            "plan_saves": naive - planned.expected_cost,
            "plan_saves_percent": 100.0 * (naive - planned.expected_cost) / naive,
        });
    }
    if let Some(path) = &args.svg {
        let title = format!(
            "expected cost {:.2}: preferred route solid, contingencies dashed",
            planned.expected_cost
        );
        std::fs::write(path, plan_svg(&terrain, &planned.plan, args.cell, &title))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    if args.check {
        check(&out)?;
    }
    if !args.summary {
        out["plan"] = planned.plan.to_json(&terrain);
    }
    Ok(out)
}

/// The acceptance checks of `--check` on the figures of one run.
fn check(out: &Value) -> Result<(), String> {
    let expected = out["expected_cost"].as_f64().unwrap_or(f64::NAN);
    let mc = &out["monte_carlo"];
    let ratio = mc["plan_mean_over_expected"].as_f64().ok_or("--check needs --samples")?;
    if (ratio - 1.0).abs() > 0.02 {
        return Err(format!("Monte Carlo mean / expected cost = {ratio}, more than 2% off"));
    }
    if let Some(naive) = out["naive_replanning"]["expected_cost"].as_f64() {
        if expected > naive + 1e-9 * naive.abs().max(1.0) {
            return Err(format!("the plan's expected cost {expected} exceeds D* Lite replanning's {naive}"));
        }
    } else {
        let (saving, error) =
            (mc["saving_mean"].as_f64().unwrap_or(0.0), mc["saving_std_error"].as_f64().unwrap_or(0.0));
        if saving < -2.0 * error {
            return Err(format!(
                "the plan costs more than D* Lite replanning by {} (standard error {error})",
                -saving
            ));
        }
    }
    Ok(())
}
