//! The motions Hybrid A* expands a state with: forward and (when allowed) in reverse, straight
//! or at the turning radius to either side, each long enough to leave its cell and turning by
//! a whole number of heading bins, so that every state the search reaches has a heading on a
//! bin (counted from the start's heading) and the footprint's cells depend only on the bin.

use std::f64::consts::{SQRT_2, TAU};

use trailmark_core::dubins::Turn;
use trailmark_core::geometry::Pose;
use trailmark_core::reeds_shepp::Gear;

use crate::path::Stretch;

/// One motion: a gear, a turn, and the bins the heading moves by (signed: counter-clockwise
/// positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Motion {
    pub gear: Gear,
    pub turn: Turn,
    pub bins: i32,
}

/// The motions of a search, all of the same length.
#[derive(Debug, Clone)]
pub(crate) struct Motions {
    pub all: Vec<Motion>,
    /// The length of every motion.
    pub length: f64,
    /// The angle of one heading bin.
    pub bin_angle: f64,
    /// Per motion, the poses where its footprint is checked, relative to its start: evenly
    /// spaced, at most the check step apart, the last its end. A motion's poses are the same
    /// from every start, so the search composes these instead of evaluating the arc.
    pub checks: Vec<Vec<Pose>>,
}

impl Motions {
    /// The motions for a car of `radius` on cells of `resolution` with `bins` headings:
    /// a turn of the fewest bins whose arc is at least 1.5 cells long (out of its cell whatever
    /// the direction), and straight motions of the same length; checked every `step` at most.
    pub fn new(radius: f64, bins: u32, resolution: f64, reverse: bool, step: f64) -> Self {
        let bin_angle = TAU / f64::from(bins);
        let least = 1.5f64.max(SQRT_2) * resolution;
        let per_turn = ((least / (radius * bin_angle)).ceil() as i32).max(1);
        let length = f64::from(per_turn) * bin_angle * radius;
        let gears: &[Gear] = if reverse { &[Gear::Forward, Gear::Reverse] } else { &[Gear::Forward] };
        let mut all = Vec::new();
        for &gear in gears {
            // Reversing with the wheels to the left turns the heading clockwise.
            let sign = if gear == Gear::Forward { 1 } else { -1 };
            all.push(Motion { gear, turn: Turn::Straight, bins: 0 });
            all.push(Motion { gear, turn: Turn::Left, bins: sign * per_turn });
            all.push(Motion { gear, turn: Turn::Right, bins: -sign * per_turn });
        }
        let n = (length / step).ceil().max(1.0) as usize;
        let checks = all
            .iter()
            .map(|m| {
                let stretch = Stretch { start: Pose::identity(), turn: m.turn, gear: m.gear, length };
                (1..=n).map(|i| stretch.pose_at(length * i as f64 / n as f64, radius)).collect()
            })
            .collect();
        Motions { all, length, bin_angle, checks }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_move_whole_bins_and_leave_the_cell() {
        let m = Motions::new(0.4, 72, 0.05, true, 0.025);
        assert_eq!(m.all.len(), 6);
        assert!(m.length >= 1.5 * 0.05);
        let start = Pose::new(nalgebra::Vector2::new(1.0, 1.0), 0.3);
        for motion in &m.all {
            let stretch = Stretch { start, turn: motion.turn, gear: motion.gear, length: m.length };
            let end = stretch.pose_at(m.length, 0.4);
            let turned = f64::from(motion.bins) * m.bin_angle;
            let d = (end.rotation.angle() - (0.3 + turned)).rem_euclid(TAU);
            assert!(d.min(TAU - d) < 1e-9, "{motion:?}: {d}");
            let moved = (end.translation.vector - start.translation.vector).norm();
            assert!(moved > 0.05 * 1.4, "{motion:?} moved {moved}");
        }
        // The checked poses, composed with a start, are the stretch's own poses.
        for (motion, checks) in m.all.iter().zip(&m.checks) {
            let stretch = Stretch { start, turn: motion.turn, gear: motion.gear, length: m.length };
            let n = checks.len();
            assert!(m.length / n as f64 <= 0.025 + 1e-12);
            for (i, offset) in checks.iter().enumerate() {
                let direct = stretch.pose_at(m.length * (i + 1) as f64 / n as f64, 0.4);
                let composed = start * offset;
                assert!((direct.translation.vector - composed.translation.vector).norm() < 1e-12);
                assert!((direct.rotation.inverse() * composed.rotation).angle().abs() < 1e-12);
            }
        }
    }
}
