//! The plane: points joined by straight motions.

use std::fmt::Debug;

use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use trailmark_core::geometry::Point;
use trailmark_core::world::Bounds;

use super::{
    StateSpace, UnitCube, area, clamp_into, diagonal, ellipsoid, finite, gaussian, in_bounds, planar,
    sample_in, separation, unit_point,
};

/// The plane region of a [`Bounds`]: states are points, distances Euclidean. Saved as
/// `{"bounds": [xmin, ymin, xmax, ymax]}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct R2 {
    bounds: Bounds,
}

impl R2 {
    /// The points of `bounds`.
    pub fn new(bounds: Bounds) -> Self {
        R2 { bounds }
    }

    /// The bounds.
    pub fn bounds(&self) -> Bounds {
        self.bounds
    }
}

impl StateSpace for R2 {
    type State = Point;
    const SYMMETRIC: bool = true;

    fn dimension(&self) -> usize {
        2
    }

    fn sample(&self, rng: &mut ChaCha8Rng) -> Point {
        sample_in(&self.bounds, rng)
    }

    fn satisfies_bounds(&self, p: &Point) -> bool {
        in_bounds(&self.bounds, p)
    }

    fn enforce_bounds(&self, p: &mut Point) {
        clamp_into(&self.bounds, p);
    }

    fn sample_near(&self, near: &Point, std_dev: f64, rng: &mut ChaCha8Rng) -> Point {
        let mut p = Point::new(near.x + std_dev * gaussian(rng), near.y + std_dev * gaussian(rng));
        self.enforce_bounds(&mut p);
        p
    }

    #[inline]
    fn distance(&self, a: &Point, b: &Point) -> f64 {
        separation(&(b - a))
    }

    #[inline]
    fn interpolate(&self, a: &Point, b: &Point, t: f64) -> Point {
        a + (b - a) * t
    }

    fn sample_informed(&self, a: &Point, b: &Point, cost: f64, rng: &mut ChaCha8Rng) -> Option<Point> {
        Some(Point::from(ellipsoid::sample(&a.coords, &b.coords, cost, rng)))
    }

    fn informed_measure(&self, a: &Point, b: &Point, cost: f64) -> Option<f64> {
        Some(ellipsoid::measure(2, (b - a).norm(), cost))
    }

    fn extent(&self) -> f64 {
        diagonal(&self.bounds)
    }

    fn measure(&self) -> f64 {
        area(&self.bounds)
    }

    fn coordinates(&self, p: &Point) -> Vec<f64> {
        vec![p.x, p.y]
    }

    fn state_from_coordinates(&self, c: &[f64]) -> Option<Point> {
        finite::<2>(c).map(|[x, y]| Point::new(x, y))
    }

    fn position<const D: usize>(&self, p: &Point) -> Option<[f64; D]> {
        planar(*p)
    }
}

impl UnitCube for R2 {
    fn state_from_unit(&self, unit: &[f64]) -> Point {
        unit_point(&self.bounds, unit)
    }
}
