//! Costmaps with Nav2's (costmap_2d's) values: 0 free, 1..=252 the cost of passing, 253 the
//! robot's inscribed radius about an obstacle, 254 lethal, 255 unknown.
//!
//! ```
//! use trailmark_core::grid::Cell;
//! use trailmark_map::{Costmap, CostmapOptions, Footprint, Inflation, MapFrame, OccupancyGrid, TravelCost};
//!
//! // A 9 x 1 corridor of 0.1 m cells with a wall at its left end.
//! let mut values = vec![0i8; 9];
//! values[0] = 100;
//! let map = OccupancyGrid::new(MapFrame::new(9, 1, 0.1, [0.0; 3])?, values)?;
//! let settings = CostmapOptions {
//!     inflation: Some(Inflation { inflation_radius: 0.5, ..Inflation::around(&Footprint::Radius(0.15))? }),
//!     ..CostmapOptions::default()
//! };
//! let costmap = Costmap::from_occupancy(&map, &settings)?;
//! // 252 exp(-10 (d - 0.15)) beyond the inscribed radius: 152.8, 56.2, 20.7, 7.6; none past 0.5 m.
//! assert_eq!(costmap.costs(), &[254, 253, 152, 56, 20, 7, 0, 0, 0]);
//! // Planning cost: lethal and inscribed cells blocked, the rest 1 + 2 x cost / 252.
//! let grid = costmap.to_grid(&TravelCost::default())?;
//! assert!(!grid.is_passable(Cell::new(1, 0)));
//! assert_eq!(grid.cost(Cell::new(6, 0)), Some(1.0));
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use serde::{Deserialize, Serialize};
use trailmark_core::grid::{Cell, Grid};

use crate::distance::NO_SOURCE;
use crate::error::MapError;
use crate::frame::MapFrame;
use crate::inflation::Inflation;
use crate::occupancy::{OccupancyGrid, UNKNOWN};
use crate::values::{FREE_SPACE, INSCRIBED, LETHAL, MAX_NON_OBSTACLE, NO_INFORMATION};

/// What an unknown cell of the map becomes in the costmap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Unknown {
    /// An obstacle (254), inflated like the others. The default: a robot does not drive where
    /// nobody has looked.
    #[default]
    Lethal,
    /// Free space (0).
    Free,
    /// Unknown (255), impassable but not inflated (Nav2's `track_unknown_space`).
    NoInformation,
    /// A cost in 0..=252 (checked).
    Cost(u8),
}

/// How an occupancy grid becomes a costmap (Nav2's static and inflation layers).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CostmapOptions {
    /// What unknown cells become.
    pub unknown: Unknown,
    /// Cells of at least this occupancy are lethal (Nav2's `lethal_cost_threshold`, 100).
    pub lethal_threshold: i8,
    /// Whether cells below the lethal threshold are free (true, Nav2's `trinary_costmap`) or
    /// take `value / lethal_threshold * 254`.
    pub trinary: bool,
    /// The inflation layer, if any.
    pub inflation: Option<Inflation>,
}

impl Default for CostmapOptions {
    /// Unknown cells lethal, lethal at 100, trinary, no inflation.
    fn default() -> Self {
        CostmapOptions { unknown: Unknown::Lethal, lethal_threshold: 100, trinary: true, inflation: None }
    }
}

/// A costmap: a cost in 0..=255 per cell of a [`MapFrame`], row 0 at the top.
#[derive(Debug, Clone, PartialEq)]
pub struct Costmap {
    frame: MapFrame,
    costs: Vec<u8>,
}

impl Costmap {
    /// A costmap from row-major costs, row 0 at the top; one per cell ([`MapError::CellCount`]).
    pub fn new(frame: MapFrame, costs: Vec<u8>) -> Result<Self, MapError> {
        frame.check_count(costs.len())?;
        Ok(Costmap { frame, costs })
    }

    /// The costmap of an occupancy grid: each cell's value as Nav2's static layer reads it,
    /// then the inflation layer.
    pub fn from_occupancy(map: &OccupancyGrid, settings: &CostmapOptions) -> Result<Self, MapError> {
        let unknown = match settings.unknown {
            Unknown::Lethal => LETHAL,
            Unknown::Free => FREE_SPACE,
            Unknown::NoInformation => NO_INFORMATION,
            Unknown::Cost(c) if c <= MAX_NON_OBSTACLE => c,
            Unknown::Cost(c) => {
                return Err(MapError::Setting {
                    setting: "unknown",
                    expected: "a cost of at most 252",
                    value: f64::from(c),
                });
            }
        };
        if !(1..=100).contains(&settings.lethal_threshold) {
            return Err(MapError::Setting {
                setting: "lethal_threshold",
                expected: "an occupancy in 1..=100",
                value: f64::from(settings.lethal_threshold),
            });
        }
        let lethal = settings.lethal_threshold;
        let costs = map
            .values()
            .iter()
            .map(|&v| match v {
                UNKNOWN => unknown,
                v if v >= lethal => LETHAL,
                _ if settings.trinary => FREE_SPACE,
                // Below the threshold, so below 254.
                v => (f64::from(v) / f64::from(lethal) * f64::from(LETHAL)) as u8,
            })
            .collect();
        let mut costmap = Costmap { frame: *map.frame(), costs };
        if let Some(inflation) = &settings.inflation {
            costmap.inflate(inflation)?;
        }
        Ok(costmap)
    }

    /// Inflates the costmap around its lethal cells ([`Inflation`]): each cell takes the larger
    /// of its cost and its inflation cost, except an unknown cell (255), which stays 255 unless
    /// it falls within the inscribed radius (as Nav2's inflation layer with
    /// `inflate_unknown: false`). Distances come from one exact distance transform, a few
    /// operations per cell.
    pub fn inflate(&mut self, inflation: &Inflation) -> Result<(), MapError> {
        inflation.check()?;
        let resolution = self.frame.resolution();
        let d2 = crate::distance::squared_distances(&self.frame, |i| self.costs[i] == LETHAL);
        for (cost, d2) in self.costs.iter_mut().zip(d2) {
            if d2 == 0 || d2 == NO_SOURCE {
                continue;
            }
            let inflated = inflation.cost(f64::from(d2).sqrt(), resolution);
            *cost = match *cost {
                NO_INFORMATION if inflated >= INSCRIBED => inflated,
                NO_INFORMATION => NO_INFORMATION,
                old => old.max(inflated),
            };
        }
        Ok(())
    }

    /// The frame: size, resolution, origin.
    pub fn frame(&self) -> &MapFrame {
        &self.frame
    }

    /// Row-major costs, row 0 at the top.
    pub fn costs(&self) -> &[u8] {
        &self.costs
    }

    /// The cost of `cell`, or `None` outside the map.
    pub fn cost(&self, cell: Cell) -> Option<u8> {
        self.frame.index_of(cell).map(|i| self.costs[i])
    }

    /// The grid every grid planner searches: cells of cost at least `model.blocked_from`
    /// blocked, the others costing `model.multiplier(cost)` per unit length.
    pub fn to_grid(&self, model: &TravelCost) -> Result<Grid, MapError> {
        model.check()?;
        let costs = self.costs.iter().map(|&c| model.multiplier(c)).collect();
        let (w, h) = (self.frame.width() as usize, self.frame.height() as usize);
        Ok(Grid::from_costs(w, h, costs)?)
    }
}

/// The price of travel over a costmap, as Nav2's Smac 2-D planner prices it: a move costs its
/// length times `neutral + factor * cost / 252` (with Smac's `cost_travel_multiplier` as the
/// factor), and cells of cost `blocked_from` and above cannot be entered.
///
/// trailmark's grid graphs charge a move the mean of its two cells' prices (Smac charges the
/// cell moved into), so a path's cost is the same whichever way it is driven.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TravelCost {
    /// The price per cell length of a free cell; positive.
    pub neutral: f64,
    /// How much a cell's cost (over 252) adds; not negative, at most 1e10.
    pub factor: f64,
    /// The first cost that blocks a cell: 253 (inscribed and lethal cells blocked) by default.
    pub blocked_from: u8,
}

impl Default for TravelCost {
    /// Neutral 1, factor 2 (Smac's default `cost_travel_multiplier`), inscribed cells and worse
    /// blocked.
    fn default() -> Self {
        TravelCost { neutral: 1.0, factor: 2.0, blocked_from: INSCRIBED }
    }
}

impl TravelCost {
    /// Checks that `neutral` is positive and finite, `factor` finite and not negative, and
    /// `blocked_from` at least 1 (a map where every cell is blocked is no use).
    pub fn check(&self) -> Result<(), MapError> {
        let bad = |setting, expected, value| Err(MapError::Setting { setting, expected, value });
        if !(self.neutral.is_finite() && self.neutral > 0.0 && self.neutral <= 1e6) {
            return bad("neutral", "a positive number of at most 1e6", self.neutral);
        }
        // 1e10: a document's factor (up to 1e6) times a map's resolution (up to 1e4 m a cell);
        // a cell then costs at most about 1e10 a cell length, far within the grids' cost limit.
        if !(self.factor.is_finite() && self.factor >= 0.0 && self.factor <= 1e10) {
            return bad("factor", "a number in 0..=1e10", self.factor);
        }
        if self.blocked_from == 0 {
            return bad("blocked_from", "a cost of at least 1", 0.0);
        }
        Ok(())
    }

    /// The price per unit length of a cell of `cost`, `f64::INFINITY` when it is blocked.
    pub fn multiplier(&self, cost: u8) -> f64 {
        if cost >= self.blocked_from || cost > MAX_NON_OBSTACLE {
            f64::INFINITY
        } else {
            self.neutral + self.factor * f64::from(cost) / f64::from(MAX_NON_OBSTACLE)
        }
    }
}
