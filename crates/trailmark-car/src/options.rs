//! The settings of Hybrid A*: the car's turning radius, the heading resolution, which gears it
//! may use, and the penalties that shape its paths. The defaults are Nav2 Smac Hybrid-A*'s.

use serde::{Deserialize, Serialize};

use crate::error::CarError;

/// The largest number of heading bins accepted: a bin of a quarter degree.
pub const MAX_HEADING_BINS: u32 = 1440;

/// How Hybrid A* searches. Lengths are in the map's units (metres on a ROS map, cells on a
/// grid read with resolution 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HybridOptions {
    /// The smallest turning radius of the car's reference point. At least half a cell: a
    /// tighter turn would not leave its cell before its heading moved a bin.
    pub turning_radius: f64,
    /// How many headings the search tells apart (72: 5 degrees), from 4 to
    /// [`MAX_HEADING_BINS`], and enough that one bin's arc at the turning radius is at most
    /// [`MAX_MOTION_CELLS`](crate::MAX_MOTION_CELLS) cells (checked by
    /// [`HybridAStar::new`](crate::HybridAStar::new)).
    pub heading_bins: u32,
    /// Whether the car may drive in reverse (Reeds-Shepp shots to the goal); otherwise forward
    /// only (Dubins shots).
    pub reverse: bool,
    /// The cost of a metre driven in reverse, over one driven forward (at least 1).
    pub reverse_penalty: f64,
    /// The cost of a metre driven while turning, over one driven straight (at least 1).
    pub non_straight_penalty: f64,
    /// A cost added at every change of gear (a cusp), in the map's units (not negative).
    pub gear_change_penalty: f64,
    /// How often the search tries a curve straight to the goal: every `h / ratio` expansions,
    /// `h` the estimate to the goal in cells (Smac's `analytic_expansion_ratio`); positive.
    pub analytic_expansion_ratio: f64,
    /// The longest shot to the goal tried, in the map's units (Smac's
    /// `analytic_expansion_max_length`); positive.
    pub analytic_expansion_max_length: f64,
    /// Whether the path found is smoothed: runs of motions replaced by the car's shortest curve
    /// between their ends where that is free and cheaper (see [`HybridAStar`](crate::HybridAStar)).
    pub smooth: bool,
}

impl Default for HybridOptions {
    /// Nav2 Smac Hybrid-A*'s defaults: turning radius 0.4 m, 72 heading bins, reverse allowed
    /// with penalty 2, turning penalty 1.2, analytic shots every `h / 3.5` expansions up to
    /// 3 m. Smac has no penalty for a change of gear beyond the reverse penalty: 0. Paths are
    /// smoothed, as Smac smooths them.
    fn default() -> Self {
        HybridOptions {
            turning_radius: 0.4,
            heading_bins: 72,
            reverse: true,
            reverse_penalty: 2.0,
            non_straight_penalty: 1.2,
            gear_change_penalty: 0.0,
            analytic_expansion_ratio: 3.5,
            analytic_expansion_max_length: 3.0,
            smooth: true,
        }
    }
}

impl HybridOptions {
    /// Checks every setting against its range, the turning radius against the map's cell size
    /// `resolution`.
    pub fn check(&self, resolution: f64) -> Result<(), CarError> {
        let bad = |setting, expected, value| Err(CarError::Setting { setting, expected, value });
        let r = self.turning_radius;
        if !(r.is_finite() && r >= 0.5 * resolution && r <= 1e6 * resolution) {
            return bad("turning_radius", "finite, from half a cell to a million cells", r);
        }
        if !(4..=MAX_HEADING_BINS).contains(&self.heading_bins) {
            return bad("heading_bins", "from 4 to 1440", f64::from(self.heading_bins));
        }
        for (setting, value) in
            [("reverse_penalty", self.reverse_penalty), ("non_straight_penalty", self.non_straight_penalty)]
        {
            if !(value.is_finite() && (1.0..=1e6).contains(&value)) {
                return bad(setting, "a number from 1 to 1e6", value);
            }
        }
        if !(self.gear_change_penalty.is_finite() && (0.0..=1e12).contains(&self.gear_change_penalty)) {
            return bad("gear_change_penalty", "a number from 0 to 1e12", self.gear_change_penalty);
        }
        if !(self.analytic_expansion_ratio.is_finite() && self.analytic_expansion_ratio > 0.0) {
            return bad("analytic_expansion_ratio", "positive and finite", self.analytic_expansion_ratio);
        }
        let max = self.analytic_expansion_max_length;
        if !(max.is_finite() && max > 0.0) {
            return bad("analytic_expansion_max_length", "positive and finite", max);
        }
        Ok(())
    }
}
