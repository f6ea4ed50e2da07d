//! BIT\* (Gammell, Srinivasa and Barfoot 2015, "Batch Informed Trees"): batches of valid
//! samples, searched in order of the best solution each edge could give, with collision checks
//! only for the edges that are processed.
//!
//! Each batch adds `batch_size` valid states, drawn from the informed set once a solution is
//! held (see `crate::informed`), to an implicit random geometric graph over the samples and
//! the tree: each state's neighbours are its k = ⌈rewire_factor · e · (1 + 1/d) · ln n⌉ nearest
//! (n the states held). The tree's vertices are expanded in order of `g + ĥ` (cost from the
//! start through the tree, plus a lower bound to the goal) into an edge queue ordered by
//! `g(v) + ĉ(v, x) + ĥ(x)`: the cost of the best solution the edge could be part of, with `ĉ` the
//! distance. The best edge is checked (one motion check) only when it is popped, and only if it
//! could still improve both its target and the solution; a vertex's rewiring edges to other
//! vertices are queued in the batch it joins. The batch ends when the best edge cannot beat the
//! solution; then states no cheaper solution passes through are pruned (once the cost has fallen
//! by 5%) and the next batch is drawn. Invalid edges are remembered until the next pruning.
//!
//! Its iterations are the samples drawn, as for the other planners: an iteration limit ends
//! the run once the batch that reached it has been searched. Time limits and conditions are
//! asked before every edge; a target cost ends the run at the edge that reaches it.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::termination::Termination;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{BitStar, KdNearest, Planner, Problem, R2};
//!
//! // A 4 x 10 block between the start and the goal, in a 40 x 40 room.
//! let bounds = Bounds::new(0.0, 0.0, 40.0, 40.0)?;
//! let block = vec![Point::new(18.0, 15.0), Point::new(22.0, 15.0), Point::new(22.0, 25.0), Point::new(18.0, 25.0)];
//! let checker = PolygonWorld::new(bounds, vec![block], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::new(&space, &checker, Point::new(10.0, 20.0), Point::new(30.0, 20.0));
//! let mut planner = BitStar::new(KdNearest::<R2, 2>::new(&space)?).with_seed(1);
//! let plan = planner.solve(&problem, &Termination::iterations(2000))?;
//! let best = 2.0 * 89f64.sqrt() + 4.0; // to a corner of the block, along it, down
//! let cost = plan.cost().expect("solved");
//! assert!(cost >= best - 1e-9 && cost < 1.01 * best, "{cost}");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashSet};

use trailmark_core::termination::{Stop, Termination, Watch};

use super::graph::{BatchGraph, NO_PARENT};
use crate::informed::{Informed, PRUNE_THRESHOLD};
use crate::nearest::{Direction, NearestNeighbors};
use crate::plan::{Plan, PlanError};
use crate::planner::Planner;
use crate::problem::{Problem, admit};
use crate::run::{Run, Spent, check_empty};
use crate::sampler::{StateSampler, Uniform};
use crate::space::StateSpace;
use crate::validity::Validity;

/// The most samples a batch may draw: a batch is searched whole, so its size bounds the work
/// between two looks at an iteration limit.
pub const MAX_BATCH_SIZE: usize = 1_000_000;

/// The most goal states a goal region adds, one per batch (a goal state adds itself once).
const MAX_GOAL_SAMPLES: usize = 64;

/// BIT\*'s settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BitOptions {
    /// Valid samples drawn per batch (default 100, OMPL's), at least 1 and at most
    /// [`MAX_BATCH_SIZE`].
    pub batch_size: usize,
    /// The factor on the neighbour count k = ⌈rewire_factor · e · (1 + 1/d) · ln n⌉ (default
    /// 1.1, OMPL's); positive and finite.
    pub rewire_factor: f64,
}

impl Default for BitOptions {
    fn default() -> Self {
        BitOptions { batch_size: 100, rewire_factor: 1.1 }
    }
}

impl BitOptions {
    fn check(&self) -> Result<(), PlanError> {
        if !(1..=MAX_BATCH_SIZE).contains(&self.batch_size) {
            let value = self.batch_size as f64;
            return Err(PlanError::InvalidOption { name: "batch_size", expected: "in [1, 1000000]", value });
        }
        if !(self.rewire_factor > 0.0 && self.rewire_factor.is_finite()) {
            let value = self.rewire_factor;
            return Err(PlanError::InvalidOption {
                name: "rewire_factor",
                expected: "positive and finite",
                value,
            });
        }
        Ok(())
    }
}

/// BIT\*: batches of samples searched in order of the solutions they could give, edges checked
/// lazily; see the [module](self) documentation.
#[derive(Debug, Clone)]
pub struct BitStar<N, Q = Uniform> {
    nearest: N,
    sampler: Q,
    /// Batch size and rewire factor.
    pub options: BitOptions,
    /// The seed of the ChaCha8 generator each run starts from.
    pub seed: u64,
    /// What the last run built, freed before the next run's clock starts (as the tree planners).
    spent: Spent<N>,
}

impl<N> BitStar<N> {
    /// BIT\* with its states in (clones of) `nearest`, which must be empty, uniform samples
    /// before the first solution, the default options and seed 0.
    pub fn new(nearest: N) -> Self {
        BitStar {
            nearest,
            sampler: Uniform,
            options: BitOptions::default(),
            seed: 0,
            spent: Spent::default(),
        }
    }
}

impl<N, Q> BitStar<N, Q> {
    /// The same planner drawing its samples from `sampler` before its first solution; after it,
    /// where the informed set cannot be drawn from directly, states of `sampler` outside it are
    /// refused.
    pub fn with_sampler<R>(self, sampler: R) -> BitStar<N, R> {
        let BitStar { nearest, options, seed, .. } = self;
        BitStar { nearest, sampler, options, seed, spent: Spent::default() }
    }

    /// The same planner with these options.
    pub fn with_options(self, options: BitOptions) -> Self {
        BitStar { options, ..self }
    }

    /// The same planner seeded with `seed`.
    pub fn with_seed(self, seed: u64) -> Self {
        BitStar { seed, ..self }
    }
}

/// An entry of a queue, ordered so that `BinaryHeap` pops the least key first: a vertex
/// (`to` unused) or an edge from `from` to `to`.
#[derive(Debug, Clone, Copy)]
struct Entry {
    key: [f64; 2],
    from: u32,
    to: u32,
}

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Entry {}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed: the least key is the greatest entry.
        (other.key[0].total_cmp(&self.key[0]))
            .then(other.key[1].total_cmp(&self.key[1]))
            .then(other.from.cmp(&self.from))
            .then(other.to.cmp(&self.to))
    }
}

impl<S, V, N, Q> Planner<S, V> for BitStar<N, Q>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
{
    fn name(&self) -> &str {
        "BIT*"
    }

    fn set_seed(&mut self, seed: u64) {
        self.seed = seed;
    }

    fn clear(&mut self) {
        self.spent.release();
    }

    fn optimizes(&self) -> bool {
        true
    }

    fn solve(
        &mut self,
        problem: &Problem<'_, S, V>,
        termination: &Termination,
    ) -> Result<Plan<S::State>, PlanError> {
        self.spent.release();
        check_empty(&self.nearest)?;
        self.options.check()?;
        let watch = Watch::start(termination);
        let run = Run::checked(problem, watch, problem.space.extent(), self.seed)?;
        let (graph, plan) = Search::new(self, problem, run).search();
        self.spent = graph.into_spent();
        Ok(plan)
    }
}

/// One run of BIT\*: the graph, the two queues and the batch under way.
struct Search<'r, S: StateSpace, V, N, Q> {
    planner: &'r BitStar<N, Q>,
    problem: &'r Problem<'r, S, V>,
    set: Informed<'r, S>,
    run: Run<'r>,
    graph: BatchGraph<S, N>,
    vertices: BinaryHeap<Entry>,
    edges: BinaryHeap<Entry>,
    /// Edges found invalid since the last pruning (both ways in a symmetric space).
    invalid: HashSet<(u32, u32)>,
    /// The neighbours of a state in this batch.
    k: usize,
    goal_samples: usize,
    /// The vertices a rewiring lowered (kept to reuse its memory).
    lowered: Vec<u32>,
}

impl<'r, S, V, N, Q> Search<'r, S, V, N, Q>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
{
    fn new(planner: &'r BitStar<N, Q>, problem: &'r Problem<'r, S, V>, run: Run<'r>) -> Self {
        Search {
            planner,
            problem,
            set: Informed::new(problem),
            run,
            graph: BatchGraph::new(planner.nearest.clone()),
            vertices: BinaryHeap::new(),
            edges: BinaryHeap::new(),
            invalid: HashSet::new(),
            k: 1,
            goal_samples: 0,
            lowered: Vec::new(),
        }
    }

    fn best_cost(&self) -> f64 {
        self.graph.best().map_or(f64::INFINITY, |b| b.1)
    }

    /// Records the graph's best solution; `Some` when it reaches the target cost.
    fn improved(&mut self) -> Option<Stop> {
        let (_, cost) = self.graph.best()?;
        self.run.improved(cost);
        self.run.watch.termination().target_cost.is_some_and(|t| cost <= t).then_some(Stop::TargetCost)
    }

    fn search(mut self) -> (BatchGraph<S, N>, Plan<S::State>) {
        let (space, goal) = (self.problem.space, &*self.problem.goal);
        for start in &self.problem.starts {
            let id = self.graph.add_sample(space, &self.set, start.clone());
            self.graph.join(space, goal, id, NO_PARENT, 0.0);
        }
        let mut stop = self.improved();
        let mut last_batch = None;
        let mut pruned_at = f64::INFINITY;
        let stop = loop {
            if let Some(stop) = stop {
                break stop;
            }
            if self.vertices.is_empty() && self.edges.is_empty() {
                if let Some(stop) = last_batch {
                    break stop;
                }
                let best = self.best_cost();
                if best < (1.0 - PRUNE_THRESHOLD) * pruned_at {
                    if let Some(stop) = self.run.watch.interrupted() {
                        break stop;
                    }
                    self.graph.prune(space, &*self.problem.goal, best);
                    self.invalid.clear();
                    pruned_at = best;
                }
                match self.draw_batch(best) {
                    Ok(None) => {}
                    Ok(Some(stop)) => last_batch = Some(stop),
                    Err(stop) => break stop,
                }
                continue;
            }
            if let Some(interrupted) = self.run.watch.interrupted() {
                break interrupted;
            }
            stop = self.process_edge();
        };
        self.finish(stop)
    }

    /// Draws the next batch and queues every vertex. `Ok(Some(stop))` when the iteration limit
    /// was reached while drawing (the batch is still searched); `Err` to stop at once.
    fn draw_batch(&mut self, best: f64) -> Result<Option<Stop>, Stop> {
        let (space, validity, goal) = (self.problem.space, self.problem.validity, &*self.problem.goal);
        let mut limit = None;
        let first_new = self.graph.len() as u32;
        if self.goal_samples == 0 || (goal.focus().is_none() && self.goal_samples < MAX_GOAL_SAMPLES) {
            if let Some(state) = goal.sample(space, &mut self.run.rng) {
                self.run.stats.collision_checks += 1;
                if admit(space, validity, &state).is_ok() {
                    self.graph.add_sample(space, &self.set, state);
                }
            }
            self.goal_samples += 1;
        }
        for _ in 0..self.planner.options.batch_size {
            match self.run.watch.next_iteration() {
                None => {}
                Some(Stop::IterationLimit) => {
                    limit = Some(Stop::IterationLimit);
                    break;
                }
                Some(stop) => return Err(stop),
            }
            if let Some(state) =
                self.set.sample(&mut self.run, space, validity, &self.planner.sampler, best)?
            {
                self.run.stats.collision_checks += 1;
                if validity.state_is_valid(space, &state) {
                    self.graph.add_sample(space, &self.set, state);
                }
            }
        }
        self.graph.tidy(space);
        let n = self.graph.len();
        let d = space.dimension().max(1) as f64;
        let k_rgg = self.planner.options.rewire_factor * std::f64::consts::E * (1.0 + 1.0 / d);
        self.k = ((k_rgg * (n.max(2) as f64).ln()).ceil() as usize).clamp(1, n.max(1));
        // A vertex whose cost fell since its edges were queued is expanded again; the others
        // meet only the new samples, each of which finds its nearest vertices.
        for v in 0..n {
            if self.graph.in_tree[v] && self.graph.cost[v] < self.graph.expanded_at[v] {
                self.queue_vertex(v as u32);
            }
        }
        for x in first_new..n as u32 {
            // A batch may be large: its queries answer to the clock too.
            if (x - first_new) % 64 == 63
                && let Some(stop) = self.run.watch.interrupted()
            {
                return Err(stop);
            }
            self.queue_to_sample(x, best);
        }
        Ok(limit)
    }

    fn queue_vertex(&mut self, v: u32) {
        let g = self.graph.cost[v as usize];
        self.vertices.push(Entry { key: [g + self.graph.go[v as usize], g], from: v, to: v });
    }

    /// Queues the edges out of vertex `v` that could improve the solution: to its nearest
    /// samples, and to its nearest vertices it would bring closer to the start.
    fn expand(&mut self, v: u32) {
        let (space, best) = (self.problem.space, self.best_cost());
        self.graph.expanded_at[v as usize] = self.graph.cost[v as usize];
        let graph = &self.graph;
        let (vi, gv, come) = (v as usize, graph.cost[v as usize], graph.come[v as usize]);
        let state = graph.state(v);
        let samples = graph.nearest(space, state, self.k, Direction::FromQuery, false);
        // Vertices only where `v` brings them closer to the start (rewiring).
        let vertices = graph
            .nearest(space, state, self.k + 1, Direction::FromQuery, true)
            .into_iter()
            .filter(|&(w, d)| {
                w != v
                    && graph.parent[vi] != w
                    && graph.parent[w as usize] != v
                    && gv + d < graph.cost[w as usize]
            });
        for (x, d) in samples.into_iter().chain(vertices) {
            let go = graph.go[x as usize];
            if come + d + go < best && gv + d + go < best {
                self.edges.push(Entry { key: [gv + d + go, gv + d], from: v, to: x });
            }
        }
    }

    /// Queues the edges from the nearest vertices of the new sample `x` whose edges were
    /// queued before and whose cost has not fallen since (the others expand in full).
    fn queue_to_sample(&mut self, x: u32, best: f64) {
        let (space, graph) = (self.problem.space, &self.graph);
        let near = graph.nearest(space, graph.state(x), self.k, Direction::ToQuery, true);
        let go = graph.go[x as usize];
        for (v, d) in near {
            let vi = v as usize;
            let gv = graph.cost[vi];
            if gv < graph.expanded_at[vi] || graph.come[vi] + d + go >= best || gv + d + go >= best {
                continue;
            }
            self.edges.push(Entry { key: [gv + d + go, gv + d], from: v, to: x });
        }
    }

    /// Expands the vertices whose key is no worse than the best edge's, then processes the
    /// best edge; `Some` when the run reached its target cost.
    fn process_edge(&mut self) -> Option<Stop> {
        let best = self.best_cost();
        while let Some(top) = self.vertices.peek().copied() {
            if self.edges.peek().is_some_and(|e| e.key[0] < top.key[0]) {
                break;
            }
            self.vertices.pop();
            if top.key[0] >= best {
                // Its edges cost at least its key (ĥ is consistent), and so do the rest's.
                self.vertices.clear();
                break;
            }
            if self.graph.cost[top.from as usize] < self.graph.expanded_at[top.from as usize] {
                self.expand(top.from);
            }
        }
        let edge = self.edges.pop()?;
        let (space, validity, goal) = (self.problem.space, self.problem.validity, &*self.problem.goal);
        let (v, x) = (edge.from, edge.to);
        let (vi, xi) = (v as usize, x as usize);
        let (from, to) = (self.graph.state(v), self.graph.state(x));
        let d = space.distance(from, to);
        let through = self.graph.cost[vi] + d;
        if through + self.graph.go[xi] >= best {
            // The least key cannot improve the solution (every vertex whose cost fell was queued
            // again at its new key), nor can any after it: the batch is over.
            self.edges.clear();
            self.vertices.clear();
            return None;
        }
        if through >= self.graph.cost[xi] || self.invalid.contains(&(v, x)) {
            return None;
        }
        self.run.stats.collision_checks += 1;
        if !validity.motion_is_valid(space, from, to) {
            self.invalid.insert((v, x));
            if S::SYMMETRIC {
                self.invalid.insert((x, v));
            }
            return None;
        }
        if self.graph.in_tree[xi] {
            // Every descendant's cost fell with it: their edges are queued again at their keys.
            let mut lowered = std::mem::take(&mut self.lowered);
            self.graph.rewire(x, v, through, &mut lowered);
            for &u in &lowered {
                self.queue_vertex(u);
            }
            self.lowered = lowered;
        } else {
            self.graph.join(space, goal, x, v, through);
            self.queue_vertex(x);
        }
        self.improved()
    }

    /// The plan of a run that stopped for `stop`, and the graph to keep.
    fn finish(mut self, stop: Stop) -> (BatchGraph<S, N>, Plan<S::State>) {
        let space = self.problem.space;
        let vertices = self.graph.vertex_count();
        self.run.stats.tree_sizes = [vertices, self.graph.len() - vertices];
        let (end, goal_distance) = match self.graph.best() {
            Some((g, _)) => (g, None),
            None => (self.graph.closest.0, Some(self.graph.closest.1)),
        };
        let path = self.graph.branch(end);
        (self.graph, self.run.finish(space, path, goal_distance, stop))
    }
}

#[cfg(test)]
mod tests {
    use trailmark_core::geometry::Point;
    use trailmark_core::termination::{Stop, Termination};
    use trailmark_core::world::{Bounds, PolygonWorld};

    use crate::test_worlds::{Block, block};
    use crate::{BitOptions, BitStar, GoalState, KdNearest, PlanError, Planner, Problem, R2, Rn, paths};

    /// Around a block whose optimum is known: within 1% on every seed in 2,000 samples, every
    /// path valid, improvements in order, the samples counted as iterations.
    #[test]
    fn reaches_the_optimum_around_a_block() {
        let Block { space, checker, start, goal, optimum: best } = block();
        let problem = Problem::new(&space, &checker, start, goal);
        let nearest = KdNearest::<R2, 2>::new(&space).unwrap();
        for seed in 0..10 {
            let plan = BitStar::new(nearest.clone())
                .with_seed(seed)
                .solve(&problem, &Termination::iterations(2000))
                .unwrap();
            let path = plan.path().expect("solved");
            assert!(paths::check(&space, &checker, path).is_ok());
            assert_eq!((path[0], *path.last().unwrap()), (start, goal));
            let cost = plan.cost().unwrap();
            assert!((best - 1e-9..1.01 * best).contains(&cost), "seed {seed}: {cost}");
            assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost));
            assert_eq!(plan.stats.iterations, 2000);
            assert_eq!(plan.stop, Stop::IterationLimit);
        }
    }

    /// The same seed, the same run; a target cost ends the run at the edge that reaches it.
    #[test]
    fn seeds_repeat_and_a_target_cost_stops() {
        let Block { space, checker, start, goal, optimum: best } = block();
        let problem = Problem::new(&space, &checker, start, goal);
        let mut planner = BitStar::new(KdNearest::<R2, 2>::new(&space).unwrap()).with_seed(5);
        let limit = Termination::iterations(1000);
        let (a, b) = (planner.solve(&problem, &limit).unwrap(), planner.solve(&problem, &limit).unwrap());
        assert_eq!(a.solution, b.solution);
        let target = Termination::iterations(100_000).and_target_cost(1.05 * best);
        let plan = planner.solve(&problem, &target).unwrap();
        assert_eq!(plan.stop, Stop::TargetCost);
        assert!(plan.cost().unwrap() <= 1.05 * best);
        assert!(plan.stats.iterations < 100_000);
    }

    /// In an empty R⁴: the straight line to a goal state, and near it to a goal ball (whose
    /// inside few samples reach: the plan ends at its centre or at one of them).
    #[test]
    fn nears_the_straight_line_in_four_dimensions() {
        let space = Rn::<4>::new([0.0; 4], [1.0; 4]).unwrap();
        let validity = crate::Sampled::new(|_: &nalgebra::SVector<f64, 4>| true, 0.01).unwrap();
        let (a, b) = (nalgebra::SVector::from([0.1; 4]), nalgebra::SVector::from([0.9, 0.8, 0.9, 0.7]));
        let nearest = KdNearest::<Rn<4>, 4>::new(&space).unwrap();
        for (tolerance, within) in [(0.0, 1.01), (0.05, 1.1)] {
            let problem = Problem::with_goal(&space, &validity, a, GoalState::within(b, tolerance));
            let limit = Termination::iterations(3000);
            let plan = BitStar::new(nearest.clone()).with_seed(2).solve(&problem, &limit).unwrap();
            let straight = (b - a).norm() - tolerance;
            let cost = plan.cost().expect("solved");
            assert!(cost >= straight - 1e-9 && cost < within * straight, "{cost} against {straight}");
            assert!((plan.path().unwrap().last().unwrap() - b).norm() <= tolerance + 1e-12);
        }
    }

    /// Settings out of range are refused before the run.
    #[test]
    fn refuses_bad_options() {
        let Block { space, checker, start, goal, .. } = block();
        let problem = Problem::new(&space, &checker, start, goal);
        let nearest = KdNearest::<R2, 2>::new(&space).unwrap();
        for options in [
            BitOptions { batch_size: 0, ..BitOptions::default() },
            BitOptions { batch_size: crate::MAX_BATCH_SIZE + 1, ..BitOptions::default() },
            BitOptions { rewire_factor: 0.0, ..BitOptions::default() },
            BitOptions { rewire_factor: f64::NAN, ..BitOptions::default() },
        ] {
            let found = BitStar::new(nearest.clone())
                .with_options(options)
                .solve(&problem, &Termination::iterations(10));
            assert!(matches!(found, Err(PlanError::InvalidOption { .. })), "{options:?}: {found:?}");
        }
    }

    /// Behind a wall that closes the room, no solution: the plan ends nearest the goal.
    #[test]
    fn approximates_when_the_goal_is_walled_off() {
        let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        let wall =
            vec![Point::new(6.0, 0.0), Point::new(7.0, 0.0), Point::new(7.0, 10.0), Point::new(6.0, 10.0)];
        let checker = PolygonWorld::new(bounds, vec![wall], 0.0).unwrap().checker();
        let space = R2::new(bounds);
        let problem = Problem::new(&space, &checker, Point::new(1.0, 5.0), Point::new(9.0, 5.0));
        let plan = BitStar::new(KdNearest::<R2, 2>::new(&space).unwrap())
            .solve(&problem, &Termination::iterations(500))
            .unwrap();
        match plan.solution {
            crate::Solution::Approximate { path, goal_distance, .. } => {
                assert!(paths::check(&space, &checker, &path).is_ok());
                assert!(goal_distance < 3.5, "{goal_distance}");
            }
            other => panic!("{other:?}"),
        }
    }
}
