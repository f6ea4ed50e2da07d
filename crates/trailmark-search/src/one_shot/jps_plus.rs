//! JPS+ (Harabor and Grastien, "Improving Jump Point Search", ICAPS 2014; Rabin's tables, Game AI
//! Pro 2): jump point search whose jumps are read from a table made once per map, the distance
//! from every cell in each of the eight directions to the next jump point, or to the last cell
//! before a blocked one.
//!
//! The table ignores the goal, so a query checks it on the way: a straight jump whose line passes
//! the goal within its distance ends at the goal, and a diagonal jump whose line passes the row or
//! column of the goal within its distance ends there (the goal then lies straight ahead of that
//! cell, or the cell is an ordinary diagonal arrival that goes on).

use std::time::{Duration, Instant};

use trailmark_core::grid::{Cell, CornerCutting, Grid};

use crate::error::SearchError;
use crate::one_shot::SearchResult;
use crate::one_shot::jump_map::{DIRECTIONS, Direction, JumpMap, Spot, direction_index};
use crate::one_shot::jump_search::JumpSearch;

/// JPS+ over one grid: a table of jump distances made once (see the module's documentation),
/// asked for many queries. Same moves and paths as [`Jps`](crate::Jps).
///
/// The table is of the grid as it was when made: after the grid changes, make a new one (in time
/// linear in the cells, 10 to 18 ms for 512 x 512 on the project's benchmark machine;
/// [`JpsPlus::preprocessing_time`] says how long this one took).
///
/// ```
/// use trailmark_core::grid::{Cell, CornerCutting, Grid};
/// use trailmark_search::{Jps, JpsPlus};
///
/// let grid = Grid::from_rows(&["........", ".@@@@@..", "....@...", "........"])?;
/// let mut plus = JpsPlus::new(&grid, CornerCutting::Forbidden)?;
/// let mut online = Jps::new(&grid, CornerCutting::Forbidden)?;
/// let (start, goal) = (Cell::new(2, 2), Cell::new(7, 0));
/// let a = plus.search(start, goal)?.path.expect("a path");
/// let b = online.search(start, goal)?.path.expect("a path");
/// assert_eq!(a.cost, b.cost);
/// assert_eq!(a.nodes.first(), Some(&start));
/// assert_eq!(a.nodes.last(), Some(&goal));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct JpsPlus {
    map: JumpMap,
    /// Per padded cell and direction (in the order of `DIRECTIONS`): `n > 0`, a jump point `n`
    /// moves away; `n <= 0`, `-n` moves possible before a blocked cell, none of them a jump point.
    table: Vec<[i16; 8]>,
    search: JumpSearch,
    directions: Vec<Direction>,
    preprocessing: Duration,
}

impl JpsPlus {
    /// The most cells a grid may have for a table (16 bytes per cell: at most 256 MiB).
    pub const MAX_CELLS: usize = 1 << 24;

    /// The longest side a grid may have for a table: its distances are 16-bit.
    pub const MAX_SIDE: u32 = i16::MAX as u32 - 1;

    /// JPS+ on `grid`, whose diagonal moves follow `rule`: makes its table.
    ///
    /// Errors: passable cells that do not all cost the same ([`SearchError::NonUniformCost`]);
    /// a grid of more than [`JpsPlus::MAX_CELLS`] cells, or with a side longer than
    /// [`JpsPlus::MAX_SIDE`] ([`SearchError::TableTooLarge`]).
    pub fn new(grid: &Grid, rule: CornerCutting) -> Result<Self, SearchError<Cell>> {
        let clock = Instant::now();
        let (width, height) = (grid.width(), grid.height());
        if width as usize * height as usize > Self::MAX_CELLS || width.max(height) > Self::MAX_SIDE {
            return Err(SearchError::TableTooLarge { width, height });
        }
        let map = JumpMap::new(grid, rule)?;
        let table = table(&map);
        let search = JumpSearch::new(map.free.len());
        Ok(JpsPlus { map, table, search, directions: Vec::with_capacity(8), preprocessing: clock.elapsed() })
    }

    /// The rule for diagonal moves.
    pub fn corner_cutting(&self) -> CornerCutting {
        self.map.rule
    }

    /// How long making the map and the table took.
    pub fn preprocessing_time(&self) -> Duration {
        self.preprocessing
    }

    /// Bytes held: the map, the table (16 bytes per cell, with the border) and the search's
    /// per-cell state and open list.
    pub fn memory_bytes(&self) -> usize {
        self.map.memory_bytes() + self.table.len() * size_of::<[i16; 8]>() + self.search.memory_bytes()
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
        let (map, table, directions) = (&self.map, &self.table, &mut self.directions);
        self.search.run(map, start, goal, |u, arrival, goal, out| {
            out.clear();
            map.directions(u.index, arrival, directions);
            for &d in directions.iter() {
                if d.0 != 0 && d.1 != 0 {
                    diagonal_jumps(map, table, u, d, goal, out);
                } else {
                    out.extend(straight_jump(map, table, u, d, goal).map(|v| (v, d)));
                }
            }
        })
    }
}

/// The number of moves from `(x, y)` in direction `(dx, dy)` to where its line first meets the
/// goal's row or column, when it does (straight: where it meets the goal).
#[inline]
fn moves_to_goal((x, y): (usize, usize), (dx, dy): Direction, goal: Spot) -> Option<isize> {
    let (kx, ky) = ((goal.x as isize - x as isize) * dx, (goal.y as isize - y as isize) * dy);
    if dx != 0 && dy != 0 {
        (kx > 0 && ky > 0).then(|| kx.min(ky))
    } else if dx != 0 {
        (goal.y == y && kx > 0).then_some(kx)
    } else {
        (goal.x == x && ky > 0).then_some(ky)
    }
}

/// The cell `moves` moves from `i` in direction `(dx, dy)`.
#[inline]
fn moved(map: &JumpMap, i: usize, (dx, dy): Direction, moves: isize) -> usize {
    i.wrapping_add_signed(moves * (dy * map.stride as isize + dx))
}

/// The straight jump from `from` in direction `d`: the goal if the line reaches it before a
/// blocked cell or the next jump point, else that jump point, if any.
#[inline]
fn straight_jump(map: &JumpMap, table: &[[i16; 8]], from: Spot, d: Direction, goal: Spot) -> Option<usize> {
    let n = table[from.index][direction_index(d)];
    match moves_to_goal((from.x, from.y), d, goal) {
        Some(k) if k <= n.unsigned_abs() as isize => Some(goal.index),
        _ => (n > 0).then(|| moved(map, from.index, d, n as isize)),
    }
}

/// Puts in `out` what the diagonal jump from `from` in direction `d` finds: going from
/// jump point to jump point along the diagonal (and stopping where it meets the goal's row or
/// column), the straight jumps from each, and a cell with a forced neighbour or the goal where the
/// diagonal ends at one (as [`JumpMap::jump`] does).
fn diagonal_jumps(
    map: &JumpMap,
    table: &[[i16; 8]],
    from: Spot,
    d: Direction,
    goal: Spot,
    out: &mut Vec<(usize, Direction)>,
) {
    let Spot { index: mut i, mut x, mut y } = from;
    let (dx, dy) = d;
    let k = direction_index(d);
    loop {
        let n = table[i][k];
        let moves = match moves_to_goal((x, y), d, goal) {
            Some(m) if m <= n.unsigned_abs() as isize => m,
            _ if n > 0 => n as isize,
            _ => return,
        };
        i = moved(map, i, d, moves);
        (x, y) = (x.wrapping_add_signed(moves * dx), y.wrapping_add_signed(moves * dy));
        if i == goal.index || map.forced_diagonal(i, dx, dy) {
            out.push((i, d));
            return;
        }
        for s in [(dx, 0), (0, dy)] {
            out.extend(straight_jump(map, table, Spot { index: i, x, y }, s, goal).map(|v| (v, s)));
        }
    }
}

/// The jump distances of every cell of `map` (as in `JpsPlus`'s table): each from the entry of the
/// next cell in the same direction, so the cells are visited from the far end of each line.
fn table(map: &JumpMap) -> Vec<[i16; 8]> {
    let mut table = vec![[0i16; 8]; map.free.len()];
    let (w, h) = (map.width as usize, map.height as usize);
    // A line holds at most `MAX_SIDE` cells, so distances stay within 16 bits.
    let chain = |next: i16| if next > 0 { next + 1 } else { next - 1 };
    // Straight directions first: the diagonals read them.
    for &d in &DIRECTIONS {
        let k = direction_index(d);
        let (dx, dy) = d;
        for y in 0..h {
            let y = if dy > 0 { h - y } else { y + 1 };
            for x in 0..w {
                let x = if dx > 0 { w - x } else { x + 1 };
                let i = y * map.stride + x;
                if !map.free[i] || !map.can_move(i, dx, dy) {
                    continue;
                }
                let j = map.step(i, d);
                let jump_point = if dx != 0 && dy != 0 {
                    map.forced_diagonal(j, dx, dy)
                        || table[j][direction_index((dx, 0))] > 0
                        || table[j][direction_index((0, dy))] > 0
                } else {
                    map.forced_straight(j, dx, dy)
                };
                table[i][k] = if jump_point { 1 } else { chain(table[j][k]) };
            }
        }
    }
    table
}
