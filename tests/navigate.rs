//! The navigation simulation end to end: every planner reaches reachable goals and proves
//! unreachable ones, never walks through a wall, travels at least the true shortest distance,
//! and D* Lite does less planning work than A* from scratch on the same run.

use trailmark::core::generate;
use trailmark::navigate::{NavigateError, Navigation, NavigationOutcome, Target, navigate};
use trailmark::prelude::*;
use trailmark::solve::{AnytimeSpec, PlannerSpec, SamplingSpec};

const PLANNERS: [PlannerSpec; 4] = [
    PlannerSpec::AStar { heuristic: None },
    PlannerSpec::LpaStar { heuristic: None },
    PlannerSpec::DStarLite { heuristic: None },
    PlannerSpec::AdStar(AnytimeSpec {
        epsilon: Some(3.0),
        epsilon_step: Some(0.5),
        heuristic: None,
        time_limit_s: None,
        max_expansions: Some(200),
    }),
];

fn far_apart(grid: &Grid) -> (Cell, Cell) {
    let cells: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    (cells[0], cells[cells.len() - 1])
}

/// A passable cell near the middle and the cell farthest from it in its region.
fn connected_far_apart(grid: &Grid) -> (Cell, Cell) {
    let graph = GridGraph::new(grid, Connectivity::Eight);
    let middle = Cell::new(grid.width() / 2, grid.height() / 2);
    let start = grid
        .cells()
        .filter(|&c| grid.is_passable(c))
        .min_by_key(|c| c.x.abs_diff(middle.x) + c.y.abs_diff(middle.y))
        .unwrap();
    let mut search = Search::new();
    search.dijkstra_all(&graph, start).unwrap();
    let reached: Vec<Cell> = search.reached(&graph).collect();
    let goal = reached
        .into_iter()
        .max_by(|a, b| search.cost_to(&graph, *a).partial_cmp(&search.cost_to(&graph, *b)).unwrap())
        .unwrap();
    (start, goal)
}

#[test]
fn every_planner_reaches_the_goal_through_free_cells_only() {
    for seed in 0..6 {
        let truth = generate::random(64, 48, 0.25, seed).unwrap();
        let prior = Grid::new(64, 48).unwrap();
        let (start, goal) = far_apart(&truth);
        let graph = GridGraph::new(&truth, Connectivity::Eight);
        let shortest =
            astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal)).unwrap().cost();
        for planner in PLANNERS {
            for radius in [1, 4] {
                let config =
                    Navigation { planner: planner.clone(), sensor_radius: radius, ..Navigation::default() };
                let run = navigate(&truth, &prior, start, Target::Cell(goal), &config).unwrap();
                match shortest {
                    None => {
                        assert_eq!(run.outcome, NavigationOutcome::Unreachable, "{planner:?} seed {seed}")
                    }
                    Some(best) => {
                        assert_eq!(run.outcome, NavigationOutcome::Reached, "{planner:?} seed {seed}");
                        assert!(run.distance >= best - 1e-9, "{} < {best}", run.distance);
                        assert_eq!(run.trajectory.last(), Some(&goal));
                    }
                }
                for pair in run.trajectory.windows(2) {
                    assert!(
                        graph.edge_cost(pair[0], pair[1]).is_some(),
                        "{planner:?} moved {} -> {}",
                        pair[0],
                        pair[1]
                    );
                }
                assert_eq!(run.steps + 1, run.trajectory.len());
                assert_eq!(run.plans, run.plan_costs.len());
            }
        }
    }
}

#[test]
fn a_walled_in_goal_is_proven_unreachable() {
    let truth =
        Grid::from_rows(&["..........", "......@@@.", "......@.@.", "......@@@.", ".........."]).unwrap();
    let prior = Grid::new(10, 5).unwrap();
    for planner in PLANNERS {
        let config = Navigation { planner: planner.clone(), ..Navigation::default() };
        let run = navigate(&truth, &prior, Cell::new(0, 2), Target::Cell(Cell::new(7, 2)), &config).unwrap();
        assert_eq!(run.outcome, NavigationOutcome::Unreachable, "{planner:?}");
        assert!(run.discoveries >= 8, "the robot walked up to the walls and saw them");
    }
}

/// A sensor radius near `u32::MAX` sees the whole map at once (the window is clipped to the
/// map): the walled-in goal is unreachable, and a reachable one is reached through free cells.
/// The window's arithmetic had wrapped, so the robot saw nothing and drove through the walls.
#[test]
fn a_huge_sensor_radius_sees_the_whole_map() {
    let truth =
        Grid::from_rows(&["..........", "......@@@.", "......@.@.", "......@@@.", ".........."]).unwrap();
    let prior = Grid::new(10, 5).unwrap();
    let graph = GridGraph::new(&truth, Connectivity::Eight);
    for planner in PLANNERS {
        for radius in [u32::MAX, u32::MAX - 1, u32::MAX / 2 + 1] {
            let config =
                Navigation { planner: planner.clone(), sensor_radius: radius, ..Navigation::default() };
            let walled =
                navigate(&truth, &prior, Cell::new(0, 2), Target::Cell(Cell::new(7, 2)), &config).unwrap();
            assert_eq!(walled.outcome, NavigationOutcome::Unreachable, "{planner:?}, radius {radius}");
            let open =
                navigate(&truth, &prior, Cell::new(0, 2), Target::Cell(Cell::new(9, 2)), &config).unwrap();
            assert_eq!(open.outcome, NavigationOutcome::Reached, "{planner:?}, radius {radius}");
            for pair in open.trajectory.windows(2) {
                assert!(
                    graph.edge_cost(pair[0], pair[1]).is_some(),
                    "{planner:?} moved {} -> {}",
                    pair[0],
                    pair[1]
                );
            }
        }
    }
}

#[test]
fn greedy_mapping_visits_every_reachable_cell() {
    let truth = generate::rooms(20, 16, 6, 3).unwrap();
    let prior = Grid::new(20, 16).unwrap();
    let (start, _) = far_apart(&truth);
    let graph = GridGraph::new(&truth, Connectivity::Eight);
    let mut search = Search::new();
    search.dijkstra_all(&graph, start).unwrap();
    let reachable: Vec<Cell> = search.reached(&graph).collect();
    for planner in [PlannerSpec::AStar { heuristic: None }, PlannerSpec::DStarLite { heuristic: None }] {
        let config = Navigation { planner: planner.clone(), ..Navigation::default() };
        let run = navigate(&truth, &prior, start, Target::Explore, &config).unwrap();
        assert_eq!(run.outcome, NavigationOutcome::Explored, "{planner:?}");
        for cell in &reachable {
            assert!(run.trajectory.contains(cell), "{planner:?} never visited {cell}");
        }
    }
}

#[test]
fn dstar_lite_plans_with_fewer_expansions_than_astar_from_scratch() {
    let truth = generate::random(128, 128, 0.25, 5).unwrap();
    let prior = Grid::new(128, 128).unwrap();
    let (start, goal) = far_apart(&truth);
    let run = |planner: PlannerSpec| {
        let config = Navigation { planner, sensor_radius: 2, ..Navigation::default() };
        navigate(&truth, &prior, start, Target::Cell(goal), &config).unwrap()
    };
    let (scratch, incremental) =
        (run(PlannerSpec::AStar { heuristic: None }), run(PlannerSpec::DStarLite { heuristic: None }));
    assert_eq!(scratch.outcome, NavigationOutcome::Reached);
    assert_eq!(incremental.outcome, NavigationOutcome::Reached);
    assert!(
        incremental.expansions * 3 < scratch.expansions,
        "D* Lite {} expansions, A* {}",
        incremental.expansions,
        scratch.expansions
    );
}

#[test]
fn a_follower_behind_the_robot_does_not_stop_it() {
    let truth = generate::random(40, 30, 0.2, 9).unwrap();
    let prior = Grid::new(40, 30).unwrap();
    let (start, goal) = far_apart(&truth);
    for planner in PLANNERS {
        let config = Navigation {
            planner: planner.clone(),
            sensor_radius: 2,
            follower_lag: Some(2),
            ..Navigation::default()
        };
        let run = navigate(&truth, &prior, start, Target::Cell(goal), &config).unwrap();
        assert!(
            matches!(run.outcome, NavigationOutcome::Reached | NavigationOutcome::Unreachable),
            "{planner:?}: {:?}",
            run.outcome
        );
        assert!(run.discoveries > 0);
    }
}

#[test]
fn bad_settings_are_errors() {
    let truth = Grid::from_rows(&["...", ".@.", "..."]).unwrap();
    let prior = Grid::new(3, 3).unwrap();
    let ok = Navigation::default();
    let go = |prior: &Grid, start, goal, config: &Navigation| {
        navigate(&truth, prior, start, Target::Cell(goal), config)
    };
    let (a, b) = (Cell::new(0, 0), Cell::new(2, 2));
    assert_eq!(
        go(&Grid::new(4, 3).unwrap(), a, b, &ok).unwrap_err(),
        NavigateError::PriorSize { prior: (4, 3), truth: (3, 3) }
    );
    assert_eq!(go(&prior, Cell::new(1, 1), b, &ok).unwrap_err(), NavigateError::Start(Cell::new(1, 1)));
    assert_eq!(go(&prior, a, Cell::new(3, 0), &ok).unwrap_err(), NavigateError::Goal(Cell::new(3, 0)));
    let blind = Navigation { sensor_radius: 0, ..ok.clone() };
    assert_eq!(go(&prior, a, b, &blind).unwrap_err(), NavigateError::SensorRadius);
    let with = |planner: PlannerSpec| Navigation { planner, ..ok.clone() };
    let ad_star = |spec| with(PlannerSpec::AdStar(spec));
    let bad = ad_star(AnytimeSpec { epsilon: Some(0.5), epsilon_step: Some(0.5), ..AnytimeSpec::default() });
    assert!(matches!(go(&prior, a, b, &bad).unwrap_err(), NavigateError::Planner(_)));
    for time_limit_s in [-1.0, f64::NAN, 1e300] {
        let bad = ad_star(AnytimeSpec { time_limit_s: Some(time_limit_s), ..AnytimeSpec::default() });
        assert!(matches!(go(&prior, a, b, &bad).unwrap_err(), NavigateError::Settings(_)), "{time_limit_s}");
    }
    for one_shot in [PlannerSpec::Dijkstra {}, PlannerSpec::RrtConnect(SamplingSpec::default())] {
        let name = one_shot.name();
        assert_eq!(
            go(&prior, a, b, &with(one_shot)).unwrap_err(),
            NavigateError::NotAReplanner { planner: name }
        );
    }
    let manhattan = with(PlannerSpec::DStarLite { heuristic: Some(GridHeuristic::Manhattan) });
    assert_eq!(go(&prior, a, b, &manhattan).unwrap_err(), NavigateError::Heuristic(GridHeuristic::Manhattan));
    let octile = with(PlannerSpec::DStarLite { heuristic: Some(GridHeuristic::Octile) });
    assert!(go(&prior, a, b, &octile).unwrap().reached());
}

#[test]
fn the_picture_shows_the_trajectory_and_the_unseen_walls() {
    let truth = generate::random(30, 20, 0.25, 2).unwrap();
    let prior = Grid::new(30, 20).unwrap();
    let (start, goal) = far_apart(&truth);
    let run = navigate(&truth, &prior, start, Target::Cell(goal), &Navigation::default()).unwrap();
    let svg = run.svg(&truth, Some(goal));
    assert!(svg.contains("<polyline") && svg.contains("#b8bec6") && svg.contains("#2f3640"));
}

/// On one shared run (D* Lite drives, the others plan from the same cells with the same
/// knowledge), every optimal planner's plan costs what D* Lite's does at every step, and AD*'s
/// stays within its epsilon of it.
#[test]
fn planners_on_one_run_agree_at_every_step() {
    use trailmark::navigate::navigate_together;
    for (seed, radius, follower) in [(1, 1, None), (2, 3, Some(2)), (3, 5, None), (4, 2, Some(3))] {
        let truth = generate::random(60, 40, 0.2, seed).unwrap();
        let prior = Grid::new(60, 40).unwrap();
        let (start, goal) = connected_far_apart(&truth);
        let config = Navigation {
            planner: PlannerSpec::DStarLite { heuristic: None },
            sensor_radius: radius,
            follower_lag: follower,
            ..Navigation::default()
        };
        let [astar, lpa_star, _, ad_star] = PLANNERS;
        let others = [astar, lpa_star, ad_star];
        let reports = navigate_together(&truth, &prior, start, Target::Cell(goal), &config, &others).unwrap();
        let driver = &reports[0];
        assert!(
            driver.plans > 10,
            "{:?} after {} plans, {:?} -> {:?}",
            driver.outcome,
            driver.plans,
            start,
            goal
        );
        for report in &reports[1..] {
            assert_eq!(report.plans, driver.plans);
            assert_eq!(report.trajectory, driver.trajectory);
            for (step, ((&mine, &theirs), &bound)) in
                report.plan_costs.iter().zip(&driver.plan_costs).zip(&report.plan_bounds).enumerate()
            {
                if theirs.is_finite() {
                    let tol = 1e-9 * theirs.max(1.0);
                    assert!(
                        mine >= theirs - tol && mine <= bound * theirs + tol,
                        "{} step {step}: {mine} vs {theirs}",
                        report.planner
                    );
                } else {
                    assert!(mine.is_infinite(), "{} step {step}", report.planner);
                }
            }
        }
    }
}
