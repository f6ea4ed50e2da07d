//! The check of the heuristic values a search is given, written once for every family.

use std::fmt::Debug;

use trailmark_core::cost::Cost;

use crate::error::SearchError;

/// Whether `value` is a valid heuristic value: non-negative (`-0.0` counts as 0), or `+inf` for
/// a dead end; negative numbers and NaN are not.
#[inline]
pub(crate) fn valid_heuristic(value: Cost) -> bool {
    // One integer comparison: the bit patterns up to that of +inf are exactly the non-negative
    // numbers and +inf (negative numbers and NaN have larger patterns).
    value.to_bits() <= f64::INFINITY.to_bits() || value == 0.0
}

/// `value`, the heuristic of `node`, or the error naming both when it is invalid.
#[inline]
pub(crate) fn checked_heuristic<N: Debug>(node: N, value: Cost) -> Result<Cost, SearchError<N>> {
    if valid_heuristic(value) { Ok(value) } else { Err(SearchError::InvalidHeuristic { node, value }) }
}

/// Keeps the first invalid heuristic value met inside a loop that cannot return an error.
#[derive(Debug, Clone)]
pub(crate) struct HeuristicCheck<N> {
    bad: Option<(N, Cost)>,
}

impl<N: Copy + Debug> HeuristicCheck<N> {
    /// Nothing invalid met yet.
    pub(crate) fn new() -> Self {
        HeuristicCheck { bad: None }
    }

    /// `value`, the heuristic of `node`, when it is valid; otherwise `None`, and the value is
    /// remembered if it is the first invalid one.
    #[inline]
    pub(crate) fn accept(&mut self, node: N, value: Cost) -> Option<Cost> {
        if valid_heuristic(value) {
            Some(value)
        } else {
            self.bad.get_or_insert((node, value));
            None
        }
    }

    /// The error naming the first invalid value met, if any.
    #[inline]
    pub(crate) fn check(&self) -> Result<(), SearchError<N>> {
        match self.bad {
            None => Ok(()),
            Some((node, value)) => Err(SearchError::InvalidHeuristic { node, value }),
        }
    }

    /// [`HeuristicCheck::check`], forgetting the value: the search goes on afterwards.
    pub(crate) fn take(&mut self) -> Result<(), SearchError<N>> {
        let result = self.check();
        self.bad = None;
        result
    }
}
