//! RRT-Connect (Kuffner and LaValle 2000) over any [`StateSpace`].
//!
//! RRT-Connect grows a tree from the start states and one into states of the goal. After each
//! extension of one tree toward a sample, the other tries to connect to the new state, and the
//! trees swap roles every iteration. The goal tree is grown backward: its motions run from the
//! new state *into* the tree and are checked that way, so asymmetric spaces such as Dubins
//! work. The goal must sample states ([`Goal::sample`](crate::problem::Goal::sample)); a region
//! goal adds new roots to the goal tree as it grows (while it has fewer than half the tree's
//! states, as OMPL's), up to [`MAX_GOAL_ROOTS`].
//!
//! Without a meeting, the plan is approximate: the start tree's branch to the state nearest
//! the goal (as OMPL's RRTConnect).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Problem, R2, RrtConnect};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let (start, goal) = (Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let problem = Problem::new(&space, &checker, start, goal);
//! let mut planner = RrtConnect::new(KdNearest::<R2, 2>::new(&space)?).with_seed(7);
//! let plan = planner.solve(&problem, &Termination::iterations(10_000))?;
//! let path = plan.path().expect("a way over the wall");
//! assert_eq!((path[0], path[path.len() - 1]), (start, goal));
//! assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
//! assert!(plan.cost().unwrap() >= 2.0 * (9.0f64 + 7.25 * 7.25).sqrt() + 2.0); // over the grown wall
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::planner::{Grow, Grown, Job, TreePlanner};
use super::{Extension, Tree};
use crate::nearest::{Direction, NearestNeighbors};
use crate::plan::{PlanError, Rejection};
use crate::problem::{Problem, admit};
use crate::run::Run;
use crate::run::Spent;
use crate::sampler::StateSampler;
use crate::sampler::Uniform;
use crate::space::StateSpace;
use crate::validity::Validity;
use trailmark_core::termination::Stop;

/// The most extensions one connect phase makes toward a new state before the next iteration
/// begins: the tree keeps what it grew (a range of 1e-7 across a world of 10 had made one
/// iteration run for minutes).
pub const MAX_CONNECT_STEPS: usize = 10_000;

/// The most roots the goal tree takes from a region goal.
pub const MAX_GOAL_ROOTS: usize = 64;

/// The goal samples refused (out of bounds or invalid) before the goal tree's first root, after
/// which the goal is refused.
const FIRST_ROOT_ATTEMPTS: usize = 1_000;

/// RRT-Connect: a tree from the start and one into the goal, grown toward each other; see
/// the [module](self) documentation.
pub type RrtConnect<N, Q = Uniform> = TreePlanner<ConnectGrowth, N, Q>;

/// What makes a [`TreePlanner`] RRT-Connect: how it grows its trees.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ConnectGrowth;

/// The goal tree's roots: states the goal sampled, each in bounds and valid.
struct GoalRoots<T> {
    roots: Vec<T>,
    /// Goal samples refused so far.
    refused: usize,
    /// Whether the goal stopped giving states.
    exhausted: bool,
}

impl<T: Clone + PartialEq> GoalRoots<T> {
    /// A new root from the goal, if it gives one not seen before that is in bounds and valid;
    /// added to `tree`.
    fn add<S: StateSpace<State = T>, V: Validity<S>, N: NearestNeighbors<S>>(
        &mut self,
        problem: &Problem<'_, S, V>,
        run: &mut Run<'_>,
        tree: &mut Tree<S, N>,
    ) {
        let Some(state) = problem.goal.sample(problem.space, &mut run.rng) else {
            self.exhausted = true;
            return;
        };
        if self.roots.contains(&state) {
            return;
        }
        run.stats.collision_checks += 1;
        if admit(problem.space, problem.validity, &state).is_ok() {
            tree.add_root(problem.space, state.clone());
            self.roots.push(state);
        } else {
            self.refused += 1;
        }
    }

    /// Whether the goal tree should take another root now.
    fn wanted(&self, tree_size: usize) -> bool {
        !self.exhausted
            && (self.roots.is_empty()
                || (self.roots.len() < MAX_GOAL_ROOTS && 2 * self.roots.len() < tree_size))
    }
}

/// The start tree's state nearest the goal, kept up to date as the tree grows, and the first
/// of its states that satisfies the goal (a region or a tolerance can be met before the trees
/// meet).
struct Closest {
    id: u32,
    distance: f64,
    satisfied: Option<u32>,
}

impl Closest {
    fn offer<S: StateSpace, V>(&mut self, problem: &Problem<'_, S, V>, id: u32, state: &S::State) {
        let d = problem.goal.distance(problem.space, state);
        if d < self.distance {
            (self.id, self.distance) = (id, d);
        }
        if self.satisfied.is_none() && problem.goal.is_satisfied(problem.space, state) {
            self.satisfied = Some(id);
        }
    }
}

impl Grow for ConnectGrowth {
    const NAME: &'static str = "RRT-Connect";
    const OPTIMIZES: bool = false;

    fn grow<S: StateSpace, V: Validity<S>, N: NearestNeighbors<S> + Clone, Q: StateSampler<S>>(
        job: Job<'_, S, V, Self, N, Q>,
    ) -> Grown<S> {
        let Job { planner, problem, space, validity, goal, mut run } = job;
        let mut trees = [
            Tree::new(planner.nearest.clone(), Direction::ToQuery),
            Tree::new(planner.nearest.clone(), Direction::FromQuery),
        ];
        for start in &problem.starts {
            let id = trees[0].add_root(space, start.clone());
            if goal.is_satisfied(space, start) {
                run.stats.tree_sizes = [trees[0].len(), 0];
                let path = trees[0].branch(id);
                run.improved(0.0);
                return Ok(run.finish(space, path, None, Stop::Solved));
            }
        }
        let mut roots = GoalRoots { roots: Vec::new(), refused: 0, exhausted: false };
        let mut closest = Closest { id: 0, distance: f64::INFINITY, satisfied: None };
        for (id, start) in problem.starts.iter().enumerate() {
            closest.offer(problem, id as u32, start);
        }
        let [start_tree, goal_tree] = &mut trees;
        // Which tree grows this iteration; the other connects.
        let mut grow = 0;
        let mut meeting = None;
        let stop = 'run: loop {
            if meeting.is_some() || closest.satisfied.is_some() {
                break Stop::Solved;
            }
            if let Some(stop) = run.watch.next_iteration() {
                break stop;
            }
            if roots.wanted(goal_tree.len()) {
                roots.add(problem, &mut run, goal_tree);
            }
            if roots.roots.is_empty() {
                // Nothing to grow toward yet: each iteration asks the goal for a first root.
                if roots.exhausted {
                    return Err(PlanError::GoalNotSampleable { planner: "RRT-Connect" });
                }
                if roots.refused >= FIRST_ROOT_ATTEMPTS {
                    return Err(PlanError::InvalidGoal(Rejection::Invalid));
                }
                continue;
            }
            let sample = match run.sample(space, validity, &planner.sampler) {
                Ok(Some(sample)) => sample,
                Ok(None) => continue,
                Err(stop) => break stop,
            };
            let (first, second) = if grow == 0 {
                (&mut *start_tree, &mut *goal_tree)
            } else {
                (&mut *goal_tree, &mut *start_tree)
            };
            grow = 1 - grow;
            let new = match first.extend(space, validity, &sample, run.range, &mut run.stats.collision_checks)
            {
                Extension::Trapped => continue,
                Extension::Advanced(id) | Extension::Reached(id) => id,
            };
            let target = first.state(new).clone();
            if grow == 1 {
                closest.offer(problem, new, &target);
            }
            // After the first step, each step goes on from the state the last one added: in a
            // metric space it is the nearest to the target (the tree's other states were
            // farther than the one it grew from), so a nearest-neighbour query per step (what
            // OMPL does) would find it again, at a cost that grows with the tree.
            let mut last: Option<u32> = None;
            for _ in 0..MAX_CONNECT_STEPS {
                // Every step is a motion check: the time limit and the caller are asked first.
                if let Some(stop) = run.watch.interrupted() {
                    break 'run stop;
                }
                let checks = &mut run.stats.collision_checks;
                let extension = match last {
                    None => second.extend(space, validity, &target, run.range, checks),
                    Some(id) => {
                        let d = second.gap(space, id, &target);
                        second.extend_from(space, validity, id, d, &target, run.range, checks)
                    }
                };
                if let (0, Extension::Advanced(id) | Extension::Reached(id)) = (grow, &extension) {
                    closest.offer(problem, *id, second.state(*id));
                }
                match extension {
                    Extension::Trapped => break,
                    Extension::Advanced(id) => last = Some(id),
                    Extension::Reached(id) => {
                        // `grow` has flipped: 1 means the start tree grew and the goal tree met it.
                        meeting = Some(if grow == 1 { (new, id) } else { (id, new) });
                        break;
                    }
                }
            }
        };
        run.stats.tree_sizes = [start_tree.len(), goal_tree.len()];
        if let (None, Some(id)) = (meeting, closest.satisfied) {
            // The start tree reached the goal before the trees met.
            let path = start_tree.branch(id);
            run.improved(crate::paths::length(space, &path));
            keep(&mut planner.spent, trees);
            return Ok(run.finish(space, path, None, stop));
        }
        let Some((from_start, into_goal)) = meeting else {
            // No meeting: the start tree's branch to the state nearest the goal.
            let path = start_tree.branch(closest.id);
            keep(&mut planner.spent, trees);
            return Ok(run.finish(space, path, Some(closest.distance), stop));
        };
        let mut path = start_tree.branch(from_start);
        let mut back = goal_tree.branch(into_goal);
        back.reverse();
        // The meeting state ends the first part and starts the second.
        path.extend(back.into_iter().skip(1));
        run.improved(crate::paths::length(space, &path));
        keep(&mut planner.spent, trees);
        Ok(run.finish(space, path, None, stop))
    }
}

/// Keeps the trees until the next run or `clear`.
fn keep<S: StateSpace, N>(spent: &mut Spent<N>, trees: [Tree<S, N>; 2]) {
    for tree in trees {
        let (nearest, parents) = tree.into_parts();
        spent.nearest.push(nearest);
        spent.ids.push(parents);
    }
}
