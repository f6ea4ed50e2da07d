//! PRM and PRM* (Kavraki et al. 1996; Karaman and Frazzoli 2011) over any [`StateSpace`]: a
//! roadmap of valid states joined by valid motions, kept across queries.
//!
//! Each milestone is a sample the validity accepts, joined to its neighbours by the space's own
//! distance (for an asymmetric space such as Dubins, motions into it from the states nearest
//! before it and out of it to the states nearest after it): the `k` nearest, those within a
//! radius, or PRM*'s k = ⌈e (1 + 1/d) ln n⌉. Every motion is checked by the validity; nearest
//! neighbours come from the planner's [`NearestNeighbors`] structure, exact in every space.
//!
//! As a [`Planner`], a run adds the problem's starts and goal states as milestones and grows the
//! roadmap until a start and a goal state are in one connected component; then A*
//! (`trailmark-search`) finds the shortest path through the roadmap. PRM stops there; PRM*
//! ([`Prm::star`]) goes on growing until its termination, searching again as the roadmap grows
//! and recording each cheaper path. The roadmap stays for the next query (multi-query, as OMPL's
//! PRM) until [`clear`](Planner::clear): queries must share the space and the validity the
//! roadmap was checked with; clear it when the world changes (its edges are not checked again).
//! A run that stops before a start and a goal connect returns [`Solution::None`](crate::Solution::None), as OMPL's PRM
//! does.
//!
//! The roadmap is a graph of the core traits (milestone ids; edges cost their motion's distance,
//! a lazy roadmap's unchecked ones included), so any search of `trailmark-search` runs on it.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Prm, Problem, R2};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let mut prm = Prm::star(KdNearest::<R2, 2>::new(&space)?).with_seed(3);
//! // Two queries on one roadmap: the second reuses what the first grew.
//! let first = prm.solve(&Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0)),
//!                       &Termination::iterations(1_000))?;
//! let grown = prm.node_count();
//! let second = prm.solve(&Problem::new(&space, &checker, Point::new(1.0, 5.0), Point::new(9.0, 5.0)),
//!                        &Termination::iterations(200))?;
//! assert!(first.cost().unwrap() >= 2.0 * (9.0f64 + 7.25 * 7.25).sqrt() + 2.0 - 1e-9); // over the wall
//! assert!(second.is_exact() && prm.node_count() >= grown);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::marker::PhantomData;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use trailmark_core::UnionFind;
use trailmark_core::cost::Cost;
use trailmark_search::Search;

use crate::nearest::{Direction, NearestNeighbors};
use crate::plan::{Plan, PlanError, Rejection};
use crate::planner::Planner;
use crate::problem::{Problem, admit};
use crate::run::Run;
use crate::sampler::{Draw, StateSampler, Uniform};
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Stop;
use trailmark_core::termination::{Termination, Watch};
pub use trailmark_space::Connection;

/// What [`Prm::grow`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Growth {
    /// `None` when the roadmap has the milestones asked for; else why the termination stopped
    /// it first.
    pub stop: Option<Stop>,
    /// The state and motion checks made.
    pub collision_checks: u64,
}

/// The most milestones a goal region adds, as for RRT-Connect's goal tree.
const MAX_GOAL_STATES: usize = 64;

/// The goal samples refused before the first goal milestone, after which the goal is refused.
const FIRST_GOAL_ATTEMPTS: usize = 1_000;

/// The roadmap grows this much (as a share of its milestones) between two searches of PRM*.
const SEARCH_GROWTH: f64 = 0.1;

/// A probabilistic roadmap planner; see the [module](self) documentation.
#[derive(Debug, Clone)]
pub struct Prm<S: StateSpace, N, Q = Uniform> {
    empty: N,
    nearest: N,
    pub(super) sampler: Q,
    connection: Connection,
    optimizing: bool,
    seed: u64,
    pub(super) rng: Option<ChaCha8Rng>,
    /// The motions out of each milestone, with their costs: the free ones, and the blocked ones
    /// (at infinite cost) in a roadmap that [`keeps_blocked`](Self::keeps_blocked).
    pub(super) out: Vec<Vec<(u32, Cost)>>,
    /// The motions into each milestone (asymmetric spaces only).
    pub(super) into: Vec<Vec<(u32, Cost)>>,
    /// Every motion tried, in order, in a roadmap whose world changes; empty otherwise.
    pub(super) tried: Vec<Candidate>,
    keeps_blocked: bool,
    /// Lazy PRM: motions are checked only on a path a search found ([`super::lazy`]).
    pub(super) lazy: bool,
    /// The motions a lazy roadmap has checked and found free.
    pub(super) verified: std::collections::HashSet<(u32, u32)>,
    pub(super) edge_count: usize,
    pub(super) components: UnionFind,
    pub(super) checks: u64,
    _space: PhantomData<fn() -> S>,
}

/// A motion a roadmap tried: free (an edge) or blocked (kept so that a change of the world can
/// free it).
#[derive(Clone, Copy, Debug)]
pub(super) struct Candidate {
    /// Tail and head (for a symmetric space, the two ends).
    pub(super) ends: [u32; 2],
    /// The motion's cost while free; infinite while blocked.
    pub(super) cost: Cost,
}

impl<S: StateSpace, N: NearestNeighbors<S> + Clone> Prm<S, N> {
    /// PRM with its milestones in (a clone of) `nearest`, which must be empty: joined to their
    /// 10 nearest neighbours, uniform samples, seed 0. It stops at the first path.
    pub fn new(nearest: N) -> Self {
        Prm::empty(nearest.clone(), nearest, Uniform, Connection::Nearest { k: 10 }, false, 0)
    }

    /// PRM*: PRM*'s connection, improving its path until the termination.
    pub fn star(nearest: N) -> Self {
        Prm { connection: Connection::PrmStar, optimizing: true, ..Prm::new(nearest) }
    }
}

impl<S: StateSpace, N: NearestNeighbors<S> + Clone, Q> Prm<S, N, Q> {
    /// The same planner drawing its milestones from `sampler` (the roadmap is cleared).
    pub fn with_sampler<R>(self, sampler: R) -> Prm<S, N, R> {
        let mut prm =
            Prm::empty(self.empty, self.nearest, sampler, self.connection, self.optimizing, self.seed);
        prm.lazy = self.lazy;
        prm.reset();
        prm
    }

    /// A planner with these settings and no roadmap yet.
    fn empty(empty: N, nearest: N, sampler: Q, connection: Connection, optimizing: bool, seed: u64) -> Self {
        Prm {
            empty,
            nearest,
            sampler,
            connection,
            optimizing,
            seed,
            rng: None,
            out: Vec::new(),
            into: Vec::new(),
            tried: Vec::new(),
            keeps_blocked: false,
            lazy: false,
            verified: Default::default(),
            edge_count: 0,
            components: UnionFind::default(),
            checks: 0,
            _space: PhantomData,
        }
    }

    /// The same planner joining milestones by `connection` (the roadmap is cleared); a
    /// connection out of range is refused when a run starts.
    pub fn with_connection(mut self, connection: Connection) -> Self {
        self.connection = connection;
        self.reset();
        self
    }

    /// The same planner seeded with `seed` (the roadmap is cleared).
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self.reset();
        self
    }

    /// The milestones.
    pub fn node_count(&self) -> usize {
        self.nearest.len()
    }

    /// The edges (each undirected edge once; a lazy roadmap's unchecked ones too).
    pub fn edge_count(&self) -> usize {
        self.edge_count
    }

    /// The connected components (ignoring direction; a lazy roadmap's count unchecked motions).
    pub fn component_count(&self) -> usize {
        self.components.set_count()
    }

    /// The state of milestone `id`.
    ///
    /// # Panics
    ///
    /// If `id` is not below [`node_count`](Self::node_count).
    pub fn state(&self, id: u32) -> &S::State {
        self.nearest.state(id)
    }

    /// The edges out of milestone `id`, with their costs (a planner's roadmap keeps free
    /// motions only; a lazy one, also those not checked yet).
    pub fn edges_from(&self, id: u32) -> &[(u32, Cost)] {
        &self.out[id as usize]
    }

    /// Grows the roadmap to `milestones` milestones before any query (OMPL's `growRoadmap`),
    /// from the roadmap's own sample stream, which later queries go on with. It stops early if
    /// `termination` (which must be bounded: the free space may be empty) says so; what it grew
    /// stays either way.
    pub fn grow<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        milestones: usize,
        termination: &Termination,
    ) -> Result<Growth, PlanError>
    where
        Q: StateSampler<S>,
    {
        self.check_connection()?;
        if !termination.is_bounded() {
            return Err(PlanError::NoLimit);
        }
        let mut watch = Watch::start(termination);
        let mut rng = self.rng.take().unwrap_or_else(|| ChaCha8Rng::seed_from_u64(self.seed));
        let mut checks = 0;
        let stop = loop {
            if self.node_count() >= milestones {
                break None;
            }
            if let Some(stop) = watch.next_iteration() {
                break Some(stop);
            }
            let mut draw = Draw::watched(&mut rng, &mut checks, &watch);
            let Some(state) = self.sampler.sample(space, validity, &mut draw) else {
                match watch.interrupted() {
                    Some(stop) => break Some(stop),
                    None => continue,
                }
            };
            checks += 1;
            if admit(space, validity, &state).is_ok() {
                self.add(space, validity, state, &watch);
            }
        };
        self.rng = Some(rng);
        let collision_checks = checks + std::mem::take(&mut self.checks);
        Ok(Growth { stop, collision_checks })
    }

    /// Adds `state` as a milestone joined to its neighbours, as a run adds its starts and goals
    /// (OMPL's `addMilestone`); its id, or the id of the milestone already there. A state that
    /// is not finite, in bounds and valid is refused.
    pub fn insert<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        state: S::State,
    ) -> Result<u32, Rejection> {
        admit(space, validity, &state)?;
        let unlimited = Termination::default();
        let id = self.add(space, validity, state, &Watch::start(&unlimited));
        Ok(id)
    }

    /// Forgets the roadmap (as [`Planner::clear`]).
    pub fn clear(&mut self) {
        self.reset();
    }

    fn reset(&mut self) {
        self.nearest = self.empty.clone();
        self.rng = None;
        self.out.clear();
        self.into.clear();
        self.tried.clear();
        self.verified.clear();
        self.edge_count = 0;
        self.components = UnionFind::default();
        self.checks = 0;
    }

    fn check_connection(&self) -> Result<(), PlanError> {
        match self.connection {
            Connection::Nearest { k: 0 } => {
                Err(PlanError::InvalidOption { name: "k", expected: "at least 1", value: 0.0 })
            }
            Connection::Radius { radius } if !(radius.is_finite() && radius > 0.0) => {
                Err(PlanError::InvalidOption {
                    name: "radius",
                    expected: "positive and finite",
                    value: radius,
                })
            }
            _ => Ok(()),
        }
    }

    /// The milestone at exactly `state`, if any.
    pub(super) fn find(&self, space: &S, state: &S::State) -> Option<u32> {
        let (id, d) = self.nearest.nearest(space, state, Direction::ToQuery)?;
        (d == 0.0 && self.nearest.state(id) == state).then_some(id)
    }

    /// The milestones a state joins, in `direction`, in a roadmap of `n` milestones (counting
    /// it), nearest first.
    pub(super) fn neighbours(
        &self,
        space: &S,
        state: &S::State,
        direction: Direction,
        n: usize,
    ) -> Vec<(u32, f64)> {
        match self.connection.neighbour_count(n, space.dimension()) {
            Some(k) => self.nearest.k_nearest(space, state, k, direction),
            None => {
                let Connection::Radius { radius } = self.connection else { unreachable!("a radius rule") };
                self.nearest.within(space, state, radius, direction)
            }
        }
    }

    /// Adds the admitted `state` as a milestone joined to its neighbours (motion checks stop
    /// when `watch` is interrupted); its id, or the id of the milestone already there.
    fn add<V: Validity<S>>(&mut self, space: &S, validity: &V, state: S::State, watch: &Watch<'_>) -> u32 {
        let (lazy, checks) = (self.lazy, self.checks);
        let motion = |from: &S::State, to: &S::State, d: f64| {
            (lazy || validity.motion_is_valid(space, from, to)).then_some(d)
        };
        let (id, _) = self
            .add_checked(space, state, usize::MAX, motion, || watch.interrupted().is_some())
            .expect("no limit");
        if lazy {
            self.checks = checks; // no motion was checked
        }
        id
    }

    /// Adds `state` as a milestone joined to its neighbours, each motion's cost given by
    /// `motion` (from, to, their distance; `None` when blocked) until `interrupted`: its id and
    /// `true`, or the id of the milestone already at `state` and `false`; `None` if the roadmap
    /// already has `limit` milestones.
    pub(super) fn add_checked(
        &mut self,
        space: &S,
        state: S::State,
        limit: usize,
        mut motion: impl FnMut(&S::State, &S::State, f64) -> Option<Cost>,
        interrupted: impl Fn() -> bool,
    ) -> Option<(u32, bool)> {
        let n = self.node_count() + 1;
        let into = self.neighbours(space, &state, Direction::ToQuery, n);
        // A milestone at `state` is at distance 0, so it leads the neighbours (every rule keeps
        // the nearest once the roadmap has a milestone).
        let mut at_zero = into.iter().take_while(|&&(_, d)| d == 0.0);
        if let Some(&(v, _)) = at_zero.find(|&&(v, _)| *self.nearest.state(v) == state) {
            return Some((v, false));
        }
        if self.node_count() >= limit {
            return None;
        }
        let out =
            if S::SYMMETRIC { Vec::new() } else { self.neighbours(space, &state, Direction::FromQuery, n) };
        let id = self.push(space, state);
        let ends = into.into_iter().map(|(v, d)| (v, id, d)).chain(out.into_iter().map(|(v, d)| (id, v, d)));
        for (from, to, d) in ends {
            if interrupted() {
                break;
            }
            self.checks += 1;
            let cost = motion(self.nearest.state(from), self.nearest.state(to), d);
            self.record(from, to, cost);
        }
        Some((id, true))
    }

    /// Stores `state` as a new milestone without edges (its own component); its id.
    pub(super) fn push(&mut self, space: &S, state: S::State) -> u32 {
        let id = self.nearest.insert(space, state);
        self.out.push(Vec::new());
        if !S::SYMMETRIC {
            self.into.push(Vec::new());
        }
        self.components.push();
        id
    }

    /// Records the motion `from -> to`: an edge of cost `cost` (both ways in a symmetric
    /// space), or, when blocked, nothing unless the roadmap keeps blocked motions.
    pub(super) fn record(&mut self, from: u32, to: u32, cost: Option<Cost>) {
        if cost.is_none() && !self.keeps_blocked {
            return;
        }
        let cost = cost.unwrap_or(Cost::INFINITY);
        if self.keeps_blocked {
            self.tried.push(Candidate { ends: [from, to], cost });
        }
        self.out[from as usize].push((to, cost));
        if S::SYMMETRIC {
            self.out[to as usize].push((from, cost));
        } else {
            self.into[to as usize].push((from, cost));
        }
        if cost.is_finite() {
            self.edge_count += 1;
            self.components.union(from, to);
        }
    }

    /// Keeps every motion tried from now on, blocked ones too, for a roadmap whose world
    /// changes ([`set_cost`](Self::set_cost)).
    pub(super) fn keep_blocked(&mut self) {
        self.keeps_blocked = true;
    }

    /// Sets the cost of the tried motion `id` (infinite: blocked), in both directions of a
    /// symmetric space; the components are rebuilt by [`rebuild_components`](Self::rebuild_components).
    pub(super) fn set_cost(&mut self, id: usize, cost: Cost) {
        let candidate = &mut self.tried[id];
        let [from, to] = candidate.ends;
        match (candidate.cost.is_finite(), cost.is_finite()) {
            (true, false) => self.edge_count -= 1,
            (false, true) => self.edge_count += 1,
            _ => {}
        }
        candidate.cost = cost;
        let set = |list: &mut Vec<(u32, Cost)>, other: u32| {
            if let Some(entry) = list.iter_mut().find(|(v, _)| *v == other) {
                entry.1 = cost;
            }
        };
        set(&mut self.out[from as usize], to);
        if S::SYMMETRIC {
            set(&mut self.out[to as usize], from);
        } else {
            set(&mut self.into[to as usize], from);
        }
    }

    /// The components again from the free motions tried (after [`set_cost`](Self::set_cost)).
    pub(super) fn rebuild_components(&mut self) {
        self.components = UnionFind::new(self.node_count());
        for &Candidate { ends: [a, b], cost } in &self.tried {
            if cost.is_finite() {
                self.components.union(a, b);
            }
        }
    }

    /// A representative of milestone `id`'s component (ignoring direction).
    pub(super) fn component(&self, id: u32) -> u32 {
        self.components.root(id)
    }

    /// Whether a start and a goal milestone share a component.
    fn connects(&mut self, starts: &[u32], goals: &[u32]) -> bool {
        let roots: Vec<u32> = starts.iter().map(|&s| self.components.find(s)).collect();
        goals.iter().any(|&g| {
            let r = self.components.find(g);
            roots.contains(&r)
        })
    }

    /// Searches the roadmap; keeps the path found in `best` if it is cheaper.
    fn improve<V: Validity<S>>(
        &mut self,
        (space, validity): (&S, &V),
        (starts, goals): (&[u32], &[u32]),
        best: &mut Option<(Vec<u32>, f64)>,
        run: &mut Run<'_>,
    ) {
        let found = if self.lazy {
            self.search_checked(space, validity, (starts, goals), || run.watch.interrupted().is_some())
        } else {
            self.search(space, starts, goals)
        };
        if let Some(found) = found
            && best.as_ref().is_none_or(|b| found.1 < b.1)
        {
            run.improved(found.1);
            *best = Some(found);
        }
    }

    /// The cheapest path from a start to a goal milestone through the roadmap, as milestone
    /// ids and cost.
    pub(super) fn search(&mut self, space: &S, starts: &[u32], goals: &[u32]) -> Option<(Vec<u32>, f64)> {
        let mut best: Option<(Vec<u32>, f64)> = None;
        let mut search = Search::new();
        for &g in goals {
            for &s in starts {
                if self.components.find(s) != self.components.find(g) {
                    continue;
                }
                let goal = self.nearest.state(g).clone();
                let heuristic = |n: u32| space.distance(self.nearest.state(n), &goal);
                let Ok(found) = search.astar(&*self, s, g, heuristic) else { continue };
                if let Some(path) = found.path
                    && best.as_ref().is_none_or(|b| path.cost < b.1)
                {
                    best = Some((path.nodes, path.cost));
                }
            }
        }
        best
    }
}

impl<S, V, N, Q> Planner<S, V> for Prm<S, N, Q>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
{
    fn name(&self) -> &str {
        ["PRM", "PRM*", "Lazy PRM", "Lazy PRM*"][2 * usize::from(self.lazy) + usize::from(self.optimizing)]
    }

    fn solve(
        &mut self,
        problem: &Problem<'_, S, V>,
        termination: &Termination,
    ) -> Result<Plan<S::State>, PlanError> {
        let (space, validity, goal) = (problem.space, problem.validity, &*problem.goal);
        self.check_connection()?;
        crate::run::check_empty(&self.empty)?;
        let mut run = Run::checked(problem, Watch::start(termination), f64::INFINITY, self.seed)?;
        // The roadmap's own stream of samples goes on from one query to the next.
        let mut rng = self.rng.take().unwrap_or_else(|| ChaCha8Rng::seed_from_u64(self.seed));
        let starts: Vec<u32> =
            problem.starts.iter().map(|s| self.add(space, validity, s.clone(), &run.watch)).collect();
        let mut goals: Vec<u32> = Vec::new();
        let (mut refused, mut exhausted) = (0, false);
        let mut best: Option<(Vec<u32>, f64)> = None;
        let mut searched_at = 0usize;
        // The components when the roadmap was last searched: before the first path, a search
        // pays only once a start and a goal may have been joined (in a directed roadmap a shared
        // component does not yet mean a path, so the components, not just the ends, decide).
        let mut searched_components = usize::MAX;
        let stop = loop {
            // Goal milestones: one at first, then more from a region while they are fewer than
            // half the roadmap.
            if !exhausted
                && (goals.is_empty()
                    || (goals.len() < MAX_GOAL_STATES && 2 * goals.len() < self.node_count()))
            {
                match goal.sample(space, &mut rng) {
                    None => exhausted = true,
                    // A goal that gives the same state again has no others (a goal state).
                    Some(state) if goals.last().is_some_and(|&g| *self.nearest.state(g) == state) => {
                        exhausted = true;
                    }
                    Some(state) => {
                        run.stats.collision_checks += 1;
                        if admit(space, validity, &state).is_ok() {
                            let id = self.add(space, validity, state, &run.watch);
                            if !goals.contains(&id) {
                                goals.push(id);
                            }
                        } else {
                            refused += 1;
                        }
                    }
                }
            }
            if goals.is_empty() {
                if exhausted {
                    self.rng = Some(rng);
                    return Err(PlanError::GoalNotSampleable { planner: "PRM" });
                }
                if refused >= FIRST_GOAL_ATTEMPTS {
                    self.rng = Some(rng);
                    return Err(PlanError::InvalidGoal(Rejection::Invalid));
                }
            }
            // Search when a start and a goal share a component, and for PRM* again each time
            // the roadmap has grown by a tenth.
            let changed = self.lazy || self.components.set_count() != searched_components;
            let joined = changed && self.connects(&starts, &goals);
            let grown = self.node_count() as f64 >= searched_at as f64 * (1.0 + SEARCH_GROWTH);
            let due = if best.is_none() { joined && (S::SYMMETRIC && !self.lazy || grown) } else { grown };
            if due && !goals.is_empty() && run.watch.interrupted().is_none() {
                searched_at = self.node_count();
                self.improve((space, validity), (&starts, &goals), &mut best, &mut run);
                searched_components = self.components.set_count(); // a lazy search may split some
            }
            if best.is_some() && !self.optimizing {
                break Stop::Solved;
            }
            if let Some(stop) = run.watch.next_iteration() {
                break stop;
            }
            std::mem::swap(&mut run.rng, &mut rng);
            let sample = run.sample(space, validity, &self.sampler);
            std::mem::swap(&mut run.rng, &mut rng);
            let state = match sample {
                Ok(Some(state)) => state,
                Ok(None) => continue,
                Err(stop) => break stop,
            };
            run.stats.collision_checks += 1;
            if admit(space, validity, &state).is_ok() {
                self.add(space, validity, state, &run.watch);
            }
        };
        // A last search, so that what PRM* grew since its last one counts; not past a time
        // limit or the caller's word (a search of a large roadmap takes milliseconds).
        let timed = matches!(stop, Stop::TimeLimit | Stop::Caller);
        let last = self.optimizing || self.lazy && best.is_none(); // Lazy PRM: a path may be there
        if last && !timed && !goals.is_empty() && searched_at < self.node_count() {
            self.improve((space, validity), (&starts, &goals), &mut best, &mut run);
        }
        self.rng = Some(rng);
        run.stats.collision_checks += self.checks;
        self.checks = 0;
        run.stats.tree_sizes = [self.node_count(), 0];
        Ok(match best {
            Some((nodes, _)) => {
                let path = nodes.iter().map(|&n| self.nearest.state(n).clone()).collect();
                run.finish(space, path, None, stop)
            }
            None => run.nothing(stop),
        })
    }

    fn clear(&mut self) {
        self.reset();
    }

    fn set_seed(&mut self, seed: u64) {
        self.seed = seed;
        self.reset();
    }

    fn optimizes(&self) -> bool {
        self.optimizing
    }
}
