//! What a single-query planner did on a world's queries: each run tallied as it comes, then
//! summed up in medians (RRT and RRT-Connect in the plane, RRT-Connect in other state spaces).

use serde::Serialize;

use crate::bench::stats::{median, sorted};

/// What a single-query planner of one library did on a world's queries.
#[derive(Debug, Clone, Serialize)]
pub struct ConnectStats {
    /// Solvable queries solved within the iterations.
    pub solved: usize,
    /// Median time per solvable query (failures included), milliseconds.
    pub median_ms: f64,
    /// Median iterations per solvable query.
    pub median_iterations: f64,
    /// Median collision checks per solvable query.
    pub median_checks: f64,
    /// Median path cost over the optimum.
    pub median_cost_ratio: f64,
    /// Paths that failed the re-check, or solutions where the visibility graph has no path
    /// (must be 0).
    pub invalid: usize,
    /// The time of each solvable query, milliseconds, sorted (for the plots; not serialized).
    #[serde(skip)]
    pub times_ms: Vec<f64>,
    /// The time of each solved query, milliseconds (for the plots; not serialized).
    #[serde(skip)]
    pub solved_ms: Vec<f64>,
}

/// Runs of one planner on a world's queries, as they come.
#[derive(Default)]
pub struct ConnectTally {
    times: Vec<f64>,
    solved_times: Vec<f64>,
    iterations: Vec<f64>,
    checks: Vec<f64>,
    ratios: Vec<f64>,
    /// The runs on queries that have a path.
    pub solvable: usize,
    solved: usize,
    invalid: usize,
}

impl ConnectTally {
    /// One run on a query of optimum `best` (`None`: no path): its time, iterations and checks,
    /// whether it found an exact path, and `cost_if_valid`, the re-checked path's cost or
    /// `None` when it fails the re-check.
    pub fn add(
        &mut self,
        best: Option<f64>,
        (ms, iterations, checks): (f64, u64, u64),
        exact: bool,
        cost_if_valid: impl FnOnce(f64) -> Option<f64>,
    ) {
        let Some(best) = best else {
            // No path by the visibility graph: a solution here would be an error of one of them.
            self.invalid += usize::from(exact);
            return;
        };
        self.solvable += 1;
        self.times.push(ms);
        self.iterations.push(iterations as f64);
        self.checks.push(checks as f64);
        if !exact {
            return;
        }
        self.solved += 1;
        self.solved_times.push(ms);
        match cost_if_valid(best) {
            Some(cost) => self.ratios.push(cost / best),
            None => self.invalid += 1,
        }
    }

    /// The medians of the runs.
    pub fn stats(self) -> ConnectStats {
        let times = sorted(self.times);
        ConnectStats {
            solved: self.solved,
            median_ms: median(&times),
            median_iterations: median(&sorted(self.iterations)),
            median_checks: median(&sorted(self.checks)),
            median_cost_ratio: median(&sorted(self.ratios)),
            invalid: self.invalid,
            times_ms: times,
            solved_ms: self.solved_times,
        }
    }
}
