//! One-shot searches: breadth-first, depth-first, Dijkstra, A*, weighted A*, Theta* and jump point
//! search ([`Jps`](crate::Jps), on uniform-cost grids), each a function
//! and a method of the reusable [`Search`](crate::Search) workspace, answering one query from
//! scratch with a [`SearchResult`].
//!
//! What they share lives here: the workspace (`workspace`: per-node state in dense vectors,
//! generation stamps, the open lists), the best-first priority key (`key`) and the check of the
//! edge costs a search meets (`edges`).

use trailmark_core::cost::Cost;
use trailmark_core::path::Path;

use crate::stats::SearchStats;

pub(crate) mod astar;
pub mod closures;
pub(crate) mod edges;
pub(crate) mod jps;
pub(crate) mod jps_plus;
pub(crate) mod jump_map;
pub(crate) mod jump_search;
pub(crate) mod key;
pub(crate) mod theta_star;
pub(crate) mod uninformed;
pub(crate) mod workspace;

/// The outcome of a search: a path (or `None` when the goal is unreachable) and statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchResult<N> {
    /// The path found, start first; `None` when no path exists.
    pub path: Option<Path<N>>,
    /// What the search did.
    pub stats: SearchStats,
}

impl<N> SearchResult<N> {
    /// The cost of the path, if one was found.
    pub fn cost(&self) -> Option<Cost> {
        self.path.as_ref().map(|p| p.cost)
    }
}
