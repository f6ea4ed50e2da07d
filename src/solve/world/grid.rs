//! Grid worlds as documents give them: a MovingAI map or inline rows with costs, the grid
//! graph they are searched on, and cells named by `[x, y]`.

use std::path::Path;

use trailmark_core::grid::{Cell, Grid, GridError, is_cell_cost};
use trailmark_core::movingai;
use trailmark_graph::{CornerCutting, GridGraph};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::GridSpec;

/// The grid of a grid world, with relative map paths resolved against `base_dir`.
pub fn load_grid(world: &GridSpec, base_dir: impl AsRef<Path>) -> Result<Grid, SolveError> {
    let mut grid = match (&world.map, &world.rows) {
        (Some(map), None) => movingai::read_map(base_dir.as_ref().join(map))?,
        (None, Some(rows)) => Grid::from_rows(rows)?,
        _ => return Err(DocumentError::GridSource.into()),
    };
    if let Some(costs) = &world.costs {
        let (w, h) = (grid.width(), grid.height());
        let shape = |row, found| DocumentError::CostsShape { width: w, height: h, row, found };
        if costs.len() != h as usize {
            return Err(shape(costs.len(), costs.len()).into());
        }
        for (y, row) in (0..h).zip(costs) {
            if row.len() != w as usize {
                return Err(shape(y as usize, row.len()).into());
            }
            for (x, &c) in (0..w).zip(row) {
                let cell = Cell::new(x, y);
                if grid.is_passable(cell) {
                    grid.set_cost(cell, c)?;
                } else if !(c.is_finite() && is_cell_cost(c)) {
                    // Blocked cells stay blocked, but their cost must still be a valid number.
                    return Err(GridError::InvalidCost { cell, cost: c }.into());
                }
            }
        }
    }
    Ok(grid)
}

/// The rule for diagonal moves of a grid world.
pub(crate) fn corner_cutting(world: &GridSpec) -> CornerCutting {
    if world.corner_cutting { CornerCutting::Allowed } else { CornerCutting::Forbidden }
}

/// The grid graph of a grid world.
pub fn grid_graph(world: &GridSpec, grid: &Grid) -> GridGraph {
    GridGraph::new(grid, world.connectivity).with_corner_cutting(corner_cutting(world))
}

pub(crate) fn cell_of(which: &'static str, value: &[f64], grid: &Grid) -> Result<Cell, DocumentError> {
    let whole = |v: f64| v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v);
    let [x, y] = value else { return Err(DocumentError::NotACell { which, value: value.to_vec() }) };
    if !whole(*x) || !whole(*y) {
        return Err(DocumentError::NotACell { which, value: value.to_vec() });
    }
    #[allow(clippy::cast_possible_truncation)] // whole numbers within u32, checked above
    let cell = Cell::new(*x as u32, *y as u32);
    check_grid_end(which, cell, grid)?;
    Ok(cell)
}

/// Whether `cell` may be the `which` end (`"start"`, `"goal"`) of a search on `grid`: inside
/// it and passable, or the document error that says why not.
pub fn check_grid_end(which: &'static str, cell: Cell, grid: &Grid) -> Result<(), DocumentError> {
    if !grid.contains(cell) {
        return Err(DocumentError::Outside { which, cell, width: grid.width(), height: grid.height() });
    }
    if !grid.is_passable(cell) {
        return Err(DocumentError::Blocked { which, cell });
    }
    Ok(())
}
