//! The `pathfinding` crate as a peer: a grid graph's moves and heuristics in the form its
//! searches take (costs as `OrderedFloat`, no allocation per node).

use ordered_float::OrderedFloat;
use trailmark::prelude::*;

/// The graph's moves out of `c`, as the `pathfinding` crate takes them.
pub fn neighbours(graph: &GridGraph, c: Cell) -> impl Iterator<Item = (Cell, OrderedFloat<f64>)> + '_ {
    graph.neighbours(c).map(|(next, cost)| (next, OrderedFloat(cost)))
}

/// The octile distance from `p` to `goal` times `scale` (the smallest cell cost), as the
/// `pathfinding` crate takes a heuristic.
pub fn octile(p: &Cell, goal: Cell, scale: f64) -> OrderedFloat<f64> {
    OrderedFloat(scale * trailmark::core::cost::octile(p.x.abs_diff(goal.x), p.y.abs_diff(goal.y)))
}
