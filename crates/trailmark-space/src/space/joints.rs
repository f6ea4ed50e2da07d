//! A robot's joint space: a box in which some coordinates are angles that wrap around (the
//! continuous joints), joined by the shortest motions.

use std::f64::consts::{PI, TAU};
use std::fmt::Debug;

use nalgebra::SVector;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use super::{SpaceError, StateSpace, UnitCube, ellipsoid, finite, gaussian, separation};

/// `N` joints: each either bounded (`low[i] <= x[i] <= high[i]`, a revolute or prismatic joint)
/// or an angle that wraps (a continuous joint, kept in `[-π, π]`: OMPL's `SO2StateSpace`). The
/// distance is Euclidean over the per-joint differences, a wrapping joint's taken the short way
/// round (at most π); motions follow those differences, so a continuous joint turning from
/// 3 to -3 rad passes through π, not through 0.
///
/// ```
/// use std::f64::consts::PI;
/// use trailmark_space::space::{Joints, StateSpace};
///
/// // A shoulder within ±2 rad and a wrist that turns forever.
/// let space = Joints::new([-2.0, -PI], [2.0, PI], [false, true])?;
/// let (a, b) = ([0.0, 3.0].into(), [0.0, -3.0].into());
/// assert!((space.distance(&a, &b) - (2.0 * PI - 6.0)).abs() < 1e-12);
/// let middle = space.interpolate(&a, &b, 0.5);
/// assert!((middle[1].abs() - PI).abs() < 1e-12); // across ±π
/// # Ok::<(), trailmark_space::space::SpaceError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joints<const N: usize> {
    low: SVector<f64, N>,
    high: SVector<f64, N>,
    wraps: [bool; N],
    /// Whether any joint wraps (without, every operation is `Rn`'s).
    any: bool,
}

/// `x` brought into `[-π, π]` by whole turns.
fn wrap(x: f64) -> f64 {
    let w = x - TAU * ((x + PI) / TAU).floor();
    // The quotient's rounding can leave `w` a turn off at either end.
    if w > PI {
        w - TAU
    } else if w < -PI {
        w + TAU
    } else {
        w
    }
}

impl<const N: usize> Joints<N> {
    /// The joints with these bounds, `wraps[i]` for the angles that wrap: their bounds are
    /// `[-π, π]` whatever `low[i]` and `high[i]` say. Errors as [`Rn::new`](super::Rn::new)
    /// on the bounds of the others.
    pub fn new(
        low: impl Into<SVector<f64, N>>,
        high: impl Into<SVector<f64, N>>,
        wraps: [bool; N],
    ) -> Result<Self, SpaceError> {
        let (mut low, mut high) = (low.into(), high.into());
        for axis in 0..N {
            if wraps[axis] {
                (low[axis], high[axis]) = (-PI, PI);
            }
            let (l, h) = (low[axis], high[axis]);
            if !(l.is_finite() && h.is_finite() && l < h && (h - l).is_finite()) {
                return Err(SpaceError::InvalidBounds { axis, low: l, high: h });
            }
        }
        let space = Joints { low, high, wraps, any: wraps.contains(&true) };
        let (diagonal, volume) = (space.extent(), space.measure());
        if !(diagonal.is_finite() && volume.is_finite() && volume > 0.0) {
            return Err(SpaceError::RegionTooLarge { diagonal, volume });
        }
        Ok(space)
    }

    /// The lower bounds (`-π` for the joints that wrap).
    pub fn low(&self) -> SVector<f64, N> {
        self.low
    }

    /// The upper bounds (`π` for the joints that wrap).
    pub fn high(&self) -> SVector<f64, N> {
        self.high
    }

    /// Which joints wrap.
    pub fn wraps(&self) -> [bool; N] {
        self.wraps
    }

    /// How many joints wrap: a k-d tree over this space's positions needs `N` plus that many
    /// coordinates ([`StateSpace::position`]).
    pub fn wrapping(&self) -> usize {
        self.wraps.iter().filter(|&&w| w).count()
    }

    /// The motion from `a` to `b` joint by joint: `b - a`, a wrapping joint's the short way
    /// round (in `[-π, π]`).
    pub fn difference(&self, a: &SVector<f64, N>, b: &SVector<f64, N>) -> SVector<f64, N> {
        let mut d = b - a;
        if self.any {
            for i in (0..N).filter(|&i| self.wraps[i]) {
                d[i] -= TAU * (d[i] / TAU).round();
            }
        }
        d
    }
}

impl<const N: usize> StateSpace for Joints<N> {
    type State = SVector<f64, N>;
    const SYMMETRIC: bool = true;

    fn dimension(&self) -> usize {
        N
    }

    fn sample(&self, rng: &mut ChaCha8Rng) -> SVector<f64, N> {
        SVector::from_fn(|i, _| rng.random_range(self.low[i]..self.high[i]))
    }

    fn satisfies_bounds(&self, s: &SVector<f64, N>) -> bool {
        // `low <= x <= high` is false for a NaN.
        (0..N).all(|i| self.low[i] <= s[i] && s[i] <= self.high[i])
    }

    fn enforce_bounds(&self, s: &mut SVector<f64, N>) {
        for i in 0..N {
            if !s[i].is_finite() {
                continue;
            }
            s[i] = if self.wraps[i] { wrap(s[i]) } else { s[i].clamp(self.low[i], self.high[i]) };
        }
    }

    fn sample_near(&self, near: &SVector<f64, N>, std_dev: f64, rng: &mut ChaCha8Rng) -> SVector<f64, N> {
        let mut s = SVector::from_fn(|i, _| near[i] + std_dev * gaussian(rng));
        self.enforce_bounds(&mut s);
        s
    }

    fn distance(&self, a: &SVector<f64, N>, b: &SVector<f64, N>) -> f64 {
        separation(&self.difference(a, b))
    }

    fn interpolate(&self, a: &SVector<f64, N>, b: &SVector<f64, N>, t: f64) -> SVector<f64, N> {
        if !self.any {
            return a + (b - a) * t;
        }
        let mut s = a + self.difference(a, b) * t;
        for i in (0..N).filter(|&i| self.wraps[i]) {
            // The ends exactly: a motion's last state is its goal.
            s[i] = if t == 1.0 { b[i] } else { wrap(s[i]) };
        }
        s
    }

    fn sample_informed(
        &self,
        a: &SVector<f64, N>,
        b: &SVector<f64, N>,
        cost: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<SVector<f64, N>> {
        if self.any {
            return None;
        }
        Some(ellipsoid::sample(a, b, cost, rng))
    }

    fn informed_measure(&self, a: &SVector<f64, N>, b: &SVector<f64, N>, cost: f64) -> Option<f64> {
        if self.any {
            return None;
        }
        Some(ellipsoid::measure(N, (b - a).norm(), cost))
    }

    fn extent(&self) -> f64 {
        // A wrapping joint is never more than half a turn from another value.
        SVector::<f64, N>::from_fn(|i, _| if self.wraps[i] { PI } else { self.high[i] - self.low[i] }).norm()
    }

    fn measure(&self) -> f64 {
        (self.high - self.low).product()
    }

    fn coordinates(&self, s: &SVector<f64, N>) -> Vec<f64> {
        s.iter().copied().collect()
    }

    fn state_from_coordinates(&self, c: &[f64]) -> Option<SVector<f64, N>> {
        finite::<N>(c).map(SVector::from)
    }

    /// With `D` at least `N` plus the wrapping joints: each bounded joint's value, each
    /// wrapping joint's cosine, then the wrapping joints' sines (the chord between two angles
    /// is never longer than the arc), then zeros.
    fn position<const D: usize>(&self, s: &SVector<f64, N>) -> Option<[f64; D]> {
        if D < N + self.wrapping() {
            return None;
        }
        let mut p = [0.0; D];
        let mut sines = N;
        for i in 0..N {
            if self.wraps[i] {
                // ±π are one angle: one position, whatever `sin_cos` rounds π to.
                let (sin, cos) = if s[i].abs() == PI { (0.0, -1.0) } else { s[i].sin_cos() };
                p[i] = cos;
                p[sines] = sin;
                sines += 1;
            } else {
                p[i] = s[i];
            }
        }
        Some(p)
    }
}

impl<const N: usize> UnitCube for Joints<N> {
    fn state_from_unit(&self, unit: &[f64]) -> SVector<f64, N> {
        SVector::from_fn(|i, _| self.low[i] + unit[i] * (self.high[i] - self.low[i]))
    }
}
