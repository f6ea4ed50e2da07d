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
    /// An incremental planner (LPA*, D* Lite) met an edge of cost 0: they need positive costs.
    #[error("the edge {from:?} -> {to:?} has cost 0; LPA* and D* Lite need positive edge costs")]
    ZeroCostEdge {
        /// The tail of the edge.
        from: N,
        /// The head of the edge.
        to: N,
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
    /// A change notification named a node the graph does not have and cannot have (a cell
    /// outside the grid); nothing of the notification was applied.
    #[error("{0:?} names no node of the graph")]
    UnknownNode(N),
    /// An epsilon schedule that is not finite numbers with `initial >= 1` and `step > 0`.
    #[error(
        "epsilon schedule invalid: initial {initial}, step {step}; need a finite initial >= 1 and a finite step > 0"
    )]
    InvalidEpsilon {
        /// The initial inflation.
        initial: f64,
        /// The decrement per iteration.
        step: f64,
    },
    /// The graph has more nodes than a search can number.
    #[error("the graph has {0} node indices; a search supports at most {max}", max = crate::search::MAX_NODES)]
    TooManyNodes(usize),
}
