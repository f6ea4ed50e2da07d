//! AD*: anytime D*, inflated solutions first, improved while time allows, repaired when the
//! graph changes or the robot moves.

use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use trailmark_core::termination::{Stop, Termination, Watch};

use crate::anytime::{AnytimeResult, EpsilonSchedule, Iteration};
use crate::error::SearchError;
use crate::heuristic::Heuristic;
use crate::incremental::EdgeChange;
use crate::incremental::engine::SearchDirection;
use crate::incremental::mode::Anytime;
use crate::incremental::planner::LifelongPlanner;
use crate::incremental::replanner::replanner_by_inherent_methods;
use crate::stats::SearchStats;

/// Changes (nodes or edges told) from which AD* treats a batch as significant and searches
/// again from the initial inflation.
pub const DEFAULT_RAISE_THRESHOLD: usize = 100;

/// Anytime D* (Likhachev, Ferguson, Gordon, Stentz and Thrun, 2005): D* Lite's backward repair
/// with ARA*'s inflation. Each iteration searches with inflation ε (keys `[rhs + ε h(start, s);
/// rhs]` for overconsistent nodes, `[g + h; g]` otherwise) and yields a path costing at most ε
/// times the optimum; the next iteration lowers ε and reuses everything. When the graph changes
/// the search is repaired; after a significant batch of changes (at least
/// [`raise_threshold`](Self::with_raise_threshold) nodes or edges) ε goes back up to its initial
/// value, so a new path comes quickly again.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_core::termination::{Stop, Termination};
/// use trailmark_search::{AdStar, EpsilonSchedule};
///
/// let grid = Grid::from_rows(&["........", ".@@@@@@.", "......@.", ".@@@@.@.", "........"])?;
/// let mut graph = GridGraph::new(&grid, Connectivity::Eight);
/// let (start, goal) = (Cell::new(2, 2), Cell::new(7, 4));
/// let h = graph.heuristic_between(GridHeuristic::Octile);
/// let mut planner = AdStar::new(&graph, start, goal, h, EpsilonSchedule::new(3.0, 1.0))?;
/// let found = planner.improve(&graph, Termination::unlimited())?;
/// assert_eq!(found.stop, Stop::Optimal);
/// assert_eq!(found.iterations[0].epsilon, 3.0);
/// let optimal = found.cost().unwrap();
///
/// // A wall closes the way the path took; the repair starts again at epsilon = 3.
/// let wall = Cell::new(5, 3);
/// graph.set_cost(wall, f64::INFINITY)?;
/// planner.raise_epsilon();
/// planner.update_nodes(&graph, graph.cells_affected_by(wall))?;
/// let repaired = planner.improve(&graph, Termination::unlimited())?;
/// assert_eq!(repaired.iterations[0].epsilon, 3.0);
/// assert!(repaired.cost().unwrap() > optimal);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct AdStar<N: Debug, H> {
    planner: LifelongPlanner<N, H, Anytime>,
    schedule: EpsilonSchedule,
    /// The inflation of the current (or last) iteration.
    epsilon: f64,
    /// An iteration was interrupted by a limit and continues at the next call.
    in_progress: bool,
    /// Iterations completed so far.
    completed: u64,
    /// Nodes and edges told changed since the last completed iteration.
    changes: usize,
    /// The robot moved or the graph changed since the last completed iteration.
    dirty: bool,
    /// `changes` from which ε goes back to its initial value.
    raise_threshold: usize,
    /// Raise ε at the next iteration whatever the changes.
    raise: bool,
    /// The last completed iteration's path (kept while a later iteration is in progress, whose
    /// values are not a path yet); `None` after a change or when the goal was unreachable.
    last_path: Option<Path<N>>,
    /// The inflation of the last completed iteration.
    last_epsilon: f64,
    /// When each plan made through [`Replanner::plan`](crate::Replanner::plan) stops improving.
    plan_termination: Termination,
}

impl<N, H> AdStar<N, H>
where
    N: Copy + Eq + Hash + Debug,
{
    // Shaped like LifelongPlanner::new, which takes a mode where this takes the public schedule.
    /// A planner from `start` to `goal` with `heuristic(a, b)` a consistent lower bound on the
    /// cost from `a` to `b`, and the inflation `schedule`. Errors when an endpoint is not a node
    /// or the schedule is invalid.
    pub fn new<G>(
        graph: &G,
        start: N,
        goal: N,
        heuristic: H,
        schedule: EpsilonSchedule,
    ) -> Result<Self, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        schedule.check()?;
        let planner = LifelongPlanner::new(
            SearchDirection::Backward,
            graph,
            start,
            goal,
            heuristic,
            Anytime::new(schedule.initial),
        )?;
        Ok(AdStar {
            planner,
            schedule,
            epsilon: schedule.initial,
            in_progress: false,
            completed: 0,
            changes: 0,
            dirty: true,
            raise_threshold: DEFAULT_RAISE_THRESHOLD,
            raise: false,
            last_path: None,
            last_epsilon: schedule.initial,
            plan_termination: Termination::unlimited(),
        })
    }

    /// Starts a new query from `start` to `goal` at the initial inflation, keeping the planner's
    /// memory: a planner reused for many queries pays, at each reset, for the nodes the previous
    /// query touched rather than for the whole graph. Errors as [`new`](Self::new) does.
    pub fn reset<G>(&mut self, graph: &G, start: N, goal: N) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.planner.reset(graph, start, goal)?;
        self.planner.engine.set_epsilon(self.schedule.initial);
        self.epsilon = self.schedule.initial;
        self.in_progress = false;
        self.completed = 0;
        self.changes = 0;
        self.dirty = true;
        self.raise = false;
        self.last_path = None;
        Ok(())
    }

    /// The same planner with another significance threshold: a batch of at least `changes`
    /// changed nodes or edges (between two completed iterations) restarts from the initial ε.
    /// `usize::MAX` never restarts on its own.
    pub fn with_raise_threshold(mut self, changes: usize) -> Self {
        self.raise_threshold = changes;
        self
    }

    /// The same planner with limits for each plan made through
    /// [`Replanner::plan`](crate::Replanner::plan) (by default none: each plan improves to ε = 1).
    pub fn with_termination_per_plan(mut self, termination: Termination) -> Self {
        self.plan_termination = termination;
        self
    }

    /// Makes the next iteration start again from the initial ε, whatever changed.
    pub fn raise_epsilon(&mut self) {
        self.raise = true;
    }

    /// The inflation of the current or last iteration.
    pub fn epsilon(&self) -> f64 {
        self.epsilon
    }

    /// The inflation of the last completed iteration, whose [`path`](Self::path) costs at most
    /// this times the optimum; it differs from [`epsilon`](Self::epsilon) while a limit holds
    /// a later iteration in progress.
    pub fn path_epsilon(&self) -> f64 {
        self.last_epsilon
    }

    /// Runs iterations, lowering ε after each, until ε = 1 (the path is optimal), the goal
    /// proves unreachable, or `termination` stops this call (any of its limits, counted from the
    /// start of the call; see [the anytime searches](crate#anytime-searches)). An iteration
    /// interrupted by a limit continues at the next call. Returns the iterations completed in this call and the
    /// path of the last one, if nothing changed since (and no iteration is in progress: a result
    /// without a path proves the goal unreachable only with [`Stop::Unreachable`]).
    ///
    /// Errors as [`DStarLite::compute_shortest_path`](crate::DStarLite::compute_shortest_path)
    /// does, [`SearchError::CostOverflow`] included.
    pub fn improve<G>(
        &mut self,
        graph: &G,
        termination: impl Into<Termination>,
    ) -> Result<AnytimeResult<N>, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.iterate(graph, &termination.into(), usize::MAX)
    }

    /// Completes one iteration, whatever it takes: the one a limit interrupted, or the next
    /// (after a change, the first one at the raised or current epsilon). A robot that must move
    /// now calls this when [`improve`](Self::improve) was stopped before any path.
    pub fn improve_once<G>(&mut self, graph: &G) -> Result<AnytimeResult<N>, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.iterate(graph, &Termination::unlimited(), 1)
    }

    fn iterate<G>(
        &mut self,
        graph: &G,
        termination: &Termination,
        most: usize,
    ) -> Result<AnytimeResult<N>, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let mut watch = Watch::start(termination);
        watch.begin_iteration();
        let mut iterations = Vec::new();
        let mut stats = SearchStats::default();
        let stop = loop {
            if !self.in_progress {
                let significant = self.raise || self.changes >= self.raise_threshold;
                if self.completed == 0 || (self.dirty && significant) {
                    self.epsilon = self.schedule.initial;
                } else if !self.dirty && self.epsilon <= 1.0 {
                    // Nothing changed since the last, optimal, iteration.
                    break if self.planner.cost().is_some() { Stop::Optimal } else { Stop::Unreachable };
                } else {
                    self.epsilon = self.schedule.next(self.epsilon);
                }
                self.raise = false;
                self.planner.next_iteration(graph, self.epsilon);
                self.in_progress = true;
            }
            // The expansion count is checked every time; the clock and the condition every 256
            // expansions.
            let spent = stats.expansions;
            let mut why = None;
            let mut interrupt = |e: u64| {
                why = if e.is_multiple_of(256) {
                    watch.set_expansions(spent + e);
                    watch.interrupted()
                } else {
                    termination.expansions_spent(spent + e).then_some(Stop::ExpansionLimit)
                };
                why.is_some()
            };
            let (complete, pass) = self.planner.compute_interruptible(graph, &mut interrupt)?;
            stats += pass;
            if !complete {
                watch.set_expansions(stats.expansions);
                break watch.interrupted().or(why).unwrap_or(Stop::TimeLimit);
            }
            self.in_progress = false;
            self.completed += 1;
            self.changes = 0;
            self.dirty = false;
            let cost = self.planner.cost();
            self.last_path = cost.and_then(|_| self.planner.path(graph));
            self.last_epsilon = self.epsilon;
            iterations.push(Iteration {
                epsilon: self.epsilon,
                cost,
                bound: self.epsilon,
                expansions: pass.expansions,
                elapsed: watch.elapsed(),
            });
            if cost.is_none() {
                break Stop::Unreachable;
            }
            if self.epsilon <= 1.0 {
                break Stop::Optimal;
            }
            if let Some(cost) = cost {
                watch.improved(cost);
            }
            watch.set_expansions(stats.expansions);
            if let Some(why) = watch.next_iteration() {
                break why;
            }
            if iterations.len() >= most {
                break Stop::Caller;
            }
        };
        stats.elapsed = watch.elapsed();
        Ok(AnytimeResult { path: self.path(graph), iterations, stop, stats })
    }

    /// The cost of the last completed iteration's path, if nothing changed since and the goal is
    /// reachable. It is at most [`epsilon`](Self::epsilon) times the optimum (of that
    /// iteration's inflation, while a later one is in progress).
    pub fn cost(&self) -> Option<Cost> {
        if self.dirty {
            return None;
        }
        if self.in_progress { self.last_path.as_ref().map(|p| p.cost) } else { self.planner.cost() }
    }

    /// The last completed iteration's path from the start to the goal, if nothing changed since
    /// (also while a limit holds a later iteration in progress).
    pub fn path<G>(&self, graph: &G) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if self.dirty {
            return None;
        }
        if self.in_progress { self.last_path.clone() } else { self.planner.path(graph) }
    }

    /// The node the robot should move to next along [`path`](Self::path).
    pub fn next_step<G>(&self, graph: &G) -> Option<N>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if self.dirty {
            return None;
        }
        if self.in_progress {
            return self.last_path.as_ref().and_then(|p| p.nodes.get(1).copied());
        }
        self.cost()?;
        self.planner.next_step(graph)
    }

    /// Moves the robot to `to`. The next iteration searches from there.
    pub fn move_start<G>(&mut self, graph: &G, to: N) -> Result<(), SearchError<N>>
    where
        G: IndexedGraph<Node = N> + ?Sized,
    {
        self.planner.move_start(graph, to)?;
        self.changed();
        Ok(())
    }

    /// Tells the planner that these edges changed cost; see [`DStarLite::update_edges`](crate::DStarLite::update_edges)
    pub fn update_edges<G>(&mut self, graph: &G, changes: &[EdgeChange<N>]) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        self.planner.update_edges(graph, changes)?;
        self.changes += changes.len();
        if !changes.is_empty() {
            self.changed();
        }
        Ok(())
    }

    // DStarLite's signature, not its body: AD* also counts the changes that raise its ε.
    /// Tells the planner that edges leaving these nodes changed; see
    /// [`DStarLite::update_nodes`](crate::DStarLite::update_nodes).
    pub fn update_nodes<G>(
        &mut self,
        graph: &G,
        nodes: impl IntoIterator<Item = N>,
    ) -> Result<(), SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let told = self.planner.update_nodes(graph, nodes)?;
        self.changes += told;
        if told > 0 {
            self.changed();
        }
        Ok(())
    }

    /// One plan of [`Replanner::plan`](crate::Replanner::plan): improves within the limits of
    /// [`with_termination_per_plan`](Self::with_termination_per_plan), then completes the
    /// iteration in progress if they stopped it before any path (and the goal is not proved
    /// unreachable).
    fn plan_within_limits<G>(&mut self, graph: &G) -> Result<SearchStats, SearchError<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
        H: Heuristic<G>,
    {
        let found = self.improve(graph, self.plan_termination.clone())?;
        let mut stats = found.stats;
        if found.path.is_none() && found.stop != Stop::Unreachable {
            stats += self.improve_once(graph)?.stats;
        }
        Ok(stats)
    }

    /// After a move or a change: the last path is stale, and an interrupted iteration is not
    /// resumed (its queued keys were computed for the old start or values); the next iteration
    /// takes over its work and recomputes every key.
    fn changed(&mut self) {
        self.dirty = true;
        self.in_progress = false;
        self.last_path = None;
    }

    /// The robot's current node.
    pub fn start(&self) -> N {
        self.planner.start
    }

    /// The goal.
    pub fn goal(&self) -> N {
        self.planner.goal
    }

    /// Counters summed over every call since the planner was made.
    pub fn totals(&self) -> SearchStats {
        self.planner.engine.totals
    }

    /// Bytes held by the planner's state and queue.
    pub fn memory_bytes(&self) -> usize {
        self.planner.engine.memory_bytes()
    }
}

replanner_by_inherent_methods!(
    /// AD* as a replanner: each plan improves within the limits it was configured with
    /// ([`AdStar::with_termination_per_plan`]); when they stop it before this plan has a path, the
    /// iteration in progress is completed anyway, since a plan without a path is no plan.
    /// [`inflation`](crate::Replanner::inflation) is the ε of the path's iteration.
    AdStar,
    plan: plan_within_limits,
    inflation: path_epsilon
);
