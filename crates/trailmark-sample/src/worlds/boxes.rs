//! Worlds of axis-aligned boxes in `N` dimensions, checked exactly: the random worlds of the
//! BIT* papers (boxes in the unit hypercube), and any box-shaped obstacles of a joint space.
//!
//! A [`BoxWorld`] is a [`Validity`] for [`Rn<N>`]: a state is valid when it lies in no box, a
//! motion when its segment meets no box, decided by the slab test (Kay and Kajiya 1986) without
//! sampling. Boxes are closed: a state on a box's face is in collision. So boxes that share a
//! face, or touch at an edge or a corner, block as their union does; with open boxes the
//! zero-width slit between two of them let paths through a solid wall.
//!
//! ```
//! use trailmark_sample::boxes::BoxWorld;
//! use trailmark_sample::{KdNearest, Planner, Problem, Rn, RrtConnect, Validity};
//! use trailmark_core::termination::Termination;
//!
//! // The unit square with a wall from x = 0.4 to 0.6, open above y = 0.8.
//! let world = BoxWorld::new([0.0; 2], [1.0; 2], vec![([0.4, 0.0], [0.6, 0.8])])?;
//! let space = world.space();
//! let (a, b) = ([0.1, 0.1].into(), [0.9, 0.1].into());
//! assert!(!world.motion_is_valid(&space, &a, &b)); // through the wall
//! let problem = Problem::new(&space, &world, a, b);
//! let mut planner = RrtConnect::new(KdNearest::<Rn<2>, 2>::new(&space)?);
//! let plan = planner.solve(&problem, &Termination::iterations(5_000))?;
//! assert!(plan.path().unwrap().windows(2).all(|m| world.motion_is_valid(&space, &m[0], &m[1])));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::SVector;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use crate::space::{Rn, SpaceError};
use crate::validity::Validity;

/// Axis-aligned boxes in a bounded region of `N` dimensions.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxWorld<const N: usize> {
    space: Rn<N>,
    boxes: Vec<([f64; N], [f64; N])>,
}

impl<const N: usize> BoxWorld<N> {
    /// The region from `low` to `high` with these obstacles, each `(low, high)` corners. A
    /// region that is not finite with low < high on every axis ([`SpaceError::InvalidBounds`],
    /// [`SpaceError::RegionTooLarge`]) or such a box ([`SpaceError::InvalidBox`]) is an error.
    pub fn new(low: [f64; N], high: [f64; N], boxes: Vec<([f64; N], [f64; N])>) -> Result<Self, SpaceError> {
        let space = Rn::new(low, high)?;
        for (index, (lo, hi)) in boxes.iter().enumerate() {
            if let Some(axis) = (0..N).find(|&i| !(lo[i].is_finite() && hi[i].is_finite() && lo[i] < hi[i])) {
                return Err(SpaceError::InvalidBox { index, axis, low: lo[axis], high: hi[axis] });
            }
        }
        Ok(BoxWorld { space, boxes })
    }

    /// `count` random boxes in the unit hypercube, each side drawn from `side` (as the random
    /// worlds of the BIT* papers), seeded; `side` must lie in `(0, 1]` and not be empty.
    pub fn random(count: usize, side: std::ops::Range<f64>, seed: u64) -> Result<Self, SpaceError> {
        use rand::SeedableRng;
        // Sides in (0, 1], a range that is not empty.
        if !(side.start > 0.0 && side.start < side.end && side.end <= 1.0) {
            return Err(SpaceError::InvalidBounds { axis: 0, low: side.start, high: side.end });
        }
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let boxes = (0..count)
            .map(|_| {
                let size: [f64; N] = std::array::from_fn(|_| rng.random_range(side.clone()));
                let low: [f64; N] =
                    std::array::from_fn(|i| rng.random_range(0.0..(1.0 - size[i]).max(f64::MIN_POSITIVE)));
                let high = std::array::from_fn(|i| low[i] + size[i]);
                (low, high)
            })
            .collect();
        BoxWorld::new([0.0; N], [1.0; N], boxes)
    }

    /// The space of the region.
    pub fn space(&self) -> Rn<N> {
        self.space
    }

    /// The obstacles.
    pub fn boxes(&self) -> &[([f64; N], [f64; N])] {
        &self.boxes
    }

    /// Whether `q` lies in no box (faces included).
    pub fn is_free(&self, q: &SVector<f64, N>) -> bool {
        self.boxes.iter().all(|(lo, hi)| (0..N).any(|i| !(q[i] >= lo[i] && q[i] <= hi[i])))
    }

    /// Whether the segment from `a` to `b` meets no box (faces included).
    pub fn segment_is_free(&self, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.boxes.iter().all(|(lo, hi)| !enters(a, b, lo, hi))
    }
}

/// How far apart, as parameters along a segment, the ends of its interval in a box may be
/// found reversed and the segment still meet the box: rounding in the slab test's divisions
/// (a few units in the last place) must not open a gap at a corner where two boxes touch.
const SLAB_ROUNDING: f64 = 1e-12;

/// Whether the segment `a`-`b` meets the closed box `[lo, hi]`: the parameters `t` in `[0, 1]`
/// where it lies within the box on every axis form a closed interval that is not empty (within
/// [`SLAB_ROUNDING`], on the side of a collision).
fn enters<const N: usize>(a: &SVector<f64, N>, b: &SVector<f64, N>, lo: &[f64; N], hi: &[f64; N]) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..N {
        let d = b[i] - a[i];
        if d == 0.0 {
            if !(a[i] >= lo[i] && a[i] <= hi[i]) {
                return false;
            }
            continue;
        }
        let (u, v) = ((lo[i] - a[i]) / d, (hi[i] - a[i]) / d);
        t0 = t0.max(u.min(v));
        t1 = t1.min(u.max(v));
        if t0 > t1 + SLAB_ROUNDING {
            return false;
        }
    }
    true
}

impl<const N: usize> Validity<Rn<N>> for BoxWorld<N> {
    fn state_is_valid(&self, _: &Rn<N>, q: &SVector<f64, N>) -> bool {
        q.iter().all(|c| c.is_finite()) && self.is_free(q)
    }

    fn motion_is_valid(&self, space: &Rn<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        use crate::space::StateSpace;
        // The region is a box: a segment between two states in it stays in it.
        space.satisfies_bounds(a) && space.satisfies_bounds(b) && self.segment_is_free(a, b)
    }
}
