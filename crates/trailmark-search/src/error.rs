//! What can be wrong with a search query.

use std::fmt::Debug;

use thiserror::Error;
use trailmark_core::graph::Graph;

use crate::limits::{MAX_EPSILON, MAX_ITERATIONS, MAX_NODES, MAX_PAIRS, MAX_WEIGHT};

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
    #[error("the edge {from:?} -> {to:?} has cost {cost:?}; edge costs must be non-negative")]
    InvalidEdgeCost {
        /// The tail of the edge.
        from: N,
        /// The head of the edge.
        to: N,
        /// The cost reported.
        cost: f64,
    },
    /// An any-angle search (Theta*) was given a negative or NaN cost for a straight line.
    #[error("the line {from:?} -> {to:?} has cost {cost:?}; line costs must be non-negative")]
    InvalidLineCost {
        /// Where the line starts.
        from: N,
        /// Where it ends.
        to: N,
        /// The cost given.
        cost: f64,
    },
    /// An incremental planner (LPA*, D* Lite, the all-pairs table) met an edge of cost 0: they
    /// need positive costs.
    #[error(
        "the edge {from:?} -> {to:?} has cost 0; LPA*, D* Lite and the all-pairs table need positive edge costs"
    )]
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
    /// A weighted search was given a weight that is not a number from 1 to
    /// [`MAX_WEIGHT`].
    #[error("weight {0:?} is invalid: the heuristic weight must be a number from 1 to {max}", max = MAX_WEIGHT)]
    InvalidWeight(f64),
    /// A change notification named a node the graph does not have and cannot have (a cell
    /// outside the grid); nothing of the notification was applied.
    #[error("{0:?} names no node of the graph")]
    UnknownNode(N),
    /// An epsilon schedule that is not `1 <= initial <= MAX_EPSILON` and a finite `step > 0`
    /// that reaches 1 in at most [`MAX_ITERATIONS`] steps, each of which
    /// lowers the inflation (a step lost to rounding, as 1 is beside 1e20, never arrives).
    #[error(
        "epsilon schedule invalid: initial {initial:?}, step {step:?}; need 1 <= initial <= {max}, and a finite step > 0 that lowers it to 1 in at most {iterations} iterations",
        max = MAX_EPSILON,
        iterations = MAX_ITERATIONS
    )]
    InvalidEpsilon {
        /// The initial inflation.
        initial: f64,
        /// The decrement per iteration.
        step: f64,
    },
    /// The goal is reachable, but only at a cost (or a priority `g + w h` on the way) beyond the
    /// largest `f64` (about 1.8e308): finite costs whose sum is infinite. Reported instead of
    /// "no path", which would be false; `+inf` edge costs (no edge) and heuristic values (dead
    /// end) keep their meaning and never cause it.
    ///
    /// The one-shot searches report it only when they found no path (a path found beside an
    /// overflowing one is still the answer, at its exact cost); breadth- and depth-first search
    /// when the path they found costs more than an `f64` holds; the incremental planners
    /// (LPA*, D* Lite, AD*) at every computation after any of their values overflowed, until
    /// `reset`, since values beyond it are no longer exact.
    #[error(
        "the cost of reaching {node:?} (a path cost plus an edge cost, or the priority g + w h) exceeds the largest f64 (about 1.8e308)"
    )]
    CostOverflow {
        /// The first node whose cost or priority overflowed.
        node: N,
    },
    /// A passable cell whose cost differs from the others', on a search that needs every cell to
    /// cost the same (jump point search).
    #[error(
        "the cell {cell:?} costs {cost:?} where the others cost {expected:?}; jump point search needs uniform costs"
    )]
    NonUniformCost {
        /// The first cell found with another cost.
        cell: N,
        /// Its cost.
        cost: f64,
        /// The cost of the cells before it.
        expected: f64,
    },
    /// The graph has more nodes than a search can number.
    #[error("the graph has {0} node indices; a search supports at most {max}", max = MAX_NODES)]
    TooManyNodes(usize),
    /// The grid is too large for a table made per cell (JPS+: at most 2^24 cells, and 32,766
    /// a side).
    #[error("a {width} x {height} grid is too large for a JPS+ table (at most 2^24 cells, 32766 a side)")]
    TableTooLarge {
        /// The grid's width.
        width: u32,
        /// The grid's height.
        height: u32,
    },
    /// A table of shortest distances (`AllPairs`) would hold more than
    /// [`MAX_PAIRS`] distances.
    #[error("{sources} sources x {nodes} nodes is more distances than a table holds (at most {max})", max = MAX_PAIRS)]
    TooManyPairs {
        /// The sources asked for.
        sources: usize,
        /// The nodes of the graph.
        nodes: usize,
    },
}

impl<N: Debug> SearchError<N> {
    /// The same error with each node it names written as `f(node)`: for a caller that reports
    /// nodes in its own terms (a roadmap's node ids as points, say).
    pub fn map_node<M: Debug>(self, mut f: impl FnMut(N) -> M) -> SearchError<M> {
        match self {
            SearchError::StartNotInGraph(n) => SearchError::StartNotInGraph(f(n)),
            SearchError::GoalNotInGraph(n) => SearchError::GoalNotInGraph(f(n)),
            SearchError::InvalidEdgeCost { from, to, cost } => {
                SearchError::InvalidEdgeCost { from: f(from), to: f(to), cost }
            }
            SearchError::InvalidLineCost { from, to, cost } => {
                SearchError::InvalidLineCost { from: f(from), to: f(to), cost }
            }
            SearchError::ZeroCostEdge { from, to } => SearchError::ZeroCostEdge { from: f(from), to: f(to) },
            SearchError::InvalidHeuristic { node, value } => {
                SearchError::InvalidHeuristic { node: f(node), value }
            }
            SearchError::InvalidWeight(w) => SearchError::InvalidWeight(w),
            SearchError::UnknownNode(n) => SearchError::UnknownNode(f(n)),
            SearchError::InvalidEpsilon { initial, step } => SearchError::InvalidEpsilon { initial, step },
            SearchError::CostOverflow { node } => SearchError::CostOverflow { node: f(node) },
            SearchError::TooManyNodes(n) => SearchError::TooManyNodes(n),
            SearchError::TableTooLarge { width, height } => SearchError::TableTooLarge { width, height },
            SearchError::TooManyPairs { sources, nodes } => SearchError::TooManyPairs { sources, nodes },
            SearchError::NonUniformCost { cell, cost, expected } => {
                SearchError::NonUniformCost { cell: f(cell), cost, expected }
            }
        }
    }
}

/// Errors unless both endpoints of a query are nodes of the graph.
pub(crate) fn check_endpoints<G>(graph: &G, start: G::Node, goal: G::Node) -> Result<(), SearchError<G::Node>>
where
    G: Graph + ?Sized,
{
    if !graph.contains(start) {
        return Err(SearchError::StartNotInGraph(start));
    }
    if !graph.contains(goal) {
        return Err(SearchError::GoalNotInGraph(goal));
    }
    Ok(())
}
