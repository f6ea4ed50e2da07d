//! The worlds of a problem document, read and checked where they enter: grids, ROS maps, box
//! worlds and robot worlds (a polygon world is made by its spec, `WorldSpec::Polygons`), and the start and goal
//! named in each one's terms. Every planner family reads its world here.

pub mod boxes;
pub mod grid;
pub mod robot;
pub mod ros_map;
