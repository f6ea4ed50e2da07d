//! The map that jump point search runs on: a grid's passable cells, padded with a blocked border,
//! in two forms (a byte per cell for single steps, and bit rows for scanning 64 cells per word,
//! Harabor and Grastien, ICAPS 2014), with the rule for diagonal moves, the pruning rules and the
//! jumps.
//!
//! Cells are addressed by padded coordinates `(px, py) = (x + 1, y + 1)`, or by the padded index
//! `py * stride + px`. A straight scan runs in one of four frames, each the map turned so that the
//! scan runs towards increasing bit positions: east as stored, west mirrored, south and north
//! transposed (and mirrored). In a frame a scan runs along a lane; the lanes on either side are the
//! cells beside the scan.

use std::f64::consts::SQRT_2;

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, CornerCutting, Grid};

use crate::error::SearchError;

/// A direction of travel `(dx, dy)`, each -1, 0 or 1.
pub(crate) type Direction = (isize, isize);

/// The eight directions; a table's entries are in this order.
pub(crate) const DIRECTIONS: [Direction; 8] =
    [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)];

/// The position of a direction in [`DIRECTIONS`].
#[inline]
pub(crate) fn direction_index((dx, dy): Direction) -> usize {
    match (dx, dy) {
        (1, 0) => 0,
        (-1, 0) => 1,
        (0, 1) => 2,
        (0, -1) => 3,
        (1, 1) => 4,
        (1, -1) => 5,
        (-1, 1) => 6,
        _ => 7,
    }
}

/// A frame of bit rows: lane `l`'s position `p` is bit `p % 64` of word `l * words + p / 64`.
/// Made with a bit set per passable cell, then turned into stops (see [`Frame::into_stops`]).
#[derive(Debug, Clone)]
struct Frame {
    words: usize,
    bits: Vec<u64>,
}

impl Frame {
    fn new(lanes: usize, positions: usize) -> Self {
        let words = positions.div_ceil(64);
        Frame { words, bits: vec![0; lanes * words] }
    }

    fn set(&mut self, lane: usize, pos: usize) {
        self.bits[lane * self.words + pos / 64] |= 1 << (pos % 64);
    }

    fn lane(&self, lane: usize) -> &[u64] {
        &self.bits[lane * self.words..(lane + 1) * self.words]
    }

    /// The frame of stops of this frame of passable cells under `rule`: a bit set where a scan
    /// along the lane ends, at a blocked cell or at a cell with a forced neighbour (whatever the
    /// scan's start: forced neighbours depend only on the lanes beside). The first and last
    /// lanes, never scanned, stop everywhere.
    fn into_stops(self, rule: CornerCutting) -> Frame {
        let lanes = self.bits.len() / self.words;
        let mut stops = vec![!0u64; self.bits.len()];
        for lane in 1..lanes.saturating_sub(1) {
            let (a, r, b) = (self.lane(lane - 1), self.lane(lane), self.lane(lane + 1));
            for w in 0..self.words {
                let forced = match rule {
                    // A side cell free with the one before it blocked.
                    CornerCutting::Forbidden => {
                        let before = |s: &[u64]| (s[w] << 1) | if w > 0 { s[w - 1] >> 63 } else { 0 };
                        (a[w] & !before(a)) | (b[w] & !before(b))
                    }
                    // A side cell blocked with the one after it free.
                    _ => {
                        let after =
                            |s: &[u64]| (s[w] >> 1) | if w + 1 < self.words { s[w + 1] << 63 } else { 0 };
                        (!a[w] & after(a)) | (!b[w] & after(b))
                    }
                };
                stops[lane * self.words + w] = forced | !r[w];
            }
        }
        Frame { words: self.words, bits: stops }
    }
}

/// A cell by its padded index and coordinates (a jump's start, a query's goal).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Spot {
    pub(crate) index: usize,
    pub(crate) x: usize,
    pub(crate) y: usize,
}

/// A grid's passable cells and its rule for diagonal moves, made for jump point search.
#[derive(Debug, Clone)]
pub(crate) struct JumpMap {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) rule: CornerCutting,
    /// The padded width: a blocked column on either side.
    pub(crate) stride: usize,
    /// `ceil(2^64 / stride)`: an index's row is the high half of its product with this, which
    /// is exact for indices and strides below 2^32 (Lemire, Kaser and Kurz 2019) and spares a
    /// division.
    magic: u64,
    /// Per padded cell: whether it is passable (the border never is).
    pub(crate) free: Vec<bool>,
    /// The cost of every passable cell: a move costs its length times it.
    pub(crate) cost: Cost,
    /// The stops of the straight scans east, west, south (+y) and north (-y).
    frames: [Frame; 4],
}

impl JumpMap {
    /// The map of `grid` under `rule`.
    ///
    /// Errors: passable cells that do not all cost the same ([`SearchError::NonUniformCost`]).
    pub(crate) fn new(grid: &Grid, rule: CornerCutting) -> Result<Self, SearchError<Cell>> {
        let (width, height) = (grid.width(), grid.height());
        let (w, h) = (width as usize, height as usize);
        let stride = w + 2;
        let mut free = vec![false; stride * (h + 2)];
        let mut frames = [
            Frame::new(h + 2, w + 2),
            Frame::new(h + 2, w + 2),
            Frame::new(w + 2, h + 2),
            Frame::new(w + 2, h + 2),
        ];
        let mut cost = None;
        for (k, &c) in grid.costs().iter().enumerate() {
            if !c.is_finite() {
                continue;
            }
            let (x, y) = (k % w, k / w);
            match cost {
                None => cost = Some(c),
                Some(expected) if expected != c => {
                    let cell = Cell::new(x as u32, y as u32);
                    return Err(SearchError::NonUniformCost { cell, cost: c, expected });
                }
                Some(_) => {}
            }
            let (px, py) = (x + 1, y + 1);
            free[py * stride + px] = true;
            frames[0].set(py, px);
            frames[1].set(py, w + 1 - px);
            frames[2].set(px, py);
            frames[3].set(px, h + 1 - py);
        }
        let magic = u64::MAX / stride as u64 + 1;
        let frames = frames.map(|f| f.into_stops(rule));
        Ok(JumpMap { width, height, rule, stride, magic, free, cost: cost.unwrap_or(1.0), frames })
    }

    /// Bytes held by the map.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.free.len() + self.frames.iter().map(|f| f.bits.len() * 8).sum::<usize>()
    }

    /// The padded index of `cell`, if it is a passable cell of the grid.
    pub(crate) fn index_of(&self, cell: Cell) -> Option<usize> {
        let inside = cell.x < self.width && cell.y < self.height;
        let i = (cell.y as usize + 1) * self.stride + cell.x as usize + 1;
        (inside && self.free[i]).then_some(i)
    }

    pub(crate) fn cell_of(&self, i: usize) -> Cell {
        let (x, y) = self.xy(i);
        Cell::new((x - 1) as u32, (y - 1) as u32)
    }

    /// The padded coordinates of index `i`.
    #[inline]
    pub(crate) fn xy(&self, i: usize) -> (usize, usize) {
        let y = ((u128::from(self.magic) * i as u128) >> 64) as usize;
        (i - y * self.stride, y)
    }

    /// The index `(dx, dy)` from `i`.
    #[inline]
    pub(crate) fn step(&self, i: usize, (dx, dy): Direction) -> usize {
        i.wrapping_add_signed(dy * self.stride as isize + dx)
    }

    #[inline]
    pub(crate) fn open(&self, i: usize, dx: isize, dy: isize) -> bool {
        self.free[self.step(i, (dx, dy))]
    }

    /// Whether the move from `i` by `(dx, dy)` is allowed: the target passable and, for a
    /// diagonal, the cells beside it as the rule asks.
    #[inline]
    pub(crate) fn can_move(&self, i: usize, dx: isize, dy: isize) -> bool {
        self.open(i, dx, dy)
            && (dx == 0
                || dy == 0
                || match self.rule {
                    CornerCutting::Forbidden => self.open(i, dx, 0) && self.open(i, 0, dy),
                    CornerCutting::Allowed => self.open(i, dx, 0) || self.open(i, 0, dy),
                    CornerCutting::Squeeze => true,
                })
    }

    /// The turns that may be forced at a cell reached by the diagonal move `(dx, dy)`: each the
    /// cell behind it on one side, and the diagonal past that cell.
    #[inline]
    fn diagonal_turns((dx, dy): Direction) -> [(Direction, Direction); 2] {
        [((-dx, 0), (-dx, dy)), ((0, -dy), (dx, -dy))]
    }

    /// Whether the turn past the cell `behind` of cell `i` is forced: that cell blocked and the
    /// turn's cell free (never with no corner cutting, where the parent could not have passed
    /// the blocked cell).
    #[inline]
    fn forced_turn(&self, i: usize, (bx, by): Direction, (tx, ty): Direction) -> bool {
        self.rule != CornerCutting::Forbidden && !self.open(i, bx, by) && self.open(i, tx, ty)
    }

    /// Whether cell `i`, reached by the diagonal move `(dx, dy)`, has a forced neighbour.
    #[inline]
    pub(crate) fn forced_diagonal(&self, i: usize, dx: isize, dy: isize) -> bool {
        Self::diagonal_turns((dx, dy)).iter().any(|&(behind, turn)| self.forced_turn(i, behind, turn))
    }

    /// The two sides of the straight move `(dx, dy)`.
    #[inline]
    fn sides((dx, dy): Direction) -> [Direction; 2] {
        let (sx, sy) = (dy.abs(), dx.abs());
        [(sx, sy), (-sx, -sy)]
    }

    /// Whether the side `(ax, ay)` of cell `i`, reached by the straight move `(dx, dy)`, is
    /// forced.
    ///
    /// With no corner cutting, the side cell free with its neighbour beside the parent blocked
    /// (the parent could not reach it diagonally); with corner cutting, the side cell blocked
    /// with the cell ahead of it free (the diagonal around it starts here).
    #[inline]
    fn forced_side(&self, i: usize, (ax, ay): Direction, (dx, dy): Direction) -> bool {
        match self.rule {
            CornerCutting::Forbidden => self.open(i, ax, ay) && !self.open(i, ax - dx, ay - dy),
            _ => !self.open(i, ax, ay) && self.open(i, ax + dx, ay + dy),
        }
    }

    /// Whether cell `i`, reached by the straight move `(dx, dy)`, has a forced neighbour.
    #[inline]
    pub(crate) fn forced_straight(&self, i: usize, dx: isize, dy: isize) -> bool {
        Self::sides((dx, dy)).iter().any(|&side| self.forced_side(i, side, (dx, dy)))
    }

    /// The directions to jump in from cell `i`, reached by a move in direction `arrival`
    /// (`None` at the start): the natural ones and the forced ones, each a move that may be
    /// blocked (the jump checks it).
    pub(crate) fn directions(&self, i: usize, arrival: Option<Direction>, out: &mut Vec<Direction>) {
        out.clear();
        let Some((dx, dy)) = arrival else {
            out.extend(DIRECTIONS);
            return;
        };
        if dx != 0 && dy != 0 {
            out.extend([(dx, 0), (0, dy), (dx, dy)]);
            for (behind, turn) in Self::diagonal_turns((dx, dy)) {
                if self.forced_turn(i, behind, turn) {
                    out.push(turn);
                }
            }
            return;
        }
        out.push((dx, dy));
        for (ax, ay) in Self::sides((dx, dy)) {
            if self.forced_side(i, (ax, ay), (dx, dy)) {
                // With no corner cutting the side cell itself is forced too.
                if self.rule == CornerCutting::Forbidden {
                    out.push((ax, ay));
                }
                out.push((ax + dx, ay + dy));
            }
        }
    }

    /// Puts in `out` the jump points reached from `from` moving by `d`, each with the direction
    /// of its last move.
    ///
    /// A straight jump ends at the goal or at a cell with a forced neighbour. A diagonal jump
    /// does not stop where a straight jump from it finds something (as the 2011 algorithm does,
    /// to expand that cell later): it gives what the straight jumps found at once and goes on,
    /// which is what expanding the cell would have done (Harabor and Grastien 2014). It stops at
    /// the goal and at a cell with a forced neighbour of its own, which it gives. The path to each
    /// is diagonal first, then straight.
    #[inline]
    pub(crate) fn jump(&self, from: Spot, d: Direction, goal: Spot, out: &mut Vec<(usize, Direction)>) {
        let Spot { index: mut i, mut x, mut y } = from;
        let (dx, dy) = d;
        if dx == 0 || dy == 0 {
            out.extend(self.jump_straight((x, y), d, goal).map(|v| (v, d)));
            return;
        }
        while self.can_move(i, dx, dy) {
            i = self.step(i, d);
            (x, y) = (x.wrapping_add_signed(dx), y.wrapping_add_signed(dy));
            if i == goal.index || self.forced_diagonal(i, dx, dy) {
                out.push((i, d));
                return;
            }
            out.extend(self.jump_straight((x, y), (dx, 0), goal).map(|v| (v, (dx, 0))));
            out.extend(self.jump_straight((x, y), (0, dy), goal).map(|v| (v, (0, dy))));
        }
    }

    /// The straight jump from the cell at `(x, y)` by `d`: a scan of the frame for that
    /// direction, which ends at a jump point when the cell it stops at is passable.
    #[inline]
    fn jump_straight(&self, (x, y): (usize, usize), d: Direction, goal: Spot) -> Option<usize> {
        let (w1, h1) = (self.width as usize + 1, self.height as usize + 1);
        let i = match d {
            (1, 0) => {
                let ahead = (goal.y == y && goal.x > x).then_some(goal.x);
                y * self.stride + scan(&self.frames[0], y, x, ahead)
            }
            (-1, 0) => {
                let ahead = (goal.y == y && goal.x < x).then_some(w1 - goal.x);
                y * self.stride + w1 - scan(&self.frames[1], y, w1 - x, ahead)
            }
            (0, 1) => {
                let ahead = (goal.x == x && goal.y > y).then_some(goal.y);
                scan(&self.frames[2], x, y, ahead) * self.stride + x
            }
            _ => {
                let ahead = (goal.x == x && goal.y < y).then_some(h1 - goal.y);
                (h1 - scan(&self.frames[3], x, h1 - y, ahead)) * self.stride + x
            }
        };
        self.free[i].then_some(i)
    }

    /// The length of a path of `dx` and `dy` cells across (straight moves, then diagonal) times
    /// the cell cost.
    #[inline]
    pub(crate) fn octile(&self, dx: usize, dy: usize) -> Cost {
        let (dx, dy) = (dx as f64, dy as f64);
        (dx.max(dy) + (SQRT_2 - 1.0) * dx.min(dy)) * self.cost
    }
}

/// The first stop after position `pos` along `lane` of `frame`, or the goal's position `goal`
/// (given only when it is ahead on this lane) if it comes first. Reads a word (64 cells) at a
/// time; the blocked border past the map ends every scan within the lane.
#[inline]
fn scan(frame: &Frame, lane: usize, pos: usize, goal: Option<usize>) -> usize {
    let stops = frame.lane(lane);
    let mut w = pos / 64;
    // Positions after `pos` only.
    let mut ahead = !1u64 << (pos % 64);
    loop {
        let mut stop = stops[w] & ahead;
        if let Some(g) = goal
            && g / 64 == w
        {
            stop |= 1 << (g % 64);
        }
        if stop != 0 {
            return w * 64 + stop.trailing_zeros() as usize;
        }
        w += 1;
        ahead = !0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The straight jump one cell at a time, as the 2011 paper gives it.
    fn step_by_step(map: &JumpMap, mut i: usize, (dx, dy): Direction, goal: Spot) -> Option<usize> {
        loop {
            if !map.can_move(i, dx, dy) {
                return None;
            }
            i = map.step(i, (dx, dy));
            if i == goal.index || map.forced_straight(i, dx, dy) {
                return Some(i);
            }
        }
    }

    #[test]
    fn coordinates_by_multiplication_match_division() {
        for w in 1..80 {
            let map = JumpMap::new(&Grid::new(w, 3).unwrap(), CornerCutting::Forbidden).unwrap();
            for i in 0..map.free.len() {
                assert_eq!(map.xy(i), (i % map.stride, i / map.stride), "width {w}, index {i}");
            }
        }
    }

    /// Every straight scan, from every passable cell in every direction towards a few goals,
    /// agrees with the step-by-step jump, on maps wide and tall enough to cross words.
    #[test]
    fn scans_agree_with_single_steps() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for (w, h, density) in
            [(1, 1, 0.0), (63, 3, 0.3), (64, 65, 0.2), (65, 64, 0.05), (130, 129, 0.1), (200, 7, 0.4)]
        {
            let mut grid = Grid::new(w, h).unwrap();
            for cell in grid.cells().collect::<Vec<_>>() {
                let blocked = (next() >> 11) as f64 / (1u64 << 53) as f64 <= density;
                grid.set_blocked(cell, blocked).unwrap();
            }
            for rule in [CornerCutting::Forbidden, CornerCutting::Allowed, CornerCutting::Squeeze] {
                let map = JumpMap::new(&grid, rule).unwrap();
                let free: Vec<usize> = (0..map.free.len()).filter(|&i| map.free[i]).collect();
                if free.is_empty() {
                    continue;
                }
                let goals: Vec<Spot> = (0..4)
                    .map(|_| {
                        let index = free[next() as usize % free.len()];
                        let (x, y) = map.xy(index);
                        Spot { index, x, y }
                    })
                    .collect();
                for &i in &free {
                    for d in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
                        for &goal in &goals {
                            assert_eq!(
                                map.jump_straight(map.xy(i), d, goal),
                                step_by_step(&map, i, d, goal),
                                "{w} x {h} {rule:?}: from {:?} by {d:?} to {:?}",
                                map.cell_of(i),
                                map.cell_of(goal.index)
                            );
                        }
                    }
                }
            }
        }
    }
}
