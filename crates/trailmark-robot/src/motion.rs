//! How both checkers decide a motion (a straight line in joint space) is free: the rule the
//! [`checker`](crate::checker) module states, written once. The coarse windows are evenly
//! spaced and their states pushed in VAMP's rake order (each batch spread over the whole
//! motion), the refinements tested first.

use std::cell::Cell;

/// A state of a motion to test: where along it, and how much the fastest sphere is grown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sample {
    pub(crate) t: f64,
    pub(crate) grow: f64,
}

/// The coarse growth as a multiple of the finest.
pub(crate) const COARSE: f64 = 80.0;

/// The most states one motion is checked at (beyond it, the motion is refused).
pub(crate) const MAX_SAMPLES: usize = 10_000_000;

/// Whether the motion is covered, as the [module](self) says. `test(samples, stop)` checks up
/// to `width` samples and returns a bit per sample found touching; it may return as soon as a
/// sample of `stop` (a bit per sample: those whose touching ends the motion) touches.
pub(crate) fn covered(
    rate: f64,
    fine: f64,
    width: usize,
    mut test: impl FnMut(&[Sample], u32) -> u32,
) -> bool {
    if !(rate.is_finite() && rate >= 0.0) {
        return false;
    }
    if rate == 0.0 {
        // No sphere moves: every state is the first.
        return test(&[Sample { t: 0.0, grow: 0.0 }], 1) == 0;
    }
    let coarse = COARSE * fine;
    let count = (rate / (2.0 * coarse)).ceil();
    if count + 1.0 > MAX_SAMPLES as f64 {
        return false;
    }
    let n = (count as usize).max(1);
    // Windows of `1 / (2n)` each side: the growth that gives them, at most `coarse`.
    let first = rate / (2.0 * n as f64);
    // A stack: the last pushed is tested first. The even states go in rake order (the first
    // batch spread over the whole motion), so collisions anywhere are met early.
    let batches = (n + 1).div_ceil(width);
    // The buffers of the thread's last motion, kept for the next (none when one is in use).
    let (mut stack, mut batch) = BUFFERS.take();
    stack.clear();
    for k in (0..batches).rev() {
        for l in (0..width).rev() {
            let i = l * batches + k;
            if i <= n {
                stack.push(Sample { t: i as f64 / n as f64, grow: first });
            }
        }
    }
    let free = refine(&mut stack, &mut batch, rate, fine, width, test);
    // Kept unless a long motion made them large.
    if stack.capacity() <= KEPT {
        BUFFERS.set((stack, batch));
    }
    free
}

/// The most samples the kept stack holds.
const KEPT: usize = 1 << 14;

thread_local! {
    /// The stack of samples and the batch `covered` uses, between motions.
    static BUFFERS: Cell<(Vec<Sample>, Vec<Sample>)> = const { Cell::new((Vec::new(), Vec::new())) };
}

/// Tests the samples of `stack` in batches, pushing the halves of those that touch.
fn refine(
    stack: &mut Vec<Sample>,
    batch: &mut Vec<Sample>,
    rate: f64,
    fine: f64,
    width: usize,
    mut test: impl FnMut(&[Sample], u32) -> u32,
) -> bool {
    let mut tested = 0usize;
    while !stack.is_empty() {
        batch.clear();
        while batch.len() < width
            && let Some(s) = stack.pop()
        {
            batch.push(s);
        }
        tested += batch.len();
        if tested > MAX_SAMPLES {
            return false;
        }
        let stop = batch.iter().enumerate().filter(|(_, s)| s.grow <= fine).fold(0, |m, (i, _)| m | 1 << i);
        let hits = test(batch, stop);
        if hits & stop != 0 {
            return false;
        }
        for (i, s) in batch.iter().enumerate() {
            if hits & (1 << i) == 0 {
                continue;
            }
            let half = s.grow / 2.0;
            let w = half / rate;
            if s.t > 0.0 {
                stack.push(Sample { t: (s.t - w).max(0.0), grow: half });
            }
            if s.t < 1.0 {
                stack.push(Sample { t: (s.t + w).min(1.0), grow: half });
            }
            // Tested first: a collision at the state itself ends the motion at once.
            stack.push(Sample { t: s.t, grow: 0.0 });
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-dimensional "robot" at position `t * rate` among `walls` (points): a sample
    /// touches when a wall is within its growth.
    fn free_between(walls: &[f64], rate: f64, fine: f64, width: usize) -> (bool, usize) {
        let mut states = 0;
        let free = covered(rate, fine, width, |batch, _| {
            states += batch.len();
            let mut hits = 0;
            for (i, s) in batch.iter().enumerate() {
                if walls.iter().any(|w| (w - s.t * rate).abs() <= s.grow) {
                    hits |= 1 << i;
                }
            }
            hits
        });
        (free, states)
    }

    #[test]
    fn a_wall_on_the_motion_is_found_and_one_beyond_the_finest_growth_is_passed() {
        for width in [1, 8] {
            // A motion of 1 m: a wall at 0.5377 m is on it.
            assert!(!free_between(&[0.5377], 1.0, 0.001, width).0);
            // Walls just past either end, farther than the finest growth.
            assert!(free_between(&[-0.0011, 1.0011], 1.0, 0.001, width).0);
            // On the motion, just before its end.
            assert!(!free_between(&[0.9995], 1.0, 0.001, width).0);
        }
    }

    #[test]
    fn open_motions_take_few_states_and_near_walls_refine() {
        let (free, open) = free_between(&[], 1.0, 0.001, 8);
        assert!(free);
        // Windows of at most 8 cm each side: seven windows of 1/14 m each side, 8 states.
        assert_eq!(open, 8);
        let (free, near) = free_between(&[1.005], 1.0, 0.001, 8);
        assert!(free);
        assert!(near > open && near < 3 * open, "{near}");
    }
}
