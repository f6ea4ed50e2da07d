//! The key of a node in a best-first open list, packed into one integer.

use trailmark_core::cost::Cost;

use crate::priority::{IGNORED_BITS, priority_bits};

/// The key of a node in a best-first open list: `f = g + w h` (at the precision of
/// [`priority_bits`]), ties broken toward larger `g` (deeper nodes first, which on grids reaches
/// the goal after fewer expansions).
///
/// One 64-bit integer: the bits of the rounded `f`, whose low [`IGNORED_BITS`] bits hold `g`
/// inverted at a precision of 2^-19 of `f`, so keys compare as integers and a heap entry takes
/// 16 bytes (docs/search.md, "Why the keys are packed"). Closer `g` values tie arbitrarily.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct FKey(u64);

impl FKey {
    /// The key of a node with `f` and `g`, both non-negative and finite, `g <= f`.
    #[inline]
    pub fn new(f: Cost, g: Cost) -> Self {
        debug_assert!(f >= 0.0 && g >= 0.0);
        const DEPTH_BITS: u32 = IGNORED_BITS - 1;
        const SCALE: u64 = (1 << IGNORED_BITS) - 1;
        let rounded = priority_bits(f);
        // `g` in units of 2^-19 of the power of two below `f`: as `g <= f`, under 2^20. The
        // power of two comes from `f`'s exponent bits rather than a division, which is slow;
        // the exponent is clamped so that the scale stays a normal float (tiny `f` only).
        let exponent = (rounded >> 52).max(u64::from(DEPTH_BITS) + 1);
        let scale = f64::from_bits((2 * 1023 + u64::from(DEPTH_BITS) - exponent) << 52);
        // Adding 2^52 puts the integer part of a number below 2^52 in the low mantissa bits
        // (rounded to nearest): cheaper than a float-to-integer conversion.
        let depth = ((g * scale + 4503599627370496.0).to_bits() & ((1 << 52) - 1)).min(SCALE);
        FKey(rounded | (SCALE - depth))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Keys order by `f` first (beyond the rounding of priorities), then by larger `g`
        /// (beyond the precision of the depth field).
        #[test]
        fn keys_order_by_f_then_larger_g(
            f1 in 0.0..1e6f64, f2 in 0.0..1e6f64, a in 0.0..=1.0f64, b in 0.0..=1.0f64,
        ) {
            let (g1, g2) = (a * f1, b * f2);
            let (k1, k2) = (FKey::new(f1, g1), FKey::new(f2, g2));
            if f1 < f2 * (1.0 - 1e-9) {
                prop_assert!(k1 < k2, "{f1} before {f2}");
            }
            // The same f, different depths.
            let (d1, d2) = (FKey::new(f1, g1), FKey::new(f1, b * f1));
            if g1 > b * f1 + f1 * 1e-5 {
                prop_assert!(d1 < d2, "g {g1} before {} at f {f1}", b * f1);
            }
        }
    }

    #[test]
    fn extreme_keys_stay_ordered() {
        assert!(FKey::new(0.0, 0.0) < FKey::new(f64::MIN_POSITIVE, 0.0));
        assert!(FKey::new(1e-300, 1e-300) < FKey::new(1e-300, 0.0));
        assert!(FKey::new(1e300, 1e300) < FKey::new(1e300, 1e299));
        assert!(FKey::new(1e300, 0.0) < FKey::new(f64::MAX, f64::MAX));
        // Values equal but for rounding noise tie on f, so the larger g wins.
        let f = 0.1 + 0.2;
        assert!(FKey::new(f, 0.2) < FKey::new(0.3, 0.1));
    }
}
