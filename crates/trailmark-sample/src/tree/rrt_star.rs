//! RRT* (Karaman and Frazzoli 2011): RRT that keeps improving its path.
//!
//! Each sample is steered from its nearest state, as in RRT, and kept only when that motion is
//! valid (one check for a blocked sample). The new state is then joined to its cheapest valid
//! parent among its `k` nearest neighbours,
//! k = ⌈k_rrt ln n⌉ with k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d) (OMPL's choice), and then offers
//! itself as a cheaper parent to those neighbours (*rewiring*); a rewired node's new cost flows
//! down to all its descendants. The run goes on after the first solution until its
//! [`Termination`](trailmark_core::termination::Termination) (iterations, time, or a target cost), recording every improvement of the
//! best path. Distances are taken in the motion's direction both ways, so asymmetric spaces
//! (Dubins) work. The parent search and the rewiring ask the termination's time limit and
//! condition before each motion check: a run stops within one check of its limit.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Problem, R2, RrtStar};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let mut planner = RrtStar::new(KdNearest::<R2, 2>::new(&space)?).with_seed(1);
//! let plan = planner.solve(&problem, &Termination::iterations(3000))?;
//! let best = 2.0 * 58f64.sqrt() + 2.0; // up to the wall's corners, across, down
//! let cost = plan.cost().expect("solved");
//! assert!(cost >= best - 1e-9 && cost < 1.1 * best);
//! // Each improvement is cheaper than the one before.
//! assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::planner::{Grow, Grown, Job, TreePlanner};
use super::{ROOT, Tree};
use crate::nearest::{Direction, NearestNeighbors};

use crate::sampler::StateSampler;
use crate::sampler::Uniform;
use crate::space::StateSpace;
use crate::validity::Validity;

/// RRT*'s neighbour count for `n` states in `dimension` dimensions: ⌈k_rrt ln n⌉ with
/// k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d), at least 1.
pub fn neighbour_count(n: usize, dimension: usize) -> usize {
    let d = dimension.max(1) as f64;
    let k_rrt = 1.1 * 2f64.powf(d + 1.0) * std::f64::consts::E * (1.0 + 1.0 / d);
    ((k_rrt * (n.max(1) as f64).ln()).ceil() as usize).max(1)
}

/// RRT*: one tree from the start states, rewired toward lower costs until the termination;
/// see the [module](self) documentation.
pub type RrtStar<N, Q = Uniform> = TreePlanner<StarGrowth, N, Q>;

/// What makes a [`TreePlanner`] RRT*: how it grows its trees.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StarGrowth;

impl Grow for StarGrowth {
    const NAME: &'static str = "RRT*";
    const OPTIMIZES: bool = true;

    fn grow<S: StateSpace, V: Validity<S>, N: NearestNeighbors<S> + Clone, Q: StateSampler<S>>(
        job: Job<'_, S, V, Self, N, Q>,
    ) -> Grown<S> {
        let Job { planner, problem, space, validity, goal, mut run } = job;
        let mut tree = Tree::new(planner.nearest.clone(), Direction::ToQuery);
        let mut costs = Vec::new();
        let mut children: Vec<Vec<u32>> = Vec::new();
        // States that satisfy the goal; the nearest state to the goal for an approximate answer.
        let mut at_goal: Vec<u32> = Vec::new();
        let mut closest = (0u32, f64::INFINITY);
        for start in &problem.starts {
            let id = tree.add_root(space, start.clone());
            costs.push(0.0);
            children.push(Vec::new());
            let d = goal.distance(space, start);
            if d < closest.1 {
                closest = (id, d);
            }
            if goal.is_satisfied(space, start) {
                at_goal.push(id);
            }
        }
        let best = |at_goal: &[u32], costs: &[f64]| {
            at_goal.iter().map(|&g| (g, costs[g as usize])).min_by(|a, b| a.1.total_cmp(&b.1))
        };
        if let Some((_, c)) = best(&at_goal, &costs) {
            run.improved(c);
        }
        let dimension = space.dimension();
        let stop = 'run: loop {
            if let Some(stop) = run.watch.next_iteration() {
                break stop;
            }
            let (target, from_goal) = match run.goal_target(problem, planner.options.goal_bias) {
                Some(target) => (target, true),
                None => match run.sample(space, validity, &planner.sampler) {
                    Ok(Some(target)) => (target, false),
                    Ok(None) => continue,
                    Err(stop) => break stop,
                },
            };
            let (near, d) =
                tree.nearest.nearest(space, &target, Direction::ToQuery).expect("a tree with its roots");
            let Some((new, _)) = tree.step_toward(space, near, d, &target, run.range) else { continue };
            // A goal state already in the tree is not added again.
            if from_goal && at_goal.iter().any(|&g| *tree.state(g) == new) {
                continue;
            }
            let from = tree.state(near).clone();
            // As in Karaman and Frazzoli's RRT*, the new state joins only when the motion from the
            // nearest state is valid: a blocked sample costs one check, not a neighbour search.
            run.stats.collision_checks += 1;
            if !validity.motion_is_valid(space, &from, &new) {
                continue;
            }
            // The cheapest valid parent among the k nearest (the nearest included, known valid).
            let k = neighbour_count(tree.len() + 1, dimension);
            let mut into = tree.nearest.k_nearest(space, &new, k, Direction::ToQuery);
            if !into.iter().any(|&(id, _)| id == near) {
                into.push((near, space.distance(&from, &new)));
            }
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
                    validity.motion_is_valid(space, tree.state(id), &new)
                };
                if valid {
                    parent = Some((id, costs[id as usize] + dist));
                    refused = i;
                    break;
                }
            }
            let Some((parent, cost)) = parent else { continue };
            let id = tree.insert(space, new.clone(), parent);
            costs.push(cost);
            children.push(Vec::new());
            children[parent as usize].push(id);
            let to_goal = goal.distance(space, &new);
            if to_goal < closest.1 {
                closest = (id, to_goal);
            }
            if goal.is_satisfied(space, &new) {
                at_goal.push(id);
            }
            // Rewire: the new state as a cheaper parent of its neighbours (motions from it).
            // In a symmetric space the neighbours are the same both ways, and the motions refused
            // as parents are refused the other way too (OMPL reuses them likewise).
            let neighbours = if S::SYMMETRIC {
                into.drain(refused..).collect()
            } else {
                tree.nearest.k_nearest(space, &new, k + 1, Direction::FromQuery)
            };
            let mut interrupted = None;
            for (nb, dist) in neighbours {
                if nb == id || nb == parent || tree.parent(nb) == ROOT {
                    continue;
                }
                let through = cost + dist;
                if through >= costs[nb as usize] {
                    continue;
                }
                // Each rewiring leaves the tree whole: stopping between two is safe.
                if let Some(stop) = run.watch.interrupted() {
                    interrupted = Some(stop);
                    break;
                }
                run.stats.collision_checks += 1;
                if !validity.motion_is_valid(space, &new, tree.state(nb)) {
                    continue;
                }
                let old = tree.parent(nb);
                children[old as usize].retain(|&c| c != nb);
                children[id as usize].push(nb);
                tree.set_parent(nb, id);
                let delta = through - costs[nb as usize];
                let mut stack = vec![nb];
                while let Some(u) = stack.pop() {
                    costs[u as usize] += delta;
                    stack.extend_from_slice(&children[u as usize]);
                }
            }
            if let Some((_, c)) = best(&at_goal, &costs) {
                run.improved(c);
            }
            if let Some(stop) = interrupted {
                break stop;
            }
        };
        run.stats.tree_sizes = [tree.len(), 0];
        let (end, goal_distance) = match best(&at_goal, &costs) {
            Some((g, _)) => (g, None),
            None => (closest.0, Some(closest.1)),
        };
        let path = tree.branch(end);
        let (nearest, parents) = tree.into_parts();
        planner.spent.nearest.push(nearest);
        planner.spent.ids.push(parents);
        planner.spent.costs = costs;
        planner.spent.lists = children;
        Ok(run.finish(space, path, goal_distance, stop))
    }
}
