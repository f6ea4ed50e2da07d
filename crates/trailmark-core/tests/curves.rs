//! Curves against their textbook definitions (Bernstein sums, the Cox–de Boor recursion, the
//! Hermite basis), and smoothing re-checked independently: every smoothed path sampled every
//! 1e-3 against the obstacles' plain distances.

use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::curve::{BSpline, Bezier, CubicHermite, CurveError};
use trailmark_core::generate;
use trailmark_core::geometry::{Point, Vector};
use trailmark_core::smooth::{Smoothing, smooth};
use trailmark_core::world::{Bounds, PolygonWorld};

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |c, i| c * (n - i) as f64 / (i + 1) as f64)
}

/// The Bernstein form: Σ C(n, i) tⁱ (1 - t)ⁿ⁻ⁱ Pᵢ.
fn bernstein(points: &[Point], t: f64) -> Point {
    let n = points.len() - 1;
    let sum = points.iter().enumerate().fold(Vector::zeros(), |s, (i, p)| {
        s + p.coords * binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
    });
    Point::from(sum)
}

/// The Cox–de Boor recursion for the basis function N(i, p) at `u` (right-open spans, the
/// domain's end taken from the left).
fn basis(knots: &[f64], i: usize, p: usize, u: f64, end: f64) -> f64 {
    if p == 0 {
        let inside = knots[i] <= u && u < knots[i + 1];
        let at_end = u == end && knots[i] < knots[i + 1] && knots[i + 1] == end;
        return f64::from(u8::from(inside || at_end));
    }
    let term = |num: f64, den: f64, n: f64| if den > 0.0 { num / den * n } else { 0.0 };
    term(u - knots[i], knots[i + p] - knots[i], basis(knots, i, p - 1, u, end))
        + term(knots[i + p + 1] - u, knots[i + p + 1] - knots[i + 1], basis(knots, i + 1, p - 1, u, end))
}

fn close(a: Point, b: Point, tol: f64) -> bool {
    (a - b).norm() <= tol * (1.0 + a.coords.norm())
}

fn points(raw: &[(f64, f64)]) -> Vec<Point> {
    raw.iter().map(|&(x, y)| Point::new(x, y)).collect()
}

fn coords() -> impl Strategy<Value = (f64, f64)> {
    (-10.0f64..10.0, -10.0f64..10.0)
}

proptest! {
    #[test]
    fn bezier_matches_the_bernstein_form(raw in prop::collection::vec(coords(), 2..8), t in 0.0f64..=1.0, s in 0.0f64..=1.0) {
        let p = points(&raw);
        let b = Bezier::new(p.clone()).unwrap();
        prop_assert!(close(b.point(t), bernstein(&p, t), 1e-12));
        prop_assert_eq!((b.point(0.0), b.point(1.0)), (p[0], p[p.len() - 1]));
        // The derivative against a central difference of the Bernstein form.
        let h = 1e-6;
        let (lo, hi) = ((t - h).max(0.0), (t + h).min(1.0));
        let diff = (bernstein(&p, hi) - bernstein(&p, lo)) / (hi - lo);
        prop_assert!((b.derivative(t) - diff).norm() <= 1e-4 * (1.0 + diff.norm()));
        // Splitting at t gives the two parts of the same curve.
        let (before, after) = b.split(t);
        prop_assert!(close(before.point(s), bernstein(&p, s * t), 1e-11));
        prop_assert!(close(after.point(s), bernstein(&p, t + s * (1.0 - t)), 1e-11));
        // Samples at most `step` apart, from end to end.
        let samples = b.sample(0.05).unwrap();
        prop_assert!(samples.windows(2).all(|w| (w[1] - w[0]).norm() <= 0.05 + 1e-12));
        prop_assert_eq!((samples[0], *samples.last().unwrap()), (p[0], p[p.len() - 1]));
    }

    #[test]
    fn bezier_length_matches_a_fine_polyline(raw in prop::collection::vec(coords(), 2..6)) {
        let b = Bezier::new(points(&raw)).unwrap();
        let n = 200_000;
        let fine: f64 = (0..n).map(|i| (bernstein(b.control_points(), (i + 1) as f64 / n as f64) - bernstein(b.control_points(), i as f64 / n as f64)).norm()).sum();
        // The fine polyline is shorter than the curve by O(1/n²).
        prop_assert!((b.length() - fine).abs() <= 1e-6 * (1.0 + fine), "{} vs {fine}", b.length());
        prop_assert!(b.length() <= b.polygon_length() + 1e-12);
    }

    #[test]
    fn hermite_matches_its_bezier(p0 in coords(), m0 in coords(), p1 in coords(), m1 in coords(), t in 0.0f64..=1.0) {
        let h = CubicHermite::new(Point::new(p0.0, p0.1), Vector::new(m0.0, m0.1), Point::new(p1.0, p1.1), Vector::new(m1.0, m1.1));
        let b = h.to_bezier();
        prop_assert!(close(h.point(t), b.point(t), 1e-12));
        prop_assert_eq!((h.point(0.0), h.point(1.0)), (h.p0, h.p1));
        prop_assert!((b.derivative(0.0) - h.m0).norm() <= 1e-12 * (1.0 + h.m0.norm()));
        prop_assert!((b.derivative(1.0) - h.m1).norm() <= 1e-12 * (1.0 + h.m1.norm()));
    }

    /// De Boor's algorithm, knot insertion and the Bézier pieces all give the curve of the
    /// Cox–de Boor basis, on random (unclamped, repeated) knot vectors.
    #[test]
    fn bspline_matches_the_cox_de_boor_basis(raw in prop::collection::vec(coords(), 2..9), degree in 1usize..5, gaps in prop::collection::vec(0u8..3, 20), u in 0.0f64..=1.0, at in 0.0f64..=1.0) {
        let control = points(&raw);
        prop_assume!(control.len() > degree);
        let mut knot = 0.0;
        let knots: Vec<f64> = gaps.iter().take(control.len() + degree + 1).map(|&g| { knot += f64::from(g); knot }).collect();
        let Ok(spline) = BSpline::new(degree, control.clone(), knots.clone()) else {
            prop_assume!(false);
            unreachable!()
        };
        let (a, b) = spline.domain();
        let u = a + (b - a) * u;
        let weights: Vec<f64> = (0..control.len()).map(|i| basis(&knots, i, degree, u, b)).collect();
        prop_assert!((weights.iter().sum::<f64>() - 1.0).abs() <= 1e-12, "partition of unity");
        let expected = Point::from(control.iter().zip(&weights).fold(Vector::zeros(), |s, (p, w)| s + p.coords * *w));
        prop_assert!(close(spline.point(u), expected, 1e-10), "{} vs {expected}", spline.point(u));
        let inserted = spline.insert_knot(a + (b - a) * at);
        prop_assert!(close(inserted.point(u), expected, 1e-10));
        // The Bézier piece of u's span.
        let spans: Vec<(f64, f64)> = knots.windows(2).map(|w| (w[0], w[1])).filter(|&(lo, hi)| lo < hi && a <= lo && hi <= b).collect();
        let pieces = spline.to_beziers();
        prop_assert_eq!(pieces.len(), spans.len());
        let (k, &(lo, hi)) = spans.iter().enumerate().find(|(_, (lo, hi))| *lo <= u && (u < *hi || *hi == b)).unwrap();
        prop_assert!(close(pieces[k].point((u - lo) / (hi - lo)), expected, 1e-9));
    }
}

/// A uniform cubic B-spline at an interior knot is (P0 + 4 P1 + P2) / 6 of the three control
/// points around it: the textbook value of the basis (1/6, 2/3, 1/6).
#[test]
fn uniform_cubic_bspline_at_a_knot() {
    let control = points(&[(0.0, 0.0), (1.0, 3.0), (4.0, 3.0), (6.0, -1.0), (8.0, 0.0)]);
    let knots: Vec<f64> = (0..9).map(f64::from).collect();
    let spline = BSpline::new(3, control.clone(), knots).unwrap();
    for (u, i) in [(3.0, 1), (4.0, 2), (5.0, 3)] {
        let expected =
            Point::from((control[i - 1].coords + control[i].coords * 4.0 + control[i + 1].coords) / 6.0);
        assert!(close(spline.point(u), expected, 1e-15), "{u}");
    }
}

#[test]
fn bad_curves_are_typed_errors() {
    let p = Point::new(0.0, 0.0);
    assert_eq!(Bezier::new(vec![p]), Err(CurveError::TooFewPoints { degree: 1, needed: 2, got: 1 }));
    assert_eq!(Bezier::new(vec![p, Point::new(f64::NAN, 0.0)]), Err(CurveError::NotFinite { index: 1 }));
    assert_eq!(BSpline::clamped_uniform(0, vec![p, p]), Err(CurveError::ZeroDegree));
    assert!(matches!(BSpline::clamped_uniform(3, vec![p, p, p]), Err(CurveError::TooFewPoints { .. })));
    let three = vec![p, Point::new(1.0, 0.0), Point::new(2.0, 0.0)];
    assert!(matches!(BSpline::new(1, three.clone(), vec![0.0, 1.0, 2.0]), Err(CurveError::InvalidKnots(_))));
    assert!(matches!(
        BSpline::new(1, three.clone(), vec![0.0, 2.0, 1.0, 3.0, 4.0]),
        Err(CurveError::InvalidKnots(_))
    ));
    assert!(matches!(
        BSpline::new(1, three.clone(), vec![0.0, 1.0, 1.0, 1.0, 4.0]),
        Err(CurveError::InvalidKnots(_))
    ));
    assert_eq!(
        BSpline::new(1, three, vec![0.0, 1.0, f64::INFINITY, 3.0, 4.0]),
        Err(CurveError::NotFinite { index: 2 })
    );
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 1.0, 1.0).unwrap(), vec![], 0.0).unwrap();
    let bad = [p, Point::new(0.5, f64::NAN)];
    assert_eq!(smooth(&world.checker(), &bad, Smoothing::Hermite), Err(CurveError::NotFinite { index: 1 }));
}

/// The points of `curve` every 1e-3 that are not clear (obstacles whose box is farther than the
/// radius from its control points' box skipped: they cannot be within the radius).
fn collisions(world: &PolygonWorld, curve: &Bezier) -> Vec<Point> {
    let r = world.robot_radius() + 1.0;
    let c = curve.control_points();
    let (lo, hi) = c.iter().fold((c[0], c[0]), |(lo, hi), p| {
        (Point::new(lo.x.min(p.x), lo.y.min(p.y)), Point::new(hi.x.max(p.x), hi.y.max(p.y)))
    });
    let near: Vec<_> = world
        .obstacles()
        .iter()
        .filter(|o| {
            let v = o.vertices();
            let (olo, ohi) = v.iter().fold((v[0], v[0]), |(a, b), p| {
                (Point::new(a.x.min(p.x), a.y.min(p.y)), Point::new(b.x.max(p.x), b.y.max(p.y)))
            });
            olo.x <= hi.x + r && ohi.x >= lo.x - r && olo.y <= hi.y + r && ohi.y >= lo.y - r
        })
        .cloned()
        .collect();
    let local = PolygonWorld::new(
        world.bounds(),
        near.into_iter().map(|o| o.vertices().to_vec()).collect(),
        world.robot_radius(),
    )
    .unwrap();
    curve.sample(1e-3).unwrap().into_iter().filter(|&p| !local.reference_is_clear(p, 1e-9)).collect()
}

/// A world of random convex obstacles and a collision-free random polyline in it.
fn world_and_path(count: usize, radius: f64, seed: u64) -> Option<(PolygonWorld, Vec<Point>)> {
    let world = generate::convex_obstacles(40.0, count, 6, radius, seed).ok()?;
    let checker = world.checker();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut point = || Point::new(rng.random_range(0.0..40.0), rng.random_range(0.0..40.0));
    let mut path = vec![(0..1000).map(|_| point()).find(|&p| checker.point_is_free(p))?];
    for _ in 0..2000 {
        let next = point();
        if checker.segment_is_free(path[path.len() - 1], next) {
            path.push(next);
            if path.len() == 8 {
                break;
            }
        }
    }
    (path.len() >= 3).then_some((world, path))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// A curve the checker accepts is clear when sampled every 1e-3; one it refuses comes
    /// within 0.05 of an obstacle (beyond the radius) or of the bounds.
    #[test]
    fn accepted_curves_are_clear((world, path) in (1usize..30, 0.0f64..1.5, any::<u64>()).prop_filter_map("a free path", |(c, r, s)| world_and_path(c, r, s)), pull in prop::collection::vec((-3.0f64..3.0, -3.0f64..3.0), 2)) {
        let checker = world.checker();
        let (a, b) = (path[0], path[1]);
        let controls = vec![a, a + Vector::new(pull[0].0, pull[0].1), b + Vector::new(pull[1].0, pull[1].1), b];
        let curve = Bezier::new(controls).unwrap();
        if checker.bezier_is_free(&curve) {
            prop_assert_eq!(collisions(&world, &curve), vec![]);
        } else {
            // Refusals are only for curves near an obstacle or the bounds: one clear of both
            // by 0.05 more than the radius is accepted (the hulls shrink onto it when split).
            let (lo, hi) = (world.bounds().min(), world.bounds().max());
            let margin = |p: Point| {
                let walls = (p.x - lo.x).min(hi.x - p.x).min(p.y - lo.y).min(hi.y - p.y);
                let obstacles = world.obstacles().iter().map(|o| o.distance_to(p) - world.robot_radius());
                obstacles.fold(walls, f64::min)
            };
            let close = curve.sample(1e-2).unwrap().into_iter().map(margin).fold(f64::INFINITY, f64::min);
            // Samples 1e-2 apart miss the least clearance by at most 0.005.
            prop_assert!(close < 0.055, "a curve clear by {close} was refused");
        }
    }

    /// Every method: the same ends, pieces end to end, every point clear when sampled every
    /// 1e-3; Hermite passes through every waypoint; corner rounding and the B-spline are no
    /// longer than the polyline; curved joins are tangent-continuous where nothing was kept.
    #[test]
    fn smoothed_paths_are_clear_and_connected((world, path) in (1usize..30, 0.0f64..1.5, any::<u64>()).prop_filter_map("a free path", |(c, r, s)| world_and_path(c, r, s))) {
        let checker = world.checker();
        let polyline: f64 = path.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        for method in Smoothing::ALL {
            let smoothed = smooth(&checker, &path, method).unwrap();
            prop_assert_eq!((smoothed.start(), smoothed.end()), (Some(path[0]), Some(path[path.len() - 1])));
            prop_assert!(smoothed.pieces.windows(2).all(|w| w[0].end() == w[1].start()));
            for piece in &smoothed.pieces {
                prop_assert_eq!(collisions(&world, piece), vec![], "{:?}", method);
            }
            let length = smoothed.length();
            match method {
                Smoothing::Hermite => {
                    let starts: Vec<Point> = smoothed.pieces.iter().map(Bezier::start).collect();
                    prop_assert_eq!(&starts[..], &path[..path.len() - 1]);
                    prop_assert!(length >= polyline - 1e-9);
                }
                Smoothing::Bezier | Smoothing::BSpline => prop_assert!(length <= polyline + 1e-9, "{method:?}: {length} > {polyline}"),
            }
            if smoothed.kept == 0 {
                for w in smoothed.pieces.windows(2) {
                    let (out, into) = (w[0].derivative(1.0), w[1].derivative(0.0));
                    prop_assert!(out.perp(&into).abs() <= 1e-6 * out.norm() * into.norm() && out.dot(&into) > 0.0, "{method:?}: a corner at {} {:?} {:?} path {:?}", w[0].end(), w[0], w[1], path);
                }
            }
        }
    }
}

/// In open space nothing is kept: every method smooths every corner.
#[test]
fn open_space_smooths_every_corner() {
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 100.0, 100.0).unwrap(), vec![], 1.0).unwrap();
    let path = points(&[(10.0, 10.0), (30.0, 60.0), (50.0, 20.0), (90.0, 90.0)]);
    for method in Smoothing::ALL {
        let smoothed = smooth(&world.checker(), &path, method).unwrap();
        assert_eq!(smoothed.kept, 0, "{method:?}");
        assert!(smoothed.pieces.iter().any(|p| p.degree() > 1), "{method:?}");
    }
}
