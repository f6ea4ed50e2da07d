//! How a computed path cost is compared with a reference optimum, by `verify` and by the
//! benchmark's grid section alike.

/// The tolerance on a published length: they are rounded (to 6 significant digits in most sets,
/// to 2 decimals in bg512).
pub fn tolerance(optimal: f64) -> f64 {
    1e-4 * optimal.max(1.0) + 0.006
}
