//! Priorities compared at a fixed precision: the rounding every open list of this crate applies
//! to the primary part of its keys.

use trailmark_core::cost::Cost;

/// Low mantissa bits that priority comparisons ignore (see [`priority_bits`]).
pub(crate) const IGNORED_BITS: u32 = 20;

/// The bit pattern of a non-negative priority (an `f` value, or the primary part of a lifelong
/// key) rounded to 32 of its 52 mantissa bits, a relative precision of 2^-32 (about 2.3e-10).
///
/// Sums equal in exact arithmetic but rounded differently become exact ties again, so the
/// tie-breaking rule applies to them (docs/search.md, "Why the keys are packed"); a path found
/// costs at most a relative 2^-32 more than the least. Rounding is monotone and keeps `+inf`.
#[inline]
pub(crate) fn priority_bits(value: Cost) -> u64 {
    // `+ 0.0` turns a negative zero into a positive one, whose bits order correctly.
    let bits = (value + 0.0).to_bits();
    (bits + (1 << (IGNORED_BITS - 1))) & !((1 << IGNORED_BITS) - 1)
}
