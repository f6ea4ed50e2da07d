//! What RRT* and Informed RRT* share: the tree RRT* grows (costs from the root, children, the
//! states at the goal), its neighbour count, and the run itself, which Informed RRT* makes with
//! informed sampling and pruning.

use super::planner::{Grown, Job};
use super::{ROOT, Tree};
use crate::informed::{Informed, PRUNE_SLACK, PRUNE_THRESHOLD};
use crate::nearest::{Direction, NearestNeighbors};
use crate::problem::Goal;
use crate::sampler::StateSampler;
use crate::space::StateSpace;
use crate::validity::Validity;

/// RRT*'s neighbour count for `n` states in `dimension` dimensions: ⌈k_rrt ln n⌉ with
/// k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d), at least 1.
pub fn neighbour_count(n: usize, dimension: usize) -> usize {
    let d = dimension.max(1) as f64;
    let k_rrt = 1.1 * 2f64.powf(d + 1.0) * std::f64::consts::E * (1.0 + 1.0 / d);
    ((k_rrt * (n.max(1) as f64).ln()).ceil() as usize).max(1)
}

/// The tree RRT* grows: the states with their parents, each state's cost from its root and its
/// children, the states that satisfy the goal, and the nearest to the goal.
pub(crate) struct StarTree<S: StateSpace, N> {
    pub(crate) tree: Tree<S, N>,
    pub(crate) costs: Vec<f64>,
    pub(crate) children: Vec<Vec<u32>>,
    /// States that satisfy the goal.
    pub(crate) at_goal: Vec<u32>,
    /// The state nearest to the goal, for an approximate answer, and its distance.
    pub(crate) closest: (u32, f64),
}

impl<S: StateSpace, N: NearestNeighbors<S>> StarTree<S, N> {
    /// Adds `state` under `parent` at `cost`; its id.
    fn add(&mut self, space: &S, goal: &dyn Goal<S>, state: S::State, parent: u32, cost: f64) -> u32 {
        let (to_goal, satisfied) = (goal.distance(space, &state), goal.is_satisfied(space, &state));
        let id = self.tree.insert(space, state, parent);
        self.costs.push(cost);
        self.children.push(Vec::new());
        if parent != ROOT {
            self.children[parent as usize].push(id);
        }
        if to_goal < self.closest.1 {
            self.closest = (id, to_goal);
        }
        if satisfied {
            self.at_goal.push(id);
        }
        id
    }

    /// Removes the states that no solution cheaper than `best` can pass through (their
    /// [`estimate`](Informed::estimate) is above it by more than rounding), keeping the roots,
    /// the best solution's state and every ancestor of a state kept, and renumbers the rest in
    /// their order (OMPL's `RRTstar::pruneTree`, which likewise removes only leaves). The
    /// nearest-neighbour structure is rebuilt from `empty`.
    fn prune(&mut self, space: &S, goal: &dyn Goal<S>, set: &Informed<'_, S>, best: f64, empty: N) {
        let n = self.tree.len();
        let bound = best * (1.0 + PRUNE_SLACK);
        let mut keep: Vec<bool> = (0..n as u32)
            .map(|id| self.tree.parent(id) == ROOT || set.estimate(space, self.tree.state(id)) <= bound)
            .collect();
        if let Some((b, _)) = self.best() {
            keep[b as usize] = true;
        }
        for id in 0..n as u32 {
            if keep[id as usize] {
                let mut up = self.tree.parent(id);
                while up != ROOT && !keep[up as usize] {
                    keep[up as usize] = true;
                    up = self.tree.parent(up);
                }
            }
        }
        let renumbered = self.tree.retain(space, &keep, empty);
        let moved = |id: u32| renumbered[id as usize];
        let mut costs = Vec::with_capacity(self.tree.len());
        let mut children = Vec::with_capacity(self.tree.len());
        for old in (0..n).filter(|&i| keep[i]) {
            costs.push(self.costs[old]);
            children
                .push(self.children[old].iter().copied().filter(|&c| keep[c as usize]).map(moved).collect());
        }
        (self.costs, self.children) = (costs, children);
        self.at_goal = self.at_goal.iter().copied().filter(|&g| keep[g as usize]).map(moved).collect();
        self.closest = (0..self.tree.len() as u32)
            .map(|id| (id, goal.distance(space, self.tree.state(id))))
            .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    }

    /// The cheapest state that satisfies the goal, and its cost.
    pub(crate) fn best(&self) -> Option<(u32, f64)> {
        self.at_goal.iter().map(|&g| (g, self.costs[g as usize])).min_by(|a, b| a.1.total_cmp(&b.1))
    }
}

/// RRT*'s run, with informed sampling and pruning when `informed` (Informed RRT*).
pub(crate) fn grow_star<
    A,
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S> + Clone,
    Q: StateSampler<S>,
>(
    job: Job<'_, S, V, A, N, Q>,
    informed: bool,
) -> Grown<S> {
    let Job { planner, problem, space, validity, goal, mut run } = job;
    let mut st = StarTree {
        tree: Tree::new(planner.nearest.clone(), Direction::ToQuery),
        costs: Vec::new(),
        children: Vec::new(),
        at_goal: Vec::new(),
        closest: (0, f64::INFINITY),
    };
    for start in &problem.starts {
        st.add(space, goal, start.clone(), ROOT, 0.0);
    }
    let set = Informed::new(problem);
    // The cost the tree was last pruned to.
    let mut pruned_at = f64::INFINITY;
    if let Some((_, c)) = st.best() {
        run.improved(c);
    }
    let dimension = space.dimension();
    let stop = 'run: loop {
        if let Some(stop) = run.watch.next_iteration() {
            break stop;
        }
        let best_cost = st.best().map_or(f64::INFINITY, |b| b.1);
        let (target, from_goal) = match run.goal_target(problem, planner.options.goal_bias) {
            Some(target) => (target, true),
            None => {
                let drawn = if informed {
                    set.sample(&mut run, space, validity, &planner.sampler, best_cost)
                } else {
                    run.sample(space, validity, &planner.sampler)
                };
                match drawn {
                    Ok(Some(target)) => (target, false),
                    Ok(None) => continue,
                    Err(stop) => break stop,
                }
            }
        };
        let (near, d) =
            st.tree.nearest.nearest(space, &target, Direction::ToQuery).expect("a tree with its roots");
        let Some((new, _)) = st.tree.step_toward(space, near, d, &target, run.range) else { continue };
        // A goal state already in the tree is not added again.
        if from_goal && st.at_goal.iter().any(|&g| *st.tree.state(g) == new) {
            continue;
        }
        let from = st.tree.state(near).clone();
        // As in Karaman and Frazzoli's RRT*, the new state joins only when the motion from the
        // nearest state is valid: a blocked sample costs one check, not a neighbour search.
        run.stats.collision_checks += 1;
        if !validity.motion_is_valid(space, &from, &new) {
            continue;
        }
        // The cheapest valid parent among the k nearest (the nearest included, known valid).
        let k = neighbour_count(st.tree.len() + 1, dimension);
        let mut into = st.tree.nearest.k_nearest(space, &new, k, Direction::ToQuery);
        if !into.iter().any(|&(id, _)| id == near) {
            into.push((near, space.distance(&from, &new)));
        }
        let costs = &st.costs;
        // By cost through each; ties in the order of distance, then id.
        into.sort_unstable_by(|a, b| {
            (costs[a.0 as usize] + a.1)
                .total_cmp(&(costs[b.0 as usize] + b.1))
                .then(a.1.total_cmp(&b.1))
                .then(a.0.cmp(&b.0))
        });
        let mut parent = None;
        // How many of `into` were checked before the parent: their motions are invalid.
        let mut refused = into.len();
        for (i, &(id, dist)) in into.iter().enumerate() {
            let valid = id == near || {
                if let Some(stop) = run.watch.interrupted() {
                    break 'run stop;
                }
                run.stats.collision_checks += 1;
                validity.motion_is_valid(space, st.tree.state(id), &new)
            };
            if valid {
                parent = Some((id, st.costs[id as usize] + dist));
                refused = i;
                break;
            }
        }
        let Some((parent, cost)) = parent else { continue };
        let id = st.add(space, goal, new.clone(), parent, cost);
        // Rewire: the new state as a cheaper parent of its neighbours (motions from it).
        // In a symmetric space the neighbours are the same both ways, and the motions refused
        // as parents are refused the other way too (OMPL reuses them likewise).
        let neighbours = if S::SYMMETRIC {
            into.drain(refused..).collect()
        } else {
            st.tree.nearest.k_nearest(space, &new, k + 1, Direction::FromQuery)
        };
        let mut interrupted = None;
        for (nb, dist) in neighbours {
            if nb == id || nb == parent || st.tree.parent(nb) == ROOT {
                continue;
            }
            let through = cost + dist;
            if through >= st.costs[nb as usize] {
                continue;
            }
            // Each rewiring leaves the tree whole: stopping between two is safe.
            if let Some(stop) = run.watch.interrupted() {
                interrupted = Some(stop);
                break;
            }
            run.stats.collision_checks += 1;
            if !validity.motion_is_valid(space, &new, st.tree.state(nb)) {
                continue;
            }
            let old = st.tree.parent(nb);
            st.children[old as usize].retain(|&c| c != nb);
            st.children[id as usize].push(nb);
            st.tree.set_parent(nb, id);
            let delta = through - st.costs[nb as usize];
            let mut stack = vec![nb];
            while let Some(u) = stack.pop() {
                st.costs[u as usize] += delta;
                stack.extend_from_slice(&st.children[u as usize]);
            }
        }
        if let Some((_, c)) = st.best() {
            run.improved(c);
            // Pruning rebuilds the structure: not once the run must stop.
            if informed && c < (1.0 - PRUNE_THRESHOLD) * pruned_at && run.watch.interrupted().is_none() {
                st.prune(space, goal, &set, c, planner.nearest.clone());
                pruned_at = c;
            }
        }
        if let Some(stop) = interrupted {
            break stop;
        }
    };
    run.stats.tree_sizes = [st.tree.len(), 0];
    let (end, goal_distance) = match st.best() {
        Some((g, _)) => (g, None),
        None => (st.closest.0, Some(st.closest.1)),
    };
    let path = st.tree.branch(end);
    let (nearest, parents) = st.tree.into_parts();
    planner.spent.nearest.push(nearest);
    planner.spent.ids.push(parents);
    planner.spent.costs.push(st.costs);
    planner.spent.ids.extend(st.children);
    Ok(run.finish(space, path, goal_distance, stop))
}
