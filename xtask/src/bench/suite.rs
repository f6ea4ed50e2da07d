//! The benchmark's suite: how many queries a run asks (`quick` or `full`), and the grid maps
//! the grid and anytime sections search, generated from the seed or read from a MovingAI folder,
//! each with seeded queries and their reference costs.

use std::path::{Path, PathBuf};

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::generate;
use trailmark::movingai;
use trailmark::prelude::*;

use crate::region::largest_region;

/// A benchmark suite.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Suite {
    /// Generated maps with 50 queries each; MovingAI maps with 10 queries each.
    Quick,
    /// Generated maps with 400 queries each; MovingAI maps with 100 queries each.
    Full,
}

impl Suite {
    /// The name in the report and its folder.
    pub fn name(self) -> &'static str {
        match self {
            Suite::Quick => "quick",
            Suite::Full => "full",
        }
    }

    /// Queries per generated map, queries per MovingAI map.
    pub fn queries(self) -> (usize, usize) {
        match self {
            Suite::Quick => (50, 10),
            Suite::Full => (400, 100),
        }
    }
}

/// A query between two cells with its reference cost.
#[derive(Clone, Copy)]
pub struct GridQuery {
    /// Where it starts.
    pub start: Cell,
    /// Where it ends.
    pub goal: Cell,
    /// The reference cost: the published optimum, or trailmark's Dijkstra on generated maps.
    pub optimal: f64,
}

/// A grid map of the suite and its queries.
pub struct SuiteMap {
    /// The map's name in the report.
    pub name: String,
    /// `generated` or `movingai`.
    pub source: &'static str,
    /// The map.
    pub grid: Grid,
    /// The queries the grid section times: `n` spread over the map's list.
    pub queries: Vec<GridQuery>,
    /// The map's whole list of queries, which other samples are drawn from: a MovingAI
    /// scenario file's (short to long), or the generated queries themselves.
    list: Vec<GridQuery>,
}

impl SuiteMap {
    /// `n` queries spread over the first half of the map's list: the shorter half of a MovingAI
    /// scenario file, the same queries whatever the suite's sample size.
    pub fn shorter_half(&self, n: usize) -> Vec<GridQuery> {
        let half = &self.list[..(self.list.len() / 2).max(1).min(self.list.len())];
        half.iter().step_by((half.len() / n.max(1)).max(1)).take(n).copied().collect()
    }
}

/// Seeded queries between cells of the largest reachable region, with Dijkstra's cost.
fn generated_queries(grid: &Grid, n: usize, rng: &mut ChaCha8Rng) -> Vec<GridQuery> {
    let graph = GridGraph::new(grid, Connectivity::Eight);
    let mut search = Search::new();
    let region = largest_region(grid, &graph, &mut search, rng).expect("a map with passable cells");
    (0..n)
        .map(|_| {
            let start = region[rng.random_range(0..region.len())];
            let goal = region[rng.random_range(0..region.len())];
            let optimal = search.dijkstra(&graph, start, goal).expect("valid").cost().expect("one region");
            GridQuery { start, goal, optimal }
        })
        .collect()
}

/// The generated maps of `seed` (random, maze, rooms; 512 x 512), `n` queries each.
pub fn generated_maps(seed: u64, n: usize) -> Vec<SuiteMap> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let grids = [
        ("random512-25", generate::random(512, 512, 0.25, seed)),
        ("maze512-4", generate::maze(512, 512, 4, seed)),
        ("rooms512-31", generate::rooms(512, 512, 31, seed)),
    ];
    grids
        .into_iter()
        .map(|(name, grid)| {
            let grid = grid.expect("valid generator arguments");
            let queries = generated_queries(&grid, n, &mut rng);
            let list = queries.clone();
            SuiteMap { name: format!("{name}-s{seed}"), source: "generated", grid, queries, list }
        })
        .collect()
}

/// `n` scenarios of each map of a MovingAI folder, spread over each file.
pub fn movingai_maps(dir: &Path, n: usize) -> Result<Vec<SuiteMap>, String> {
    let mut maps = Vec::new();
    let scenarios = dir.join("scenarios");
    let mut sets: Vec<PathBuf> = std::fs::read_dir(&scenarios)
        .map_err(|e| format!("cannot list {}: {e}", scenarios.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir())
        .collect();
    sets.sort();
    for set in sets {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&set)
            .map_err(|e| e.to_string())?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        files.sort();
        for scen in files {
            let file = scen.file_name().unwrap_or_default().to_string_lossy().into_owned();
            let Some(map_file) = file.strip_suffix(".scen") else { continue };
            let map = dir.join("maps").join(set.file_name().unwrap_or_default()).join(map_file);
            let grid = movingai::read_map(&map).map_err(|e| e.to_string())?;
            let list: Vec<GridQuery> = movingai::read_scenarios(&scen)
                .map_err(|e| e.to_string())?
                .iter()
                .map(|s| GridQuery { start: s.start, goal: s.goal, optimal: s.optimal_length })
                .collect();
            let step = (list.len() / n).max(1);
            let queries = list.iter().step_by(step).take(n).copied().collect();
            let name = map_file.trim_end_matches(".map").to_string();
            maps.push(SuiteMap { name, source: "movingai", grid, queries, list });
        }
    }
    Ok(maps)
}
