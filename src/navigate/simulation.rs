//! The simulation loop: sense, tell the planner, plan, move, until the robot arrives, proves
//! its target unreachable or runs out of steps.

use std::collections::VecDeque;
use std::time::{Duration, Instant};

use trailmark_core::cost::Cost;
use trailmark_core::graph::EdgeChange;
use trailmark_core::grid::{Cell, Grid};
use trailmark_search::{Replanner, SearchError};

use crate::navigate::config::{Navigation, Target, check_planner};
use crate::navigate::error::NavigateError;
use crate::navigate::graph::{NavGraph, VIRTUAL_GOAL, estimate};
use crate::navigate::report::{NavigationOutcome, NavigationReport};
use crate::navigate::world::SimulatedWorld;
use crate::solve::PlannerSpec;

/// What changed since the last plan, in the form the planner is told it: the edges at the cells
/// whose cost changed (and, in greedy mapping, from the cells just visited to the virtual goal)
/// for the planners that relax each changed edge alone (Adaptive A*, MPGAA*); every node with a
/// changed edge for the others.
enum Changes {
    Nodes(Vec<Cell>),
    Edges(Vec<EdgeChange<Cell>>),
}

impl Changes {
    /// The changes of the cells `costs` (their cost changed) and `visited` (their edge to the
    /// virtual goal went), as edges when `edges`.
    fn new(graph: &NavGraph, costs: &[Cell], visited: &[Cell], edges: bool) -> Self {
        if edges {
            let mut told: Vec<EdgeChange<Cell>> =
                visited.iter().map(|&c| EdgeChange::new(c, VIRTUAL_GOAL)).collect();
            told.extend(costs.iter().flat_map(|&cell| graph.grid.edges_affected_by(cell)));
            return Changes::Edges(told);
        }
        let mut nodes: Vec<Cell> = visited.to_vec();
        nodes.extend(costs.iter().flat_map(|&cell| graph.grid.cells_affected_by(cell)));
        nodes.sort_unstable_by_key(|c| (c.y, c.x));
        nodes.dedup();
        Changes::Nodes(nodes)
    }
}

/// Whether `planner` is told the changed edges themselves rather than the nodes they leave.
fn told_edges(planner: &PlannerSpec) -> bool {
    matches!(planner, PlannerSpec::AdaptiveAStar { .. } | PlannerSpec::MpgaaStar { .. })
}

/// What one plan produced: the next cell (`None`: no path), the plan's cost, expansions, and
/// the inflation it was made with (1 unless AD* stopped early).
struct Plan {
    next: Option<Cell>,
    cost: Option<Cost>,
    expansions: u64,
    epsilon: f64,
}

/// Plans from `robot` on `graph` with `planner`, told first (unless it was just made there)
/// that the robot moved and what `changed` since the last plan.
fn plan_step(
    planner: &mut dyn Replanner<NavGraph>,
    fresh: bool,
    graph: &NavGraph,
    robot: Cell,
    changed: &Changes,
) -> Result<Plan, SearchError<Cell>> {
    if !fresh {
        planner.move_start(graph, robot)?;
        match changed {
            Changes::Edges(edges) => planner.update_edges(graph, edges)?,
            Changes::Nodes(nodes) => planner.update_nodes(graph, nodes)?,
        }
    }
    let stats = planner.plan(graph)?;
    Ok(Plan {
        next: planner.next_step(graph),
        cost: planner.cost(),
        expansions: stats.expansions,
        epsilon: planner.inflation(),
    })
}

/// The most cells a navigation world may have (4096 x 4096). The robot's map, the truth and
/// each planner's tables take about a hundred bytes a cell with four planners on one run (85 MB
/// for a million cells), so 2^24 cells stay near 2 GB; the grids' own maximum, 2^28 cells, would
/// take 25 GB.
pub const MAX_NAVIGATION_CELLS: usize = 1 << 24;

/// Runs the robot from `start` toward `target` through `truth`, starting from the map `prior`.
///
/// Errors (before the robot moves) when the maps differ in size or have more than
/// [`MAX_NAVIGATION_CELLS`] cells, the start or goal is outside the map or blocked in the true
/// map, the sensor radius is 0, the planner cannot replan (see
/// [`Navigation::planner`]) or its settings are invalid.
pub fn navigate(
    truth: &Grid,
    prior: &Grid,
    start: Cell,
    target: Target,
    config: &Navigation,
) -> Result<NavigationReport, NavigateError> {
    run(truth, prior, start, target, config, &config.planner, None, |_, _, _| {})
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
    others: &[PlannerSpec],
) -> Result<Vec<NavigationReport>, NavigateError> {
    let driver = run(truth, prior, start, target, config, &config.planner, None, |_, _, _| {})?;
    let mut reports = Vec::with_capacity(others.len() + 1);
    for planner in others {
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
    planner: &PlannerSpec,
    script: Option<&[Cell]>,
    mut inspect: impl FnMut(&NavGraph, Cell, &Plan),
) -> Result<NavigationReport, NavigateError> {
    if (prior.width(), prior.height()) != (truth.width(), truth.height()) {
        return Err(NavigateError::PriorSize {
            prior: (prior.width(), prior.height()),
            truth: (truth.width(), truth.height()),
        });
    }
    let cells = truth.width() as usize * truth.height() as usize;
    if cells > MAX_NAVIGATION_CELLS {
        return Err(NavigateError::TooLarge { width: truth.width(), height: truth.height() });
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
    check_planner(planner)?;
    let explore = target == Target::Explore;
    let mut world = SimulatedWorld::new(truth, prior, start, explore);
    let goal_node = match target {
        Target::Cell(goal) => goal,
        Target::Explore => VIRTUAL_GOAL,
    };
    let max_steps = config.max_steps.unwrap_or(truth.len().saturating_mul(20));
    let mut report = NavigationReport {
        planner: planner.name().to_string(),
        outcome: NavigationOutcome::StepLimit,
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
        plan_times: Vec::new(),
        sensed: Vec::new(),
    };
    let mut robot = start;
    let mut trail: VecDeque<Cell> = VecDeque::new();
    let edges = told_edges(planner);
    let mut changed = Changes::new(&world.known, &[], &[], edges);
    world.sense(robot, config.sensor_radius);
    // Made on what the robot knows once it has looked around, and timed as part of its first plan.
    let clock = Instant::now();
    let mut replanner = planner
        .replanner(&world.known, robot, goal_node, estimate(scale))
        .ok_or(NavigateError::NotAReplanner { planner: planner.name() })??;
    let mut making = Some(clock.elapsed());
    loop {
        if target == Target::Cell(robot) {
            report.outcome = NavigationOutcome::Reached;
            break;
        }
        if report.steps >= max_steps {
            break;
        }
        let clock = Instant::now();
        let plan = plan_step(&mut *replanner, making.is_some(), &world.known, robot, &changed)?;
        let spent = clock.elapsed() + making.take().unwrap_or_default();
        report.plans += 1;
        report.expansions += plan.expansions;
        report.planning_time += spent;
        report.max_plan_time = report.max_plan_time.max(spent);
        report.plan_costs.push(plan.cost.unwrap_or(f64::INFINITY));
        report.plan_bounds.push(plan.epsilon);
        report.plan_expansions.push(plan.expansions);
        report.plan_times.push(spent);
        inspect(&world.known, robot, &plan);
        let next = match script {
            Some(script) => script.get(report.steps + 1).copied(),
            None => plan.next.filter(|&n| n != VIRTUAL_GOAL),
        };
        let Some(next) = next else {
            report.outcome =
                if explore { NavigationOutcome::Explored } else { NavigationOutcome::Unreachable };
            break;
        };
        report.distance += world.known.grid.edge_cost(robot, next).unwrap_or(f64::INFINITY);
        trail.push_back(robot);
        robot = next;
        report.steps += 1;
        report.trajectory.push(robot);
        let visited = world.visit(robot, explore);
        if let Some(lag) = config.follower_lag {
            let behind = trail.len().checked_sub(lag.max(1) as usize).map(|i| trail[i]);
            world.move_follower(behind.filter(|&c| c != robot && Target::Cell(c) != target));
        }
        let costs = world.sense(robot, config.sensor_radius);
        changed = Changes::new(&world.known, &costs, &visited, edges);
    }
    report.discoveries = world.discoveries;
    report.sensed = std::mem::take(&mut world.sensed);
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::AnytimeSpec;
    use trailmark_core::generate;
    use trailmark_search::Search;

    /// Every plan of every planner, on what the robot knew at that step, costs what A* from
    /// scratch finds there (AD*: at most epsilon times as much), on random maps with and without
    /// a follower, toward a goal and mapping.
    #[test]
    fn every_plan_matches_astar_on_the_robots_map() {
        let ad_star = |epsilon, epsilon_step, max_expansions| {
            PlannerSpec::AdStar(AnytimeSpec {
                epsilon: Some(epsilon),
                epsilon_step: Some(epsilon_step),
                max_expansions,
                ..AnytimeSpec::default()
            })
        };
        let planners = [
            PlannerSpec::AStar { heuristic: None },
            PlannerSpec::LpaStar { heuristic: None },
            PlannerSpec::DStarLite { heuristic: None },
            // Told the changed edges themselves (see `told_edges`).
            PlannerSpec::AdaptiveAStar { heuristic: None },
            PlannerSpec::MpgaaStar { heuristic: None },
            ad_star(2.5, 0.5, Some(30)),
            ad_star(2.0, 1.0, None),
            ad_star(3.0, 0.5, Some(0)),
        ];
        let mut plans = 0;
        for seed in 0..16u64 {
            let (w, h) = if seed < 8 { (24, 18) } else { (64, 48) };
            let truth = generate::random(w, h, 0.3, seed).unwrap();
            let prior = Grid::new(w, h).unwrap();
            let cells: Vec<Cell> = truth.cells().filter(|&c| truth.is_passable(c)).collect();
            let (start, goal) = (cells[0], cells[cells.len() - 1]);
            let target = if seed % 4 == 3 { Target::Explore } else { Target::Cell(goal) };
            for planner in &planners {
                let config = Navigation {
                    planner: planner.clone(),
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
                assert_ne!(report.outcome, NavigationOutcome::StepLimit, "{planner:?} seed {seed}");
                for pair in report.trajectory.windows(2) {
                    assert!(pair[0].x.abs_diff(pair[1].x) <= 1 && pair[0].y.abs_diff(pair[1].y) <= 1);
                }
            }
        }
        assert!(plans > 1000, "{plans} plans checked");
    }
}
