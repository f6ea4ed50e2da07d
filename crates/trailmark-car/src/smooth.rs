//! Smoothing a Hybrid A* path: runs of the search's short motions are replaced by the car's
//! shortest curve between their ends (Reeds-Shepp, or Dubins for a car that only drives
//! forward), as OMPL's path simplifier shortcuts a path in its state space.
//!
//! A curve replaces a run only when the footprint stays free along it by the search's own
//! check and its cost, priced as the search prices motions (the costmap's cost of each metre,
//! the penalties for reversing, turning and changing gear), is lower. So the curvature bound
//! holds exactly (the curves turn at the turning radius), the clearance the costmap's prices
//! ask for is kept, and the path never gets dearer.

use crate::hybrid_astar::{HybridAStar, Shot};
use crate::path::Stretch;
use crate::stats::HybridStats;
use trailmark_core::reeds_shepp::Gear;

/// The most stretches one curve may replace: bounds the curves tried per stretch.
const WINDOW: usize = 48;

/// Passes over the path at most: each pass may join curves the previous one made.
const PASSES: usize = 3;

impl HybridAStar<'_> {
    /// `stretches` (map coordinates, the first from the start pose) shortcut where a cheaper
    /// free curve joins two of their ends, and the path's cost.
    pub(crate) fn smooth(&self, stretches: Vec<Stretch>, stats: &mut HybridStats) -> (Vec<Stretch>, f64) {
        let mut path = stretches;
        let mut cost = self.stretches_cost(&path, stats).unwrap_or(f64::INFINITY);
        for _ in 0..PASSES {
            let (shorter, new_cost) = self.shortcut_pass(&path, stats);
            let better = new_cost < cost;
            if better {
                path = shorter;
                cost = new_cost;
            }
            if !better {
                break;
            }
        }
        (path, cost)
    }

    /// The cost of driving `stretches` in turn, each priced after its predecessor's gear;
    /// `None` if one is not free.
    fn stretches_cost(&self, stretches: &[Stretch], stats: &mut HybridStats) -> Option<f64> {
        let mut before = None;
        let mut cost = 0.0;
        for s in stretches {
            cost += self.curve_cost(&s.start, &vec![(s.turn, s.gear, s.length)], before, stats)?;
            before = Some(s.gear);
        }
        Some(cost)
    }

    /// One pass from the start: at each stretch, the farthest end within [`WINDOW`] that a
    /// cheaper free curve reaches replaces the stretches in between.
    fn shortcut_pass(&self, stretches: &[Stretch], stats: &mut HybridStats) -> (Vec<Stretch>, f64) {
        let n = stretches.len();
        let r = self.settings().turning_radius;
        // Each stretch's cost without a change of gear, and with the change from its
        // predecessor; the ends: each stretch's start, then the last one's end.
        let mut own = Vec::with_capacity(n);
        for s in stretches {
            own.push(
                self.curve_cost(&s.start, &vec![(s.turn, s.gear, s.length)], None, stats).unwrap_or(0.0),
            );
        }
        let change = |before: Option<Gear>, gear: Gear| {
            if before.is_some_and(|b| b != gear) { self.settings().gear_change_penalty } else { 0.0 }
        };
        let mut ends: Vec<_> = stretches.iter().map(|s| s.start).collect();
        ends.extend(stretches.last().map(|s| s.pose_at(s.length, r)));
        let mut out: Vec<Stretch> = Vec::with_capacity(n);
        let mut total = 0.0;
        let mut i = 0;
        while i < n {
            let before = out.last().map(|s| s.gear);
            // The cost of stretches i..j as they are, after `before`.
            let mut window = vec![own[i] + change(before, stretches[i].gear)];
            for k in i + 1..n.min(i + WINDOW) {
                window.push(
                    window[k - i - 1] + own[k] + change(Some(stretches[k - 1].gear), stretches[k].gear),
                );
            }
            let mut taken = None;
            for j in (i + 2..=n.min(i + WINDOW)).rev() {
                let old = window[j - i - 1];
                let Some(curve) = self.curve(&ends[i], &ends[j]) else { continue };
                let length: f64 = curve.iter().map(|&(_, _, l)| l).sum();
                // No piece of a curve costs less than its length at the cheapest price.
                if length * self.least_price() >= old {
                    continue;
                }
                if let Some(cost) = self.curve_cost(&ends[i], &curve, before, stats)
                    && cost < old
                {
                    taken = Some((j, curve, cost));
                    break;
                }
            }
            match taken {
                Some((j, curve, cost)) => {
                    out.extend(pieces(&ends[i], &curve, r));
                    total += cost;
                    i = j;
                }
                None => {
                    out.push(stretches[i]);
                    total += window[0];
                    i += 1;
                }
            }
        }
        (out, total)
    }
}

/// The stretches of `curve` from `start`.
fn pieces(start: &trailmark_core::geometry::Pose, curve: &Shot, r: f64) -> Vec<Stretch> {
    let mut at = *start;
    curve
        .iter()
        .map(|&(turn, gear, length)| {
            let stretch = Stretch { start: at, turn, gear, length };
            at = stretch.pose_at(length, r);
            stretch
        })
        .collect()
}
