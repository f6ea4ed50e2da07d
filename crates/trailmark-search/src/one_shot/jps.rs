//! Jump point search (Harabor and Grastien, "Online Graph Pruning for Pathfinding on Grid Maps",
//! AAAI 2011), under the MovingAI rule that a diagonal move needs both cells beside it free (the
//! pruning rules of their 2012 revision): A* on an 8-connected grid of uniform cost that puts on
//! its open list only the jump points, the cells where an optimal path may turn.
//!
//! - Arriving straight, a cell's successors are the cell ahead, and a side cell (with the
//!   diagonal ahead of it) when the cell beside the parent on that side is blocked: the parent
//!   could not reach it diagonally without cutting that corner.
//! - Arriving diagonally, the two straight cells and the diagonal ahead: with no corner cutting,
//!   a diagonal arrival forces nothing.
//! - A jump runs in a direction until the goal, a cell with a forced neighbour, or a blocked
//!   cell; a diagonal jump stops at a cell from which either straight jump finds something.
//!
//! Every jump runs along one line, so the path between two jump points is that line's cells.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::f64::consts::SQRT_2;
use std::time::Instant;

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::one_shot::SearchResult;
use crate::stats::SearchStats;

/// No parent: the start.
const ROOT: u32 = u32::MAX;

/// Jump point search over one grid: made once (a padded copy of which cells are free, and the
/// grid's one cell cost), asked for many queries.
///
/// The grid's moves are those of an 8-connected grid graph without corner cutting
/// (`GridGraph::new(grid, Connectivity::Eight)`): straight moves cost the cell cost, diagonal
/// ones √2 times it, and a diagonal needs both cells beside it passable.
///
/// ```
/// use trailmark_core::grid::{Cell, Grid};
/// use trailmark_search::Jps;
///
/// let grid = Grid::from_rows(&["......", ".@@@@.", "......"])?;
/// let mut jps = Jps::new(&grid)?;
/// let found = jps.search(Cell::new(0, 1), Cell::new(5, 1))?;
/// let path = found.path.expect("around the wall");
/// // Up, along the top row, down: no diagonal, which would cut the wall's corners.
/// assert_eq!(path.cost, 7.0);
/// assert_eq!(path.nodes.len(), 8);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Jps {
    width: u32,
    height: u32,
    /// The padded width: a blocked column on either side.
    stride: usize,
    /// Per padded cell: whether it is passable (the border never is).
    free: Vec<bool>,
    /// The cost of every passable cell: a move costs its length times it.
    cost: Cost,
    g: Vec<Cost>,
    parent: Vec<u32>,
    /// The query that last reached each cell, and whether it closed it (`era` odd: open;
    /// `era + 1`: closed).
    stamp: Vec<u32>,
    era: u32,
}

impl Jps {
    /// Jump point search on `grid`.
    ///
    /// Errors: passable cells that do not all cost the same ([`SearchError::NonUniformCost`]):
    /// jump point search needs uniform costs, and would give a wrong path on others.
    pub fn new(grid: &Grid) -> Result<Self, SearchError<Cell>> {
        let (width, height) = (grid.width(), grid.height());
        let stride = width as usize + 2;
        let cells = stride * (height as usize + 2);
        let mut free = vec![false; cells];
        let mut cost = None;
        for (k, &c) in grid.costs().iter().enumerate() {
            if !c.is_finite() {
                continue;
            }
            let (x, y) = (k % width as usize, k / width as usize);
            match cost {
                None => cost = Some(c),
                Some(expected) if expected != c => {
                    let cell = Cell::new(x as u32, y as u32);
                    return Err(SearchError::NonUniformCost { cell, cost: c, expected });
                }
                Some(_) => {}
            }
            free[(y + 1) * stride + x + 1] = true;
        }
        Ok(Jps {
            width,
            height,
            stride,
            free,
            cost: cost.unwrap_or(1.0),
            g: vec![0.0; cells],
            parent: vec![ROOT; cells],
            stamp: vec![0; cells],
            era: 0,
        })
    }

    /// The padded index of `cell`, if it is a passable cell of the grid.
    fn index_of(&self, cell: Cell) -> Option<usize> {
        let inside = cell.x < self.width && cell.y < self.height;
        let i = (cell.y as usize + 1) * self.stride + cell.x as usize + 1;
        (inside && self.free[i]).then_some(i)
    }

    fn cell_of(&self, i: usize) -> Cell {
        Cell::new((i % self.stride - 1) as u32, (i / self.stride - 1) as u32)
    }

    #[inline]
    fn open(&self, i: usize, dx: isize, dy: isize) -> bool {
        self.free[i.wrapping_add_signed(dy * self.stride as isize + dx)]
    }

    /// Whether the move from `i` by `(dx, dy)` is allowed: the target free, and for a diagonal
    /// both cells beside it too.
    #[inline]
    fn can_move(&self, i: usize, dx: isize, dy: isize) -> bool {
        self.open(i, dx, dy) && (dx == 0 || dy == 0 || (self.open(i, dx, 0) && self.open(i, 0, dy)))
    }

    /// Whether cell `i`, reached by a straight move `(dx, dy)`, has a forced neighbour.
    #[inline]
    fn forced_straight(&self, i: usize, dx: isize, dy: isize) -> bool {
        // The sides of the move; the cell beside the parent on a side is `side - (dx, dy)`.
        let (sx, sy) = (dy.abs(), dx.abs());
        [(sx, sy), (-sx, -sy)].iter().any(|&(ax, ay)| self.open(i, ax, ay) && !self.open(i, ax - dx, ay - dy))
    }

    /// The jump point reached from `i` moving by `(dx, dy)`, if any: the goal, a cell with a
    /// forced neighbour, or (diagonally) a cell from which a straight jump finds one.
    fn jump(&self, mut i: usize, dx: isize, dy: isize, goal: usize) -> Option<usize> {
        loop {
            if !self.can_move(i, dx, dy) {
                return None;
            }
            i = i.wrapping_add_signed(dy * self.stride as isize + dx);
            if i == goal {
                return Some(i);
            }
            if dx != 0 && dy != 0 {
                if self.jump(i, dx, 0, goal).is_some() || self.jump(i, 0, dy, goal).is_some() {
                    return Some(i);
                }
            } else if self.forced_straight(i, dx, dy) {
                return Some(i);
            }
        }
    }

    /// The directions to jump in from cell `i`, reached from `from` (`None` at the start): the
    /// natural ones and the forced ones, each a move that may be blocked (the jump checks it).
    fn directions(&self, i: usize, from: Option<usize>, out: &mut Vec<(isize, isize)>) {
        out.clear();
        let Some(p) = from else {
            out.extend([(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)]);
            return;
        };
        let (px, py) = ((p % self.stride) as isize, (p / self.stride) as isize);
        let (x, y) = ((i % self.stride) as isize, (i / self.stride) as isize);
        let (dx, dy) = ((x - px).signum(), (y - py).signum());
        if dx != 0 && dy != 0 {
            out.extend([(dx, 0), (0, dy), (dx, dy)]);
            return;
        }
        out.push((dx, dy));
        let (sx, sy) = (dy.abs(), dx.abs());
        for (ax, ay) in [(sx, sy), (-sx, -sy)] {
            if self.open(i, ax, ay) && !self.open(i, ax - dx, ay - dy) {
                out.extend([(ax, ay), (ax + dx, ay + dy)]);
            }
        }
    }

    /// The octile distance between padded cells `a` and `b` times the cell cost.
    fn distance(&self, a: usize, b: usize) -> Cost {
        let (ax, ay) = (a % self.stride, a / self.stride);
        let (bx, by) = (b % self.stride, b / self.stride);
        let (dx, dy) = (ax.abs_diff(bx) as f64, ay.abs_diff(by) as f64);
        (dx.max(dy) + (SQRT_2 - 1.0) * dx.min(dy)) * self.cost
    }

    /// A least-cost path from `start` to `goal`, every cell of it (`None`: no path).
    ///
    /// Errors: a start or goal outside the grid or blocked.
    pub fn search(&mut self, start: Cell, goal: Cell) -> Result<SearchResult<Cell>, SearchError<Cell>> {
        let clock = Instant::now();
        let s = self.index_of(start).ok_or(SearchError::StartNotInGraph(start))?;
        let t = self.index_of(goal).ok_or(SearchError::GoalNotInGraph(goal))?;
        // A new era: stamps below it are of earlier queries. Restarted before it wraps.
        if self.era >= u32::MAX - 2 {
            self.stamp.fill(0);
            self.era = 0;
        }
        self.era += 2;
        let (open, closed) = (self.era - 1, self.era);
        let mut stats = SearchStats::default();
        let mut heap = BinaryHeap::new();
        self.g[s] = 0.0;
        self.parent[s] = ROOT;
        self.stamp[s] = open;
        heap.push(Reverse((self.distance(s, t).to_bits(), !0.0f64.to_bits(), s)));
        stats.pushes += 1;
        let mut directions = Vec::with_capacity(8);
        let mut found = false;
        while let Some(Reverse((_, g_bits, u))) = heap.pop() {
            if self.stamp[u] == closed || !g_bits != self.g[u].to_bits() {
                continue; // expanded already, or reached more cheaply since this entry
            }
            if u == t {
                found = true;
                break;
            }
            self.stamp[u] = closed;
            stats.expansions += 1;
            let from = (self.parent[u] != ROOT).then(|| self.parent[u] as usize);
            self.directions(u, from, &mut directions);
            for &(dx, dy) in &directions {
                let Some(v) = self.jump(u, dx, dy, t) else { continue };
                let gv = self.g[u] + self.distance(u, v);
                let seen = self.stamp[v] == open || self.stamp[v] == closed;
                if seen && (self.stamp[v] == closed || gv >= self.g[v]) {
                    continue;
                }
                if seen {
                    stats.decreases += 1;
                }
                self.g[v] = gv;
                self.parent[v] = u as u32;
                self.stamp[v] = open;
                let f = gv + self.distance(v, t);
                // Among equal f, the deeper entry first: larger g, so its inverted bits are smaller.
                heap.push(Reverse((f.to_bits(), !gv.to_bits(), v)));
                stats.pushes += 1;
            }
        }
        let path = found.then(|| self.path_to(t));
        stats.elapsed = clock.elapsed();
        Ok(SearchResult { path, stats })
    }

    /// The cells from the start to `t` along the jump points' parents, each jump's line filled
    /// in, and the path's cost.
    fn path_to(&self, t: usize) -> Path<Cell> {
        let mut jumps = vec![t];
        while let Some(&last) = jumps.last() {
            match self.parent[last] {
                ROOT => break,
                p => jumps.push(p as usize),
            }
        }
        jumps.reverse();
        let mut nodes = vec![self.cell_of(jumps[0])];
        for pair in jumps.windows(2) {
            let (a, b) = (self.cell_of(pair[0]), self.cell_of(pair[1]));
            let (dx, dy) = ((b.x as i64 - a.x as i64).signum(), (b.y as i64 - a.y as i64).signum());
            let steps = (b.x as i64 - a.x as i64).abs().max((b.y as i64 - a.y as i64).abs());
            for k in 1..=steps {
                nodes.push(Cell::new((a.x as i64 + k * dx) as u32, (a.y as i64 + k * dy) as u32));
            }
        }
        Path { nodes, cost: self.g[t] }
    }
}

/// Jump point search from `start` to `goal` on `grid` (see [`Jps`]; make one to ask many
/// queries of the same grid).
pub fn jps(grid: &Grid, start: Cell, goal: Cell) -> Result<SearchResult<Cell>, SearchError<Cell>> {
    Jps::new(grid)?.search(start, goal)
}
