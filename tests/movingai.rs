//! The MovingAI benchmark files in `../shared/movingai`: every map and scenario file parses, every
//! scenario fits its map, and a sample of scenarios is solved to its published optimal length.
//! The full check of every scenario is `cargo xtask verify movingai ../shared/movingai`.
//!
//! Without the folder, each test says so and passes without checking anything.

use std::path::{Path, PathBuf};

use trailmark::movingai;
use trailmark::prelude::*;

#[path = "support/shared_data.rs"]
mod shared_data;

fn data() -> Option<PathBuf> {
    shared_data::shared_data("movingai", "MovingAI benchmark data")
}

/// `(map, scenario file)` for every scenario file under `dir/scenarios/<set>/`.
fn pairs(dir: &Path) -> Vec<(PathBuf, PathBuf)> {
    let mut out = Vec::new();
    for set in std::fs::read_dir(dir.join("scenarios")).unwrap() {
        let set = set.unwrap().path();
        for scen in std::fs::read_dir(&set).unwrap() {
            let scen = scen.unwrap().path();
            let name = scen.file_name().unwrap().to_string_lossy().into_owned();
            if let Some(map) = name.strip_suffix(".scen") {
                out.push((dir.join("maps").join(set.file_name().unwrap()).join(map), scen));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn every_file_parses_and_every_scenario_fits_its_map() {
    let Some(dir) = data() else { return };
    let pairs = pairs(&dir);
    assert!(pairs.len() >= 20, "expected the 20 benchmark maps, found {}", pairs.len());
    let mut scenarios = 0;
    for (map, scen) in &pairs {
        let grid = movingai::read_map(map).unwrap();
        for s in movingai::read_scenarios(scen).unwrap() {
            assert_eq!((s.map_width, s.map_height), (grid.width(), grid.height()), "{}", scen.display());
            assert!(grid.is_passable(s.start) && grid.is_passable(s.goal), "{}: {s:?}", scen.display());
            scenarios += 1;
        }
    }
    assert!(scenarios > 50_000, "{scenarios} scenarios");
    // The any-angle map is a MovingAI map too.
    let cape = movingai::read_map(dir.join("anyangle/AcrosstheCape.map")).unwrap();
    assert!(cape.passable_count() > 0);
}

#[test]
fn a_sample_of_scenarios_meets_the_published_optima() {
    let Some(dir) = data() else { return };
    let mut checked = 0;
    for (map, scen) in pairs(&dir) {
        let grid = movingai::read_map(&map).unwrap();
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let mut search = Search::new();
        let all = movingai::read_scenarios(&scen).unwrap();
        // Eight queries per map, spread over the difficulty buckets.
        for s in all.iter().step_by(all.len() / 8) {
            let h = graph.heuristic(GridHeuristic::Octile, s.goal);
            let cost = search.astar(&graph, s.start, s.goal, h).unwrap().cost().unwrap();
            let tolerance = 1e-4 * s.optimal_length.max(1.0) + 0.006;
            assert!(
                (cost - s.optimal_length).abs() <= tolerance,
                "{}: {} -> {}: {cost} vs published {}",
                scen.display(),
                s.start,
                s.goal,
                s.optimal_length
            );
            checked += 1;
        }
    }
    assert!(checked >= 160);
}
