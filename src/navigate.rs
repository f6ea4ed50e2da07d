//! Navigation in partly known terrain: a robot senses, replans and moves until it reaches its
//! goal or proves it unreachable, with the planner of your choice.
//!
//! The robot lives on an 8-connected grid without corner cutting. It starts with a *prior* map
//! (often free space: every cell assumed passable) and, at each step, senses the true cells
//! within its sensor radius (a square window: radius 1 is the eight neighbours), folds what
//! differs into its map, replans from where it stands and moves one cell along the plan. Four
//! planners can drive it, on the same run:
//!
//! - `astar`: A* from scratch at every step;
//! - `lpa_star`: LPA*, restarted whenever the start moves (so at every step: a forward search
//!   cannot keep its values when its start moves);
//! - `dstar_lite`: D* Lite, which searches from the goal and repairs only what changed;
//! - `ad_star`: AD*, D* Lite with an inflated heuristic lowered as time allows.
//!
//! Two variations exercise the incremental planners harder: an obstacle that follows the robot
//! a few cells behind (cells block and free up during the run), and *greedy mapping*, where
//! there is no goal: every cell the robot has not visited is joined to a virtual goal, so the
//! robot keeps going to the nearest unvisited cell until it has visited every cell it can reach.
//!
//! ```
//! use trailmark::navigate::{Navigation, PlannerChoice, Target, navigate};
//! use trailmark::prelude::*;
//!
//! let truth = Grid::from_rows(&[
//!     "........",
//!     "....@...",
//!     "....@...",
//!     "....@...",
//!     "........",
//! ])?;
//! let prior = Grid::new(8, 5)?; // the robot assumes free space
//! let (start, goal) = (Cell::new(1, 2), Cell::new(7, 2));
//! let mut costs = Vec::new();
//! for planner in [PlannerChoice::AStar, PlannerChoice::DStarLite] {
//!     let config = Navigation { planner, ..Navigation::default() };
//!     let run = navigate(&truth, &prior, start, Target::Cell(goal), &config)?;
//!     assert!(run.reached());
//!     costs.push(run.distance);
//! }
//! assert_eq!(costs[0], costs[1]); // same decisions, different effort
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// Integer casts of user-derived values are checked conversions here, not silent truncation.
#![deny(clippy::cast_possible_truncation)]

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};
use thiserror::Error;

use trailmark_core::cost::{Cost, octile};
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::grid::{Cell, Connectivity, Grid};
use trailmark_core::svg::GridSvg;
use trailmark_graph::GridGraph;
use trailmark_search::{AdStar, Budget, DStarLite, EpsilonSchedule, LpaStar, Search, SearchError};

/// The node standing for "any unvisited cell" in greedy mapping.
pub const VIRTUAL_GOAL: Cell = Cell { x: u32::MAX, y: u32::MAX };

/// The cost of the edge from an unvisited cell to the virtual goal: positive (the incremental
/// planners need positive costs) and small enough not to change which cell is nearest.
pub const VIRTUAL_EDGE_COST: Cost = 1e-3;

/// Which planner drives the robot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", rename_all = "snake_case")]
pub enum PlannerChoice {
    /// A* from scratch at every step.
    #[serde(rename = "astar")]
    AStar,
    /// LPA*, restarted each time the start moves.
    LpaStar,
    /// D* Lite.
    DStarLite,
    /// AD*: each step improves within `expansions_per_step` expansions, from `epsilon` down by
    /// `epsilon_step`; when the budget runs out before a path, the iteration in progress is
    /// completed anyway (the robot needs a path to move). A budget of 0 makes one iteration per
    /// step.
    AdStar {
        /// The initial inflation.
        #[serde(default = "default_epsilon")]
        epsilon: f64,
        /// The decrease per iteration.
        #[serde(default = "default_epsilon_step")]
        epsilon_step: f64,
        /// The expansion budget of one step's improvement; `None` improves to epsilon = 1.
        #[serde(default)]
        expansions_per_step: Option<u64>,
    },
}

fn default_epsilon() -> f64 {
    EpsilonSchedule::default().initial
}

fn default_epsilon_step() -> f64 {
    EpsilonSchedule::default().step
}

impl PlannerChoice {
    /// The planner's name as in the problem JSON (`"astar"`, `"lpa_star"`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            PlannerChoice::AStar => "astar",
            PlannerChoice::LpaStar => "lpa_star",
            PlannerChoice::DStarLite => "dstar_lite",
            PlannerChoice::AdStar { .. } => "ad_star",
        }
    }
}

/// Where the robot is going.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Target {
    /// A goal cell.
    Cell(Cell),
    /// Greedy mapping: visit every reachable cell, nearest unvisited first.
    Explore,
}

/// How the simulation runs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Navigation {
    /// The planner.
    pub planner: PlannerChoice,
    /// Cells within this Chebyshev distance are sensed each step (at least 1).
    pub sensor_radius: u32,
    /// An obstacle that occupies the cell the robot stood on this many steps ago (when that
    /// cell is free and is neither the robot's cell nor the goal); `None` for a static world.
    pub follower_lag: Option<u32>,
    /// The most steps before giving up (`None`: 20 times the number of cells).
    pub max_steps: Option<usize>,
}

impl Default for Navigation {
    fn default() -> Self {
        Navigation {
            planner: PlannerChoice::DStarLite,
            sensor_radius: 1,
            follower_lag: None,
            max_steps: None,
        }
    }
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// The robot stands on the goal.
    Reached,
    /// Greedy mapping: no unvisited cell is reachable any more.
    Explored,
    /// No path exists in the robot's map. With an optimistic prior (free space, or any map
    /// that blocks no truly free cell) the goal is truly unreachable.
    Unreachable,
    /// The step limit ran out.
    StepLimit,
}

/// What a run did.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NavigationReport {
    /// The planner's name.
    pub planner: String,
    /// How the run ended.
    pub outcome: Outcome,
    /// Moves made.
    pub steps: usize,
    /// The cost of the trajectory (cell costs of the true map).
    pub distance: Cost,
    /// Planning episodes (one per step, plus the first).
    pub plans: usize,
    /// Node expansions summed over every plan.
    pub expansions: u64,
    /// Planning time summed over every plan (sensing and moving excluded).
    pub planning_time: Duration,
    /// The longest single plan.
    pub max_plan_time: Duration,
    /// Cells whose true state the robot learned differed from its map.
    pub discoveries: usize,
    /// The cells the robot stood on, start first.
    pub trajectory: Vec<Cell>,
    /// The cost of each plan, from where the robot stood to the target in what it knew then
    /// (`inf`: no path).
    #[serde(skip)]
    pub plan_costs: Vec<Cost>,
    /// The suboptimality bound of each plan: 1 for the optimal planners, AD*'s epsilon.
    #[serde(skip)]
    pub plan_bounds: Vec<f64>,
    /// The expansions of each plan.
    #[serde(skip)]
    pub plan_expansions: Vec<u64>,
    /// Whether each cell of the grid (row-major) was ever sensed.
    #[serde(skip)]
    pub sensed: Vec<bool>,
}

impl NavigationReport {
    /// Whether the robot reached its goal (or, mapping, visited all it could reach).
    pub fn reached(&self) -> bool {
        matches!(self.outcome, Outcome::Reached | Outcome::Explored)
    }

    /// The mean planning time per plan.
    pub fn mean_plan_time(&self) -> Duration {
        self.planning_time / u32::try_from(self.plans.max(1)).unwrap_or(u32::MAX)
    }

    /// An SVG of the true map, what the robot sensed (shaded), the obstacles it never saw
    /// (pale), and its trajectory.
    pub fn svg(&self, truth: &Grid, goal: Option<Cell>) -> String {
        let w = truth.width() as usize;
        let sensed: Vec<Cell> =
            truth.cells().filter(|c| self.sensed[c.y as usize * w + c.x as usize]).collect();
        let unseen = truth.cells().filter(|c| !self.sensed[c.y as usize * w + c.x as usize]);
        let mut svg = GridSvg::new(truth)
            .cell_size((1024.0 / f64::from(truth.width().max(truth.height()))).clamp(1.0, 24.0))
            .explored(sensed)
            .unknown(unseen)
            .path(&self.trajectory)
            .title(format!("{}: {:?} after {} steps", self.planner, self.outcome, self.steps));
        if let Some(&s) = self.trajectory.first() {
            svg = svg.start(s);
        }
        if let Some(g) = goal {
            svg = svg.goal(g);
        }
        svg.to_svg()
    }
}

/// Why a simulation could not start.
#[derive(Debug, Error, PartialEq)]
pub enum NavigateError {
    /// The prior map's size differs from the true map's.
    #[error("the prior map is {prior:?} cells but the true map is {truth:?}")]
    PriorSize {
        /// Width and height of the prior map.
        prior: (u32, u32),
        /// Width and height of the true map.
        truth: (u32, u32),
    },
    /// The start is outside the map or blocked in the true map.
    #[error("the start {0} is outside the map or blocked")]
    Start(Cell),
    /// The goal is outside the map or blocked in the true map.
    #[error("the goal {0} is outside the map or blocked")]
    Goal(Cell),
    /// The sensor radius is 0: the robot could not see where it steps.
    #[error("the sensor radius must be at least 1")]
    SensorRadius,
    /// A planner refused its input (an invalid epsilon schedule, for instance).
    #[error("planner: {0}")]
    Planner(#[from] SearchError<Cell>),
}

/// The robot's graph: its grid map, plus in greedy mapping the virtual goal that every
/// unvisited passable cell leads to.
struct NavGraph {
    grid: GridGraph,
    /// Per padded grid index: visited by the robot.
    visited: Vec<bool>,
    /// Greedy mapping: the virtual goal exists.
    explore: bool,
}

impl NavGraph {
    fn unvisited(&self, index: usize) -> bool {
        self.explore && !self.visited[index]
    }
}

impl Graph for NavGraph {
    type Node = Cell;
    fn contains(&self, cell: Cell) -> bool {
        if cell == VIRTUAL_GOAL { self.explore } else { self.grid.contains(cell) }
    }
}

impl Successors for NavGraph {
    fn for_each_successor<F: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: F) {
        if cell == VIRTUAL_GOAL {
            return;
        }
        if !self.explore {
            return self.grid.for_each_successor(cell, visit);
        }
        self.grid.for_each_successor(cell, &mut visit);
        if self.grid.contains(cell) && self.unvisited(self.grid.index_of(cell)) {
            visit(VIRTUAL_GOAL, VIRTUAL_EDGE_COST);
        }
    }

    #[inline]
    fn for_each_successor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, mut visit: F) {
        let bound = self.grid.node_bound();
        if index == bound {
            return;
        }
        if !self.explore {
            // Handing `visit` over by value keeps the grid's loop and the search's callback in
            // one inlined body, as on a bare grid.
            return self.grid.for_each_successor_index(index, visit);
        }
        self.grid.for_each_successor_index(index, &mut visit);
        if self.unvisited(index) && self.grid.contains(self.grid.node_at(index)) {
            visit(bound, VIRTUAL_GOAL, VIRTUAL_EDGE_COST);
        }
    }
}

impl Predecessors for NavGraph {
    fn for_each_predecessor<F: FnMut(Cell, Cost)>(&self, cell: Cell, mut visit: F) {
        self.for_each_predecessor_index(self.index_of(cell), |_, c, cost| visit(c, cost));
    }

    #[inline]
    fn for_each_predecessor_index<F: FnMut(usize, Cell, Cost)>(&self, index: usize, mut visit: F) {
        if index < self.grid.node_bound() {
            // Grid moves are symmetric; nothing leads out of the virtual goal.
            return self.grid.for_each_predecessor_index(index, visit);
        }
        if !self.explore {
            return;
        }
        for y in 0..self.grid.height() {
            for x in 0..self.grid.width() {
                let cell = Cell::new(x, y);
                let i = self.grid.index_of(cell);
                if !self.visited[i] && self.grid.contains(cell) {
                    visit(i, cell, VIRTUAL_EDGE_COST);
                }
            }
        }
    }
}

impl IndexedGraph for NavGraph {
    fn node_bound(&self) -> usize {
        self.grid.node_bound() + 1
    }
    fn index_of(&self, cell: Cell) -> usize {
        if cell == VIRTUAL_GOAL { self.grid.node_bound() } else { self.grid.index_of(cell) }
    }
    fn node_at(&self, index: usize) -> Cell {
        if index == self.grid.node_bound() { VIRTUAL_GOAL } else { self.grid.node_at(index) }
    }
    fn checked_index(&self, cell: Cell) -> Option<usize> {
        if cell == VIRTUAL_GOAL { Some(self.grid.node_bound()) } else { self.grid.checked_index(cell) }
    }
}

/// The octile distance between cells, 0 to or from the virtual goal: consistent on a grid whose
/// cells cost at least 1 (the simulation scales it by the smallest cell cost otherwise).
fn estimate(scale: Cost) -> impl Fn(Cell, Cell) -> Cost + Copy {
    move |a: Cell, b: Cell| {
        if a == VIRTUAL_GOAL || b == VIRTUAL_GOAL {
            0.0
        } else {
            scale * octile(a.x.abs_diff(b.x), a.y.abs_diff(b.y))
        }
    }
}

/// A planner with the state it keeps between steps.
enum Driver<H> {
    AStar(Search),
    Lpa(Option<LpaStar<Cell, H>>),
    DStar(Option<DStarLite<Cell, H>>),
    Ad(Option<AdStar<Cell, H>>, EpsilonSchedule, Budget),
}

/// What one plan produced: the next cell (`None`: no path), the plan's cost, expansions, and
/// the inflation it was made with (1 unless AD* stopped early).
struct Plan {
    next: Option<Cell>,
    cost: Option<Cost>,
    expansions: u64,
    epsilon: f64,
}

impl<H: FnMut(Cell, Cell) -> Cost + Copy> Driver<H> {
    fn new(choice: PlannerChoice) -> Result<Self, SearchError<Cell>> {
        Ok(match choice {
            PlannerChoice::AStar => Driver::AStar(Search::new()),
            PlannerChoice::LpaStar => Driver::Lpa(None),
            PlannerChoice::DStarLite => Driver::DStar(None),
            PlannerChoice::AdStar { epsilon, epsilon_step, expansions_per_step } => {
                let schedule = EpsilonSchedule::new(epsilon, epsilon_step);
                schedule.check::<Cell>()?;
                Driver::Ad(None, schedule, Budget { time: None, expansions: expansions_per_step })
            }
        })
    }

    /// Plans from `robot` to `target` on `graph`, told that the out-edges of `changed` changed
    /// since the last plan.
    fn plan(
        &mut self,
        graph: &NavGraph,
        robot: Cell,
        target: Cell,
        changed: &[Cell],
        h: H,
    ) -> Result<Plan, SearchError<Cell>> {
        let second = |nodes: &[Cell]| nodes.get(1).copied();
        match self {
            Driver::AStar(search) => {
                let mut h = h;
                let found = search.astar(graph, robot, target, |c| h(c, target))?;
                let cost = found.cost();
                let next = found.path.and_then(|p| second(&p.nodes));
                Ok(Plan { next, cost, expansions: found.stats.expansions, epsilon: 1.0 })
            }
            Driver::Lpa(state) => {
                // A forward search cannot keep its values when its start moves: every step
                // restarts it (reusing its memory).
                let planner = match state {
                    Some(planner) => {
                        planner.reset(graph, robot, target)?;
                        planner
                    }
                    None => state.insert(LpaStar::new(graph, robot, target, h)?),
                };
                let stats = planner.compute_shortest_path(graph)?;
                let next = planner.path(graph).and_then(|p| second(&p.nodes));
                Ok(Plan { next, cost: planner.cost(), expansions: stats.expansions, epsilon: 1.0 })
            }
            Driver::DStar(state) => {
                let planner = match state {
                    Some(planner) => {
                        planner.move_start(graph, robot)?;
                        planner.update_nodes(graph, changed.iter().copied())?;
                        planner
                    }
                    None => state.insert(DStarLite::new(graph, robot, target, h)?),
                };
                let stats = planner.compute_shortest_path(graph)?;
                let (next, cost) = (planner.next_step(graph), planner.cost());
                Ok(Plan { next, cost, expansions: stats.expansions, epsilon: 1.0 })
            }
            Driver::Ad(state, schedule, budget) => {
                let planner = match state {
                    Some(planner) => {
                        planner.move_start(graph, robot)?;
                        planner.update_nodes(graph, changed.iter().copied())?;
                        planner
                    }
                    None => state.insert(AdStar::new(graph, robot, target, h, *schedule)?),
                };
                let found = planner.improve(graph, *budget)?;
                let mut expansions = found.stats.expansions;
                // The robot needs a path: finish the iteration the budget cut short.
                if found.path.is_none() && found.stop != trailmark_search::Stop::Unreachable {
                    expansions += planner.improve_once(graph)?.stats.expansions;
                }
                let (next, cost) = (planner.next_step(graph), planner.cost());
                Ok(Plan { next, cost, expansions, epsilon: planner.path_epsilon() })
            }
        }
    }
}

/// Runs the robot from `start` toward `target` through `truth`, starting from the map `prior`.
///
/// Errors (before anything runs) when the maps differ in size, the start or goal is outside the
/// map or blocked in the true map, the sensor radius is 0, or the planner's settings are
/// invalid.
pub fn navigate(
    truth: &Grid,
    prior: &Grid,
    start: Cell,
    target: Target,
    config: &Navigation,
) -> Result<NavigationReport, NavigateError> {
    run(truth, prior, start, target, config, config.planner, None, |_, _, _| {})
}

/// Several planners on one run: `config.planner` drives the robot, then each of `others` is run
/// along the driver's trajectory, planning at every step from the same cell with the same
/// knowledge, so their planning work is compared on exactly the same sequence of problems (each
/// run on its own, so no planner's timing suffers from another's use of the caches). Returns the
/// driver's report first, then one per other planner (sharing the driver's trajectory, outcome
/// and discoveries).
pub fn navigate_together(
    truth: &Grid,
    prior: &Grid,
    start: Cell,
    target: Target,
    config: &Navigation,
    others: &[PlannerChoice],
) -> Result<Vec<NavigationReport>, NavigateError> {
    let driver = run(truth, prior, start, target, config, config.planner, None, |_, _, _| {})?;
    let mut reports = Vec::with_capacity(others.len() + 1);
    for &planner in others {
        let script = Some(&driver.trajectory[..]);
        let mut report = run(truth, prior, start, target, config, planner, script, |_, _, _| {})?;
        report.outcome = driver.outcome;
        reports.push(report);
    }
    reports.insert(0, driver);
    Ok(reports)
}

/// Runs `planner` from `start`. Without a `script` the robot follows the planner; with one it
/// moves along the script whatever the planner says (the planner still plans at every step), and
/// the run ends where the script does. `inspect(robot's graph, robot, plan)` sees every plan.
#[allow(clippy::too_many_arguments)]
fn run(
    truth: &Grid,
    prior: &Grid,
    start: Cell,
    target: Target,
    config: &Navigation,
    planner: PlannerChoice,
    script: Option<&[Cell]>,
    mut inspect: impl FnMut(&NavGraph, Cell, &Plan),
) -> Result<NavigationReport, NavigateError> {
    if (prior.width(), prior.height()) != (truth.width(), truth.height()) {
        return Err(NavigateError::PriorSize {
            prior: (prior.width(), prior.height()),
            truth: (truth.width(), truth.height()),
        });
    }
    if !truth.is_passable(start) {
        return Err(NavigateError::Start(start));
    }
    if let Target::Cell(goal) = target
        && !truth.is_passable(goal)
    {
        return Err(NavigateError::Goal(goal));
    }
    if config.sensor_radius == 0 {
        return Err(NavigateError::SensorRadius);
    }
    let scale = truth.min_cost().unwrap_or(1.0).min(prior.min_cost().unwrap_or(1.0)).min(1.0);
    let mut driver = Driver::new(planner)?;
    let explore = target == Target::Explore;
    let mut world = World::new(truth, prior, start, explore);
    let goal_node = match target {
        Target::Cell(goal) => goal,
        Target::Explore => VIRTUAL_GOAL,
    };
    let max_steps = config.max_steps.unwrap_or(truth.len().saturating_mul(20));
    let mut report = NavigationReport {
        planner: planner.name().to_string(),
        outcome: Outcome::StepLimit,
        steps: 0,
        distance: 0.0,
        plans: 0,
        expansions: 0,
        planning_time: Duration::ZERO,
        max_plan_time: Duration::ZERO,
        discoveries: 0,
        trajectory: vec![start],
        plan_costs: Vec::new(),
        plan_bounds: Vec::new(),
        plan_expansions: Vec::new(),
        sensed: Vec::new(),
    };
    let mut robot = start;
    let mut trail: VecDeque<Cell> = VecDeque::new();
    let mut changed = world.sense(robot, config.sensor_radius);
    loop {
        if target == Target::Cell(robot) {
            report.outcome = Outcome::Reached;
            break;
        }
        if report.steps >= max_steps {
            break;
        }
        let clock = Instant::now();
        let plan = driver.plan(&world.known, robot, goal_node, &changed, estimate(scale))?;
        let spent = clock.elapsed();
        report.plans += 1;
        report.expansions += plan.expansions;
        report.planning_time += spent;
        report.max_plan_time = report.max_plan_time.max(spent);
        report.plan_costs.push(plan.cost.unwrap_or(f64::INFINITY));
        report.plan_bounds.push(plan.epsilon);
        report.plan_expansions.push(plan.expansions);
        inspect(&world.known, robot, &plan);
        let next = match script {
            Some(script) => script.get(report.steps + 1).copied(),
            None => plan.next.filter(|&n| n != VIRTUAL_GOAL),
        };
        let Some(next) = next else {
            report.outcome = if explore { Outcome::Explored } else { Outcome::Unreachable };
            break;
        };
        report.distance += world.known.grid.edge_cost(robot, next).unwrap_or(f64::INFINITY);
        trail.push_back(robot);
        robot = next;
        report.steps += 1;
        report.trajectory.push(robot);
        changed = world.visit(robot, explore);
        if let Some(lag) = config.follower_lag {
            let behind = trail.len().checked_sub(lag.max(1) as usize).map(|i| trail[i]);
            world.move_follower(behind.filter(|&c| c != robot && Target::Cell(c) != target));
        }
        changed.extend(world.sense(robot, config.sensor_radius));
        changed.sort_unstable_by_key(|c| (c.y, c.x));
        changed.dedup();
    }
    report.discoveries = world.discoveries;
    report.sensed = std::mem::take(&mut world.sensed);
    Ok(report)
}

/// The true world (with the follower), the robot's map, and the cells visited.
struct World {
    truth: Grid,
    /// The true map without the follower.
    fixed: Grid,
    known: NavGraph,
    follower: Option<Cell>,
    /// Per cell of the grid (row-major): sensed at least once.
    sensed: Vec<bool>,
    /// Cells found to differ from the map.
    discoveries: usize,
}

impl World {
    fn new(truth: &Grid, prior: &Grid, start: Cell, explore: bool) -> Self {
        let grid = GridGraph::new(prior, Connectivity::Eight);
        let mut visited = vec![false; grid.node_bound()];
        visited[grid.index_of(start)] = true;
        let known = NavGraph { grid, visited, explore };
        World {
            truth: truth.clone(),
            fixed: truth.clone(),
            known,
            follower: None,
            sensed: vec![false; truth.len()],
            discoveries: 0,
        }
    }

    /// Senses the window around `robot`: updates the map where it differs from the truth and
    /// returns the cells whose edges changed.
    fn sense(&mut self, robot: Cell, radius: u32) -> Vec<Cell> {
        let (w, h) = (self.truth.width(), self.truth.height());
        let mut changed = Vec::new();
        for y in robot.y.saturating_sub(radius)..=robot.y.saturating_add(radius).min(h - 1) {
            for x in robot.x.saturating_sub(radius)..=robot.x.saturating_add(radius).min(w - 1) {
                let cell = Cell::new(x, y);
                self.sensed[y as usize * w as usize + x as usize] = true;
                let truth = self.truth.cost(cell).expect("inside the map");
                if self.known.grid.cost(cell) != Some(truth) {
                    self.known.grid.set_cost(cell, truth).expect("a cost of a valid grid");
                    self.discoveries += 1;
                    changed.extend(self.known.grid.cells_affected_by(cell));
                }
            }
        }
        changed
    }

    /// Marks `cell` visited; in greedy mapping its edge to the virtual goal goes, so it changed.
    fn visit(&mut self, cell: Cell, explore: bool) -> Vec<Cell> {
        let i = self.known.grid.index_of(cell);
        let first = !self.known.visited[i];
        self.known.visited[i] = true;
        if explore && first { vec![cell] } else { Vec::new() }
    }

    /// Moves the follower to `to` (or nowhere), freeing the cell it left.
    fn move_follower(&mut self, to: Option<Cell>) {
        let to = to.filter(|&c| self.fixed.is_passable(c));
        if to == self.follower {
            return;
        }
        if let Some(old) = self.follower {
            let cost = self.fixed.cost(old).expect("inside the map");
            self.truth.set_cost(old, cost).expect("a cost of a valid grid");
        }
        if let Some(new) = to {
            self.truth.set_blocked(new, true).expect("inside the map");
        }
        self.follower = to;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trailmark_core::generate;

    /// Every plan of every planner, on what the robot knew at that step, costs what A* from
    /// scratch finds there (AD*: at most epsilon times as much), on random maps with and without
    /// a follower, toward a goal and mapping.
    #[test]
    fn every_plan_matches_astar_on_the_robots_map() {
        let planners = [
            PlannerChoice::AStar,
            PlannerChoice::LpaStar,
            PlannerChoice::DStarLite,
            PlannerChoice::AdStar { epsilon: 2.5, epsilon_step: 0.5, expansions_per_step: Some(30) },
            PlannerChoice::AdStar { epsilon: 2.0, epsilon_step: 1.0, expansions_per_step: None },
            PlannerChoice::AdStar { epsilon: 3.0, epsilon_step: 0.5, expansions_per_step: Some(0) },
        ];
        let mut plans = 0;
        for seed in 0..16u64 {
            let (w, h) = if seed < 8 { (24, 18) } else { (64, 48) };
            let truth = generate::random(w, h, 0.3, seed).unwrap();
            let prior = Grid::new(w, h).unwrap();
            let cells: Vec<Cell> = truth.cells().filter(|&c| truth.is_passable(c)).collect();
            let (start, goal) = (cells[0], cells[cells.len() - 1]);
            let target = if seed % 4 == 3 { Target::Explore } else { Target::Cell(goal) };
            for planner in planners {
                let config = Navigation {
                    planner,
                    sensor_radius: 1 + (seed % 5) as u32,
                    follower_lag: (seed % 2 == 1).then_some(2),
                    max_steps: Some(2000),
                };
                let mut search = Search::new();
                let report =
                    run(&truth, &prior, start, target, &config, planner, None, |graph, robot, plan| {
                        let to = if target == Target::Explore { VIRTUAL_GOAL } else { goal };
                        let h = estimate(1.0);
                        let best = search.astar(graph, robot, to, |c| h(c, to)).unwrap().cost();
                        match (best, plan.cost) {
                            (None, None) => {}
                            (Some(best), Some(cost)) => {
                                let tol = 1e-9 * best.max(1.0);
                                assert!(
                                    cost >= best - tol && cost <= plan.epsilon * best + tol,
                                    "{planner:?} at {robot}: {cost} vs {best}"
                                );
                            }
                            other => panic!("{planner:?} at {robot}: planner and A* disagree: {other:?}"),
                        }
                        plans += 1;
                    })
                    .unwrap();
                assert_ne!(report.outcome, Outcome::StepLimit, "{planner:?} seed {seed}");
                for pair in report.trajectory.windows(2) {
                    assert!(pair[0].x.abs_diff(pair[1].x) <= 1 && pair[0].y.abs_diff(pair[1].y) <= 1);
                }
            }
        }
        assert!(plans > 1000, "{plans} plans checked");
    }

    #[test]
    fn a_follower_blocks_and_frees_cells() {
        let truth = Grid::new(5, 1).unwrap();
        let mut world = World::new(&truth, &truth, Cell::new(0, 0), false);
        world.move_follower(Some(Cell::new(1, 0)));
        assert!(!world.truth.is_passable(Cell::new(1, 0)));
        world.move_follower(Some(Cell::new(2, 0)));
        assert!(world.truth.is_passable(Cell::new(1, 0)) && !world.truth.is_passable(Cell::new(2, 0)));
        world.move_follower(None);
        assert!(world.truth.is_passable(Cell::new(2, 0)));
    }
}
