//! RRT (LaValle 1998) over any [`StateSpace`].
//!
//! RRT grows a tree of valid motions from the start states by steering toward random samples,
//! at most `range` at a time, and with probability `goal_bias` toward a state of the goal.
//! It stops at the first state that satisfies the goal, or at its [`Termination`](trailmark_core::termination::Termination); then the
//! plan is approximate: the path to the state nearest the goal.
//!
//! Runs are reproducible: the same seed gives the same tree, path and statistics.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{GoalState, KdNearest, Planner, Problem, R2, Rrt};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! // Anywhere within 0.5 of (9, 1).
//! let goal = GoalState::within(Point::new(9.0, 1.0), 0.5);
//! let problem = Problem::with_goal(&space, &checker, Point::new(1.0, 1.0), goal);
//! let mut rrt = Rrt::new(KdNearest::<R2, 2>::new(&space)?).with_seed(7);
//! let plan = rrt.solve(&problem, &Termination::iterations(10_000))?;
//! let path = plan.path().expect("a way over the wall");
//! assert!((path[path.len() - 1] - Point::new(9.0, 1.0)).norm() <= 0.5);
//! assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::planner::{Grow, Grown, Job, TreePlanner};
use super::{Extension, Tree};
use crate::nearest::{Direction, NearestNeighbors};

use crate::sampler::StateSampler;
use crate::sampler::Uniform;
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Stop;

/// RRT: one tree from the start states; see the [module](self) documentation.
pub type Rrt<N, Q = Uniform> = TreePlanner<RrtGrowth, N, Q>;

/// What makes a [`TreePlanner`] RRT: how it grows its trees.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RrtGrowth;

impl Grow for RrtGrowth {
    const NAME: &'static str = "RRT";
    const OPTIMIZES: bool = false;

    fn grow<S: StateSpace, V: Validity<S>, N: NearestNeighbors<S> + Clone, Q: StateSampler<S>>(
        job: Job<'_, S, V, Self, N, Q>,
    ) -> Grown<S> {
        let Job { planner, problem, space, validity, goal, mut run } = job;
        let mut tree = Tree::new(planner.nearest.clone(), Direction::ToQuery);
        let mut closest: Option<(u32, f64)> = None;
        let mut solved = None;
        for start in &problem.starts {
            let id = tree.add_root(space, start.clone());
            let d = goal.distance(space, start);
            if closest.is_none_or(|c| d < c.1) {
                closest = Some((id, d));
            }
            if solved.is_none() && goal.is_satisfied(space, start) {
                solved = Some(id);
            }
        }
        let stop = loop {
            if solved.is_some() {
                break Stop::Solved;
            }
            if let Some(stop) = run.watch.next_iteration() {
                break stop;
            }
            let target = match run.goal_target(problem, planner.options.goal_bias) {
                Some(target) => target,
                None => match run.sample(space, validity, &planner.sampler) {
                    Ok(Some(target)) => target,
                    Ok(None) => continue,
                    Err(stop) => break stop,
                },
            };
            let id = match tree.extend(space, validity, &target, run.range, &mut run.stats.collision_checks) {
                Extension::Trapped => continue,
                Extension::Advanced(id) | Extension::Reached(id) => id,
            };
            let state = tree.state(id);
            let d = goal.distance(space, state);
            if closest.is_none_or(|c| d < c.1) {
                closest = Some((id, d));
            }
            if goal.is_satisfied(space, state) {
                solved = Some(id);
            }
        };
        run.stats.tree_sizes = [tree.len(), 0];
        let (end, goal_distance) = match solved {
            Some(id) => (id, None),
            None => {
                let (id, d) = closest.expect("a tree with its roots");
                (id, Some(d))
            }
        };
        let path = tree.branch(end);
        if goal_distance.is_none() {
            run.improved(crate::paths::length(space, &path));
        }
        let (nearest, parents) = tree.into_parts();
        planner.spent.nearest.push(nearest);
        planner.spent.ids.push(parents);
        Ok(run.finish(space, path, goal_distance, stop))
    }
}
