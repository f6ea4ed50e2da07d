//! Worlds the planners come with, checked exactly: boxes in `N` dimensions, and a planar arm
//! among polygons.

pub mod arm;
pub mod boxes;
