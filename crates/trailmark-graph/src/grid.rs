//! Grid graphs: the cells of a [`Grid`] as nodes, moves between neighbouring cells as edges.
//!
//! A move between neighbouring cells costs its length (1 orthogonally, `sqrt(2)` diagonally)
//! times the mean of the two cells' costs, so on an occupancy grid (every cost 1) the costs are
//! exactly 1 and `sqrt(2)`. The graph is symmetric: the cost of `a -> b` equals that of `b -> a`,
//! so predecessors are the successors.
//!
//! The graph keeps its own copy of the cells, surrounded by a border of blocked cells, so that
//! enumerating the neighbours of a cell needs no bounds checks and allocates nothing.
//!
//! ```
//! use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic, Successors};
//! use trailmark_graph::grid::{CornerCutting, GridGraph};
//!
//! let grid = Grid::from_rows(&["..", ".@"])?;
//! let graph = GridGraph::new(&grid, Connectivity::Eight);
//! let mut moves = Vec::new();
//! graph.for_each_successor(Cell::new(0, 0), |cell, cost| moves.push((cell, cost)));
//! // No corner cutting: the diagonal to (1, 1) is blocked anyway, and the two orthogonal moves cost 1.
//! assert_eq!(moves, [(Cell::new(1, 0), 1.0), (Cell::new(0, 1), 1.0)]);
//!
//! let cut = GridGraph::new(&Grid::from_rows(&["..", "@."])?, Connectivity::Eight)
//!     .with_corner_cutting(CornerCutting::Allowed);
//! let h = cut.heuristic(GridHeuristic::Octile, Cell::new(1, 1));
//! assert_eq!(h(Cell::new(0, 0)), std::f64::consts::SQRT_2);
//! # Ok::<(), trailmark_core::GridError>(())
//! ```

use std::sync::OnceLock;

use trailmark_core::cost::{Cost, SQRT_2};
use trailmark_core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
pub use trailmark_core::grid::CornerCutting;
use trailmark_core::grid::{Cell, Connectivity, Grid, GridError, GridHeuristic, is_cell_cost};

use crate::squares::open_squares;

/// One of the eight moves: its offset in the padded array is `dy * stride + dx`.
#[derive(Clone, Copy)]
struct Move {
    dx: i32,
    dy: i32,
    length: Cost,
}

/// Orthogonal moves first, so 4-connected graphs use the first four.
const MOVES: [Move; 8] = [
    Move { dx: 1, dy: 0, length: 1.0 },
    Move { dx: 0, dy: 1, length: 1.0 },
    Move { dx: -1, dy: 0, length: 1.0 },
    Move { dx: 0, dy: -1, length: 1.0 },
    Move { dx: 1, dy: 1, length: SQRT_2 },
    Move { dx: -1, dy: 1, length: SQRT_2 },
    Move { dx: -1, dy: -1, length: SQRT_2 },
    Move { dx: 1, dy: -1, length: SQRT_2 },
];

/// The graph of a grid: passable cells are nodes, moves to passable neighbours are edges.
#[derive(Debug, Clone)]
pub struct GridGraph {
    width: u32,
    height: u32,
    /// `width + 2`: the row length of the padded arrays.
    pub(crate) stride: usize,
    connectivity: Connectivity,
    pub(crate) corner_cutting: CornerCutting,
    /// Padded passability, border cells false.
    pub(crate) open: Vec<bool>,
    /// Padded move masks: bit `k` is set when `MOVES[k]` from the cell is an edge (target
    /// passable, corners as the rule demands, within the connectivity). Precomputed so that
    /// enumerating successors tests nothing but these bits.
    moves: Vec<u8>,
    /// `MOVES[k]` as an offset in the padded arrays.
    offsets: [isize; 8],
    /// Padded cell costs, only when some passable cell does not cost 1.
    pub(crate) costs: Option<Vec<Cost>>,
    /// The smallest passable cell cost (1 when there is none), which scales heuristics.
    min_cost: Cost,
    /// The padded cells' distances to the nearest edge cell (`squares.rs`), made at the first
    /// line drawn and forgotten when a cost changes.
    squares: OnceLock<Vec<u16>>,
}

impl GridGraph {
    /// The graph of `grid` with the given connectivity, without corner cutting.
    pub fn new(grid: &Grid, connectivity: Connectivity) -> Self {
        let (w, h) = (grid.width() as usize, grid.height() as usize);
        let stride = w + 2;
        let mut open = vec![false; stride * (h + 2)];
        let uniform = grid.is_uniform();
        let mut costs = (!uniform).then(|| vec![f64::INFINITY; open.len()]);
        for (y, row) in grid.costs().chunks(w).enumerate() {
            let base = (y + 1) * stride + 1;
            for (x, &c) in row.iter().enumerate() {
                open[base + x] = c.is_finite();
                if let Some(costs) = costs.as_mut() {
                    costs[base + x] = c;
                }
            }
        }
        let offsets = MOVES.map(|m| m.dy as isize * stride as isize + m.dx as isize);
        let mut graph = GridGraph {
            width: grid.width(),
            height: grid.height(),
            stride,
            connectivity,
            corner_cutting: CornerCutting::Forbidden,
            moves: vec![0; open.len()],
            open,
            offsets,
            costs,
            min_cost: grid.min_cost().unwrap_or(1.0),
            squares: OnceLock::new(),
        };
        graph.update_moves(0..graph.open.len());
        graph
    }

    /// The same graph with another corner-cutting rule (only 8-connected graphs move diagonally).
    pub fn with_corner_cutting(mut self, rule: CornerCutting) -> Self {
        self.corner_cutting = rule;
        self.update_moves(0..self.open.len());
        self
    }

    /// The padded cells' distances to the nearest edge cell, made once.
    pub(crate) fn squares(&self) -> &[u16] {
        self.squares.get_or_init(|| open_squares(&self.open, self.costs.as_deref(), self.stride))
    }

    /// Recomputes the move masks of the padded cells in `range`.
    fn update_moves(&mut self, range: std::ops::Range<usize>) {
        let count = match self.connectivity {
            Connectivity::Four => 4,
            Connectivity::Eight => 8,
        };
        for i in range {
            let mut mask = 0u8;
            if self.open[i] {
                for (k, &m) in MOVES.iter().enumerate().take(count) {
                    let target = self.open[(i as isize + self.offsets[k]) as usize];
                    if target && (m.dx == 0 || m.dy == 0 || self.diagonal_allowed(i, m)) {
                        mask |= 1 << k;
                    }
                }
            }
            self.moves[i] = mask;
        }
    }

    /// The number of columns.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The number of rows.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// 4- or 8-connected.
    pub fn connectivity(&self) -> Connectivity {
        self.connectivity
    }

    /// The corner-cutting rule for diagonal moves.
    pub fn corner_cutting(&self) -> CornerCutting {
        self.corner_cutting
    }

    /// The smallest cost of a passable cell: every move costs at least its length times this.
    pub fn min_cost(&self) -> Cost {
        self.min_cost
    }

    /// Whether `cell` is inside the grid and passable.
    #[inline]
    pub fn is_passable(&self, cell: Cell) -> bool {
        self.contains(cell)
    }

    #[inline]
    pub(crate) fn index(&self, cell: Cell) -> usize {
        (cell.y as usize + 1) * self.stride + cell.x as usize + 1
    }

    /// The cost of `cell`: `None` outside the grid, `Some(f64::INFINITY)` when blocked.
    pub fn cost(&self, cell: Cell) -> Option<Cost> {
        if cell.x >= self.width || cell.y >= self.height {
            return None;
        }
        let i = self.index(cell);
        Some(match (&self.costs, self.open[i]) {
            (_, false) => f64::INFINITY,
            (Some(costs), true) => costs[i],
            (None, true) => 1.0,
        })
    }

    /// Changes the cost of a cell: positive and finite, or `f64::INFINITY` to block it.
    ///
    /// The heuristics made afterwards account for a new smallest cost; the ones made before keep
    /// the smallest cost they were made with.
    pub fn set_cost(&mut self, cell: Cell, cost: Cost) -> Result<(), GridError> {
        if cell.x >= self.width || cell.y >= self.height {
            return Err(GridError::OutOfBounds { cell, width: self.width, height: self.height });
        }
        if !is_cell_cost(cost) {
            return Err(GridError::InvalidCost { cell, cost });
        }
        let i = self.index(cell);
        if cost.is_finite() && cost != 1.0 && self.costs.is_none() {
            let costs = self.open.iter().map(|&o| if o { 1.0 } else { f64::INFINITY }).collect();
            self.costs = Some(costs);
        }
        if let Some(costs) = self.costs.as_mut() {
            costs[i] = cost;
        }
        self.open[i] = cost.is_finite();
        self.squares = OnceLock::new();
        // The moves that start, end or cut a corner at this cell start within one cell of it.
        for row in [i - self.stride, i, i + self.stride] {
            self.update_moves(row - 1..row + 2);
        }
        if cost.is_finite() {
            self.min_cost = self.min_cost.min(cost);
        }
        Ok(())
    }

    /// The cells whose edges a change of `cell`'s cost can change: `cell` and its neighbours
    /// inside the grid (a diagonal move between two neighbours of `cell` cuts its corner). An
    /// incremental planner told of these cells after [`set_cost`](Self::set_cost) repairs
    /// every edge the change touched.
    ///
    /// ```
    /// use trailmark_core::{Cell, Connectivity, Grid};
    /// use trailmark_graph::GridGraph;
    ///
    /// let graph = GridGraph::new(&Grid::new(4, 4)?, Connectivity::Eight);
    /// assert_eq!(graph.cells_affected_by(Cell::new(0, 0)).count(), 4);
    /// assert_eq!(graph.cells_affected_by(Cell::new(1, 1)).count(), 9);
    /// assert_eq!(graph.cells_affected_by(Cell::new(9, 9)).count(), 0);
    /// # Ok::<(), trailmark_core::GridError>(())
    /// ```
    pub fn cells_affected_by(&self, cell: Cell) -> impl Iterator<Item = Cell> + use<> {
        let (w, h) = (self.width, self.height);
        let inside = cell.x < w && cell.y < h;
        let xs = cell.x.saturating_sub(1)..=(cell.x + 1).min(w.saturating_sub(1));
        let ys = cell.y.saturating_sub(1)..=(cell.y + 1).min(h.saturating_sub(1));
        ys.filter(move |_| inside).flat_map(move |y| xs.clone().map(move |x| Cell::new(x, y)))
    }

    /// Every move whose cost may change when `cell`'s cost changes, as the changes a replanner
    /// is told: the moves into and out of `cell`, and with 8-connectivity the diagonal moves
    /// between two of its orthogonal neighbours, which pass `cell`'s corner. Fewer than
    /// [`cells_affected_by`](Self::cells_affected_by) names: the planners that relax each
    /// changed edge (Adaptive A*, MPGAA*) look at these alone.
    ///
    /// ```
    /// use trailmark_core::{Cell, Connectivity, Grid};
    /// use trailmark_graph::GridGraph;
    ///
    /// let graph = GridGraph::new(&Grid::new(4, 4)?, Connectivity::Eight);
    /// assert_eq!(graph.edges_affected_by(Cell::new(1, 1)).len(), 16 + 8);
    /// assert_eq!(graph.edges_affected_by(Cell::new(0, 0)).len(), 6 + 2);
    /// let four = GridGraph::new(&Grid::new(4, 4)?, Connectivity::Four);
    /// assert_eq!(four.edges_affected_by(Cell::new(1, 1)).len(), 8);
    /// assert!(graph.edges_affected_by(Cell::new(9, 9)).is_empty());
    /// # Ok::<(), trailmark_core::GridError>(())
    /// ```
    pub fn edges_affected_by(&self, cell: Cell) -> Vec<EdgeChange<Cell>> {
        let mut edges = Vec::new();
        if !(cell.x < self.width && cell.y < self.height) {
            return edges;
        }
        let eight = self.connectivity == Connectivity::Eight;
        let at = |dx: i64, dy: i64| {
            let (x, y) = (i64::from(cell.x) + dx, i64::from(cell.y) + dy);
            (x >= 0 && y >= 0 && x < i64::from(self.width) && y < i64::from(self.height))
                .then(|| Cell::new(x as u32, y as u32))
        };
        for (dx, dy) in [(1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)] {
            if !eight && dx != 0 && dy != 0 {
                continue;
            }
            if let Some(n) = at(dx, dy) {
                edges.push(EdgeChange::new(cell, n));
                edges.push(EdgeChange::new(n, cell));
            }
        }
        if eight {
            // The orthogonal neighbours on either side of each corner of `cell`.
            for (a, b) in [((1, 0), (0, 1)), ((0, 1), (-1, 0)), ((-1, 0), (0, -1)), ((0, -1), (1, 0))] {
                if let (Some(a), Some(b)) = (at(a.0, a.1), at(b.0, b.1)) {
                    edges.push(EdgeChange::new(a, b));
                    edges.push(EdgeChange::new(b, a));
                }
            }
        }
        edges
    }

    /// The cost of the move `from -> to` between neighbouring cells, or `None` when it is not an
    /// edge of the graph (not neighbours, a cell blocked, a corner rule forbids it).
    pub fn edge_cost(&self, from: Cell, to: Cell) -> Option<Cost> {
        let mut found = None;
        if self.contains(from) {
            self.for_each_successor(from, |n, c| {
                if n == to {
                    found = Some(c);
                }
            });
        }
        found
    }

    /// A heuristic toward `goal`: the grid distance of `kind`, scaled by the smallest cell cost so
    /// that an admissible distance stays admissible with cell costs.
    pub fn heuristic(&self, kind: GridHeuristic, goal: Cell) -> impl Fn(Cell) -> Cost + Copy + use<> {
        let scale = self.min_cost;
        move |cell: Cell| scale * kind.distance(cell.x.abs_diff(goal.x), cell.y.abs_diff(goal.y))
    }

    /// A heuristic between any two cells, `h(a, b)`: the grid distance of `kind` scaled by the
    /// smallest cell cost, as [`heuristic`](Self::heuristic) but with both ends free. The
    /// incremental planners take this form (D* Lite estimates from the moving robot).
    pub fn heuristic_between(&self, kind: GridHeuristic) -> impl Fn(Cell, Cell) -> Cost + Copy + use<> {
        let scale = self.min_cost;
        move |a: Cell, b: Cell| scale * kind.distance(a.x.abs_diff(b.x), a.y.abs_diff(b.y))
    }

    #[inline]
    fn diagonal_allowed(&self, i: usize, m: Move) -> bool {
        let a = self.open[(i as isize + m.dx as isize) as usize];
        let b = self.open[(i as isize + m.dy as isize * self.stride as isize) as usize];
        match self.corner_cutting {
            CornerCutting::Forbidden => a && b,
            CornerCutting::Allowed => a || b,
            CornerCutting::Squeeze => true,
        }
    }
}

impl Graph for GridGraph {
    type Node = Cell;

    /// A cell is a node when it lies inside the grid and is passable.
    #[inline]
    fn contains(&self, cell: Cell) -> bool {
        cell.x < self.width && cell.y < self.height && self.open[self.index(cell)]
    }
}

impl Successors for GridGraph {
    #[inline]
    fn for_each_successor<F: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: F) {
        self.visit_moves(self.index(cell), cell, |_, next, cost| visit(next, cost));
    }

    #[inline]
    fn for_each_successor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, visit: F) {
        self.visit_moves(index, self.node_at(index), visit);
    }
}

/// The moves out of a cell, as an iterator of `(neighbour, cost)`; see [`GridGraph::neighbours`].
#[derive(Debug, Clone)]
pub struct Neighbours<'a> {
    graph: &'a GridGraph,
    cell: Cell,
    index: usize,
    mask: u8,
}

impl Iterator for Neighbours<'_> {
    type Item = (Cell, Cost);

    #[inline]
    fn next(&mut self) -> Option<(Cell, Cost)> {
        if self.mask == 0 {
            return None;
        }
        let k = self.mask.trailing_zeros() as usize;
        self.mask &= self.mask - 1;
        let (_, next, cost) = self.graph.step(self.index, self.cell, k);
        Some((next, cost))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.mask.count_ones() as usize;
        (n, Some(n))
    }
}

impl GridGraph {
    /// The moves out of `cell` as an iterator of `(neighbour, cost)`, allocating nothing: the
    /// same edges as [`Successors::for_each_successor`], for code that wants an iterator (the
    /// `pathfinding` crate's successor functions, for instance). Empty when `cell` is not a node.
    ///
    /// ```
    /// use trailmark_core::{Cell, Connectivity, Grid};
    /// use trailmark_graph::GridGraph;
    ///
    /// let graph = GridGraph::new(&Grid::from_rows(&["..", ".."])?, Connectivity::Eight);
    /// assert_eq!(graph.neighbours(Cell::new(0, 0)).count(), 3);
    /// assert_eq!(graph.neighbours(Cell::new(7, 7)).count(), 0);
    /// # Ok::<(), trailmark_core::GridError>(())
    /// ```
    pub fn neighbours(&self, cell: Cell) -> Neighbours<'_> {
        let (index, mask) = if self.contains(cell) {
            let i = self.index(cell);
            (i, self.moves[i])
        } else {
            (0, 0)
        };
        Neighbours { graph: self, cell, index, mask }
    }

    /// Move `k` from the cell at padded index `i`: the target's index, the target, the cost.
    #[inline]
    fn step(&self, i: usize, cell: Cell, k: usize) -> (usize, Cell, Cost) {
        let m = MOVES[k];
        let j = (i as isize + self.offsets[k]) as usize;
        let next = Cell::new(cell.x.wrapping_add_signed(m.dx), cell.y.wrapping_add_signed(m.dy));
        let cost = match &self.costs {
            None => m.length,
            Some(costs) => m.length * 0.5 * (costs[i] + costs[j]),
        };
        (j, next, cost)
    }

    /// The successors of the cell at padded index `i`, as `(index, cell, cost)`.
    #[inline]
    fn visit_moves<F: FnMut(usize, Cell, Cost)>(&self, i: usize, cell: Cell, mut visit: F) {
        let mut mask = self.moves[i];
        while mask != 0 {
            let k = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let (j, next, cost) = self.step(i, cell, k);
            visit(j, next, cost);
        }
    }
}

impl Predecessors for GridGraph {
    /// The grid graph is symmetric: the predecessors of a cell are its successors.
    #[inline]
    fn for_each_predecessor<F: FnMut(Cell, Cost)>(&self, cell: Cell, visit: F) {
        self.for_each_successor(cell, visit)
    }

    #[inline]
    fn for_each_predecessor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, visit: F) {
        self.visit_moves(index, self.node_at(index), visit);
    }
}

impl IndexedGraph for GridGraph {
    /// The padded cell count `(width + 2) x (height + 2)`.
    #[inline]
    fn node_bound(&self) -> usize {
        self.open.len()
    }

    #[inline]
    fn index_of(&self, cell: Cell) -> usize {
        self.index(cell)
    }

    #[inline]
    fn node_at(&self, index: usize) -> Cell {
        // Indices fit in u32 (the grid checks its size), and 32-bit division is the faster one.
        let (i, stride) = (index as u32, self.stride as u32);
        Cell::new(i % stride - 1, i / stride - 1)
    }

    /// Every cell inside the grid, passable or blocked, has an index: a blocked cell may open.
    #[inline]
    fn checked_index(&self, cell: Cell) -> Option<usize> {
        (cell.x < self.width && cell.y < self.height).then(|| self.index(cell))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn successors(g: &GridGraph, c: Cell) -> Vec<(Cell, Cost)> {
        let mut v = Vec::new();
        g.for_each_successor(c, |n, k| v.push((n, k)));
        v.sort_by_key(|a| a.0);
        v
    }

    #[test]
    fn corner_rules() {
        // (0,0) -> (1,1) with corner (1,0) blocked and corner (0,1) open.
        let grid = Grid::from_rows(&[".@", ".."]).unwrap();
        let diag = Cell::new(1, 1);
        let has = |rule| {
            let g = GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
            successors(&g, Cell::new(0, 0)).iter().any(|&(c, _)| c == diag)
        };
        assert!(!has(CornerCutting::Forbidden));
        assert!(has(CornerCutting::Allowed));
        assert!(has(CornerCutting::Squeeze));
        // Both corners blocked: only Squeeze passes.
        let grid = Grid::from_rows(&[".@", "@."]).unwrap();
        let g = |rule| GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
        assert!(successors(&g(CornerCutting::Allowed), Cell::new(0, 0)).is_empty());
        assert_eq!(successors(&g(CornerCutting::Squeeze), Cell::new(0, 0)), [(diag, SQRT_2)]);
    }

    #[test]
    fn four_and_eight_neighbours_with_costs() {
        let mut grid = Grid::new(3, 3).unwrap();
        grid.set_cost(Cell::new(2, 2), 3.0).unwrap();
        let four = GridGraph::new(&grid, Connectivity::Four);
        let eight = GridGraph::new(&grid, Connectivity::Eight);
        let centre = Cell::new(1, 1);
        assert_eq!(successors(&four, centre).len(), 4);
        let s = successors(&eight, centre);
        assert_eq!(s.len(), 8);
        assert_eq!(s.iter().find(|(c, _)| *c == Cell::new(2, 2)).unwrap().1, SQRT_2 * 2.0);
        assert_eq!(eight.edge_cost(Cell::new(2, 2), centre), Some(SQRT_2 * 2.0));
        assert_eq!(eight.edge_cost(Cell::new(0, 0), Cell::new(2, 2)), None);
        // Corner cells have 3 neighbours: no wrap-around through the border.
        assert_eq!(successors(&eight, Cell::new(0, 0)).len(), 3);
        assert_eq!(successors(&eight, Cell::new(2, 0)).len(), 3);
    }

    #[test]
    fn the_three_ways_to_enumerate_moves_agree() {
        let mut grid = Grid::from_rows(&[".@..", "...@", "@...", "..@."]).unwrap();
        grid.set_cost(Cell::new(2, 2), 2.0).unwrap();
        for connectivity in [Connectivity::Four, Connectivity::Eight] {
            for rule in [CornerCutting::Forbidden, CornerCutting::Allowed, CornerCutting::Squeeze] {
                let g = GridGraph::new(&grid, connectivity).with_corner_cutting(rule);
                for c in grid.cells() {
                    let mut by_node = Vec::new();
                    if g.contains(c) {
                        g.for_each_successor(c, |n, k| by_node.push((n, k)));
                    }
                    let mut by_index = Vec::new();
                    if g.contains(c) {
                        g.for_each_successor_index(g.index_of(c), |i, n, k| {
                            assert_eq!(g.index_of(n), i);
                            by_index.push((n, k));
                        });
                    }
                    let iterated: Vec<_> = g.neighbours(c).collect();
                    assert_eq!(by_node, by_index);
                    assert_eq!(by_node, iterated);
                }
            }
        }
    }

    #[test]
    fn indices_round_trip_and_stay_below_bound() {
        let grid = Grid::new(5, 3).unwrap();
        let g = GridGraph::new(&grid, Connectivity::Eight);
        for c in grid.cells() {
            let i = g.index_of(c);
            assert!(i < g.node_bound());
            assert_eq!(g.node_at(i), c);
        }
        assert!(!g.contains(Cell::new(5, 0)) && !g.contains(Cell::new(0, 3)));
    }

    #[test]
    fn set_cost_validates_and_updates() {
        let grid = Grid::new(2, 1).unwrap();
        let mut g = GridGraph::new(&grid, Connectivity::Four);
        assert!(g.set_cost(Cell::new(2, 0), 1.0).is_err());
        assert!(g.set_cost(Cell::new(1, 0), f64::NAN).is_err());
        g.set_cost(Cell::new(1, 0), 0.5).unwrap();
        assert_eq!(g.edge_cost(Cell::new(0, 0), Cell::new(1, 0)), Some(0.75));
        assert_eq!(g.min_cost(), 0.5);
        g.set_cost(Cell::new(1, 0), f64::INFINITY).unwrap();
        assert_eq!(g.edge_cost(Cell::new(0, 0), Cell::new(1, 0)), None);
        assert_eq!(g.cost(Cell::new(1, 0)), Some(f64::INFINITY));
    }
}
