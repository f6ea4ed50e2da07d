//! Reading a path out of the values of the repair engine: from the target, each node's best
//! support, back to the source.

use std::collections::{HashMap, VecDeque};
use std::fmt::Debug;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::incremental::engine::{RepairEngine, SearchDirection};
use crate::incremental::mode::Mode;

impl<N: Copy + Eq + std::hash::Hash + Debug, M: Mode> RepairEngine<N, M> {
    /// The path from `target` to the source along the best supports (`argmin c + g`), in the
    /// order walked; `None` when the target's value is infinite. Ties prefer the smaller `g`.
    ///
    /// With positive costs `g` falls strictly along such a path, so the walk only takes
    /// supports of smaller `g` and needs no record of where it has been. Where rounding makes
    /// the best support's `g` equal to the node's own (an edge far cheaper than the values it
    /// joins, absorbed in the sum), a greedy walk could go round in circles or, kept from doing
    /// so, take a worse support: the walk is then made breadth-first over every best support.
    pub fn walk<G>(&self, graph: &G, target: usize) -> Option<Vec<usize>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        if self.g(target).min(self.rhs(target)) == f64::INFINITY {
            return None;
        }
        let mut slots = vec![target];
        let mut at = target;
        while at != self.source {
            let limit = self.g(at).min(self.rhs(at));
            match self.best_support(graph, at) {
                Some(next) if self.g(next) < limit => {
                    slots.push(next);
                    at = next;
                }
                _ => return self.walk_breadth_first(graph, target),
            }
        }
        Some(slots)
    }

    /// [`RepairEngine::walk`] as a breadth-first search from `target` over the edges to each node's
    /// best supports (all those with the least `c + g`, rounded): the fewest edges among the
    /// paths whose every step is a best support, so the path's cost is the target's value.
    fn walk_breadth_first<G>(&self, graph: &G, target: usize) -> Option<Vec<usize>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut parent = HashMap::from([(target, target)]);
        let mut queue = VecDeque::from([target]);
        let mut supports: Vec<(usize, Cost)> = Vec::new();
        while let Some(at) = queue.pop_front() {
            if at == self.source {
                let mut slots = vec![at];
                let mut node = at;
                while node != target {
                    node = parent[&node];
                    slots.push(node);
                }
                slots.reverse();
                return Some(slots);
            }
            supports.clear();
            let mut collect = |s: usize, c: Cost| {
                let via = c + self.g(s);
                // `via < inf` also rejects invalid (NaN) costs.
                if s != at && via < f64::INFINITY {
                    supports.push((s, via));
                }
            };
            match self.dir {
                SearchDirection::Backward => graph.for_each_successor_index(at, |s, _, c| collect(s, c)),
                SearchDirection::Forward => graph.for_each_predecessor_index(at, |s, _, c| collect(s, c)),
            }
            let best = supports.iter().map(|&(_, via)| via).fold(f64::INFINITY, f64::min);
            for &(s, via) in &supports {
                if via == best && !parent.contains_key(&s) {
                    parent.insert(s, at);
                    queue.push_back(s);
                }
            }
        }
        None
    }

    /// The neighbour of `at` that `at`'s value flows through: `argmin c + g` over its supports
    /// (successors backward, predecessors forward), ties to the smaller `g`; `None` when every
    /// support is infinitely far.
    pub fn best_support<G>(&self, graph: &G, at: usize) -> Option<usize>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut best: Option<(Cost, Cost, usize)> = None;
        let mut consider = |s: usize, c: Cost| {
            let via = (c + self.g(s), self.g(s), s);
            // `via.0 < inf` also rejects invalid (NaN) costs; negative ones never come this
            // far, since the search refused them.
            if via.0 < f64::INFINITY && s != at && best.is_none_or(|b| (via.0, via.1) < (b.0, b.1)) {
                best = Some(via);
            }
        };
        match self.dir {
            SearchDirection::Backward => graph.for_each_successor_index(at, |s, _, c| consider(s, c)),
            SearchDirection::Forward => graph.for_each_predecessor_index(at, |s, _, c| consider(s, c)),
        }
        best.map(|b| b.2)
    }

    /// The walk as a path of nodes from the start to the goal, with `cost`.
    pub fn path<G>(&self, graph: &G, target: usize, cost: Cost) -> Option<Path<N>>
    where
        G: Successors + Predecessors + IndexedGraph<Node = N> + ?Sized,
    {
        let mut nodes: Vec<N> = self.walk(graph, target)?.into_iter().map(|s| graph.node_at(s)).collect();
        if self.dir == SearchDirection::Forward {
            nodes.reverse();
        }
        Some(Path { nodes, cost })
    }
}
