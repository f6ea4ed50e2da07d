//! A car's path: stretches of one turn in one gear, end to end, in the world's frame.

use serde::{Deserialize, Serialize};
use trailmark_core::dubins::{Turn, drive};
use trailmark_core::geometry::Pose;
use trailmark_core::reeds_shepp::Gear;

/// One stretch of a car path: from `start`, `length` driven in `gear` along `turn` (at the
/// path's turning radius, or straight).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stretch {
    /// The pose where the stretch begins.
    pub start: Pose,
    /// Left, right or straight.
    pub turn: Turn,
    /// Forward or in reverse.
    pub gear: Gear,
    /// The length driven (not negative).
    pub length: f64,
}

impl Stretch {
    /// The pose `s` along the stretch (`0 <= s <= length`) for a car of `turning_radius`.
    pub fn pose_at(&self, s: f64, turning_radius: f64) -> Pose {
        let signed = if self.gear == Gear::Forward { s } else { -s };
        drive(&self.start, self.turn, signed, turning_radius)
    }
}

/// A path for a car: stretches end to end, each starting where the one before it ends.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CarPath {
    /// The stretches, in order.
    pub stretches: Vec<Stretch>,
    /// The turning radius of the arcs.
    pub turning_radius: f64,
    /// What the planner charged for the path: its length priced by the map's cells, with the
    /// penalties for reversing, turning and changing gear.
    pub cost: f64,
}

impl CarPath {
    /// The length driven, forward and in reverse.
    pub fn length(&self) -> f64 {
        // An empty sum of floats is -0; a path of no stretches has length 0.
        0.0 + self.stretches.iter().map(|s| s.length).sum::<f64>()
    }

    /// The start pose (`None` for an empty path).
    pub fn start(&self) -> Option<Pose> {
        self.stretches.first().map(|s| s.start)
    }

    /// The end pose (`None` for an empty path).
    pub fn end(&self) -> Option<Pose> {
        self.stretches.last().map(|s| s.pose_at(s.length, self.turning_radius))
    }

    /// The poses where the car changes gear (the cusps), in order.
    pub fn cusps(&self) -> Vec<Pose> {
        self.stretches.windows(2).filter(|w| w[0].gear != w[1].gear).map(|w| w[1].start).collect()
    }

    /// Poses along the path at most `step` apart on every stretch, each stretch's ends included,
    /// with the gear driven to reach each (the start's: the first stretch's). A `step` that is
    /// not positive and finite gives the stretches' ends only.
    pub fn sample(&self, step: f64) -> Vec<(Pose, Gear)> {
        let mut out = Vec::new();
        for (k, stretch) in self.stretches.iter().enumerate() {
            if k == 0 {
                out.push((stretch.start, stretch.gear));
            }
            let n =
                if step.is_finite() && step > 0.0 { (stretch.length / step).ceil().max(1.0) } else { 1.0 };
            let n = n.min(1e6) as usize;
            for i in 1..=n {
                let s = stretch.length * i as f64 / n as f64;
                out.push((stretch.pose_at(s, self.turning_radius), stretch.gear));
            }
        }
        out
    }
}
