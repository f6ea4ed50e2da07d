//! Probabilistic roadmaps: samples in free space joined by collision-free local paths.
//!
//! A [`Prm`] draws configurations in the free space of a [`PolygonWorld`] (seeded uniform
//! samples, or a deterministic Halton sequence), and joins each new node to its neighbours
//! among the nodes already there (the k nearest, those within a radius, or PRM*'s
//! k = ⌈e(1 + 1/d) ln n⌉) wherever the local path between them is collision-free. Every local
//! path is checked exactly against the obstacles by the world's [`CollisionChecker`] (segment
//! and arc distances, not sampling); nearest neighbours come from a k-d tree (kiddo).
//!
//! The local path is a [`Steering`]: [`Straight`] segments for a disc robot (an undirected
//! roadmap over points), or [`DubinsSteering`] curves for a car-like robot (a directed roadmap
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

use kiddo::SquaredEuclidean;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::dubins::{DubinsPath, RadiusOutOfScale, check_extent};
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::world::{Bounds, CollisionChecker, PolygonWorld, WorldError};

use crate::roadmap::{Roadmap, RoadmapQuery};

type KdTree = kiddo::KdTree<f64, 2>;

/// How a roadmap joins two configurations: the local path, its exact collision test and its
/// cost.
pub trait Steering: Copy + Debug {
    /// A configuration: a point, or a pose.
    type State: Copy + Debug + PartialEq;

    /// Whether the local path from `a` to `b` differs from the reverse of the one from `b` to
    /// `a`, so the roadmap's edges are directed.
    const DIRECTED: bool;

    /// The dimension of the configuration space (for PRM*'s number of neighbours).
    const DIMENSION: usize;

    /// The configuration at `unit` (coordinates in `[0, 1)`, one per dimension) of the bounds.
    fn state(&self, bounds: &Bounds, unit: [f64; 3]) -> Self::State;

    /// Where the robot's centre is in `state`.
    fn point(state: &Self::State) -> Point;

    /// The cost of the local path from `from` to `to`, `None` if it collides.
    fn connect(&self, checker: &CollisionChecker, from: &Self::State, to: &Self::State) -> Option<Cost>;

    /// The state's coordinates, for saving: `[x, y]` or `[x, y, heading]`.
    fn coordinates(state: &Self::State) -> Vec<f64>;

    /// The state with these coordinates, `None` if there are not [`DIMENSION`](Self::DIMENSION)
    /// finite ones.
    fn from_coordinates(coordinates: &[f64]) -> Option<Self::State>;

    /// Whether local paths between states in `bounds` are within this steering's supported
    /// range (every steering, unless it says otherwise).
    fn supports(&self, bounds: &Bounds) -> Result<(), PrmError> {
        let _ = bounds;
        Ok(())
    }
}

/// Straight segments between points: the local path of a disc robot.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Straight;

impl Steering for Straight {
    type State = Point;
    const DIRECTED: bool = false;
    const DIMENSION: usize = 2;

    fn state(&self, bounds: &Bounds, unit: [f64; 3]) -> Point {
        let (min, max) = (bounds.min(), bounds.max());
        Point::new(min.x + unit[0] * (max.x - min.x), min.y + unit[1] * (max.y - min.y))
    }

    fn point(state: &Point) -> Point {
        *state
    }

    fn connect(&self, checker: &CollisionChecker, from: &Point, to: &Point) -> Option<Cost> {
        checker.segment_is_free(*from, *to).then(|| (to - from).norm())
    }

    fn coordinates(state: &Point) -> Vec<f64> {
        vec![state.x, state.y]
    }

    fn from_coordinates(c: &[f64]) -> Option<Point> {
        match *c {
            [x, y] if x.is_finite() && y.is_finite() => Some(Point::new(x, y)),
            _ => None,
        }
    }
}

/// Shortest Dubins paths between poses: the local path of a car that drives forward with a
/// bounded turning radius.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "DubinsSteeringDocument", into = "DubinsSteeringDocument")]
pub struct DubinsSteering {
    turning_radius: f64,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct DubinsSteeringDocument {
    turning_radius: f64,
}

impl TryFrom<DubinsSteeringDocument> for DubinsSteering {
    type Error = PrmError;
    fn try_from(d: DubinsSteeringDocument) -> Result<Self, PrmError> {
        DubinsSteering::new(d.turning_radius)
    }
}

impl From<DubinsSteering> for DubinsSteeringDocument {
    fn from(s: DubinsSteering) -> Self {
        DubinsSteeringDocument { turning_radius: s.turning_radius }
    }
}

impl DubinsSteering {
    /// Dubins paths with this turning radius, which must be positive and finite.
    pub fn new(turning_radius: f64) -> Result<Self, PrmError> {
        if turning_radius.is_finite() && turning_radius > 0.0 {
            Ok(DubinsSteering { turning_radius })
        } else {
            Err(PrmError::InvalidTurningRadius(turning_radius))
        }
    }

    /// The turning radius.
    pub fn turning_radius(&self) -> f64 {
        self.turning_radius
    }

    /// The shortest Dubins path from `from` to `to`.
    pub fn path(&self, from: &Pose, to: &Pose) -> Option<DubinsPath> {
        DubinsPath::shortest(from, to, self.turning_radius).ok()
    }
}

impl Steering for DubinsSteering {
    type State = Pose;
    const DIRECTED: bool = true;
    const DIMENSION: usize = 3;

    fn supports(&self, bounds: &Bounds) -> Result<(), PrmError> {
        Ok(check_extent(self.turning_radius, (bounds.max() - bounds.min()).norm())?)
    }

    fn state(&self, bounds: &Bounds, unit: [f64; 3]) -> Pose {
        let p = Straight.state(bounds, unit);
        Pose::new(p.coords, (2.0 * unit[2] - 1.0) * std::f64::consts::PI)
    }

    fn point(state: &Pose) -> Point {
        Point::from(state.translation.vector)
    }

    fn connect(&self, checker: &CollisionChecker, from: &Pose, to: &Pose) -> Option<Cost> {
        let path = self.path(from, to)?;
        checker.dubins_is_free(&path).then(|| path.length())
    }

    fn coordinates(state: &Pose) -> Vec<f64> {
        vec![state.translation.x, state.translation.y, state.rotation.angle()]
    }

    fn from_coordinates(c: &[f64]) -> Option<Pose> {
        match *c {
            [x, y, heading] if x.is_finite() && y.is_finite() && heading.is_finite() => {
                Some(Pose::new(Vector::new(x, y), heading))
            }
            _ => None,
        }
    }
}

/// How samples are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sampler {
    /// Independent uniform samples from a ChaCha8 generator with this seed: the same seed gives
    /// the same roadmap on every machine.
    Uniform {
        /// The generator's seed.
        seed: u64,
    },
    /// The Halton sequence in bases 2, 3 (and 5 for a heading): deterministic, and more even
    /// than independent samples.
    Halton,
}

/// Which existing nodes a new node is joined to.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Connection {
    /// The `k` nearest nodes.
    Nearest {
        /// How many.
        k: usize,
    },
    /// Every node within this distance.
    Radius {
        /// The distance.
        radius: f64,
    },
    /// The `k = ⌈e (1 + 1/d) ln n⌉` nearest, `n` the number of nodes and `d` the dimension:
    /// the asymptotically optimal PRM* of Karaman and Frazzoli.
    PrmStar,
}

impl Connection {
    /// The number of nearest neighbours for a roadmap of `n` nodes in dimension `d`, `None`
    /// for a radius connection.
    fn neighbour_count(&self, n: usize, d: usize) -> Option<usize> {
        match *self {
            Connection::Nearest { k } => Some(k),
            Connection::Radius { .. } => None,
            Connection::PrmStar => {
                let k = std::f64::consts::E * (1.0 + 1.0 / d as f64) * (n.max(1) as f64).ln();
                Some(k.ceil() as usize)
            }
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
    /// A Dubins turning radius must be positive and finite.
    #[error("the turning radius must be positive and finite, got {0:?}")]
    InvalidTurningRadius(f64),
    /// A Dubins turning radius out of the solver's supported range for the world's bounds.
    #[error(transparent)]
    TurningRadiusOutOfScale(#[from] RadiusOutOfScale),
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
    halton_index: u64,
    attempts: u64,
}

/// A probabilistic roadmap over a polygon world, with [`Straight`] or [`DubinsSteering`] local
/// paths. Node `i` is at [`Prm::position`]; edges cost their local path's length.
///
/// It implements the graph traits itself (with permanent nodes from [`Prm::insert`]) and
/// [`Roadmap`], so [`Prm::query`] joins a start and a goal without changing it.
#[derive(Clone, Debug)]
pub struct Prm<S: Steering = Straight> {
    checker: CollisionChecker,
    steering: S,
    options: PrmOptions,
    states: Vec<S::State>,
    tree: KdTree,
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
pub type DubinsPrm = Prm<DubinsSteering>;

/// A [`Prm`] with a start and a goal joined to it.
pub type PrmQuery<'g, S = Straight> = RoadmapQuery<'g, Prm<S>>;

impl Prm<Straight> {
    /// An empty roadmap of straight segments over `world`.
    pub fn new(world: PolygonWorld, options: PrmOptions) -> Result<Self, PrmError> {
        Self::with_steering(world, Straight, options)
    }
}

impl<S: Steering> Prm<S> {
    /// An empty roadmap over `world` whose local paths are `steering`'s.
    pub fn with_steering(world: PolygonWorld, steering: S, options: PrmOptions) -> Result<Self, PrmError> {
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
        steering.supports(&world.bounds())?;
        let seed = match options.sampler {
            Sampler::Uniform { seed } => seed,
            Sampler::Halton => 0,
        };
        Ok(Prm {
            checker: world.checker(),
            steering,
            options,
            states: Vec::new(),
            tree: KdTree::new(),
            candidates: Vec::new(),
            out: Vec::new(),
            into: Vec::new(),
            edge_count: 0,
            parent: Vec::new(),
            components: 0,
            stream: Stream { rng: ChaCha8Rng::seed_from_u64(seed), halton_index: 0, attempts: 0 },
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
        if self.states.len().saturating_add(samples) > MAX_NODES {
            return Err(PrmError::TooManyNodes);
        }
        let first = self.states.len() as u32;
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
            let state = self.draw();
            if self.is_free(&state) && self.find(&state).is_none() {
                self.add_node(state)?;
                added += 1;
            }
        }
        Ok(first..self.states.len() as u32)
    }

    /// Adds `state` as a node (joined like a sample) and returns its index; if a node is
    /// already there, returns that node's index.
    pub fn insert(&mut self, state: S::State) -> Result<u32, PrmError> {
        if !self.is_free(&state) {
            return Err(PrmError::Blocked(S::coordinates(&state)));
        }
        match self.find(&state) {
            Some(node) => Ok(node),
            None => self.add_node(state),
        }
    }

    /// The graph with `start` and `goal` joined to their neighbours (by the roadmap's
    /// connection rule) and to each other when the goal is among the start's neighbours.
    /// The roadmap is not changed.
    pub fn query(&self, start: S::State, goal: S::State) -> Result<PrmQuery<'_, S>, PrmError> {
        if !self.is_free(&start) {
            return Err(PrmError::StartBlocked(S::coordinates(&start)));
        }
        if !self.is_free(&goal) {
            return Err(PrmError::GoalBlocked(S::coordinates(&goal)));
        }
        let n = self.states.len();
        let (mut from_start, mut to_goal) = (vec![Cost::INFINITY; n], vec![Cost::INFINITY; n]);
        for (u, _) in self.neighbours_of(S::point(&start), n + 1) {
            if let Some(c) = self.steering.connect(&self.checker, &start, &self.states[u as usize]) {
                from_start[u as usize] = c;
            }
        }
        for (u, _) in self.neighbours_of(S::point(&goal), n + 1) {
            if let Some(c) = self.steering.connect(&self.checker, &self.states[u as usize], &goal) {
                to_goal[u as usize] = c;
            }
        }
        let direct = if start == goal {
            Some(0.0)
        } else if self.within_reach(S::point(&start), S::point(&goal), n + 2) {
            self.steering.connect(&self.checker, &start, &goal)
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

    /// The local path.
    pub fn steering(&self) -> S {
        self.steering
    }

    /// The settings.
    pub fn options(&self) -> PrmOptions {
        self.options
    }

    /// The number of nodes.
    pub fn node_count(&self) -> usize {
        self.states.len()
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
        self.states[node as usize]
    }

    /// The configuration of `node`, `None` if the roadmap has no such node.
    pub fn get_position(&self, node: u32) -> Option<S::State> {
        self.states.get(node as usize).copied()
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
        ((node as usize) < self.states.len()).then(|| self.component(node))
    }

    fn draw(&mut self) -> S::State {
        self.stream.attempts += 1;
        let unit = match self.options.sampler {
            Sampler::Uniform { .. } => {
                let rng = &mut self.stream.rng;
                [rng.random::<f64>(), rng.random::<f64>(), rng.random::<f64>()]
            }
            Sampler::Halton => {
                self.stream.halton_index += 1;
                let i = self.stream.halton_index;
                [radical_inverse(i, 2), radical_inverse(i, 3), radical_inverse(i, 5)]
            }
        };
        self.steering.state(&self.checker.world().bounds(), unit)
    }

    fn is_free(&self, state: &S::State) -> bool {
        S::from_coordinates(&S::coordinates(state)).is_some() && self.checker.point_is_free(S::point(state))
    }

    /// The node at exactly `state`, if any.
    fn find(&self, state: &S::State) -> Option<u32> {
        if self.states.is_empty() {
            return None;
        }
        let p = S::point(state);
        self.tree
            .within_unsorted::<SquaredEuclidean>(&[p.x, p.y], 0.0)
            .into_iter()
            .map(|n| n.item as u32)
            .find(|&u| self.states[u as usize] == *state)
    }

    /// The nodes a configuration at `p` joins in a roadmap of `n` nodes, nearest first, with
    /// their distances.
    fn neighbours_of(&self, p: Point, n: usize) -> Vec<(u32, f64)> {
        if self.states.is_empty() {
            return Vec::new();
        }
        match self.options.connection.neighbour_count(n, S::DIMENSION) {
            Some(k) => self
                .tree
                .nearest_n::<SquaredEuclidean>(&[p.x, p.y], k.min(self.states.len()))
                .into_iter()
                .map(|m| m.item as u32)
                .map(|u| (u, (S::point(&self.states[u as usize]) - p).norm()))
                .collect(),
            None => {
                let Connection::Radius { radius } = self.options.connection else { unreachable!() };
                let mut within: Vec<(u32, f64)> = self
                    .tree
                    .within_unsorted::<SquaredEuclidean>(&[p.x, p.y], radius * radius)
                    .into_iter()
                    .map(|m| m.item as u32)
                    .map(|u| (u, (S::point(&self.states[u as usize]) - p).norm()))
                    .filter(|&(_, d)| d <= radius)
                    .collect();
                within.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
                within
            }
        }
    }

    /// Whether `q` is among the neighbours of `p` by the connection rule, in a roadmap of `n`
    /// nodes that holds `q`.
    fn within_reach(&self, p: Point, q: Point, n: usize) -> bool {
        let d = (q - p).norm();
        match self.options.connection {
            Connection::Radius { radius } => d <= radius,
            connection => {
                let k = connection.neighbour_count(n, S::DIMENSION).expect("a nearest-neighbour rule");
                let nearest = self.neighbours_of(p, n);
                // PRM*'s k is 0 in a roadmap of one node: nothing is in reach.
                nearest.len() < k
                    || k.checked_sub(1).and_then(|last| nearest.get(last)).is_some_and(|&(_, kth)| d <= kth)
            }
        }
    }

    fn add_node(&mut self, state: S::State) -> Result<u32, PrmError> {
        if self.states.len() >= MAX_NODES {
            return Err(PrmError::TooManyNodes);
        }
        let neighbours = self.neighbours_of(S::point(&state), self.states.len() + 1);
        let u = self.push_node(state);
        for (v, _) in neighbours {
            self.try_edge(u, v);
            if S::DIRECTED {
                self.try_edge(v, u);
            }
        }
        Ok(u)
    }

    /// Stores `state` as a new node without edges (its own component) and returns its index.
    fn push_node(&mut self, state: S::State) -> u32 {
        let u = self.states.len() as u32;
        let p = S::point(&state);
        self.states.push(state);
        self.tree.add(&[p.x, p.y], u64::from(u));
        self.out.push(Vec::new());
        if S::DIRECTED {
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
        if S::DIRECTED {
            self.into[to as usize].push(id);
        } else {
            self.out[to as usize].push(id);
        }
        if cost.is_finite() {
            self.edge_count += 1;
            self.union(from, to);
        }
    }

    fn local_path(&self, checker: &CollisionChecker, from: u32, to: u32) -> Option<Cost> {
        self.steering.connect(checker, &self.states[from as usize], &self.states[to as usize])
    }

    fn report(&self, changes: &mut Vec<EdgeChange<u32>>, a: u32, b: u32, old_cost: Cost) {
        changes.push(EdgeChange { from: a, to: b, old_cost });
        if !S::DIRECTED {
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
        self.parent = (0..self.states.len() as u32).collect();
        self.components = self.states.len();
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

/// The radical inverse of `i` in `base`: the `i`-th element of the van der Corput sequence.
fn radical_inverse(mut i: u64, base: u64) -> f64 {
    let (mut result, mut scale) = (0.0, 1.0 / base as f64);
    while i > 0 {
        result += (i % base) as f64 * scale;
        i /= base;
        scale /= base as f64;
    }
    result
}

impl<S: Steering> Roadmap for Prm<S> {
    type Position = S::State;
    const DIRECTED: bool = S::DIRECTED;

    fn node_count(&self) -> usize {
        self.states.len()
    }

    fn position(&self, node: u32) -> S::State {
        self.states[node as usize]
    }

    fn lower_bound(&self, a: S::State, b: S::State) -> Cost {
        (S::point(&b) - S::point(&a)).norm()
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
        if !S::DIRECTED {
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

impl<S: Steering> Graph for Prm<S> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.states.len()
    }
}

impl<S: Steering> Successors for Prm<S> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_out(node, visit)
    }
}

impl<S: Steering> Predecessors for Prm<S> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_in(node, visit)
    }
}

impl<S: Steering> IndexedGraph for Prm<S> {
    fn node_bound(&self) -> usize {
        self.states.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}

/// A saved roadmap: the world, the settings, the nodes, every edge tried and where the sample
/// stream stands.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PrmDocument<S> {
    world: PolygonWorld,
    steering: S,
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

impl<S: Steering + Serialize> Serialize for Prm<S> {
    /// Saves as `{"world", "steering", "options", "nodes", "edges", "stream"}`.
    fn serialize<Ser: serde::Serializer>(&self, serializer: Ser) -> Result<Ser::Ok, Ser::Error> {
        PrmDocument {
            world: self.checker.world().clone(),
            steering: self.steering,
            options: self.options,
            nodes: self.states.iter().map(S::coordinates).collect(),
            edges: self
                .candidates
                .iter()
                .map(|c| [c.ends[0], c.ends[1], u32::from(c.cost.is_finite())])
                .collect(),
            stream: StreamDocument {
                word_position: self.stream.rng.get_word_pos().to_string(),
                halton_index: self.stream.halton_index,
                attempts: self.stream.attempts,
            },
        }
        .serialize(serializer)
    }
}

impl<'de, S: Steering + Deserialize<'de>> Deserialize<'de> for Prm<S> {
    /// Loads a saved roadmap, re-checking every node and every edge's free or blocked state in
    /// the saved world; a mismatch is an error, not a silent repair.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let document = PrmDocument::<S>::deserialize(deserializer)?;
        Prm::from_document(document).map_err(serde::de::Error::custom)
    }
}

impl<S: Steering> Prm<S> {
    fn from_document(d: PrmDocument<S>) -> Result<Self, PrmError> {
        let mut prm = Prm::with_steering(d.world, d.steering, d.options)?;
        for (index, coordinates) in d.nodes.iter().enumerate() {
            let state = S::from_coordinates(coordinates).ok_or(PrmError::InvalidNode { index })?;
            if !prm.is_free(&state) || prm.find(&state).is_some() {
                return Err(PrmError::InvalidNode { index });
            }
            prm.push_node(state);
        }
        let n = prm.states.len() as u32;
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
        prm.stream.halton_index = d.stream.halton_index;
        prm.stream.attempts = d.stream.attempts;
        prm.local_paths_checked = 0;
        Ok(prm)
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use trailmark_core::generate::convex_obstacles;

    use super::*;

    fn world(seed: u64, radius: f64) -> PolygonWorld {
        convex_obstacles(20.0, 12, 6, radius, seed).expect("a valid world")
    }

    fn options(connection: Connection) -> PrmOptions {
        PrmOptions { connection, ..PrmOptions::default() }
    }

    #[test]
    fn halton_matches_the_van_der_corput_sequence() {
        let base2: Vec<f64> = (1..=7).map(|i| radical_inverse(i, 2)).collect();
        assert_eq!(base2, [0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]);
        let base3: Vec<f64> = (1..=4).map(|i| radical_inverse(i, 3)).collect();
        let expected = [1.0 / 3.0, 2.0 / 3.0, 1.0 / 9.0, 4.0 / 9.0];
        for (got, want) in base3.iter().zip(expected) {
            assert!((got - want).abs() < 1e-15, "{got} vs {want}");
        }
    }

    #[test]
    fn prm_star_uses_karaman_and_frazzolis_k() {
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
        assert_eq!(Prm::new(w, none).err(), Some(PrmError::InvalidAttempts));
        assert!(DubinsSteering::new(0.0).is_err() && DubinsSteering::new(f64::NAN).is_err());
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
        for sampler in [Sampler::Halton, Sampler::Uniform { seed: 9 }] {
            let o = PrmOptions { sampler, ..options(Connection::PrmStar) };
            let mut once = Prm::new(world(6, 0.3), o).unwrap();
            once.grow(90).unwrap();
            let mut steps = Prm::new(world(6, 0.3), o).unwrap();
            steps.grow(40).unwrap();
            steps.grow(50).unwrap();
            assert_eq!(once.states, steps.states);
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
        assert_eq!(loaded.states, prm.states);
        assert_eq!(loaded.edges().collect::<Vec<_>>(), prm.edges().collect::<Vec<_>>());
        assert_eq!(loaded.candidate_count(), prm.candidate_count());
        assert_eq!(loaded.component_count(), prm.component_count());
        prm.grow(20).unwrap();
        loaded.grow(20).unwrap();
        assert_eq!(loaded.states, prm.states);
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
        let steering = DubinsSteering::new(1.5).unwrap();
        let o = PrmOptions { sampler: Sampler::Halton, ..options(Connection::Nearest { k: 8 }) };
        let mut prm = Prm::with_steering(world(9, 0.3), steering, o).unwrap();
        prm.grow(80).unwrap();
        let checker = prm.world().checker();
        let mut asymmetric = 0;
        for (a, b, cost) in prm.edges() {
            let path = steering.path(&prm.position(a), &prm.position(b)).unwrap();
            assert!(checker.dubins_is_free(&path));
            assert_eq!(cost, path.length());
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
