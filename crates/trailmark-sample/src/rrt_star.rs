//! RRT* (Karaman and Frazzoli 2011): RRT that keeps improving its path.
//!
//! Each sample is steered from its nearest state, as in RRT, and kept only when that motion is
//! valid (one check for a blocked sample). The new state is then joined to its cheapest valid
//! parent among its `k` nearest neighbours,
//! k = ⌈k_rrt ln n⌉ with k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d) (OMPL's choice), and then offers
//! itself as a cheaper parent to those neighbours (*rewiring*); a rewired node's new cost flows
//! down to all its descendants. The run goes on after the first solution until its
//! [`Termination`] (iterations, time, or a target cost), recording every improvement of the
//! best path. Distances are taken in the motion's direction both ways, so asymmetric spaces
//! (Dubins) work.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::nearest::KdNearest;
//! use trailmark_sample::rrt::{Query, RrtOptions, Termination};
//! use trailmark_sample::rrt_star::rrt_star;
//! use trailmark_sample::space::R2;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let query = Query::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let nearest = KdNearest::<R2, 2>::new(&space)?;
//! let plan = rrt_star(&query, nearest, &RrtOptions::default(), &Termination::iterations(3000), 1)?;
//! let best = 2.0 * 58f64.sqrt() + 2.0; // up to the wall's corners, across, down
//! let cost = plan.cost.expect("solved");
//! assert!(cost >= best - 1e-9 && cost < 1.1 * best);
//! // Each improvement is cheaper than the one before.
//! assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rand::RngExt;

use crate::nearest::{Direction, NearestNeighbors};
use crate::rrt::{Improvement, Plan, PlanError, Query, RrtOptions, Run, Termination, cost_of};
use crate::sampler::StateSampler;
use crate::space::StateSpace;
use crate::validity::Validity;

const ROOT: u32 = u32::MAX;

/// RRT*'s neighbour count for `n` states in `dimension` dimensions: ⌈k_rrt ln n⌉ with
/// k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d), at least 1.
pub fn neighbour_count(n: usize, dimension: usize) -> usize {
    let d = dimension.max(1) as f64;
    let k_rrt = 1.1 * 2f64.powf(d + 1.0) * std::f64::consts::E * (1.0 + 1.0 / d);
    ((k_rrt * (n.max(1) as f64).ln()).ceil() as usize).max(1)
}

/// RRT* for `query`; arguments as for [`rrt`](crate::rrt::rrt). The run stops at `termination`
/// (or when the best cost reaches `target_cost`), not at the first solution.
pub fn rrt_star<S, V, N, Q>(
    query: &Query<'_, S, V, Q>,
    mut nearest: N,
    options: &RrtOptions,
    termination: &Termination,
    seed: u64,
) -> Result<Plan<S::State>, PlanError>
where
    S: StateSpace,
    V: Validity<S>,
    N: NearestNeighbors<S>,
    Q: StateSampler<S>,
{
    let Query { space, validity, ref sampler, .. } = *query;
    let Run { start, goal, clock, mut stats, range, mut rng } =
        Run::begin(query, options, termination, seed)?;
    nearest.insert(space, start.clone());
    let mut parents = vec![ROOT];
    let mut costs = vec![0.0];
    let mut children: Vec<Vec<u32>> = vec![Vec::new()];
    // States within the goal tolerance; the nearest state to the goal for an approximate answer.
    let mut at_goal: Vec<u32> = Vec::new();
    let mut closest = (0u32, space.distance(&start, &goal));
    if closest.1 <= options.goal_tolerance {
        at_goal.push(0);
    }
    let mut history: Vec<Improvement> = Vec::new();
    let best = |at_goal: &[u32], costs: &[f64]| {
        at_goal.iter().map(|&g| (g, costs[g as usize])).min_by(|a, b| a.1.total_cmp(&b.1))
    };
    let dimension = space.dimension();
    while !termination.reached(stats.iterations, &clock, history.last().map(|b| b.cost)) {
        stats.iterations += 1;
        let target = if rng.random::<f64>() < options.goal_bias {
            goal.clone()
        } else {
            sampler.sample(space, validity, &mut rng, &mut stats.collision_checks)
        };
        let Some((near, d)) = nearest.nearest(space, &target, Direction::ToQuery) else { break };
        let from = nearest.state(near).clone();
        let new = if d <= range { target } else { space.interpolate(&from, &target, range / d) };
        if new == from || (new == goal && at_goal.iter().any(|&g| *nearest.state(g) == goal)) {
            continue;
        }
        // As in Karaman and Frazzoli's RRT*, the new state joins only when the motion from the
        // nearest state is valid: a blocked sample costs one check, not a neighbour search.
        stats.collision_checks += 1;
        if !validity.motion_is_valid(space, &from, &new) {
            continue;
        }
        // The cheapest valid parent among the k nearest (the nearest included, known valid).
        let k = neighbour_count(nearest.len() + 1, dimension);
        let mut into = nearest.k_nearest(space, &new, k, Direction::ToQuery);
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
                stats.collision_checks += 1;
                validity.motion_is_valid(space, nearest.state(id), &new)
            };
            if valid {
                parent = Some((id, costs[id as usize] + dist));
                refused = i;
                break;
            }
        }
        let Some((parent, cost)) = parent else { continue };
        let id = nearest.insert(space, new.clone());
        parents.push(parent);
        costs.push(cost);
        children.push(Vec::new());
        children[parent as usize].push(id);
        // Rewire: the new state as a cheaper parent of its neighbours (motions from it).
        // In a symmetric space the neighbours are the same both ways, and the motions refused
        // as parents are refused the other way too (OMPL reuses them likewise).
        let neighbours = if S::SYMMETRIC {
            into.drain(refused..).collect()
        } else {
            nearest.k_nearest(space, &new, k + 1, Direction::FromQuery)
        };
        for (nb, dist) in neighbours {
            if nb == id || nb == parent || nb == 0 {
                continue;
            }
            let through = cost + dist;
            if through >= costs[nb as usize] {
                continue;
            }
            stats.collision_checks += 1;
            if !validity.motion_is_valid(space, &new, nearest.state(nb)) {
                continue;
            }
            let old = parents[nb as usize];
            children[old as usize].retain(|&c| c != nb);
            children[id as usize].push(nb);
            parents[nb as usize] = id;
            let delta = through - costs[nb as usize];
            let mut stack = vec![nb];
            while let Some(u) = stack.pop() {
                costs[u as usize] += delta;
                stack.extend_from_slice(&children[u as usize]);
            }
        }
        let to_goal = space.distance(&new, &goal);
        if to_goal < closest.1 {
            closest = (id, to_goal);
        }
        if to_goal <= options.goal_tolerance {
            at_goal.push(id);
        }
        if let Some((_, c)) = best(&at_goal, &costs)
            && history.last().is_none_or(|b| c < b.cost)
        {
            history.push(Improvement { iteration: stats.iterations, time: clock.elapsed(), cost: c });
        }
    }
    stats.time_to_solution = history.first().map(|b| b.time);
    stats.tree_sizes = [nearest.len(), 0];
    let (end, approximate, goal_distance) = match best(&at_goal, &costs) {
        Some((g, _)) => (g, false, space.distance(nearest.state(g), &goal)),
        None => (closest.0, true, closest.1),
    };
    let mut path = Vec::new();
    let mut u = end;
    while u != ROOT {
        path.push(nearest.state(u).clone());
        u = parents[u as usize];
    }
    path.reverse();
    stats.elapsed = clock.elapsed();
    let cost = cost_of(space, &path);
    Ok(Plan { path: Some(path), cost: Some(cost), approximate, goal_distance, history, stats })
}
