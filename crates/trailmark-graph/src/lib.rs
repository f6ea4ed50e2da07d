//! Graph builders: turn a world into a graph that every `trailmark-search` algorithm can search.
//!
//! Grid graphs ([`GridGraph`]): 4- or 8-connected, with per-cell costs and a choice of
//! corner-cutting rule. Roadmaps of polygon worlds: visibility graphs ([`VisibilityGraph`]) by
//! Lee's rotational sweep with exact predicates, trapezoidal cell decompositions
//! ([`Trapezoids`]), all queried through [`RoadmapQuery`] (as `trailmark-sample`'s probabilistic
//! roadmap of a polygon world is, through the same [`Roadmap`] trait); and
//! roadmaps of worlds whose obstacles change, with stable node ids and the changed edges for
//! D* Lite ([`DynamicRoadmap`]). The graphs implement the traits of [`trailmark_core::graph`];
//! no builder here runs a search.
//!
//! Every item is documented at the crate root; the module paths
//! (`trailmark_graph::visibility::VisibilityGraph`) still work, hidden, for one release.
//!
//! **Features.** `roadmaps` (on by default) brings everything over polygon worlds and state
//! spaces: the visibility graph, trapezoidal cells, [`Roadmap`] and the dynamic
//! roadmap, with parry2d beneath them. Without it
//! (`default-features = false`) the crate is the grid graphs alone ([`GridGraph`],
//! [`CornerGraph`]) on `trailmark-core`'s light build: 14 crates with `trailmark-search`, see
//! the search guide's "A light build".
//!
//! ```
//! use trailmark_core::{Cell, Connectivity, Grid, IndexedGraph, Successors};
//! use trailmark_graph::GridGraph;
//!
//! let grid = Grid::from_rows(&["...", ".@.", "..."])?;
//! let graph = GridGraph::new(&grid, Connectivity::Eight);
//!
//! // The centre is blocked, so the top-middle cell reaches its two side neighbours only.
//! let mut next = Vec::new();
//! graph.for_each_successor(Cell::new(1, 0), |cell, cost| next.push((cell, cost)));
//! assert_eq!(next, [(Cell::new(2, 0), 1.0), (Cell::new(0, 0), 1.0)]);
//!
//! // Dense node indices let algorithms keep their state in vectors.
//! assert_eq!(graph.node_at(graph.index_of(Cell::new(2, 2))), Cell::new(2, 2));
//! # Ok::<(), trailmark_core::GridError>(())
//! ```

#![deny(missing_docs)]

// One documented path per item: the root. The modules stay public, hidden, for one release.
mod corners;
#[cfg(feature = "roadmaps")]
#[doc(hidden)]
pub mod dynamic;
#[doc(hidden)]
pub mod grid;
#[cfg(feature = "roadmaps")]
#[doc(hidden)]
pub mod roadmap;
mod sight;
mod squares;
#[cfg(feature = "roadmaps")]
#[doc(hidden)]
pub mod trapezoid;
#[cfg(feature = "roadmaps")]
#[doc(hidden)]
pub mod visibility;

pub use corners::CornerGraph;
#[cfg(feature = "roadmaps")]
pub use dynamic::{DynamicError, DynamicRoadmap, NodeKey, Rebuild};
pub use grid::{CornerCutting, GridGraph, Neighbours};
#[cfg(feature = "roadmaps")]
pub use roadmap::{Roadmap, RoadmapQuery};
#[cfg(feature = "roadmaps")]
pub use trapezoid::{Portal, Side, Trapezoid, TrapezoidError, TrapezoidQuery, Trapezoids};
#[cfg(feature = "roadmaps")]
pub use visibility::{
    BoundedVisibility, Edges, LazyVisibilityGraph, VisibilityError, VisibilityGraph, VisibilityQuery,
};
