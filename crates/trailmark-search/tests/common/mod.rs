//! Helpers shared by the integration tests of this crate.

use trailmark_core::cost::Cost;
use trailmark_core::graph::Successors;

/// The cost of `nodes` walked in `graph`, `None` if a step is not an edge.
pub fn walk_cost<G: Successors>(graph: &G, nodes: &[G::Node]) -> Option<Cost> {
    let mut total = 0.0;
    for pair in nodes.windows(2) {
        let mut best = f64::INFINITY;
        graph.for_each_successor(pair[0], |n, c| {
            if n == pair[1] {
                best = best.min(c);
            }
        });
        if !best.is_finite() {
            return None;
        }
        total += best;
    }
    Some(total)
}
