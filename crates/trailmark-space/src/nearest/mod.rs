//! Nearest-neighbour structures over the states of a tree: exact answers for every space.
//!
//! [`NearestNeighbors`] stores states under ids `0, 1, 2, ...` and answers the nearest, the `k`
//! nearest, and all within a radius, measuring the distance *from* the stored state *to* the
//! query ([`Direction::ToQuery`], the motion a tree grows along) or back
//! ([`Direction::FromQuery`], for a tree grown backward from a goal): the two differ in
//! asymmetric spaces such as [`Dubins`](crate::space::Dubins).
//!
//! [`KdNearest`] keeps the states' positions in a k-d tree ([`KdTree`], which stays shallow
//! whatever order the states arrive in) and is exact for every space
//! whose distance is at least the straight-line distance of the positions (every space of this
//! crate): candidates come from the tree in order of that lower bound, and the search
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

mod kd;
mod kd_leaf;
mod kd_search;
mod kd_tree;

pub use kd::KdNearest;
pub use kd_tree::KdTree;

use crate::space::StateSpace;

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
pub(super) fn by_distance(a: &(u32, f64), b: &(u32, f64)) -> std::cmp::Ordering {
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
        measure_all(space, &self.states, query, direction)
    }
}

/// Every state of `states` (numbered by position) measured, nearest first (ties by id).
pub(super) fn measure_all<S: StateSpace>(
    space: &S,
    states: &[S::State],
    query: &S::State,
    direction: Direction,
) -> Vec<(u32, f64)> {
    let mut all: Vec<(u32, f64)> =
        states.iter().enumerate().map(|(i, s)| (i as u32, measure(space, s, query, direction))).collect();
    all.sort_unstable_by(by_distance);
    all
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
