//! Finding choke points in a grid: narrow passages between obstacles, and which of them are
//! articulation points of the region adjacency graph.
//!
//! A passable cell is *narrow* when the run of passable cells through it, along its row or
//! along its column, is at most [`DetectOptions::max_width`] cells long and ends at impassable
//! cells (or the edge of the map) on both sides. Connected narrow cells form a candidate; a
//! candidate is a choke point when it has at most [`DetectOptions::max_cells`] cells (longer ones
//! are corridors, not choke points) and is a passage: the cells beside it fall into at least two
//! groups that do not touch (a dead-end pocket has one, its mouth).
//!
//! With the choke points taken out, the passable cells fall into regions; the regions and the
//! choke points form the region adjacency graph. A choke point is an *articulation point* of that
//! graph when blocking it separates regions that it joins: no other way around exists.
//!
//! ```
//! use trailmark_core::{Cell, Connectivity, Grid};
//! use trailmark_contingency::detect::{DetectOptions, detect};
//!
//! let grid = Grid::from_rows(&[
//!     "....@....",
//!     "....@....",
//!     ".........",
//!     "....@....",
//!     "....@....",
//! ])?;
//! let found = detect(&grid, Connectivity::Eight, &DetectOptions::default(), &[])?;
//! assert_eq!(found.len(), 1);
//! assert_eq!(found[0].cells, [Cell::new(4, 2)]); // the gap in the wall
//! assert!(found[0].name.contains("articulation"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use serde::{Deserialize, Serialize};
use thiserror::Error;

use trailmark_core::grid::{Cell, Connectivity, Grid};
use trailmark_graph::GridGraph;

use crate::regions::label_regions;
use crate::terrain::{ChokePoint, MAX_CHOKE_POINTS};

/// What counts as a choke point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DetectOptions {
    /// The widest passage, in cells.
    pub max_width: u32,
    /// The most cells a choke point may have.
    pub max_cells: usize,
    /// The probability given to each choke point found.
    pub probability: f64,
    /// Keep only articulation points of the region adjacency graph.
    pub only_articulation: bool,
    /// Keep only choke points that lie wholly inside this rectangle (its top-left and
    /// bottom-right cells, inclusive): on a large map, the part the route will cross.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub within: Option<[Cell; 2]>,
}

impl Default for DetectOptions {
    fn default() -> Self {
        DetectOptions {
            max_width: 2,
            max_cells: 16,
            probability: 0.25,
            only_articulation: false,
            within: None,
        }
    }
}

/// Why detection failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DetectError {
    /// An option is out of range.
    #[error("detection option {name} = {value} is out of range ({expected})")]
    Option {
        /// The option.
        name: &'static str,
        /// Its value.
        value: String,
        /// What is expected.
        expected: &'static str,
    },
}

/// Finds the choke points of `grid`, leaving out any that would contain a cell of `keep_clear`
/// (the start and the goal). At most [`MAX_CHOKE_POINTS`] are returned: the articulation points
/// first, then the smallest passages. Names say `"articulation"` or `"passage"`.
pub fn detect(
    grid: &Grid,
    connectivity: Connectivity,
    options: &DetectOptions,
    keep_clear: &[Cell],
) -> Result<Vec<ChokePoint>, DetectError> {
    if options.max_width == 0 {
        return Err(DetectError::Option { name: "max_width", value: "0".into(), expected: "at least 1" });
    }
    if !(0.0..=1.0).contains(&options.probability) {
        return Err(DetectError::Option {
            name: "probability",
            value: options.probability.to_string(),
            expected: "in [0, 1]",
        });
    }
    if let Some([lo, hi]) = options.within
        && !(lo.x <= hi.x && lo.y <= hi.y)
    {
        return Err(DetectError::Option {
            name: "within",
            value: format!("[{lo}, {hi}]"),
            expected: "the top-left cell, then the bottom-right one",
        });
    }
    let graph = GridGraph::new(grid, connectivity);
    let (w, h) = (grid.width() as usize, grid.height() as usize);
    let index = |c: Cell| c.y as usize * w + c.x as usize;
    let narrow = narrow_cells(grid, options.max_width);

    // Candidates: connected narrow cells.
    let mut component = vec![u32::MAX; w * h];
    let mut candidates: Vec<Vec<Cell>> = Vec::new();
    for cell in grid.cells() {
        if !narrow[index(cell)] || component[index(cell)] != u32::MAX {
            continue;
        }
        let id = candidates.len() as u32;
        let mut cells = vec![cell];
        component[index(cell)] = id;
        let mut i = 0;
        while i < cells.len() {
            for (n, _) in graph.neighbours(cells[i]) {
                if narrow[index(n)] && component[index(n)] == u32::MAX {
                    component[index(n)] = id;
                    cells.push(n);
                }
            }
            i += 1;
        }
        candidates.push(cells);
    }
    let kept: Vec<bool> = candidates
        .iter()
        .map(|cells| {
            let inside = |c: &Cell| {
                options
                    .within
                    .is_none_or(|[lo, hi]| (lo.x..=hi.x).contains(&c.x) && (lo.y..=hi.y).contains(&c.y))
            };
            cells.len() <= options.max_cells
                && cells.iter().all(inside)
                && !cells.iter().any(|c| keep_clear.contains(c))
                && is_passage(&graph, cells, |c| narrow[index(c)])
        })
        .collect();

    // Regions with the kept candidates taken out, and the regions each candidate joins.
    let is_choke = |c: Cell| narrow[index(c)] && kept[component[index(c)] as usize];
    let (region_of, regions) = label_regions(grid, &graph, is_choke);
    let mut joins: Vec<(usize, Vec<u32>)> = Vec::new();
    for (id, cells) in candidates.iter().enumerate().filter(|&(id, _)| kept[id]) {
        let mut touched: Vec<u32> = cells
            .iter()
            .flat_map(|&c| graph.neighbours(c).map(|(n, _)| n))
            .filter(|&n| !is_choke(n))
            .map(|n| region_of[index(n)])
            .collect();
        touched.sort_unstable();
        touched.dedup();
        joins.push((id, touched));
    }

    // Articulation points: blocking the choke point leaves its regions apart.
    let mut found: Vec<(bool, usize, Vec<Cell>)> = Vec::new();
    for (i, (id, touched)) in joins.iter().enumerate() {
        let mut parent: Vec<u32> = (0..regions as u32).collect();
        fn find(parent: &mut [u32], mut x: u32) -> u32 {
            while parent[x as usize] != x {
                x = parent[x as usize];
            }
            x
        }
        for (j, (_, other)) in joins.iter().enumerate() {
            if j != i
                && let Some(&first) = other.first()
            {
                let root = find(&mut parent, first);
                for &r in other {
                    let o = find(&mut parent, r);
                    parent[o as usize] = root;
                }
            }
        }
        let roots: Vec<u32> = touched.iter().map(|&r| find(&mut parent, r)).collect();
        let articulation = roots.iter().any(|&r| r != roots[0]);
        if articulation || !options.only_articulation {
            found.push((articulation, candidates[*id].len(), candidates[*id].clone()));
        }
    }
    // Articulation points first, then small passages first; ties in map order.
    found.sort_by_key(|(articulation, size, cells)| (!articulation, *size, cells[0].y, cells[0].x));
    found.truncate(MAX_CHOKE_POINTS);
    found.sort_by_key(|(_, _, cells)| (cells[0].y, cells[0].x));
    Ok(found
        .into_iter()
        .enumerate()
        .map(|(i, (articulation, _, cells))| ChokePoint {
            name: format!("{} {}", if articulation { "articulation" } else { "passage" }, i + 1),
            cells,
            probability: options.probability,
        })
        .collect())
}

/// Whether each cell (row-major) is narrow.
fn narrow_cells(grid: &Grid, max_width: u32) -> Vec<bool> {
    let (w, h) = (grid.width(), grid.height());
    let mut narrow = vec![false; grid.len()];
    // Runs along rows, then along columns.
    for (outer, inner, cell) in [
        (h, w, (|o, i| Cell::new(i, o)) as fn(u32, u32) -> Cell),
        (w, h, (|o, i| Cell::new(o, i)) as fn(u32, u32) -> Cell),
    ] {
        for o in 0..outer {
            let mut i = 0;
            while i < inner {
                if !grid.is_passable(cell(o, i)) {
                    i += 1;
                    continue;
                }
                let begin = i;
                while i < inner && grid.is_passable(cell(o, i)) {
                    i += 1;
                }
                if i - begin <= max_width {
                    for j in begin..i {
                        let c = cell(o, j);
                        narrow[c.y as usize * w as usize + c.x as usize] = true;
                    }
                }
            }
        }
    }
    narrow
}

/// Whether the cells beside a candidate fall into at least two groups that do not touch.
fn is_passage(graph: &GridGraph, cells: &[Cell], narrow: impl Fn(Cell) -> bool) -> bool {
    let mut beside: Vec<Cell> =
        cells.iter().flat_map(|&c| graph.neighbours(c).map(|(n, _)| n)).filter(|&n| !narrow(n)).collect();
    beside.sort_unstable();
    beside.dedup();
    let Some(&first) = beside.first() else {
        return false;
    };
    // Grow the group of the first cell by 8-adjacency among the cells beside the candidate.
    let mut group = vec![first];
    let mut i = 0;
    while i < group.len() {
        let c = group[i];
        for &n in &beside {
            if c.x.abs_diff(n.x) <= 1 && c.y.abs_diff(n.y) <= 1 && !group.contains(&n) {
                group.push(n);
            }
        }
        i += 1;
    }
    group.len() < beside.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A `within` box given bottom-right first selects nothing; it is refused, not taken as an
    /// empty box.
    #[test]
    fn an_inverted_within_box_is_refused() {
        let grid = Grid::from_rows(&["....@....", ".........", "....@...."]).unwrap();
        let inverted =
            DetectOptions { within: Some([Cell::new(8, 2), Cell::new(0, 0)]), ..DetectOptions::default() };
        let error = detect(&grid, Connectivity::Eight, &inverted, &[]).unwrap_err();
        assert!(matches!(error, DetectError::Option { name: "within", .. }), "{error}");
        let upright =
            DetectOptions { within: Some([Cell::new(0, 0), Cell::new(8, 2)]), ..DetectOptions::default() };
        assert!(detect(&grid, Connectivity::Eight, &upright, &[]).is_ok());
    }
}
