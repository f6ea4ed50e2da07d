//! Heuristics: the estimate between two nodes the replanners are given, and the check of the
//! values every search is given.

mod check;

pub(crate) use check::{HeuristicCheck, checked_heuristic};

use trailmark_core::cost::Cost;
use trailmark_core::graph::Graph;

/// An estimate of the cost from one node of a graph to another, asked with the graph as it is
/// at that call: what the replanners ([`Replanner`](crate::Replanner)) are given.
///
/// Because the graph is passed at each call, the heuristic need not hold a borrow of it, and the
/// graph stays free to change between plans. A closure `FnMut(Node, Node) -> Cost` is a
/// heuristic that does not read the graph (the grid heuristics of
/// `GridGraph::heuristic_between` are); [`ReadsGraph`] makes one that does. For the replanners
/// that need it, the estimate must be a consistent lower bound on the cost of the cheapest path.
///
/// ```
/// use trailmark_core::cost::Cost;
/// use trailmark_search::{DStarLite, Heuristic, ReadsGraph};
/// # use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
/// # /// Towns on a line, with a road between neighbours that may close.
/// # struct Towns { x: Vec<f64>, closed: Vec<bool> }
/// # impl Graph for Towns {
/// #     type Node = usize;
/// #     fn contains(&self, n: usize) -> bool { n < self.x.len() }
/// # }
/// # impl Successors for Towns {
/// #     fn for_each_successor<F: FnMut(usize, Cost)>(&self, n: usize, mut visit: F) {
/// #         for m in [n.wrapping_sub(1), n + 1] {
/// #             if m < self.x.len() && !self.closed[n.min(m)] {
/// #                 visit(m, (self.x[n] - self.x[m]).abs());
/// #             }
/// #         }
/// #     }
/// # }
/// # impl Predecessors for Towns {
/// #     fn for_each_predecessor<F: FnMut(usize, Cost)>(&self, n: usize, visit: F) {
/// #         self.for_each_successor(n, visit)
/// #     }
/// # }
/// # impl IndexedGraph for Towns {
/// #     fn node_bound(&self) -> usize { self.x.len() }
/// #     fn index_of(&self, n: usize) -> usize { n }
/// #     fn node_at(&self, i: usize) -> usize { i }
/// # }
/// # impl Towns {
/// #     fn straight(&self, a: usize, b: usize) -> Cost { (self.x[a] - self.x[b]).abs() }
/// # }
/// let mut towns = Towns { x: vec![0.0, 1.0, 3.0, 6.0], closed: vec![false; 4] };
/// // The straight-line distance, read from the graph at each plan: no borrow of `towns` is kept.
/// let h = ReadsGraph(|towns: &Towns, a: usize, b: usize| towns.straight(a, b));
/// let mut planner = DStarLite::new(&towns, 0, 3, h)?;
/// planner.compute_shortest_path(&towns)?;
/// assert_eq!(planner.cost(), Some(6.0));
///
/// towns.closed[1] = true; // the road 1-2 closes: the graph changes while the planner lives
/// planner.update_nodes(&towns, [1, 2])?;
/// planner.compute_shortest_path(&towns)?;
/// assert_eq!(planner.cost(), None);
///
/// // A closure of two nodes is a heuristic too.
/// let mut zero = |_: usize, _: usize| 0.0;
/// assert_eq!(Heuristic::<Towns>::estimate(&mut zero, &towns, 0, 3), 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Heuristic<G: Graph + ?Sized> {
    /// The estimate of the cost from `from` to `to` in `graph`.
    fn estimate(&mut self, graph: &G, from: G::Node, to: G::Node) -> Cost;
}

impl<G, F> Heuristic<G> for F
where
    G: Graph + ?Sized,
    F: FnMut(G::Node, G::Node) -> Cost,
{
    #[inline]
    fn estimate(&mut self, _graph: &G, from: G::Node, to: G::Node) -> Cost {
        self(from, to)
    }
}

/// A heuristic that reads the graph: `ReadsGraph(|graph: &MyGraph, a, b| ...)` is asked with the
/// graph of each call, so it keeps no borrow of the graph between plans (see [`Heuristic`]).
#[derive(Debug, Clone, Copy)]
pub struct ReadsGraph<F>(pub F);

impl<G, F> Heuristic<G> for ReadsGraph<F>
where
    G: Graph + ?Sized,
    F: FnMut(&G, G::Node, G::Node) -> Cost,
{
    #[inline]
    fn estimate(&mut self, graph: &G, from: G::Node, to: G::Node) -> Cost {
        (self.0)(graph, from, to)
    }
}
