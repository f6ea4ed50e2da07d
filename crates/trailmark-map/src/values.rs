//! The cost values of Nav2's costmap_2d, which every costmap of trailmark keeps.

/// A free cell.
pub const FREE_SPACE: u8 = 0;
/// The largest cost of a cell the robot's centre may occupy.
pub const MAX_NON_OBSTACLE: u8 = 252;
/// Within the robot's inscribed radius of an obstacle: the robot collides.
pub const INSCRIBED: u8 = 253;
/// An obstacle.
pub const LETHAL: u8 = 254;
/// Unknown.
pub const NO_INFORMATION: u8 = 255;
