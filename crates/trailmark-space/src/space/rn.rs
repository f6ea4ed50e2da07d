//! A box of any fixed dimension: points joined by straight motions.

use std::fmt::Debug;

use nalgebra::SVector;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use super::{SpaceError, StateSpace, UnitCube, ellipsoid, finite, gaussian, separation};

/// A box in `N` dimensions (a planar arm's joint angles, say): distances Euclidean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rn<const N: usize> {
    low: SVector<f64, N>,
    high: SVector<f64, N>,
}

impl<const N: usize> Rn<N> {
    /// The box `low[i] <= x[i] <= high[i]` (bounds are closed: a state on a face is in the
    /// space), its corners given as arrays (`[0.0; 6]`) or as the space's states
    /// ([`SVector`]). Errors when a side is not finite or not longer than 0.
    pub fn new(
        low: impl Into<SVector<f64, N>>,
        high: impl Into<SVector<f64, N>>,
    ) -> Result<Self, SpaceError> {
        let (low, high) = (low.into(), high.into());
        for axis in 0..N {
            let (l, h) = (low[axis], high[axis]);
            // The width too must be finite: samples are drawn across it.
            if !(l.is_finite() && h.is_finite() && l < h && (h - l).is_finite()) {
                return Err(SpaceError::InvalidBounds { axis, low: l, high: h });
            }
        }
        let space = Rn { low, high };
        let (diagonal, volume) = (space.extent(), space.measure());
        if !(diagonal.is_finite() && volume.is_finite() && volume > 0.0) {
            return Err(SpaceError::RegionTooLarge { diagonal, volume });
        }
        Ok(space)
    }

    /// The lower corner.
    pub fn low(&self) -> SVector<f64, N> {
        self.low
    }

    /// The upper corner.
    pub fn high(&self) -> SVector<f64, N> {
        self.high
    }
}

impl<const N: usize> StateSpace for Rn<N> {
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
            s[i] = s[i].clamp(self.low[i], self.high[i]);
        }
    }

    fn sample_near(&self, near: &SVector<f64, N>, std_dev: f64, rng: &mut ChaCha8Rng) -> SVector<f64, N> {
        let mut s = SVector::from_fn(|i, _| near[i] + std_dev * gaussian(rng));
        self.enforce_bounds(&mut s);
        s
    }

    fn distance(&self, a: &SVector<f64, N>, b: &SVector<f64, N>) -> f64 {
        separation(&(b - a))
    }

    fn interpolate(&self, a: &SVector<f64, N>, b: &SVector<f64, N>, t: f64) -> SVector<f64, N> {
        a + (b - a) * t
    }

    fn sample_informed(
        &self,
        a: &SVector<f64, N>,
        b: &SVector<f64, N>,
        cost: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<SVector<f64, N>> {
        Some(ellipsoid::sample(a, b, cost, rng))
    }

    fn informed_measure(&self, a: &SVector<f64, N>, b: &SVector<f64, N>, cost: f64) -> Option<f64> {
        Some(ellipsoid::measure(N, (b - a).norm(), cost))
    }

    fn extent(&self) -> f64 {
        (self.high - self.low).norm()
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

    fn position<const D: usize>(&self, s: &SVector<f64, N>) -> Option<[f64; D]> {
        (D == N).then(|| std::array::from_fn(|i| s[i]))
    }
}

impl<const N: usize> UnitCube for Rn<N> {
    fn state_from_unit(&self, unit: &[f64]) -> SVector<f64, N> {
        SVector::from_fn(|i, _| self.low[i] + unit[i] * (self.high[i] - self.low[i]))
    }
}
