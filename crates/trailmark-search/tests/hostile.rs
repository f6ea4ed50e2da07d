//! Hostile input (issue 23): costs and inflations that overflow `f64`, inflation schedules that
//! would never end, and change notifications with a wrong old cost. Each gives a typed error or
//! the right answer: never a false "no path", a path with a wrong cost, or a hang.

use std::sync::mpsc;

use proptest::prelude::*;
use std::time::Duration;

mod common;

use common::walk_cost;
use trailmark_core::cost::Cost;
use trailmark_core::graph::EdgeChange;
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_graph::GridGraph;
use trailmark_search::{
    AdStar, DStarLite, EpsilonSchedule, LpaStar, Search, SearchError, ara_star, astar, bfs, dfs, dijkstra,
    weighted_astar,
};

#[path = "common/digraph.rs"]
mod digraph;

use digraph::Digraph;

/// What a planner answered: a path's nodes and reported cost, no path, or an error.
type Answer = Result<Option<(Vec<usize>, Cost)>, SearchError<usize>>;

/// Every planner of the crate from `start` to `goal`, by name, with the heuristic `h(a, b)`.
fn every_planner(
    graph: &Digraph,
    start: usize,
    goal: usize,
    h: fn(usize, usize) -> Cost,
) -> Vec<(&'static str, Answer)> {
    let to_goal = |n| h(n, goal);
    let path = |p: Option<trailmark_core::path::Path<usize>>| p.map(|p| (p.nodes, p.cost));
    let schedule = EpsilonSchedule::new(3.0, 1.0);
    vec![
        ("bfs", bfs(graph, start, goal).map(|r| path(r.path))),
        ("dfs", dfs(graph, start, goal).map(|r| path(r.path))),
        ("dijkstra", dijkstra(graph, start, goal).map(|r| path(r.path))),
        ("astar", astar(graph, start, goal, to_goal).map(|r| path(r.path))),
        ("weighted_astar", weighted_astar(graph, start, goal, to_goal, 2.0).map(|r| path(r.path))),
        (
            "ara_star",
            ara_star(graph, start, goal, to_goal, schedule, Termination::unlimited()).map(|r| path(r.path)),
        ),
        (
            "lpa_star",
            LpaStar::new(graph, start, goal, h).and_then(|mut p| {
                p.compute_shortest_path(graph)?;
                Ok(path(p.path(graph)))
            }),
        ),
        (
            "dstar_lite",
            DStarLite::new(graph, start, goal, h).and_then(|mut p| {
                p.compute_shortest_path(graph)?;
                Ok(path(p.path(graph)))
            }),
        ),
        (
            "ad_star",
            AdStar::new(graph, start, goal, h, schedule)
                .and_then(|mut p| p.improve(graph, Termination::unlimited()).map(|r| path(r.path))),
        ),
    ]
}

fn zero(_: usize, _: usize) -> Cost {
    0.0
}

/// Whether `answer` is the error for a cost that overflowed.
fn overflowed(answer: &Answer) -> bool {
    matches!(answer, Err(SearchError::CostOverflow { .. }))
}

/// `0 -> 1 -> 2` with edges of 1e308: the goal is reachable, but no `f64` holds the cost of
/// the way there. Every planner says so; none says "no path" or reports an infinite cost.
#[test]
fn path_costs_past_f64_max_are_errors_not_no_path() {
    let graph = Digraph::new(3, &[(0, 1, 1e308), (1, 2, 1e308)]);
    for (name, answer) in every_planner(&graph, 0, 2, zero) {
        assert!(overflowed(&answer), "{name}: {answer:?}");
    }
    // Dijkstra to every node cannot say the goal is unreachable either.
    let err = Search::new().dijkstra_all(&graph, 0).unwrap_err();
    assert!(matches!(err, SearchError::CostOverflow { node: 2 }), "{err:?}");
}

/// Beside a route whose cost overflows, a route that costs 1.2e308 is the answer: the planners
/// that minimise cost find it, with its exact cost. (BFS and DFS do not look at costs.)
#[test]
fn a_representable_path_beside_an_overflowing_one_is_found() {
    let graph = Digraph::new(4, &[(0, 1, 1e308), (1, 3, 1e308), (0, 2, 0.6e308), (2, 3, 0.6e308)]);
    for (name, answer) in every_planner(&graph, 0, 3, zero).into_iter().skip(2) {
        let (nodes, cost) = answer.unwrap_or_else(|e| panic!("{name}: {e}")).expect(name);
        assert_eq!((nodes.as_slice(), cost), ([0, 2, 3].as_slice(), 1.2e308), "{name}");
    }
}

/// A heuristic whose values, added to a path cost, overflow (1.7e308 away from the target):
/// the answer is the right path or a typed error, never "no path".
#[test]
fn priorities_that_overflow_never_give_no_path() {
    let graph = Digraph::new(3, &[(0, 1, 1e307), (1, 2, 1e307)]);
    let huge = |a: usize, b: usize| if a == b { 0.0 } else { 1.7e308 };
    for (name, answer) in every_planner(&graph, 0, 2, huge) {
        match answer {
            Ok(Some((nodes, cost))) => assert_eq!((nodes, cost), (vec![0, 1, 2], 2e307), "{name}"),
            other => assert!(overflowed(&other), "{name}: {other:?}"),
        }
    }
}

/// A weight or an initial inflation so large that `w h` overflows is refused, not a search in
/// which every node looks like a dead end.
#[test]
fn huge_weights_and_inflations_are_refused() {
    let graph = GridGraph::new(&Grid::new(8, 8).unwrap(), Connectivity::Eight);
    let (start, goal) = (Cell::new(0, 0), Cell::new(7, 5));
    let h = graph.heuristic(GridHeuristic::Octile, goal);
    for weight in [1e308, f64::MAX, 2e6] {
        let found = weighted_astar(&graph, start, goal, h, weight);
        assert!(matches!(found, Err(SearchError::InvalidWeight(_))), "weight {weight}: {found:?}");
    }
    assert!(weighted_astar(&graph, start, goal, h, 1e6).unwrap().path.is_some());
    let between = graph.heuristic_between(GridHeuristic::Octile);
    for (initial, step) in [(1e308, 1e305), (2e6, 1e3)] {
        let schedule = EpsilonSchedule::new(initial, step);
        let found = ara_star(&graph, start, goal, h, schedule, Termination::unlimited());
        assert!(matches!(found, Err(SearchError::InvalidEpsilon { .. })), "ARA* {initial}: {found:?}");
        let planner = AdStar::new(&graph, start, goal, between, schedule);
        assert!(matches!(planner, Err(SearchError::InvalidEpsilon { .. })), "AD* {initial}");
    }
    let top = EpsilonSchedule::new(1e6, 1e3);
    assert!(ara_star(&graph, start, goal, h, top, Termination::unlimited()).unwrap().path.is_some());
}

/// Runs `task` on a thread and waits at most 20 seconds for its answer.
fn within_seconds<T: Send + 'static>(task: impl FnOnce() -> T + Send + 'static) -> Option<T> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(task());
    });
    receive.recv_timeout(Duration::from_secs(20)).ok()
}

/// Schedules whose step is lost to rounding (1e20 - 1 == 1e20 in `f64`), or that would take
/// more iterations than a count can hold, are refused at once, not run forever.
#[test]
fn schedules_that_cannot_reach_one_are_refused_promptly() {
    for (initial, step) in [(1e20, 1.0), (1e300, 1.0), (1.0 + f64::EPSILON, 1e-17), (4.0, 1e-300)] {
        let schedule = EpsilonSchedule::new(initial, step);
        let answers = within_seconds(move || {
            let graph = GridGraph::new(&Grid::new(6, 6).unwrap(), Connectivity::Eight);
            let (start, goal) = (Cell::new(0, 0), Cell::new(5, 3));
            let h = graph.heuristic(GridHeuristic::Octile, goal);
            let ara = ara_star(&graph, start, goal, h, schedule, Termination::unlimited()).map(|r| r.stop);
            let between = graph.heuristic_between(GridHeuristic::Octile);
            let ad = AdStar::new(&graph, start, goal, between, schedule)
                .and_then(|mut p| p.improve(&graph, Termination::unlimited()))
                .map(|r| r.stop);
            (schedule.check::<Cell>(), ara, ad)
        });
        let (checked, ara, ad) = answers.unwrap_or_else(|| panic!("({initial}, {step}) did not end"));
        for answer in [checked.map(|_| Stop::Optimal), ara, ad] {
            assert!(
                matches!(answer, Err(SearchError::InvalidEpsilon { .. })),
                "({initial}, {step}): {answer:?}"
            );
        }
    }
    assert!(EpsilonSchedule::new(3.0, 0.5).iterations() == 5);
}

/// A change told by its endpoints only: `1 -> 2` goes from 1 to 10 (the way `0 -> 2` costs 11),
/// twice over (a second telling of the same change changes nothing). The planners' cost is that
/// of the path they return, walked in the graph, and the least cost.
#[test]
fn a_rise_told_without_its_old_cost_gives_the_right_path_cost() {
    for told in 1..=2 {
        let mut graph = Digraph::new(3, &[(0, 1, 1.0), (1, 2, 1.0), (0, 2, 11.5)]);
        let mut dstar = DStarLite::new(&graph, 0, 2, zero).unwrap();
        let mut lpa = LpaStar::new(&graph, 0, 2, zero).unwrap();
        let mut ad = AdStar::new(&graph, 0, 2, zero, EpsilonSchedule::new(2.0, 1.0)).unwrap();
        dstar.compute_shortest_path(&graph).unwrap();
        lpa.compute_shortest_path(&graph).unwrap();
        assert_eq!(ad.improve(&graph, Termination::unlimited()).unwrap().cost(), Some(2.0));
        graph.cost[1][2] = 10.0;
        let change = vec![EdgeChange::new(1, 2); told];
        dstar.update_edges(&graph, &change).unwrap();
        lpa.update_edges(&graph, &change).unwrap();
        ad.update_edges(&graph, &change).unwrap();
        dstar.compute_shortest_path(&graph).unwrap();
        lpa.compute_shortest_path(&graph).unwrap();
        let found = ad.improve(&graph, Termination::unlimited()).unwrap();
        for (name, cost, path) in [
            ("D* Lite", dstar.cost(), dstar.path(&graph)),
            ("LPA*", lpa.cost(), lpa.path(&graph)),
            ("AD*", found.cost(), found.path.clone()),
        ] {
            let path = path.unwrap_or_else(|| panic!("{name}: no path"));
            assert_eq!(walk_cost(&graph, &path.nodes), Some(path.cost), "{name}, told {told}");
            assert_eq!((cost, path.cost), (Some(11.0), 11.0), "{name}, told {told}: {:?}", path.nodes);
        }
    }
}

/// The same through a cheaper edge: `0 -> 2` drops from 11.5 to 3.
#[test]
fn a_fall_told_without_its_old_cost_is_found() {
    let mut graph = Digraph::new(3, &[(0, 1, 2.0), (1, 2, 2.0), (0, 2, 11.5)]);
    let mut dstar = DStarLite::new(&graph, 0, 2, zero).unwrap();
    let mut lpa = LpaStar::new(&graph, 0, 2, zero).unwrap();
    dstar.compute_shortest_path(&graph).unwrap();
    lpa.compute_shortest_path(&graph).unwrap();
    graph.cost[0][2] = 3.0;
    let change = [EdgeChange::new(0, 2)];
    dstar.update_edges(&graph, &change).unwrap();
    lpa.update_edges(&graph, &change).unwrap();
    dstar.compute_shortest_path(&graph).unwrap();
    lpa.compute_shortest_path(&graph).unwrap();
    for (name, cost, path) in
        [("D* Lite", dstar.cost(), dstar.path(&graph)), ("LPA*", lpa.cost(), lpa.path(&graph))]
    {
        assert_eq!((cost, path.map(|p| p.nodes)), (Some(3.0), Some(vec![0, 2])), "{name}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Random digraphs whose edges change in batches, each change told by its endpoints (some
    /// twice, some of edges that did not change): D* Lite and LPA* still answer as Dijkstra
    /// does, and each path's reported cost is its cost walked in the graph.
    #[test]
    fn changes_told_by_endpoints_on_digraphs_match_dijkstra(
        (n, edges, start, goal, batches) in (2usize..10).prop_flat_map(|n| (
            Just(n),
            prop::collection::vec((0..n, 0..n, 0.5f64..10.0), 0..30),
            0..n,
            0..n,
            prop::collection::vec(
                prop::collection::vec((0..n, 0..n, edge_cost(), 0usize..3), 1..5), 1..6),
        )),
    ) {
        let mut graph = Digraph::new(n, &edges);
        let mut dstar = DStarLite::new(&graph, start, goal, zero).unwrap();
        let mut lpa = LpaStar::new(&graph, start, goal, zero).unwrap();
        for batch in std::iter::once(&vec![]).chain(&batches) {
            let mut changes = Vec::new();
            for &(a, b, new, told) in batch {
                // Told 0 times: an edge left as it was; its change is told as that of an edge
                // beside it, which did not change.
                if told == 0 {
                    changes.push(EdgeChange::new(b, a));
                } else {
                    graph.cost[a][b] = new;
                    changes.extend(std::iter::repeat_n(EdgeChange::new(a, b), told));
                }
            }
            dstar.update_edges(&graph, &changes).unwrap();
            lpa.update_edges(&graph, &changes).unwrap();
            dstar.compute_shortest_path(&graph).unwrap();
            lpa.compute_shortest_path(&graph).unwrap();
            let expected = dijkstra(&graph, start, goal).unwrap().cost();
            for (name, cost, path) in [("D* Lite", dstar.cost(), dstar.path(&graph)), ("LPA*", lpa.cost(), lpa.path(&graph))] {
                prop_assert!(same(cost, expected), "{}: {:?}, Dijkstra {:?}", name, cost, expected);
                if let Some(path) = path {
                    prop_assert!(same(walk_cost(&graph, &path.nodes), Some(path.cost)), "{}", name);
                }
            }
        }
    }
}

/// Edge costs for changes: none, or positive.
fn edge_cost() -> impl Strategy<Value = Cost> {
    prop_oneof![2 => Just(f64::INFINITY), 1 => Just(1.0), 4 => 0.5f64..10.0]
}

/// Costs equal up to rounding (sums in different orders).
fn same(a: Option<Cost>, b: Option<Cost>) -> bool {
    match (a, b) {
        (Some(x), Some(y)) => (x - y).abs() <= 1e-9 * x.max(y).max(1.0),
        (None, None) => true,
        _ => false,
    }
}

/// D* Lite's key modifier made infinite (a heuristic that says +inf from where the robot was to
/// where it moved): the planner re-keys its queue from the new start and still answers right.
#[test]
fn an_infinite_key_modifier_is_recovered_from() {
    // A line 0 - 1 - 2 - 3, both ways, cost 1, and a shortcut 1 -> 3 that becomes dearer.
    let both: Vec<(usize, usize, Cost)> = (0..3).flat_map(|a| [(a, a + 1, 1.0), (a + 1, a, 1.0)]).collect();
    let mut graph = Digraph::new(4, &[both, vec![(1, 3, 1.5)]].concat());
    let hostile = |a: usize, b: usize| if (a, b) == (0, 2) { f64::INFINITY } else { 0.0 };
    let mut planner = DStarLite::new(&graph, 0, 3, hostile).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    assert_eq!(planner.cost(), Some(2.5));
    // The robot jumps to 2: `k_m` grows by h(0, 2) = +inf when the graph next changes.
    planner.move_start(&graph, 2).unwrap();
    graph.cost[1][3] = 5.0;
    planner.update_edges(&graph, &[EdgeChange::new(1, 3)]).unwrap();
    planner.compute_shortest_path(&graph).unwrap();
    assert!(planner.key_modifier().is_finite());
    assert_eq!((planner.cost(), planner.path(&graph).map(|p| p.nodes)), (Some(1.0), Some(vec![2, 3])));
}

/// Cells of 1e-200 beside cells of 1 (found by the fuzzer): a cheap step is absorbed in the sum
/// `c + g`, so two neighbours hold the same value. LPA\*'s walk then took a worse support and
/// reported 1.207 for a path of 1.414; D\* Lite's went round in circles and said "no path";
/// AD\* said "stopped". The walk now goes breadth-first over the best supports.
#[test]
fn cells_far_cheaper_than_their_neighbours_keep_paths_and_costs() {
    let tiny = 1e-200;
    let grid = Grid::from_costs(2, 4, vec![1.0, 1.0, 1.0, tiny, 1.0, tiny, 1.0, tiny]).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (start, goal) = (Cell::new(0, 2), Cell::new(0, 0));
    let h = |_: Cell, _: Cell| 0.0;
    let expected = dijkstra(&graph, start, goal).unwrap().cost().unwrap();
    assert!((expected - (0.5 + 0.5f64.sqrt())).abs() < 1e-12, "{expected}");
    let mut lpa = LpaStar::new(&graph, start, goal, h).unwrap();
    lpa.compute_shortest_path(&graph).unwrap();
    let mut dstar = DStarLite::new(&graph, start, goal, h).unwrap();
    dstar.compute_shortest_path(&graph).unwrap();
    let mut ad = AdStar::new(&graph, start, goal, h, EpsilonSchedule::new(2.0, 0.5)).unwrap();
    let ad_path = ad.improve(&graph, Termination::unlimited()).unwrap().path;
    for (name, path) in [("LPA*", lpa.path(&graph)), ("D* Lite", dstar.path(&graph)), ("AD*", ad_path)] {
        let path = path.unwrap_or_else(|| panic!("{name}: no path"));
        assert_eq!(walk_cost(&graph, &path.nodes), Some(path.cost), "{name}: {:?}", path.nodes);
        assert_eq!(path.cost, expected, "{name}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Digraphs mixing edges of 1e-200 and 1e-20 with edges near 1, as above: every planner's
    /// path costs what it reports, walked in the graph, and the optimal ones cost what
    /// Dijkstra's does.
    #[test]
    fn absorbed_edge_costs_never_give_a_wrong_path(
        (n, edges, start, goal) in (2usize..9).prop_flat_map(|n| (
            Just(n),
            prop::collection::vec(
                (0..n, 0..n, prop_oneof![Just(1e-200), Just(1e-20), 0.5f64..2.0]), 0..30),
            0..n,
            0..n,
        )),
    ) {
        let graph = Digraph::new(n, &edges);
        let expected = dijkstra(&graph, start, goal).unwrap().cost();
        for (name, answer) in every_planner(&graph, start, goal, zero) {
            let answer = answer.unwrap();
            if let Some((nodes, cost)) = &answer {
                prop_assert!(same(walk_cost(&graph, nodes), Some(*cost)), "{}: {:?} for {}", name, nodes, cost);
            }
            prop_assert_eq!(answer.is_some(), expected.is_some(), "{}", name);
            if !matches!(name, "bfs" | "dfs" | "weighted_astar" | "ara_star" | "ad_star") {
                prop_assert!(same(answer.map(|a| a.1), expected), "{}: Dijkstra {:?}", name, expected);
            }
        }
    }
}
