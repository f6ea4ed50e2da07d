//! How the repair engine treats the nodes it expanded: LPA* and D* Lite expand a node again as
//! soon as it is inconsistent ([`Exact`]); AD* closes the nodes of an iteration until the next
//! one and inflates the heuristic of overconsistent keys ([`Anytime`]).
//!
//! The engine is generic over its mode, so the exact planners carry none of AD*'s state, and
//! their loop has no branch on it: every test of the mode is a constant there, removed when the
//! engine is compiled for them.

use crate::incremental::values::grow_zeroed;

/// The part of the repair engine that differs between the exact planners and AD*.
pub(crate) trait Mode {
    /// Whether the planner keeps D* Lite's key modifier `k_m` when the start moves (the exact
    /// planners); AD* recomputes every key at each iteration instead.
    const KEY_MODIFIER: bool;

    /// The heuristic inflation of overconsistent keys.
    fn inflation(&self) -> f64;

    /// Sizes the per-node state for slots `0..len`.
    fn fit(&mut self, len: usize);

    /// Forgets the closed nodes and those held back (a new query).
    fn reset(&mut self);

    /// Whether `slot` was expanded (overconsistent) in the current iteration.
    fn is_closed(&self, slot: usize) -> bool;

    /// Records that `slot` was expanded overconsistent.
    fn close(&mut self, slot: usize);

    /// Holds back `slot`, closed and made inconsistent, until the next iteration.
    fn hold_back(&mut self, slot: usize);

    /// Bytes held by the per-node state.
    fn memory_bytes(&self) -> usize;
}

/// LPA* and D* Lite: no inflation, nothing closed.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Exact;

impl Mode for Exact {
    const KEY_MODIFIER: bool = true;

    #[inline]
    fn inflation(&self) -> f64 {
        1.0
    }

    #[inline]
    fn fit(&mut self, _len: usize) {}

    #[inline]
    fn reset(&mut self) {}

    #[inline]
    fn is_closed(&self, _slot: usize) -> bool {
        false
    }

    #[inline]
    fn close(&mut self, _slot: usize) {}

    #[inline]
    fn hold_back(&mut self, _slot: usize) {}

    fn memory_bytes(&self) -> usize {
        0
    }
}

/// AD*: overconsistent keys inflated by `epsilon`, and the nodes expanded in an iteration
/// closed until the next; an inconsistent closed node waits in `incons` instead of the queue.
#[derive(Debug, Clone)]
pub(crate) struct Anytime {
    /// The heuristic inflation of overconsistent keys.
    pub(crate) epsilon: f64,
    /// `closed[s] == iteration` when `s` was expanded (overconsistent) in this iteration.
    closed: Vec<u32>,
    iteration: u32,
    /// Closed nodes made inconsistent in this iteration (may repeat).
    incons: Vec<u32>,
}

impl Anytime {
    /// The mode at inflation `epsilon`.
    pub(crate) fn new(epsilon: f64) -> Self {
        Anytime { epsilon, closed: Vec::new(), iteration: 1, incons: Vec::new() }
    }

    /// Moves to the next iteration number, which makes every closed mark stale. After 2^32 - 1
    /// iterations (resets included) the marks are cleared and the numbers start again.
    pub(crate) fn advance_iteration(&mut self) {
        if self.iteration == u32::MAX {
            self.closed.fill(0);
            self.iteration = 0;
        }
        self.iteration += 1;
    }

    /// Takes the nodes held back in this iteration.
    pub(crate) fn take_held_back(&mut self) -> impl Iterator<Item = usize> + '_ {
        self.incons.drain(..).map(|s| s as usize)
    }
}

impl Mode for Anytime {
    const KEY_MODIFIER: bool = false;

    #[inline]
    fn inflation(&self) -> f64 {
        self.epsilon
    }

    fn fit(&mut self, len: usize) {
        if self.closed.len() < len {
            grow_zeroed(&mut self.closed, len);
        }
    }

    fn reset(&mut self) {
        self.incons.clear();
        // Closed marks are iteration numbers: the next one makes them all stale.
        self.advance_iteration();
    }

    #[inline]
    fn is_closed(&self, slot: usize) -> bool {
        self.closed[slot] == self.iteration
    }

    #[inline]
    fn close(&mut self, slot: usize) {
        self.closed[slot] = self.iteration;
    }

    #[inline]
    fn hold_back(&mut self, slot: usize) {
        self.incons.push(slot as u32);
    }

    fn memory_bytes(&self) -> usize {
        (self.closed.capacity() + self.incons.capacity()) * 4
    }
}
