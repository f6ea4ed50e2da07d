//! Search algorithms over any graph that implements the traits of
//! [`trailmark_core::graph`]: breadth-first, depth-first, Dijkstra, A* and weighted A*; the
//! incremental planners [`LpaStar`] and [`DStarLite`], which repair their search after edge
//! costs change (and, for D* Lite, as the robot moves); the anytime planners [`ara_star`] and
//! [`AdStar`], which return an inflated solution fast and improve it while time allows; and the
//! indexed priority queue they all share.
//!
//! Each algorithm is a function (`astar(&graph, start, goal, heuristic)`) and a method of a
//! reusable [`Search`] workspace, which keeps its per-node state in dense vectors across queries.
//! Every search returns the path (or `None` when the goal is unreachable), its cost and
//! [`SearchStats`]; a query that cannot be answered (start outside the graph, a negative edge
//! cost, a weight above [`MAX_WEIGHT`], a path whose cost exceeds the largest `f64`) is a
//! [`SearchError`], never a panic, a hang or a false "no path".
//!
//! ```
//! use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
//! use trailmark_graph::GridGraph;
//! use trailmark_search::{astar, dijkstra};
//!
//! let grid = Grid::from_rows(&[
//!     "........",
//!     ".@@@@@@.",
//!     "......@.",
//!     ".@@@@.@.",
//!     "........",
//! ])?;
//! let graph = GridGraph::new(&grid, Connectivity::Eight);
//! let (start, goal) = (Cell::new(2, 2), Cell::new(7, 4));
//!
//! let found = astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
//! let path = found.path.expect("the goal is reachable");
//! assert_eq!((path.start(), path.goal()), (Some(start), Some(goal)));
//!
//! // A* with an admissible heuristic finds the same cost as Dijkstra, expanding fewer nodes.
//! let reference = dijkstra(&graph, start, goal)?;
//! assert_eq!(reference.cost(), Some(path.cost));
//! assert!(found.stats.expansions <= reference.stats.expansions);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Graphs that cannot number their nodes use a hashing workspace:
//!
//! ```
//! use trailmark_core::graph::{Graph, Successors};
//! use trailmark_search::Search;
//!
//! /// The integers, each linked to its double and its successor.
//! struct Numbers;
//! impl Graph for Numbers {
//!     type Node = u64;
//!     fn contains(&self, _: u64) -> bool { true }
//! }
//! impl Successors for Numbers {
//!     fn for_each_successor<F: FnMut(u64, f64)>(&self, n: u64, mut visit: F) {
//!         visit(n + 1, 1.0);
//!         visit(2 * n, 1.0);
//!     }
//! }
//! let found = Search::hashed().bfs(&Numbers, 1, 100)?;
//! assert_eq!(found.path.unwrap().nodes, [1, 2, 3, 6, 12, 24, 25, 50, 100]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

mod ad_star;
mod ara_star;
mod astar;
mod bfs;
mod dfs;
mod dstar_lite;
pub mod error;
pub mod index;
mod lifelong;
mod lpa_star;
pub mod queue;
pub mod search;
pub mod stats;

pub use ad_star::{AdStar, DEFAULT_RAISE_THRESHOLD};
pub use ara_star::{
    AnytimeResult, Budget, EpsilonSchedule, Iteration, MAX_EPSILON, MAX_ITERATIONS, Stop, ara_star,
};
pub use astar::{MAX_WEIGHT, astar, dijkstra, weighted_astar};
pub use bfs::bfs;
pub use dfs::dfs;
pub use dstar_lite::DStarLite;
pub use error::SearchError;
pub use index::{Dense, Hashed, NodeIndex};
pub use lifelong::{Consistency, EdgeChange, Expansion, Key};
pub use lpa_star::LpaStar;
pub use queue::IndexedHeap;
pub use search::{Search, SearchResult};
pub use stats::SearchStats;
