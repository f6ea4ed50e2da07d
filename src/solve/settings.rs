//! The settings of a planner's family in a problem document: the anytime searches'
//! ([`AnytimeSpec`]), Hybrid A*'s ([`HybridSpec`]) and the sampling planners' ([`SamplingSpec`],
//! with their [`SamplerSpec`]); [`PlannerSpec`](super::PlannerSpec) holds one per variant.
//! Every optional setting carries the same serde attribute (absent in a document: the
//! default; `None`: not written back).

use std::time::Duration;

use serde::{Deserialize, Serialize};
use trailmark_car::HybridOptions;
use trailmark_core::grid::GridHeuristic;
use trailmark_core::smooth::Smoothing;
use trailmark_core::termination::Termination;
use trailmark_search::EpsilonSchedule;

use super::stop::stoppable;

/// The settings of an anytime search (ARA*, AD*). Each has a default.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnytimeSpec {
    /// The initial inflation (default 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub epsilon: Option<f64>,
    /// The decrease per iteration (default 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub epsilon_step: Option<f64>,
    /// The heuristic (default as for A*).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heuristic: Option<GridHeuristic>,
    /// Stop after this many seconds (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_limit_s: Option<f64>,
    /// Stop after this many expansions (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_expansions: Option<u64>,
}

impl AnytimeSpec {
    /// The inflation schedule, with the library's defaults.
    pub(crate) fn schedule(&self) -> EpsilonSchedule {
        let default = EpsilonSchedule::default();
        EpsilonSchedule::new(
            self.epsilon.unwrap_or(default.initial),
            self.epsilon_step.unwrap_or(default.step),
        )
    }

    /// The limits of the search.
    pub(crate) fn budget(&self) -> Termination {
        // Checked by solve: a limit too large for a Duration has been refused already.
        let time = self.time_limit_s.and_then(|t| Duration::try_from_secs_f64(t).ok());
        let budget =
            Termination { time_limit: time, max_expansions: self.max_expansions, ..Termination::default() };
        stoppable(budget, None)
    }
}

/// The settings of Hybrid A*: `turning_radius` (metres) is required, the others default to
/// Nav2 Smac Hybrid-A*'s (see [`HybridOptions`]); the footprint to the world's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HybridSpec {
    /// The smallest turning radius, in metres.
    pub turning_radius: f64,
    /// Headings told apart (default 72).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heading_bins: Option<u32>,
    /// Whether the car may reverse (default true).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reverse: Option<bool>,
    /// The cost of a metre in reverse over one forward (default 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reverse_penalty: Option<f64>,
    /// The cost of a metre turning over one straight (default 1.2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub non_straight_penalty: Option<f64>,
    /// Added at each change of gear, in metres (default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gear_change_penalty: Option<f64>,
    /// Whether the path is smoothed (default true).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smooth: Option<bool>,
    /// The robot's polygon `[[x, y], ...]` in metres about its reference point, x forward
    /// (default: on ROS maps the world's `footprint`, else a disc of its `robot_radius`; on
    /// polygon worlds a disc of the world's `robot_radius`; on grids a point).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub footprint: Option<Vec<[f64; 2]>>,
    /// The width of a cell in metres: on grid worlds, of the grid's cells (default 1); on
    /// polygon worlds, of the cells the obstacles are laid on (default an eighth of the
    /// turning radius). ROS maps give their own.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resolution: Option<f64>,
    /// Stop after this many seconds (default 5, Smac's `max_planning_time`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_limit_s: Option<f64>,
    /// Stop after this many expansions (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_expansions: Option<u64>,
}

impl HybridSpec {
    /// Smac's defaults where the document says nothing.
    pub(crate) fn settings(&self) -> HybridOptions {
        let d = HybridOptions::default();
        HybridOptions {
            turning_radius: self.turning_radius,
            heading_bins: self.heading_bins.unwrap_or(d.heading_bins),
            reverse: self.reverse.unwrap_or(d.reverse),
            reverse_penalty: self.reverse_penalty.unwrap_or(d.reverse_penalty),
            non_straight_penalty: self.non_straight_penalty.unwrap_or(d.non_straight_penalty),
            gear_change_penalty: self.gear_change_penalty.unwrap_or(d.gear_change_penalty),
            smooth: self.smooth.unwrap_or(d.smooth),
            ..d
        }
    }

    /// The limits of the search.
    pub(crate) fn termination(&self) -> Termination {
        // Checked by solve: a limit too large for a Duration has been refused already.
        let time = Duration::try_from_secs_f64(self.time_limit_s.unwrap_or(5.0)).ok();
        let limits =
            Termination { time_limit: time, max_expansions: self.max_expansions, ..Termination::default() };
        stoppable(limits, None)
    }
}

/// The settings of a sampling planner (RRT, RRT-Connect, RRT*, Informed RRT*, BIT*, PRM, PRM*,
/// Lazy PRM, Lazy PRM*).
/// Each has a default.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SamplingSpec {
    /// The tree planners: the longest motion added at once (default 0.2 x the space's extent);
    /// refused by BIT* and the roadmaps.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<f64>,
    /// RRT, RRT* and Informed RRT*: the probability of steering toward the goal (default 0.05);
    /// refused by BIT* and the roadmaps.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_bias: Option<f64>,
    /// Stop after this many iterations, samples drawn (default 10,000 unless `time_limit_s` is
    /// given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<u64>,
    /// Stop after this many seconds (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_limit_s: Option<f64>,
    /// Shortcut the path afterwards (default false).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simplify: Option<bool>,
    /// `r2` only: smooth the (simplified) path with `hermite`, `bezier` or `bspline` curves,
    /// reported beside it (default: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub smooth: Option<Smoothing>,
    /// Where samples are drawn (default: uniformly).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<SamplerSpec>,
}

/// Where a sampling planner draws the states it steers toward. In JSON, an object whose
/// `"name"` selects the sampler; the two that look for obstacles take `"std_dev"` (required:
/// the distance between the two states tested, about the width of the passages sought),
/// `"share"` (default 0.5) and `"attempts"` (default 100).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", rename_all = "snake_case", deny_unknown_fields)]
pub enum SamplerSpec {
    /// Uniformly over the space. (A struct variant, so that unknown fields beside its name
    /// are refused as for the others.)
    Uniform {},
    /// The bridge test: free midpoints of two nearby states in collision (narrow passages).
    Bridge {
        /// The partner's standard deviation.
        std_dev: f64,
        /// The probability of a bridge sample rather than a uniform one.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        share: Option<f64>,
        /// Tries before a uniform sample.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        attempts: Option<u32>,
    },
    /// Free states beside states in collision (near obstacles' surfaces).
    Gaussian {
        /// The partner's standard deviation.
        std_dev: f64,
        /// The probability of such a sample rather than a uniform one.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        share: Option<f64>,
        /// Tries before a uniform sample.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        attempts: Option<u32>,
    },
}

impl Default for SamplerSpec {
    fn default() -> Self {
        SamplerSpec::Uniform {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every sampler refuses a field it does not take, the uniform one included.
    #[test]
    fn samplers_refuse_unknown_fields() {
        let spec =
            |sampler: &str| serde_json::from_str::<SamplingSpec>(&format!(r#"{{"sampler": {sampler}}}"#));
        assert_eq!(spec(r#"{"name": "uniform"}"#).unwrap().sampler, Some(SamplerSpec::Uniform {}));
        for sampler in [
            r#"{"name": "uniform", "std_dev": 2}"#,
            r#"{"name": "uniform", "surprise": true}"#,
            r#"{"name": "bridge", "std_dev": 2, "surprise": true}"#,
            r#"{"name": "gaussian", "std_dev": 2, "surprise": true}"#,
        ] {
            assert!(spec(sampler).is_err(), "{sampler}");
        }
    }
}
