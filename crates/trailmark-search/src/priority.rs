//! Priorities compared at a fixed precision: the rounding every open list of this crate applies
//! to the primary part of its keys.

use trailmark_core::cost::Cost;

/// Low mantissa bits that priority comparisons ignore (see [`priority_bits`]).
pub(crate) const IGNORED_BITS: u32 = 20;

/// The bit pattern of a non-negative priority (an `f` value, or the primary part of a lifelong
/// key) rounded to 32 of its 52 mantissa bits, a relative precision of 2^-32 (about 2.3e-10).
///
/// Priorities add edge costs and heuristic values in orders that differ from node to node, so
/// values equal in exact arithmetic differ in their last bits (on an open grid, by about 1e-13
/// after a few hundred moves). Compared bit for bit, such near-ties are ordered by rounding
/// noise, and the tie-breaking rule (larger `g` first), which is what lets A* walk straight
/// across the many cells of equal `f` of an open area, never applies: on an empty 512 x 512
/// grid, A* between far corners then expands a whole parallelogram of cells (128,145 in one
/// measured query) instead of the path's cells. Rounding every priority to 2^-32 makes such
/// near-ties exact ties again. The price is that priorities closer than that are ordered as
/// equal: a search can return a path whose cost exceeds the least by at most a relative 2^-32,
/// far below what costs summed in floating point resolve anyway.
///
/// Rounding is monotone, so the order of priorities that differ by more is unchanged; `+inf`
/// stays `+inf`.
#[inline]
pub(crate) fn priority_bits(value: Cost) -> u64 {
    // `+ 0.0` turns a negative zero into a positive one, whose bits order correctly.
    let bits = (value + 0.0).to_bits();
    (bits + (1 << (IGNORED_BITS - 1))) & !((1 << IGNORED_BITS) - 1)
}
