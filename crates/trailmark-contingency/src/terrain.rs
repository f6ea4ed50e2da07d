//! The terrain: a cost grid, a start, a goal, and choke points that may turn out blocked.
//!
//! A [`Terrain`] is checked where it is made: every choke point has a probability in `[0, 1]`
//! and passable cells inside the grid, no cell belongs to two choke points, two choke points never
//! touch (no move leads from one straight into the other, so every route between them crosses a
//! region), the start and goal are passable cells outside every choke point, and the goal can be
//! reached when every choke point is open.
//!
//! Moves follow the grid graph of `trailmark-graph` without corner cutting: 1 orthogonally,
//! `sqrt(2)` diagonally, times the mean cost of the two cells. A blocked choke point cannot be
//! entered; it does not stop a diagonal move between two cells beside it (a closed bridge is a
//! bridge one may not cross, not a wall).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, Connectivity, Grid, GridError, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::Search;

use crate::view::View;

/// The largest number of choke points a terrain may have (knowledge is kept in 64-bit masks).
pub const MAX_CHOKE_POINTS: usize = 64;

/// A narrow passable region that may turn out blocked: a bridge, a pass, a road through forest.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChokePoint {
    /// A name for plans and pictures ("north bridge"); unique within a terrain.
    pub name: String,
    /// The cells of the choke point: passable, inside the grid.
    pub cells: Vec<Cell>,
    /// The probability that the choke point is blocked, in `[0, 1]`. Choke points are blocked
    /// independently of each other.
    pub probability: f64,
}

/// What was wrong with a terrain.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TerrainError {
    /// The grid itself was wrong (a cost, a size, a cell outside it).
    #[error(transparent)]
    Grid(#[from] GridError),
    /// A choke point's probability of being blocked is not in `[0, 1]` (or is NaN).
    #[error("choke point {name:?}: probability {probability:?} is not in [0, 1]")]
    Probability {
        /// The choke point's name.
        name: String,
        /// The probability given.
        probability: f64,
    },
    /// A choke point has no cells.
    #[error("choke point {name:?} has no cells")]
    EmptyChokePoint {
        /// The choke point's name.
        name: String,
    },
    /// A choke point's cell lies outside the grid.
    #[error("choke point {name:?}: cell {cell} is outside the {width} x {height} grid")]
    ChokeCellOutside {
        /// The choke point's name.
        name: String,
        /// The cell.
        cell: Cell,
        /// The grid width.
        width: u32,
        /// The grid height.
        height: u32,
    },
    /// A choke point's cell is impassable terrain.
    #[error("choke point {name:?}: cell {cell} is impassable")]
    ChokeCellImpassable {
        /// The choke point's name.
        name: String,
        /// The cell.
        cell: Cell,
    },
    /// A cell belongs to two choke points (or twice to one).
    #[error("cell {cell} belongs to choke points {first:?} and {second:?}")]
    ChokePointsOverlap {
        /// The first choke point.
        first: String,
        /// The second (the same name when a choke point lists a cell twice).
        second: String,
        /// The shared cell.
        cell: Cell,
    },
    /// Two choke points touch: a move leads from a cell of one into a cell of the other.
    #[error(
        "choke points {first:?} and {second:?} touch at {from} -> {to}; merge them or leave a cell between"
    )]
    ChokePointsTouch {
        /// The first choke point.
        first: String,
        /// The second.
        second: String,
        /// A cell of the first.
        from: Cell,
        /// A neighbouring cell of the second.
        to: Cell,
    },
    /// Two choke points have the same name.
    #[error("two choke points are named {name:?}")]
    DuplicateName {
        /// The name.
        name: String,
    },
    /// More choke points than [`MAX_CHOKE_POINTS`].
    #[error("{count} choke points; at most {MAX_CHOKE_POINTS} are supported")]
    TooManyChokePoints {
        /// How many were given.
        count: usize,
    },
    /// The start or the goal is outside the grid, impassable, or inside a choke point.
    #[error("the {which} {cell} {reason}")]
    Endpoint {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// The cell.
        cell: Cell,
        /// What is wrong with it.
        reason: String,
    },
    /// The goal cannot be reached from the start even with every choke point open.
    #[error("the goal {goal} cannot be reached from the start {start}, even with every choke point open")]
    Unreachable {
        /// The start.
        start: Cell,
        /// The goal.
        goal: Cell,
    },
    /// A terrain description (JSON) could not be read.
    #[error("terrain description: {0}")]
    Spec(String),
}

/// No choke point: the value of [`Terrain::choke_at`]'s table for ordinary cells.
pub(crate) const NO_CHOKE: u8 = u8::MAX;

/// A checked terrain: grid, connectivity, start, goal and choke points.
#[derive(Debug, Clone)]
pub struct Terrain {
    grid: Grid,
    connectivity: Connectivity,
    start: Cell,
    goal: Cell,
    chokes: Vec<ChokePoint>,
    /// Row-major: the choke point of each cell, or [`NO_CHOKE`].
    choke_of: Vec<u8>,
    /// The grid graph with every choke point open.
    graph: GridGraph,
}

impl Terrain {
    /// Checks and builds a terrain. See the [module documentation](self) for what is checked.
    pub fn new(
        grid: Grid,
        connectivity: Connectivity,
        start: Cell,
        goal: Cell,
        chokes: Vec<ChokePoint>,
    ) -> Result<Self, TerrainError> {
        if chokes.len() > MAX_CHOKE_POINTS {
            return Err(TerrainError::TooManyChokePoints { count: chokes.len() });
        }
        let (w, h) = (grid.width(), grid.height());
        let mut choke_of = vec![NO_CHOKE; grid.len()];
        let mut names = BTreeMap::new();
        for (id, choke) in chokes.iter().enumerate() {
            let name = || choke.name.clone();
            if names.insert(choke.name.as_str(), id).is_some() {
                return Err(TerrainError::DuplicateName { name: name() });
            }
            if !(0.0..=1.0).contains(&choke.probability) {
                return Err(TerrainError::Probability { name: name(), probability: choke.probability });
            }
            if choke.cells.is_empty() {
                return Err(TerrainError::EmptyChokePoint { name: name() });
            }
            for &cell in &choke.cells {
                if !grid.contains(cell) {
                    return Err(TerrainError::ChokeCellOutside { name: name(), cell, width: w, height: h });
                }
                if !grid.is_passable(cell) {
                    return Err(TerrainError::ChokeCellImpassable { name: name(), cell });
                }
                let slot = &mut choke_of[cell.y as usize * w as usize + cell.x as usize];
                if *slot != NO_CHOKE {
                    return Err(TerrainError::ChokePointsOverlap {
                        first: chokes[*slot as usize].name.clone(),
                        second: name(),
                        cell,
                    });
                }
                *slot = id as u8;
            }
        }
        let graph = GridGraph::new(&grid, connectivity);
        let terrain = Terrain { grid, connectivity, start, goal, chokes, choke_of, graph };
        for (id, choke) in terrain.chokes.iter().enumerate() {
            for &from in &choke.cells {
                let mut touch = None;
                terrain.graph.neighbours(from).for_each(|(to, _)| {
                    if let Some(other) = terrain.choke_at(to).filter(|&o| o != id) {
                        touch.get_or_insert((other, to));
                    }
                });
                if let Some((other, to)) = touch {
                    return Err(TerrainError::ChokePointsTouch {
                        first: choke.name.clone(),
                        second: terrain.chokes[other].name.clone(),
                        from,
                        to,
                    });
                }
            }
        }
        for (which, cell) in [("start", start), ("goal", goal)] {
            let reason = if !terrain.grid.contains(cell) {
                Some(format!("is outside the {w} x {h} grid"))
            } else if !terrain.grid.is_passable(cell) {
                Some("is impassable".to_string())
            } else {
                terrain.choke_at(cell).map(|c| format!("lies in choke point {:?}", terrain.chokes[c].name))
            };
            if let Some(reason) = reason {
                return Err(TerrainError::Endpoint { which, cell, reason });
            }
        }
        let all_open = View::new(&terrain.graph, |_| true);
        let mut search = Search::new();
        let found = search
            .astar(
                &all_open,
                start,
                goal,
                terrain.graph.heuristic(GridHeuristic::for_connectivity(connectivity), goal),
            )
            .map_err(|e| TerrainError::Spec(e.to_string()))?;
        if found.path.is_none() {
            return Err(TerrainError::Unreachable { start, goal });
        }
        Ok(terrain)
    }

    /// The cost grid (choke points open).
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The grid graph with every choke point open.
    pub fn graph(&self) -> &GridGraph {
        &self.graph
    }

    /// 4- or 8-connected moves.
    pub fn connectivity(&self) -> Connectivity {
        self.connectivity
    }

    /// Where the vehicle starts.
    pub fn start(&self) -> Cell {
        self.start
    }

    /// Where the vehicle must go.
    pub fn goal(&self) -> Cell {
        self.goal
    }

    /// The choke points, in the order given; a choke point's id is its index here.
    pub fn choke_points(&self) -> &[ChokePoint] {
        &self.chokes
    }

    /// Every choke point, as a bit mask.
    pub fn choke_mask(&self) -> u64 {
        match self.chokes.len() {
            MAX_CHOKE_POINTS => u64::MAX,
            n => (1u64 << n) - 1,
        }
    }

    /// The choke point `cell` belongs to, if any (`None` outside the grid too).
    pub fn choke_at(&self, cell: Cell) -> Option<usize> {
        if !self.grid.contains(cell) {
            return None;
        }
        let c = self.choke_of[cell.y as usize * self.grid.width() as usize + cell.x as usize];
        (c != NO_CHOKE).then_some(c as usize)
    }

    /// The choke points next to `cell`: those with a cell one move away, as a bit mask.
    pub fn chokes_beside(&self, cell: Cell) -> u64 {
        let mut mask = 0;
        if self.grid.is_passable(cell) {
            self.graph.neighbours(cell).for_each(|(n, _)| {
                if let Some(c) = self.choke_at(n) {
                    mask |= 1 << c;
                }
            });
        }
        mask
    }

    /// The same terrain with other choke points (checked again).
    pub fn with_choke_points(self, chokes: Vec<ChokePoint>) -> Result<Self, TerrainError> {
        Terrain::new(self.grid, self.connectivity, self.start, self.goal, chokes)
    }

    /// The cost of following `route` (a sequence of neighbouring cells) in the world where the
    /// choke points of `blocked` (a bit mask) are blocked; `None` if a move is not possible there.
    pub fn route_cost(&self, route: &[Cell], blocked: u64) -> Option<Cost> {
        let mut total = 0.0;
        for pair in route.windows(2) {
            let enter = |c: Cell| self.choke_at(c).is_none_or(|k| blocked & (1 << k) == 0);
            if !enter(pair[0]) || !enter(pair[1]) {
                return None;
            }
            total += self.graph.edge_cost(pair[0], pair[1])?;
        }
        Some(total)
    }
}

/// A grid from rows of terrain characters and a legend (MovingAI characters without one).
///
/// The size is checked against [`Grid::MAX_CELLS`] before anything is allocated, memory grows
/// with the rows given, and every cost must be a valid cell cost (at most
/// [`trailmark_core::grid::MAX_CELL_COST`]).
pub fn grid_from_rows<S: AsRef<str>>(
    rows: &[S],
    legend: Option<&BTreeMap<char, Option<Cost>>>,
) -> Result<Grid, TerrainError> {
    let Some(legend) = legend else {
        return Ok(Grid::from_rows(rows)?);
    };
    let width = rows.first().map_or(0, |r| r.as_ref().chars().count());
    Grid::cell_count(width, rows.len())?;
    // Memory grows with the rows actually given (each is checked before its costs are kept): a
    // long first row and many short ones must not reserve width x rows up front.
    let mut costs = Vec::new();
    for (y, row) in rows.iter().enumerate() {
        let row = row.as_ref();
        if row.chars().count() != width {
            return Err(GridError::RaggedRow { row: y, expected: width, found: row.chars().count() }.into());
        }
        costs.reserve(width);
        for (x, ch) in row.chars().enumerate() {
            match legend.get(&ch) {
                Some(cost) => costs.push(cost.unwrap_or(f64::INFINITY)),
                None => {
                    return Err(TerrainError::Spec(format!(
                        "row {y}, column {x}: {ch:?} is not in the legend"
                    )));
                }
            }
        }
    }
    Ok(Grid::from_costs(width, rows.len(), costs)?)
}
