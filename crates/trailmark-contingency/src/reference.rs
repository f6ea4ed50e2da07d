//! The reference solver: the optimal expected cost by exhaustive recursion, every route costed by
//! its own Dijkstra search on the whole grid. No regions, no segments, no estimates, no nesting
//! bound: slow, and meant for tests on small terrains, where [`crate::plan()`] must agree with it.
//!
//! The decision problem is the planner's: the vehicle sees the choke points beside the cell it
//! stops at; it may drive to the goal over choke points known to be open, or to a cell beside
//! choke points it has not seen; an outcome with no route left to the goal ends there.

use std::collections::HashMap;

use trailmark_core::cost::Cost;
use trailmark_core::grid::Cell;
use trailmark_search::Search;

use crate::plan::{Knowledge, outcomes};
use crate::terrain::Terrain;
use crate::view::View;

/// The exhaustive solver's memory of values and routes.
pub struct Reference<'t> {
    terrain: &'t Terrain,
    /// The cells the vehicle may stop at: the goal and the cells beside choke points.
    stops: Vec<Cell>,
    values: HashMap<(Cell, Knowledge), (Cost, Option<Cell>)>,
    distances: HashMap<(Cell, u64), Vec<Cost>>,
    search: Search,
}

impl<'t> Reference<'t> {
    /// A solver for `terrain`.
    pub fn new(terrain: &'t Terrain) -> Self {
        let stops = terrain
            .grid()
            .cells()
            .filter(|&c| {
                c == terrain.goal() || (terrain.choke_at(c).is_none() && terrain.chokes_beside(c) != 0)
            })
            .collect();
        Reference { terrain, stops, values: HashMap::new(), distances: HashMap::new(), search: Search::new() }
    }

    /// The optimal expected cost from the start.
    pub fn expected_cost(&mut self) -> Cost {
        let start = self.terrain.start();
        let seen = self.terrain.chokes_beside(start);
        outcomes(seen, self.terrain)
            .into_iter()
            .map(|(blocked, p)| p * self.value(start, Knowledge::default().after(seen, blocked)).0)
            .sum()
    }

    /// The expected cost of the optimal policy computed the other way round: drive it in every
    /// world (every combination of blocked choke points) and sum the costs weighted by the
    /// worlds' probabilities.
    pub fn expected_cost_by_worlds(&mut self) -> Cost {
        crate::plan::worlds(self.terrain).into_iter().map(|(blocked, p)| p * self.drive(blocked)).sum()
    }

    /// What the optimal policy drives in the world where `blocked` are blocked.
    pub fn drive(&mut self, blocked: u64) -> Cost {
        let mut at = self.terrain.start();
        let mut k = Knowledge::default();
        let mut total = 0.0;
        loop {
            let seen = self.terrain.chokes_beside(at) & k.unknown(self.terrain.choke_mask());
            k = k.after(seen, blocked);
            match self.value(at, k).1 {
                None => return total,
                Some(next) => {
                    total += self.distance(at, k.open(), next);
                    at = next;
                }
            }
        }
    }

    /// The cost of the cheapest grid route from `from` to `to` entering no choke point outside
    /// `crossable`.
    fn distance(&mut self, from: Cell, crossable: u64, to: Cell) -> Cost {
        let i = self.stops.iter().position(|&s| s == to).expect("a stop");
        self.distances_from(from, crossable)[i]
    }

    fn distances_from(&mut self, from: Cell, crossable: u64) -> &[Cost] {
        if !self.distances.contains_key(&(from, crossable)) {
            let terrain = self.terrain;
            let view = View::new(terrain.graph(), |c: Cell| {
                terrain.choke_at(c).is_none_or(|k| crossable & (1 << k) != 0)
            });
            self.search.dijkstra_all(&view, from).expect("the vehicle stands on a passable cell");
            let row =
                self.stops.iter().map(|&s| self.search.cost_to(&view, s).unwrap_or(f64::INFINITY)).collect();
            self.distances.insert((from, crossable), row);
        }
        &self.distances[&(from, crossable)]
    }

    /// The optimal expected cost at `at` with knowledge `k` (everything beside `at` seen), and the
    /// next stop (`None` at the goal or when stuck).
    fn value(&mut self, at: Cell, k: Knowledge) -> (Cost, Option<Cell>) {
        if let Some(&v) = self.values.get(&(at, k)) {
            return v;
        }
        let terrain = self.terrain;
        let all = terrain.choke_mask();
        let goal = terrain.goal();
        let v = if at == goal || !self.distance(at, all & !k.blocked, goal).is_finite() {
            (0.0, None)
        } else {
            let mut best = (self.distance(at, k.open(), goal), Some(goal));
            let unknown = k.unknown(all);
            for i in 0..self.stops.len() {
                let to = self.stops[i];
                let seen = terrain.chokes_beside(to) & unknown;
                let transit = self.distances_from(at, k.open())[i];
                if to == goal || seen == 0 || !transit.is_finite() {
                    continue;
                }
                let mut q = transit;
                for (blocked, p) in outcomes(seen, terrain) {
                    q += p * self.value(to, k.after(seen, blocked)).0;
                }
                if q < best.0 {
                    best = (q, Some(to));
                }
            }
            best
        };
        self.values.insert((at, k), v);
        v
    }
}
