//! Monte Carlo over blockage outcomes: driving a contingency plan against following the shortest
//! path and replanning with D* Lite.
//!
//! Each sample draws a world (each choke point blocked with its probability, independently),
//! then drives both strategies in it on the grid:
//!
//! - the plan: its routes, cell by cell, re-costed on the grid of that world (a route that would
//!   enter a blocked choke point is an error, never expected), taking at each point the
//!   sub-plan of what was seen;
//! - naive replanning: D* Lite on the grid with every unseen choke point taken as open; at every
//!   cell the vehicle sees the choke points beside it, and when one is blocked D* Lite is told
//!   and repairs its path. It stops when no route to the goal is left.
//!
//! Both see a choke point from any cell beside it, so neither knows more than the other.

use std::cell::Cell as Shared;
use std::collections::HashMap;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use trailmark_core::cost::Cost;
use trailmark_core::grid::GridHeuristic;
use trailmark_search::{DStarLite, SearchError};

use crate::plan::{Execution, ExecutionError, PlanNode, outcomes};
use crate::terrain::Terrain;
use crate::view::View;

/// Why a simulation failed: a defect, never expected.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SimulationError {
    /// The plan could not be driven.
    #[error(transparent)]
    Plan(#[from] ExecutionError),
    /// D* Lite refused a query.
    #[error("D* Lite: {0}")]
    Search(String),
    /// Naive replanning did not come beside the same choke points when replaying the same
    /// outcomes (it is deterministic, so this is a defect).
    #[error("naive replanning did not replay the same observations")]
    Replay,
    /// More Monte Carlo samples than [`MAX_SAMPLES`].
    #[error("at most {max} Monte Carlo samples, not {0}", max = MAX_SAMPLES)]
    TooManySamples(usize),
}

/// The most worlds [`monte_carlo`] draws: it keeps each world's two drives (their routes
/// included), so memory grows with the samples; a million estimate a mean to about a
/// thousandth of its standard deviation.
pub const MAX_SAMPLES: usize = 1_000_000;

impl<N: std::fmt::Debug> From<SearchError<N>> for SimulationError {
    fn from(e: SearchError<N>) -> Self {
        SimulationError::Search(format!("{e:?}"))
    }
}

/// Draws a world: each choke point blocked with its probability. Returns the blocked ones as a
/// bit mask.
pub fn sample_world(terrain: &Terrain, rng: &mut ChaCha8Rng) -> u64 {
    let mut blocked = 0;
    for (c, choke) in terrain.choke_points().iter().enumerate() {
        if rng.random::<f64>() < choke.probability {
            blocked |= 1 << c;
        }
    }
    blocked
}

/// Drives the naive strategy in the world where `blocked` are blocked: D* Lite with unseen choke
/// points taken as open, told of each blocked one the vehicle sees.
pub fn naive_replanning(terrain: &Terrain, blocked: u64) -> Result<Execution, SimulationError> {
    drive_naive(terrain, |seen| Ok(seen & blocked))
}

/// Drives the naive strategy, asking `observe` which of the choke points the vehicle has just
/// come beside (a non-empty mask, never asked twice) are blocked.
fn drive_naive(
    terrain: &Terrain,
    mut observe: impl FnMut(u64) -> Result<u64, SimulationError>,
) -> Result<Execution, SimulationError> {
    let known_blocked = Shared::new(0u64);
    let view = View::new(terrain.graph(), |c| {
        terrain.choke_at(c).is_none_or(|k| known_blocked.get() & (1 << k) == 0)
    });
    let h = terrain.graph().heuristic_between(GridHeuristic::for_connectivity(terrain.connectivity()));
    let (start, goal) = (terrain.start(), terrain.goal());
    let mut planner = DStarLite::new(&view, start, goal, h)?;
    let mut seen = 0u64;
    let mut at = start;
    let mut run = Execution { cost: 0.0, arrived: false, route: vec![start] };
    loop {
        let beside = terrain.chokes_beside(at) & !seen;
        seen |= beside;
        let newly = if beside == 0 { 0 } else { observe(beside)? & beside };
        if newly != 0 {
            known_blocked.set(known_blocked.get() | newly);
            let mut changed = Vec::new();
            for (c, choke) in terrain.choke_points().iter().enumerate() {
                if newly & (1 << c) != 0 {
                    changed
                        .extend(choke.cells.iter().flat_map(|&cell| terrain.graph().cells_affected_by(cell)));
                }
            }
            planner.update_nodes(&view, changed)?;
        }
        planner.compute_shortest_path(&view)?;
        if at == goal {
            run.arrived = true;
            return Ok(run);
        }
        let Some(next) = planner.next_step(&view) else {
            return Ok(run);
        };
        // Every choke point is seen from the cell before it, so the blocked ones seen so far
        // are all the vehicle could drive into.
        run.cost += terrain
            .route_cost(&[at, next], known_blocked.get())
            .ok_or(ExecutionError::Undrivable { from: at, to: next })?;
        planner.move_start(&view, next)?;
        run.route.push(next);
        at = next;
    }
}

/// The mean of a sample of costs, with its standard error and the fraction of runs that got
/// stuck.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Estimate {
    /// The mean cost.
    pub mean: Cost,
    /// The standard error of the mean.
    pub std_error: Cost,
    /// The fraction of runs that did not reach the goal.
    pub stuck: f64,
}

impl Estimate {
    fn of(runs: &[Execution]) -> Estimate {
        let n = runs.len() as f64;
        let mean = runs.iter().map(|r| r.cost).sum::<Cost>() / n;
        let var = runs.iter().map(|r| (r.cost - mean).powi(2)).sum::<Cost>() / (n - 1.0).max(1.0);
        Estimate {
            mean,
            std_error: (var / n).sqrt(),
            stuck: runs.iter().filter(|r| !r.arrived).count() as f64 / n,
        }
    }
}

/// The result of a Monte Carlo comparison.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MonteCarlo {
    /// How many worlds were drawn.
    pub samples: usize,
    /// Driving the contingency plan.
    pub plan: Estimate,
    /// Following the shortest path and replanning with D* Lite.
    pub naive: Estimate,
    /// What the plan saves over naive replanning, world by world (naive cost minus plan cost):
    /// its mean and the standard error of that mean (paired, so much smaller than the two
    /// strategies' own standard errors).
    pub saving: Estimate,
    /// Worlds in which the plan cost less than naive replanning (by more than 1e-9).
    pub plan_cheaper: usize,
    /// Worlds in which the plan cost more.
    pub plan_dearer: usize,
}

/// Draws `samples` worlds from `seed` (at most [`MAX_SAMPLES`]) and drives both strategies in
/// each.
pub fn monte_carlo(
    terrain: &Terrain,
    plan: &PlanNode,
    samples: usize,
    seed: u64,
) -> Result<MonteCarlo, SimulationError> {
    if samples > MAX_SAMPLES {
        return Err(SimulationError::TooManySamples(samples));
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let worlds: Vec<u64> = (0..samples).map(|_| sample_world(terrain, &mut rng)).collect();
    // A world is which choke points are blocked, and both strategies drive each world the same
    // way every time: each distinct world is driven once, the worlds shared out over the cores
    // (the figures do not depend on how many there are).
    let mut distinct = worlds.clone();
    distinct.sort_unstable();
    distinct.dedup();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(distinct.len().max(1));
    let chunk = distinct.len().div_ceil(threads).max(1);
    let drive = |world: u64| -> Result<(Execution, Execution), SimulationError> {
        Ok((plan.execute(terrain, world)?, naive_replanning(terrain, world)?))
    };
    let driven: HashMap<u64, Result<(Execution, Execution), SimulationError>> = std::thread::scope(|scope| {
        let handles: Vec<_> = distinct
            .chunks(chunk)
            .map(|part| scope.spawn(move || part.iter().map(|&w| (w, drive(w))).collect::<Vec<_>>()))
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("a driving thread does not panic")).collect()
    });
    let mut planned = Vec::with_capacity(samples);
    let mut naive = Vec::with_capacity(samples);
    // The first sample (in drawing order) whose world fails reports the error, as one by one.
    for world in &worlds {
        let (p, n) = driven[world].clone()?;
        planned.push(p);
        naive.push(n);
    }
    let diff = |a: &Execution, b: &Execution| a.cost - b.cost;
    let savings: Vec<Execution> = planned
        .iter()
        .zip(&naive)
        .map(|(p, n)| Execution { cost: n.cost - p.cost, arrived: true, route: Vec::new() })
        .collect();
    Ok(MonteCarlo {
        samples,
        plan: Estimate::of(&planned),
        naive: Estimate::of(&naive),
        saving: Estimate::of(&savings),
        plan_cheaper: planned.iter().zip(&naive).filter(|(a, b)| diff(a, b) < -1e-9).count(),
        plan_dearer: planned.iter().zip(&naive).filter(|(a, b)| diff(a, b) > 1e-9).count(),
    })
}

/// The exact expected cost of naive replanning, with the probability of getting stuck.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct NaiveExpectation {
    /// The expected cost.
    pub expected_cost: Cost,
    /// The probability of getting stuck.
    pub stuck_probability: f64,
    /// How many drives it took: one per distinct sequence of observations.
    pub drives: usize,
}

/// The exact expected cost of naive replanning, by driving D* Lite once for each distinct
/// sequence of what the vehicle sees.
///
/// Naive replanning is deterministic, so its drive depends only on the outcomes of the choke
/// points it comes beside, in the order it comes beside them: the worlds that agree on those
/// share one drive, whose probability is the product of the outcomes'. The drives are
/// enumerated depth-first, each replaying the outcomes of the one before up to the last choke
/// point (or group of choke points seen together) that has an outcome left to try, and taking
/// every choke point seen after that as open at first. This needs far fewer drives than
/// [`naive_expected_cost_by_worlds`] when the vehicle comes beside few of the choke points, and
/// gives the same result.
pub fn naive_expected_cost(terrain: &Terrain) -> Result<NaiveExpectation, SimulationError> {
    let mut total = NaiveExpectation { expected_cost: 0.0, stuck_probability: 0.0, drives: 0 };
    // The outcomes to replay: (choke points seen together, index into their outcomes).
    let mut replay: Vec<(u64, usize)> = Vec::new();
    loop {
        let mut asked: Vec<(u64, usize)> = Vec::new();
        let mut probability = 1.0;
        let run = drive_naive(terrain, |group| {
            let choice = match replay.get(asked.len()) {
                Some(&(g, choice)) if g == group => choice,
                Some(_) => return Err(SimulationError::Replay),
                None => 0,
            };
            let (blocked, p) = outcomes(group, terrain)[choice];
            probability *= p;
            asked.push((group, choice));
            Ok(blocked)
        })?;
        total.drives += 1;
        total.expected_cost += probability * run.cost;
        if !run.arrived {
            total.stuck_probability += probability;
        }
        // The next drive: the deepest observation with an outcome left to try.
        loop {
            match asked.pop() {
                None => return Ok(total),
                Some((group, choice)) if choice + 1 < outcomes(group, terrain).len() => {
                    asked.push((group, choice + 1));
                    break;
                }
                Some(_) => {}
            }
        }
        replay = asked;
    }
}

/// The exact expected cost of naive replanning by brute force: D* Lite driven in every world
/// (every combination of blocked choke points, `2^choke points` of them), weighted by the
/// worlds' probabilities. The cross-check of [`naive_expected_cost`].
pub fn naive_expected_cost_by_worlds(terrain: &Terrain) -> Result<NaiveExpectation, SimulationError> {
    let mut total = NaiveExpectation { expected_cost: 0.0, stuck_probability: 0.0, drives: 0 };
    for (world, p) in crate::plan::worlds(terrain) {
        let run = naive_replanning(terrain, world)?;
        total.drives += 1;
        total.expected_cost += p * run.cost;
        if !run.arrived {
            total.stuck_probability += p;
        }
    }
    Ok(total)
}
