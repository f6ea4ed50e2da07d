//! The terrain document: a terrain as written in JSON, built into a [`Terrain`].

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, Connectivity};
use trailmark_core::movingai;

use crate::detect::{DetectOptions, detect};
use crate::terrain::{ChokePoint, Terrain, TerrainError, grid_from_rows};

/// A terrain as written in JSON: rows of terrain characters with a legend, or a MovingAI map;
/// a start and a goal; choke points given, or found by [`crate::detect`].
///
/// ```json
/// {
///   "rows": ["..~~..", "..==..", "..~~.."],
///   "legend": {".": 1, "=": 1, "~": null},
///   "start": [0, 1], "goal": [5, 1],
///   "choke_points": [{"name": "bridge", "cells": [[2, 1], [3, 1]], "probability": 0.3}]
/// }
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TerrainSpec {
    /// The terrain, one string per row, one character per cell (with `legend`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rows: Option<Vec<String>>,
    /// Terrain character -> cost per unit length, `null` for impassable. Without a legend the
    /// MovingAI characters apply: `.`, `G`, `S` cost 1; `@`, `O`, `T`, `W` are impassable.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub legend: Option<BTreeMap<char, Option<Cost>>>,
    /// A MovingAI `.map` file to use instead of `rows`; relative to the JSON file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub movingai: Option<String>,
    /// 4 or 8 (the default).
    #[serde(default = "eight")]
    pub connectivity: u8,
    /// The start cell `[x, y]`.
    pub start: Cell,
    /// The goal cell `[x, y]`.
    pub goal: Cell,
    /// The choke points.
    #[serde(default)]
    pub choke_points: Vec<ChokePoint>,
    /// Find choke points automatically (added after the given ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub detect: Option<DetectOptions>,
}

fn eight() -> u8 {
    8
}

impl TerrainSpec {
    /// Builds the terrain; `base` is the folder a `movingai` path is relative to.
    pub fn build(&self, base: &std::path::Path) -> Result<Terrain, TerrainError> {
        let grid = match (&self.rows, &self.movingai) {
            (Some(rows), None) => grid_from_rows(rows, self.legend.as_ref())?,
            (None, Some(map)) => {
                movingai::read_map(base.join(map)).map_err(|e| TerrainError::Spec(format!("{map}: {e}")))?
            }
            _ => return Err(TerrainError::Spec("give exactly one of \"rows\" and \"movingai\"".into())),
        };
        let connectivity = Connectivity::try_from(self.connectivity)
            .map_err(|_| TerrainError::Spec(format!("connectivity {} is not 4 or 8", self.connectivity)))?;
        let mut chokes = self.choke_points.clone();
        if let Some(options) = &self.detect {
            let found = detect(&grid, connectivity, options, &[self.start, self.goal])
                .map_err(|e| TerrainError::Spec(e.to_string()))?;
            chokes.extend(found);
        }
        Terrain::new(grid, connectivity, self.start, self.goal, chokes)
    }
}

/// The document of a terrain.
impl Terrain {
    /// The terrain as a description that [`TerrainSpec::build`] turns back into it: rows of
    /// characters (`@` impassable; `.`, `,`, `:`, ... for the passable costs from cheapest to
    /// dearest) with their legend. `None` with more than 60 distinct costs.
    pub fn to_spec(&self) -> Option<TerrainSpec> {
        const CHARS: &str = ".,:;+*%&=~-_^!?abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTU";
        let mut costs: Vec<Cost> = self.grid().costs().iter().copied().filter(|c| c.is_finite()).collect();
        costs.sort_by(f64::total_cmp);
        costs.dedup();
        if costs.len() > CHARS.len() {
            return None;
        }
        let char_of = |cost: Cost| {
            costs.iter().position(|&c| c == cost).and_then(|i| CHARS.chars().nth(i)).unwrap_or('@')
        };
        let rows = self
            .grid()
            .costs()
            .chunks(self.grid().width() as usize)
            .map(|row| row.iter().map(|&c| char_of(c)).collect())
            .collect();
        let mut legend: BTreeMap<char, Option<Cost>> = costs.iter().map(|&c| (char_of(c), Some(c))).collect();
        legend.insert('@', None);
        Some(TerrainSpec {
            rows: Some(rows),
            legend: Some(legend),
            movingai: None,
            connectivity: self.connectivity().into(),
            start: self.start(),
            goal: self.goal(),
            choke_points: self.choke_points().to_vec(),
            detect: None,
        })
    }
}
