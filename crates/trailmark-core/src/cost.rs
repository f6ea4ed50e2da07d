//! Costs: what it takes to traverse an edge or a cell.
//!
//! Costs are plain `f64`. A finite, non-negative cost is a traversable edge; [`NO_EDGE`]
//! (`f64::INFINITY`) means "no edge"; a negative or NaN cost is an error wherever it enters.

/// The cost of traversing an edge: finite and non-negative, or [`NO_EDGE`].
pub type Cost = f64;

/// The cost that means "there is no edge here".
pub const NO_EDGE: Cost = f64::INFINITY;

/// The length of a diagonal grid move, `sqrt(2)`.
pub const SQRT_2: Cost = std::f64::consts::SQRT_2;

/// Whether `cost` can be the cost of an existing edge: finite and `>= 0`.
///
/// ```
/// use trailmark_core::cost::is_edge_cost;
/// assert!(is_edge_cost(0.0) && is_edge_cost(1.5));
/// assert!(!is_edge_cost(-1.0) && !is_edge_cost(f64::NAN) && !is_edge_cost(f64::INFINITY));
/// ```
#[inline]
pub fn is_edge_cost(cost: Cost) -> bool {
    cost.is_finite() && cost >= 0.0
}

/// The octile distance between two cells that are `dx` and `dy` apart: the length of the
/// shortest 8-connected path on an empty grid with unit orthogonal and `sqrt(2)` diagonal moves.
///
/// ```
/// use trailmark_core::cost::octile;
/// assert_eq!(octile(3, 0), 3.0);
/// assert!((octile(2, 5) - (3.0 + 2.0 * std::f64::consts::SQRT_2)).abs() < 1e-12);
/// ```
#[inline]
pub fn octile(dx: u32, dy: u32) -> Cost {
    let (lo, hi) = if dx < dy { (dx, dy) } else { (dy, dx) };
    f64::from(hi - lo) + SQRT_2 * f64::from(lo)
}

/// The Manhattan distance `dx + dy`: the shortest 4-connected path length on an empty grid.
#[inline]
pub fn manhattan(dx: u32, dy: u32) -> Cost {
    f64::from(dx) + f64::from(dy)
}

/// The Euclidean distance `sqrt(dx² + dy²)`, a lower bound for any grid connectivity. The
/// squares of cell offsets are exact in `f64` (below 2^53 for grids under 67 million cells a
/// side), so the plain square root is the correctly rounded distance, at a fraction of
/// `hypot`'s time (which guards against overflow that cannot happen here).
#[inline]
pub fn euclidean(dx: u32, dy: u32) -> Cost {
    let (x, y) = (f64::from(dx), f64::from(dy));
    (x * x + y * y).sqrt()
}
