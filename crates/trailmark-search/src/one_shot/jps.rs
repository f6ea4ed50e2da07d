//! Jump point search (Harabor and Grastien, "Online Graph Pruning for Pathfinding on Grid Maps",
//! AAAI 2011, with the block-based jumps of "Improving Jump Point Search", ICAPS 2014): A* on an
//! 8-connected grid of uniform cost that puts on its open list only the jump points, the cells
//! where an optimal path may turn.
//!
//! - Arriving straight, a cell's successors are the cell ahead and its forced neighbours. With no
//!   corner cutting (the MovingAI rule), a side cell is forced (with the diagonal ahead of it)
//!   when the cell beside the parent on that side is blocked: the parent could not reach it
//!   diagonally. With corner cutting, the diagonal past a blocked side cell is forced.
//! - Arriving diagonally, the two straight cells and the diagonal ahead; with corner cutting, also
//!   the diagonal past a blocked cell behind. With no corner cutting a diagonal arrival forces
//!   nothing.
//! - A straight jump scans 64 cells per word of bit rows until the goal, a cell with a forced
//!   neighbour, or a blocked cell.
//! - A diagonal jump steps, and at each cell runs both straight jumps: what they find goes on
//!   the open list at once, reached diagonally first, then straight, and the diagonal goes on
//!   (the 2014 paper's way: the 2011 one stops there and puts the cell on the list, to expand it
//!   later into the same jumps). It stops at the goal, at a blocked cell, and (with corner
//!   cutting) at a cell with a forced neighbour of its own.
//! - The path between two jump points is diagonal first, then straight; every cell of it is
//!   returned.

use trailmark_core::grid::{Cell, CornerCutting, Grid};

use crate::error::SearchError;
use crate::one_shot::SearchResult;
use crate::one_shot::jump_map::{Direction, JumpMap};
use crate::one_shot::jump_search::JumpSearch;

/// Jump point search over one grid: made once (the map's passable cells as bytes and bit rows,
/// its one cell cost), asked for many queries.
///
/// The grid's moves are those of an 8-connected grid graph with the same corner-cutting rule
/// (`GridGraph::new(grid, Connectivity::Eight).with_corner_cutting(rule)`): straight moves cost
/// the cell cost, diagonal ones √2 times it.
///
/// ```
/// use trailmark_core::grid::{Cell, CornerCutting, Grid};
/// use trailmark_search::Jps;
///
/// let grid = Grid::from_rows(&["......", ".@@@@.", "......"])?;
/// let mut jps = Jps::new(&grid, CornerCutting::Forbidden)?;
/// let found = jps.search(Cell::new(0, 1), Cell::new(5, 1))?;
/// let path = found.path.expect("around the wall");
/// // Up, along the top row, down: no diagonal, which would cut the wall's corners.
/// assert_eq!(path.cost, 7.0);
/// assert_eq!(path.nodes.len(), 8);
///
/// // Clipping the wall's corners is shorter.
/// let mut cutting = Jps::new(&grid, CornerCutting::Allowed)?;
/// let cost = cutting.search(Cell::new(0, 1), Cell::new(5, 1))?.cost().expect("a path");
/// assert!((cost - (3.0 + 2.0 * std::f64::consts::SQRT_2)).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Jps {
    map: JumpMap,
    search: JumpSearch,
    directions: Vec<Direction>,
}

impl Jps {
    /// Jump point search on `grid`, whose diagonal moves follow `rule`.
    ///
    /// Errors: passable cells that do not all cost the same ([`SearchError::NonUniformCost`]):
    /// jump point search needs uniform costs, and would give a wrong path on others.
    pub fn new(grid: &Grid, rule: CornerCutting) -> Result<Self, SearchError<Cell>> {
        let map = JumpMap::new(grid, rule)?;
        let search = JumpSearch::new(map.free.len());
        Ok(Jps { map, search, directions: Vec::with_capacity(8) })
    }

    /// The rule for diagonal moves.
    pub fn corner_cutting(&self) -> CornerCutting {
        self.map.rule
    }

    /// Bytes held: the map (a byte and four bits per cell, with the border) and the search's
    /// per-cell state and open list.
    pub fn memory_bytes(&self) -> usize {
        self.map.memory_bytes() + self.search.memory_bytes()
    }

    /// The cells the last search expanded (the jump points it took off the open list), to draw
    /// or count; empty before the first.
    pub fn expanded(&self) -> Vec<Cell> {
        self.search.expanded(&self.map)
    }

    /// A least-cost path from `start` to `goal`, every cell of it (`None`: no path).
    ///
    /// Errors: a start or goal outside the grid or blocked.
    pub fn search(&mut self, start: Cell, goal: Cell) -> Result<SearchResult<Cell>, SearchError<Cell>> {
        let (map, directions) = (&self.map, &mut self.directions);
        self.search.run(map, start, goal, |u, arrival, goal, out| {
            out.clear();
            map.directions(u.index, arrival, directions);
            for &d in directions.iter() {
                map.jump(u, d, goal, out);
            }
        })
    }
}

/// Jump point search from `start` to `goal` on `grid` under `rule` (see [`Jps`]; make one to ask
/// many queries of the same grid).
pub fn jps(
    grid: &Grid,
    rule: CornerCutting,
    start: Cell,
    goal: Cell,
) -> Result<SearchResult<Cell>, SearchError<Cell>> {
    Jps::new(grid, rule)?.search(start, goal)
}
