//! The all-pairs table against Floyd-Warshall, recomputed from scratch after every batch of
//! changes on random directed graphs: edges that get cheaper, dearer, appear and go.

use proptest::prelude::*;
use trailmark_core::cost::Cost;
use trailmark_core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
use trailmark_search::{AllPairs, SearchError};

#[path = "common/digraph.rs"]
mod digraph;
use digraph::Digraph;

/// Every pair's shortest distance by Floyd-Warshall.
fn floyd_warshall(graph: &Digraph) -> Vec<Vec<Cost>> {
    let n = graph.cost.len();
    let mut d = graph.cost.clone();
    for (v, row) in d.iter_mut().enumerate() {
        row[v] = 0.0;
    }
    for k in 0..n {
        for i in 0..n {
            for j in 0..n {
                let through = d[i][k] + d[k][j];
                if through < d[i][j] {
                    d[i][j] = through;
                }
            }
        }
    }
    d
}

/// Checks every distance of `table` (rows: `sources`) against Floyd-Warshall on `graph`.
fn check(table: &AllPairs<usize>, graph: &Digraph, sources: &[usize]) -> Result<(), TestCaseError> {
    let expected = floyd_warshall(graph);
    for &s in sources {
        for (t, &best) in expected[s].iter().enumerate() {
            let want = Some(best).filter(|d| d.is_finite());
            let got = table.distance(s, t);
            match (got, want) {
                (Some(a), Some(b)) => {
                    prop_assert!((a - b).abs() <= 1e-9 * b.max(1.0), "{s} -> {t}: {a} vs {b}")
                }
                _ => prop_assert_eq!(got, want, "{} -> {}", s, t),
            }
        }
    }
    Ok(())
}

/// A random graph: up to 13 nodes and 60 edges, costs whole numbers from 1 to 20 (so sums are
/// exact) or fractions.
fn graph_strategy() -> impl Strategy<Value = Digraph> {
    let cost = prop_oneof![(1u32..=20).prop_map(f64::from), 0.1f64..10.0];
    (2usize..14, prop::collection::vec((any::<usize>(), any::<usize>(), cost), 0..60)).prop_map(
        |(n, edges)| {
            let edges: Vec<_> =
                edges.into_iter().map(|(a, b, c)| (a % n, b % n, c)).filter(|(a, b, _)| a != b).collect();
            Digraph::new(n, &edges)
        },
    )
}

/// A batch of changes: (from, to, new cost or none), by index into the graph's nodes.
fn batches() -> impl Strategy<Value = Vec<Vec<(usize, usize, Option<f64>)>>> {
    let change = (any::<usize>(), any::<usize>(), prop::option::weighted(0.8, 0.1f64..25.0));
    prop::collection::vec(prop::collection::vec(change, 1..8), 1..6)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// After every batch of changes the table equals Floyd-Warshall on the changed graph, for
    /// every node as a source and for a few sources.
    #[test]
    fn equal_to_floyd_warshall_after_every_change(mut graph in graph_strategy(), batches in batches(), pick in any::<usize>()) {
        let n = graph.cost.len();
        let every: Vec<usize> = (0..n).collect();
        let some: Vec<usize> = vec![pick % n, (pick / 7) % n];
        let mut table = AllPairs::new(&graph, 0..n).expect("valid graph");
        let mut rows = AllPairs::from_sources(&graph, 0..n, &some).expect("valid graph");
        check(&table, &graph, &every)?;
        check(&rows, &graph, &some)?;
        for batch in batches {
            let mut changes = Vec::new();
            for (a, b, cost) in batch {
                let (a, b) = (a % n, b % n);
                if a == b {
                    continue;
                }
                graph.cost[a][b] = cost.map_or(f64::INFINITY, |c| (c * 4.0).round().max(1.0) / 4.0);
                changes.push(EdgeChange::new(a, b));
            }
            table.update_edges(&graph, &changes).expect("valid changes");
            rows.update_edges(&graph, &changes).expect("valid changes");
            check(&table, &graph, &every)?;
            check(&rows, &graph, &some)?;
        }
    }
}

#[test]
fn refused_changes_leave_the_table_as_it_was() {
    let mut graph = Digraph::new(3, &[(0, 1, 1.0), (1, 2, 1.0), (0, 2, 5.0)]);
    let mut table = AllPairs::new(&graph, 0..3).unwrap();
    assert_eq!(table.distance(0, 2), Some(2.0));
    graph.cost[1][2] = 0.0;
    let err = table.update_edges(&graph, &[EdgeChange::new(1, 2)]).unwrap_err();
    assert_eq!(err, SearchError::ZeroCostEdge { from: 1, to: 2 });
    graph.cost[1][2] = f64::NAN;
    assert!(matches!(
        table.update_edges(&graph, &[EdgeChange::new(1, 2)]),
        Err(SearchError::InvalidEdgeCost { .. })
    ));
    // A node the graph gained since the table was built.
    let mut grown = graph.clone();
    grown.cost.iter_mut().for_each(|row| row.push(f64::INFINITY));
    grown.cost.push(vec![f64::INFINITY; 4]);
    grown.cost[1][3] = 1.0;
    assert_eq!(table.update_edges(&grown, &[EdgeChange::new(1, 3)]), Err(SearchError::UnknownNode(3)));
    assert_eq!(table.distance(0, 2), Some(2.0), "untouched by the refused changes");
    // An edge to what is no node, then or now, is no edge.
    assert!(table.update_edges(&graph, &[EdgeChange::new(1, 7)]).is_ok());
    // Removed: the long way.
    graph.cost[1][2] = f64::INFINITY;
    table.update_edges(&graph, &[EdgeChange::new(1, 2)]).unwrap();
    assert_eq!(table.distance(0, 2), Some(5.0));
    assert_eq!(table.distance(2, 0), None);
    assert_eq!(table.distance(0, 9), None);
}

#[test]
fn costs_that_could_overflow_are_refused() {
    let graph = Digraph::new(3, &[(0, 1, 1e308), (1, 2, 1e308)]);
    assert_eq!(AllPairs::new(&graph, 0..3).unwrap_err(), SearchError::CostOverflow { node: 1 });
    assert_eq!(AllPairs::from_sources(&graph, 0..3, &[5]).unwrap_err(), SearchError::StartNotInGraph(5));
    assert_eq!(AllPairs::new(&graph, 0..5).unwrap_err(), SearchError::UnknownNode(3));
    // A node the list lacks, reached by an edge.
    let graph = Digraph::new(3, &[(0, 1, 1.0), (1, 2, 1.0)]);
    assert_eq!(AllPairs::new(&graph, 0..2).unwrap_err(), SearchError::UnknownNode(2));
}

/// A path of `n` nodes whose edges exist only when asked: a graph too large for a table.
struct Line(usize);

impl Graph for Line {
    type Node = usize;
    fn contains(&self, node: usize) -> bool {
        node < self.0
    }
}
impl Successors for Line {
    fn for_each_successor<F: FnMut(usize, Cost)>(&self, node: usize, mut visit: F) {
        if node + 1 < self.0 {
            visit(node + 1, 1.0);
        }
    }
}
impl Predecessors for Line {
    fn for_each_predecessor<F: FnMut(usize, Cost)>(&self, node: usize, mut visit: F) {
        if node > 0 {
            visit(node - 1, 1.0);
        }
    }
}
impl IndexedGraph for Line {
    fn node_bound(&self) -> usize {
        self.0
    }
    fn index_of(&self, node: usize) -> usize {
        node
    }
    fn node_at(&self, index: usize) -> usize {
        index
    }
}

#[test]
fn tables_too_large_are_refused_before_allocating() {
    let line = Line(20_000);
    assert_eq!(
        AllPairs::new(&line, 0..20_000).unwrap_err(),
        SearchError::TooManyPairs { sources: 20_000, nodes: 20_000 }
    );
    // A few rows of the same graph fit.
    let table = AllPairs::from_sources(&line, 0..20_000, &[0, 19_999]).unwrap();
    assert_eq!(table.distance(0, 19_999), Some(19_999.0));
    assert_eq!(table.distance(19_999, 0), None);
}

#[test]
fn a_cell_blocked_keeps_its_place_without_edges() {
    use trailmark_core::{Cell, Connectivity, Grid};
    use trailmark_graph::GridGraph;

    let grid = Grid::from_rows(&[".....", ".....", ".....", ".....", "....."]).unwrap();
    let mut graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut table = AllPairs::new(&graph, grid.cells()).unwrap();
    let report = |graph: &mut GridGraph, cell: Cell, cost: f64| {
        graph.set_cost(cell, cost).unwrap();
        let mut changes = Vec::new();
        for other in graph.cells_affected_by(cell) {
            changes.extend([EdgeChange::new(other, cell), EdgeChange::new(cell, other)]);
        }
        changes
    };
    // A wall across the middle but for its ends: paths through it go round.
    for x in 1..4 {
        let changes = report(&mut graph, Cell::new(x, 2), f64::INFINITY);
        table.update_edges(&graph, &changes).unwrap();
    }
    let fresh = AllPairs::new(&graph, grid.cells()).unwrap();
    for a in fresh.nodes() {
        for b in fresh.nodes() {
            let (x, y) = (table.distance(*a, *b), fresh.distance(*a, *b));
            assert!(
                x.zip(y).is_some_and(|(x, y)| (x - y).abs() < 1e-9) || x == y,
                "{a:?} -> {b:?}: {x:?} vs {y:?}"
            );
        }
    }
    assert_eq!(table.distance(Cell::new(2, 2), Cell::new(0, 0)), None, "a blocked cell reaches nothing");
    assert_eq!(table.distance(Cell::new(0, 0), Cell::new(2, 2)), None);
    // Opened again, the cell is a node the table has.
    let changes = report(&mut graph, Cell::new(2, 2), 1.0);
    table.update_edges(&graph, &changes).unwrap();
    assert_eq!(table.distance(Cell::new(2, 1), Cell::new(2, 3)), Some(2.0));
}

#[test]
fn costs_lost_to_rounding_are_refused() {
    // 1e17 + 1 rounds to 1e17: the loop 1 <-> 2 would hold up its distance after 0 -> 1 went.
    let graph = Digraph::new(3, &[(0, 1, 1e17), (1, 2, 1.0), (2, 1, 1.0)]);
    assert_eq!(AllPairs::new(&graph, 0..3).unwrap_err(), SearchError::ZeroCostEdge { from: 1, to: 2 });
}

#[test]
fn a_batch_refused_by_its_last_change_changes_nothing() {
    let mut graph = Digraph::new(4, &[(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (0, 3, 9.0)]);
    let mut table = AllPairs::new(&graph, 0..4).unwrap();
    let before: Vec<Vec<Cost>> = (0..4).map(|s| table.row_from(s).unwrap().to_vec()).collect();
    graph.cost[0][1] = 5.0; // valid
    graph.cost[2][3] = -1.0; // refused
    let changes = [EdgeChange::new(0, 1), EdgeChange::new(2, 3)];
    assert!(matches!(table.update_edges(&graph, &changes), Err(SearchError::InvalidEdgeCost { .. })));
    assert!(!table.is_broken());
    let after: Vec<Vec<Cost>> = (0..4).map(|s| table.row_from(s).unwrap().to_vec()).collect();
    assert_eq!(before, after);
    // Fixed, the same batch goes through.
    graph.cost[2][3] = 2.0;
    table.update_edges(&graph, &changes).unwrap();
    assert_eq!(table.distance(0, 3), Some(8.0));
}
