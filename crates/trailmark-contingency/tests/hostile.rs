//! Issue 23 for terrains: hostile options and descriptions give typed errors, never a crash, a
//! hang or unbounded memory.
//!
//! This test binary runs under an allocator that refuses any single request above
//! [`REFUSE_ABOVE`] bytes (the process then aborts: the test fails instead of exhausting the
//! machine) and measures the peak memory each thread holds.

use std::collections::BTreeMap;

use trailmark_contingency::generate::{RiverOptions, river_terrain};
use trailmark_contingency::terrain::grid_from_rows;
use trailmark_contingency::{TerrainError, TerrainSpec};
use trailmark_core::grid::{Cell as GridCell, GridError, MAX_CELL_COST};

#[path = "../../trailmark-core/tests/common/guard.rs"]
mod guard;

use guard::{peak_during, within};

#[test]
fn huge_river_terrains_are_refused_before_allocating() {
    for (width, height) in [(100_000, 100_000), (u32::MAX, u32::MAX), (1 << 16, 1 << 13)] {
        let options = RiverOptions { width, height, ..RiverOptions::default() };
        let (r, peak) = peak_during(|| river_terrain(1, &options));
        assert!(
            matches!(r, Err(TerrainError::Grid(GridError::TooLarge { .. }))),
            "{width} x {height}: {r:?}"
        );
        assert!(peak < 1 << 20, "{width} x {height}: {peak} bytes");
    }
}

#[test]
fn huge_forest_and_choke_point_counts_are_refused_quickly() {
    for options in [
        RiverOptions { forests: u32::MAX, ..RiverOptions::default() },
        RiverOptions { forests: 1_000_000, roads: 0, ..RiverOptions::default() },
        RiverOptions { width: 4000, height: 4000, rivers: 100, bridges: 100, ..RiverOptions::default() },
        RiverOptions { width: 4000, height: 4000, rivers: 2, bridges: u32::MAX, ..RiverOptions::default() },
    ] {
        let shown = format!("{options:?}");
        let r = within(20, &shown, move || river_terrain(1, &options).map(|_| ()));
        assert!(r.is_err(), "{shown}");
    }
    // The defaults and other modest options still work.
    assert!(river_terrain(1, &RiverOptions::default()).is_ok());
    assert!(river_terrain(2, &RiverOptions { forests: 12, roads: 2, ..RiverOptions::default() }).is_ok());
}

#[test]
fn river_costs_beyond_the_maximum_are_refused() {
    for cost in [1e300, f64::MAX, MAX_CELL_COST * 2.0] {
        let ford = RiverOptions { ford_cost: cost, ..RiverOptions::default() };
        assert!(river_terrain(1, &ford).is_err(), "ford {cost}");
        let forest = RiverOptions { forest_cost: cost, ..RiverOptions::default() };
        assert!(river_terrain(1, &forest).is_err(), "forest {cost}");
    }
}

#[test]
fn ragged_legend_rows_allocate_by_the_rows_given() {
    let mut rows = vec![".".repeat(1 << 14)];
    rows.extend(std::iter::repeat_n(".".to_string(), (1 << 14) - 1));
    let legend: BTreeMap<char, Option<f64>> = [('.', Some(1.0))].into_iter().collect();
    let (r, peak) = peak_during(|| grid_from_rows(&rows, Some(&legend)));
    assert!(matches!(r, Err(TerrainError::Grid(GridError::RaggedRow { row: 1, .. }))), "{r:?}");
    assert!(peak < 4 << 20, "{peak} bytes");
}

#[test]
fn legend_costs_beyond_the_maximum_are_refused() {
    let legend: BTreeMap<char, Option<f64>> = [('.', Some(1.0)), ('~', Some(1e300))].into_iter().collect();
    let r = grid_from_rows(&["..~", "..."], Some(&legend));
    assert!(matches!(r, Err(TerrainError::Grid(GridError::InvalidCost { .. }))), "{r:?}");
}

#[cfg(unix)]
#[test]
fn a_terrain_naming_dev_zero_or_a_directory_as_its_map_is_refused() {
    for map in ["/dev/zero", "/"] {
        let spec = TerrainSpec {
            rows: None,
            legend: None,
            movingai: Some(map.to_string()),
            connectivity: 8,
            start: GridCell::new(0, 0),
            goal: GridCell::new(1, 0),
            choke_points: Vec::new(),
            detect: None,
        };
        let (r, peak) =
            within(20, map, move || peak_during(|| spec.build(std::path::Path::new(".")).map(|_| ())));
        assert!(matches!(r, Err(TerrainError::Spec(_))), "{map}: {r:?}");
        assert!(peak < 1 << 20, "{map}: {peak} bytes");
    }
}

/// A Monte Carlo run of `usize::MAX` samples asked for that many slots at once (a capacity
/// overflow panic): the count has a documented maximum.
#[test]
fn monte_carlo_sample_counts_are_bounded() {
    use trailmark_contingency::simulate::{MAX_SAMPLES, SimulationError, monte_carlo};
    let terrain = river_terrain(1, &RiverOptions::default()).unwrap();
    let planned =
        trailmark_contingency::plan(&terrain, &trailmark_contingency::PlannerOptions::default()).unwrap();
    for samples in [MAX_SAMPLES + 1, usize::MAX] {
        let r = monte_carlo(&terrain, &planned.plan, samples, 1);
        assert!(matches!(r, Err(SimulationError::TooManySamples(n)) if n == samples), "{samples}");
    }
    assert!(monte_carlo(&terrain, &planned.plan, 10, 1).is_ok());
}
