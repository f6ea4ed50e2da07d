//! Probabilistic roadmaps: samples in free space joined by collision-free local paths.
//!
//! A [`Prm`] draws configurations in the free space of a [`PolygonWorld`] (seeded uniform
//! samples, or a deterministic Halton sequence), and joins each new node to its neighbours
//! among the nodes already there (the k nearest, those within a radius, or PRM*'s
//! k = ⌈e(1 + 1/d) ln n⌉) wherever the local path between them is collision-free. Every local
//! path is checked exactly against the obstacles by the world's [`CollisionChecker`] (segment
//! and arc distances, not sampling); nearest neighbours come from a k-d tree (kiddo).
//!
//! The states, motions and distances are a state space of `trailmark-sample` ([`PlanarSpace`]):
//! [`R2`] segments for a disc robot (an undirected
//! roadmap over points), or [`Dubins`](trailmark_sample::Dubins) curves for a car-like robot (a directed roadmap
//! over poses, since a Dubins path from `a` to `b` is not the reverse of one from `b` to `a`).
//!
//! A roadmap grows incrementally ([`Prm::grow`], [`Prm::insert`]), tracks its connected
//! components, saves and loads with serde (re-checking everything it loads), reports which
//! edges changed when an obstacle is added or removed ([`Prm::add_obstacle`],
//! [`Prm::remove_obstacle`]) so D* Lite can repair its path, and answers queries without
//! changing ([`Prm::query`]).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_graph::prm::{Connection, Prm, PrmOptions, Sampler};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let world = PolygonWorld::new(bounds, vec![wall], 0.25)?;
//!
//! let options = PrmOptions { sampler: Sampler::Halton, connection: Connection::PrmStar, ..PrmOptions::default() };
//! let mut prm = Prm::new(world, options)?;
//! prm.grow(300)?;
//! assert_eq!(prm.node_count(), 300);
//!
//! let query = prm.query(Point::new(1.0, 1.0), Point::new(9.0, 1.0))?;
//! let route = trailmark_search::astar(&query, query.start(), query.goal(), query.heuristic())?;
//! let cost = route.cost().expect("the gap above the wall joins the two sides");
//! assert!(cost >= 14.5); // up past the wall's top (y = 8 + 0.25) and down again, at least
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt::Debug;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::geometry::Point;
use trailmark_core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::world::{CollisionChecker, PolygonWorld, WorldError};
use trailmark_sample::nearest::{Direction, KdNearest, NearestNeighbors};
use trailmark_sample::sampler::{Bridge, Draw, Gaussian, Halton, SamplerError, StateSampler, Uniform};
use trailmark_sample::space::{R2, SpaceError, UnitCube};
use trailmark_sample::validity::Validity;

pub use trailmark_sample::prm::Connection;

use crate::roadmap::{Roadmap, RoadmapQuery};

/// A state space a roadmap over a polygon world is built in: one whose states the world's exact
/// [`CollisionChecker`] checks ([`R2`] for a disc robot, [`Se2`](trailmark_sample::Se2),
/// [`Dubins`](trailmark_sample::Dubins) for a car), that maps the unit cube (for the Halton
/// sequence) and whose states are small values. Every such space of `trailmark-sample` is one.
pub trait PlanarSpace: UnitCube<State: Copy> + Clone + Debug {
    /// Whether the world of `checker` leaves `state` free.
    fn state_is_free(&self, checker: &CollisionChecker, state: &Self::State) -> bool;

    /// Whether the world of `checker` leaves the space's motion from `from` to `to` free.
    fn motion_is_free(&self, checker: &CollisionChecker, from: &Self::State, to: &Self::State) -> bool;
}

impl<S> PlanarSpace for S
where
    S: UnitCube<State: Copy> + Clone + Debug,
    CollisionChecker: Validity<S>,
{
    fn state_is_free(&self, checker: &CollisionChecker, state: &S::State) -> bool {
        checker.state_is_valid(self, state)
    }

    fn motion_is_free(&self, checker: &CollisionChecker, from: &S::State, to: &S::State) -> bool {
        checker.motion_is_valid(self, from, to)
    }
}

/// The world's checker as the samplers' validity.
struct Exact<'a>(&'a CollisionChecker);

impl<S: PlanarSpace> Validity<S> for Exact<'_> {
    fn state_is_valid(&self, space: &S, state: &S::State) -> bool {
        space.state_is_free(self.0, state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        space.motion_is_free(self.0, from, to)
    }
}

/// How samples are drawn: which of `trailmark-sample`'s samplers, with its settings.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sampler {
    /// Independent uniform samples ([`Uniform`]) from a ChaCha8 generator with this seed: the
    /// same seed gives the same roadmap on every machine.
    Uniform {
        /// The generator's seed.
        seed: u64,
    },
    /// The Halton sequence ([`Halton`]) in bases 2, 3 (and 5 for a heading): deterministic, and
    /// more even than independent samples.
    Halton,
    /// Near obstacles' surfaces ([`Gaussian`]), half the draws, the others uniform.
    Gaussian {
        /// The generator's seed.
        seed: u64,
        /// The standard deviation of the partner's distance.
        std_dev: f64,
    },
    /// In narrow passages ([`Bridge`], the bridge test), half the draws, the others uniform.
    Bridge {
        /// The generator's seed.
        seed: u64,
        /// The standard deviation of the partner's distance (about a passage's width).
        std_dev: f64,
    },
}

/// A [`Sampler`] made.
#[derive(Clone, Debug)]
enum Drawer {
    Uniform,
    Halton(Halton),
    Gaussian(Gaussian),
    Bridge(Bridge),
}

impl Drawer {
    fn new(sampler: Sampler) -> Result<Self, PrmError> {
        Ok(match sampler {
            Sampler::Uniform { .. } => Drawer::Uniform,
            Sampler::Halton => Drawer::Halton(Halton::new()),
            Sampler::Gaussian { std_dev, .. } => Drawer::Gaussian(Gaussian::new(std_dev)?),
            Sampler::Bridge { std_dev, .. } => Drawer::Bridge(Bridge::new(std_dev)?),
        })
    }
}

impl Sampler {
    /// The generator's seed (0 for the Halton sequence, which does not use it).
    fn seed(&self) -> u64 {
        match *self {
            Sampler::Uniform { seed } | Sampler::Gaussian { seed, .. } | Sampler::Bridge { seed, .. } => seed,
            Sampler::Halton => 0,
        }
    }
}

/// The settings of a [`Prm`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PrmOptions {
    /// How samples are drawn.
    pub sampler: Sampler,
    /// Which nodes a new node is joined to.
    pub connection: Connection,
    /// How many draws [`Prm::grow`] may make per sample asked for before it gives up (draws in
    /// obstacles are rejected).
    pub attempts_per_sample: u32,
}

impl Default for PrmOptions {
    /// Seed-0 uniform samples joined to their 10 nearest neighbours, 1000 draws per sample.
    fn default() -> Self {
        PrmOptions {
            sampler: Sampler::Uniform { seed: 0 },
            connection: Connection::Nearest { k: 10 },
            attempts_per_sample: 1000,
        }
    }
}

/// The most nodes a roadmap holds. Each node keeps its state, a few dozen edges and their
/// collision results, so ten million nodes take gigabytes; a larger request is refused with
/// [`PrmError::TooManyNodes`] before anything is drawn.
pub const MAX_NODES: usize = 10_000_000;

/// What went wrong building, growing, querying, changing or loading a roadmap.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrmError {
    /// `Connection::Nearest` needs at least one neighbour.
    #[error("a nearest-neighbour connection needs k >= 1")]
    InvalidK,
    /// A connection radius must be positive and finite.
    #[error("the connection radius must be positive and finite, got {0:?}")]
    InvalidRadius(f64),
    /// `attempts_per_sample` must be at least 1.
    #[error("attempts_per_sample must be at least 1")]
    InvalidAttempts,
    /// The space could not be made (a Dubins turning radius that is not positive and finite,
    /// or out of the solver's range for the bounds).
    #[error(transparent)]
    Space(#[from] SpaceError),
    /// A sampler setting out of its range.
    #[error(transparent)]
    Sampler(#[from] SamplerError),
    /// [`Prm::grow`] ran out of draws: the free space is empty or very small. The samples
    /// found were added.
    #[error("found only {added} of {requested} free samples in {attempts} draws")]
    SamplingExhausted {
        /// Samples asked for.
        requested: usize,
        /// Samples found and added.
        added: usize,
        /// Draws made.
        attempts: u64,
    },
    /// A configuration given to [`Prm::insert`] collides or leaves the bounds.
    #[error("the configuration {0:?} collides or is outside the bounds")]
    Blocked(Vec<f64>),
    /// A query's start collides or is outside the bounds.
    #[error("the start {0:?} collides or is outside the bounds")]
    StartBlocked(Vec<f64>),
    /// A query's goal collides or is outside the bounds.
    #[error("the goal {0:?} collides or is outside the bounds")]
    GoalBlocked(Vec<f64>),
    /// The roadmap would pass [`MAX_NODES`] nodes.
    #[error("a roadmap holds at most {max} nodes", max = MAX_NODES)]
    TooManyNodes,
    /// The world rejected an obstacle change.
    #[error(transparent)]
    World(#[from] WorldError),
    /// [`Prm::remove_obstacle`] named an obstacle that does not exist.
    #[error("there is no obstacle {index} (the world has {count})")]
    NoSuchObstacle {
        /// The index given.
        index: usize,
        /// The number of obstacles.
        count: usize,
    },
    /// A saved roadmap's node is malformed, collides, or repeats an earlier node.
    #[error("saved node {index} is malformed, collides, or repeats an earlier node")]
    InvalidNode {
        /// Its index.
        index: usize,
    },
    /// A saved roadmap's sample-stream position is not a decimal number.
    #[error("the saved stream position is not a decimal number")]
    InvalidStream,
    /// A saved roadmap's edge names a missing node, a loop, or a free/blocked state its local
    /// path does not have in this world.
    #[error("saved edge {index} names a missing node or a loop, or its free flag is wrong")]
    InvalidEdge {
        /// Its index.
        index: usize,
    },
}

/// An edge the roadmap tried: free (in the graph) or blocked (kept so an obstacle removal can
/// restore it).
#[derive(Clone, Copy, Debug)]
struct Candidate {
    /// Tail and head (for an undirected roadmap, the two ends).
    ends: [u32; 2],
    /// The local path's cost while free; infinite while blocked.
    cost: Cost,
}

/// The state of the sample stream, so a grown, saved and reloaded roadmap continues it.
#[derive(Clone, Debug)]
struct Stream {
    rng: ChaCha8Rng,
    drawer: Drawer,
    attempts: u64,
}

/// A probabilistic roadmap over a polygon world, in any [`PlanarSpace`]: [`R2`] (straight
/// segments for a disc robot, an undirected roadmap over points) by default, or
/// [`Dubins`](trailmark_sample::Dubins) (a directed roadmap over poses, since a Dubins path
/// from `a` to `b` is not the reverse of one from `b` to `a`). Node `i` is at
/// [`Prm::position`]; edges cost their motion's distance in the space.
///
/// It implements the graph traits itself (with permanent nodes from [`Prm::insert`]) and
/// [`Roadmap`], so [`Prm::query`] joins a start and a goal without changing it.
#[derive(Clone, Debug)]
pub struct Prm<S: PlanarSpace = R2> {
    checker: CollisionChecker,
    space: S,
    options: PrmOptions,
    nearest: KdNearest<S, 2>,
    candidates: Vec<Candidate>,
    /// Candidate ids leaving each node (both ends' lists when undirected).
    out: Vec<Vec<u32>>,
    /// Candidate ids entering each node (directed roadmaps only).
    into: Vec<Vec<u32>>,
    edge_count: usize,
    /// Union-find parents over free edges (ignoring direction).
    parent: Vec<u32>,
    components: usize,
    stream: Stream,
    local_paths_checked: u64,
}

/// A probabilistic roadmap of Dubins paths between poses.
pub type DubinsPrm = Prm<trailmark_sample::Dubins>;

/// A [`Prm`] with a start and a goal joined to it.
pub type PrmQuery<'g, S = R2> = RoadmapQuery<'g, Prm<S>>;

impl Prm<R2> {
    /// An empty roadmap of straight segments over `world` (the space [`R2`] of its bounds).
    pub fn new(world: PolygonWorld, options: PrmOptions) -> Result<Self, PrmError> {
        let space = R2::new(world.bounds());
        Self::with_space(world, space, options)
    }
}

impl<S: PlanarSpace> Prm<S> {
    /// An empty roadmap over `world` whose states and motions are `space`'s.
    pub fn with_space(world: PolygonWorld, space: S, options: PrmOptions) -> Result<Self, PrmError> {
        match options.connection {
            Connection::Nearest { k: 0 } => return Err(PrmError::InvalidK),
            Connection::Radius { radius } if !(radius.is_finite() && radius > 0.0) => {
                return Err(PrmError::InvalidRadius(radius));
            }
            _ => {}
        }
        if options.attempts_per_sample == 0 {
            return Err(PrmError::InvalidAttempts);
        }
        let nearest = KdNearest::new(&space)?;
        let drawer = Drawer::new(options.sampler)?;
        Ok(Prm {
            checker: world.checker(),
            space,
            options,
            nearest,
            candidates: Vec::new(),
            out: Vec::new(),
            into: Vec::new(),
            edge_count: 0,
            parent: Vec::new(),
            components: 0,
            stream: Stream { rng: ChaCha8Rng::seed_from_u64(options.sampler.seed()), drawer, attempts: 0 },
            local_paths_checked: 0,
        })
    }

    /// Draws `samples` more free configurations and joins each to the roadmap; returns the
    /// indices of the new nodes' range start. Fails with [`PrmError::SamplingExhausted`] after
    /// `attempts_per_sample × samples` draws, or as soon as fewer than one draw in
    /// `attempts_per_sample` has been free over `attempts_per_sample × (added + 10)` draws,
    /// keeping the samples found; with [`PrmError::TooManyNodes`] before any draw if the
    /// roadmap would pass [`MAX_NODES`].
    pub fn grow(&mut self, samples: usize) -> Result<std::ops::Range<u32>, PrmError> {
        if self.node_count().saturating_add(samples) > MAX_NODES {
            return Err(PrmError::TooManyNodes);
        }
        let first = self.node_count() as u32;
        let attempts = u64::from(self.options.attempts_per_sample);
        let budget = attempts.saturating_mul(samples as u64);
        let mut draws = 0u64;
        let mut added = 0;
        while added < samples {
            // Besides the whole budget, give up as soon as fewer than one draw in
            // `attempts_per_sample` has been free (after the first ten samples' worth): a world
            // with no free space fails in thousands of draws, not millions.
            if draws == budget || draws >= attempts.saturating_mul(added as u64 + 10) {
                return Err(PrmError::SamplingExhausted { requested: samples, added, attempts: draws });
            }
            draws += 1;
            if let Some(state) = self.draw()
                && self.is_free(&state)
                && self.add_node(state)?.1
            {
                added += 1;
            }
        }
        Ok(first..self.node_count() as u32)
    }

    /// Adds `state` as a node (joined like a sample) and returns its index; if a node is
    /// already there, returns that node's index.
    pub fn insert(&mut self, state: S::State) -> Result<u32, PrmError> {
        if !self.is_free(&state) {
            return Err(PrmError::Blocked(self.space.coordinates(&state)));
        }
        Ok(self.add_node(state)?.0)
    }

    /// The graph with `start` and `goal` joined to their neighbours (by the roadmap's
    /// connection rule, measured by the space's distance) and to each other when the goal is
    /// among the start's neighbours. The roadmap is not changed.
    pub fn query(&self, start: S::State, goal: S::State) -> Result<PrmQuery<'_, S>, PrmError> {
        if !self.is_free(&start) {
            return Err(PrmError::StartBlocked(self.space.coordinates(&start)));
        }
        if !self.is_free(&goal) {
            return Err(PrmError::GoalBlocked(self.space.coordinates(&goal)));
        }
        let n = self.node_count();
        let (mut from_start, mut to_goal) = (vec![Cost::INFINITY; n], vec![Cost::INFINITY; n]);
        for (u, _) in self.neighbours_of(&start, Direction::FromQuery, n + 1) {
            if let Some(c) = self.connect(&self.checker, &start, self.nearest.state(u)) {
                from_start[u as usize] = c;
            }
        }
        for (u, _) in self.neighbours_of(&goal, Direction::ToQuery, n + 1) {
            if let Some(c) = self.connect(&self.checker, self.nearest.state(u), &goal) {
                to_goal[u as usize] = c;
            }
        }
        let direct = if start == goal {
            Some(0.0)
        } else if self.within_reach(&start, &goal, n + 2) {
            self.connect(&self.checker, &start, &goal)
        } else {
            None
        };
        Ok(RoadmapQuery::new(self, (start, goal), from_start, to_goal, direct))
    }

    /// Adds an obstacle (checked like the world's) and blocks the edges it collides with.
    /// Returns the changed edges with their old costs, in both directions for an undirected
    /// roadmap, for [`DStarLite::update_edges`](https://docs.rs/trailmark-search) after the
    /// change. Nodes inside the obstacle stay, with all their edges blocked.
    pub fn add_obstacle(&mut self, vertices: Vec<Point>) -> Result<Vec<EdgeChange<u32>>, PrmError> {
        let world = self.checker.world().with_obstacle(vertices)?;
        let added = world.obstacles().last().expect("just added").clone();
        let alone = world.only(added).checker();
        self.checker = world.checker();
        let mut changes = Vec::new();
        for id in 0..self.candidates.len() {
            let Candidate { ends: [a, b], cost } = self.candidates[id];
            if cost.is_finite() && self.local_path(&alone, a, b).is_none() {
                self.candidates[id].cost = Cost::INFINITY;
                self.edge_count -= 1;
                self.report(&mut changes, a, b, cost);
            }
        }
        self.rebuild_components();
        Ok(changes)
    }

    /// Removes obstacle `index` (later obstacles move down by one) and restores the edges it
    /// alone blocked. Returns the changed edges (old cost infinite), as
    /// [`add_obstacle`](Self::add_obstacle) does.
    pub fn remove_obstacle(&mut self, index: usize) -> Result<Vec<EdgeChange<u32>>, PrmError> {
        let count = self.checker.world().obstacles().len();
        let (world, removed) =
            self.checker.world().without_obstacle(index).ok_or(PrmError::NoSuchObstacle { index, count })?;
        let alone = world.only(removed).checker();
        self.checker = world.checker();
        let mut changes = Vec::new();
        for id in 0..self.candidates.len() {
            let Candidate { ends: [a, b], cost } = self.candidates[id];
            if cost.is_infinite()
                && self.local_path(&alone, a, b).is_none()
                && let Some(c) = self.local_path(&self.checker, a, b)
            {
                self.candidates[id].cost = c;
                self.edge_count += 1;
                self.report(&mut changes, a, b, Cost::INFINITY);
            }
        }
        self.rebuild_components();
        Ok(changes)
    }

    /// The world the roadmap is built in (with its current obstacles).
    pub fn world(&self) -> &PolygonWorld {
        self.checker.world()
    }

    /// The exact collision checker of the world.
    pub fn checker(&self) -> &CollisionChecker {
        &self.checker
    }

    /// The state space: its states, motions and distances.
    pub fn space(&self) -> &S {
        &self.space
    }

    /// The settings.
    pub fn options(&self) -> PrmOptions {
        self.options
    }

    /// The number of nodes.
    pub fn node_count(&self) -> usize {
        self.nearest.len()
    }

    /// The number of free edges (each undirected edge once).
    pub fn edge_count(&self) -> usize {
        self.edge_count
    }

    /// The number of edges tried, free or blocked.
    pub fn candidate_count(&self) -> usize {
        self.candidates.len()
    }

    /// The configuration of `node`.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count): node ids are indices, as a
    /// slice's. [`get_position`](Self::get_position) is the checked form.
    pub fn position(&self, node: u32) -> S::State {
        *self.nearest.state(node)
    }

    /// The configuration of `node`, `None` if the roadmap has no such node.
    pub fn get_position(&self, node: u32) -> Option<S::State> {
        ((node as usize) < self.node_count()).then(|| self.position(node))
    }

    /// The free edges, as `(from, to, cost)`, each undirected edge once.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32, Cost)> + '_ {
        self.candidates.iter().filter(|c| c.cost.is_finite()).map(|c| (c.ends[0], c.ends[1], c.cost))
    }

    /// Draws made by the sampler so far (accepted or not).
    pub fn attempts(&self) -> u64 {
        self.stream.attempts
    }

    /// Local paths collision-checked so far (building and querying a copy do not share this).
    pub fn local_paths_checked(&self) -> u64 {
        self.local_paths_checked
    }

    /// The number of connected components (ignoring edge direction).
    pub fn component_count(&self) -> usize {
        self.components
    }

    /// A representative of `node`'s connected component (ignoring edge direction): two nodes
    /// are connected exactly when their representatives are equal.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count).
    /// [`get_component`](Self::get_component) is the checked form.
    pub fn component(&self, node: u32) -> u32 {
        let mut x = node;
        while self.parent[x as usize] != x {
            x = self.parent[x as usize];
        }
        x
    }

    /// The representative of `node`'s connected component, `None` if the roadmap has no such
    /// node.
    pub fn get_component(&self, node: u32) -> Option<u32> {
        ((node as usize) < self.node_count()).then(|| self.component(node))
    }

    /// One draw of the sampler (`None` when it found nothing).
    fn draw(&mut self) -> Option<S::State> {
        self.stream.attempts += 1;
        let validity = Exact(&self.checker);
        let mut checks = 0;
        let mut draw = Draw::new(&mut self.stream.rng, &mut checks);
        let space = &self.space;
        match &self.stream.drawer {
            Drawer::Uniform => Uniform.sample(space, &validity, &mut draw),
            Drawer::Halton(halton) => halton.sample(space, &validity, &mut draw),
            Drawer::Gaussian(gaussian) => gaussian.sample(space, &validity, &mut draw),
            Drawer::Bridge(bridge) => bridge.sample(space, &validity, &mut draw),
        }
    }

    /// Whether `state` is within the space's bounds and free.
    fn is_free(&self, state: &S::State) -> bool {
        self.space.satisfies_bounds(state) && self.space.state_is_free(&self.checker, state)
    }

    /// The cost of the motion from `from` to `to` in the world of `checker`, `None` if it
    /// collides.
    fn connect(&self, checker: &CollisionChecker, from: &S::State, to: &S::State) -> Option<Cost> {
        self.space.motion_is_free(checker, from, to).then(|| self.space.distance(from, to))
    }

    /// The node at exactly `state`, if any.
    fn find(&self, state: &S::State) -> Option<u32> {
        let (id, d) = self.nearest.nearest(&self.space, state, Direction::ToQuery)?;
        (d == 0.0 && self.nearest.state(id) == state).then_some(id)
    }

    /// The nodes a configuration `state` joins in a roadmap of `n` nodes, nearest first, with
    /// their distances measured the way `direction` says.
    fn neighbours_of(&self, state: &S::State, direction: Direction, n: usize) -> Vec<(u32, f64)> {
        match self.options.connection.neighbour_count(n, self.space.dimension()) {
            Some(k) => self.nearest.k_nearest(&self.space, state, k, direction),
            None => {
                let Connection::Radius { radius } = self.options.connection else { unreachable!() };
                self.nearest.within(&self.space, state, radius, direction)
            }
        }
    }

    /// Whether `goal` is among the neighbours of `start` (the motions out of it) by the
    /// connection rule, in a roadmap of `n` nodes that holds `goal`.
    fn within_reach(&self, start: &S::State, goal: &S::State, n: usize) -> bool {
        let d = self.space.distance(start, goal);
        match self.options.connection {
            Connection::Radius { radius } => d <= radius,
            connection => {
                let k =
                    connection.neighbour_count(n, self.space.dimension()).expect("a nearest-neighbour rule");
                let nearest = self.neighbours_of(start, Direction::FromQuery, n);
                // PRM*'s k is 0 in a roadmap of one node: nothing is in reach.
                nearest.len() < k
                    || k.checked_sub(1).and_then(|last| nearest.get(last)).is_some_and(|&(_, kth)| d <= kth)
            }
        }
    }

    /// Adds `state` as a node joined to its neighbours: its index and `true`, or the index of
    /// the node already at `state` and `false`.
    fn add_node(&mut self, state: S::State) -> Result<(u32, bool), PrmError> {
        let n = self.node_count() + 1;
        let into = self.neighbours_of(&state, Direction::ToQuery, n);
        // A node at `state` is at distance 0, so it leads the neighbours (every rule keeps the
        // nearest once the roadmap has a node); the search for neighbours finds it too.
        let mut at_zero = into.iter().take_while(|&&(_, d)| d == 0.0);
        if let Some(&(v, _)) = at_zero.find(|&&(v, _)| *self.nearest.state(v) == state) {
            return Ok((v, false));
        }
        if self.node_count() >= MAX_NODES {
            return Err(PrmError::TooManyNodes);
        }
        let out = if S::SYMMETRIC { Vec::new() } else { self.neighbours_of(&state, Direction::FromQuery, n) };
        let u = self.push_node(state);
        for (v, _) in into {
            self.try_edge(v, u);
        }
        for (v, _) in out {
            self.try_edge(u, v);
        }
        Ok((u, true))
    }

    /// Stores `state` as a new node without edges (its own component) and returns its index.
    fn push_node(&mut self, state: S::State) -> u32 {
        let u = self.nearest.insert(&self.space, state);
        self.out.push(Vec::new());
        if !S::SYMMETRIC {
            self.into.push(Vec::new());
        }
        self.parent.push(u);
        self.components += 1;
        u
    }

    /// Checks the local path `from -> to` and records it as a candidate.
    fn try_edge(&mut self, from: u32, to: u32) {
        let cost = self.local_path(&self.checker, from, to).unwrap_or(Cost::INFINITY);
        self.local_paths_checked += 1;
        let id = self.candidates.len() as u32;
        self.candidates.push(Candidate { ends: [from, to], cost });
        self.out[from as usize].push(id);
        if S::SYMMETRIC {
            self.out[to as usize].push(id);
        } else {
            self.into[to as usize].push(id);
        }
        if cost.is_finite() {
            self.edge_count += 1;
            self.union(from, to);
        }
    }

    fn local_path(&self, checker: &CollisionChecker, from: u32, to: u32) -> Option<Cost> {
        self.connect(checker, self.nearest.state(from), self.nearest.state(to))
    }

    fn report(&self, changes: &mut Vec<EdgeChange<u32>>, a: u32, b: u32, old_cost: Cost) {
        changes.push(EdgeChange { from: a, to: b, old_cost });
        if S::SYMMETRIC {
            changes.push(EdgeChange { from: b, to: a, old_cost });
        }
    }

    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find_root(a), self.find_root(b));
        if ra != rb {
            // The smaller index becomes the root, so representatives do not depend on the
            // order edges were added in.
            let (root, child) = if ra < rb { (ra, rb) } else { (rb, ra) };
            self.parent[child as usize] = root;
            self.components -= 1;
        }
    }

    fn find_root(&mut self, x: u32) -> u32 {
        let mut x = x;
        while self.parent[x as usize] != x {
            let grand = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = grand;
            x = grand;
        }
        x
    }

    fn rebuild_components(&mut self) {
        self.parent = (0..self.node_count() as u32).collect();
        self.components = self.node_count();
        for id in 0..self.candidates.len() {
            let Candidate { ends: [a, b], cost } = self.candidates[id];
            if cost.is_finite() {
                self.union(a, b);
            }
        }
    }

    fn other_end(&self, id: u32, node: u32) -> (u32, Cost) {
        let c = &self.candidates[id as usize];
        (c.ends[0] ^ c.ends[1] ^ node, c.cost)
    }
}

impl<S: PlanarSpace> Roadmap for Prm<S> {
    type Position = S::State;
    const DIRECTED: bool = !S::SYMMETRIC;

    fn node_count(&self) -> usize {
        self.nearest.len()
    }

    fn position(&self, node: u32) -> S::State {
        *self.nearest.state(node)
    }

    /// The space's distance: every edge costs its motion's distance, and a path of motions is
    /// no shorter than the shortest motion between its ends (in `R2` the straight line, in
    /// `Dubins` the shortest Dubins path).
    fn lower_bound(&self, a: S::State, b: S::State) -> Cost {
        self.space.distance(&a, &b)
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &id in &self.out[node as usize] {
            let (v, c) = self.other_end(id, node);
            if c.is_finite() {
                visit(v, c);
            }
        }
    }

    fn for_each_in<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        if S::SYMMETRIC {
            return self.for_each_out(node, visit);
        }
        for &id in &self.into[node as usize] {
            let (u, c) = self.other_end(id, node);
            if c.is_finite() {
                visit(u, c);
            }
        }
    }
}

impl<S: PlanarSpace> Graph for Prm<S> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.nearest.len()
    }
}

impl<S: PlanarSpace> Successors for Prm<S> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_out(node, visit)
    }
}

impl<S: PlanarSpace> Predecessors for Prm<S> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_in(node, visit)
    }
}

impl<S: PlanarSpace> IndexedGraph for Prm<S> {
    fn node_bound(&self) -> usize {
        self.nearest.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}

/// A saved roadmap: the world, the space, the settings, the nodes, every edge tried and where
/// the sample stream stands.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PrmDocument<S> {
    world: PolygonWorld,
    space: S,
    options: PrmOptions,
    /// `[x, y]` or `[x, y, heading]`.
    nodes: Vec<Vec<f64>>,
    /// `[from, to, free (1) or blocked (0)]`.
    edges: Vec<[u32; 3]>,
    /// How far the ChaCha8 stream has gone (in 32-bit words), and the Halton index.
    stream: StreamDocument,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StreamDocument {
    /// The word position, as a decimal string (it may exceed 2^64).
    word_position: String,
    halton_index: u64,
    attempts: u64,
}

impl<S: PlanarSpace + Serialize> Serialize for Prm<S> {
    /// Saves as `{"world", "space", "options", "nodes", "edges", "stream"}`.
    fn serialize<Ser: serde::Serializer>(&self, serializer: Ser) -> Result<Ser::Ok, Ser::Error> {
        PrmDocument {
            world: self.checker.world().clone(),
            space: self.space.clone(),
            options: self.options,
            nodes: (0..self.node_count() as u32)
                .map(|u| self.space.coordinates(self.nearest.state(u)))
                .collect(),
            edges: self
                .candidates
                .iter()
                .map(|c| [c.ends[0], c.ends[1], u32::from(c.cost.is_finite())])
                .collect(),
            stream: StreamDocument {
                word_position: self.stream.rng.get_word_pos().to_string(),
                halton_index: match &self.stream.drawer {
                    Drawer::Halton(halton) => halton.drawn(),
                    _ => 0,
                },
                attempts: self.stream.attempts,
            },
        }
        .serialize(serializer)
    }
}

impl<'de, S: PlanarSpace + Deserialize<'de>> Deserialize<'de> for Prm<S> {
    /// Loads a saved roadmap, re-checking every node and every edge's free or blocked state in
    /// the saved world; a mismatch is an error, not a silent repair.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let document = PrmDocument::<S>::deserialize(deserializer)?;
        Prm::from_document(document).map_err(serde::de::Error::custom)
    }
}

impl<S: PlanarSpace> Prm<S> {
    fn from_document(d: PrmDocument<S>) -> Result<Self, PrmError> {
        let mut prm = Prm::with_space(d.world, d.space, d.options)?;
        for (index, coordinates) in d.nodes.iter().enumerate() {
            let state =
                prm.space.state_from_coordinates(coordinates).ok_or(PrmError::InvalidNode { index })?;
            if !prm.is_free(&state) || prm.find(&state).is_some() {
                return Err(PrmError::InvalidNode { index });
            }
            prm.push_node(state);
        }
        let n = prm.node_count() as u32;
        for (index, &[from, to, free]) in d.edges.iter().enumerate() {
            if from >= n || to >= n || from == to || free > 1 {
                return Err(PrmError::InvalidEdge { index });
            }
            prm.try_edge(from, to);
            if prm.candidates[index].cost.is_finite() != (free == 1) {
                return Err(PrmError::InvalidEdge { index });
            }
        }
        let word_position: u128 = d.stream.word_position.parse().map_err(|_| PrmError::InvalidStream)?;
        prm.stream.rng.set_word_pos(word_position);
        if let Drawer::Halton(halton) = &mut prm.stream.drawer {
            *halton = Halton::after(d.stream.halton_index);
        }
        prm.stream.attempts = d.stream.attempts;
        prm.local_paths_checked = 0;
        Ok(prm)
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use trailmark_core::generate::convex_obstacles;
    use trailmark_core::geometry::Vector;
    use trailmark_core::world::Bounds;
    use trailmark_sample::Dubins;

    use super::*;

    fn world(seed: u64, radius: f64) -> PolygonWorld {
        convex_obstacles(20.0, 12, 6, radius, seed).expect("a valid world")
    }

    fn nodes<S: PlanarSpace>(prm: &Prm<S>) -> Vec<S::State> {
        (0..prm.node_count() as u32).map(|u| prm.position(u)).collect()
    }

    fn options(connection: Connection) -> PrmOptions {
        PrmOptions { connection, ..PrmOptions::default() }
    }

    #[test]
    fn prm_star_uses_karaman_and_frazzolis_k() {
        // The connection rule is trailmark-sample's, shared by both roadmaps.
        // e (1 + 1/2) ln 1000 = 28.17 and e (1 + 1/3) ln 1000 = 25.04.
        assert_eq!(Connection::PrmStar.neighbour_count(1000, 2), Some(29));
        assert_eq!(Connection::PrmStar.neighbour_count(1000, 3), Some(26));
        assert_eq!(Connection::Nearest { k: 7 }.neighbour_count(1000, 2), Some(7));
    }

    #[test]
    fn bad_settings_are_typed_errors() {
        let w = world(1, 0.0);
        assert_eq!(
            Prm::new(w.clone(), options(Connection::Nearest { k: 0 })).err(),
            Some(PrmError::InvalidK)
        );
        for radius in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Prm::new(w.clone(), options(Connection::Radius { radius })).err();
            assert!(matches!(e, Some(PrmError::InvalidRadius(_))), "{e:?}");
        }
        let none = PrmOptions { attempts_per_sample: 0, ..PrmOptions::default() };
        assert_eq!(Prm::new(w.clone(), none).err(), Some(PrmError::InvalidAttempts));
        let b = w.bounds();
        assert!(Dubins::new(b, 0.0).is_err() && Dubins::new(b, f64::NAN).is_err());
        let bad =
            PrmOptions { sampler: Sampler::Gaussian { seed: 0, std_dev: -1.0 }, ..PrmOptions::default() };
        assert!(matches!(Prm::new(w, bad).err(), Some(PrmError::Sampler(_))));
    }

    #[test]
    fn sampling_a_blocked_world_gives_up_with_an_error() {
        let bounds = Bounds::new(0.0, 0.0, 1.0, 1.0).unwrap();
        let cover =
            vec![Point::new(-1.0, -1.0), Point::new(2.0, -1.0), Point::new(2.0, 2.0), Point::new(-1.0, 2.0)];
        let w = PolygonWorld::new(bounds, vec![cover], 0.0).unwrap();
        let mut prm = Prm::new(w, PrmOptions { attempts_per_sample: 10, ..PrmOptions::default() }).unwrap();
        assert_eq!(prm.grow(5), Err(PrmError::SamplingExhausted { requested: 5, added: 0, attempts: 50 }));
        assert!(matches!(prm.insert(Point::new(0.5, 0.5)), Err(PrmError::Blocked(_))));
    }

    /// The radius roadmap is the radius graph: every pair within the radius whose segment is
    /// free, found by brute force over all pairs.
    #[test]
    fn radius_roadmap_equals_brute_force_radius_graph() {
        for (seed, r) in [(1, 0.0), (2, 0.4), (3, 1.0)] {
            let radius = 3.0;
            let mut prm = Prm::new(world(seed, r), options(Connection::Radius { radius })).unwrap();
            prm.grow(150).unwrap();
            let checker = prm.world().checker();
            let mut brute = BTreeSet::new();
            for u in 0..prm.node_count() as u32 {
                for v in u + 1..prm.node_count() as u32 {
                    let (a, b) = (prm.position(u), prm.position(v));
                    if (b - a).norm() <= radius && checker.segment_is_free(a, b) {
                        brute.insert((u, v));
                    }
                }
            }
            let built: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a.min(b), a.max(b))).collect();
            assert_eq!(built, brute, "seed {seed}");
            assert_eq!(prm.edge_count(), brute.len());
        }
    }

    /// Components by union-find equal components by graph search.
    #[test]
    fn components_match_a_traversal() {
        let mut prm = Prm::new(world(4, 0.5), options(Connection::Nearest { k: 3 })).unwrap();
        prm.grow(120).unwrap();
        let n = prm.node_count();
        let mut label = vec![u32::MAX; n];
        let mut count = 0;
        for s in 0..n as u32 {
            if label[s as usize] != u32::MAX {
                continue;
            }
            count += 1;
            let mut stack = vec![s];
            label[s as usize] = s;
            while let Some(u) = stack.pop() {
                prm.for_each_successor(u, |v, _| {
                    if label[v as usize] == u32::MAX {
                        label[v as usize] = s;
                        stack.push(v);
                    }
                });
            }
        }
        assert_eq!(prm.component_count(), count);
        for u in 0..n as u32 {
            for v in 0..n as u32 {
                assert_eq!(prm.component(u) == prm.component(v), label[u as usize] == label[v as usize]);
            }
        }
    }

    #[test]
    fn inserting_the_same_point_returns_the_same_node() {
        let mut prm = Prm::new(world(5, 0.0), PrmOptions::default()).unwrap();
        prm.grow(10).unwrap();
        let p = prm.position(3);
        // More repeats than a k-d tree bucket holds.
        for _ in 0..40 {
            assert_eq!(prm.insert(p), Ok(3));
        }
        assert_eq!(prm.node_count(), 10);
    }

    #[test]
    fn growing_in_steps_equals_growing_at_once() {
        let bridge = Sampler::Bridge { seed: 4, std_dev: 0.5 };
        for sampler in [Sampler::Halton, Sampler::Uniform { seed: 9 }, bridge] {
            let o = PrmOptions { sampler, ..options(Connection::PrmStar) };
            let mut once = Prm::new(world(6, 0.3), o).unwrap();
            once.grow(90).unwrap();
            let mut steps = Prm::new(world(6, 0.3), o).unwrap();
            steps.grow(40).unwrap();
            steps.grow(50).unwrap();
            assert_eq!(nodes(&once), nodes(&steps));
            assert_eq!(once.edges().collect::<Vec<_>>(), steps.edges().collect::<Vec<_>>());
        }
    }

    #[test]
    fn save_and_load_keep_the_roadmap_and_its_sample_stream() {
        let o =
            PrmOptions { sampler: Sampler::Uniform { seed: 11 }, ..options(Connection::Nearest { k: 5 }) };
        let mut prm = Prm::new(world(7, 0.4), o).unwrap();
        prm.grow(60).unwrap();
        let text = serde_json::to_string(&prm).unwrap();
        let mut loaded: Prm = serde_json::from_str(&text).unwrap();
        assert_eq!(nodes(&loaded), nodes(&prm));
        assert_eq!(loaded.edges().collect::<Vec<_>>(), prm.edges().collect::<Vec<_>>());
        assert_eq!(loaded.candidate_count(), prm.candidate_count());
        assert_eq!(loaded.component_count(), prm.component_count());
        prm.grow(20).unwrap();
        loaded.grow(20).unwrap();
        assert_eq!(nodes(&loaded), nodes(&prm));
        assert_eq!(loaded.attempts(), prm.attempts());

        // A flipped free flag, an edge to a missing node, a node moved into an obstacle.
        let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        let flag = doc["edges"][0][2].as_u64().unwrap();
        doc["edges"][0][2] = serde_json::json!(1 - flag);
        assert!(serde_json::from_value::<Prm>(doc.clone()).unwrap_err().to_string().contains("edge 0"));
        doc["edges"][0] = serde_json::json!([0, 1000, 1]);
        assert!(serde_json::from_value::<Prm>(doc.clone()).unwrap_err().to_string().contains("edge 0"));
        let inside =
            prm.world().obstacles()[0].vertices().iter().fold(Vector::zeros(), |s, v| s + v.coords) / 6.0;
        doc["nodes"][2] = serde_json::json!([inside.x, inside.y]);
        assert!(serde_json::from_value::<Prm>(doc).unwrap_err().to_string().contains("node 2"));
    }

    /// After an obstacle is added and removed, the free edges are the candidates free in the
    /// current world, and the reported changes are exactly the difference.
    #[test]
    fn obstacle_changes_report_exactly_the_changed_edges() {
        let mut prm = Prm::new(world(8, 0.3), options(Connection::Nearest { k: 6 })).unwrap();
        prm.grow(150).unwrap();
        let before: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
        let block =
            vec![Point::new(6.0, 6.0), Point::new(14.0, 6.0), Point::new(14.0, 14.0), Point::new(6.0, 14.0)];
        let changes = prm.add_obstacle(block).unwrap();
        let checker = prm.world().checker();
        let free_now = |prm: &Prm| -> BTreeSet<(u32, u32)> {
            prm.candidates
                .iter()
                .filter(|c| checker_free(&checker, prm, c.ends))
                .map(|c| (c.ends[0], c.ends[1]))
                .collect()
        };
        let after: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
        assert_eq!(after, free_now(&prm));
        let lost: BTreeSet<(u32, u32)> = before.difference(&after).copied().collect();
        assert!(!lost.is_empty());
        let reported: BTreeSet<(u32, u32)> =
            changes.iter().map(|c| (c.from, c.to)).filter(|(a, b)| a < b).collect();
        let lost_sorted: BTreeSet<(u32, u32)> = lost.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect();
        assert_eq!(reported, lost_sorted);
        assert_eq!(changes.len(), 2 * lost.len());
        assert!(changes.iter().all(|c| c.old_cost.is_finite()));

        let last = prm.world().obstacles().len() - 1;
        let changes = prm.remove_obstacle(last).unwrap();
        let restored: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
        assert_eq!(restored, before);
        assert_eq!(changes.len(), 2 * lost.len());
        assert!(changes.iter().all(|c| c.old_cost.is_infinite()));
        assert!(matches!(prm.remove_obstacle(99), Err(PrmError::NoSuchObstacle { index: 99, .. })));
    }

    fn checker_free(checker: &CollisionChecker, prm: &Prm, [a, b]: [u32; 2]) -> bool {
        checker.segment_is_free(prm.position(a), prm.position(b))
    }

    /// Dubins roadmaps are directed: each edge's cost is its own shortest Dubins path, free by
    /// the exact checker, and the reverse edge is checked on its own.
    #[test]
    fn dubins_edges_are_directed_and_free() {
        let w = world(9, 0.3);
        let space = Dubins::new(w.bounds(), 1.5).unwrap();
        let o = PrmOptions { sampler: Sampler::Halton, ..options(Connection::Nearest { k: 8 }) };
        let mut prm = Prm::with_space(w, space, o).unwrap();
        prm.grow(80).unwrap();
        let checker = prm.world().checker();
        let mut asymmetric = 0;
        for (a, b, cost) in prm.edges() {
            let path = space.path(&prm.position(a), &prm.position(b));
            assert!(checker.dubins_is_free(&path));
            // The space's distance is the length-only solver's, within rounding of the path's.
            assert!((cost - path.length()).abs() <= 1e-12 * cost, "{cost} vs {}", path.length());
            let mut back = None;
            prm.for_each_successor(b, |v, c| {
                if v == a {
                    back = Some(c)
                }
            });
            asymmetric += usize::from(back != Some(cost));
        }
        assert!(asymmetric > 0, "Dubins edges differ by direction");
        let mut into = 0;
        for v in 0..prm.node_count() as u32 {
            prm.for_each_predecessor(v, |_, _| into += 1);
        }
        assert_eq!(into, prm.edge_count());
    }
}
