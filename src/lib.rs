//! trailmark: motion planning in Rust. Grid, roadmap and sampling planners that share one
//! vocabulary, and a benchmark harness that measures them all.
//!
//! This facade re-exports every trailmark crate; depend on the crates one by one to take only
//! what you use:
//!
//! | module | crate | what it holds |
//! |---|---|---|
//! | [`core`] | `trailmark-core` | geometry, costs, graph traits, grids, MovingAI files, JSON, SVG |
//! | [`graph`] | `trailmark-graph` | builders from a world to a graph: grid graphs, visibility graphs, trapezoidal cells, roadmaps of changing worlds |
//! | [`search`] | `trailmark-search` | BFS, DFS, Dijkstra, A*, weighted A*, ARA*; LPA*, D* Lite, AD*; indexed priority queue |
//! | [`space`] | `trailmark-space` | configuration spaces (R², Rⁿ, SE(2), Dubins, Reeds-Shepp, your own), validity, samplers, exact nearest neighbours, connection rules |
//! | [`sample`] | `trailmark-sample` | sampling planners: RRT, RRT-Connect, RRT*, PRM over any space of [`space`]; the PRM roadmap of a polygon world (Dubins and Reeds-Shepp roadmaps too); path shortcutting |
//! | [`contingency`] | `trailmark-contingency` | contingency route planning over choke points that may be blocked |
//! | [`map`] | `trailmark-map` | robot maps: ROS map_server files and `nav_msgs/OccupancyGrid`, map frames in metres, Nav2-style costmaps and inflation |
//! | [`car`] | `trailmark-car` | car-like robots: footprints checked on a costmap's cells, Hybrid A* with Reeds-Shepp or Dubins shots |
//! | [`robot`] | `trailmark-robot` | robot arms in 3-D: URDF and SRDF, MoveIt scenes and requests, sphere collision checks, a group's joint space for the sampling planners |
//!
//! ```
//! use trailmark::prelude::*;
//!
//! let grid = Grid::from_rows(&[
//!     ".....",
//!     ".@@@.",
//!     ".....",
//! ])?;
//! let graph = GridGraph::new(&grid, Connectivity::Eight);
//! let (start, goal) = (Cell::new(0, 1), Cell::new(4, 1));
//! let found = astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
//! let path = found.path.expect("reachable");
//! assert_eq!(path.cost, 6.0); // over the wall: no diagonal move may clip a blocked corner
//! println!("{} moves, cost {:.3}, {} expansions", path.moves(), path.cost, found.stats.expansions);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

pub mod navigate;
pub mod solve;

pub use trailmark_car as car;
pub use trailmark_contingency as contingency;
pub use trailmark_core as core;
pub use trailmark_graph as graph;
pub use trailmark_map as map;
pub use trailmark_robot as robot;
pub use trailmark_sample as sample;
pub use trailmark_search as search;
pub use trailmark_space as space;

// Second paths of core modules, kept for one release; `trailmark::core::movingai` and
// `trailmark::core::svg` are the paths.
#[doc(hidden)]
pub use trailmark_core::{movingai, svg};

/// The README's example, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The code of the guide's page on car-like robots, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../docs/car.md")]
pub struct CarDoctests;

/// The code of the guide's page on navigation, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../docs/navigation.md")]
pub struct NavigationDoctests;

/// The code of the guide's page on ROS maps, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../docs/ros-maps.md")]
pub struct RosMapsGuideDoctests;

/// The code of the guide's page on robot arms, compiled as a doc test (it reads the shared data).
#[cfg(doctest)]
#[doc = include_str!("../docs/arms.md")]
pub struct ArmsGuideDoctests;

/// The code of the guide's page on jump point search, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../docs/jump-points.md")]
pub struct JumpPointsGuideDoctests;

/// The code of the page for users of the `pathfinding` crate, run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../docs/from-pathfinding.md")]
pub struct FromPathfindingDoctests;

/// The names most programs need: `use trailmark::prelude::*;`.
pub mod prelude {
    pub use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
    pub use trailmark_core::grid::{Cell, Connectivity, Grid, GridHeuristic};
    pub use trailmark_core::termination::{Stop, Termination};
    pub use trailmark_core::{Cost, Path};
    pub use trailmark_graph::{CornerCutting, GridGraph};
    pub use trailmark_search::{
        AdStar, DStarLite, EdgeChange, EpsilonSchedule, Jps, JpsPlus, LpaStar, Search, SearchError,
        SearchResult, ara_star, astar, bfs, dfs, dijkstra, jps, weighted_astar,
    };
}
