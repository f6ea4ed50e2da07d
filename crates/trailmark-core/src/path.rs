//! Paths: a sequence of nodes from start to goal with its total cost.

use serde::{Deserialize, Serialize};

use crate::cost::Cost;

/// A path through a graph: the nodes from start to goal, both included, and the sum of the
/// costs of its edges.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Path<N> {
    /// The nodes, start first and goal last; a single node when start is the goal.
    pub nodes: Vec<N>,
    /// The total cost of the edges along the path.
    pub cost: Cost,
}

impl<N: Copy> Path<N> {
    /// The first node.
    pub fn start(&self) -> Option<N> {
        self.nodes.first().copied()
    }

    /// The last node.
    pub fn goal(&self) -> Option<N> {
        self.nodes.last().copied()
    }

    /// The number of edges (moves) along the path.
    pub fn moves(&self) -> usize {
        self.nodes.len().saturating_sub(1)
    }
}
