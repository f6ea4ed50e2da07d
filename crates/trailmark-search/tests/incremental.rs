//! LPA*, D* Lite, Adaptive A* and MPGAA* against A* from scratch: after every batch of random
//! changes (and, for all but LPA*, moves of the start), the planners must report the cost A* finds on the
//! graph as it is now, with a path that exists in that graph and costs what they say.

mod common;

use common::walk_cost;
use proptest::prelude::*;
use trailmark_core::cost::Cost;
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::{
    AdStar, AdaptiveAStar, DStarLite, EdgeChange, EpsilonSchedule, LpaStar, MpgaaStar, Replanner,
    SearchError, astar, dijkstra,
};

/// Relative tolerance between costs summed in different orders (forward by A*, backward by D*
/// Lite): the same path, the same edges, rounding may differ in the last bits.
fn same_cost(a: Option<Cost>, b: Option<Cost>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * a.abs().max(1.0),
        (None, None) => true,
        _ => false,
    }
}

/// Octile distance without scaling: admissible and consistent while every cell costs >= 1.
fn octile(a: Cell, b: Cell) -> Cost {
    GridHeuristic::Octile.distance(a.x.abs_diff(b.x), a.y.abs_diff(b.y))
}

#[derive(Debug, Clone)]
enum Change {
    /// Set the cost of cell (x, y): a finite cost in [1, 4], or blocked.
    Cell { x: u32, y: u32, cost: Option<f64> },
    /// Move the robot to a neighbour: the next step of the planner's last plan for indices from
    /// 8 on where it has one (a robot following its plan), else a neighbour by index.
    Step(usize),
}

fn change(w: u32, h: u32) -> impl Strategy<Value = Change> {
    prop_oneof![
        4 => (0..w, 0..h, prop::option::weighted(0.6, 1.0f64..4.0)).prop_map(|(x, y, cost)| Change::Cell { x, y, cost }),
        1 => (0usize..12).prop_map(Change::Step),
    ]
}

/// A random grid, start, goal and batches of changes. Half the worlds have unit costs (a cell
/// is free at cost 1 or blocked, before and after changes): there, with the octile heuristic,
/// many nodes tie on their keys, and ties are where the planners' termination is delicate.
fn world() -> impl Strategy<Value = (Grid, Connectivity, Cell, Cell, Vec<Vec<Change>>)> {
    (3u32..14, 3u32..14, any::<bool>(), any::<bool>()).prop_flat_map(|(w, h, eight, unit)| {
        let n = (w * h) as usize;
        (
            prop::collection::vec(prop::option::weighted(0.8, 1.0f64..3.0), n),
            (0..w, 0..h),
            (0..w, 0..h),
            prop::collection::vec(prop::collection::vec(change(w, h), 1..6), 1..8),
        )
            .prop_map(move |(costs, s, t, mut batches)| {
                let unit_cost = |c: f64| if unit { 1.0 } else { c };
                let costs = costs.into_iter().map(|c| c.map_or(f64::INFINITY, unit_cost)).collect();
                for change in batches.iter_mut().flatten() {
                    if let Change::Cell { cost: Some(c), .. } = change {
                        *c = unit_cost(*c);
                    }
                }
                let mut grid = Grid::from_costs(w as usize, h as usize, costs).expect("valid costs");
                let (start, goal) = (Cell::new(s.0, s.1), Cell::new(t.0, t.1));
                grid.set_cost(start, 1.0).expect("inside");
                grid.set_cost(goal, 1.0).expect("inside");
                let connectivity = if eight { Connectivity::Eight } else { Connectivity::Four };
                (grid, connectivity, start, goal, batches)
            })
    })
}

/// What a planner is told after a change of the world.
enum Told {
    /// This cell's cost changed, and with it the edges of these cells.
    Cells(Cell, Vec<Cell>),
    /// The robot moved here.
    Moved(Cell),
}

/// Applies `batch` to `graph` and the robot, telling `tell` of each change; `planned` is the
/// next step of the planner's last plan, if any.
fn apply(
    batch: &[Change],
    graph: &mut GridGraph,
    robot: &mut Cell,
    mut planned: Option<Cell>,
    mut tell: impl FnMut(&GridGraph, Told),
) {
    for change in batch {
        match *change {
            Change::Cell { x, y, cost } => {
                let cell = Cell::new(x, y);
                graph.set_cost(cell, cost.unwrap_or(f64::INFINITY)).unwrap();
                let cells = graph.cells_affected_by(cell).collect();
                tell(graph, Told::Cells(cell, cells));
            }
            Change::Step(k) => {
                let next: Vec<Cell> = graph.neighbours(*robot).map(|(c, _)| c).collect();
                let follow = planned.take().filter(|c| k >= 8 && next.contains(c));
                if let Some(to) = follow.or_else(|| next.get(k % next.len().max(1)).copied()) {
                    *robot = to;
                    tell(graph, Told::Moved(to));
                }
            }
        }
    }
}

/// A replanner told every batch of changes and moves (half of the moves along its own plan)
/// plans after each the cost of A* from scratch, with a path of the graph from the robot to the
/// goal that costs what it says, and the same error when an end is blocked.
fn replanner_matches_astar(
    mut graph: GridGraph,
    mut planner: impl Replanner<GridGraph>,
    (start, goal): (Cell, Cell),
    batches: &[Vec<Change>],
    name: &str,
    by_edges: bool,
) -> Result<(), TestCaseError> {
    let mut robot = start;
    for batch in std::iter::once(&vec![]).chain(batches) {
        let planned = planner.next_step(&graph);
        apply(batch, &mut graph, &mut robot, planned, |graph, told| match told {
            // Told the changed edges alone, or every edge of the cells around the change.
            Told::Cells(cell, _) if by_edges => {
                planner.update_edges(graph, &graph.edges_affected_by(cell)).unwrap()
            }
            Told::Cells(_, cells) => planner.update_nodes(graph, &cells).unwrap(),
            Told::Moved(to) => planner.move_start(graph, to).unwrap(),
        });
        let expected = reference(&graph, robot, goal);
        let got = planner.plan(&graph);
        match expected {
            Err(e) => prop_assert_eq!(got.unwrap_err(), e),
            Ok(cost) => {
                got.unwrap();
                prop_assert!(same_cost(planner.cost(), cost), "{} {:?}, A* {:?}", name, planner.cost(), cost);
                if let Some(path) = planner.path(&graph) {
                    prop_assert_eq!(path.start(), Some(robot));
                    prop_assert_eq!(path.goal(), Some(goal));
                    prop_assert!(same_cost(walk_cost(&graph, &path.nodes), cost));
                } else {
                    prop_assert!(cost.is_none());
                }
            }
        }
    }
    Ok(())
}

/// A* from scratch: the cost, or an error when an endpoint is blocked.
fn reference(graph: &GridGraph, start: Cell, goal: Cell) -> Result<Option<Cost>, SearchError<Cell>> {
    astar(graph, start, goal, |c| octile(c, goal)).map(|r| r.cost())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn dstar_lite_matches_astar_after_every_change((grid, connectivity, start, goal, batches) in world()) {
        let graph = GridGraph::new(&grid, connectivity);
        let planner = DStarLite::new(&graph, start, goal, octile).unwrap();
        replanner_matches_astar(graph, planner, (start, goal), &batches, "D* Lite", false)?;
    }

    #[test]
    fn adaptive_astar_matches_astar_after_every_change((grid, connectivity, start, goal, batches) in world(), by_edges in any::<bool>()) {
        let graph = GridGraph::new(&grid, connectivity);
        let planner = AdaptiveAStar::new(&graph, start, goal, octile).unwrap();
        replanner_matches_astar(graph, planner, (start, goal), &batches, "Adaptive A*", by_edges)?;
    }

    #[test]
    fn mpgaa_star_matches_astar_after_every_change((grid, connectivity, start, goal, batches) in world(), by_edges in any::<bool>()) {
        let graph = GridGraph::new(&grid, connectivity);
        let planner = MpgaaStar::new(&graph, start, goal, octile).unwrap();
        replanner_matches_astar(graph, planner, (start, goal), &batches, "MPGAA*", by_edges)?;
    }

    #[test]
    fn lpa_star_matches_astar_after_every_change((grid, connectivity, start, goal, batches) in world()) {
        let mut graph = GridGraph::new(&grid, connectivity);
        let mut planner = LpaStar::new(&graph, start, goal, octile).unwrap();
        for batch in std::iter::once(&vec![]).chain(&batches) {
            for change in batch {
                if let Change::Cell { x, y, cost } = *change {
                    let cell = Cell::new(x, y);
                    graph.set_cost(cell, cost.unwrap_or(f64::INFINITY)).unwrap();
                    planner.update_nodes(&graph, graph.cells_affected_by(cell)).unwrap();
                }
            }
            let expected = reference(&graph, start, goal);
            let got = planner.compute_shortest_path(&graph);
            match expected {
                Err(e) => prop_assert_eq!(got.unwrap_err(), e),
                Ok(cost) => {
                    got.unwrap();
                    prop_assert!(same_cost(planner.cost(), cost), "LPA* {:?}, A* {:?}", planner.cost(), cost);
                    match planner.path(&graph) {
                        Some(path) => {
                            prop_assert_eq!((path.start(), path.goal()), (Some(start), Some(goal)));
                            prop_assert!(same_cost(walk_cost(&graph, &path.nodes), cost));
                        }
                        None => prop_assert!(cost.is_none()),
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// AD* after every batch of changes and moves: each iteration's path costs at most epsilon
    /// times the optimum of the current graph, and the last (epsilon = 1) is optimal. Thresholds
    /// 0, 5 and never exercise raising epsilon again after changes.
    #[test]
    fn ad_star_iterations_are_bounded_and_end_optimal(
        (grid, connectivity, start, goal, batches) in world(),
        initial in 1.0f64..4.0,
        step in 0.25f64..1.5,
        threshold in prop_oneof![Just(0usize), Just(5), Just(usize::MAX)],
        first_budget in prop_oneof![Just(None), (1u64..40).prop_map(Some)],
    ) {
        let mut graph = GridGraph::new(&grid, connectivity);
        let schedule = EpsilonSchedule::new(initial, step);
        let mut planner = AdStar::new(&graph, start, goal, octile, schedule).unwrap().with_raise_threshold(threshold);
        let mut robot = start;
        for batch in std::iter::once(&vec![]).chain(&batches) {
            apply(batch, &mut graph, &mut robot, None, |graph, told| match told {
                Told::Cells(_, cells) => planner.update_nodes(graph, cells).unwrap(),
                Told::Moved(to) => planner.move_start(graph, to).unwrap(),
            });
            let expected = reference(&graph, robot, goal);
            // A first call cut short by a budget (resumed below, or abandoned at the next change).
            if first_budget.is_some() && expected.is_ok() {
                planner.improve(&graph, Termination { max_expansions: first_budget, ..Termination::default() }).unwrap();
            }
            let got = planner.improve(&graph, Termination::unlimited());
            match expected {
                Err(e) => prop_assert_eq!(got.unwrap_err(), e),
                Ok(None) => {
                    let found = got.unwrap();
                    prop_assert_eq!(found.stop, Stop::Unreachable);
                    prop_assert!(found.path.is_none());
                }
                Ok(Some(opt)) => {
                    let found = got.unwrap();
                    prop_assert_eq!(found.stop, Stop::Optimal);
                    for it in &found.iterations {
                        let cost = it.cost.unwrap();
                        prop_assert!(cost <= it.epsilon * opt * (1.0 + 1e-9), "cost {} at epsilon {}, optimum {}", cost, it.epsilon, opt);
                        prop_assert!(cost >= opt * (1.0 - 1e-9));
                    }
                    prop_assert!(same_cost(found.cost(), Some(opt)), "AD* {:?}, A* {}", found.cost(), opt);
                    let path = found.path.unwrap();
                    prop_assert_eq!((path.start(), path.goal()), (Some(robot), Some(goal)));
                    prop_assert!(same_cost(walk_cost(&graph, &path.nodes), Some(opt)));
                }
            }
        }
    }
}

#[path = "common/digraph.rs"]
mod digraph;

use digraph::Digraph;

/// Edge costs: none, or positive (tiny ones included, and repeated values for ties).
fn edge_cost() -> impl Strategy<Value = Cost> {
    prop_oneof![3 => Just(f64::INFINITY), 1 => Just(1e-9), 1 => Just(1.0), 4 => 0.5f64..10.0]
}

/// Batches of changes: (from, to, new cost, where the robot may jump).
type Batches = Vec<Vec<(usize, usize, Cost, usize)>>;

fn digraph_world() -> impl Strategy<Value = (Digraph, usize, usize, Batches)> {
    (2usize..12).prop_flat_map(|n| {
        (
            prop::collection::vec(prop::collection::vec(edge_cost(), n), n),
            0..n,
            0..n,
            // Batches of (from, to, new cost, robot move target).
            prop::collection::vec(prop::collection::vec((0..n, 0..n, edge_cost(), 0..n), 1..5), 1..8),
        )
            .prop_map(|(cost, s, t, batches)| (Digraph { cost }, s, t, batches))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// Edge changes told with their old costs, cycles, arbitrary robot jumps
    /// (the heuristic is 0, which stays consistent for any jump).
    #[test]
    fn edge_changes_on_digraphs_match_dijkstra((mut graph, start, goal, batches) in digraph_world()) {
        let zero = |_: usize, _: usize| 0.0;
        let mut dstar = DStarLite::new(&graph, start, goal, zero).unwrap();
        let mut lpa = LpaStar::new(&graph, start, goal, zero).unwrap();
        let mut robot = start;
        for batch in std::iter::once(&vec![]).chain(&batches) {
            let mut changes = Vec::new();
            for &(a, b, c, jump) in batch {
                if a == b {
                    continue;
                }
                changes.push(EdgeChange::new(a, b));
                graph.cost[a][b] = c;
                robot = if jump % 3 == 0 { jump } else { robot };
            }
            dstar.update_edges(&graph, &changes).unwrap();
            lpa.update_edges(&graph, &changes).unwrap();
            dstar.move_start(&graph, robot).unwrap();
            dstar.compute_shortest_path(&graph).unwrap();
            lpa.compute_shortest_path(&graph).unwrap();
            let from_robot = dijkstra(&graph, robot, goal).unwrap().cost();
            let from_start = dijkstra(&graph, start, goal).unwrap().cost();
            prop_assert!(same_cost(dstar.cost(), from_robot), "D* Lite {:?}, Dijkstra {:?}", dstar.cost(), from_robot);
            prop_assert!(same_cost(lpa.cost(), from_start), "LPA* {:?}, Dijkstra {:?}", lpa.cost(), from_start);
            for path in [dstar.path(&graph), lpa.path(&graph)].into_iter().flatten() {
                prop_assert!(same_cost(walk_cost(&graph, &path.nodes), Some(path.cost)));
            }
        }
    }
}

/// Costs: none, zero (cycles of zero-cost edges among them), tiny or ordinary.
fn cost_or_zero() -> impl Strategy<Value = Cost> {
    prop_oneof![3 => Just(f64::INFINITY), 1 => Just(0.0), 1 => Just(1e-9), 4 => 0.5f64..10.0]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// Adaptive A* and MPGAA* on digraphs with cycles and zero-cost edges (which they accept, as
    /// A* does), edge changes and jumps of the robot or steps along its plan: the cost of
    /// Dijkstra from the robot after every batch.
    #[test]
    fn learning_planners_on_digraphs_match_dijkstra(
        n in 2usize..12,
        seed in prop::collection::vec(cost_or_zero(), 144),
        ends in (0usize..12, 0usize..12),
        batches in prop::collection::vec(prop::collection::vec((0usize..12, 0usize..12, cost_or_zero(), 0usize..24), 1..5), 1..8),
    ) {
        let cost = (0..n).map(|a| (0..n).map(|b| seed[a * 12 + b]).collect()).collect();
        let mut graph = Digraph { cost };
        let (start, goal) = (ends.0 % n, ends.1 % n);
        let zero = |_: usize, _: usize| 0.0;
        let mut planners: Vec<Box<dyn Replanner<Digraph>>> = vec![
            Box::new(AdaptiveAStar::new(&graph, start, goal, zero).unwrap()),
            Box::new(MpgaaStar::new(&graph, start, goal, zero).unwrap()),
        ];
        let mut robots = vec![start; planners.len()];
        for batch in std::iter::once(&vec![]).chain(&batches) {
            let mut changes = Vec::new();
            for &(a, b, c, jump) in batch {
                let (a, b) = (a % n, b % n);
                if a != b {
                    changes.push(EdgeChange::new(a, b));
                    graph.cost[a][b] = c;
                }
                for (planner, robot) in planners.iter_mut().zip(&mut robots) {
                    // A third of the time a jump, a third a step along the last plan.
                    *robot = match jump % 3 {
                        0 => jump / 2 % n,
                        1 => planner.next_step(&graph).unwrap_or(*robot),
                        _ => *robot,
                    };
                }
            }
            for (planner, &robot) in planners.iter_mut().zip(&robots) {
                planner.update_edges(&graph, &changes).unwrap();
                planner.move_start(&graph, robot).unwrap();
                planner.plan(&graph).unwrap();
                let best = dijkstra(&graph, robot, goal).unwrap().cost();
                prop_assert!(same_cost(planner.cost(), best), "{:?}, Dijkstra {:?}", planner.cost(), best);
                if let Some(path) = planner.path(&graph) {
                    prop_assert_eq!((path.start(), path.goal()), (Some(robot), Some(goal)));
                    prop_assert!(same_cost(walk_cost(&graph, &path.nodes), Some(path.cost)));
                    prop_assert_eq!(planner.next_step(&graph), path.nodes.get(1).copied());
                }
            }
        }
    }
}

/// Adaptive A* and MPGAA*: notifications naming nothing are errors that change nothing; a NaN
/// edge is reported, and once the graph is fixed and the change told they plan as before.
#[test]
fn learning_planners_reject_bad_input_and_stay_usable() {
    let mut graph = Digraph::new(3, &[(0, 1, 1.0), (1, 2, 1.0), (0, 2, 5.0)]);
    let zero = |_: usize, _: usize| 0.0;
    let planners: Vec<Box<dyn Replanner<Digraph>>> = vec![
        Box::new(AdaptiveAStar::new(&graph, 0, 2, zero).unwrap()),
        Box::new(MpgaaStar::new(&graph, 0, 2, zero).unwrap()),
    ];
    for mut planner in planners {
        graph.cost[1][2] = 1.0;
        planner.plan(&graph).unwrap();
        assert_eq!(planner.cost(), Some(2.0));
        assert_eq!(planner.update_nodes(&graph, &[1, 7]), Err(SearchError::UnknownNode(7)));
        let outside = EdgeChange::new(1, 9);
        assert_eq!(planner.update_edges(&graph, &[outside]), Err(SearchError::UnknownNode(9)));
        assert_eq!(planner.move_start(&graph, 3), Err(SearchError::StartNotInGraph(3)));
        planner.plan(&graph).unwrap();
        assert_eq!((planner.cost(), planner.next_step(&graph)), (Some(2.0), Some(1)));

        graph.cost[1][2] = f64::NAN;
        planner.update_edges(&graph, &[EdgeChange::new(1, 2)]).unwrap();
        let err = planner.plan(&graph).unwrap_err();
        assert!(matches!(err, SearchError::InvalidEdgeCost { from: 1, to: 2, .. }), "{err:?}");
        // A plan that failed leaves no answer.
        assert_eq!((planner.cost(), planner.path(&graph), planner.next_step(&graph)), (None, None, None));
        graph.cost[1][2] = 3.0;
        planner.update_edges(&graph, &[EdgeChange::new(1, 2)]).unwrap();
        planner.plan(&graph).unwrap();
        assert_eq!(planner.cost(), Some(4.0));
        assert_eq!(planner.path(&graph).unwrap().nodes, [0, 1, 2]);
    }
}

/// Notifications naming nothing, or invalid costs, are errors that change nothing.
#[test]
fn bad_notifications_are_rejected_and_the_planner_stays_usable() {
    let grid = Grid::from_rows(&["....", "....", "...."]).unwrap();
    let mut graph = GridGraph::new(&grid, Connectivity::Eight);
    let (start, goal) = (Cell::new(0, 0), Cell::new(3, 2));
    let h = graph.heuristic_between(GridHeuristic::Octile);
    let mut planner = DStarLite::new(&graph, start, goal, h).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    let cost = planner.cost();

    let outside = Cell::new(4, 0);
    assert_eq!(
        planner.update_nodes(&graph, [Cell::new(1, 1), outside]),
        Err(SearchError::UnknownNode(outside))
    );
    let bad = [EdgeChange::new(Cell::new(0, 0), Cell::new(1, 0)), EdgeChange::new(Cell::new(3, 0), outside)];
    assert_eq!(planner.update_edges(&graph, &bad), Err(SearchError::UnknownNode(outside)));
    assert_eq!(planner.move_start(&graph, outside), Err(SearchError::StartNotInGraph(outside)));
    assert_eq!(planner.compute_shortest_path(&graph).unwrap().expansions, 0);
    assert_eq!(planner.cost(), cost);

    // The goal blocked: an error, and once it opens again the planner answers as before.
    graph.set_cost(goal, f64::INFINITY).unwrap();
    planner.update_nodes(&graph, graph.cells_affected_by(goal)).unwrap();
    assert_eq!(planner.compute_shortest_path(&graph), Err(SearchError::GoalNotInGraph(goal)));
    graph.set_cost(goal, 1.0).unwrap();
    planner.update_nodes(&graph, graph.cells_affected_by(goal)).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    assert_eq!(planner.cost(), cost);

    // Start and goal blocked at creation.
    graph.set_cost(start, f64::INFINITY).unwrap();
    assert_eq!(LpaStar::new(&graph, start, goal, h).err(), Some(SearchError::StartNotInGraph(start)));
}

/// A graph that reports a NaN edge: the error names it, and the planner recovers once the graph
/// is fixed and the change told.
#[test]
fn invalid_edge_costs_are_reported_then_repaired() {
    let mut graph = Digraph::new(3, &[]);
    graph.cost[0][1] = 1.0;
    graph.cost[1][2] = f64::NAN;
    graph.cost[0][2] = 5.0;
    let zero = |_: usize, _: usize| 0.0;
    let mut planner = LpaStar::new(&graph, 0, 2, zero).unwrap();
    let err = planner.compute_shortest_path(&graph).unwrap_err();
    assert!(matches!(err, SearchError::InvalidEdgeCost { from: 1, to: 2, .. }), "{err:?}");
    assert_eq!(planner.cost(), Some(5.0)); // the NaN edge counted as absent
    graph.cost[1][2] = 1.0;
    planner.update_edges(&graph, &[EdgeChange::new(1, 2)]).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    assert_eq!(planner.cost(), Some(2.0));
    assert_eq!(planner.path(&graph).unwrap().nodes, [0, 1, 2]);
}

/// Zero-cost edges are refused with their own error (they would break the repair, see
/// `valid_cost` in the source), both when met in the search and in a notification.
#[test]
fn zero_cost_edges_are_refused() {
    let mut graph = Digraph::new(2, &[]);
    graph.cost[0][1] = 1.0;
    let zero = |_: usize, _: usize| 0.0;
    let mut planner = DStarLite::new(&graph, 0, 1, zero).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    graph.cost[0][1] = 0.0;
    let change = EdgeChange::new(0, 1);
    assert_eq!(planner.update_edges(&graph, &[change]), Err(SearchError::ZeroCostEdge { from: 0, to: 1 }));
    let mut fresh = LpaStar::new(&graph, 0, 1, zero).unwrap();
    assert_eq!(fresh.compute_shortest_path(&graph), Err(SearchError::ZeroCostEdge { from: 0, to: 1 }));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// One planner of each kind reused through `reset` for a series of queries answers each as
    /// A* from scratch does, whatever the earlier queries left behind (changes included).
    #[test]
    fn reset_planners_answer_like_fresh_ones(
        (grid, connectivity, start, goal, batches) in world(),
        queries in prop::collection::vec((0u32..12, 0u32..12, 0u32..12, 0u32..12), 1..6),
    ) {
        let mut graph = GridGraph::new(&grid, connectivity);
        let mut dstar = DStarLite::new(&graph, start, goal, octile).unwrap();
        let mut lpa = LpaStar::new(&graph, start, goal, octile).unwrap();
        let mut ad = AdStar::new(&graph, start, goal, octile, EpsilonSchedule::new(2.0, 0.5)).unwrap();
        dstar.compute_shortest_path(&graph).unwrap();
        lpa.compute_shortest_path(&graph).unwrap();
        ad.improve(&graph, Termination::expansions(5)).unwrap();
        // Change the world a little, so that a reset must forget repaired state too.
        let mut robot = start;
        for batch in batches.iter().take(1) {
            apply(batch, &mut graph, &mut robot, None, |graph, told| {
                if let Told::Cells(_, cells) = told {
                    dstar.update_nodes(graph, cells.iter().copied()).unwrap();
                    lpa.update_nodes(graph, cells.iter().copied()).unwrap();
                    ad.update_nodes(graph, cells).unwrap();
                }
            });
        }
        for (sx, sy, gx, gy) in queries {
            let (s, g) = (Cell::new(sx % grid.width(), sy % grid.height()), Cell::new(gx % grid.width(), gy % grid.height()));
            let expected = reference(&graph, s, g);
            let resets = [dstar.reset(&graph, s, g), lpa.reset(&graph, s, g), ad.reset(&graph, s, g)];
            match expected {
                Err(e) => {
                    for r in resets {
                        prop_assert_eq!(r.unwrap_err(), e.clone());
                    }
                }
                Ok(cost) => {
                    for r in resets {
                        r.unwrap();
                    }
                    dstar.compute_shortest_path(&graph).unwrap();
                    lpa.compute_shortest_path(&graph).unwrap();
                    let found = ad.improve(&graph, Termination::unlimited()).unwrap();
                    prop_assert!(same_cost(dstar.cost(), cost), "D* Lite {:?}, A* {:?}", dstar.cost(), cost);
                    prop_assert!(same_cost(lpa.cost(), cost), "LPA* {:?}, A* {:?}", lpa.cost(), cost);
                    prop_assert!(same_cost(found.cost(), cost), "AD* {:?}, A* {:?}", found.cost(), cost);
                    prop_assert_eq!(found.iterations.first().map(|i| i.epsilon), Some(2.0));
                }
            }
        }
    }
}
