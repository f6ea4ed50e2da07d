//! The roadmap planners: multi-query roadmaps over any space, queried with A*; and the roadmap of
//! a polygon world that changes, built on the same [`Prm`](prm::Prm).

mod graph;
mod lazy;
pub mod polygon;
pub mod prm;
