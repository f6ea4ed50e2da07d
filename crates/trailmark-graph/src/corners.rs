//! The corner graph of a grid: its nodes are the corners of cells, the plane of the GPPC
//! any-angle track, where an agent is a point and blocked cells are closed unit squares.
//!
//! A corner `(x, y)` is the top-left corner of cell `(x, y)`; corners run from `(0, 0)` to
//! `(width, height)`. A straight segment between two corners is clear, by the track's rules, when
//! it passes through no blocked cell's interior, runs along no edge shared by two blocked cells
//! (the map's outside counts as blocked), and passes through no corner shared by two blocked
//! cells that touch only diagonally (it may end at one). Edges join each corner to its eight
//! neighbours by clear unit segments; [`CornerGraph::line_cost`] gives any clear segment's
//! length, for Theta*. Such double corners have no edges: a path through one would cut between
//! its blocked cells or turn back, so paths here never visit them (the track allows a path to
//! touch one and turn; doing without is never shorter than the track's optimum).
//!
//! ```
//! use trailmark_core::{Cell, Grid};
//! use trailmark_graph::CornerGraph;
//!
//! // Two blocked cells touching diagonally: the line through their shared corner is not clear.
//! let graph = CornerGraph::new(&Grid::from_rows(&["@.", ".@"])?);
//! assert_eq!(graph.line_cost(Cell::new(0, 2), Cell::new(2, 0)), None);
//! // Along the top edge of the map, over a free cell: clear.
//! assert_eq!(graph.line_cost(Cell::new(1, 0), Cell::new(2, 0)), Some(1.0));
//! // Along the left edge of the map beside the blocked cell (0, 0): the outside is blocked too.
//! assert_eq!(graph.line_cost(Cell::new(0, 0), Cell::new(0, 1)), None);
//! # Ok::<(), trailmark_core::GridError>(())
//! ```

use trailmark_core::cost::{Cost, SQRT_2};
use trailmark_core::graph::{Graph, IndexedGraph, Lines, Successors};
use trailmark_core::grid::{Cell, Grid};

/// The eight unit moves between corners.
const MOVES: [(i64, i64); 8] = [(1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)];

/// The graph of a grid's cell corners (see the module's documentation).
#[derive(Debug, Clone)]
pub struct CornerGraph {
    width: u32,
    height: u32,
    /// Cell passability with a one-cell border of blocked cells: cell `(x, y)` is at
    /// `(y + 1) * (width + 2) + x + 1`.
    open: Vec<bool>,
    /// Bit `k` set when `MOVES[k]` from the corner is clear; corner `(x, y)` at
    /// `y * (width + 1) + x`.
    moves: Vec<u8>,
}

impl CornerGraph {
    /// The corner graph of `grid`.
    pub fn new(grid: &Grid) -> Self {
        let (w, h) = (grid.width(), grid.height());
        let stride = w as usize + 2;
        let mut open = vec![false; stride * (h as usize + 2)];
        for cell in grid.cells() {
            open[(cell.y as usize + 1) * stride + cell.x as usize + 1] = grid.is_passable(cell);
        }
        let mut graph = CornerGraph { width: w, height: h, open, moves: Vec::new() };
        let corners = (w as usize + 1) * (h as usize + 1);
        graph.moves = (0..corners)
            .map(|i| {
                let c = graph.node_at(i);
                let (x, y) = (i64::from(c.x), i64::from(c.y));
                let mut mask = 0;
                // A path may not go on through a double corner (it would cut between the two
                // blocked cells, or at best turn back), so they have no edges at all.
                if graph.double_corner(x, y) {
                    return mask;
                }
                for (k, (dx, dy)) in MOVES.iter().enumerate() {
                    let (nx, ny) = (x + dx, y + dy);
                    if graph.inside(nx, ny) && !graph.double_corner(nx, ny) && graph.clear(x, y, nx, ny) {
                        mask |= 1 << k;
                    }
                }
                mask
            })
            .collect();
        graph
    }

    /// Corners per row: `width + 1`.
    fn row(&self) -> usize {
        self.width as usize + 1
    }

    fn inside(&self, x: i64, y: i64) -> bool {
        x >= 0 && y >= 0 && x <= i64::from(self.width) && y <= i64::from(self.height)
    }

    /// Whether cell `(x, y)` is blocked; cells outside the map are.
    fn blocked(&self, x: i64, y: i64) -> bool {
        if x < -1 || y < -1 || x > i64::from(self.width) || y > i64::from(self.height) {
            return true;
        }
        !self.open[((y + 1) as usize) * (self.width as usize + 2) + (x + 1) as usize]
    }

    /// Whether the corner `(x, y)` is shared by two blocked cells that touch only diagonally.
    fn double_corner(&self, x: i64, y: i64) -> bool {
        let (tl, tr, bl, br) =
            (self.blocked(x - 1, y - 1), self.blocked(x, y - 1), self.blocked(x - 1, y), self.blocked(x, y));
        (tl && br && !tr && !bl) || (tr && bl && !tl && !br)
    }

    /// The length of the straight segment from corner `from` to corner `to`, or `None` when it
    /// is not clear (or either end is not a corner of the map).
    pub fn line_cost(&self, from: Cell, to: Cell) -> Option<Cost> {
        let (ax, ay, bx, by) = (i64::from(from.x), i64::from(from.y), i64::from(to.x), i64::from(to.y));
        (self.inside(ax, ay) && self.inside(bx, by) && self.clear(ax, ay, bx, by))
            .then(|| ((bx - ax) as f64).hypot((by - ay) as f64))
    }

    /// Whether the segment from corner `(ax, ay)` to corner `(bx, by)` is clear.
    fn clear(&self, ax: i64, ay: i64, bx: i64, by: i64) -> bool {
        let (dx, dy) = (bx - ax, by - ay);
        let (sx, sy) = (dx.signum(), dy.signum());
        let (adx, ady) = (dx.abs(), dy.abs());
        if adx == 0 && ady == 0 {
            return true;
        }
        if ady == 0 || adx == 0 {
            // Along a grid line: each unit step needs a free cell on one side of it, and no
            // corner passed through may be a double corner.
            let n = adx.max(ady);
            for k in 0..n {
                let (x, y) = (ax + sx * k, ay + sy * k);
                if k > 0 && self.double_corner(x, y) {
                    return false;
                }
                let (a, b) = if ady == 0 {
                    let cx = if sx > 0 { x } else { x - 1 };
                    (self.blocked(cx, y - 1), self.blocked(cx, y))
                } else {
                    let cy = if sy > 0 { y } else { y - 1 };
                    (self.blocked(x - 1, cy), self.blocked(x, cy))
                };
                if a && b {
                    return false;
                }
            }
            return true;
        }
        // Through cell interiors: the first cell is the one the segment enters from its start.
        let (mut cx, mut cy) = (if sx > 0 { ax } else { ax - 1 }, if sy > 0 { ay } else { ay - 1 });
        if self.blocked(cx, cy) {
            return false;
        }
        // Crossings of vertical lines at t = i / adx, of horizontal ones at j / ady (1 <= i < adx,
        // 1 <= j < ady), compared exactly: i * ady against j * adx.
        let (mut i, mut j) = (1, 1);
        while i < adx || j < ady {
            let (ti, tj) =
                (if i < adx { i * ady } else { i64::MAX }, if j < ady { j * adx } else { i64::MAX });
            if ti < tj {
                cx += sx;
                i += 1;
            } else if tj < ti {
                cy += sy;
                j += 1;
            } else {
                // Through a corner: not a double corner; the next cell is diagonal.
                let (px, py) = (ax + sx * i, ay + sy * j);
                if self.double_corner(px, py) {
                    return false;
                }
                cx += sx;
                cy += sy;
                i += 1;
                j += 1;
            }
            if self.blocked(cx, cy) {
                return false;
            }
        }
        true
    }
}

impl Graph for CornerGraph {
    type Node = Cell;

    /// Every corner of the map is a node: `(0, 0)` to `(width, height)`.
    fn contains(&self, corner: Cell) -> bool {
        corner.x <= self.width && corner.y <= self.height
    }
}

impl IndexedGraph for CornerGraph {
    fn node_bound(&self) -> usize {
        self.moves.len()
    }

    fn index_of(&self, corner: Cell) -> usize {
        corner.y as usize * self.row() + corner.x as usize
    }

    fn node_at(&self, index: usize) -> Cell {
        Cell::new((index % self.row()) as u32, (index / self.row()) as u32)
    }
}

impl Successors for CornerGraph {
    fn for_each_successor<F: FnMut(Cell, Cost)>(&self, corner: Cell, mut visit: F) {
        if !self.contains(corner) {
            return;
        }
        let mask = self.moves[self.index_of(corner)];
        for (k, (dx, dy)) in MOVES.iter().enumerate() {
            if mask & (1 << k) != 0 {
                let next = Cell::new((i64::from(corner.x) + dx) as u32, (i64::from(corner.y) + dy) as u32);
                visit(next, if k < 4 { 1.0 } else { SQRT_2 });
            }
        }
    }
}

/// The corners' lines for any-angle searches: [`CornerGraph::line_cost`], at least the length.
impl Lines<Cell> for CornerGraph {
    #[inline]
    fn line_cost(&self, from: Cell, to: Cell) -> Option<Cost> {
        CornerGraph::line_cost(self, from, to)
    }

    #[inline]
    fn line_lower_bound(&self, from: Cell, to: Cell) -> Cost {
        f64::from(from.x.abs_diff(to.x)).hypot(f64::from(from.y.abs_diff(to.y)))
    }
}
