//! Nearest-neighbour structures over the states of a tree: exact answers for every space.
//!
//! [`NearestNeighbors`] stores states under ids `0, 1, 2, ...` and answers the nearest, the `k`
//! nearest, and all within a radius, measuring the distance *from* the stored state *to* the
//! query ([`Direction::ToQuery`], the motion a tree grows along) or back
//! ([`Direction::FromQuery`], for a tree grown backward from a goal): the two differ in
//! asymmetric spaces such as [`Dubins`](crate::space::Dubins).
//!
//! [`KdNearest`] keeps the states' positions in a k-d tree (kiddo) and is exact for every space
//! whose distance is at least the straight-line distance of the positions (all four spaces of
//! this crate): candidates come from the tree in order of that lower bound, and the search
//! stops once the bound exceeds the k-th best true distance. [`BruteForce`] measures every
//! state, the reference the tests compare with.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::Bounds;
//! use trailmark_space::nearest::{Direction, KdNearest, NearestNeighbors};
//! use trailmark_space::space::R2;
//!
//! let space = R2::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?);
//! let mut tree = KdNearest::<R2, 2>::new(&space)?;
//! for p in [Point::new(1.0, 1.0), Point::new(5.0, 5.0), Point::new(9.0, 1.0)] {
//!     tree.insert(&space, p);
//! }
//! let q = Point::new(6.0, 4.0);
//! assert_eq!(tree.nearest(&space, &q, Direction::ToQuery).map(|(id, _)| id), Some(1));
//! let two: Vec<u32> = tree.k_nearest(&space, &q, 2, Direction::ToQuery).iter().map(|n| n.0).collect();
//! assert_eq!(two, [1, 2]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::collections::HashSet;

use kiddo::SquaredEuclidean;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::space::{SpaceError, StateSpace};

/// Which way a distance is measured between a stored state and a query.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From the stored state to the query: `distance(stored, query)`.
    ToQuery,
    /// From the query to the stored state: `distance(query, stored)`.
    FromQuery,
}

/// The distance between a stored state and a query, measured the way `direction` says.
pub fn measure<S: StateSpace>(space: &S, stored: &S::State, query: &S::State, direction: Direction) -> f64 {
    match direction {
        Direction::ToQuery => space.distance(stored, query),
        Direction::FromQuery => space.distance(query, stored),
    }
}

/// A set of states, numbered in insertion order, that answers proximity queries exactly.
pub trait NearestNeighbors<S: StateSpace> {
    /// Stores `state`; returns its id (the number of states stored before it).
    fn insert(&mut self, space: &S, state: S::State) -> u32;

    /// The number of states stored.
    fn len(&self) -> usize;

    /// Whether no state is stored.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The state with id `id`.
    fn state(&self, id: u32) -> &S::State;

    /// The `k` nearest states and their distances, nearest first (ties by id).
    fn k_nearest(&self, space: &S, query: &S::State, k: usize, direction: Direction) -> Vec<(u32, f64)>;

    /// Every state within `radius` (inclusive), nearest first (ties by id).
    fn within(&self, space: &S, query: &S::State, radius: f64, direction: Direction) -> Vec<(u32, f64)>;

    /// The nearest state and its distance.
    fn nearest(&self, space: &S, query: &S::State, direction: Direction) -> Option<(u32, f64)> {
        self.k_nearest(space, query, 1, direction).first().copied()
    }
}

/// Nearest first, ties by id.
fn by_distance(a: &(u32, f64), b: &(u32, f64)) -> std::cmp::Ordering {
    a.1.total_cmp(&b.1).then(a.0.cmp(&b.0))
}

/// Every state measured: the reference answer, and fast enough for a few hundred states.
#[derive(Debug, Clone)]
pub struct BruteForce<S: StateSpace> {
    states: Vec<S::State>,
}

impl<S: StateSpace> Default for BruteForce<S> {
    fn default() -> Self {
        BruteForce { states: Vec::new() }
    }
}

impl<S: StateSpace> BruteForce<S> {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    fn all(&self, space: &S, query: &S::State, direction: Direction) -> Vec<(u32, f64)> {
        let mut all: Vec<(u32, f64)> = self
            .states
            .iter()
            .enumerate()
            .map(|(i, s)| (i as u32, measure(space, s, query, direction)))
            .collect();
        all.sort_unstable_by(by_distance);
        all
    }
}

impl<S: StateSpace> NearestNeighbors<S> for BruteForce<S> {
    fn insert(&mut self, _space: &S, state: S::State) -> u32 {
        self.states.push(state);
        self.states.len() as u32 - 1
    }

    fn len(&self) -> usize {
        self.states.len()
    }

    fn state(&self, id: u32) -> &S::State {
        &self.states[id as usize]
    }

    fn k_nearest(&self, space: &S, query: &S::State, k: usize, direction: Direction) -> Vec<(u32, f64)> {
        let mut all = self.all(space, query, direction);
        all.truncate(k);
        all
    }

    fn within(&self, space: &S, query: &S::State, radius: f64, direction: Direction) -> Vec<(u32, f64)> {
        let mut all = self.all(space, query, direction);
        all.retain(|n| n.1 <= radius);
        all
    }
}

/// A k-d tree (kiddo) over the states' `D`-dimensional positions
/// ([`StateSpace::position`]), exact for spaces whose distance is at least the positions'
/// straight-line distance. States at the same position share one tree entry (kiddo allows only
/// a bucket's worth of equal points).
#[derive(Debug, Clone)]
pub struct KdNearest<S: StateSpace, const D: usize> {
    states: Vec<S::State>,
    tree: kiddo::KdTree<f64, D>,
    /// The last id stored at each tree entry's position; the others follow through `next`
    /// (a list per entry, so that storing a state allocates nothing of its own).
    head: Vec<u32>,
    /// The id stored before each id at the same position, or `NONE`.
    next: Vec<u32>,
    /// The tree entry of each position stored (by the bits of its coordinates).
    group_of: foldhash::HashMap<[u64; D], u32>,
}

/// Up to this many states, [`KdNearest::nearest`] measures them all instead of asking the tree.
const SCAN: usize = 32;

/// The end of a list of ids.
const NONE: u32 = u32::MAX;

impl<S: StateSpace, const D: usize> KdNearest<S, D> {
    /// An empty set for states of `space`, whose positions must have `D` coordinates
    /// ([`SpaceError::NoPosition`] otherwise).
    pub fn new(space: &S) -> Result<Self, SpaceError> {
        let probe = space.sample(&mut ChaCha8Rng::seed_from_u64(0));
        if space.position::<D>(&probe).is_none() {
            return Err(SpaceError::NoPosition { dimension: D });
        }
        Ok(KdNearest {
            states: Vec::new(),
            tree: kiddo::KdTree::new(),
            head: Vec::new(),
            next: Vec::new(),
            group_of: foldhash::HashMap::default(),
        })
    }

    /// The nearest of all states, each measured: for a few states, quicker than the tree.
    fn scan(&self, space: &S, query: &S::State, direction: Direction) -> Option<(u32, f64)> {
        let measured =
            self.states.iter().enumerate().map(|(id, s)| (id as u32, measure(space, s, query, direction)));
        measured.min_by(by_distance)
    }

    /// The ids stored at tree entry `group`.
    fn members(&self, group: u64) -> impl Iterator<Item = u32> + '_ {
        let listed = |id: u32| (id != NONE).then_some(id);
        std::iter::successors(listed(self.head[group as usize]), move |&id| listed(self.next[id as usize]))
    }

    fn key(space: &S, state: &S::State) -> [f64; D] {
        space.position::<D>(state).expect("checked by KdNearest::new: the space has D-dimensional positions")
    }
}

impl<S: StateSpace, const D: usize> NearestNeighbors<S> for KdNearest<S, D> {
    fn insert(&mut self, space: &S, state: S::State) -> u32 {
        let id = self.states.len() as u32;
        let at = Self::key(space, &state);
        let bits = at.map(|c| (c + 0.0).to_bits());
        let fresh = self.head.len() as u32;
        let group = *self.group_of.entry(bits).or_insert(fresh);
        if group == fresh {
            self.head.push(NONE);
            self.tree.add(&at, u64::from(group));
        }
        self.next.push(self.head[group as usize]);
        self.head[group as usize] = id;
        self.states.push(state);
        id
    }

    fn len(&self) -> usize {
        self.states.len()
    }

    fn state(&self, id: u32) -> &S::State {
        &self.states[id as usize]
    }

    fn k_nearest(&self, space: &S, query: &S::State, k: usize, direction: Direction) -> Vec<(u32, f64)> {
        if k == 0 || self.states.is_empty() {
            return Vec::new();
        }
        let at = Self::key(space, query);
        let mut best: Vec<(u32, f64)> = Vec::new();
        // One candidate more than asked: where the distance is the straight-line one (R², Rⁿ),
        // the k-th best is then below the bound of the next and one tree query suffices.
        let k = k.min(self.states.len());
        let mut asked = k.saturating_add(1).min(self.head.len());
        // The groups measured, kept once a second, wider query is needed.
        let mut measured: Option<HashSet<u64>> = None;
        loop {
            let candidates = self.tree.nearest_n::<SquaredEuclidean>(&at, asked);
            // Measure the groups not measured before (equal bounds may come in another order).
            for c in &candidates {
                if measured.as_mut().is_none_or(|m| m.insert(c.item)) {
                    for id in self.members(c.item) {
                        best.push((id, measure(space, &self.states[id as usize], query, direction)));
                    }
                }
            }
            best.sort_unstable_by(by_distance);
            best.truncate(k);
            if candidates.len() == self.head.len() {
                return best;
            }
            // Every group not returned is at least this far by the lower bound.
            let bound = candidates.last().map_or(0.0, |c| c.distance.sqrt());
            if best.len() == k && best[k - 1].1 < bound {
                return best;
            }
            measured.get_or_insert_with(|| candidates.iter().map(|c| c.item).collect());
            asked = (asked * 2).min(self.head.len());
        }
    }

    /// The tree's nearest position first; then every other position whose lower bound is
    /// within the best true distance found (usually none but ties), measured too.
    fn nearest(&self, space: &S, query: &S::State, direction: Direction) -> Option<(u32, f64)> {
        if self.states.is_empty() {
            return None;
        }
        if self.states.len() <= SCAN {
            return self.scan(space, query, direction);
        }
        let at = Self::key(space, query);
        let first = self.tree.nearest_one::<SquaredEuclidean>(&at).item;
        let consider = |best: &mut Option<(u32, f64)>, group: u64| {
            for id in self.members(group) {
                let candidate = (id, measure(space, &self.states[id as usize], query, direction));
                if best.is_none_or(|b| by_distance(&candidate, &b).is_lt()) {
                    *best = Some(candidate);
                }
            }
        };
        let mut best = None;
        consider(&mut best, first);
        let reach = best.map_or(0.0, |b: (u32, f64)| b.1);
        // Widened by a rounding allowance, as in `within`: the true distance decides.
        for c in self.tree.within_unsorted::<SquaredEuclidean>(&at, reach * reach * (1.0 + 1e-9)) {
            if c.item != first {
                consider(&mut best, c.item);
            }
        }
        best
    }

    fn within(&self, space: &S, query: &S::State, radius: f64, direction: Direction) -> Vec<(u32, f64)> {
        if radius.is_nan() || radius < 0.0 || self.states.is_empty() {
            return Vec::new();
        }
        let at = Self::key(space, query);
        let mut found = Vec::new();
        // A true distance within the radius has its lower bound within it too (the tree's
        // radius is widened by a rounding allowance; the true distance decides).
        for c in self.tree.within_unsorted::<SquaredEuclidean>(&at, radius * radius * (1.0 + 1e-9)) {
            for id in self.members(c.item) {
                let d = measure(space, &self.states[id as usize], query, direction);
                if d <= radius {
                    found.push((id, d));
                }
            }
        }
        found.sort_unstable_by(by_distance);
        found
    }
}
