//! A directed graph of nodes `0..n` as an adjacency matrix: the custom graph of the tests that
//! need every edge cost under their control. Included by path where it is used.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};

/// A directed graph of nodes `0..n`, at most one edge per ordered pair.
#[derive(Debug, Clone)]
pub struct Digraph {
    /// `cost[a][b]`: the cost of `a -> b`, `+inf` for no edge.
    pub cost: Vec<Vec<Cost>>,
}

impl Digraph {
    /// `n` nodes and the edges `(from, to, cost)`.
    pub fn new(n: usize, edges: &[(usize, usize, Cost)]) -> Self {
        let mut cost = vec![vec![f64::INFINITY; n]; n];
        for &(a, b, c) in edges {
            cost[a][b] = c;
        }
        Digraph { cost }
    }
}

impl Graph for Digraph {
    type Node = usize;
    fn contains(&self, node: usize) -> bool {
        node < self.cost.len()
    }
}

impl Successors for Digraph {
    fn for_each_successor<F: FnMut(usize, Cost)>(&self, node: usize, mut visit: F) {
        for (b, &c) in self.cost[node].iter().enumerate() {
            if c != f64::INFINITY {
                visit(b, c);
            }
        }
    }
}

impl Predecessors for Digraph {
    fn for_each_predecessor<F: FnMut(usize, Cost)>(&self, node: usize, mut visit: F) {
        for (a, row) in self.cost.iter().enumerate() {
            if row[node] != f64::INFINITY {
                visit(a, row[node]);
            }
        }
    }
}

impl IndexedGraph for Digraph {
    fn node_bound(&self) -> usize {
        self.cost.len()
    }
    fn index_of(&self, node: usize) -> usize {
        node
    }
    fn node_at(&self, index: usize) -> usize {
        index
    }
}
