//! The best-first search over jump points that jump point search and JPS+ share: A* whose
//! successors of a cell are the jump points its caller finds from it, each reached along one
//! line, so the path between two of them is that line's cells.

use std::time::Instant;

use trailmark_core::cost::Cost;
use trailmark_core::grid::Cell;
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::one_shot::SearchResult;
use crate::one_shot::jump_map::{DIRECTIONS, Direction, JumpMap, Spot, direction_index};
use crate::one_shot::key::FKey;
use crate::queue::IndexedHeap;
use crate::stats::SearchStats;

/// No parent: the start.
const ROOT: u32 = u32::MAX;

/// What the search knows of one cell, in one place: a cell met is one cache line read.
#[derive(Debug, Clone, Copy, Default)]
struct Node {
    g: Cost,
    parent: u32,
    /// The query that last reached the cell and whether it closed it (`era - 1`: open; `era`:
    /// closed), shifted left 3 bits above the direction of the jump that reached it (its index
    /// in `DIRECTIONS`).
    stamp: u32,
}

/// Per-cell search state over a [`JumpMap`]'s padded cells, reused across queries.
#[derive(Debug, Clone)]
pub(crate) struct JumpSearch {
    nodes: Vec<Node>,
    era: u32,
    heap: IndexedHeap<FKey>,
    successors: Vec<(usize, Direction)>,
}

impl JumpSearch {
    /// Search state for a map of `cells` padded cells.
    pub(crate) fn new(cells: usize) -> Self {
        JumpSearch {
            nodes: vec![Node::default(); cells],
            era: 0,
            heap: IndexedHeap::with_item_capacity(cells),
            successors: Vec::with_capacity(8),
        }
    }

    /// Bytes held.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.nodes.capacity() * size_of::<Node>() + self.heap.memory_bytes()
    }

    /// The cells the last search expanded, in index order.
    pub(crate) fn expanded(&self, map: &JumpMap) -> Vec<Cell> {
        let closed = self.era;
        let expanded = |i: &usize| self.era > 0 && self.nodes[*i].stamp >> 3 == closed;
        (0..self.nodes.len()).filter(expanded).map(|i| map.cell_of(i)).collect()
    }

    /// A least-cost path from `start` to `goal` on `map`, where `successors(u, arrival, goal,
    /// out)` puts in `out` the jump points found from cell `u`,
    /// reached by a jump whose last move was in direction `arrival` (`None`: the start), towards
    /// the goal, each with the direction of its last move. The path to each is diagonal first,
    /// then straight.
    ///
    /// Errors: a start or goal outside the grid or blocked.
    pub(crate) fn run(
        &mut self,
        map: &JumpMap,
        start: Cell,
        goal: Cell,
        mut successors: impl FnMut(Spot, Option<Direction>, Spot, &mut Vec<(usize, Direction)>),
    ) -> Result<SearchResult<Cell>, SearchError<Cell>> {
        let clock = Instant::now();
        let s = map.index_of(start).ok_or(SearchError::StartNotInGraph(start))?;
        let t = map.index_of(goal).ok_or(SearchError::GoalNotInGraph(goal))?;
        // A new era: stamps below it are of earlier queries. Restarted before it wraps.
        if self.era >= (u32::MAX >> 3) - 2 {
            self.nodes.fill(Node::default());
            self.era = 0;
        }
        self.era += 2;
        let (open, closed) = (self.era - 1, self.era);
        let mut stats = SearchStats::default();
        self.heap.clear();
        let mut found = std::mem::take(&mut self.successors);
        let (tx, ty) = map.xy(t);
        let goal = Spot { index: t, x: tx, y: ty };
        self.nodes[s] = Node { g: 0.0, parent: ROOT, stamp: open << 3 };
        let (sx, sy) = map.xy(s);
        self.heap.push_absent(s, FKey::new(map.octile(sx.abs_diff(tx), sy.abs_diff(ty)), 0.0));
        stats.pushes += 1;
        let mut reached = false;
        while let Some((u, _)) = self.heap.pop() {
            if u == t {
                reached = true;
                break;
            }
            let node = &mut self.nodes[u];
            node.stamp = closed << 3 | (node.stamp & 7);
            let (gu, arrival) =
                (node.g, (node.parent != ROOT).then(|| DIRECTIONS[(node.stamp & 7) as usize]));
            stats.expansions += 1;
            let (ux, uy) = map.xy(u);
            successors(Spot { index: u, x: ux, y: uy }, arrival, goal, &mut found);
            for &(v, d) in &found {
                let (vx, vy) = map.xy(v);
                let gv = gu + map.octile(ux.abs_diff(vx), uy.abs_diff(vy));
                let node = &mut self.nodes[v];
                // The heuristic is consistent: a closed cell's cost is final.
                let seen = node.stamp >> 3 == open;
                if node.stamp >> 3 == closed || (seen && gv >= node.g) {
                    continue;
                }
                *node = Node { g: gv, parent: u as u32, stamp: open << 3 | direction_index(d) as u32 };
                let key = FKey::new(gv + map.octile(vx.abs_diff(tx), vy.abs_diff(ty)), gv);
                if seen {
                    stats.decreases += 1;
                    self.heap.push(v, key);
                } else {
                    self.heap.push_absent(v, key);
                    stats.pushes += 1;
                }
            }
        }
        self.successors = found;
        let path = reached.then(|| self.path_to(map, t));
        stats.elapsed = clock.elapsed();
        Ok(SearchResult { path, stats })
    }

    /// The cells from the start to `t` along the jump points' parents, the path between two
    /// filled in diagonal first, then straight, and the path's cost.
    fn path_to(&self, map: &JumpMap, t: usize) -> Path<Cell> {
        let mut jumps = vec![t];
        while let Some(&last) = jumps.last() {
            match self.nodes[last].parent {
                ROOT => break,
                p => jumps.push(p as usize),
            }
        }
        jumps.reverse();
        let mut nodes = vec![map.cell_of(jumps[0])];
        for pair in jumps.windows(2) {
            let (a, b) = (map.cell_of(pair[0]), map.cell_of(pair[1]));
            let (dx, dy) = (i64::from(b.x) - i64::from(a.x), i64::from(b.y) - i64::from(a.y));
            let diagonal = dx.abs().min(dy.abs());
            let (mut x, mut y) = (i64::from(a.x), i64::from(a.y));
            for k in 0..dx.abs().max(dy.abs()) {
                let along = k < diagonal;
                if along || dx.abs() > dy.abs() {
                    x += dx.signum();
                }
                if along || dy.abs() > dx.abs() {
                    y += dy.signum();
                }
                nodes.push(Cell::new(x as u32, y as u32));
            }
        }
        Path { nodes, cost: self.nodes[t].g }
    }
}
