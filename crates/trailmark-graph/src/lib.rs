//! Graph builders: turn a world into a graph that every `trailmark-search` algorithm can search.
//!
//! Grid graphs ([`grid::GridGraph`]): 4- or 8-connected, with per-cell costs and a choice of
//! corner-cutting rule. Roadmaps of polygon worlds: visibility graphs
//! ([`visibility::VisibilityGraph`]) by Lee's rotational sweep with exact predicates, trapezoidal
//! cell decompositions ([`trapezoid::Trapezoids`]), probabilistic roadmaps over the state spaces
//! of `trailmark-sample` (segments in `R2`, Dubins curves, ...) ([`prm::Prm`]), all queried
//! through [`roadmap::RoadmapQuery`]; and roadmaps of worlds whose obstacles change, with stable
//! node ids and the changed edges for D* Lite ([`dynamic::DynamicRoadmap`]). The graphs
//! implement the traits of [`trailmark_core::graph`]; no builder here runs a search.
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

pub mod dynamic;
pub mod grid;
pub mod prm;
pub mod roadmap;
pub mod trapezoid;
pub mod visibility;

pub use dynamic::{DynamicError, DynamicRoadmap};
pub use grid::{CornerCutting, GridGraph, Neighbours};
pub use prm::{Connection, DubinsPrm, PlanarSpace, Prm, PrmError, PrmOptions, PrmQuery, Sampler};
pub use roadmap::{Roadmap, RoadmapQuery};
pub use trapezoid::{TrapezoidError, TrapezoidQuery, Trapezoids};
pub use visibility::{VisibilityGraph, VisibilityQuery};
