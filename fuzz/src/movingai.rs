//! The MovingAI parsers: no panic, and what they return is consistent with the text read.

use trailmark_core::movingai::{parse_map, parse_scenarios, write_map};

/// Parses `text` as a `.map` file; on success, checks the grid against the text.
pub fn check_map(text: &str) {
    let Ok(grid) = parse_map(text) else { return };
    // Each cell is a character of the text, which takes one byte at least.
    assert!(grid.len() <= text.len(), "{} cells from {} bytes", grid.len(), text.len());
    assert_eq!(
        grid.len(),
        grid.width() as usize * grid.height() as usize,
        "cell count is not width x height"
    );
    assert!(grid.passable_count() <= grid.len());
    assert!(
        grid.costs().iter().all(|&c| c == 1.0 || c == f64::INFINITY),
        "a map cell costs neither 1 nor inf"
    );
    // The map format keeps passable/blocked only, which is all a parsed map has.
    let again = parse_map(&write_map(&grid)).expect("a written map parses");
    assert_eq!(again, grid, "write_map then parse_map changed the grid");
}

/// Parses `text` as a `.map.scen` file; on success, checks every query.
pub fn check_scenarios(text: &str) {
    let Ok(scenarios) = parse_scenarios(text) else { return };
    let lines = text.split('\n').count();
    assert!(scenarios.len() <= lines, "{} scenarios from {lines} lines", scenarios.len());
    for s in &scenarios {
        assert!(s.start.x < s.map_width && s.start.y < s.map_height, "start outside the map: {s:?}");
        assert!(s.goal.x < s.map_width && s.goal.y < s.map_height, "goal outside the map: {s:?}");
        assert!(s.optimal_length.is_finite() && s.optimal_length >= 0.0, "optimal length: {s:?}");
        assert!(
            !s.map.is_empty() || text.contains('\t'),
            "an empty map name from space-separated fields: {s:?}"
        );
    }
}
