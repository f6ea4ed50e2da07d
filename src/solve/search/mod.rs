//! The graph searches of [`solve`](super::solve) (every planner of the registry but the
//! sampling planners and Hybrid A*), one file per world: cell to cell on grids and ROS maps, on
//! a roadmap of a polygon world (of points, or of car poses) or of a box world.

pub(super) mod boxes;
pub(super) mod car_roadmap;
pub(super) mod grid;
pub(super) mod polygons;
pub(super) mod roadmap;
pub(super) mod ros_map;
mod visibility;
