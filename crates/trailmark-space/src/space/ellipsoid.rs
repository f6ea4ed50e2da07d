//! The informed set of a straight-line space: the states through which a path from one focus to
//! the other is no longer than a cost, a prolate hyperspheroid (Gammell, Barfoot and
//! Srinivasa 2018, "Informed sampling for asymptotically optimal path planning"), drawn from
//! directly rather than by rejection.

use nalgebra::SVector;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use super::gaussian;

/// A state drawn uniformly from the solid ellipsoid of the states `x` with
/// `|x - a| + |x - b| <= cost`: a point of the unit ball stretched to the ellipsoid's axes,
/// then turned so that its major axis runs from `a` to `b`. A `cost` below `|b - a|` (rounding)
/// gives a point of the segment.
pub(crate) fn sample<const N: usize>(
    a: &SVector<f64, N>,
    b: &SVector<f64, N>,
    cost: f64,
    rng: &mut ChaCha8Rng,
) -> SVector<f64, N> {
    let axis = b - a;
    let focal = axis.norm();
    // Uniform in the unit ball: a Gaussian direction, a radius with density r^(N-1).
    let mut v = SVector::<f64, N>::from_fn(|_, _| gaussian(rng));
    let norm = v.norm();
    if norm > 0.0 {
        v *= rng.random::<f64>().powf(1.0 / N as f64) / norm;
    }
    let (major, minor) = semi_axes(focal, cost);
    v[0] *= major;
    for i in 1..N {
        v[i] *= minor;
    }
    // The Householder reflection that takes the first axis onto the foci's direction: the
    // ellipsoid is symmetric about its major axis, so a reflection serves as a rotation.
    if focal > 0.0 {
        let mut w = -axis / focal;
        w[0] += 1.0;
        let ww = w.dot(&w);
        if ww > f64::EPSILON {
            v -= w * (2.0 * w.dot(&v) / ww);
        }
    }
    (a + b) * 0.5 + v
}

/// The volume of that ellipsoid in `dimension` dimensions.
pub(crate) fn measure(dimension: usize, focal: f64, cost: f64) -> f64 {
    let (major, minor) = semi_axes(focal, cost);
    unit_ball(dimension) * major * minor.powi(dimension.saturating_sub(1) as i32)
}

/// The semi-major axis (half the cost) and the semi-minor ones.
fn semi_axes(focal: f64, cost: f64) -> (f64, f64) {
    let major = 0.5 * cost.max(focal);
    // (c - f)(c + f) rather than c² - f²: no overflow for large coordinates, no cancellation
    // as the cost nears the focal distance.
    (major, 0.5 * ((cost - focal).max(0.0) * (cost + focal)).sqrt())
}

/// The volume of the unit ball in `dimension` dimensions: V(n) = 2π/n V(n - 2), V(0) = 1, V(1) = 2.
fn unit_ball(dimension: usize) -> f64 {
    let even = dimension.is_multiple_of(2);
    let mut v = if even { 1.0 } else { 2.0 };
    let mut n = if even { 2 } else { 3 };
    while n <= dimension {
        v *= std::f64::consts::TAU / n as f64;
        n += 2;
    }
    v
}

#[cfg(test)]
mod tests {
    use rand::SeedableRng;

    use super::*;

    #[test]
    fn unit_balls_have_their_known_volumes() {
        let pi = std::f64::consts::PI;
        for (n, v) in [(1, 2.0), (2, pi), (3, 4.0 / 3.0 * pi), (4, pi * pi / 2.0), (8, pi.powi(4) / 24.0)] {
            assert!((unit_ball(n) - v).abs() < 1e-12 * v, "{n}");
        }
    }

    /// Every draw lies in the set; the draws fill it evenly (the share within the inner
    /// ellipsoid of half the axes is 2^-N, as volumes scale), on either side of the foci.
    fn fills<const N: usize>() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let a = SVector::<f64, N>::from_fn(|i, _| i as f64 * 0.3);
        let b = SVector::<f64, N>::from_fn(|i, _| 2.0 - (i as f64).sqrt());
        let focal = (b - a).norm();
        let cost = 1.3 * focal;
        let centre = (a + b) * 0.5;
        let (draws, mut inner, mut nearer_a) = (40_000, 0, 0);
        for _ in 0..draws {
            let x = sample(&a, &b, cost, &mut rng);
            let through = (x - a).norm() + (x - b).norm();
            assert!(through <= cost * (1.0 + 1e-12), "{through} > {cost}");
            // Halving the offset from the centre maps the ellipsoid onto its inner half.
            let doubled = centre + (x - centre) * 2.0;
            if (doubled - a).norm() + (doubled - b).norm() <= cost {
                inner += 1;
            }
            if (x - a).norm() < (x - b).norm() {
                nearer_a += 1;
            }
        }
        let expected = draws as f64 * 0.5f64.powi(N as i32);
        let sd = (expected * (1.0 - 0.5f64.powi(N as i32))).sqrt();
        assert!((inner as f64 - expected).abs() < 5.0 * sd, "N = {N}: {inner} inner, {expected} expected");
        let half = draws as f64 / 2.0;
        assert!((nearer_a as f64 - half).abs() < 5.0 * (half / 2.0).sqrt(), "{nearer_a}");
    }

    #[test]
    fn draws_fill_the_set_evenly() {
        fills::<2>();
        fills::<4>();
        fills::<8>();
    }

    #[test]
    fn volume_is_the_share_of_a_box_its_draws_take() {
        // Monte Carlo over the box around the ellipse: the share inside is its measure over the box's.
        let (a, b) = (SVector::<f64, 3>::new(0.0, 0.0, 0.0), SVector::<f64, 3>::new(1.0, 1.0, 0.0));
        let cost = 2.0;
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let (n, mut inside) = (200_000, 0);
        let (lo, hi) = (-1.0, 2.0);
        for _ in 0..n {
            let x = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(lo..hi));
            if (x - a).norm() + (x - b).norm() <= cost {
                inside += 1;
            }
        }
        let estimate = inside as f64 / n as f64 * (hi - lo).powi(3);
        let exact = measure(3, (b - a).norm(), cost);
        assert!((estimate - exact).abs() < 0.02 * exact, "{estimate} against {exact}");
    }
}
