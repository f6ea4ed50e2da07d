//! Path smoothing with curves: a polyline through a polygon world becomes a chain of Bézier
//! pieces, every piece proven collision-free, falling back to the polyline where a curve is not.
//!
//! Three methods, from the curves of [`curve`](crate::curve):
//!
//! - [`Smoothing::Hermite`]: a cubic Hermite segment between each pair of waypoints, tangent at
//!   each waypoint along the bisector of its two legs (so the chain turns smoothly through every
//!   waypoint), tangent lengths the leg's length. A segment that collides is retried with its
//!   tangents halved (up to three times: the curve nears its leg), then kept straight.
//! - [`Smoothing::Bezier`]: corner rounding. Each interior waypoint's corner is cut by a
//!   quadratic Bézier from a point on the incoming leg to a point on the outgoing one, at most
//!   half of the shorter leg from the corner, tangent to both legs; halved up to three times
//!   where it collides, then the corner is kept sharp.
//! - [`Smoothing::BSpline`]: the waypoints are the control points of a clamped cubic B-spline,
//!   which cuts every corner and is curvature-continuous. Where a span collides, the waypoints
//!   that shape it are flanked by control points on their legs, half the shorter leg away and
//!   halving up to three times, which pulls the curve toward the corner; at last a waypoint is
//!   pinned: the curve passes through it and splits there, each part its own B-spline, and a
//!   part between two neighbouring pinned waypoints is the input's own leg.
//!
//! Every curved piece is accepted only when the world's [`Clearance`] (for a polygon world,
//! [`CollisionChecker::bezier_is_free`]) proves it free,
//! and every straight piece is either tested exactly or is one of the input's own legs, so a
//! collision-free input gives a collision-free result, starting and ending at the same points.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::smooth::{Smoothing, smooth};
//! use trailmark_core::world::{Bounds, PolygonWorld};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 6.0), Point::new(4.0, 6.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.5)?.checker();
//! let path = [Point::new(1.0, 1.0), Point::new(3.0, 8.0), Point::new(7.0, 8.0), Point::new(9.0, 1.0)];
//! for method in Smoothing::ALL {
//!     let smooth = smooth(&checker, &path, method)?;
//!     assert_eq!((smooth.start(), smooth.end()), (Some(path[0]), Some(path[3])));
//!     assert!(smooth.pieces.iter().all(|piece| checker.bezier_is_free(piece)));
//!     let polyline = 2.0 * 53f64.sqrt() + 4.0;
//!     match method {
//!         // Through every waypoint: never shorter than the polyline.
//!         Smoothing::Hermite => assert!(smooth.length() >= polyline),
//!         // Cutting the corners.
//!         Smoothing::Bezier | Smoothing::BSpline => assert!(smooth.length() < polyline - 0.5),
//!     }
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use serde::{Deserialize, Serialize};

use crate::curve::{BSpline, Bezier, CubicHermite, CurveError, MAX_SAMPLES};
use crate::geometry::{Point, Vector};
use crate::predicates::orient;
use crate::world::CollisionChecker;

/// What smoothing asks of a world: whether a curved piece, and a straight segment, are free.
/// A polygon world's [`CollisionChecker`] answers exactly; a costmap answers for the cells
/// below a chosen cost (`trailmark-map`); implement it for your own world to smooth paths in it.
pub trait Clearance {
    /// Whether every point of `curve` is free.
    fn bezier_is_free(&self, curve: &Bezier) -> bool;
    /// Whether every point of the segment from `a` to `b` is free.
    fn segment_is_free(&self, a: Point, b: Point) -> bool;
}

impl Clearance for CollisionChecker {
    fn bezier_is_free(&self, curve: &Bezier) -> bool {
        CollisionChecker::bezier_is_free(self, curve)
    }

    fn segment_is_free(&self, a: Point, b: Point) -> bool {
        CollisionChecker::segment_is_free(self, a, b)
    }
}

/// How to smooth a path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Smoothing {
    /// Cubic Hermite segments through the waypoints.
    Hermite,
    /// Corners rounded by quadratic Bézier curves.
    Bezier,
    /// A clamped cubic B-spline with the waypoints as control points.
    #[serde(rename = "bspline")]
    BSpline,
}

impl Smoothing {
    /// Every method, in the order above.
    pub const ALL: [Smoothing; 3] = [Smoothing::Hermite, Smoothing::Bezier, Smoothing::BSpline];

    /// The method's name in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            Smoothing::Hermite => "hermite",
            Smoothing::Bezier => "bezier",
            Smoothing::BSpline => "bspline",
        }
    }
}

/// A smoothed path: Bézier pieces end to end.
#[derive(Debug, Clone, PartialEq)]
pub struct Smoothed {
    /// The pieces in order, each starting where the last ends (straight legs are degree 1).
    pub pieces: Vec<Bezier>,
    /// Legs or corners left as they were because no curve there was proven free.
    pub kept: usize,
}

impl Smoothed {
    /// Where the path starts.
    pub fn start(&self) -> Option<Point> {
        self.pieces.first().map(Bezier::start)
    }

    /// Where the path ends.
    pub fn end(&self) -> Option<Point> {
        self.pieces.last().map(Bezier::end)
    }

    /// The length of the path.
    pub fn length(&self) -> f64 {
        self.pieces.iter().map(Bezier::length).sum()
    }

    /// Points along the path, consecutive points at most `step` apart (each piece sampled by
    /// [`Bezier::sample`], the point shared by two pieces once).
    ///
    /// Errors with [`CurveError::InvalidStep`] unless `step` is positive and finite, and with
    /// [`CurveError::TooManySamples`] when all the pieces together would take more than
    /// [`MAX_SAMPLES`] points (checked before anything is allocated).
    pub fn sample(&self, step: f64) -> Result<Vec<Point>, CurveError> {
        if !(step.is_finite() && step > 0.0) {
            return Err(CurveError::InvalidStep(step));
        }
        let mut total = 1usize;
        let mut counts = Vec::with_capacity(self.pieces.len());
        for piece in &self.pieces {
            let count = piece.sample_intervals(step)?;
            counts.push(count);
            total = total.saturating_add(count);
            if total > MAX_SAMPLES {
                return Err(CurveError::TooManySamples { step });
            }
        }
        // Straight into the one allocation: sampling each piece on its own first had held a
        // second copy of the largest piece (a peak of twice the answer).
        let mut points: Vec<Point> = Vec::with_capacity(total);
        for (piece, &count) in self.pieces.iter().zip(&counts) {
            let skip = usize::from(!points.is_empty());
            points.extend((skip..=count).map(|i| piece.point(i as f64 / count as f64)));
        }
        Ok(points)
    }
}

/// How many times a curve is shrunk toward the polyline before the polyline is kept.
const SHRINKS: usize = 4;

/// `path` smoothed by `method` in the world of `checker` (a polygon world's
/// [`CollisionChecker`], or any [`Clearance`]; see the [module](self) for the methods). Repeated consecutive waypoints are merged; a path of one point gives no pieces.
/// A waypoint that is not finite is an error.
pub fn smooth<C: Clearance + ?Sized>(
    checker: &C,
    path: &[Point],
    method: Smoothing,
) -> Result<Smoothed, CurveError> {
    if let Some(index) = path.iter().position(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(CurveError::NotFinite { index });
    }
    let mut points: Vec<Point> = path.to_vec();
    points.dedup();
    if points.len() < 2 {
        return Ok(Smoothed { pieces: Vec::new(), kept: 0 });
    }
    Ok(match method {
        Smoothing::Hermite => hermite(checker, &points),
        Smoothing::Bezier => round_corners(checker, &points),
        Smoothing::BSpline => bspline(checker, &points)?,
    })
}

/// The unit tangent at each waypoint: along the first and last legs at the ends, along the
/// bisector of the two legs' directions between (the outgoing leg's where they reverse).
fn tangents(points: &[Point]) -> Vec<Vector> {
    let n = points.len();
    let leg = |i: usize| (points[i + 1] - points[i]).normalize();
    (0..n)
        .map(|i| {
            if i == 0 {
                leg(0)
            } else if i == n - 1 {
                leg(n - 2)
            } else {
                let sum = leg(i - 1) + leg(i);
                if sum.norm() > 1e-9 { sum.normalize() } else { leg(i) }
            }
        })
        .collect()
}

fn hermite<C: Clearance + ?Sized>(checker: &C, points: &[Point]) -> Smoothed {
    let tangent = tangents(points);
    let mut kept = 0;
    let pieces = points
        .windows(2)
        .enumerate()
        .map(|(i, leg)| {
            let (a, b) = (leg[0], leg[1]);
            let length = (b - a).norm();
            let curve = (0..SHRINKS).map(|k| length * 0.5f64.powi(k as i32)).find_map(|m| {
                let curve = CubicHermite::new(a, tangent[i] * m, b, tangent[i + 1] * m).to_bezier();
                checker.bezier_is_free(&curve).then_some(curve)
            });
            curve.unwrap_or_else(|| {
                kept += 1;
                Bezier::line(a, b)
            })
        })
        .collect();
    Smoothed { pieces, kept }
}

fn round_corners<C: Clearance + ?Sized>(checker: &C, points: &[Point]) -> Smoothed {
    let n = points.len();
    // Corners kept sharp because a straight connector beside them was not proven free.
    let mut sharp = vec![false; n];
    loop {
        let mut pieces = Vec::new();
        let mut kept = 0;
        // Where the straight part of the current leg starts, and at which waypoint's corner.
        let (mut from, mut from_corner) = (points[0], 0);
        // The straight connectors: their piece, and the waypoints from their start to their end.
        let mut connectors = Vec::new();
        for i in 1..n - 1 {
            let (before, at, after) = (points[i - 1], points[i], points[i + 1]);
            let (incoming, outgoing) = (at - before, after - at);
            let straight = orient(before, at, after) == 0.0 && incoming.dot(&outgoing) > 0.0;
            if straight && !sharp[i] {
                continue; // no corner: the leg goes straight on
            }
            let (u, v) = (incoming.normalize(), outgoing.normalize());
            let cut = 0.5 * incoming.norm().min(outgoing.norm());
            let round =
                (0..SHRINKS).filter(|_| !sharp[i]).map(|k| cut * 0.5f64.powi(k as i32)).find_map(|d| {
                    // Where the last corner's cut took the leg's other half, start exactly there.
                    let a = at - u * d;
                    let a = if (a - from).norm() <= 1e-9 * incoming.norm() { from } else { a };
                    let curve = Bezier::new(vec![a, at, at + v * d]).ok()?;
                    checker.bezier_is_free(&curve).then_some(curve)
                });
            let next = round.as_ref().map_or(at, Bezier::start);
            if next != from {
                connectors.push((pieces.len(), from_corner, i));
                pieces.push(Bezier::line(from, next));
            }
            from_corner = i;
            match round {
                Some(curve) => {
                    from = curve.end();
                    pieces.push(curve);
                }
                None => {
                    kept += usize::from(!straight);
                    from = at;
                }
            }
        }
        let last = points[n - 1];
        if from != last {
            connectors.push((pieces.len(), from_corner, n - 1));
            pieces.push(Bezier::line(from, last));
        }
        // A connector not proven free (rounding puts its computed ends a hair off the leg):
        // keep the corners it spans sharp and start again. Between two sharp corners it is the
        // input's own leg.
        let mut sharpened = false;
        for &(k, first, end) in &connectors {
            if !checker.segment_is_free(pieces[k].start(), pieces[k].end()) {
                for corner in sharp.iter_mut().take(end.min(n - 2) + 1).skip(first.max(1)) {
                    sharpened |= !*corner;
                    *corner = true;
                }
            }
        }
        if !sharpened {
            return Smoothed { pieces, kept };
        }
    }
}

fn bspline<C: Clearance + ?Sized>(checker: &C, points: &[Point]) -> Result<Smoothed, CurveError> {
    let n = points.len();
    let pinned = SHRINKS + 1;
    // How tightly each waypoint holds the curve: 0 alone; 1..=SHRINKS flanked by control points
    // on its legs, half a shorter leg from it at 1 and halving at each level; pinned: on the
    // curve, which splits there (the ends are pinned).
    let mut level = vec![0usize; n];
    level[0] = pinned;
    level[n - 1] = pinned;
    loop {
        let mut pieces = Vec::new();
        let mut tighten = vec![false; n];
        let pins: Vec<usize> = (0..n).filter(|&i| level[i] == pinned).collect();
        for stretch in pins.windows(2) {
            let (first, last) = (stretch[0], stretch[1]);
            if last == first + 1 {
                pieces.push(Bezier::line(points[first], points[last])); // the input's own leg
                continue;
            }
            let mut control = vec![points[first]];
            let mut owner = vec![first];
            for i in first + 1..last {
                let (at, u, v) = (points[i], points[i] - points[i - 1], points[i + 1] - points[i]);
                let flank = 0.5 * u.norm().min(v.norm()) * 0.5f64.powi(level[i] as i32 - 1);
                let around = match level[i] {
                    0 => vec![at],
                    _ => vec![at - u.normalize() * flank, at, at + v.normalize() * flank],
                };
                owner.extend(std::iter::repeat_n(i, around.len()));
                control.extend(around);
            }
            control.push(points[last]);
            owner.push(last);
            let degree = 3.min(control.len() - 1);
            // Span j is shaped by control points j..=j + degree, among which is always a
            // waypoint between the stretch's ends: tighten those of a span not proven free.
            for (j, piece) in BSpline::clamped_uniform(degree, control)?.to_beziers().into_iter().enumerate()
            {
                if !checker.bezier_is_free(&piece) {
                    for &w in &owner[j..=j + degree] {
                        tighten[w] = w != first && w != last;
                    }
                }
                pieces.push(piece);
            }
        }
        if !tighten.contains(&true) {
            let kept = level[1..n - 1].iter().filter(|&&l| l == pinned).count();
            let pieces =
                pieces.into_iter().filter(|b| b.control_points().iter().any(|&p| p != b.start())).collect();
            return Ok(Smoothed { pieces, kept });
        }
        for (w, _) in tighten.iter().enumerate().filter(|(_, t)| **t) {
            level[w] += 1;
        }
    }
}
