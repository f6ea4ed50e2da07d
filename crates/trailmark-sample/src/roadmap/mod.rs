//! The roadmap planners: multi-query roadmaps over any space, queried with A*.

pub mod prm;
