//! RRT (LaValle 1998) and RRT-Connect (Kuffner and LaValle 2000) over any [`StateSpace`].
//!
//! Both grow trees of valid motions by steering toward random samples, at most `range` at a
//! time. **RRT** grows one tree from the start and, with probability `goal_bias`, steers toward
//! the goal itself. **RRT-Connect** grows a tree from each end; after each extension of one tree
//! the other tries to connect to the new state, and the trees swap roles every iteration. The
//! goal tree is grown backward: its motions run from the new state *into* the tree and are
//! checked that way, so asymmetric spaces such as Dubins work.
//!
//! Runs are reproducible: the same seed gives the same trees, path and statistics. A run stops
//! at the first solution or at its [`Termination`]. Without a solution, RRT returns the path to
//! the state nearest the goal, marked approximate.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::nearest::KdNearest;
//! use trailmark_sample::rrt::{Query, RrtOptions, Termination, rrt_connect};
//! use trailmark_sample::space::R2;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let nearest = KdNearest::<R2, 2>::new(&space)?;
//! let (start, goal) = (Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let query = Query::new(&space, &checker, start, goal);
//! let plan = rrt_connect(&query, nearest, &RrtOptions::default(), &Termination::iterations(10_000), 7)?;
//! let path = plan.path.expect("a way over the wall");
//! assert_eq!((path[0], *path.last().unwrap()), (start, goal));
//! assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
//! assert!(plan.cost.unwrap() >= 2.0 * (9.0f64 + 7.25 * 7.25).sqrt() + 2.0); // over the grown wall
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::sync::Arc;
use std::time::{Duration, Instant};

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use thiserror::Error;

use crate::nearest::{Direction, NearestNeighbors, measure};
use crate::sampler::{StateSampler, Uniform};
use crate::space::StateSpace;
use crate::validity::Validity;

/// What to plan: a space, what is valid in it, a start and a goal (OMPL's problem definition),
/// and where to draw samples ([`Uniform`] unless set with [`Query::with_sampler`]).
#[derive(Debug, Clone)]
pub struct Query<'a, S: StateSpace, V, Q = Uniform> {
    /// The state space.
    pub space: &'a S,
    /// The validity of states and motions.
    pub validity: &'a V,
    /// Where the robot is.
    pub start: S::State,
    /// Where it must go.
    pub goal: S::State,
    /// Where the planners draw the states they steer toward.
    pub sampler: Q,
}

impl<'a, S: StateSpace, V> Query<'a, S, V> {
    /// The query from `start` to `goal`, sampled uniformly.
    pub fn new(space: &'a S, validity: &'a V, start: S::State, goal: S::State) -> Self {
        Query { space, validity, start, goal, sampler: Uniform }
    }
}

impl<'a, S: StateSpace, V, Q> Query<'a, S, V, Q> {
    /// The same query with samples drawn by `sampler` (see [`sampler`](crate::sampler)).
    pub fn with_sampler<R: StateSampler<S>>(self, sampler: R) -> Query<'a, S, V, R> {
        let Query { space, validity, start, goal, .. } = self;
        Query { space, validity, start, goal, sampler }
    }
}

/// When a planner gives up (whichever comes first). At least one limit must be set: iterations,
/// time or a user condition.
///
/// ```
/// use std::sync::Arc;
/// use std::sync::atomic::{AtomicBool, Ordering};
/// use std::time::Duration;
/// use trailmark_sample::rrt::Termination;
///
/// // At most 50,000 iterations or 2 s, and stop early when another thread says so.
/// let cancel = Arc::new(AtomicBool::new(false));
/// let flag = Arc::clone(&cancel);
/// let limit = Termination { time_limit: Some(Duration::from_secs(2)), ..Termination::iterations(50_000) }
///     .or_when(move |_| flag.load(Ordering::Relaxed));
/// # let _ = limit;
/// ```
#[derive(Clone, Default)]
pub struct Termination {
    /// Iterations (samples drawn).
    pub max_iterations: Option<u64>,
    /// Wall-clock time.
    pub time_limit: Option<Duration>,
    /// RRT*: stop once the best path costs at most this (with a limit above as well).
    pub target_cost: Option<f64>,
    /// A user condition, asked once per iteration: stop when it returns `true`.
    pub condition: Option<Condition>,
}

/// A user stopping condition: asked with the run's progress before every iteration.
pub type Condition = Arc<dyn Fn(&Progress) -> bool + Send + Sync>;

/// How far a run has come, as a [`Condition`] sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Iterations done.
    pub iterations: u64,
    /// Time since the run began.
    pub elapsed: Duration,
    /// The best solution's cost so far (RRT*; `None` before the first solution, and always for
    /// RRT and RRT-Connect, which stop at their first).
    pub best_cost: Option<f64>,
}

impl std::fmt::Debug for Termination {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Termination")
            .field("max_iterations", &self.max_iterations)
            .field("time_limit", &self.time_limit)
            .field("target_cost", &self.target_cost)
            .field("condition", &self.condition.as_ref().map(|_| "user closure"))
            .finish()
    }
}

/// The most extensions one connect phase of RRT-Connect makes toward a new state before the
/// next iteration begins: the tree keeps what it grew, and the limits are checked again (a range
/// of 1e-7 across a world of 10 had made one iteration run for minutes).
pub const MAX_CONNECT_STEPS: usize = 10_000;

/// The shortest `range` a planner takes, as a share of the space's extent: 1e-4, so that one
/// connect phase of [`MAX_CONNECT_STEPS`] can cross the space. Shorter steps only pile up
/// states (a range of 1e-8 of a world had made RRT-Connect run for minutes, its trees
/// millions of states along lines).
pub const MIN_RELATIVE_RANGE: f64 = 1e-4;

impl Termination {
    /// Stop after `n` iterations.
    pub fn iterations(n: u64) -> Self {
        Termination { max_iterations: Some(n), ..Termination::default() }
    }

    /// Stop after `limit`.
    pub fn time(limit: Duration) -> Self {
        Termination { time_limit: Some(limit), ..Termination::default() }
    }

    /// Stop when `condition` returns `true` (and at no other limit).
    pub fn when(condition: impl Fn(&Progress) -> bool + Send + Sync + 'static) -> Self {
        Termination::default().or_when(condition)
    }

    /// These limits, and also stop when `condition` returns `true` (replacing any earlier
    /// condition).
    pub fn or_when(self, condition: impl Fn(&Progress) -> bool + Send + Sync + 'static) -> Self {
        Termination { condition: Some(Arc::new(condition)), ..self }
    }

    /// Whether any limit is set (a target cost alone is not one: it may never be reached).
    pub fn is_bounded(&self) -> bool {
        self.max_iterations.is_some() || self.time_limit.is_some() || self.condition.is_some()
    }

    pub(crate) fn reached(&self, iterations: u64, clock: &Instant, best_cost: Option<f64>) -> bool {
        self.max_iterations.is_some_and(|n| iterations >= n)
            || self.time_limit.is_some_and(|t| clock.elapsed() >= t)
            || self.target_cost.is_some_and(|t| best_cost.is_some_and(|c| c <= t))
            || self
                .condition
                .as_ref()
                .is_some_and(|stop| stop(&Progress { iterations, elapsed: clock.elapsed(), best_cost }))
    }
}

/// The settings of RRT and RRT-Connect.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtOptions {
    /// The longest motion added at once (default: 0.2 x the space's extent, as OMPL; at least
    /// [`MIN_RELATIVE_RANGE`] of it).
    pub range: Option<f64>,
    /// RRT: the probability of steering toward the goal (default 0.05).
    pub goal_bias: f64,
    /// RRT: a state within this distance of the goal solves the problem, and the path ends
    /// there (default 0: the goal itself must be reached).
    pub goal_tolerance: f64,
}

impl Default for RrtOptions {
    fn default() -> Self {
        RrtOptions { range: None, goal_bias: 0.05, goal_tolerance: 0.0 }
    }
}

/// Why a planner did not run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PlanError {
    /// The start state is not valid.
    #[error("the start state is not valid (in collision or out of bounds)")]
    InvalidStart,
    /// The goal state is not valid.
    #[error("the goal state is not valid (in collision or out of bounds)")]
    InvalidGoal,
    /// A setting out of its range.
    #[error("{name} must be {expected}, got {value}")]
    InvalidOption {
        /// The setting.
        name: &'static str,
        /// Its range.
        expected: &'static str,
        /// The value given.
        value: f64,
    },
    /// A termination condition with no limit.
    #[error("the termination condition sets no limit (iterations, time or a user condition)")]
    NoLimit,
}

/// What a run did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlanStats {
    /// Iterations (samples drawn).
    pub iterations: u64,
    /// States in the start tree, and in the goal tree (RRT-Connect).
    pub tree_sizes: [usize; 2],
    /// State and motion validity checks.
    pub collision_checks: u64,
    /// Time to the first solution.
    pub time_to_solution: Option<Duration>,
    /// Time of the whole run.
    pub elapsed: Duration,
}

/// The result of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan<T> {
    /// The states from the start to the goal (or, when approximate, to the state nearest the
    /// goal), each motion valid; `None` when nothing was found.
    pub path: Option<Vec<T>>,
    /// The path's cost (the sum of its motions' distances).
    pub cost: Option<f64>,
    /// Whether the path stops short of the goal.
    pub approximate: bool,
    /// The distance from the path's last state to the goal.
    pub goal_distance: f64,
    /// The cost of the best solution each time it improved (one entry for RRT and RRT-Connect,
    /// which stop at their first solution; empty without one).
    pub history: Vec<Improvement>,
    /// What the run did.
    pub stats: PlanStats,
}

/// A new best solution of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Improvement {
    /// The iteration that found it.
    pub iteration: u64,
    /// The time since the start of the run.
    pub time: Duration,
    /// Its cost.
    pub cost: f64,
}

/// A tree of states: each with its parent, searched through a nearest-neighbour structure.
struct Tree<S: StateSpace, N> {
    nearest: N,
    parents: Vec<u32>,
    /// Forward (from the start) or backward (into the goal).
    direction: Direction,
    _space: std::marker::PhantomData<fn() -> S>,
}

const ROOT: u32 = u32::MAX;

enum Extension {
    Trapped,
    Advanced(u32),
    Reached(u32),
}

impl<S: StateSpace, N: NearestNeighbors<S>> Tree<S, N> {
    fn new(space: &S, mut nearest: N, root: S::State, direction: Direction) -> Self {
        nearest.insert(space, root);
        Tree { nearest, parents: vec![ROOT], direction, _space: std::marker::PhantomData }
    }

    fn state(&self, id: u32) -> &S::State {
        self.nearest.state(id)
    }

    /// Grows one motion of at most `range` toward `target`.
    fn extend<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        target: &S::State,
        range: f64,
        checks: &mut u64,
    ) -> Extension {
        let Some((near, d)) = self.nearest.nearest(space, target, self.direction) else {
            return Extension::Trapped;
        };
        self.extend_from(space, validity, near, d, target, range, checks)
    }

    /// [`Tree::extend`] from the state `near`, `d` from `target` in the tree's direction.
    #[allow(clippy::too_many_arguments)]
    fn extend_from<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        near: u32,
        d: f64,
        target: &S::State,
        range: f64,
        checks: &mut u64,
    ) -> Extension {
        let from = self.state(near).clone();
        let (new, reached) = if d <= range {
            (target.clone(), true)
        } else {
            match self.direction {
                // Forward: range along the motion from the tree toward the target.
                Direction::ToQuery => (space.interpolate(&from, target, range / d), false),
                // Backward: range before the tree along the motion from the target into it.
                Direction::FromQuery => (space.interpolate(target, &from, 1.0 - range / d), false),
            }
        };
        if new == from {
            return Extension::Trapped;
        }
        *checks += 1;
        let valid = match self.direction {
            Direction::ToQuery => validity.motion_is_valid(space, &from, &new),
            Direction::FromQuery => validity.motion_is_valid(space, &new, &from),
        };
        if !valid {
            return Extension::Trapped;
        }
        let id = self.nearest.insert(space, new);
        self.parents.push(near);
        if reached { Extension::Reached(id) } else { Extension::Advanced(id) }
    }

    /// The distance from state `id` to `target` in the tree's direction (the query's motions
    /// run from the tree toward it, or from it into the tree).
    fn gap(&self, space: &S, id: u32, target: &S::State) -> f64 {
        measure(space, self.state(id), target, self.direction)
    }

    /// The states from the root to `id`.
    fn branch(&self, mut id: u32) -> Vec<S::State> {
        let mut states = Vec::new();
        while id != ROOT {
            states.push(self.state(id).clone());
            id = self.parents[id as usize];
        }
        states.reverse();
        states
    }
}

/// What every run starts with: the ends, its clock and statistics, the checked range, and the
/// seeded generator.
pub(crate) struct Run<T> {
    pub(crate) start: T,
    pub(crate) goal: T,
    pub(crate) clock: Instant,
    pub(crate) stats: PlanStats,
    pub(crate) range: f64,
    pub(crate) rng: ChaCha8Rng,
}

impl<T: Clone> Run<T> {
    /// Checks `query` and the settings, and starts the clock.
    pub(crate) fn begin<S: StateSpace<State = T>, V: Validity<S>, Q>(
        query: &Query<'_, S, V, Q>,
        options: &RrtOptions,
        termination: &Termination,
        seed: u64,
    ) -> Result<Self, PlanError> {
        let clock = Instant::now();
        let mut stats = PlanStats::default();
        let (start, goal) = (query.start.clone(), query.goal.clone());
        let range = prepare(
            query.space,
            query.validity,
            &start,
            &goal,
            options,
            termination,
            &mut stats.collision_checks,
        )?;
        Ok(Run { start, goal, clock, stats, range, rng: ChaCha8Rng::seed_from_u64(seed) })
    }
}

/// Checks the settings and the ends; returns the range.
fn prepare<S: StateSpace, V: Validity<S>>(
    space: &S,
    validity: &V,
    start: &S::State,
    goal: &S::State,
    options: &RrtOptions,
    termination: &Termination,
    checks: &mut u64,
) -> Result<f64, PlanError> {
    if !termination.is_bounded() {
        return Err(PlanError::NoLimit);
    }
    let range = options.range.unwrap_or(0.2 * space.extent());
    if !(range.is_finite() && range > 0.0) {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "positive and finite",
            value: range,
        });
    }
    if range < MIN_RELATIVE_RANGE * space.extent() {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "at least 1e-4 of the space's extent (MIN_RELATIVE_RANGE)",
            value: range,
        });
    }
    if !(0.0..=1.0).contains(&options.goal_bias) {
        let value = options.goal_bias;
        return Err(PlanError::InvalidOption { name: "goal_bias", expected: "in [0, 1]", value });
    }
    if !(options.goal_tolerance >= 0.0 && options.goal_tolerance.is_finite()) {
        let value = options.goal_tolerance;
        return Err(PlanError::InvalidOption { name: "goal_tolerance", expected: ">= 0 and finite", value });
    }
    *checks += 2;
    if !validity.state_is_valid(space, start) {
        return Err(PlanError::InvalidStart);
    }
    if !validity.state_is_valid(space, goal) {
        return Err(PlanError::InvalidGoal);
    }
    Ok(range)
}

/// The cost of a path: its motions' distances summed.
pub(crate) fn cost_of<S: StateSpace>(space: &S, path: &[S::State]) -> f64 {
    // A fold from +0: an empty float sum is -0.0, which a one-state path would report.
    path.windows(2).fold(0.0, |total, m| total + space.distance(&m[0], &m[1]))
}

/// RRT for `query`, nearest neighbours from `nearest` (empty), samples from a ChaCha8 generator
/// seeded with `seed`.
pub fn rrt<S, V, N, Q>(
    query: &Query<'_, S, V, Q>,
    nearest: N,
    options: &RrtOptions,
    termination: &Termination,
    seed: u64,
) -> Result<Plan<S::State>, PlanError>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S>,
    Q: StateSampler<S>,
{
    let Query { space, validity, ref sampler, .. } = *query;
    let Run { start, goal, clock, mut stats, range, mut rng } =
        Run::begin(query, options, termination, seed)?;
    let mut tree = Tree::new(space, nearest, start.clone(), Direction::ToQuery);
    let mut closest = (0u32, space.distance(&start, &goal));
    let mut solved = closest.1 <= options.goal_tolerance;
    while !solved && !termination.reached(stats.iterations, &clock, None) {
        stats.iterations += 1;
        let target = if rng.random::<f64>() < options.goal_bias {
            goal.clone()
        } else {
            sampler.sample(space, validity, &mut rng, &mut stats.collision_checks)
        };
        let id = match tree.extend(space, validity, &target, range, &mut stats.collision_checks) {
            Extension::Trapped => continue,
            Extension::Advanced(id) | Extension::Reached(id) => id,
        };
        let d = space.distance(tree.state(id), &goal);
        if d < closest.1 {
            closest = (id, d);
        }
        solved = d <= options.goal_tolerance;
    }
    if solved {
        stats.time_to_solution = Some(clock.elapsed());
    }
    let path = tree.branch(closest.0);
    stats.tree_sizes = [tree.nearest.len(), 0];
    stats.elapsed = clock.elapsed();
    let cost = cost_of(space, &path);
    let history = stats
        .time_to_solution
        .map(|time| Improvement { iteration: stats.iterations, time, cost })
        .into_iter()
        .collect();
    Ok(Plan {
        cost: Some(cost),
        path: Some(path),
        approximate: !solved,
        goal_distance: closest.1,
        history,
        stats,
    })
}

/// RRT-Connect for `query`; arguments as for [`rrt`] (`nearest` is cloned for
/// the second tree; `goal_bias` and `goal_tolerance` are not used: the trees meet exactly).
/// Without a meeting, the plan is the start tree's branch to the state nearest the goal, marked
/// approximate.
pub fn rrt_connect<S, V, N, Q>(
    query: &Query<'_, S, V, Q>,
    nearest: N,
    options: &RrtOptions,
    termination: &Termination,
    seed: u64,
) -> Result<Plan<S::State>, PlanError>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
{
    let Query { space, validity, ref sampler, .. } = *query;
    let Run { start, goal, clock, mut stats, range, mut rng } =
        Run::begin(query, options, termination, seed)?;
    let mut trees = [
        Tree::new(space, nearest.clone(), start.clone(), Direction::ToQuery),
        Tree::new(space, nearest, goal.clone(), Direction::FromQuery),
    ];
    // Which tree grows this iteration; the other connects.
    let mut grow = 0;
    let mut meeting = None;
    if start == goal {
        meeting = Some((0, 0));
    }
    while meeting.is_none() && !termination.reached(stats.iterations, &clock, None) {
        stats.iterations += 1;
        let sample = sampler.sample(space, validity, &mut rng, &mut stats.collision_checks);
        let [a, b] = if grow == 0 { [0, 1] } else { [1, 0] };
        let (first, second) = if grow == 0 {
            let (x, y) = trees.split_at_mut(1);
            (&mut x[0], &mut y[0])
        } else {
            let (x, y) = trees.split_at_mut(1);
            (&mut y[0], &mut x[0])
        };
        let new = match first.extend(space, validity, &sample, range, &mut stats.collision_checks) {
            Extension::Trapped => None,
            Extension::Advanced(id) | Extension::Reached(id) => Some(id),
        };
        if let Some(new) = new {
            let target = first.state(new).clone();
            // After the first step, each step goes on from the state the last one added: in a
            // metric space it is the nearest to the target (the tree's other states were
            // farther than the one it grew from), so a nearest-neighbour query per step (what
            // OMPL does) would find it again, at a cost that grows with the tree.
            let mut last: Option<u32> = None;
            for step in 0..MAX_CONNECT_STEPS {
                // The connect phase answers to the time limit and the caller's condition too
                // (checked every 256 steps): with a tiny range it can take millions of steps.
                // (As of the iteration before: the iteration count's own limit ends the loop.)
                if step % 256 == 255 && termination.reached(stats.iterations - 1, &clock, None) {
                    break;
                }
                let extension = match last {
                    None => second.extend(space, validity, &target, range, &mut stats.collision_checks),
                    Some(id) => {
                        let d = second.gap(space, id, &target);
                        second.extend_from(
                            space,
                            validity,
                            id,
                            d,
                            &target,
                            range,
                            &mut stats.collision_checks,
                        )
                    }
                };
                match extension {
                    Extension::Trapped => break,
                    Extension::Advanced(id) => last = Some(id),
                    Extension::Reached(id) => {
                        let mut ids = [0, 0];
                        ids[a] = new;
                        ids[b] = id;
                        meeting = Some((ids[0], ids[1]));
                        break;
                    }
                }
            }
        }
        grow = 1 - grow;
    }
    stats.tree_sizes = [trees[0].nearest.len(), trees[1].nearest.len()];
    let Some((from_start, into_goal)) = meeting else {
        // No meeting: the approximate answer is the start tree's branch to the state nearest
        // the goal (OMPL's RRTConnect does the same).
        let (closest, goal_distance) = trees[0]
            .nearest
            .nearest(space, &goal, Direction::ToQuery)
            .unwrap_or((0, space.distance(&start, &goal)));
        let path = trees[0].branch(closest);
        let cost = cost_of(space, &path);
        stats.elapsed = clock.elapsed();
        return Ok(Plan {
            path: Some(path),
            cost: Some(cost),
            approximate: true,
            goal_distance,
            history: Vec::new(),
            stats,
        });
    };
    stats.time_to_solution = Some(clock.elapsed());
    let mut path = trees[0].branch(from_start);
    let mut back = trees[1].branch(into_goal);
    back.reverse();
    // The meeting state ends the first part and starts the second.
    path.extend(back.into_iter().skip(1));
    stats.elapsed = clock.elapsed();
    let cost = cost_of(space, &path);
    let solution =
        Improvement { iteration: stats.iterations, time: stats.time_to_solution.unwrap_or_default(), cost };
    Ok(Plan {
        path: Some(path),
        cost: Some(cost),
        approximate: false,
        goal_distance: 0.0,
        history: vec![solution],
        stats,
    })
}
