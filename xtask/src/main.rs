//! `cargo xtask`: the trailmark harness and driver.
//!
//! - `cargo xtask bench` runs the planners on a built-in generated suite (and the MovingAI maps
//!   in `../shared/movingai` when present) beside peer libraries, and writes a report.
//! - `cargo xtask verify movingai DIR` checks every scenario of a MovingAI benchmark folder
//!   against its published optimal length; `cargo xtask verify anyangle DIR` checks the GPPC
//!   any-angle track on visibility graphs; `cargo xtask verify mbm DIR --urdf F --srdf F` plans
//!   every MotionBenchMaker problem of a folder and checks each path again.
//! - `cargo xtask solve PROBLEM.json` solves one problem document and prints the result JSON;
//!   `cargo xtask render PROBLEM.json OUT.svg` also draws the world, its graph and the path.
//! - `cargo xtask navigate` runs a robot through partly known terrain with each incremental
//!   planner and prints a JSON summary.
//! - `cargo xtask contingency TERRAIN.json` plans with contingencies over choke points that may
//!   be blocked and prints `{"expected_cost": ..., "plan": ...}`.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use trailmark::graph::visibility::Edges;

use crate::verify::VerifyAlgo;

#[macro_use]
mod output;

mod bench;
mod contingency;
mod mbm;
mod memory;
mod navigate;
mod reference;
mod region;
mod solve;
mod terrain_file;
mod verify;
mod workspace;

#[derive(Parser)]
#[command(
    name = "cargo xtask",
    about = "The trailmark harness: bench, verify, solve, render, navigate, contingency"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Runs the planners on the benchmark suite and writes a report to target/bench/.
    Bench(bench::Args),
    /// Checks planners against published benchmark optima.
    Verify {
        #[command(subcommand)]
        set: VerifySet,
    },
    /// Solves a problem document (a file, or - for standard input) and prints the result JSON.
    Solve {
        /// The problem JSON file.
        problem: PathBuf,
    },
    /// Solves a problem document, prints the result JSON and writes an SVG of the world, the
    /// graph searched and the path.
    Render {
        /// The problem JSON file (or - for standard input).
        problem: PathBuf,
        /// The SVG file to write.
        out: PathBuf,
    },
    /// Reads and solves a problem document `--repeat` times in this process and prints the
    /// median and least wall time of one (JSON): the Rust side of a comparison with another
    /// language's call (python/bench/bench.py). `--prepared`: a grid world's grid loaded and its
    /// graph built once, each time only the search, as a program that keeps the grid does; a
    /// robot world read once (`RobotWorld`), each time only the plan.
    Time {
        /// The problem JSON file.
        problem: PathBuf,
        /// How many solves to time.
        #[arg(long, default_value_t = 21)]
        repeat: usize,
        /// Time only the search on a grid world, or the plan in a robot world, prepared once.
        #[arg(long)]
        prepared: bool,
    },
    /// Runs a robot through partly known terrain with each planner; prints a JSON summary.
    Navigate(navigate::Args),
    /// Plans with contingencies over choke points that may be blocked; prints
    /// `{"expected_cost": ..., "plan": ...}`.
    Contingency(contingency::Args),
}

#[derive(Subcommand)]
enum VerifySet {
    /// Every DIR/scenarios/SET/NAME.map.scen, solved on its map DIR/maps/SET/NAME.map.
    Movingai {
        /// The MovingAI folder (with maps/ and scenarios/).
        dir: PathBuf,
        /// The algorithms to check (comma-separated or repeated).
        #[arg(long, value_enum, value_delimiter = ',', default_value = "astar")]
        algo: Vec<VerifyAlgo>,
        /// Check every K-th scenario of each file only.
        #[arg(allow_negative_numbers = true, long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
        every: u64,
    },
    /// Every DIR/NAME.map.scen of the GPPC any-angle track, on the visibility graph of DIR/NAME.map.
    Anyangle {
        /// The folder with the maps and their scenario files.
        dir: PathBuf,
        /// Check every K-th scenario of each file only.
        #[arg(allow_negative_numbers = true, long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
        every: u64,
        /// The relative tolerance on a published optimum.
        #[arg(long, default_value_t = 1e-6, allow_negative_numbers = true)]
        rel: f64,
        /// Build the full visibility graph instead of its tangent edges only.
        #[arg(long)]
        all_edges: bool,
    },
    /// Every MotionBenchMaker problem of a folder (requestNNNN.yaml beside sceneNNNN.yaml, at
    /// any depth), planned and its path checked again by the f64 sphere checker.
    Mbm(mbm::Args),
}

/// Every allocation is counted, for the benchmark's peak-memory figures.
#[global_allocator]
static ALLOCATOR: memory::Counting = memory::Counting;

fn main() -> ExitCode {
    // Arguments that cannot be used are reported as every other input is, as
    // `{"status": "error"}` on standard output; help and the version print as clap writes them.
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => return output::error_report(e.render().to_string().trim_end()),
    };
    match cli.command {
        Command::Bench(args) => bench::run(&args),
        Command::Verify { set: VerifySet::Movingai { dir, algo, every } } => {
            verify::movingai(&dir, &algo, every)
        }
        Command::Verify { set: VerifySet::Anyangle { dir, every, rel, all_edges } } => {
            let edges = if all_edges { Edges::All } else { Edges::Tangent };
            verify::anyangle(&dir, every, rel, edges)
        }
        Command::Verify { set: VerifySet::Mbm(args) } => mbm::run(&args),
        Command::Solve { problem } => solve::run(&problem),
        Command::Render { problem, out } => solve::render(&problem, &out),
        Command::Time { problem, repeat, prepared } => solve::time(&problem, repeat, prepared),
        Command::Navigate(args) => navigate::run(&args),
        Command::Contingency(args) => contingency::run(&args),
    }
}
