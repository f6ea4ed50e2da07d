//! The graph BIT* searches: every valid state drawn so far (its samples), the tree of those
//! joined to a start, and what it knows of each state without a check (its admissible cost
//! from the starts and to the goal). The vertices and the samples not yet joined each have a
//! nearest-neighbour structure, so that a vertex finds its `k` nearest of each kind however
//! many of the other kind crowd around it (one structure for both had left samples among many
//! unjoined ones without a vertex in reach, and the solution stalled).

use crate::informed::{Informed, PRUNE_SLACK};
use crate::nearest::{Direction, NearestNeighbors};
use crate::problem::Goal;
use crate::run::Spent;
use crate::space::StateSpace;

/// The parent of a root, and of a sample not in the tree.
pub(crate) const NO_PARENT: u32 = u32::MAX;

/// States of one kind in a nearest-neighbour structure, by their ids in the graph; a sample
/// that joins the tree stays in its structure, skipped, until the structure is rebuilt.
#[derive(Debug, Clone)]
struct Kind<N> {
    nearest: N,
    /// The graph id of each state of `nearest`.
    ids: Vec<u32>,
    /// States of `nearest` no longer of this kind.
    gone: usize,
}

impl<N> Kind<N> {
    fn new(nearest: N) -> Self {
        Kind { nearest, ids: Vec::new(), gone: 0 }
    }
}

/// Samples and the tree among them.
#[derive(Debug, Clone)]
pub(crate) struct BatchGraph<S: StateSpace, N> {
    /// Every state, by id.
    states: Vec<S::State>,
    /// The empty structure each kind's is cloned from.
    empty: N,
    vertices: Kind<N>,
    samples: Kind<N>,
    pub(crate) parent: Vec<u32>,
    /// The cost from the root through the tree; infinite for a sample not in it.
    pub(crate) cost: Vec<f64>,
    pub(crate) children: Vec<Vec<u32>>,
    pub(crate) in_tree: Vec<bool>,
    /// The cost a vertex had when its edges were last queued (infinite: never): a vertex
    /// whose cost has not fallen since needs only the edges to new samples.
    pub(crate) expanded_at: Vec<f64>,
    /// A lower bound on the cost from the starts (`ĝ`).
    pub(crate) come: Vec<f64>,
    /// A lower bound on the cost to the goal (`ĥ`).
    pub(crate) go: Vec<f64>,
    /// Vertices that satisfy the goal.
    pub(crate) at_goal: Vec<u32>,
    /// The vertex nearest the goal and its distance, for an approximate answer.
    pub(crate) closest: (u32, f64),
}

impl<S: StateSpace, N: NearestNeighbors<S> + Clone> BatchGraph<S, N> {
    /// A graph with no states; `empty` is the structure with none that both kinds start from.
    pub(crate) fn new(empty: N) -> Self {
        BatchGraph {
            states: Vec::new(),
            vertices: Kind::new(empty.clone()),
            samples: Kind::new(empty.clone()),
            empty,
            parent: Vec::new(),
            cost: Vec::new(),
            children: Vec::new(),
            in_tree: Vec::new(),
            expanded_at: Vec::new(),
            come: Vec::new(),
            go: Vec::new(),
            at_goal: Vec::new(),
            closest: (0, f64::INFINITY),
        }
    }

    /// The number of states, samples and vertices.
    pub(crate) fn len(&self) -> usize {
        self.states.len()
    }

    /// The vertices in the tree.
    pub(crate) fn vertex_count(&self) -> usize {
        self.vertices.ids.len()
    }

    pub(crate) fn state(&self, id: u32) -> &S::State {
        &self.states[id as usize]
    }

    /// The cheapest vertex that satisfies the goal, and its cost.
    pub(crate) fn best(&self) -> Option<(u32, f64)> {
        self.at_goal.iter().map(|&g| (g, self.cost[g as usize])).min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// Stores `state` as a sample (not in the tree); its id.
    pub(crate) fn add_sample(&mut self, space: &S, set: &Informed<'_, S>, state: S::State) -> u32 {
        let id = self.states.len() as u32;
        self.come.push(set.come(space, &state));
        self.go.push(set.go(space, &state));
        self.parent.push(NO_PARENT);
        self.cost.push(f64::INFINITY);
        self.children.push(Vec::new());
        self.in_tree.push(false);
        self.expanded_at.push(f64::INFINITY);
        self.samples.nearest.insert(space, state.clone());
        self.samples.ids.push(id);
        self.states.push(state);
        id
    }

    /// Joins sample `x` to the tree under `parent` (or as a root, [`NO_PARENT`]) at `cost`.
    pub(crate) fn join(&mut self, space: &S, goal: &dyn Goal<S>, x: u32, parent: u32, cost: f64) {
        let i = x as usize;
        (self.parent[i], self.cost[i], self.in_tree[i]) = (parent, cost, true);
        if parent != NO_PARENT {
            self.children[parent as usize].push(x);
        }
        self.samples.gone += 1;
        self.vertices.nearest.insert(space, self.states[i].clone());
        self.vertices.ids.push(x);
        let to_goal = goal.distance(space, &self.states[i]);
        if to_goal < self.closest.1 {
            self.closest = (x, to_goal);
        }
        if goal.is_satisfied(space, &self.states[i]) {
            self.at_goal.push(x);
        }
    }

    /// What of the graph does not hold states, for a planner to keep past its run's clock: the
    /// two structures and the per-state lists (freeing large ones takes long enough to matter
    /// to a time limit, as for the tree planners).
    pub(crate) fn into_spent(self) -> Spent<N> {
        let mut ids = vec![self.parent, self.vertices.ids, self.samples.ids];
        ids.extend(self.children);
        Spent {
            nearest: vec![self.vertices.nearest, self.samples.nearest],
            ids,
            costs: vec![self.cost, self.expanded_at, self.come, self.go],
        }
    }

    /// The `k` nearest samples (`vertices`: vertices) to or from `state` as `direction` says,
    /// with their distances, nearest first.
    pub(crate) fn nearest(
        &self,
        space: &S,
        state: &S::State,
        k: usize,
        direction: Direction,
        vertices: bool,
    ) -> Vec<(u32, f64)> {
        let kind = if vertices { &self.vertices } else { &self.samples };
        // Ask for as many more as have left the kind, at most: joined samples are skipped.
        let mut ask = k;
        loop {
            let found = kind.nearest.k_nearest(space, state, ask, direction);
            let all = found.len() < ask;
            let live: Vec<(u32, f64)> = found
                .into_iter()
                .map(|(i, d)| (kind.ids[i as usize], d))
                .filter(|&(id, _)| self.in_tree[id as usize] == vertices)
                .take(k)
                .collect();
            if live.len() == k || all || ask >= k + kind.gone {
                return live;
            }
            ask = (2 * ask).min(k + kind.gone);
        }
    }

    /// Rebuilds the samples' structure without the samples that joined the tree once they
    /// are a quarter of it, so that queries skip few.
    pub(crate) fn tidy(&mut self, space: &S) {
        if 4 * self.samples.gone <= self.samples.ids.len() {
            return;
        }
        let mut samples = Kind::new(self.empty.clone());
        for &id in self.samples.ids.iter().filter(|&&id| !self.in_tree[id as usize]) {
            samples.nearest.insert(space, self.states[id as usize].clone());
            samples.ids.push(id);
        }
        self.samples = samples;
    }

    /// Makes `parent` the parent of vertex `x` at the lower `cost`, and passes the saving down
    /// to its descendants; `x` and they, whose costs fell, are left in `lowered`.
    pub(crate) fn rewire(&mut self, x: u32, parent: u32, cost: f64, lowered: &mut Vec<u32>) {
        let old = self.parent[x as usize];
        if old != NO_PARENT {
            self.children[old as usize].retain(|&c| c != x);
        }
        self.children[parent as usize].push(x);
        self.parent[x as usize] = parent;
        let delta = cost - self.cost[x as usize];
        lowered.clear();
        lowered.push(x);
        let mut next = 0;
        while let Some(&u) = lowered.get(next) {
            self.cost[u as usize] += delta;
            lowered.extend_from_slice(&self.children[u as usize]);
            next += 1;
        }
    }

    /// The states from a root to vertex `id`.
    pub(crate) fn branch(&self, mut id: u32) -> Vec<S::State> {
        let mut states = Vec::new();
        loop {
            states.push(self.states[id as usize].clone());
            match self.parent[id as usize] {
                NO_PARENT => break,
                p => id = p,
            }
        }
        states.reverse();
        states
    }

    /// Drops the samples and vertices through which no solution cheaper than `best` can pass
    /// (`ĝ + ĥ` above it by more than rounding), keeping the roots, the best solution's vertex
    /// and every ancestor of a vertex kept, and renumbers the rest in their order; both
    /// structures are rebuilt.
    pub(crate) fn prune(&mut self, space: &S, goal: &dyn Goal<S>, best: f64) {
        let n = self.len();
        let bound = best * (1.0 + PRUNE_SLACK);
        let mut keep: Vec<bool> = (0..n)
            .map(|i| (self.in_tree[i] && self.parent[i] == NO_PARENT) || self.come[i] + self.go[i] <= bound)
            .collect();
        if let Some((b, _)) = self.best() {
            keep[b as usize] = true;
        }
        for i in 0..n {
            if keep[i] && self.in_tree[i] {
                let mut up = self.parent[i];
                while up != NO_PARENT && !keep[up as usize] {
                    keep[up as usize] = true;
                    up = self.parent[up as usize];
                }
            }
        }
        let mut renumbered = vec![NO_PARENT; n];
        for (new, old) in (0..n).filter(|&i| keep[i]).enumerate() {
            renumbered[old] = new as u32;
        }
        let moved = |id: u32| if id == NO_PARENT { NO_PARENT } else { renumbered[id as usize] };
        let kept = |v: &[f64]| -> Vec<f64> { (0..n).filter(|&i| keep[i]).map(|i| v[i]).collect() };
        let (cost, come, go, expanded_at) =
            (kept(&self.cost), kept(&self.come), kept(&self.go), kept(&self.expanded_at));
        let parent = (0..n).filter(|&i| keep[i]).map(|i| moved(self.parent[i])).collect();
        let children = (0..n)
            .filter(|&i| keep[i])
            .map(|i| self.children[i].iter().filter(|&&c| keep[c as usize]).map(|&c| moved(c)).collect())
            .collect();
        let in_tree: Vec<bool> = (0..n).filter(|&i| keep[i]).map(|i| self.in_tree[i]).collect();
        let states: Vec<S::State> =
            std::mem::take(&mut self.states).into_iter().zip(&keep).filter(|s| *s.1).map(|s| s.0).collect();
        let (mut vertices, mut samples) = (Kind::new(self.empty.clone()), Kind::new(self.empty.clone()));
        // The vertices in the order they joined, so that ties fall as before.
        for &old in self.vertices.ids.iter().filter(|&&v| keep[v as usize]) {
            vertices.nearest.insert(space, states[renumbered[old as usize] as usize].clone());
            vertices.ids.push(renumbered[old as usize]);
        }
        for (id, state) in states.iter().enumerate().filter(|s| !in_tree[s.0]) {
            samples.nearest.insert(space, state.clone());
            samples.ids.push(id as u32);
        }
        let at_goal = self.at_goal.iter().filter(|&&g| keep[g as usize]).map(|&g| moved(g)).collect();
        let closest = vertices
            .ids
            .iter()
            .map(|&v| (v, goal.distance(space, &states[v as usize])))
            .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        let empty = self.empty.clone();
        *self = BatchGraph {
            states,
            empty,
            vertices,
            samples,
            parent,
            cost,
            children,
            in_tree,
            expanded_at,
            come,
            go,
            at_goal,
            closest,
        };
    }
}
