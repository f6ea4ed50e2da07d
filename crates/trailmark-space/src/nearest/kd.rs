//! [`KdNearest`]: the states' positions in a [`KdTree`], candidates measured by the space's own
//! distance.

use std::collections::HashSet;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use super::{Direction, KdTree, NearestNeighbors, by_distance, measure, measure_all};
use crate::space::{SpaceError, StateSpace};

/// A k-d tree ([`KdTree`]) over the states' `D`-dimensional positions
/// ([`StateSpace::position`]), exact for spaces whose distance is at least the positions'
/// straight-line distance. States at the same position share one tree entry (so that a tree
/// of many equal positions is no deeper, and each is measured once a query).
#[derive(Debug, Clone)]
pub struct KdNearest<S: StateSpace, const D: usize> {
    states: Vec<S::State>,
    tree: KdTree<D>,
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
            tree: KdTree::new(),
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
    fn members(&self, group: u32) -> impl Iterator<Item = u32> + '_ {
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
            self.tree.insert(at, group);
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
        let mut measured: Option<HashSet<u32>> = None;
        loop {
            let candidates = self.tree.nearest_n(&at, asked);
            // Measure the groups not measured before (equal bounds may come in another order).
            for &(group, _) in &candidates {
                if measured.as_mut().is_none_or(|m| m.insert(group)) {
                    for id in self.members(group) {
                        best.push((id, measure(space, &self.states[id as usize], query, direction)));
                    }
                }
            }
            best.sort_unstable_by(by_distance);
            best.truncate(k);
            if candidates.len() == self.head.len() {
                return best;
            }
            // Fewer than asked: the others are at no comparable distance by position (a NaN
            // coordinate): the space's distance decides, measured for every state.
            if candidates.len() < asked {
                let mut all = measure_all(space, &self.states, query, direction);
                all.truncate(k);
                return all;
            }
            // Every group not returned is at least this far by the lower bound.
            let bound = candidates.last().map_or(0.0, |c| c.1.sqrt());
            if best.len() == k && best[k - 1].1 < bound {
                return best;
            }
            measured.get_or_insert_with(|| candidates.iter().map(|c| c.0).collect());
            asked = (asked * 2).min(self.head.len());
        }
    }

    /// The tree's nearest positions first; then, unless the nearest of them is as near by the
    /// space's distance, every other position whose lower bound is within the best true
    /// distance found, measured too.
    fn nearest(&self, space: &S, query: &S::State, direction: Direction) -> Option<(u32, f64)> {
        if self.states.is_empty() {
            return None;
        }
        if self.states.len() <= SCAN {
            return self.scan(space, query, direction);
        }
        let at = Self::key(space, query);
        // The positions nearest (with those within a rounding allowance of it): where the
        // space's distance is the straight-line one, the nearest state is among them.
        let (close, bound) = self.tree.nearest_within(&at, 1.0 + 1e-9);
        if close.is_empty() {
            return self.scan(space, query, direction);
        }
        let consider = |best: &mut Option<(u32, f64)>, group: u32| {
            for id in self.members(group) {
                let candidate = (id, measure(space, &self.states[id as usize], query, direction));
                if best.is_none_or(|b| by_distance(&candidate, &b).is_lt()) {
                    *best = Some(candidate);
                }
            }
        };
        let mut best = None;
        for &(group, _) in &close {
            consider(&mut best, group);
        }
        let reach = best.map_or(f64::NAN, |b: (u32, f64)| b.1);
        if reach.is_nan() {
            // No comparable distance among them: every state measured.
            return self.scan(space, query, direction);
        }
        // Every other position is farther than `bound` allows, so by the space's distance too.
        if reach * reach * (1.0 + 1e-12) < bound {
            return best;
        }
        // The space's distance is longer than the straight line (a car's turns): every other
        // position within the best true distance found (widened by a rounding allowance, as in
        // `within`).
        for (group, _) in self.tree.within(&at, reach * reach * (1.0 + 1e-9)) {
            if !close.iter().any(|&(measured, _)| measured == group) {
                consider(&mut best, group);
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
        for (group, _) in self.tree.within(&at, radius * radius * (1.0 + 1e-9)) {
            for id in self.members(group) {
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
