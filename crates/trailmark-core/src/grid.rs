//! Occupancy and cost grids.
//!
//! A [`Grid`] is a `width x height` array of cells addressed by [`Cell`] `{x, y}`, `(0, 0)` the
//! top-left cell and `x` the column. Every cell is either blocked or passable with a cost: the
//! price per unit length of moving through it (1 for an ordinary cell). Graph builders turn a grid
//! into a graph; a move between two neighbouring cells then costs its length (1 or `sqrt(2)`)
//! times the mean of the two cells' costs.
//!
//! ```
//! use trailmark_core::grid::{Cell, Grid};
//!
//! let mut grid = Grid::from_rows(&["....", ".@@.", "...."])?;
//! assert_eq!((grid.width(), grid.height()), (4, 3));
//! assert!(!grid.is_passable(Cell::new(1, 1)));
//! grid.set_cost(Cell::new(0, 2), 2.5)?;
//! assert_eq!(grid.cost(Cell::new(0, 2)), Some(2.5));
//! assert_eq!(grid.cost(Cell::new(9, 9)), None); // outside
//! # Ok::<(), trailmark_core::grid::GridError>(())
//! ```

use std::fmt;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::cost::Cost;

/// A cell of a grid: `x` is the column, `y` the row, `(0, 0)` the top-left cell.
///
/// In JSON a cell is the array `[x, y]`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default, Serialize, Deserialize)]
#[serde(from = "[u32; 2]", into = "[u32; 2]")]
pub struct Cell {
    /// The column, counted from the left.
    pub x: u32,
    /// The row, counted from the top.
    pub y: u32,
}

impl Cell {
    /// The cell at column `x`, row `y`.
    #[inline]
    pub const fn new(x: u32, y: u32) -> Self {
        Cell { x, y }
    }
}

impl fmt::Debug for Cell {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

impl fmt::Display for Cell {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

impl From<[u32; 2]> for Cell {
    fn from([x, y]: [u32; 2]) -> Self {
        Cell { x, y }
    }
}

impl From<Cell> for [u32; 2] {
    fn from(cell: Cell) -> Self {
        [cell.x, cell.y]
    }
}

/// When a diagonal move between two cells is allowed, given their two common orthogonal
/// neighbours (the "corners").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CornerCutting {
    /// Both corners must be passable: the MovingAI benchmark rule, and the default.
    #[default]
    Forbidden,
    /// At least one corner must be passable: the move may clip one blocked corner.
    Allowed,
    /// Only the target matters: the move may pass between two blocked corners.
    Squeeze,
}

/// Which neighbours of a grid cell are adjacent to it.
///
/// In JSON a connectivity is the number `4` or `8`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(try_from = "u8", into = "u8")]
pub enum Connectivity {
    /// The four orthogonal neighbours; every move has length 1.
    Four,
    /// The eight orthogonal and diagonal neighbours; diagonal moves have length `sqrt(2)`.
    #[default]
    Eight,
}

impl TryFrom<u8> for Connectivity {
    type Error = String;

    fn try_from(n: u8) -> Result<Self, String> {
        match n {
            4 => Ok(Connectivity::Four),
            8 => Ok(Connectivity::Eight),
            _ => Err(format!("connectivity must be 4 or 8, got {n}")),
        }
    }
}

impl From<Connectivity> for u8 {
    fn from(c: Connectivity) -> u8 {
        match c {
            Connectivity::Four => 4,
            Connectivity::Eight => 8,
        }
    }
}

/// A distance estimate between grid cells, for A*-like searches.
///
/// In JSON: `"zero"`, `"manhattan"`, `"octile"` or `"euclidean"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GridHeuristic {
    /// Always 0: A* becomes Dijkstra.
    Zero,
    /// `dx + dy`: exact on an empty 4-connected grid, not admissible on an 8-connected one.
    Manhattan,
    /// `max - min + sqrt(2) min`: exact on an empty 8-connected grid.
    Octile,
    /// `sqrt(dx² + dy²)`: admissible for any connectivity, but weaker than the two above.
    Euclidean,
}

impl GridHeuristic {
    /// The natural (tightest admissible) heuristic for a connectivity.
    pub fn for_connectivity(connectivity: Connectivity) -> Self {
        match connectivity {
            Connectivity::Four => GridHeuristic::Manhattan,
            Connectivity::Eight => GridHeuristic::Octile,
        }
    }

    /// Whether the heuristic never overestimates the unit-cost distance under `connectivity`.
    pub fn is_admissible(self, connectivity: Connectivity) -> bool {
        !(self == GridHeuristic::Manhattan && connectivity == Connectivity::Eight)
    }

    /// The estimate between cells that are `dx` columns and `dy` rows apart, for unit costs.
    #[inline]
    pub fn distance(self, dx: u32, dy: u32) -> Cost {
        match self {
            GridHeuristic::Zero => 0.0,
            GridHeuristic::Manhattan => crate::cost::manhattan(dx, dy),
            GridHeuristic::Octile => crate::cost::octile(dx, dy),
            GridHeuristic::Euclidean => crate::cost::euclidean(dx, dy),
        }
    }
}

/// What was wrong with a grid or with a change to one.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GridError {
    /// A grid needs at least one row and one column.
    #[error("a grid needs at least one cell, got {width} x {height}")]
    Empty {
        /// The requested width.
        width: usize,
        /// The requested height.
        height: usize,
    },
    /// The grid has more than [`Grid::MAX_CELLS`] cells (or `width x height` overflows).
    #[error("a {width} x {height} grid is too large (at most {} cells)", Grid::MAX_CELLS)]
    TooLarge {
        /// The requested width.
        width: usize,
        /// The requested height.
        height: usize,
    },
    /// The number of costs given does not match `width x height`.
    #[error("expected {expected} cell costs ({width} x {height}), got {found}")]
    CostCount {
        /// The grid width.
        width: usize,
        /// The grid height.
        height: usize,
        /// `width x height`.
        expected: usize,
        /// How many costs were given.
        found: usize,
    },
    /// A cell cost is not a positive finite number of at most [`MAX_CELL_COST`], or `+inf`
    /// (blocked).
    #[error(
        "cell {cell}: cost {cost:?} is invalid (a cell cost is positive and at most {MAX_CELL_COST:e}, or +inf for blocked)"
    )]
    InvalidCost {
        /// The cell.
        cell: Cell,
        /// The cost given.
        cost: f64,
    },
    /// A row of a textual grid has a different length from the first row.
    #[error("row {row}: {found} cells, but the grid is {expected} wide")]
    RaggedRow {
        /// The row, from 0.
        row: usize,
        /// The width of the grid.
        expected: usize,
        /// The length of this row.
        found: usize,
    },
    /// A character of a textual grid is not one of `.GS` (passable) or `@OTW` (blocked).
    #[error(
        "row {row}, column {column}: unknown cell character {character:?} (passable: . G S, blocked: @ O T W)"
    )]
    UnknownCell {
        /// The row, from 0.
        row: usize,
        /// The column, from 0.
        column: usize,
        /// The character found.
        character: char,
    },
    /// A cell lies outside the grid.
    #[error("cell {cell} is outside the {width} x {height} grid")]
    OutOfBounds {
        /// The cell.
        cell: Cell,
        /// The grid width.
        width: u32,
        /// The grid height.
        height: u32,
    },
}

/// A rectangular grid of blocked and passable cells, each passable cell with a positive cost.
#[derive(Clone, PartialEq)]
pub struct Grid {
    width: u32,
    height: u32,
    /// Row-major costs; `f64::INFINITY` is a blocked cell.
    costs: Vec<Cost>,
}

impl fmt::Debug for Grid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Grid")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("passable", &self.passable_count())
            .finish()
    }
}

/// Whether `c` is a passable cell character of the MovingAI format.
#[inline]
pub fn is_passable_char(c: char) -> Option<bool> {
    match c {
        '.' | 'G' | 'S' => Some(true),
        '@' | 'O' | 'T' | 'W' => Some(false),
        _ => None,
    }
}

impl Grid {
    /// The largest number of cells of a grid: 2^28 = 268,435,456 (16384 x 16384).
    ///
    /// A grid holds 8 bytes per cell (2 GiB at this size) and the graph builders and searches
    /// over it some tens of bytes more per cell, so this is about the largest grid a
    /// workstation can plan over; the largest MovingAI and GPPC benchmark maps have fewer than
    /// 2^24 cells. It keeps every cell index, with a border, far within `u32`, and bounds the
    /// cost of any path (see [`MAX_CELL_COST`]). Every constructor and generator checks it, with
    /// checked multiplication, before it allocates anything.
    pub const MAX_CELLS: usize = 1 << 28;

    /// The largest number of cells of a grid including a one-cell border around it, so that every
    /// cell of a grid graph has a `u32` index with room for sentinels. Every grid of at most
    /// [`Grid::MAX_CELLS`] cells is within it.
    pub const MAX_PADDED_CELLS: u64 = u32::MAX as u64 - 2;

    /// The number of cells of a `width x height` grid, checked: an error for a side of 0
    /// ([`GridError::Empty`]), and for more than [`Grid::MAX_CELLS`] cells or a product that
    /// overflows ([`GridError::TooLarge`]). Check a size with it before allocating for it.
    ///
    /// ```
    /// use trailmark_core::grid::{Grid, GridError};
    ///
    /// assert_eq!(Grid::cell_count(640, 480), Ok(307_200));
    /// assert!(matches!(Grid::cell_count(100_000, 100_000), Err(GridError::TooLarge { .. })));
    /// assert!(matches!(Grid::cell_count(usize::MAX, 2), Err(GridError::TooLarge { .. })));
    /// ```
    pub fn cell_count(width: usize, height: usize) -> Result<usize, GridError> {
        Self::check_size(width, height).map(|(_, _, cells)| cells)
    }

    fn check_size(width: usize, height: usize) -> Result<(u32, u32, usize), GridError> {
        if width == 0 || height == 0 {
            return Err(GridError::Empty { width, height });
        }
        let too_large = || GridError::TooLarge { width, height };
        let cells = width.checked_mul(height).filter(|&n| n <= Self::MAX_CELLS).ok_or_else(too_large)?;
        // Within MAX_CELLS, each side fits a u32 and the padded grid fits MAX_PADDED_CELLS.
        let (w, h) =
            (u32::try_from(width).map_err(|_| too_large())?, u32::try_from(height).map_err(|_| too_large())?);
        let padded = (u64::from(w) + 2).checked_mul(u64::from(h) + 2);
        if padded.is_none_or(|n| n > Self::MAX_PADDED_CELLS) {
            return Err(too_large());
        }
        Ok((w, h, cells))
    }

    /// A grid of `width x height` passable cells of cost 1.
    pub fn new(width: usize, height: usize) -> Result<Self, GridError> {
        let (w, h, cells) = Self::check_size(width, height)?;
        Ok(Grid { width: w, height: h, costs: vec![1.0; cells] })
    }

    /// A grid from row-major cell costs: a positive finite cost of at most [`MAX_CELL_COST`] for
    /// a passable cell, `f64::INFINITY` for a blocked one.
    pub fn from_costs(width: usize, height: usize, costs: Vec<Cost>) -> Result<Self, GridError> {
        let (w, h, expected) = Self::check_size(width, height)?;
        if costs.len() != expected {
            return Err(GridError::CostCount { width, height, expected, found: costs.len() });
        }
        if let Some(i) = costs.iter().position(|&c| !is_cell_cost(c)) {
            // i < width x height, so both fit a u32.
            let cell = Cell::new((i % width) as u32, (i / width) as u32);
            return Err(GridError::InvalidCost { cell, cost: costs[i] });
        }
        Ok(Grid { width: w, height: h, costs })
    }

    /// A grid from rows of MovingAI characters: `.`, `G`, `S` passable (cost 1), `@`, `O`, `T`,
    /// `W` blocked. All rows must have the same length; a trailing `\r` is ignored.
    pub fn from_rows<S: AsRef<str>>(rows: &[S]) -> Result<Self, GridError> {
        let height = rows.len();
        let width = rows.first().map_or(0, |r| trim_cr(r.as_ref()).chars().count());
        Self::check_size(width, height)?;
        // Memory grows with the rows actually given: a long first row and many short ones (a
        // ragged input) must not reserve the full width x height up front.
        let mut costs = Vec::new();
        for (row, text) in rows.iter().enumerate() {
            let text = trim_cr(text.as_ref());
            let before = costs.len();
            costs.reserve(width);
            for (column, character) in text.chars().enumerate() {
                match is_passable_char(character) {
                    Some(true) => costs.push(1.0),
                    Some(false) => costs.push(f64::INFINITY),
                    None => return Err(GridError::UnknownCell { row, column, character }),
                }
            }
            let found = costs.len() - before;
            if found != width {
                return Err(GridError::RaggedRow { row, expected: width, found });
            }
        }
        Self::from_costs(width, height, costs)
    }

    /// The rows of the grid as MovingAI characters: `.` for passable, `@` for blocked.
    /// Cell costs other than blocked/passable are not represented.
    pub fn to_rows(&self) -> Vec<String> {
        self.costs
            .chunks(self.width as usize)
            .map(|row| row.iter().map(|c| if c.is_finite() { '.' } else { '@' }).collect())
            .collect()
    }

    /// The number of columns.
    #[inline]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The number of rows.
    #[inline]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The number of cells, `width x height`.
    #[inline]
    pub fn len(&self) -> usize {
        self.costs.len()
    }

    /// Always false: a grid has at least one cell.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.costs.is_empty()
    }

    /// Whether `cell` lies inside the grid.
    #[inline]
    pub fn contains(&self, cell: Cell) -> bool {
        cell.x < self.width && cell.y < self.height
    }

    #[inline]
    fn offset(&self, cell: Cell) -> usize {
        cell.y as usize * self.width as usize + cell.x as usize
    }

    fn check(&self, cell: Cell) -> Result<usize, GridError> {
        if self.contains(cell) {
            Ok(self.offset(cell))
        } else {
            Err(GridError::OutOfBounds { cell, width: self.width, height: self.height })
        }
    }

    /// The cost of `cell`: `None` outside the grid, `Some(f64::INFINITY)` for a blocked cell.
    #[inline]
    pub fn cost(&self, cell: Cell) -> Option<Cost> {
        self.contains(cell).then(|| self.costs[self.offset(cell)])
    }

    /// Whether `cell` is inside the grid and passable.
    #[inline]
    pub fn is_passable(&self, cell: Cell) -> bool {
        self.cost(cell).is_some_and(f64::is_finite)
    }

    /// Sets the cost of `cell`: positive and at most [`MAX_CELL_COST`], or `f64::INFINITY` to
    /// block it.
    pub fn set_cost(&mut self, cell: Cell, cost: Cost) -> Result<(), GridError> {
        let i = self.check(cell)?;
        if !is_cell_cost(cost) {
            return Err(GridError::InvalidCost { cell, cost });
        }
        self.costs[i] = cost;
        Ok(())
    }

    /// Blocks `cell`, or makes it passable with cost 1.
    pub fn set_blocked(&mut self, cell: Cell, blocked: bool) -> Result<(), GridError> {
        self.set_cost(cell, if blocked { f64::INFINITY } else { 1.0 })
    }

    /// The row-major cell costs (`f64::INFINITY` for blocked cells).
    #[inline]
    pub fn costs(&self) -> &[Cost] {
        &self.costs
    }

    /// The number of passable cells.
    pub fn passable_count(&self) -> usize {
        self.costs.iter().filter(|c| c.is_finite()).count()
    }

    /// The smallest cost of a passable cell, or `None` when every cell is blocked.
    pub fn min_cost(&self) -> Option<Cost> {
        self.costs.iter().copied().filter(|c| c.is_finite()).reduce(f64::min)
    }

    /// Whether every passable cell costs exactly 1 (an occupancy grid).
    pub fn is_uniform(&self) -> bool {
        self.costs.iter().all(|&c| c == 1.0 || c == f64::INFINITY)
    }

    /// All cells, row by row.
    pub fn cells(&self) -> impl Iterator<Item = Cell> + '_ {
        (0..self.height).flat_map(move |y| (0..self.width).map(move |x| Cell::new(x, y)))
    }
}

/// The largest cost of a passable cell: 1e12.
///
/// A move costs its length (at most `sqrt(2)`) times the mean cost of two cells, and a simple
/// path has fewer than [`Grid::MAX_CELLS`] moves, so no path costs more than
/// `1e12 x sqrt(2) x 2^28`, about 3.8e20: some 287 orders of magnitude below `f64::MAX`, so path
/// costs, their sums over a planner's whole run, and heuristics inflated by any practical
/// weight stay finite, while a ratio of 1e12 to an ordinary cost of 1 is more than any terrain
/// model needs (a cost like 1e308 is finite, but two of them overflow to infinity, which means
/// "no edge"). Costs below it are not limited: any positive cost is allowed.
pub const MAX_CELL_COST: Cost = 1e12;

/// Whether `cost` is a valid cell cost: positive and at most [`MAX_CELL_COST`], or `+inf`
/// (blocked).
#[inline]
pub fn is_cell_cost(cost: Cost) -> bool {
    cost == f64::INFINITY || (cost > 0.0 && cost <= MAX_CELL_COST)
}

fn trim_cr(s: &str) -> &str {
    s.strip_suffix('\r').unwrap_or(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip() {
        let rows = ["..@.", "@...", "..T."];
        let grid = Grid::from_rows(&rows).unwrap();
        assert_eq!(grid.to_rows(), ["..@.", "@...", "..@."]);
        assert_eq!(grid.passable_count(), 9);
        assert!(grid.is_uniform());
        assert_eq!(grid.min_cost(), Some(1.0));
    }

    #[test]
    fn bad_rows_are_named() {
        assert_eq!(
            Grid::from_rows(&["...", ".."]),
            Err(GridError::RaggedRow { row: 1, expected: 3, found: 2 })
        );
        assert_eq!(
            Grid::from_rows(&["..", ".x"]),
            Err(GridError::UnknownCell { row: 1, column: 1, character: 'x' })
        );
        assert_eq!(Grid::from_rows::<&str>(&[]), Err(GridError::Empty { width: 0, height: 0 }));
        assert_eq!(Grid::from_rows(&["", ""]), Err(GridError::Empty { width: 0, height: 2 }));
    }

    #[test]
    fn costs_are_validated() {
        for bad in [0.0, -1.0, f64::NAN, f64::NEG_INFINITY] {
            let err = Grid::from_costs(2, 1, vec![1.0, bad]).unwrap_err();
            assert!(matches!(err, GridError::InvalidCost { cell: Cell { x: 1, y: 0 }, .. }));
        }
        assert!(matches!(
            Grid::from_costs(2, 2, vec![1.0; 3]),
            Err(GridError::CostCount { expected: 4, found: 3, .. })
        ));
        let mut grid = Grid::new(2, 2).unwrap();
        assert!(grid.set_cost(Cell::new(2, 0), 1.0).is_err());
        assert!(grid.set_cost(Cell::new(1, 0), -3.0).is_err());
        assert_eq!(grid.cost(Cell::new(1, 0)), Some(1.0), "a rejected change leaves the cell as it was");
    }

    #[test]
    fn huge_grids_are_refused() {
        assert!(matches!(Grid::new(1 << 20, 1 << 20), Err(GridError::TooLarge { .. })));
        assert!(matches!(Grid::new(usize::MAX, 3), Err(GridError::TooLarge { .. })));
        assert!(matches!(Grid::new(Grid::MAX_CELLS + 1, 1), Err(GridError::TooLarge { .. })));
        assert_eq!(Grid::cell_count(Grid::MAX_CELLS, 1), Ok(Grid::MAX_CELLS));
        assert_eq!(Grid::cell_count(1 << 14, 1 << 14), Ok(Grid::MAX_CELLS));
    }

    #[test]
    fn costs_are_bounded() {
        assert!(
            is_cell_cost(MAX_CELL_COST) && is_cell_cost(f64::MIN_POSITIVE) && is_cell_cost(f64::INFINITY)
        );
        for bad in [MAX_CELL_COST * 1.000001, 1e300, f64::MAX, 0.0, -0.0, f64::NAN] {
            assert!(!is_cell_cost(bad), "{bad}");
        }
    }

    #[test]
    fn cell_json_is_an_array() {
        let json = serde_json::to_string(&Cell::new(3, 7)).unwrap();
        assert_eq!(json, "[3,7]");
        assert_eq!(serde_json::from_str::<Cell>("[3, 7]").unwrap(), Cell::new(3, 7));
    }
}
