//! The queue key of the incremental searches packed into one integer.

use trailmark_core::cost::Cost;

use crate::incremental::Key;
use crate::priority::priority_bits;

/// A [`Key`] as one integer, in the order the queue takes nodes: by the primary part (rounded
/// as [`priority_bits`] says), then, among ties, the underconsistent nodes (smaller `g` first, as
/// in the papers) before the overconsistent ones (larger `rhs` first, nearer the target).
///
/// Taking the overconsistent tie nearer the target first walks across an open area, as A*'s
/// larger-`g` rule does, instead of filling it; it is safe because such ties cannot hold up a
/// value (docs/search.md, "Why the keys are packed", gives the argument and the bit layout).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct PackedKey(u128);

/// The top bit of the secondary word: an overconsistent node.
const OVER: u64 = 1 << 63;

impl PackedKey {
    #[inline]
    pub(super) fn new(key: Key, overconsistent: bool) -> Self {
        let secondary = (key.secondary + 0.0).to_bits();
        let low = if overconsistent { OVER | ((OVER - 1) - secondary) } else { secondary };
        PackedKey((u128::from(priority_bits(key.primary)) << 64) | u128::from(low))
    }

    /// The bits of the (rounded) primary part, which order like its value.
    #[inline]
    pub(super) fn primary_bits(self) -> u64 {
        (self.0 >> 64) as u64
    }

    /// Whether the node was underconsistent when queued.
    #[inline]
    pub(super) fn under(self) -> bool {
        (self.0 as u64) & OVER == 0
    }

    #[inline]
    pub(super) fn key(self) -> Key {
        let low = self.0 as u64;
        let secondary = if low & OVER == 0 { low } else { (OVER - 1) - (low & !OVER) };
        Key::new(f64::from_bits(self.primary_bits()), f64::from_bits(secondary))
    }
}

/// Whether an underconsistent node whose key has the (rounded) `primary` part must be expanded
/// before the repair loop ends at a `target` primary key: when it is below, or when the two
/// differ by no more than rounding (a relative 1e-9).
///
/// The primary part of a key adds `g`, `h` (and `k_m`) in an order that can differ, in the last
/// bits, from the sums that made the target's `g`; rounding priorities to 32 mantissa bits
/// (see `priority_bits`) makes most such near-ties exact, but two values on either side of a
/// rounding boundary still differ by one unit. Leaving behind an underconsistent node whose
/// key ties with the target's in exact arithmetic could leave a stale value a path would
/// follow; overconsistent near-ties cannot lower the target's value and may wait.
#[inline]
pub(super) fn below(primary: Cost, target: Cost) -> bool {
    // Written as a difference so that a target near the largest `f64` cannot overflow to a
    // tolerance that admits every key.
    primary <= target || (target.is_finite() && primary - target <= 1e-9 * target.max(1.0))
}
