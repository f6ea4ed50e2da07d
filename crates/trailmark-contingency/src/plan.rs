//! Contingency plans: trees of drives and outcomes, their execution and their exact evaluation.
//!
//! A plan starts where the vehicle is. Each [`PlanNode`] either has arrived, is stuck (the goal
//! cannot be reached in this outcome: every route left is blocked), or drives a route to a cell
//! beside choke points whose state it does not know yet. On arrival it sees them, and the plan
//! goes on with the sub-plan of what it saw: one [`Outcome`] per combination of open and blocked.
//! The preferred route is the chain of most likely outcomes; the others are the contingencies.

use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use trailmark_core::cost::Cost;
use trailmark_core::grid::Cell;

use crate::terrain::Terrain;

/// What the knowledge of the choke points is at some point of a plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
pub struct Knowledge {
    /// The choke points whose state is known, as a bit mask.
    pub known: u64,
    /// The choke points known to be blocked (a subset of `known`).
    pub blocked: u64,
}

impl Knowledge {
    /// The choke points known to be open.
    pub fn open(self) -> u64 {
        self.known & !self.blocked
    }

    /// The choke points of `all` whose state is not known.
    pub fn unknown(self, all: u64) -> u64 {
        all & !self.known
    }

    /// After seeing the choke points of `seen`, those of `blocked` blocked.
    pub fn after(self, seen: u64, blocked: u64) -> Knowledge {
        Knowledge { known: self.known | seen, blocked: self.blocked | (blocked & seen) }
    }
}

/// Every combination of open and blocked for the choke points of `seen`, as `(blocked mask,
/// probability)`, leaving out those of probability zero.
pub fn outcomes(seen: u64, terrain: &Terrain) -> Vec<(u64, f64)> {
    let mut all = vec![(0u64, 1.0f64)];
    let mut bits = seen;
    while bits != 0 {
        let c = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let p = terrain.choke_points()[c].probability;
        all = all
            .into_iter()
            .flat_map(|(mask, q)| [(mask, q * (1.0 - p)), (mask | 1 << c, q * p)])
            .filter(|&(_, q)| q > 0.0)
            .collect();
    }
    all
}

/// A point of a plan: where the vehicle is and what it does next.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlanNode {
    /// Where the vehicle is.
    pub at: Cell,
    /// The expected cost from here to the end of the plan.
    pub expected_cost: Cost,
    /// What it does.
    pub action: Action,
}

/// What the vehicle does at a point of a plan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Action {
    /// It is at the goal.
    Arrived,
    /// Every route to the goal is blocked in this outcome: it stops.
    Stuck,
    /// It drives a route, then sees choke points and goes on by what it saw.
    Drive(Drive),
}

/// A drive: a route from one point of the plan to the next, and what may be seen on arrival.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Drive {
    /// Where the route ends.
    pub to: Cell,
    /// The route's cost.
    pub cost: Cost,
    /// The choke points it crosses (all known to be open), by id, in order.
    pub crosses: Vec<usize>,
    /// The choke points seen on arrival whose state was unknown, by id.
    pub sees: Vec<usize>,
    /// Whether this step lies beyond the nesting depth: it follows the cheapest route as if
    /// every unknown choke point were open, replanning on each blockage, rather than a plan
    /// optimised for the outcomes.
    pub replan: bool,
    /// The route's cells, `at` first and `to` last.
    pub route: Vec<Cell>,
    /// One sub-plan per combination of states of `sees` (a single one when it is empty).
    pub outcomes: Vec<Outcome>,
}

/// One combination of states of the choke points seen, and the sub-plan that follows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// Which of the choke points seen are blocked (the others are open), by id.
    pub blocked: Vec<usize>,
    /// The probability of this combination.
    pub probability: f64,
    /// The sub-plan.
    pub next: PlanNode,
}

/// The result of driving a plan in one world.
#[derive(Debug, Clone, PartialEq)]
pub struct Execution {
    /// The cost driven.
    pub cost: Cost,
    /// Whether the vehicle reached the goal (rather than getting stuck).
    pub arrived: bool,
    /// The cells driven, start first.
    pub route: Vec<Cell>,
}

/// A plan that could not be driven in some world: a defect, never expected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExecutionError {
    /// A route entered a blocked choke point or made a move the grid does not have.
    #[error("the route from {from} to {to} cannot be driven in this world")]
    Undrivable {
        /// Where the route starts.
        from: Cell,
        /// Where it ends.
        to: Cell,
    },
    /// No outcome of a drive matches the world.
    #[error("no outcome at {at} matches the world")]
    NoOutcome {
        /// Where.
        at: Cell,
    },
}

impl PlanNode {
    /// Drives the plan in the world where the choke points of `blocked` (a bit mask) are blocked,
    /// re-costing every route on the grid of that world.
    pub fn execute(&self, terrain: &Terrain, blocked: u64) -> Result<Execution, ExecutionError> {
        let mut node = self;
        let mut run = Execution { cost: 0.0, arrived: false, route: vec![self.at] };
        loop {
            match &node.action {
                Action::Arrived => {
                    run.arrived = true;
                    return Ok(run);
                }
                Action::Stuck => return Ok(run),
                Action::Drive(drive) => {
                    let undrivable = || ExecutionError::Undrivable { from: node.at, to: drive.to };
                    run.cost += terrain.route_cost(&drive.route, blocked).ok_or_else(undrivable)?;
                    run.route.extend_from_slice(&drive.route[1..]);
                    let seen: u64 = drive.sees.iter().map(|&c| 1u64 << c).sum();
                    node = drive
                        .outcomes
                        .iter()
                        .find(|o| o.blocked.iter().map(|&c| 1u64 << c).sum::<u64>() == blocked & seen)
                        .map(|o| &o.next)
                        .ok_or(ExecutionError::NoOutcome { at: drive.to })?;
                }
            }
        }
    }

    /// The expected cost of the plan computed from its tree: the sum over its leaves of the
    /// probability of reaching them times the cost of the routes on the way.
    pub fn tree_expected_cost(&self) -> Cost {
        match &self.action {
            Action::Arrived | Action::Stuck => 0.0,
            Action::Drive(d) => {
                d.cost + d.outcomes.iter().map(|o| o.probability * o.next.tree_expected_cost()).sum::<Cost>()
            }
        }
    }

    /// The probability of ending stuck.
    pub fn stuck_probability(&self) -> f64 {
        match &self.action {
            Action::Arrived => 0.0,
            Action::Stuck => 1.0,
            Action::Drive(d) => d.outcomes.iter().map(|o| o.probability * o.next.stuck_probability()).sum(),
        }
    }

    /// The number of points in the plan.
    pub fn size(&self) -> usize {
        1 + match &self.action {
            Action::Drive(d) => d.outcomes.iter().map(|o| o.next.size()).sum(),
            _ => 0,
        }
    }

    /// The deepest nesting of contingencies: the most blockages on one branch.
    pub fn depth(&self) -> usize {
        match &self.action {
            Action::Drive(d) => {
                d.outcomes.iter().map(|o| o.blocked.len() + o.next.depth()).max().unwrap_or(0)
            }
            _ => 0,
        }
    }

    /// The preferred route: the cells driven when every choke point seen is open (or, where a
    /// drive has no such outcome, its most likely one).
    pub fn preferred_route(&self) -> Vec<Cell> {
        let mut cells = vec![self.at];
        let mut node = self;
        while let Action::Drive(d) = &node.action {
            cells.extend_from_slice(&d.route[1..]);
            let Some(next) = d
                .outcomes
                .iter()
                .find(|o| o.blocked.is_empty())
                .or_else(|| d.outcomes.iter().max_by(|a, b| a.probability.total_cmp(&b.probability)))
            else {
                break;
            };
            node = &next.next;
        }
        cells
    }

    /// The plan as readable JSON: choke points by name, routes left out (their ends and costs
    /// stay).
    pub fn to_json(&self, terrain: &Terrain) -> Value {
        let names = |ids: &[usize]| -> Vec<&str> {
            ids.iter().map(|&c| terrain.choke_points()[c].name.as_str()).collect()
        };
        let at = [self.at.x, self.at.y];
        match &self.action {
            Action::Arrived => json!({"at": at, "arrived": true}),
            Action::Stuck => json!({"at": at, "stuck": "every route to the goal is blocked"}),
            Action::Drive(d) => {
                let mut drive = json!({"to": [d.to.x, d.to.y], "cost": d.cost});
                if !d.crosses.is_empty() {
                    drive["crosses"] = json!(names(&d.crosses));
                }
                if d.replan {
                    drive["replan"] = json!(true);
                }
                let mut node = json!({"at": at, "expected_cost": self.expected_cost, "drive": drive});
                if !d.sees.is_empty() {
                    node["sees"] = json!(names(&d.sees));
                    node["outcomes"] = d
                        .outcomes
                        .iter()
                        .map(|o| {
                            let open: Vec<usize> =
                                d.sees.iter().copied().filter(|c| !o.blocked.contains(c)).collect();
                            json!({
                                "open": names(&open),
                                "blocked": names(&o.blocked),
                                "probability": o.probability,
                                "then": o.next.to_json(terrain),
                            })
                        })
                        .collect();
                } else if let Some(o) = d.outcomes.first() {
                    node["then"] = o.next.to_json(terrain);
                }
                node
            }
        }
    }
}

/// Every world of a terrain with its probability: each combination of blocked choke points, as
/// `(blocked mask, probability)`, leaving out those of probability zero. There are up to
/// `2^choke points` of them.
pub fn worlds(terrain: &Terrain) -> Vec<(u64, f64)> {
    outcomes(terrain.choke_mask(), terrain)
}
