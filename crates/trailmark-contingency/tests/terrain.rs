//! Bad terrains give typed errors naming what is wrong; nothing panics.

use proptest::prelude::*;
use trailmark_contingency::terrain::MAX_CHOKE_POINTS;
use trailmark_contingency::{ChokePoint, Terrain, TerrainError, TerrainSpec};
use trailmark_core::{Cell, Connectivity, Grid};

/// A river with one bridge: the bridge is column 2 of row 1.
fn grid() -> Grid {
    Grid::from_rows(&["..@..", ".....", "..@..", "..@.."]).unwrap()
}

fn choke(name: &str, cells: &[(u32, u32)], probability: f64) -> ChokePoint {
    ChokePoint {
        name: name.into(),
        cells: cells.iter().map(|&(x, y)| Cell::new(x, y)).collect(),
        probability,
    }
}

fn build(chokes: Vec<ChokePoint>) -> Result<Terrain, TerrainError> {
    Terrain::new(grid(), Connectivity::Eight, Cell::new(0, 0), Cell::new(4, 3), chokes)
}

#[test]
fn probabilities_outside_zero_one_are_refused() {
    for p in [-0.1, 1.5, f64::NAN, f64::INFINITY] {
        let err = build(vec![choke("bridge", &[(2, 1)], p)]).unwrap_err();
        assert!(matches!(err, TerrainError::Probability { ref name, .. } if name == "bridge"), "{p}: {err}");
    }
    assert!(build(vec![choke("bridge", &[(2, 1)], 0.0)]).is_ok());
    assert!(build(vec![choke("bridge", &[(2, 1)], 1.0)]).is_ok());
}

#[test]
fn choke_points_in_impassable_cells_are_refused() {
    let err = build(vec![choke("bridge", &[(2, 0)], 0.5)]).unwrap_err();
    assert_eq!(err, TerrainError::ChokeCellImpassable { name: "bridge".into(), cell: Cell::new(2, 0) });
    let err = build(vec![choke("bridge", &[(9, 1)], 0.5)]).unwrap_err();
    assert!(matches!(err, TerrainError::ChokeCellOutside { .. }));
    assert!(matches!(
        build(vec![choke("bridge", &[], 0.5)]).unwrap_err(),
        TerrainError::EmptyChokePoint { .. }
    ));
}

#[test]
fn unreachable_goals_are_refused() {
    let walled = Grid::from_rows(&["..@..", "..@..", "..@.."]).unwrap();
    let err =
        Terrain::new(walled, Connectivity::Eight, Cell::new(0, 0), Cell::new(4, 2), vec![]).unwrap_err();
    assert_eq!(err, TerrainError::Unreachable { start: Cell::new(0, 0), goal: Cell::new(4, 2) });
    // Reachable only through the bridge: accepted, the bridge may be closed.
    assert!(build(vec![choke("bridge", &[(2, 1)], 0.9)]).is_ok());
}

#[test]
fn overlapping_touching_and_duplicate_choke_points_are_refused() {
    let err = build(vec![choke("a", &[(2, 1)], 0.5), choke("b", &[(2, 1)], 0.5)]).unwrap_err();
    assert!(matches!(err, TerrainError::ChokePointsOverlap { .. }));
    let err = build(vec![choke("a", &[(2, 1)], 0.5), choke("b", &[(3, 1)], 0.5)]).unwrap_err();
    assert!(matches!(err, TerrainError::ChokePointsTouch { .. }));
    let err = build(vec![choke("a", &[(2, 1)], 0.5), choke("a", &[(4, 0)], 0.5)]).unwrap_err();
    assert!(matches!(err, TerrainError::DuplicateName { .. }));
    let many = (0..=MAX_CHOKE_POINTS).map(|i| choke(&i.to_string(), &[(0, 3)], 0.5)).collect();
    assert!(matches!(build(many).unwrap_err(), TerrainError::TooManyChokePoints { .. }));
}

#[test]
fn endpoints_must_be_open_cells_outside_choke_points() {
    let at = |start: Cell| {
        Terrain::new(grid(), Connectivity::Eight, start, Cell::new(4, 3), vec![choke("b", &[(2, 1)], 0.5)])
    };
    for start in [Cell::new(2, 0), Cell::new(7, 7), Cell::new(2, 1)] {
        assert!(matches!(at(start).unwrap_err(), TerrainError::Endpoint { which: "start", .. }), "{start}");
    }
}

#[test]
fn terrain_json_reads_and_reports_bad_input() {
    let text = r#"{"rows": ["..~..", "..=..", "..~.."], "legend": {".": 1, "=": 1, "~": null},
                   "start": [0, 1], "goal": [4, 1],
                   "choke_points": [{"name": "bridge", "cells": [[2, 1]], "probability": 0.3}]}"#;
    let spec: TerrainSpec = serde_json::from_str(text).unwrap();
    let terrain = spec.build(std::path::Path::new(".")).unwrap();
    assert_eq!(terrain.choke_points().len(), 1);
    let bad = text.replace("0.3", "1.3");
    let spec: TerrainSpec = serde_json::from_str(&bad).unwrap();
    assert!(matches!(spec.build(std::path::Path::new(".")).unwrap_err(), TerrainError::Probability { .. }));
    let unknown = text.replace("\"=\": 1, ", "");
    let spec: TerrainSpec = serde_json::from_str(&unknown).unwrap();
    assert!(matches!(spec.build(std::path::Path::new(".")).unwrap_err(), TerrainError::Spec(_)));
    assert!(serde_json::from_str::<TerrainSpec>(&text.replace("rows", "rowz")).is_err());
}

proptest! {
    /// Arbitrary choke points on an arbitrary grid: a terrain or a typed error, never a panic.
    #[test]
    fn arbitrary_input_never_panics(
        rows in proptest::collection::vec("[.@]{1,6}", 1..6),
        cells in proptest::collection::vec((0u32..8, 0u32..8), 0..6),
        probability in -1.0f64..2.0,
        start in (0u32..8, 0u32..8),
        goal in (0u32..8, 0u32..8),
    ) {
        let width = rows[0].len();
        let rows: Vec<String> = rows.iter().map(|r| format!("{r:.<width$}").chars().take(width).collect()).collect();
        let grid = Grid::from_rows(&rows).unwrap();
        let chokes = vec![ChokePoint {
            name: "c".into(),
            cells: cells.iter().map(|&(x, y)| Cell::new(x, y)).collect(),
            probability,
        }];
        let made = Terrain::new(grid, Connectivity::Eight, Cell::new(start.0, start.1), Cell::new(goal.0, goal.1), chokes);
        if let Ok(terrain) = made {
            let planned = trailmark_contingency::plan(&terrain, &Default::default()).unwrap();
            prop_assert!(planned.expected_cost.is_finite());
        }
    }
}

#[test]
fn generated_terrains_write_and_read_back() {
    let terrain = trailmark_contingency::generate::river_terrain(3, &Default::default()).unwrap();
    let text = serde_json::to_string(&terrain.to_spec().unwrap()).unwrap();
    let spec: TerrainSpec = serde_json::from_str(&text).unwrap();
    let back = spec.build(std::path::Path::new(".")).unwrap();
    assert_eq!(back.grid(), terrain.grid());
    assert_eq!(back.choke_points(), terrain.choke_points());
    assert_eq!((back.start(), back.goal()), (terrain.start(), terrain.goal()));
}
