//! The paths earlier plans found, kept for the plans after them: MPGAA*'s pointer per node
//! toward the goal (Hernández, Baier and Asín, "Reusing previously found A* paths for fast
//! goal-directed navigation in dynamic terrain", AAAI 2015).
//!
//! A node's pointer names the next node of a path to the goal that an earlier plan found (or
//! that the consistency repair found when a cost fell). The path from a node is usable when
//! every step along it still satisfies `h(s) = c(s, next(s)) + h(next(s))` with the learned
//! heuristic, down to the goal: then it costs exactly `h(s)`, and a search that takes `s` off
//! its open list at the least `f = g(s) + h(s)` has found a least-cost path without going
//! further. The learned values along a path are laid backward from the goal with the very sums
//! the test makes, so the equality is exact in floating point.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Successors};
use trailmark_core::path::Path;

use crate::incremental::planner::edge_cost;
use crate::incremental::values::grow_zeroed;

/// No pointer. Pointers are stored as the index plus one, so that fresh state is all zeros
/// (memory the system hands out zeroed, touched only where used).
const NONE: u32 = 0;

/// Pointers toward the goal, one per node index, and which of them are known to reach it.
#[derive(Debug, Clone)]
pub(crate) struct PathReuse {
    /// One more than the index of the next node toward the goal, or [`NONE`].
    next: Vec<u32>,
    /// The cost of the edge to the next node when the pointer was set; a told change that makes
    /// the edge cost anything else cuts the pointer.
    step: Vec<Cost>,
    /// The era in which the path from a node was last found to reach the goal (0: never).
    verified: Vec<u32>,
    /// Bumped whenever costs or learned values may have changed: what was verified before
    /// must be verified again. Never 0.
    era: u32,
    /// The nodes of the path being tested.
    walked: Vec<u32>,
}

impl PathReuse {
    /// No kept path, and no room yet: see [`resize`](Self::resize).
    pub fn new() -> Self {
        PathReuse { next: Vec::new(), step: Vec::new(), verified: Vec::new(), era: 1, walked: Vec::new() }
    }

    /// Room for `bound` node indices.
    pub fn resize(&mut self, bound: usize) {
        grow_zeroed(&mut self.next, bound);
        grow_zeroed(&mut self.step, bound);
        grow_zeroed(&mut self.verified, bound);
    }

    /// Forgets what was verified: a cost or a learned value along a kept path changed.
    fn invalidate(&mut self) {
        self.era = self.era.wrapping_add(1);
        if self.era == 0 {
            self.verified.fill(0);
            self.era = 1;
        }
    }

    /// Points `from` at `to` over an edge of cost `c`: the consistency repair lowered `h(from)`
    /// to `c + h(to)`, which changes the learned cost of every kept path through `from`.
    pub fn point(&mut self, from: usize, to: usize, c: Cost) {
        self.next[from] = to as u32 + 1;
        self.step[from] = c;
        self.forget_through(from);
    }

    /// Forgets what was verified if a verified path goes through node index `s`, which just
    /// changed. Every node of a verified path is verified itself, so a node that is not
    /// changes none.
    fn forget_through(&mut self, s: usize) {
        if self.verified[s] == self.era {
            self.invalidate();
        }
    }

    /// Whether the step from node index `s` along its pointer is exact under `learned` (edge
    /// costs are checked when changes are told: [`step_kept`](Self::step_kept)).
    #[inline]
    fn step_holds(&self, learned: &[Cost], s: usize) -> bool {
        let n = self.next[s];
        n != NONE && learned[s] == self.step[s] + learned[n as usize - 1]
    }

    /// The node index that the pointer of node index `s` names, if any.
    #[inline]
    pub fn next_of(&self, s: usize) -> Option<usize> {
        (self.next[s] != NONE).then(|| self.next[s] as usize - 1)
    }

    /// Whether an edge of cost `c` is the one the step of node index `s` was set with.
    #[inline]
    pub fn step_is(&self, s: usize, c: Cost) -> bool {
        c.to_bits() == self.step[s].to_bits()
    }

    /// Whether an edge from node index `s` to the node its pointer names still has the cost the
    /// step was set with (a parallel edge may serve).
    pub fn step_kept<G>(&self, graph: &G, s: usize) -> bool
    where
        G: Successors + IndexedGraph + ?Sized,
    {
        let Some(n) = self.next_of(s) else { return false };
        let mut kept = false;
        graph.for_each_successor_index(s, |j, _, c| kept |= j == n && self.step_is(s, c));
        kept
    }

    /// Cuts the pointer of node index `s` (its edge changed), forgetting what was verified
    /// through it.
    pub fn cut(&mut self, s: usize) {
        self.next[s] = NONE;
        self.forget_through(s);
    }

    /// Whether the kept path from node index `from` reaches `goal` with every step exact under
    /// `learned`. Pointers of a path that fails are cut, so later tests stop where it broke.
    pub fn reaches_goal(&mut self, learned: &[Cost], from: usize, goal: usize) -> bool {
        self.walked.clear();
        let mut s = from;
        let reached = loop {
            if s == goal || self.verified[s] == self.era {
                break true;
            }
            // More steps than nodes: a cycle of zero-cost edges, not a path.
            if self.walked.len() >= self.next.len() || !self.step_holds(learned, s) {
                break false;
            }
            self.walked.push(s as u32);
            s = self.next[s] as usize - 1;
        };
        if reached {
            for &w in &self.walked {
                self.verified[w as usize] = self.era;
            }
        } else {
            self.next[s] = NONE;
            for &w in &self.walked {
                self.next[w as usize] = NONE;
            }
        }
        reached
    }

    /// The kept path from node index `from`, which [`reaches_goal`](Self::reaches_goal) has
    /// accepted in the last plan, appended to `path` (whose last node is `from`). Pointers change
    /// only while planning, and none of that path's: no node of a verified path is expanded.
    pub fn extend<G>(&self, graph: &G, path: &mut Path<G::Node>, from: usize, goal: usize)
    where
        G: IndexedGraph + ?Sized,
    {
        let mut s = from;
        while s != goal && path.nodes.len() <= self.next.len() {
            let Some(n) = self.next_of(s) else { break };
            s = n;
            path.nodes.push(graph.node_at(s));
        }
    }

    /// Makes the new part of a plan's path, `nodes` (from the start to the node where the search
    /// ended, on the goal or on a verified kept path), a kept path: each node points at the next,
    /// and its learned value becomes the exact cost of the rest, summed backward from the end.
    ///
    /// Nothing verified changes: every node but the end was expanded by the plan, and no node
    /// of a verified path is expanded (the search would have ended there).
    pub fn lay<G>(&mut self, graph: &G, learned: &mut [Cost], nodes: &[G::Node])
    where
        G: Successors + IndexedGraph + ?Sized,
    {
        let Some(&end) = nodes.last() else { return };
        let mut to = graph.index_of(end);
        for pair in nodes.windows(2).rev() {
            let from = graph.index_of(pair[0]);
            let c = edge_cost(graph, pair[0], pair[1]);
            learned[from] = c + learned[to];
            self.next[from] = to as u32 + 1;
            self.step[from] = c;
            self.verified[from] = self.era;
            to = from;
        }
    }

    /// Bytes held.
    pub fn memory_bytes(&self) -> usize {
        (self.next.capacity() + self.verified.capacity() + self.walked.capacity()) * 4
            + self.step.capacity() * 8
    }
}
