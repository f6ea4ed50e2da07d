//! The vocabulary shared by every trailmark crate: geometry, costs, graph traits, grids,
//! polygon worlds and their free space, Dubins and Reeds-Shepp curves, MovingAI benchmark files, SVG
//! pictures, and when a long-running planner stops ([`termination`]).
//!
//! Algorithms (`trailmark-search`) and graph builders (`trailmark-graph`) both depend on this
//! crate and never on each other; a graph of your own that implements the traits of [`graph`]
//! works with every algorithm.
//!
//! **Features.** `geometry` (on by default) brings the modules of points and shapes:
//! `geometry`, `world`, `freespace`, `footprint`, `predicates`, `dubins`, `reeds_shepp`,
//! `curve`, `smooth`, `generate` and `svg`, on nalgebra, parry2d, geo, robust and rand. Without
//! it (`default-features = false`) the crate is [`cost`], [`graph`], [`grid`], [`path`],
//! [`movingai`], [`read`], [`termination`] and [`union_find`], on serde and thiserror alone:
//! what grid search needs, and what `trailmark-search` takes.
//!
//! ```
//! use trailmark_core::grid::{Cell, Grid};
//! use trailmark_core::movingai::parse_map;
//! use trailmark_core::svg::GridSvg;
//!
//! // A MovingAI map, read from text (CRLF line ends are fine).
//! let grid = parse_map("type octile\r\nheight 3\r\nwidth 5\r\nmap\r\n.....\r\n.@@@.\r\n.....\r\n")?;
//! assert!(grid.is_passable(Cell::new(0, 1)) && !grid.is_passable(Cell::new(2, 1)));
//!
//! // A picture of it with a path drawn through cell centres.
//! let path = [Cell::new(0, 2), Cell::new(0, 1), Cell::new(1, 0), Cell::new(4, 0)];
//! let svg = GridSvg::new(&grid).path(&path).to_svg();
//! assert!(svg.contains("polyline"));
//! # Ok::<(), trailmark_core::movingai::ParseError>(())
//! ```

#![deny(missing_docs)]

pub mod cost;
#[cfg(feature = "geometry")]
pub mod curve;
#[cfg(feature = "geometry")]
pub mod dubins;
#[cfg(feature = "geometry")]
pub mod footprint;
#[cfg(feature = "geometry")]
pub mod freespace;
#[cfg(feature = "geometry")]
pub mod generate;
#[cfg(feature = "geometry")]
pub mod geometry;
pub mod graph;
pub mod grid;
pub mod movingai;
pub mod path;
#[cfg(feature = "geometry")]
pub mod predicates;
pub mod read;
#[cfg(feature = "geometry")]
pub mod reeds_shepp;
#[cfg(feature = "geometry")]
pub mod smooth;
#[cfg(feature = "geometry")]
pub mod svg;
pub mod termination;
pub mod union_find;
#[cfg(feature = "geometry")]
pub mod world;
#[cfg(feature = "yaml")]
pub mod yaml;

// One documented path per item: the vocabulary's families above (`grid::Cell`,
// `graph::Successors`). The everyday names stay usable from the root, undocumented there.
#[doc(hidden)]
pub use cost::Cost;
#[doc(hidden)]
pub use graph::{EdgeChange, Graph, IndexedGraph, Lines, Predecessors, Successors};
#[doc(hidden)]
pub use grid::{Cell, Connectivity, CornerCutting, Grid, GridError, GridHeuristic};
#[doc(hidden)]
pub use path::Path;
#[doc(hidden)]
pub use termination::{Stop, Termination};
#[doc(hidden)]
pub use union_find::UnionFind;
