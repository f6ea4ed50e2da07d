//! The tree planners' settings, and their check.

use crate::plan::PlanError;
use crate::space::StateSpace;

/// The settings of the tree planners (RRT, RRT-Connect, RRT*).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RrtOptions {
    /// The longest motion added at once (default: 0.2 x the space's extent, as OMPL; at least
    /// [`MIN_RELATIVE_RANGE`] of it).
    pub range: Option<f64>,
    /// RRT and RRT*: the probability of steering toward a state of the goal (default 0.05).
    pub goal_bias: f64,
}

impl Default for RrtOptions {
    fn default() -> Self {
        RrtOptions { range: None, goal_bias: 0.05 }
    }
}

/// The shortest `range` a planner takes, as a share of the space's extent: 1e-4, so that one
/// connect phase of [`MAX_CONNECT_STEPS`](crate::MAX_CONNECT_STEPS) can cross the
/// space. Shorter steps only pile up states (a range of 1e-8 of a world had made RRT-Connect
/// run for minutes, its trees millions of states along lines).
pub const MIN_RELATIVE_RANGE: f64 = 1e-4;

/// The range of the tree planners' motions, checked.
pub(crate) fn checked_range<S: StateSpace>(space: &S, options: &RrtOptions) -> Result<f64, PlanError> {
    let range = options.range.unwrap_or(0.2 * space.extent());
    if !(range.is_finite() && range > 0.0) {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "positive and finite",
            value: range,
        });
    }
    if range < MIN_RELATIVE_RANGE * space.extent() {
        return Err(PlanError::InvalidOption {
            name: "range",
            expected: "at least 1e-4 of the space's extent (MIN_RELATIVE_RANGE)",
            value: range,
        });
    }
    if !(0.0..=1.0).contains(&options.goal_bias) {
        let value = options.goal_bias;
        return Err(PlanError::InvalidOption { name: "goal_bias", expected: "in [0, 1]", value });
    }
    Ok(range)
}
