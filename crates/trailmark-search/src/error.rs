//! What can be wrong with a search query.

use std::fmt::Debug;

use thiserror::Error;

/// Why a search could not run. An unreachable goal is not an error: the search then returns a
/// result without a path.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SearchError<N: Debug> {
    /// The start is not a node of the graph (outside it, or a blocked cell).
    #[error("the start {0:?} is not a node of the graph (outside it or blocked)")]
    StartNotInGraph(N),
    /// The goal is not a node of the graph (outside it, or a blocked cell).
    #[error("the goal {0:?} is not a node of the graph (outside it or blocked)")]
    GoalNotInGraph(N),
    /// The graph reported an edge with a negative or NaN cost.
    #[error("the edge {from:?} -> {to:?} has cost {cost}; edge costs must be non-negative")]
    InvalidEdgeCost {
        /// The tail of the edge.
        from: N,
        /// The head of the edge.
        to: N,
        /// The cost reported.
        cost: f64,
    },
    /// The heuristic returned a negative or NaN value.
    #[error(
        "the heuristic of {node:?} is {value}; heuristic values must be non-negative (or +inf for a dead end)"
    )]
    InvalidHeuristic {
        /// The node.
        node: N,
        /// The value returned.
        value: f64,
    },
    /// A weighted search was given a weight that is not a finite number of at least 1.
    #[error("weight {0} is invalid: the heuristic weight must be a finite number >= 1")]
    InvalidWeight(f64),
    /// The graph has more nodes than a search can number.
    #[error("the graph has {0} node indices; a search supports at most {max}", max = crate::search::MAX_NODES)]
    TooManyNodes(usize),
}
