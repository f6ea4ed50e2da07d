//! Straight lines between cell centres on a grid graph: which cells a line crosses, whether it
//! may, and what it costs. Any-angle searches (Theta*) join cells by such lines.
//!
//! A line from the centre of one cell to the centre of another crosses the cells its interior
//! enters, each for some length; it costs the sum of those lengths times the cells' costs (the
//! integral of the cost along the line), so a move between neighbours costs exactly what the
//! graph's edge costs. A line may be drawn when every cell it crosses is passable and, where it
//! passes exactly through a corner shared by four cells, the two cells it only touches obey
//! the graph's corner-cutting rule (both passable when corners may not be cut, as for diagonal
//! moves).
//!
//! ```
//! use trailmark_core::{Cell, Connectivity, Grid};
//! use trailmark_graph::GridGraph;
//!
//! let mut grid = Grid::from_rows(&["....", "..@.", "...."])?;
//! grid.set_cost(Cell::new(1, 0), 3.0)?;
//! let graph = GridGraph::new(&grid, Connectivity::Eight);
//! // Along the top row: half of (0, 0) and of (2, 0) at cost 1, all of (1, 0) at cost 3.
//! assert_eq!(graph.line_cost(Cell::new(0, 0), Cell::new(2, 0)), Some(4.0));
//! // Through the wall cell (2, 1).
//! assert_eq!(graph.line_cost(Cell::new(0, 1), Cell::new(3, 1)), None);
//! // Neighbours: the edge cost.
//! assert_eq!(graph.line_cost(Cell::new(0, 0), Cell::new(1, 0)), graph.edge_cost(Cell::new(0, 0), Cell::new(1, 0)));
//! # Ok::<(), trailmark_core::GridError>(())
//! ```

use trailmark_core::cost::{Cost, euclidean};
use trailmark_core::graph::{Graph, Lines};
use trailmark_core::grid::Cell;

use crate::grid::{CornerCutting, GridGraph};

impl GridGraph {
    /// The cost of the straight line from the centre of `from` to the centre of `to`, or `None`
    /// when it is blocked (or either cell is not a node).
    pub fn line_cost(&self, from: Cell, to: Cell) -> Option<Cost> {
        self.line_cost_within(from, to, f64::INFINITY)
    }

    /// [`GridGraph::line_cost`], or `None` as soon as the cells crossed so far cost more than
    /// `budget` (a line the caller would not use: the walk stops there).
    pub fn line_cost_within(&self, from: Cell, to: Cell, budget: Cost) -> Option<Cost> {
        let length = euclidean(from.x.abs_diff(to.x), from.y.abs_diff(to.y));
        // The walk sums fractions of the line: the budget in those units.
        let limit = if length > 0.0 { budget / length } else { f64::INFINITY };
        let mut total = 0.0;
        self.walk_line(from, to, true, |fraction, cost, _| {
            total += fraction * cost;
            total <= limit
        })?;
        Some(total * length)
    }

    /// Whether the straight line from the centre of `from` to the centre of `to` may be drawn.
    pub fn line_of_sight(&self, from: Cell, to: Cell) -> bool {
        self.walk_line(from, to, true, |_, _, _| true).is_some()
    }

    /// The cells the line from `from` to `to` crosses, in order, each with the fraction of the
    /// line inside it; `None` when the line is blocked.
    pub fn line_cells(&self, from: Cell, to: Cell) -> Option<Vec<(Cell, f64)>> {
        let mut cells = Vec::new();
        let stride = self.stride;
        self.walk_line(from, to, false, |fraction, _, i| {
            // Padded index to cell: the border is one cell wide.
            cells.push((Cell::new((i % stride - 1) as u32, (i / stride - 1) as u32), fraction));
            true
        })?;
        Some(cells)
    }

    /// A path of cells shortened by straight lines (string pulling): from each corner, the
    /// farthest of the following cells reached by a clear line that costs no more than the path
    /// it replaces, scanning forward until a line is blocked or dearer. The result starts and
    /// ends where `path` does, every line of it is clear, and it never costs more (by
    /// [`GridGraph::line_cost`]) than `path`. Consecutive cells of `path` must be joined by
    /// clear lines (a path of this graph's moves is).
    ///
    /// ```
    /// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
    /// use trailmark_graph::GridGraph;
    /// use trailmark_search::astar;
    ///
    /// let graph = GridGraph::new(&Grid::from_rows(&["......", "......", "......"])?, Connectivity::Eight);
    /// let goal = Cell::new(5, 2);
    /// let found = astar(&graph, Cell::new(0, 0), goal, graph.heuristic(GridHeuristic::Octile, goal))?;
    /// let path = found.path.expect("reachable").nodes;
    /// assert_eq!(graph.shortcut(&path), [Cell::new(0, 0), goal]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn shortcut(&self, path: &[Cell]) -> Vec<Cell> {
        if path.len() <= 2 {
            return path.to_vec();
        }
        // The cost along the path up to each cell.
        let mut along = Vec::with_capacity(path.len());
        along.push(0.0);
        for pair in path.windows(2) {
            let step = self.line_cost(pair[0], pair[1]).unwrap_or(f64::INFINITY);
            along.push(along.last().copied().unwrap_or(0.0) + step);
        }
        let mut out = vec![path[0]];
        let mut i = 0;
        while i + 1 < path.len() {
            let mut reach = i + 1;
            for j in i + 2..path.len() {
                let slack = 1e-12 * along[j].max(1.0);
                match self.line_cost(path[i], path[j]) {
                    Some(c) if c <= along[j] - along[i] + slack => reach = j,
                    _ => break,
                }
            }
            out.push(path[reach]);
            i = reach;
        }
        out
    }

    /// Walks the line from the centre of `from` to the centre of `to`, calling `visit(fraction,
    /// cost, padded index)` for each crossed cell with the fraction of the line in it; `None` as
    /// soon as the line is blocked or `visit` answers `false`. With `skip`, a stretch of the
    /// line inside a square of open cells of one cost (`squares.rs`) is visited once, at the
    /// index where it starts: the sum of fractions times costs is the same (up to rounding), the
    /// cells are not listed.
    fn walk_line(
        &self,
        from: Cell,
        to: Cell,
        skip: bool,
        mut visit: impl FnMut(f64, Cost, usize) -> bool,
    ) -> Option<()> {
        if !self.contains(from) || !self.contains(to) {
            return None;
        }
        let (adx, ady) = (u64::from(from.x.abs_diff(to.x)), u64::from(from.y.abs_diff(to.y)));
        if adx == 0 && ady == 0 {
            let cost = self.costs.as_ref().map_or(1.0, |c| c[self.index(from)]);
            return visit(1.0, cost, self.index(from)).then_some(());
        }
        let squares = skip.then(|| self.squares());
        let stride = self.stride as isize;
        let step_x: isize = if to.x >= from.x { 1 } else { -1 };
        let step_y: isize = if to.y >= from.y { stride } else { -stride };
        let mut i = self.index(from) as isize;
        let cost_at = |i: isize| self.costs.as_ref().map_or(1.0, |c| c[i as usize]);
        // Crossings of vertical grid lines happen at t = (2 kx + 1) / (2 adx), of horizontal
        // ones at (2 ky + 1) / (2 ady); they are compared exactly in integers.
        let (mut kx, mut ky) = (0u64, 0u64);
        let mut t_prev = 0.0;
        while kx < adx || ky < ady {
            if let Some(squares) = squares
                && let Some((nkx, nky)) = across_square(squares[i as usize], (kx, ky), (adx, ady))
            {
                let t = crossing_time(nkx, adx).max(crossing_time(nky, ady));
                if !visit(t - t_prev, cost_at(i), i as usize) {
                    return None;
                }
                t_prev = t;
                i += (nkx - kx) as isize * step_x + (nky - ky) as isize * step_y;
                (kx, ky) = (nkx, nky);
                continue;
            }
            let x_first = ky == ady || (kx < adx && (2 * kx + 1) * ady < (2 * ky + 1) * adx);
            let y_first = kx == adx || (ky < ady && (2 * ky + 1) * adx < (2 * kx + 1) * ady);
            let t = if x_first {
                (2 * kx + 1) as f64 / (2 * adx) as f64
            } else {
                (2 * ky + 1) as f64 / (2 * ady) as f64
            };
            if !visit(t - t_prev, cost_at(i), i as usize) {
                return None;
            }
            t_prev = t;
            if x_first {
                i += step_x;
                kx += 1;
            } else if y_first {
                i += step_y;
                ky += 1;
            } else {
                // Exactly through a corner: the two cells beside it are only touched.
                let (a, b) = (self.open[(i + step_x) as usize], self.open[(i + step_y) as usize]);
                let allowed = match self.corner_cutting {
                    CornerCutting::Forbidden => a && b,
                    CornerCutting::Allowed => a || b,
                    CornerCutting::Squeeze => true,
                };
                if !allowed {
                    return None;
                }
                i += step_x + step_y;
                kx += 1;
                ky += 1;
            }
            if !self.open[i as usize] {
                return None;
            }
        }
        visit(1.0 - t_prev, cost_at(i), i as usize).then_some(())
    }
}

/// The time, as a fraction of the line, of the last of the first `k` crossings of grid lines
/// of one direction (of `a` in all): 0 before the first.
#[inline]
fn crossing_time(k: u64, a: u64) -> f64 {
    if k == 0 { 0.0 } else { (2 * k - 1) as f64 / (2 * a) as f64 }
}

/// How many crossings of the other direction (of `other` in all) come strictly before
/// crossing `k` of this one (of `this` in all, `k < this`).
#[inline]
fn before(k: u64, this: u64, other: u64) -> u64 {
    let at = (2 * k + 1) * other;
    if at <= this { 0 } else { ((at - this - 1) / (2 * this) + 1).min(other) }
}

/// Where the line, having made `(kx, ky)` of its `(adx, ady)` crossings and standing in a cell
/// `reach` from the nearest edge cell, leaves the square of radius `reach` around that cell:
/// the crossings made just before it leaves, `None` for a cell on the edge. Every cell of that
/// square is open at the cell's cost: those within `reach - 1` are not edge cells, and each
/// cell at `reach` is a neighbour of one of them, which is open at the cost of all its
/// neighbours.
#[inline]
fn across_square(reach: u16, (kx, ky): (u64, u64), (adx, ady): (u64, u64)) -> Option<(u64, u64)> {
    if reach == 0 {
        return None;
    }
    let r = u64::from(reach);
    let (xe, ye) = ((kx + r).min(adx), (ky + r).min(ady));
    Some(if xe == adx && ye == ady {
        (adx, ady)
    } else if ye == ady || (xe < adx && (2 * xe + 1) * ady <= (2 * ye + 1) * adx) {
        // Out across a vertical grid line first (or through a corner with a horizontal one).
        (xe, before(xe, adx, ady))
    } else {
        (before(ye, ady, adx), ye)
    })
}

/// The grid's lines for any-angle searches: [`GridGraph::line_cost`], bounded below by the
/// line's length times the cheapest cell cost, and its end cells' costs.
impl Lines<Cell> for GridGraph {
    #[inline]
    fn line_cost(&self, from: Cell, to: Cell) -> Option<Cost> {
        GridGraph::line_cost(self, from, to)
    }

    #[inline]
    fn line_cost_within(&self, from: Cell, to: Cell, budget: Cost) -> Option<Cost> {
        GridGraph::line_cost_within(self, from, to, budget)
    }

    /// The line runs at least half a cell inside each end cell (from the centre to its side), and
    /// the rest at no less than the cheapest cost: on a costmap the ends' costs make the bound
    /// much tighter near obstacles, where most lines start or end.
    #[inline]
    fn line_lower_bound(&self, from: Cell, to: Cell) -> Cost {
        let (length, min) = (euclidean(from.x.abs_diff(to.x), from.y.abs_diff(to.y)), self.min_cost());
        match self.costs.as_ref() {
            Some(costs) if length >= 1.0 && self.contains(from) && self.contains(to) => {
                let (a, b) = (costs[self.index(from)], costs[self.index(to)]);
                // Blocked ends (infinite costs) price no line: the plain bound then.
                if a.is_finite() && b.is_finite() {
                    length * min + 0.5 * ((a - min) + (b - min))
                } else {
                    length * min
                }
            }
            _ => length * min,
        }
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;
    use trailmark_core::grid::{Cell, Connectivity, Grid};

    use crate::grid::{CornerCutting, GridGraph};

    /// Grids of rooms: wide open areas of one cost (where lines skip), walls, and patches of a
    /// dearer cost, with two cells to join.
    fn world() -> impl Strategy<Value = (Grid, Cell, Cell, CornerCutting)> {
        (8u32..60, 8u32..60)
            .prop_flat_map(|(w, h)| {
                let rects = proptest::collection::vec((0..w, 0..h, 1u32..12, 1u32..12, 0u8..3), 0..8);
                let rule = prop_oneof![
                    Just(CornerCutting::Forbidden),
                    Just(CornerCutting::Allowed),
                    Just(CornerCutting::Squeeze)
                ];
                (Just((w, h)), rects, 0..w, 0..h, 0..w, 0..h, rule)
            })
            .prop_map(|((w, h), rects, ax, ay, bx, by, rule)| {
                let mut grid = Grid::new(w as usize, h as usize).unwrap();
                for (x, y, rw, rh, kind) in rects {
                    for cy in y..(y + rh).min(h) {
                        for cx in x..(x + rw).min(w) {
                            let cost = [f64::INFINITY, 2.5, 1.0][kind as usize];
                            grid.set_cost(Cell::new(cx, cy), cost).unwrap();
                        }
                    }
                }
                for end in [Cell::new(ax, ay), Cell::new(bx, by)] {
                    grid.set_cost(end, 1.0).unwrap();
                }
                (grid, Cell::new(ax, ay), Cell::new(bx, by), rule)
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        /// A line crossing squares in one step is blocked exactly when the cell-by-cell walk
        /// is, and costs what the cells it lists cost, to rounding.
        #[test]
        fn skipping_squares_changes_nothing((grid, a, b, rule) in world()) {
            let graph = GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
            let cells = graph.line_cells(a, b);
            prop_assert_eq!(graph.line_of_sight(a, b), cells.is_some());
            let length = f64::from(a.x.abs_diff(b.x)).hypot(f64::from(a.y.abs_diff(b.y)));
            let listed = cells.map(|c| length * c.iter().map(|&(cell, f)| f * grid.cost(cell).unwrap()).sum::<f64>());
            match (graph.line_cost(a, b), listed) {
                (Some(x), Some(y)) => prop_assert!((x - y).abs() <= 1e-12 * y.max(1.0), "{} against {}", x, y),
                (x, y) => prop_assert_eq!(x, y),
            }
        }

        /// Pricing within a budget gives the full price, or `None` only for a line dearer than
        /// the budget.
        #[test]
        fn a_budget_only_stops_dearer_lines((grid, a, b, rule) in world(), share in 0.0..1.5f64) {
            let graph = GridGraph::new(&grid, Connectivity::Eight).with_corner_cutting(rule);
            let full = graph.line_cost(a, b);
            let budget = share * full.unwrap_or(10.0);
            match graph.line_cost_within(a, b, budget) {
                Some(c) => prop_assert_eq!(Some(c), full),
                None => prop_assert!(full.is_none_or(|c| c > budget), "{:?} within {}", full, budget),
            }
        }
    }

    /// After a cost changes, lines see it: the squares are made again.
    #[test]
    fn a_changed_cost_is_seen() {
        let grid = Grid::new(40, 40).unwrap();
        let mut graph = GridGraph::new(&grid, Connectivity::Eight);
        let (a, b) = (Cell::new(0, 0), Cell::new(39, 39));
        assert!(graph.line_of_sight(a, b));
        graph.set_cost(Cell::new(20, 20), f64::INFINITY).unwrap();
        assert!(!graph.line_of_sight(a, b));
        graph.set_cost(Cell::new(20, 20), 3.0).unwrap();
        let expected = 39.0 * 2f64.sqrt() * (38.0 + 3.0) / 39.0;
        assert!((graph.line_cost(a, b).unwrap() - expected).abs() < 1e-9);
    }
}
