//! Navigation in partly known terrain: a robot senses, replans and moves until it reaches its
//! goal or proves it unreachable, with the planner of your choice.
//!
//! The robot lives on an 8-connected grid without corner cutting. It starts with a *prior* map
//! (often free space: every cell assumed passable) and, at each step, senses the true cells
//! within its sensor radius (a square window: radius 1 is the eight neighbours), folds what
//! differs into its map, replans from where it stands and moves one cell along the plan. Four
//! planners of the solve registry can drive it ([`Navigation::planner`]), on the same run:
//!
//! - `astar`: A* from scratch at every step;
//! - `lpa_star`: LPA*, restarted whenever the start moves (so at every step: a forward search
//!   cannot keep its values when its start moves);
//! - `dstar_lite`: D* Lite, which searches from the goal and repairs only what changed;
//! - `ad_star`: AD*, D* Lite with an inflated heuristic lowered as time allows.
//!
//! Two variations exercise the incremental planners harder: an obstacle that follows the robot
//! a few cells behind (cells block and free up during the run), and *greedy mapping*, where
//! there is no goal: every cell the robot has not visited is joined to a virtual goal, so the
//! robot keeps going to the nearest unvisited cell until it has visited every cell it can reach.
//!
//! ```
//! use trailmark::navigate::{Navigation, Target, navigate};
//! use trailmark::prelude::*;
//! use trailmark::solve::PlannerSpec;
//!
//! let truth = Grid::from_rows(&[
//!     "........",
//!     "....@...",
//!     "....@...",
//!     "....@...",
//!     "........",
//! ])?;
//! let prior = Grid::new(8, 5)?; // the robot assumes free space
//! let (start, goal) = (Cell::new(1, 2), Cell::new(7, 2));
//! let mut costs = Vec::new();
//! for planner in [PlannerSpec::AStar { heuristic: None }, PlannerSpec::DStarLite { heuristic: None }] {
//!     let config = Navigation { planner, ..Navigation::default() };
//!     let run = navigate(&truth, &prior, start, Target::Cell(goal), &config)?;
//!     assert!(run.reached());
//!     costs.push(run.distance);
//! }
//! assert_eq!(costs[0], costs[1]); // same decisions, different effort
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// Integer casts of user-derived values are checked conversions here, not silent truncation.
#![deny(clippy::cast_possible_truncation)]

mod config;
mod error;
mod graph;
mod report;
mod simulation;
mod world;

pub use config::{Navigation, Target};
pub use error::NavigateError;
pub use graph::{VIRTUAL_EDGE_COST, VIRTUAL_GOAL};
pub use report::{NavigationOutcome, NavigationReport};
pub use simulation::MAX_NAVIGATION_CELLS;
pub use simulation::{navigate, navigate_together};
