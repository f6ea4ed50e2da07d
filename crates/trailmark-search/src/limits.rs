//! The largest inputs a search accepts: beyond them a query is refused with a
//! [`SearchError`](crate::SearchError) rather than run with a meaningless or overflowing value.

/// The most node slots a search supports.
pub const MAX_NODES: usize = u32::MAX as usize - 2;

/// The largest heuristic weight [`weighted_astar`](crate::weighted_astar()) accepts, 1e6 (also
/// the largest initial inflation of the anytime planners, [`MAX_EPSILON`]).
///
/// At a weight of 1e6 the heuristic already outweighs path cost a million to one: the search
/// orders nodes as greedy best-first search does (by `h` alone) except between nodes whose `h`
/// differ by less than a millionth of their `g` difference, and the proven bound, a million
/// times the least cost, says nothing any more. A larger weight changes nothing a user could
/// want, and brings `w h` toward the largest `f64` (beyond it, `w h` would be `+inf`, which
/// means a dead end): refusing it keeps a typo such as 1e308 from silently making every node
/// look unreachable.
pub const MAX_WEIGHT: f64 = 1e6;

/// The most iterations an inflation schedule may ask for.
pub const MAX_ITERATIONS: usize = 10_000;

/// The largest initial inflation an anytime planner accepts: [`MAX_WEIGHT`], 1e6, for the same
/// reasons (an inflation is a heuristic weight). An inflation that large makes the first
/// iteration a greedy search; a larger one only brings `ε h` toward overflow.
pub const MAX_EPSILON: f64 = MAX_WEIGHT;

/// The most distances an `AllPairs` table holds (sources x nodes): 2^27, a
/// gibibyte of `f64`s.
pub const MAX_PAIRS: usize = 1 << 27;
