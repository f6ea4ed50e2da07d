//! Benchmarking any planner, the user's own included: seeded runs on a problem, each measured
//! (time, overshoot of the time limit, memory, cost, success, iterations, checks), and logs in
//! OMPL's format ([`log`]) for OMPL's `ompl_benchmark_statistics` and Planner Arena.
//!
//! `cargo xtask bench` runs its sampling section through [`benchmark`].
//!
//! ```
//! use std::time::Duration;
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::benchmark::{Experiment, benchmark, log};
//! use trailmark_sample::{KdNearest, Problem, R2, RrtConnect};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let mut planner = RrtConnect::new(KdNearest::<R2, 2>::new(&space)?);
//! let limit = Termination::time(Duration::from_secs(1));
//! let runs = benchmark(&mut planner, &problem, &limit, 20, 1, None)?;
//! assert!(runs.runs.iter().all(|r| r.solved));
//! let text = log::write(&Experiment {
//!     name: "wall".into(),
//!     setup: "one wall".into(),
//!     seed: 1,
//!     time_limit_s: 1.0,
//!     date: "2026-12-02".into(),
//!     planners: vec![runs.logged()],
//! });
//! assert!(text.contains("20 runs"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod log;

use std::time::Instant;

pub use log::{Experiment, PlannerRuns};

use crate::plan::{Plan, PlanError, Solution};
use crate::planner::Planner;
use crate::problem::Problem;
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Termination;

/// One measured run of a planner.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunRecord {
    /// The seed of the run.
    pub seed: u64,
    /// Seconds, measured around the planner's `solve`.
    pub time_s: f64,
    /// How far past the termination's time limit the run returned, seconds (`None`: no time
    /// limit, or returned within it).
    pub overshoot_s: Option<f64>,
    /// Whether it found an exact solution.
    pub solved: bool,
    /// Whether it returned an approximate solution instead.
    pub approximate: bool,
    /// Peak heap bytes during the run (`None`: not measured).
    pub memory_bytes: Option<usize>,
    /// States in the planner's trees or graph.
    pub graph_states: u64,
    /// The exact solution's cost.
    pub solution_length: Option<f64>,
    /// Iterations.
    pub iterations: u64,
    /// Collision checks.
    pub collision_checks: u64,
    /// `(seconds, best cost)` at each improvement.
    pub progress: Vec<(f64, f64)>,
}

impl RunRecord {
    /// The record of `plan`, which took `time_s` under `termination`.
    pub fn of<T>(plan: &Plan<T>, time_s: f64, termination: &Termination, seed: u64) -> Self {
        let overshoot_s = termination.time_limit.map(|t| time_s - t.as_secs_f64()).filter(|&o| o > 0.0);
        RunRecord {
            seed,
            time_s,
            overshoot_s,
            solved: plan.is_exact(),
            approximate: matches!(plan.solution, Solution::Approximate { .. }),
            memory_bytes: None,
            graph_states: plan.stats.tree_sizes.iter().map(|&n| n as u64).sum(),
            solution_length: plan.cost(),
            iterations: plan.stats.iterations,
            collision_checks: plan.stats.collision_checks,
            progress: plan.history.iter().map(|h| (h.time.as_secs_f64(), h.cost)).collect(),
        }
    }
}

/// The peak heap use of a run, for a program that counts its allocations (a counting global
/// allocator, say): the library cannot count them itself.
pub trait MemoryProbe {
    /// Marks the start of a run.
    fn begin(&self);

    /// The most bytes in use above the mark since [`begin`](Self::begin).
    fn peak_bytes(&self) -> usize;
}

/// A planner's runs on one problem: each run's plan beside its record.
#[derive(Debug, Clone)]
pub struct Runs<T> {
    /// The planner's name.
    pub planner: String,
    /// Whether it improves its solution after the first (its progress is logged).
    pub optimizing: bool,
    /// The plans, in the order of the runs (to check their paths).
    pub plans: Vec<Plan<T>>,
    /// The records.
    pub runs: Vec<RunRecord>,
}

impl<T> Runs<T> {
    /// The runs for an OMPL-format log, the planner named `trailmark_<name>`.
    pub fn logged(&self) -> PlannerRuns {
        // OMPL's spelling: RRTConnect, RRTstar.
        let name = format!("trailmark_{}", self.planner.replace('-', "").replace('*', "star"));
        PlannerRuns { name, optimizing: self.optimizing, runs: self.runs.clone() }
    }

    /// The largest overshoot of the time limit over the runs, seconds (0 when none ran over).
    pub fn largest_overshoot_s(&self) -> f64 {
        self.runs.iter().filter_map(|r| r.overshoot_s).fold(0.0, f64::max)
    }
}

/// `runs` runs of `planner` on `problem` under `termination`, seeded `seed`, `seed + 1`, ...,
/// the planner cleared before each; memory measured by `memory` when given.
pub fn benchmark<S: StateSpace, V: Validity<S>>(
    planner: &mut dyn Planner<S, V>,
    problem: &Problem<'_, S, V>,
    termination: &Termination,
    runs: usize,
    seed: u64,
    memory: Option<&dyn MemoryProbe>,
) -> Result<Runs<S::State>, PlanError> {
    let mut out = Runs {
        planner: planner.name().to_string(),
        optimizing: planner.optimizes(),
        plans: Vec::new(),
        runs: Vec::new(),
    };
    for i in 0..runs {
        let seed = seed.wrapping_add(i as u64);
        planner.clear();
        planner.set_seed(seed);
        if let Some(m) = memory {
            m.begin();
        }
        let clock = Instant::now();
        let plan = planner.solve(problem, termination)?;
        let time_s = clock.elapsed().as_secs_f64();
        let mut record = RunRecord::of(&plan, time_s, termination, seed);
        record.memory_bytes = memory.map(|m| m.peak_bytes());
        out.plans.push(plan);
        out.runs.push(record);
    }
    Ok(out)
}
