//! Sampling-based planners for continuous spaces: RRT, RRT-Connect and RRT* over pluggable state
//! spaces (R², Rⁿ, SE(2), Dubins), with exact collision checks and seeded, reproducible runs.
//!
//! **Status: planned.** This crate reserves its place in the workspace; its planners arrive in a
//! later release. Until then it exports only the names of the planners it will provide, so that
//! code and documentation can refer to them.
//!
//! ```
//! use trailmark_sample::PlannerKind;
//!
//! assert_eq!(PlannerKind::ALL.len(), 3);
//! assert_eq!(PlannerKind::RrtConnect.name(), "rrt_connect");
//! ```

#![deny(missing_docs)]

/// The sampling planners this crate will provide.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlannerKind {
    /// Rapidly-exploring random tree (LaValle 1998).
    Rrt,
    /// Two trees grown toward each other (Kuffner and LaValle 2000).
    RrtConnect,
    /// Asymptotically optimal RRT with rewiring (Karaman and Frazzoli 2011).
    RrtStar,
}

impl PlannerKind {
    /// Every planner, in the order above.
    pub const ALL: [PlannerKind; 3] = [PlannerKind::Rrt, PlannerKind::RrtConnect, PlannerKind::RrtStar];

    /// The planner's name in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            PlannerKind::Rrt => "rrt",
            PlannerKind::RrtConnect => "rrt_connect",
            PlannerKind::RrtStar => "rrt_star",
        }
    }
}
