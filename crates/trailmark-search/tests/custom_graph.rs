//! The algorithms on a graph defined here (adjacency lists), with zero-cost edges, parallel
//! edges, `NO_EDGE` costs and admissible but inconsistent heuristics, against Bellman-Ford.

use proptest::prelude::*;
use trailmark_core::graph::{Graph, IndexedGraph, Successors};
use trailmark_search::{Hashed, Search, SearchError, astar, dijkstra};

/// Nodes `0..n`, edges as adjacency lists.
#[derive(Debug, Clone)]
struct Adjacency(Vec<Vec<(usize, f64)>>);

impl Graph for Adjacency {
    type Node = usize;
    fn contains(&self, node: usize) -> bool {
        node < self.0.len()
    }
}

impl Successors for Adjacency {
    fn for_each_successor<F: FnMut(usize, f64)>(&self, node: usize, mut visit: F) {
        for &(n, c) in &self.0[node] {
            visit(n, c);
        }
    }
}

impl IndexedGraph for Adjacency {
    fn node_bound(&self) -> usize {
        self.0.len()
    }
    fn index_of(&self, node: usize) -> usize {
        node
    }
    fn node_at(&self, index: usize) -> usize {
        index
    }
}

/// Least costs from every node to `goal`, by Bellman-Ford on the reversed edges.
fn distances_to(graph: &Adjacency, goal: usize) -> Vec<f64> {
    let mut d = vec![f64::INFINITY; graph.0.len()];
    d[goal] = 0.0;
    for _ in 0..graph.0.len() {
        for (a, out) in graph.0.iter().enumerate() {
            for &(b, c) in out {
                if c.is_finite() && d[b] + c < d[a] {
                    d[a] = d[b] + c;
                }
            }
        }
    }
    d
}

fn graph_and_query() -> impl Strategy<Value = (Adjacency, usize, usize, Vec<f64>)> {
    (2usize..30).prop_flat_map(|n| {
        let edge = (0..n, prop_oneof![4 => 0.0f64..10.0, 1 => Just(0.0), 1 => Just(f64::INFINITY)]);
        (
            prop::collection::vec(prop::collection::vec(edge, 0..5), n),
            0..n,
            0..n,
            prop::collection::vec(0.0f64..=1.0, n),
        )
            .prop_map(|(adj, s, t, r)| (Adjacency(adj), s, t, r))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// With a heuristic that never overestimates but jumps around (inconsistent), A* still finds
    /// the least cost, reopening nodes as needed; Dijkstra and the hashing workspace agree.
    #[test]
    fn astar_is_optimal_with_inconsistent_admissible_heuristics((graph, s, t, r) in graph_and_query()) {
        let exact = distances_to(&graph, t);
        let h = |n: usize| if exact[n].is_finite() { r[n] * exact[n] } else { 0.0 };
        let want = exact[s].is_finite().then_some(exact[s]);
        let got = astar(&graph, s, t, h).unwrap().cost();
        let reference = dijkstra(&graph, s, t).unwrap().cost();
        let hashed = Search::<Hashed<usize>>::hashed().astar(&graph, s, t, h).unwrap().cost();
        for (name, cost) in [("astar", got), ("dijkstra", reference), ("hashed astar", hashed)] {
            match (cost, want) {
                (Some(a), Some(b)) => prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "{}: {} vs {}", name, a, b),
                (a, b) => prop_assert_eq!(a, b, "{}", name),
            }
        }
    }

    /// A perfect heuristic with dead ends marked `+inf` prunes without losing the optimum.
    #[test]
    fn infinite_heuristic_marks_dead_ends((graph, s, t, _r) in graph_and_query()) {
        let exact = distances_to(&graph, t);
        let found = astar(&graph, s, t, |n| exact[n]).unwrap();
        prop_assert_eq!(found.cost().is_some(), exact[s].is_finite());
        if let Some(c) = found.cost() {
            prop_assert!((c - exact[s]).abs() <= 1e-9 * c.max(1.0));
        }
    }
}

#[test]
fn negative_and_nan_edge_costs_are_errors() {
    for bad in [-1.0, f64::NAN, f64::NEG_INFINITY] {
        let graph = Adjacency(vec![vec![(1, 1.0)], vec![(2, bad)], vec![]]);
        let err = dijkstra(&graph, 0, 2).unwrap_err();
        match err {
            SearchError::InvalidEdgeCost { from: 1, to: 2, cost } => {
                assert!(cost.is_nan() || cost == bad, "{cost}")
            }
            other => panic!("unexpected {other:?}"),
        }
    }
    // +inf is "no edge", zero is a free edge.
    let graph = Adjacency(vec![vec![(1, f64::INFINITY), (2, 0.0)], vec![], vec![(1, 0.0)]]);
    assert_eq!(dijkstra(&graph, 0, 1).unwrap().path.unwrap().nodes, [0, 2, 1]);
    let err = Search::<Hashed<usize>>::hashed().bfs(&Adjacency(vec![vec![(1, -2.0)], vec![]]), 0, 1);
    assert!(matches!(err, Err(SearchError::InvalidEdgeCost { from: 0, to: 1, .. })));
}

#[test]
fn a_search_workspace_survives_many_queries_and_graphs() {
    let small = Adjacency(vec![vec![(1, 1.0)], vec![(0, 1.0)]]);
    let large = Adjacency((0..100).map(|i| vec![((i + 1) % 100, 1.0)]).collect());
    let mut search = Search::new();
    for round in 0..300 {
        assert_eq!(search.dijkstra(&small, 0, 1).unwrap().cost(), Some(1.0));
        let t = round % 100;
        assert_eq!(search.dijkstra(&large, 0, t).unwrap().cost(), Some(t as f64));
        assert_eq!(search.expanded(&large).count(), t, "only this query's nodes count as expanded");
    }
}

/// Stamps are counted per query and cleared when the count runs out: queries on either side of
/// the reset (and many after it) see none of the earlier queries' state.
#[test]
fn state_survives_the_stamp_reset() {
    // A path 0 -> 1 -> 2 -> 3 with unit costs, and a shortcut 0 -> 3 of cost 5.
    let graph = Adjacency(vec![vec![(1, 1.0), (3, 5.0)], vec![(2, 1.0)], vec![(3, 1.0)], vec![]]);
    let mut search = Search::new();
    for query in 0..70_000u32 {
        // Alternate goals so that every query leaves different nodes stamped.
        let (goal, cost) = if query % 3 == 0 { (3, 3.0) } else { (2, 2.0) };
        let found = search.dijkstra(&graph, 0, goal).expect("valid query");
        assert_eq!(found.cost(), Some(cost), "query {query}");
        assert_eq!(found.stats.expansions, goal as u64, "query {query}");
    }
}
