//! Search algorithms over any graph that implements the traits of [`trailmark_core::graph`],
//! in three families:
//!
//! - **one-shot searches** answer one query from scratch: [`bfs`], [`dfs`], [`dijkstra`],
//!   [`astar`], [`weighted_astar`] and the any-angle [`theta_star`], each a function and a method of the reusable [`Search`]
//!   workspace, which keeps its per-node state in dense vectors across queries, returning a
//!   [`SearchResult`]; and on uniform-cost grids, jump point search ([`Jps`], [`jps`]);
//! - **anytime searches** return an inflated solution fast and improve it while their
//!   [`Termination`](trailmark_core::termination::Termination) allows: [`ara_star`] and
//!   [`AdStar`], with an [`EpsilonSchedule`], reporting every [`Iteration`] in an
//!   [`AnytimeResult`];
//! - **incremental searches** repair their last search after edge costs change
//!   ([`EdgeChange`]): [`LpaStar`], and [`DStarLite`], which also follows a robot that moves;
//!   [`AdaptiveAStar`] and [`MpgaaStar`] search forward from the robot at every plan, guided by
//!   what earlier plans learned (MPGAA* also reuses their paths). [`Replanner`] is the one
//!   interface of the planners kept between plans (these, AD*, and [`RepeatedAStar`], A* from
//!   scratch at every plan, the baseline), so a program picks one at run time
//!   (`Box<dyn Replanner<G>>`) or compares them on the same changes.
//!
//! Shared by all: [`SearchStats`], [`SearchError`], the node numbering ([`NodeIndex`]: [`Dense`]
//! or [`Hashed`]) and the indexed priority queue [`IndexedHeap`]. Every search returns the path
//! (or `None` when the goal is unreachable), its cost and its statistics; a query that cannot be
//! answered (start outside the graph, a negative edge cost, a weight above [`MAX_WEIGHT`], a path
//! whose cost exceeds the largest `f64`) is a [`SearchError`], never a panic, a hang or a false
//! "no path". Every item is at the crate root.
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
//!
//! # Anytime searches
//!
//! [`ara_star`] and [`AdStar::improve`] stop when a
//! [`Termination`](trailmark_core::termination::Termination) says so, the vocabulary the sampling
//! planners of `trailmark-sample` share, and report why as a
//! [`Stop`](trailmark_core::termination::Stop). They honour its iteration limit (improvement
//! iterations, one per inflation, completed in the call), expansion limit (checked at every
//! expansion), time limit and condition (asked every 256 expansions and between iterations) and
//! target cost (between iterations). Without any limit they run until the path is optimal.

#![deny(missing_docs)]

mod anytime;
#[doc(hidden)]
pub mod error;
mod heuristic;
mod incremental;
#[doc(hidden)]
pub mod index;
mod limits;
mod one_shot;
mod priority;
#[doc(hidden)]
pub mod queue;
#[doc(hidden)]
pub mod stats;

pub use anytime::ad_star::{AdStar, DEFAULT_RAISE_THRESHOLD};
pub use anytime::ara_star::ara_star;
pub use anytime::{AnytimeResult, EpsilonSchedule, Iteration};
pub use error::SearchError;
pub use heuristic::{Heuristic, ReadsGraph};
pub use incremental::adaptive_astar::{AdaptiveAStar, AdaptivePlanner, LearnOnly, Memory};
pub use incremental::all_pairs::AllPairs;
pub use incremental::dstar_lite::{CostsToGoal, DStarLite};
pub use incremental::lifelong::{Costs, Lifelong};
pub use incremental::lpa_star::{CostsFromStart, LpaStar};
pub use incremental::mpgaa_star::{MpgaaStar, ReusePaths};
pub use incremental::repeated_astar::RepeatedAStar;
pub use incremental::replanner::Replanner;
pub use incremental::{Consistency, EdgeChange, Expansion, Key};
pub use index::{Dense, Hashed, NodeIndex};
pub use limits::{MAX_EPSILON, MAX_ITERATIONS, MAX_NODES, MAX_PAIRS, MAX_WEIGHT};
pub use one_shot::SearchResult;
pub use one_shot::astar::{astar, dijkstra, weighted_astar};
pub use one_shot::closures;
pub use one_shot::jps::{Jps, jps};
pub use one_shot::jps_plus::JpsPlus;
pub use one_shot::theta_star::theta_star;
pub use one_shot::uninformed::{bfs, dfs};
pub use one_shot::workspace::Search;
pub use queue::IndexedHeap;
pub use stats::SearchStats;
