//! The check of the edge costs a one-shot search meets.

use std::fmt::Debug;

use trailmark_core::cost::Cost;

use crate::error::SearchError;

/// Keeps the first invalid edge cost met inside a successor callback.
pub(crate) struct EdgeCheck<N> {
    bad: Option<(N, Cost)>,
}

impl<N: Copy + Debug> EdgeCheck<N> {
    pub fn new() -> Self {
        EdgeCheck { bad: None }
    }

    /// Whether the edge to `to` should be followed: false for `NO_EDGE`, and for invalid costs
    /// (which are remembered).
    #[inline]
    pub fn accept(&mut self, to: N, cost: Cost) -> bool {
        // One integer comparison: the bit patterns below that of +inf are exactly the
        // non-negative finite numbers (negative numbers and NaN have larger patterns).
        if cost.to_bits() < f64::INFINITY.to_bits() {
            return true;
        }
        self.unusual(to, cost)
    }

    /// The rest of [`EdgeCheck::accept`], out of the hot path: `-0.0` is accepted, `NO_EDGE`
    /// skipped, anything else remembered as invalid.
    #[cold]
    #[inline(never)]
    fn unusual(&mut self, to: N, cost: Cost) -> bool {
        if cost == 0.0 {
            return true;
        }
        if cost != f64::INFINITY && self.bad.is_none() {
            self.bad = Some((to, cost));
        }
        false
    }

    /// An error naming the first invalid edge met, whose tail is `from()`.
    pub fn check(&self, from: impl FnOnce() -> N) -> Result<(), SearchError<N>> {
        match self.bad {
            None => Ok(()),
            Some((to, cost)) => Err(SearchError::InvalidEdgeCost { from: from(), to, cost }),
        }
    }
}
