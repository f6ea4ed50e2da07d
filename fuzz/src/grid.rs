//! Grid worlds: an independent reading of the grid, its moves and their costs, a Dijkstra search
//! and a breadth-first search, and the check of a grid result against them.
//!
//! The rules, from trailmark-core's `grid.rs` and trailmark-graph's `grid.rs`: `.`, `G`, `S` are
//! passable, `@`, `O`, `T`, `W` blocked, a trailing `\r` of a row ignored; a passable cell costs
//! 1 or its entry in `costs` (positive, at most 1e12); a move costs its length (1 orthogonally,
//! `sqrt(2)` diagonally) times the mean of the two cells' costs; a diagonal move needs both
//! orthogonal corners passable, or one with `corner_cutting`.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};
use std::f64::consts::SQRT_2;

use trailmark::solve::{AnytimeSpec, GridSpec, PlannerSpec, ProblemSpec, SolveResult, Status, Waypoint};
use trailmark_core::grid::{Cell, Connectivity};

use crate::close;

/// The relative tolerance of cost comparisons: sums in another order differ by far less.
pub const COST_TOLERANCE: f64 = 1e-9;

/// A grid as this module reads it.
#[derive(Debug, Clone)]
pub struct RefGrid {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Row-major cell costs, `f64::INFINITY` for a blocked cell.
    pub costs: Vec<f64>,
    /// 8-connected (else 4).
    pub eight: bool,
    /// Whether a diagonal move may pass one blocked corner.
    pub corner_cutting: bool,
}

fn passable_char(c: char) -> Option<bool> {
    match c {
        '.' | 'G' | 'S' => Some(true),
        '@' | 'O' | 'T' | 'W' => Some(false),
        _ => None,
    }
}

impl RefGrid {
    /// The grid of an inline-rows world, or why it is not a valid one.
    pub fn from_world(world: &GridSpec) -> Result<RefGrid, String> {
        if world.map.is_some() {
            return Err("a map file".into());
        }
        let rows = world.rows.as_ref().ok_or("no rows")?;
        let trim = |r: &str| r.strip_suffix('\r').unwrap_or(r).to_string();
        let rows: Vec<String> = rows.iter().map(|r| trim(r)).collect();
        let height = rows.len();
        let width = rows.first().map_or(0, |r| r.chars().count());
        if width == 0 || height == 0 {
            return Err("empty".into());
        }
        let mut costs = Vec::with_capacity(width * height);
        for (y, row) in rows.iter().enumerate() {
            if row.chars().count() != width {
                return Err(format!("row {y} is ragged"));
            }
            for c in row.chars() {
                match passable_char(c) {
                    Some(true) => costs.push(1.0),
                    Some(false) => costs.push(f64::INFINITY),
                    None => return Err(format!("unknown cell {c:?}")),
                }
            }
        }
        if let Some(given) = &world.costs {
            if given.len() != height || given.iter().any(|r| r.len() != width) {
                return Err("costs shape".into());
            }
            for (y, row) in given.iter().enumerate() {
                for (x, &c) in row.iter().enumerate() {
                    let slot = &mut costs[y * width + x];
                    if slot.is_finite() {
                        if !(c > 0.0 && c <= 1e12) {
                            return Err(format!("cost {c} of a passable cell"));
                        }
                        *slot = c;
                    } else if !(c.is_finite() && c > 0.0) {
                        return Err(format!("cost {c} of a blocked cell"));
                    }
                }
            }
        }
        Ok(RefGrid {
            width,
            height,
            costs,
            eight: world.connectivity == Connectivity::Eight,
            corner_cutting: world.corner_cutting,
        })
    }

    /// The cost of `(x, y)`: `None` outside the grid, infinite when blocked.
    fn cost(&self, x: i64, y: i64) -> Option<f64> {
        (x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height)
            .then(|| self.costs[y as usize * self.width + x as usize])
    }

    fn open(&self, x: i64, y: i64) -> bool {
        self.cost(x, y).is_some_and(f64::is_finite)
    }

    /// Whether `cell` is inside the grid and passable.
    pub fn is_open(&self, cell: Cell) -> bool {
        self.open(cell.x.into(), cell.y.into())
    }

    /// Whether every point of the segment between the centres of `a` and `b`, sampled every
    /// 1/256 of a cell, lies in a passable cell (points on a cell boundary are skipped).
    pub fn line_clear(&self, a: Cell, b: Cell) -> bool {
        let (ax, ay) = (f64::from(a.x) + 0.5, f64::from(a.y) + 0.5);
        let (bx, by) = (f64::from(b.x) + 0.5, f64::from(b.y) + 0.5);
        let n = (((bx - ax).hypot(by - ay)) * 256.0).ceil().max(1.0) as usize;
        (0..=n).all(|k| {
            let t = k as f64 / n as f64;
            let (x, y) = (ax + t * (bx - ax), ay + t * (by - ay));
            x.fract() == 0.0 || y.fract() == 0.0 || self.open(x.floor() as i64, y.floor() as i64)
        })
    }

    /// The cost of the move `a -> b`, `None` unless it is a move of this grid.
    pub fn step_cost(&self, a: Cell, b: Cell) -> Option<f64> {
        let (ax, ay, bx, by) = (i64::from(a.x), i64::from(a.y), i64::from(b.x), i64::from(b.y));
        let (dx, dy) = (bx - ax, by - ay);
        if dx.abs() > 1 || dy.abs() > 1 || (dx == 0 && dy == 0) {
            return None;
        }
        if !self.open(ax, ay) || !self.open(bx, by) {
            return None;
        }
        let diagonal = dx != 0 && dy != 0;
        if diagonal {
            if !self.eight {
                return None;
            }
            let (c1, c2) = (self.open(ax + dx, ay), self.open(ax, ay + dy));
            if !(if self.corner_cutting { c1 || c2 } else { c1 && c2 }) {
                return None;
            }
        }
        let length = if diagonal { SQRT_2 } else { 1.0 };
        Some(length * 0.5 * (self.cost(ax, ay)? + self.cost(bx, by)?))
    }

    fn neighbours(&self, c: Cell) -> impl Iterator<Item = (Cell, f64)> + '_ {
        (-1i64..=1).flat_map(move |dy| (-1i64..=1).map(move |dx| (dx, dy))).filter_map(move |(dx, dy)| {
            let (x, y) = (i64::from(c.x) + dx, i64::from(c.y) + dy);
            if x < 0 || y < 0 || x > i64::from(u32::MAX) || y > i64::from(u32::MAX) {
                return None;
            }
            let n = Cell::new(x as u32, y as u32);
            self.step_cost(c, n).map(|cost| (n, cost))
        })
    }

    fn index(&self, c: Cell) -> usize {
        c.y as usize * self.width + c.x as usize
    }

    /// The least cost from `s` to `g`, `None` when unreachable.
    pub fn dijkstra(&self, s: Cell, g: Cell) -> Option<f64> {
        let mut dist = vec![f64::INFINITY; self.costs.len()];
        let mut heap = BinaryHeap::new();
        dist[self.index(s)] = 0.0;
        // Non-negative floats order as their bit patterns.
        heap.push(Reverse((0f64.to_bits(), s.y, s.x)));
        while let Some(Reverse((bits, y, x))) = heap.pop() {
            let (d, c) = (f64::from_bits(bits), Cell::new(x, y));
            if d > dist[self.index(c)] {
                continue;
            }
            if c == g {
                return Some(d);
            }
            for (n, w) in self.neighbours(c) {
                let nd = d + w;
                let slot = &mut dist[self.index(n)];
                if nd < *slot {
                    *slot = nd;
                    heap.push(Reverse((nd.to_bits(), n.y, n.x)));
                }
            }
        }
        None
    }

    /// The fewest moves from `s` to `g`, `None` when unreachable.
    pub fn bfs_moves(&self, s: Cell, g: Cell) -> Option<usize> {
        let mut seen = vec![usize::MAX; self.costs.len()];
        let mut queue = VecDeque::from([s]);
        seen[self.index(s)] = 0;
        while let Some(c) = queue.pop_front() {
            let d = seen[self.index(c)];
            if c == g {
                return Some(d);
            }
            for (n, _) in self.neighbours(c) {
                let i = self.index(n);
                if seen[i] == usize::MAX {
                    seen[i] = d + 1;
                    queue.push_back(n);
                }
            }
        }
        None
    }
}

/// The cell a problem's start or goal names, by the rule of `solve`: whole numbers in
/// `[0, u32::MAX]`, inside the grid and passable.
pub fn cell_of(value: &[f64], grid: &RefGrid) -> Option<Cell> {
    let whole = |v: f64| v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v);
    let [x, y] = *value else { return None };
    if !whole(x) || !whole(y) {
        return None;
    }
    let cell = Cell::new(x as u32, y as u32);
    grid.is_open(cell).then_some(cell)
}

/// Checks the result of a grid problem that `solve` accepted.
pub fn check_result(problem: &ProblemSpec, world: &GridSpec, result: &SolveResult) {
    let grid = RefGrid::from_world(world)
        .unwrap_or_else(|why| panic!("solve accepted a grid world the reference rejects: {why}"));
    let start = cell_of(&problem.start, &grid)
        .unwrap_or_else(|| panic!("solve accepted the start {:?}, not a passable cell", problem.start));
    let goal = cell_of(&problem.goal, &grid)
        .unwrap_or_else(|| panic!("solve accepted the goal {:?}, not a passable cell", problem.goal));
    let optimum = grid.dijkstra(start, goal);
    let planner = &problem.planner;
    match result.status {
        Status::Solved => {}
        Status::NoPath => {
            assert!(result.path.is_empty() && result.cost.is_none(), "no_path with a path or cost");
            assert!(
                optimum.is_none(),
                "{} said no_path, but the goal is reachable at cost {optimum:?}",
                planner.name()
            );
            return;
        }
        Status::Stopped => {
            assert!(
                matches!(planner, PlannerSpec::AraStar(_) | PlannerSpec::AdStar(_)),
                "{} stopped on a grid",
                planner.name()
            );
            assert!(result.path.is_empty() && result.cost.is_none(), "stopped with a path or cost");
            return;
        }
        Status::Approximate => panic!("{} gave an approximate path on a grid", planner.name()),
    }
    let cells: Vec<Cell> = result
        .path
        .iter()
        .map(|w| match w {
            Waypoint::Cell(c) => *c,
            Waypoint::Point(p) => panic!("a grid path holds the point {p:?}"),
        })
        .collect();
    assert_eq!(cells.first(), Some(&start), "the path does not start at the start");
    assert_eq!(cells.last(), Some(&goal), "the path does not end at the goal");
    let cost = result.cost.expect("a solved result without a cost");
    assert!(cost.is_finite() && cost >= 0.0, "cost {cost}");
    let optimum = optimum.unwrap_or_else(|| panic!("a path was found but the reference finds none"));
    if matches!(planner, PlannerSpec::ThetaStar {}) {
        // Straight lines between cell centres: each clear, and the whole no dearer than the
        // least-cost grid path (Theta* with a consistent heuristic never is).
        for pair in cells.windows(2) {
            assert!(
                grid.line_clear(pair[0], pair[1]),
                "the line {} -> {} crosses a blocked cell",
                pair[0],
                pair[1]
            );
        }
        assert!(
            cost <= optimum * (1.0 + COST_TOLERANCE) + 16.0 * f64::MIN_POSITIVE,
            "theta_star cost {cost} above the least grid cost {optimum}"
        );
        return;
    }
    let mut sum = 0.0;
    for (i, pair) in cells.windows(2).enumerate() {
        let step = grid
            .step_cost(pair[0], pair[1])
            .unwrap_or_else(|| panic!("move {i} {} -> {} is not a move of the grid", pair[0], pair[1]));
        sum += step;
    }
    assert!(close(cost, sum, COST_TOLERANCE), "cost {cost} but the moves sum to {sum}");
    let optimal = || {
        assert!(close(cost, optimum, COST_TOLERANCE), "{} cost {cost}, least cost {optimum}", planner.name())
    };
    match planner {
        PlannerSpec::Dijkstra {}
        | PlannerSpec::AStar { .. }
        | PlannerSpec::LpaStar { .. }
        | PlannerSpec::AdaptiveAStar { .. }
        | PlannerSpec::MpgaaStar { .. }
        | PlannerSpec::DStarLite { .. }
        | PlannerSpec::Jps {}
        | PlannerSpec::JpsPlus {} => optimal(),
        PlannerSpec::Bfs {} => {
            let fewest = grid.bfs_moves(start, goal).expect("reachable");
            assert_eq!(cells.len() - 1, fewest, "bfs path of {} moves, fewest {fewest}", cells.len() - 1);
        }
        PlannerSpec::Dfs {} => {}
        PlannerSpec::WeightedAStar { weight, .. } => {
            assert!(
                cost <= weight * optimum * (1.0 + COST_TOLERANCE) + 16.0 * f64::MIN_POSITIVE,
                "weighted_astar (weight {weight}) cost {cost}, least cost {optimum}"
            );
        }
        PlannerSpec::AraStar(AnytimeSpec { time_limit_s, max_expansions, .. })
        | PlannerSpec::AdStar(AnytimeSpec { time_limit_s, max_expansions, .. }) => {
            if let Some(bound) = result.stats.bound {
                assert!(bound >= 1.0, "bound {bound} below 1");
                assert!(
                    cost <= bound * optimum * (1.0 + COST_TOLERANCE) + 16.0 * f64::MIN_POSITIVE,
                    "{} bound {bound} but cost {cost}, least cost {optimum}",
                    planner.name()
                );
            }
            if time_limit_s.is_none() && max_expansions.is_none() {
                optimal();
            }
        }
        PlannerSpec::Rrt(_)
        | PlannerSpec::RrtConnect(_)
        | PlannerSpec::RrtStar(_)
        | PlannerSpec::InformedRrtStar(_)
        | PlannerSpec::BitStar(_)
        | PlannerSpec::Prm(_)
        | PlannerSpec::PrmStar(_)
        | PlannerSpec::LazyPrm(_)
        | PlannerSpec::LazyPrmStar(_) => {
            panic!("a sampling planner solved a grid problem")
        }
        PlannerSpec::HybridAStar(_) => unreachable!("checked by car::check_result"),
        PlannerSpec::ThetaStar {} => unreachable!("checked above"),
    }
}
