//! Smooth curves in the plane: Bézier curves of any degree, cubic Hermite segments and
//! B-splines, evaluated exactly (de Casteljau and de Boor) and convertible into one another.
//!
//! A Bézier curve lies in the convex hull of its control points and splits into two Bézier
//! curves at any parameter; every curve here converts to Bézier pieces, which is what the
//! collision test ([`CollisionChecker::bezier_is_free`](crate::world::CollisionChecker::bezier_is_free))
//! and the path smoothing of [`smooth`](crate::smooth) build on.
//!
//! ```
//! use trailmark_core::curve::{BSpline, Bezier, CubicHermite};
//! use trailmark_core::geometry::{Point, Vector};
//!
//! // A quarter-turn Bézier: it starts and ends at its end control points, tangent to the
//! // control polygon.
//! let b = Bezier::new(vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.0, 1.0)])?;
//! assert_eq!((b.point(0.0), b.point(1.0)), (Point::new(0.0, 0.0), Point::new(1.0, 1.0)));
//! assert_eq!(b.derivative(0.0), Vector::new(2.0, 0.0));
//!
//! // A Hermite segment is a cubic Bézier with control points a third of the tangents in.
//! let h = CubicHermite::new(Point::new(0.0, 0.0), Vector::new(3.0, 0.0), Point::new(2.0, 2.0), Vector::new(0.0, 3.0));
//! assert_eq!(h.to_bezier().control_points()[1], Point::new(1.0, 0.0));
//!
//! // A clamped cubic B-spline passes through its first and last control points; at an interior
//! // knot of a uniform spline it sits at (P0 + 4 P1 + P2) / 6 of the three control points there.
//! let s = BSpline::clamped_uniform(3, (0..6).map(|i| Point::new(f64::from(i), f64::from(i % 2))).collect())?;
//! let (a, b) = s.domain();
//! assert_eq!((s.point(a), s.point(b)), (Point::new(0.0, 0.0), Point::new(5.0, 1.0)));
//! assert_eq!(s.to_beziers().len(), 3);
//! # Ok::<(), trailmark_core::curve::CurveError>(())
//! ```

use thiserror::Error;

use crate::geometry::{Point, Vector};

/// The most points (or poses) one sampling call returns: 10 million, some 160 MB of points
/// (320 MB of Dubins poses).
///
/// A sample count is a length divided by a step, so a step tiny beside the curve (or a curve
/// huge beside the step) would otherwise ask for any amount of memory: every sampler in
/// trailmark ([`Bezier::sample`], [`Smoothed::sample`](crate::smooth::Smoothed::sample),
/// [`DubinsPath::sample`](crate::dubins::DubinsPath::sample)) checks its count against this
/// before it allocates, and returns a typed error beyond it.
pub const MAX_SAMPLES: usize = 10_000_000;

/// The most pieces [`Bezier::length`] subdivides a curve into before it estimates the rest
/// without subdividing further: 2^20.
const MAX_LENGTH_PIECES: usize = 1 << 20;

/// Why a curve could not be made or sampled.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CurveError {
    /// Fewer control points than the curve needs.
    #[error("a curve of degree {degree} needs at least {needed} control points, got {got}")]
    TooFewPoints {
        /// The degree asked for.
        degree: usize,
        /// The least number of control points.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// A coordinate or knot that is not finite.
    #[error("control point or knot {index} is not finite")]
    NotFinite {
        /// Its position in the input.
        index: usize,
    },
    /// A knot vector of the wrong length, decreasing, or with an empty domain.
    #[error("invalid knot vector: {0}")]
    InvalidKnots(&'static str),
    /// Degree 0.
    #[error("the degree must be at least 1")]
    ZeroDegree,
    /// A sampling step that is not positive and finite.
    #[error("the sampling step must be positive and finite, got {0}")]
    InvalidStep(f64),
    /// Sampling with this step would take more than [`MAX_SAMPLES`] points.
    #[error("sampling every {step:e} takes more than {MAX_SAMPLES} points")]
    TooManySamples {
        /// The step asked for.
        step: f64,
    },
}

fn check_finite(points: &[Point]) -> Result<(), CurveError> {
    match points.iter().position(|p| !(p.x.is_finite() && p.y.is_finite())) {
        Some(index) => Err(CurveError::NotFinite { index }),
        None => Ok(()),
    }
}

/// One de Casteljau step: the points `t` of the way along each leg of `points` (weighted so
/// that `t` = 0 and 1 give the legs' ends exactly).
fn casteljau_step(points: &mut [Point], t: f64) {
    for i in 0..points.len() - 1 {
        points[i] = Point::from(points[i].coords * (1.0 - t) + points[i + 1].coords * t);
    }
}

/// A Bézier curve of degree n ≥ 1: n + 1 control points, parameter in [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub struct Bezier {
    points: Vec<Point>,
}

impl Bezier {
    /// The curve with these control points (at least two, all finite).
    pub fn new(points: Vec<Point>) -> Result<Self, CurveError> {
        if points.len() < 2 {
            return Err(CurveError::TooFewPoints { degree: 1, needed: 2, got: points.len() });
        }
        check_finite(&points)?;
        Ok(Bezier { points })
    }

    /// The straight segment from `a` to `b` (degree 1).
    pub fn line(a: Point, b: Point) -> Self {
        Bezier { points: vec![a, b] }
    }

    /// The degree: one less than the number of control points.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The control points.
    pub fn control_points(&self) -> &[Point] {
        &self.points
    }

    /// The first control point, where the curve starts.
    pub fn start(&self) -> Point {
        self.points[0]
    }

    /// The last control point, where the curve ends.
    pub fn end(&self) -> Point {
        self.points[self.points.len() - 1]
    }

    /// The point at parameter `t` (de Casteljau).
    pub fn point(&self, t: f64) -> Point {
        let mut p = self.points.clone();
        for n in (1..p.len()).rev() {
            casteljau_step(&mut p[..=n], t);
        }
        p[0]
    }

    /// The derivative with respect to the parameter at `t`: n times the curve of degree n - 1
    /// over the control polygon's legs.
    pub fn derivative(&self, t: f64) -> Vector {
        let n = self.degree();
        let mut legs: Vec<Point> =
            self.points.windows(2).map(|w| Point::from((w[1] - w[0]) * n as f64)).collect();
        for k in (1..legs.len()).rev() {
            casteljau_step(&mut legs[..=k], t);
        }
        legs[0].coords
    }

    /// The two curves before and after parameter `t`, together the same curve.
    pub fn split(&self, t: f64) -> (Bezier, Bezier) {
        let mut p = self.points.clone();
        let mut before = Vec::with_capacity(p.len());
        let mut after = Vec::with_capacity(p.len());
        for n in (0..p.len()).rev() {
            before.push(p[0]);
            after.push(p[n]);
            casteljau_step(&mut p[..=n], t);
        }
        after.reverse();
        (Bezier { points: before }, Bezier { points: after })
    }

    /// The length of the control polygon: at least the curve's length.
    pub fn polygon_length(&self) -> f64 {
        self.points.windows(2).map(|w| (w[1] - w[0]).norm()).sum()
    }

    /// The arc length, to a relative accuracy of about 1e-10: the curve is subdivided until
    /// each piece's control polygon and chord agree to that accuracy, or to the rounding of the
    /// piece's coordinates (a small curve far from the origin cannot do better), and each piece
    /// counts the mean of the two. The work is bounded: at most 40 halvings deep and
    /// 2^20 pieces in all, beyond which the remaining pieces are estimated as they are.
    pub fn length(&self) -> f64 {
        let mut total = 0.0;
        let mut pieces = 0;
        let mut stack = vec![(self.clone(), 0u32)];
        while let Some((b, depth)) = stack.pop() {
            let polygon = b.polygon_length();
            let chord = (b.end() - b.start()).norm();
            // Each control point's coordinates are rounded by up to an ulp of the largest
            // coordinate, each leg by twice that: below this the difference is noise.
            let magnitude = b.points.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
            let noise = 4.0 * b.points.len() as f64 * f64::EPSILON * magnitude;
            let tolerance = (1e-10 * polygon).max(noise).max(f64::MIN_POSITIVE);
            pieces += 1;
            // A NaN difference (from an overflowing leg) stops too.
            let difference = polygon - chord;
            if difference.is_nan()
                || difference <= tolerance
                || depth == 40
                || pieces + stack.len() >= MAX_LENGTH_PIECES
            {
                total += 0.5 * (polygon + chord);
                continue;
            }
            let (l, r) = b.split(0.5);
            // Right first, so the left piece is measured first.
            stack.push((r, depth + 1));
            stack.push((l, depth + 1));
        }
        total
    }

    /// How many intervals [`Bezier::sample`] divides the parameter into for `step`.
    pub(crate) fn sample_intervals(&self, step: f64) -> Result<usize, CurveError> {
        if !(step.is_finite() && step > 0.0) {
            return Err(CurveError::InvalidStep(step));
        }
        let n = self.degree() as f64;
        let leg = self.points.windows(2).map(|w| (w[1] - w[0]).norm()).fold(0.0, f64::max);
        let count = (n * leg / step).ceil().max(1.0);
        // NaN (an overflowing leg) fails too; count + 1 points <= MAX_SAMPLES.
        if count.is_nan() || count >= MAX_SAMPLES as f64 {
            return Err(CurveError::TooManySamples { step });
        }
        Ok(count as usize)
    }

    /// Points along the curve, both ends included, consecutive points at most `step` apart
    /// (the parameter is spaced by the bound n · max leg on the speed).
    ///
    /// Errors with [`CurveError::InvalidStep`] unless `step` is positive and finite, and with
    /// [`CurveError::TooManySamples`] when that would be more than [`MAX_SAMPLES`] points
    /// (checked before anything is allocated).
    pub fn sample(&self, step: f64) -> Result<Vec<Point>, CurveError> {
        let count = self.sample_intervals(step)?;
        Ok((0..=count).map(|i| self.point(i as f64 / count as f64)).collect())
    }
}

/// A cubic Hermite segment: from `p0` with tangent `m0` to `p1` with tangent `m1`, parameter
/// in [0, 1] (the tangents are derivatives with respect to it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicHermite {
    /// The start.
    pub p0: Point,
    /// The derivative at the start.
    pub m0: Vector,
    /// The end.
    pub p1: Point,
    /// The derivative at the end.
    pub m1: Vector,
}

impl CubicHermite {
    /// The segment from `p0` leaving with `m0` to `p1` arriving with `m1`.
    pub fn new(p0: Point, m0: Vector, p1: Point, m1: Vector) -> Self {
        CubicHermite { p0, m0, p1, m1 }
    }

    /// The point at `t`, from the Hermite basis h00 = 2t³ - 3t² + 1, h10 = t³ - 2t² + t,
    /// h01 = -2t³ + 3t², h11 = t³ - t².
    pub fn point(&self, t: f64) -> Point {
        let (t2, t3) = (t * t, t * t * t);
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        Point::from(self.p0.coords * h00 + self.m0 * h10 + self.p1.coords * h01 + self.m1 * h11)
    }

    /// The same curve as a cubic Bézier: p0, p0 + m0 / 3, p1 - m1 / 3, p1.
    pub fn to_bezier(&self) -> Bezier {
        Bezier { points: vec![self.p0, self.p0 + self.m0 / 3.0, self.p1 - self.m1 / 3.0, self.p1] }
    }
}

/// A B-spline curve: degree p, control points P0..P(m-1), and m + p + 1 knots; the curve is
/// defined for parameters in the domain [knot p, knot m].
#[derive(Debug, Clone, PartialEq)]
pub struct BSpline {
    degree: usize,
    control: Vec<Point>,
    knots: Vec<f64>,
}

impl BSpline {
    /// The B-spline of `degree` with these control points and knots (non-decreasing, finite,
    /// `control.len() + degree + 1` of them, with a domain of positive length).
    pub fn new(degree: usize, control: Vec<Point>, knots: Vec<f64>) -> Result<Self, CurveError> {
        if degree == 0 {
            return Err(CurveError::ZeroDegree);
        }
        if control.len() <= degree {
            let (needed, got) = (degree.saturating_add(1), control.len());
            return Err(CurveError::TooFewPoints { degree, needed, got });
        }
        check_finite(&control)?;
        if knots.len() != control.len() + degree + 1 {
            return Err(CurveError::InvalidKnots("there must be control points + degree + 1 knots"));
        }
        if let Some(index) = knots.iter().position(|k| !k.is_finite()) {
            return Err(CurveError::NotFinite { index });
        }
        if knots.windows(2).any(|w| w[1] < w[0]) {
            return Err(CurveError::InvalidKnots("the knots must not decrease"));
        }
        if knots[degree] >= knots[control.len()] {
            return Err(CurveError::InvalidKnots("the domain is empty"));
        }
        Ok(BSpline { degree, control, knots })
    }

    /// The clamped uniform B-spline of `degree` over `control`: knots 0 (p + 1 times), 1, 2, ...,
    /// m - p (p + 1 times), so it starts at the first control point and ends at the last.
    pub fn clamped_uniform(degree: usize, control: Vec<Point>) -> Result<Self, CurveError> {
        let m = control.len();
        // Checked before `m + degree + 1` is computed: a huge degree must not overflow it.
        if degree == 0 {
            return Err(CurveError::ZeroDegree);
        }
        if m <= degree {
            return Err(CurveError::TooFewPoints { degree, needed: degree.saturating_add(1), got: m });
        }
        let spans = m.saturating_sub(degree).max(1);
        let knots = (0..m + degree + 1).map(|i| i.saturating_sub(degree).min(spans) as f64).collect();
        BSpline::new(degree, control, knots)
    }

    /// The degree.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points.
    pub fn control_points(&self) -> &[Point] {
        &self.control
    }

    /// The knots.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The parameter range over which the curve is defined.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.control.len()])
    }

    /// The index k of the knot span [knot k, knot k+1) holding `u` (clamped to the domain;
    /// the domain's end belongs to the last non-empty span).
    fn span(&self, u: f64) -> usize {
        let (p, m) = (self.degree, self.control.len());
        let last = (p..m).rev().find(|&k| self.knots[k] < self.knots[k + 1]).unwrap_or(p);
        (p..=last).rev().find(|&k| self.knots[k] <= u).unwrap_or(p)
    }

    /// The point at parameter `u` (de Boor), `u` clamped to the domain.
    pub fn point(&self, u: f64) -> Point {
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let (p, k) = (self.degree, self.span(u));
        let mut d: Vec<Point> = self.control[k - p..=k].to_vec();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let (lo, hi) = (self.knots[j + k - p], self.knots[j + 1 + k - r]);
                let alpha = if hi > lo { (u - lo) / (hi - lo) } else { 0.0 };
                d[j] = d[j - 1] + (d[j] - d[j - 1]) * alpha;
            }
        }
        d[p]
    }

    /// The same curve with the knot `u` (inside the domain) inserted once (Boehm's algorithm).
    /// Inserting a knot that already ends the knot vector changes nothing.
    pub fn insert_knot(&self, u: f64) -> BSpline {
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let p = self.degree;
        // The span [knot k, knot k+1) holding u, over the whole knot vector.
        let Some(k) = (0..self.knots.len() - 1).rev().find(|&k| self.knots[k] <= u && u < self.knots[k + 1])
        else {
            return self.clone();
        };
        let s = self.knots.iter().filter(|&&x| x == u).count();
        let mut control = Vec::with_capacity(self.control.len() + 1);
        for i in 0..=self.control.len() {
            let q = if i + p <= k {
                self.control[i]
            } else if i + s > k {
                self.control[i - 1]
            } else {
                let alpha = (u - self.knots[i]) / (self.knots[i + p] - self.knots[i]);
                self.control[i - 1] + (self.control[i] - self.control[i - 1]) * alpha
            };
            control.push(q);
        }
        let mut knots = self.knots.clone();
        knots.insert(k + 1, u);
        BSpline { degree: p, control, knots }
    }

    /// The curve as Bézier pieces of its degree, one per non-empty knot span in order: every
    /// knot in the domain is inserted until it appears `degree` times.
    pub fn to_beziers(&self) -> Vec<Bezier> {
        let p = self.degree;
        let (a, b) = self.domain();
        let mut spline = self.clone();
        let mut values: Vec<f64> = self.knots.iter().copied().filter(|&u| a <= u && u <= b).collect();
        values.dedup();
        for u in values {
            while spline.knots.iter().filter(|&&x| x == u).count() < p {
                spline = spline.insert_knot(u);
            }
        }
        (p..spline.control.len())
            .filter(|&k| spline.knots[k] < spline.knots[k + 1])
            .map(|k| Bezier { points: spline.control[k - p..=k].to_vec() })
            .collect()
    }
}
