//! The termination vocabulary's old place: it lives in `trailmark_core::termination`, shared
//! with the anytime searches. These names keep working for one release.

/// Moved: when a planner gives up.
#[deprecated(since = "0.2.0", note = "use trailmark_core::termination::Termination")]
pub type Termination = trailmark_core::termination::Termination;

/// Moved: a user stopping condition.
#[deprecated(since = "0.2.0", note = "use trailmark_core::termination::Condition")]
pub type Condition = trailmark_core::termination::Condition;

/// Moved: how far a run has come.
#[deprecated(since = "0.2.0", note = "use trailmark_core::termination::Progress")]
pub type Progress = trailmark_core::termination::Progress;
