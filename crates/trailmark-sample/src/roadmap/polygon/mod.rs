//! Probabilistic roadmaps: samples in free space joined by collision-free local paths.
//!
//! A [`PolygonPrm`] draws configurations in the free space of a [`PolygonWorld`] (seeded uniform
//! samples, or a deterministic Halton sequence), and joins each new node to its neighbours
//! among the nodes already there (the k nearest, those within a radius, or PRM*'s
//! k = ⌈e(1 + 1/d) ln n⌉) wherever the local path between them is collision-free. Every local
//! path is checked exactly against the obstacles by the world's [`CollisionChecker`] (segment
//! and arc distances, not sampling); nearest neighbours come from a k-d tree (kiddo).
//!
//! It is [`Prm`](crate::Prm), the one roadmap of this crate, with the world kept beside it: the
//! states, motions and distances are a state space of `trailmark-space` ([`PlanarSpace`]):
//! [`R2`] segments for a disc robot (an undirected
//! roadmap over points), or [`Dubins`](trailmark_space::Dubins) curves for a car-like robot (a directed roadmap
//! over poses, since a Dubins path from `a` to `b` is not the reverse of one from `b` to `a`).
//!
//! A roadmap grows incrementally ([`PolygonPrm::grow`], [`PolygonPrm::insert`]), tracks its connected
//! components, saves and loads with serde (re-checking everything it loads), reports which
//! edges changed when an obstacle is added or removed ([`PolygonPrm::add_obstacle`],
//! [`PolygonPrm::remove_obstacle`]) so D* Lite can repair its path, and answers queries without
//! changing ([`PolygonPrm::query`]).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let world = PolygonWorld::new(bounds, vec![wall], 0.25)?;
//!
//! let options = PrmOptions { sampler: PrmSampler::Halton, connection: Connection::PrmStar, ..PrmOptions::default() };
//! let mut prm = PolygonPrm::new(world, options)?;
//! prm.grow(300)?;
//! assert_eq!(prm.node_count(), 300);
//!
//! let query = prm.query(Point::new(1.0, 1.0), Point::new(9.0, 1.0))?;
//! let route = trailmark_search::astar(&query, query.start(), query.goal(), query.heuristic())?;
//! let cost = route.cost().expect("the gap above the wall joins the two sides");
//! assert!(cost >= 14.5); // up past the wall's top (y = 8 + 0.25) and down again, at least
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use trailmark_core::cost::Cost;
use trailmark_core::geometry::Point;
use trailmark_core::graph::EdgeChange;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_graph::RoadmapQuery;
use trailmark_space::nearest::{Direction, KdNearest};
use trailmark_space::sampler::{Draw, StateSampler};
use trailmark_space::space::R2;

pub use trailmark_space::Connection;

use super::prm::{Candidate, Prm};

mod document;
mod graph;
mod options;
mod space;

use options::Drawer;
pub use options::{MAX_ROADMAP_NODES, PrmError, PrmOptions, PrmSampler};
use space::ExactValidity;
pub use space::PlanarSpace;

/// A probabilistic roadmap over a polygon world, in any [`PlanarSpace`]: [`R2`] (straight
/// segments for a disc robot, an undirected roadmap over points) by default, or
/// [`Dubins`](trailmark_space::Dubins) (a directed roadmap over poses, since a Dubins path
/// from `a` to `b` is not the reverse of one from `b` to `a`). Node `i` is at
/// [`PolygonPrm::position`]; edges cost their motion's distance in the space.
///
/// It implements the graph traits itself (with permanent nodes from [`PolygonPrm::insert`]) and
/// [`Roadmap`](trailmark_graph::Roadmap), so [`PolygonPrm::query`] joins a start and a goal without changing it.
#[derive(Clone, Debug)]
pub struct PolygonPrm<S: PlanarSpace = R2> {
    checker: CollisionChecker,
    space: S,
    options: PrmOptions,
    /// The milestones and every motion tried between them, blocked ones too (for
    /// [`add_obstacle`](Self::add_obstacle) and [`remove_obstacle`](Self::remove_obstacle)),
    /// drawn by the options' sampler from the roadmap's own stream.
    roadmap: Prm<S, KdNearest<S, 2>, Drawer>,
    /// Draws made by the sampler so far.
    attempts: u64,
}

/// A probabilistic roadmap of Dubins paths between poses.
pub type DubinsPrm = PolygonPrm<trailmark_space::Dubins>;

/// A probabilistic roadmap of Reeds-Shepp paths between poses (a car that reverses: each edge
/// costs the same both ways).
pub type ReedsSheppPrm = PolygonPrm<trailmark_space::ReedsShepp>;

/// A [`PolygonPrm`] with a start and a goal joined to it.
pub type PrmQuery<'g, S = R2> = RoadmapQuery<'g, PolygonPrm<S>>;

impl PolygonPrm<R2> {
    /// An empty roadmap of straight segments over `world` (the space [`R2`] of its bounds).
    pub fn new(world: PolygonWorld, options: PrmOptions) -> Result<Self, PrmError> {
        let space = R2::new(world.bounds());
        Self::with_space(world, space, options)
    }
}

impl<S: PlanarSpace> PolygonPrm<S> {
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
        let mut roadmap = Prm::new(nearest)
            .with_connection(options.connection)
            .with_seed(options.sampler.seed())
            .with_sampler(drawer);
        roadmap.keep_blocked();
        Ok(PolygonPrm { checker: world.checker(), space, options, roadmap, attempts: 0 })
    }

    /// Draws `samples` more free configurations and joins each to the roadmap; returns the
    /// indices of the new nodes' range start. Fails with [`PrmError::SamplingExhausted`] after
    /// `attempts_per_sample × samples` draws, or as soon as fewer than one draw in
    /// `attempts_per_sample` has been free over `attempts_per_sample × (added + 10)` draws,
    /// keeping the samples found; with [`PrmError::TooManyNodes`] before any draw if the
    /// roadmap would pass [`MAX_ROADMAP_NODES`].
    pub fn grow(&mut self, samples: usize) -> Result<std::ops::Range<u32>, PrmError> {
        if self.node_count().saturating_add(samples) > MAX_ROADMAP_NODES {
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
            if let Some(c) = self.connect(&self.checker, &start, self.roadmap.state(u)) {
                from_start[u as usize] = c;
            }
        }
        for (u, _) in self.neighbours_of(&goal, Direction::ToQuery, n + 1) {
            if let Some(c) = self.connect(&self.checker, self.roadmap.state(u), &goal) {
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
        Ok(RoadmapQuery::new(self, (start, goal), from_start, to_goal, direct)
            .expect("a link per roadmap node"))
    }

    /// Adds an obstacle (checked like the world's) and blocks the edges it collides with.
    /// Returns the changed edges, in both directions for an undirected
    /// roadmap, for [`DStarLite::update_edges`](https://docs.rs/trailmark-search) after the
    /// change. Nodes inside the obstacle stay, with all their edges blocked.
    pub fn add_obstacle(&mut self, vertices: Vec<Point>) -> Result<Vec<EdgeChange<u32>>, PrmError> {
        let world = self.checker.world().with_obstacle(vertices)?;
        let added = world.obstacles().last().expect("just added").clone();
        let alone = world.only(added).checker();
        self.checker = world.checker();
        let mut changes = Vec::new();
        for id in 0..self.roadmap.tried.len() {
            let Candidate { ends: [a, b], cost } = self.roadmap.tried[id];
            if cost.is_finite() && self.local_path(&alone, a, b).is_none() {
                self.roadmap.set_cost(id, Cost::INFINITY);
                self.report(&mut changes, a, b);
            }
        }
        self.roadmap.rebuild_components();
        Ok(changes)
    }

    /// Removes obstacle `index` (later obstacles move down by one) and restores the edges it
    /// alone blocked. Returns the changed edges, as
    /// [`add_obstacle`](Self::add_obstacle) does.
    pub fn remove_obstacle(&mut self, index: usize) -> Result<Vec<EdgeChange<u32>>, PrmError> {
        let (world, removed) = self.checker.world().without_obstacle(index)?;
        let alone = world.only(removed).checker();
        self.checker = world.checker();
        let mut changes = Vec::new();
        for id in 0..self.roadmap.tried.len() {
            let Candidate { ends: [a, b], cost } = self.roadmap.tried[id];
            if cost.is_infinite()
                && self.local_path(&alone, a, b).is_none()
                && let Some(c) = self.local_path(&self.checker, a, b)
            {
                self.roadmap.set_cost(id, c);
                self.report(&mut changes, a, b);
            }
        }
        self.roadmap.rebuild_components();
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
        self.roadmap.node_count()
    }

    /// The number of free edges (each undirected edge once).
    pub fn edge_count(&self) -> usize {
        self.roadmap.edge_count()
    }

    /// The number of edges tried, free or blocked.
    pub fn candidate_count(&self) -> usize {
        self.roadmap.tried.len()
    }

    /// The configuration of `node`.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count): node ids are indices, as a
    /// slice's. [`get_position`](Self::get_position) is the checked form.
    pub fn position(&self, node: u32) -> S::State {
        *self.roadmap.state(node)
    }

    /// The configuration of `node`, `None` if the roadmap has no such node.
    pub fn get_position(&self, node: u32) -> Option<S::State> {
        ((node as usize) < self.node_count()).then(|| self.position(node))
    }

    /// The free edges, as `(from, to, cost)`, each undirected edge once.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32, Cost)> + '_ {
        self.roadmap.tried.iter().filter(|c| c.cost.is_finite()).map(|c| (c.ends[0], c.ends[1], c.cost))
    }

    /// Draws made by the sampler so far (accepted or not).
    pub fn attempts(&self) -> u64 {
        self.attempts
    }

    /// Local paths collision-checked so far (building and querying a copy do not share this).
    pub fn local_paths_checked(&self) -> u64 {
        self.roadmap.checks
    }

    /// The number of connected components (ignoring edge direction).
    pub fn component_count(&self) -> usize {
        self.roadmap.component_count()
    }

    /// A representative of `node`'s connected component (ignoring edge direction): two nodes
    /// are connected exactly when their representatives are equal.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count).
    /// [`get_component`](Self::get_component) is the checked form.
    pub fn component(&self, node: u32) -> u32 {
        self.roadmap.component(node)
    }

    /// The representative of `node`'s connected component, `None` if the roadmap has no such
    /// node.
    pub fn get_component(&self, node: u32) -> Option<u32> {
        ((node as usize) < self.node_count()).then(|| self.component(node))
    }

    /// One draw of the sampler (`None` when it found nothing).
    fn draw(&mut self) -> Option<S::State> {
        self.attempts += 1;
        let validity = ExactValidity(&self.checker);
        let mut checks = 0;
        let roadmap = &mut self.roadmap;
        let seed = self.options.sampler.seed();
        let rng = roadmap.rng.get_or_insert_with(|| rand::SeedableRng::seed_from_u64(seed));
        roadmap.sampler.sample(&self.space, &validity, &mut Draw::new(rng, &mut checks))
    }

    /// Whether `state` is within the space's bounds and free.
    fn is_free(&self, state: &S::State) -> bool {
        self.space.satisfies_bounds(state) && self.space.state_is_free(&self.checker, state)
    }

    /// The cost of the motion from `from` to `to` in the world of `checker`, `None` if it
    /// collides.
    fn connect(&self, checker: &CollisionChecker, from: &S::State, to: &S::State) -> Option<Cost> {
        motion_cost(&self.space, checker, from, to)
    }

    /// The nodes a configuration `state` joins in a roadmap of `n` nodes, nearest first, with
    /// their distances measured the way `direction` says.
    fn neighbours_of(&self, state: &S::State, direction: Direction, n: usize) -> Vec<(u32, f64)> {
        self.roadmap.neighbours(&self.space, state, direction, n)
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
        let (space, checker) = (&self.space, &self.checker);
        let motion = |from: &S::State, to: &S::State, _| motion_cost(space, checker, from, to);
        self.roadmap
            .add_checked(space, state, MAX_ROADMAP_NODES, motion, || false)
            .ok_or(PrmError::TooManyNodes)
    }

    fn local_path(&self, checker: &CollisionChecker, from: u32, to: u32) -> Option<Cost> {
        self.connect(checker, self.roadmap.state(from), self.roadmap.state(to))
    }

    fn report(&self, changes: &mut Vec<EdgeChange<u32>>, a: u32, b: u32) {
        changes.push(EdgeChange::new(a, b));
        if S::SYMMETRIC {
            changes.push(EdgeChange::new(b, a));
        }
    }
}

/// The cost of `space`'s motion from `from` to `to` in the world of `checker`, `None` if it
/// collides.
fn motion_cost<S: PlanarSpace>(
    space: &S,
    checker: &CollisionChecker,
    from: &S::State,
    to: &S::State,
) -> Option<Cost> {
    space.motion_is_free(checker, from, to).then(|| space.distance(from, to))
}

#[cfg(test)]
mod tests;
