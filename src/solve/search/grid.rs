//! Grid worlds: a MovingAI map or inline rows, with costs, searched cell to cell.

use std::path::Path;

use trailmark_core::grid::Cell;
use trailmark_core::svg::GridSvg;

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{GridSpec, ProblemSpec};
use crate::solve::result::{SolveResult, Waypoint};
use crate::solve::world::grid::{cell_of, corner_cutting, grid_graph, load_grid};

/// Solves a grid-world problem.
pub(in crate::solve) fn solve_grid(
    problem: &ProblemSpec,
    world: &GridSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForGrids { field: name }.into());
    }
    let grid = load_grid(world, base_dir)?;
    let start = cell_of("start", &problem.start, &grid)?;
    let goal = cell_of("goal", &problem.goal, &grid)?;
    let ends = (start, goal);
    let result = match problem.planner.grid_search(&grid, world.connectivity, corner_cutting(world), ends) {
        Some(found) => found?,
        None => {
            let graph = grid_graph(world, &grid);
            let h = graph.heuristic_between(problem.planner.grid_heuristic(world.connectivity)?);
            problem.planner.search(&graph, ends, h, Waypoint::Cell, Some(&graph))?
        }
    };
    if let Some(picture) = picture {
        let cells: Vec<Cell> = result
            .path
            .iter()
            .filter_map(|w| match w {
                Waypoint::Cell(c) => Some(*c),
                Waypoint::Point(_) => None,
            })
            .collect();
        let scale = (800.0 / f64::from(grid.width().max(grid.height()))).clamp(1.0, 24.0);
        let svg = GridSvg::new(&grid).cell_size(scale).path(&cells).start(start).goal(goal);
        *picture = svg.title(format!("{} from {start} to {goal}", problem.planner.name())).to_svg();
    }
    Ok(result)
}
