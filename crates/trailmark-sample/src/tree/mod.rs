//! The tree planners: RRT, RRT-Connect, RRT* and Informed RRT*, each in its file (how it grows its
//! trees; `star.rs` the run RRT* and Informed RRT* share), and
//! what they share: the tree of valid motions they grow toward targets at most a range at a
//! time (here), their settings (`options.rs`), and the planner every one of them is
//! (`planner.rs`: `TreePlanner`, its builders and its `Planner` impl).

pub mod informed_rrt_star;
pub mod options;
pub mod planner;
pub mod rrt;
pub mod rrt_connect;
pub mod rrt_star;
pub(crate) mod star;

use crate::nearest::{Direction, NearestNeighbors, measure};
use crate::space::StateSpace;
use crate::validity::Validity;

/// The parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

/// A tree of states: each with its parent, searched through a nearest-neighbour structure.
pub(crate) struct Tree<S: StateSpace, N> {
    pub(crate) nearest: N,
    parents: Vec<u32>,
    /// Forward (motions from the roots out) or backward (motions into the roots).
    direction: Direction,
    _space: std::marker::PhantomData<fn() -> S>,
}

/// What one extension did.
pub(crate) enum Extension {
    /// Nothing added: the motion was refused or went nowhere.
    Trapped,
    /// A state `range` toward the target.
    Advanced(u32),
    /// The target itself.
    Reached(u32),
}

impl<S: StateSpace, N> Tree<S, N> {
    /// The nearest-neighbour structure and the parents, for the planner to keep.
    pub(crate) fn into_parts(self) -> (N, Vec<u32>) {
        (self.nearest, self.parents)
    }
}

impl<S: StateSpace, N: NearestNeighbors<S>> Tree<S, N> {
    /// A tree with no states, growing in `direction`.
    pub(crate) fn new(nearest: N, direction: Direction) -> Self {
        Tree { nearest, parents: Vec::new(), direction, _space: std::marker::PhantomData }
    }

    /// Adds `state` as a root; its id.
    pub(crate) fn add_root(&mut self, space: &S, state: S::State) -> u32 {
        self.insert(space, state, ROOT)
    }

    pub(crate) fn len(&self) -> usize {
        self.nearest.len()
    }

    pub(crate) fn state(&self, id: u32) -> &S::State {
        self.nearest.state(id)
    }

    /// Grows one motion of at most `range` toward `target`.
    pub(crate) fn extend<V: Validity<S>>(
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
    pub(crate) fn extend_from<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        near: u32,
        d: f64,
        target: &S::State,
        range: f64,
        checks: &mut u64,
    ) -> Extension {
        let Some((new, reached)) = self.step_toward(space, near, d, target, range) else {
            return Extension::Trapped;
        };
        let from = self.state(near);
        *checks += 1;
        let valid = match self.direction {
            Direction::ToQuery => validity.motion_is_valid(space, from, &new),
            Direction::FromQuery => validity.motion_is_valid(space, &new, from),
        };
        if !valid {
            return Extension::Trapped;
        }
        let id = self.insert(space, new, near);
        if reached { Extension::Reached(id) } else { Extension::Advanced(id) }
    }

    /// The state at most `range` from state `near` toward `target` (`d` from it in the tree's
    /// direction), and whether that is the target itself: the steering every tree planner
    /// shares. `None` when the step goes nowhere, or leaves the bounds (every state of a tree is
    /// in bounds: a target outside them, or a step rounded across them, is refused).
    pub(crate) fn step_toward(
        &self,
        space: &S,
        near: u32,
        d: f64,
        target: &S::State,
        range: f64,
    ) -> Option<(S::State, bool)> {
        let from = self.state(near);
        let (new, reached) = if d <= range {
            (target.clone(), true)
        } else {
            match self.direction {
                // Forward: range along the motion from the tree toward the target.
                Direction::ToQuery => (space.interpolate(from, target, range / d), false),
                // Backward: range before the tree along the motion from the target into it.
                Direction::FromQuery => (space.interpolate(target, from, 1.0 - range / d), false),
            }
        };
        (new != *from && space.satisfies_bounds(&new)).then_some((new, reached))
    }

    /// Adds `state` with `parent` (a state of the tree, or [`ROOT`]); its id.
    pub(crate) fn insert(&mut self, space: &S, state: S::State, parent: u32) -> u32 {
        self.parents.push(parent);
        self.nearest.insert(space, state)
    }

    /// Keeps the states `id` with `keep[id]`, whose parents must be kept too, renumbered in
    /// their order into `empty` (a structure with no states); the new id of every state kept,
    /// indexed by its old one (the others' entries are meaningless).
    pub(crate) fn retain(&mut self, space: &S, keep: &[bool], empty: N) -> Vec<u32> {
        let mut renumbered = vec![ROOT; keep.len()];
        let mut nearest = empty;
        for (old, _) in keep.iter().enumerate().filter(|k| *k.1) {
            renumbered[old] = nearest.insert(space, self.state(old as u32).clone());
        }
        self.parents = (0..keep.len())
            .filter(|&old| keep[old])
            .map(|old| match self.parents[old] {
                ROOT => ROOT,
                p => renumbered[p as usize],
            })
            .collect();
        self.nearest = nearest;
        renumbered
    }

    /// The parent of state `id` ([`ROOT`] for a root).
    pub(crate) fn parent(&self, id: u32) -> u32 {
        self.parents[id as usize]
    }

    /// Makes `parent` the parent of state `id` (RRT*'s rewiring).
    pub(crate) fn set_parent(&mut self, id: u32, parent: u32) {
        self.parents[id as usize] = parent;
    }

    /// The distance from state `id` to `target` in the tree's direction (the query's motions
    /// run from the tree toward it, or from it into the tree).
    pub(crate) fn gap(&self, space: &S, id: u32, target: &S::State) -> f64 {
        measure(space, self.state(id), target, self.direction)
    }

    /// The states from a root to `id`.
    pub(crate) fn branch(&self, mut id: u32) -> Vec<S::State> {
        let mut states = Vec::new();
        while id != ROOT {
            states.push(self.state(id).clone());
            id = self.parents[id as usize];
        }
        states.reverse();
        states
    }
}
