//! ARA* against A*: on random grids with cell costs, every iteration's path costs at most ε
//! (and at most its proven bound) times the optimum, costs never rise, and the last iteration
//! at ε = 1 finds the optimum; unreachable goals and budgets end the search cleanly.

use std::ops::ControlFlow;

mod common;

use common::walk_cost;
use proptest::prelude::*;
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::{EpsilonSchedule, Search, SearchError, ara_star, astar};

fn grid_world() -> impl Strategy<Value = (Grid, Connectivity, Cell, Cell)> {
    (2u32..16, 2u32..16, any::<bool>()).prop_flat_map(|(w, h, eight)| {
        let n = (w * h) as usize;
        (prop::collection::vec(prop::option::weighted(0.75, 1.0f64..5.0), n), (0..w, 0..h), (0..w, 0..h))
            .prop_map(move |(costs, s, t)| {
                let costs = costs.into_iter().map(|c| c.unwrap_or(f64::INFINITY)).collect();
                let mut grid = Grid::from_costs(w as usize, h as usize, costs).expect("valid costs");
                let (start, goal) = (Cell::new(s.0, s.1), Cell::new(t.0, t.1));
                grid.set_cost(start, 1.0).expect("inside");
                grid.set_cost(goal, 1.0).expect("inside");
                (grid, if eight { Connectivity::Eight } else { Connectivity::Four }, start, goal)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn ara_star_iterations_stay_within_epsilon_and_end_optimal(
        (grid, connectivity, start, goal) in grid_world(),
        initial in 1.0f64..5.0,
        step in 0.1f64..2.0,
    ) {
        let graph = GridGraph::new(&grid, connectivity);
        let h = graph.heuristic(GridHeuristic::for_connectivity(connectivity), goal);
        let optimum = astar(&graph, start, goal, h).unwrap().cost();
        let schedule = EpsilonSchedule::new(initial, step);
        let found = ara_star(&graph, start, goal, h, schedule, Termination::unlimited()).unwrap();
        match optimum {
            None => {
                prop_assert_eq!(found.stop, Stop::Unreachable);
                prop_assert!(found.path.is_none());
                prop_assert_eq!(found.iterations.len(), 1);
            }
            Some(opt) => {
                prop_assert_eq!(found.stop, Stop::Optimal);
                let tol = 1e-9 * opt.max(1.0);
                let mut last = f64::INFINITY;
                for it in &found.iterations {
                    let cost = it.cost.unwrap();
                    prop_assert!(cost <= it.epsilon * opt + tol, "cost {} at epsilon {} > {} x optimum", cost, it.epsilon, it.epsilon);
                    prop_assert!(cost <= it.bound * opt + tol, "cost {} above bound {} x {}", cost, it.bound, opt);
                    prop_assert!(it.bound <= it.epsilon && it.bound >= 1.0);
                    prop_assert!(cost <= last + tol);
                    last = cost;
                }
                prop_assert!((found.cost().unwrap() - opt).abs() <= tol, "final {:?} optimum {}", found.cost(), opt);
                let path = found.path.unwrap();
                prop_assert_eq!((path.start(), path.goal()), (Some(start), Some(goal)));
                prop_assert!((walk_cost(&graph, &path.nodes).unwrap() - path.cost).abs() <= tol);
            }
        }
    }
}

/// The first solution comes from the most inflated search and takes the fewest expansions; the
/// search reuses its open list, so the iterations together expand less than separate weighted
/// searches would.
#[test]
fn iterations_reuse_effort_on_an_open_map() {
    let grid = trailmark_core::generate::random(200, 200, 0.25, 7).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let cells: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    let (start, goal) = (cells[0], cells[cells.len() - 1]);
    let h = graph.heuristic(GridHeuristic::Octile, goal);
    let schedule = EpsilonSchedule::new(3.0, 0.5);
    let found = ara_star(&graph, start, goal, h, schedule, Termination::unlimited()).unwrap();
    let first = &found.iterations[0];
    let optimal = astar(&graph, start, goal, h).unwrap();
    assert!(
        first.expansions * 5 < optimal.stats.expansions,
        "{} vs {}",
        first.expansions,
        optimal.stats.expansions
    );
    let separate: u64 = found
        .iterations
        .iter()
        .map(|it| {
            trailmark_search::weighted_astar(&graph, start, goal, h, it.epsilon).unwrap().stats.expansions
        })
        .sum();
    assert!(found.stats.expansions < separate, "{} vs {}", found.stats.expansions, separate);
    // The same least cost, to rounding (A* does not reopen a node for a rounding's saving).
    let (cost, least) = (found.cost().unwrap(), optimal.cost().unwrap());
    assert!((cost - least).abs() <= 1e-9 * least, "{cost} vs {least}");
}

/// A seeded 80 x 80 map, 30% blocked, and two far passable cells: more than one iteration of
/// ARA* apart.
fn random_world() -> (GridGraph, Cell, Cell) {
    let grid = trailmark_core::generate::random(80, 80, 0.3, 11).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let cells: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    (graph, cells[0], cells[cells.len() - 1])
}

#[test]
fn budgets_and_callers_stop_the_search() {
    let (graph, start, goal) = random_world();
    let h = graph.heuristic(GridHeuristic::Octile, goal);
    let schedule = EpsilonSchedule::default();
    let unlimited = ara_star(&graph, start, goal, h, schedule, Termination::unlimited()).unwrap();
    assert!(unlimited.iterations.len() >= 2, "this map needs more than one iteration");

    let tight = Termination::expansions(1);
    let found = ara_star(&graph, start, goal, h, schedule, tight).unwrap();
    assert_eq!(found.stop, Stop::ExpansionLimit);
    assert!(found.path.is_none() && found.iterations.is_empty());

    let mut seen = Vec::new();
    let found = Search::new()
        .ara_star(&graph, start, goal, h, schedule, Termination::unlimited(), |it| {
            seen.push(it.epsilon);
            ControlFlow::Break(())
        })
        .unwrap();
    assert_eq!((found.stop, seen), (Stop::Caller, vec![3.0]));
    assert!(found.cost().is_some() && found.bound() == Some(found.iterations[0].bound));

    let zero_time = Termination::time(std::time::Duration::ZERO);
    assert_eq!(ara_star(&graph, start, goal, h, schedule, zero_time).unwrap().stop, Stop::TimeLimit);
}

/// The limits the shared termination adds: improvement iterations, a target cost and a
/// condition, each stopping the search with its own reason.
#[test]
fn iteration_limits_target_costs_and_conditions_stop_the_search() {
    let (graph, start, goal) = random_world();
    let h = graph.heuristic(GridHeuristic::Octile, goal);
    let schedule = EpsilonSchedule::default();
    let unlimited = ara_star(&graph, start, goal, h, schedule, Termination::unlimited()).unwrap();
    let first = unlimited.iterations[0];

    let one = ara_star(&graph, start, goal, h, schedule, Termination::iterations(1)).unwrap();
    assert_eq!((one.stop, one.iterations.len()), (Stop::IterationLimit, 1));
    assert_eq!(one.cost(), first.cost);

    let target = Termination::unlimited().and_target_cost(first.cost.unwrap());
    let met = ara_star(&graph, start, goal, h, schedule, &target).unwrap();
    assert_eq!((met.stop, met.iterations.len()), (Stop::TargetCost, 1));

    let asked = Termination::when(|progress| progress.iterations >= 2);
    let stopped = ara_star(&graph, start, goal, h, schedule, asked).unwrap();
    assert_eq!((stopped.stop, stopped.iterations.len()), (Stop::Caller, 2));
}

#[test]
fn invalid_schedules_are_errors() {
    let graph = GridGraph::new(&Grid::new(3, 3).unwrap(), Connectivity::Four);
    let h = |_: Cell| 0.0;
    let (s, t) = (Cell::new(0, 0), Cell::new(2, 2));
    for (initial, step) in
        [(0.5, 0.5), (f64::NAN, 0.5), (3.0, 0.0), (3.0, -1.0), (f64::INFINITY, 1.0), (3.0, 1e-9)]
    {
        let schedule = EpsilonSchedule::new(initial, step);
        let err = ara_star(&graph, s, t, h, schedule, Termination::unlimited()).unwrap_err();
        assert!(matches!(err, SearchError::InvalidEpsilon { .. }), "{initial} {step}: {err:?}");
    }
}

/// A budget that ends AD* inside its second iteration keeps the first iteration's path: the
/// result has that path and cost, and the robot's next step follows it (it had no path).
#[test]
fn ad_star_cut_off_mid_iteration_keeps_the_last_path() {
    use trailmark_search::AdStar;
    let grid = trailmark_core::generate::random(48, 48, 0.2, 3).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let cells: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    let (start, goal) = (cells[0], cells[cells.len() - 1]);
    let h = graph.heuristic_between(GridHeuristic::Octile);
    let schedule = EpsilonSchedule::new(3.0, 0.5);
    let mut probe = AdStar::new(&graph, start, goal, h, schedule).unwrap();
    let all = probe.improve(&graph, Termination::unlimited()).unwrap();
    // The first iteration after the first that expands at least two nodes: cut it after one.
    let k = (1..all.iterations.len())
        .find(|&k| all.iterations[k].expansions >= 2)
        .expect("a later iteration works");
    let before: u64 = all.iterations[..k].iter().map(|it| it.expansions).sum();
    let last_cost = all.iterations[k - 1].cost.expect("reachable");
    let mut planner = AdStar::new(&graph, start, goal, h, schedule).unwrap();
    let found = planner.improve(&graph, Termination::expansions(before + 1)).unwrap();
    assert_eq!(found.stop, Stop::ExpansionLimit);
    assert_eq!(found.iterations.len(), k, "iteration {k} was cut off");
    let path = found.path.expect("the last completed iteration's path");
    assert_eq!(path.cost, last_cost);
    assert_eq!(planner.cost(), Some(last_cost));
    assert_eq!(planner.next_step(&graph), path.nodes.get(1).copied());
    assert_eq!(planner.path_epsilon(), all.iterations[k - 1].epsilon);
    assert!(planner.epsilon() < planner.path_epsilon());
    assert!(walk_cost(&graph, &path.nodes).is_some_and(|c| (c - last_cost).abs() < 1e-9));
}
