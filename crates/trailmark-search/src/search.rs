//! The old path of the search workspace (`trailmark_search::search::Search`), kept working for
//! one release: the items live at the crate root.

#![allow(deprecated)]

use crate::index::Dense;

/// Moved: the reusable search workspace.
#[deprecated(since = "0.2.0", note = "use trailmark_search::Search")]
pub type Search<I = Dense> = crate::one_shot::workspace::Search<I>;

/// Moved: the outcome of a search.
#[deprecated(since = "0.2.0", note = "use trailmark_search::SearchResult")]
pub type SearchResult<N> = crate::one_shot::SearchResult<N>;

/// Moved: the most node slots a search supports.
#[deprecated(since = "0.2.0", note = "use trailmark_search::MAX_NODES")]
pub const MAX_NODES: usize = crate::limits::MAX_NODES;
