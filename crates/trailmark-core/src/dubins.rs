//! Dubins curves: the shortest paths of a vehicle that only drives forward, at unit speed, with
//! a bounded turning radius.
//!
//! Dubins (1957) showed that such a shortest path between two poses is made of at most three
//! pieces, each a left turn (`L`) or right turn (`R`) at the minimum turning radius or a straight
//! segment (`S`), in one of six *words*: `LSL`, `LSR`, `RSL`, `RSR`, `RLR`, `LRL`.
//! [`DubinsPath::shortest`] tries all six with the closed forms of Shkel and Lumelsky (2001) and
//! keeps the shortest; [`DubinsPath::with_word`] builds one given word.
//!
//! Poses are [`Pose`]s (nalgebra `Isometry2`): position in world units, heading in radians,
//! counter-clockwise from +x. A path can be measured ([`DubinsPath::length`]), evaluated at any
//! arc length ([`DubinsPath::pose_at`]), sampled ([`DubinsPath::sample`]), cut
//! ([`DubinsPath::subpath`]), and taken apart into exact arcs and segments
//! ([`DubinsPath::pieces`]) for collision checks.
//!
//! # Supported range
//!
//! Coordinates and the turning radius are at most [`MAX_MAGNITUDE`] (1e300) in magnitude, so
//! every length, centre and position a path computes is a finite `f64`; and the poses are at
//! most [`MAX_NORMALISED_DISTANCE`] (1e12) turning radii apart. The pieces are computed in units
//! of the turning radius, to within a few units in the last place of that distance: at 1e12
//! radii that is about a ten-thousandth of a radius, beyond it (a radius of 1e-200 between
//! poses a unit apart) the turns could not be resolved at all, and the squares of the
//! normalised distance would overflow. A query outside the range is a typed error
//! ([`DubinsError::InvalidRadius`], [`DubinsError::NonFinitePose`], [`DubinsError::OutOfScale`]),
//! never a panic. Sampling returns at most [`MAX_SAMPLES`] poses
//! ([`DubinsError::TooManySamples`] beyond), whatever the step.
//!
//! ```
//! use std::f64::consts::PI;
//! use trailmark_core::dubins::{DubinsPath, DubinsWord};
//! use trailmark_core::geometry::{Pose, Vector};
//!
//! // From the origin facing +x to (4, 0) facing back: turn around with a radius of 1.
//! let start = Pose::new(Vector::new(0.0, 0.0), 0.0);
//! let goal = Pose::new(Vector::new(4.0, 0.0), PI);
//! let path = DubinsPath::shortest(&start, &goal, 1.0)?;
//! let end = path.end();
//! assert!((end.translation.vector - goal.translation.vector).norm() < 1e-9);
//! assert!(path.length() > 4.0); // longer than the straight line
//! // No word is shorter.
//! for word in DubinsWord::ALL {
//!     if let Ok(other) = DubinsPath::with_word(&start, &goal, 1.0, word) {
//!         assert!(path.length() <= other.length() + 1e-12);
//!     }
//! }
//!
//! // Poses along the way, every 0.1 units, the end included.
//! let poses = path.sample(0.1)?;
//! assert_eq!(poses.len(), (path.length() / 0.1).ceil() as usize + 1);
//! # Ok::<(), trailmark_core::dubins::DubinsError>(())
//! ```

use std::f64::consts::TAU;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::curve::MAX_SAMPLES;
use crate::geometry::{Point, Pose, Vector};

/// The largest magnitude of a coordinate or of the turning radius: 1e300. Within it the
/// distance between two poses, a path's length (at most the distance plus three full turns)
/// and every centre and position along it are finite.
pub const MAX_MAGNITUDE: f64 = 1e300;

/// The largest distance between two poses, in turning radii: 1e12 (see the
/// [module documentation](self#supported-range)).
pub const MAX_NORMALISED_DISTANCE: f64 = 1e12;

/// The largest turning radius beside the extent of the poses a planner joins (the diagonal of
/// its bounds): 1e3. The solver's answers are accurate to a small fraction of the radius, and
/// near its degenerate cases (two circles that touch) to about 1e-7 radii: with a radius a
/// thousand times the world, that is still 1e-4 of the world, where a radius of 1e10 in a world
/// of 10 had called two poses 1 apart the same. Checked by the Dubins state space and roadmap
/// steering, not by [`DubinsPath::shortest`] (which sees no bounds).
pub const MAX_RADIUS_PER_EXTENT: f64 = 1e3;

/// A turning radius outside the supported range for poses within an extent (the diagonal of
/// the bounds a planner works in): the diagonal more than [`MAX_NORMALISED_DISTANCE`] radii,
/// or the radius more than [`MAX_RADIUS_PER_EXTENT`] diagonals.
#[derive(Clone, Copy, Debug, Error, PartialEq)]
#[error(
    "a turning radius of {turning_radius:e} in bounds {diagonal:e} across is outside the supported range (the diagonal at most {max:e} radii, the radius at most {ratio:e} diagonals)",
    max = MAX_NORMALISED_DISTANCE, ratio = MAX_RADIUS_PER_EXTENT
)]
pub struct RadiusOutOfScale {
    /// The turning radius.
    pub turning_radius: f64,
    /// The diagonal of the bounds.
    pub diagonal: f64,
}

/// Whether Dubins paths of `turning_radius` between any two poses within bounds `diagonal`
/// across are in the solver's supported range (and the radius itself at most
/// [`MAX_MAGNITUDE`]).
pub fn check_extent(turning_radius: f64, diagonal: f64) -> Result<(), RadiusOutOfScale> {
    if turning_radius <= MAX_MAGNITUDE
        && diagonal / turning_radius <= MAX_NORMALISED_DISTANCE
        && turning_radius <= MAX_RADIUS_PER_EXTENT * diagonal
    {
        Ok(())
    } else {
        Err(RadiusOutOfScale { turning_radius, diagonal })
    }
}

/// The largest normalised length of a straight piece: the distance between the poses plus at
/// most four radii for the circles' offsets.
const MAX_STRAIGHT_PARAM: f64 = MAX_NORMALISED_DISTANCE + 4.0;

/// What a piece of a Dubins path does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Turn {
    /// A counter-clockwise arc at the turning radius.
    Left,
    /// A straight segment.
    Straight,
    /// A clockwise arc at the turning radius.
    Right,
}

/// The six kinds of Dubins path, named by their three pieces (`L`eft, `S`traight, `R`ight).
///
/// In JSON a word is written in capitals: `"LSL"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "UPPERCASE")]
pub enum DubinsWord {
    /// Left, straight, left.
    Lsl,
    /// Left, straight, right.
    Lsr,
    /// Right, straight, left.
    Rsl,
    /// Right, straight, right.
    Rsr,
    /// Right, left, right.
    Rlr,
    /// Left, right, left.
    Lrl,
}

impl DubinsWord {
    /// All six words.
    pub const ALL: [DubinsWord; 6] = [
        DubinsWord::Lsl,
        DubinsWord::Lsr,
        DubinsWord::Rsl,
        DubinsWord::Rsr,
        DubinsWord::Rlr,
        DubinsWord::Lrl,
    ];

    /// The three pieces of the word, in order.
    pub const fn turns(self) -> [Turn; 3] {
        use Turn::{Left as L, Right as R, Straight as S};
        match self {
            DubinsWord::Lsl => [L, S, L],
            DubinsWord::Lsr => [L, S, R],
            DubinsWord::Rsl => [R, S, L],
            DubinsWord::Rsr => [R, S, R],
            DubinsWord::Rlr => [R, L, R],
            DubinsWord::Lrl => [L, R, L],
        }
    }

    /// The word in capitals, as in the literature: `"LSL"`.
    pub const fn name(self) -> &'static str {
        match self {
            DubinsWord::Lsl => "LSL",
            DubinsWord::Lsr => "LSR",
            DubinsWord::Rsl => "RSL",
            DubinsWord::Rsr => "RSR",
            DubinsWord::Rlr => "RLR",
            DubinsWord::Lrl => "LRL",
        }
    }
}

impl std::fmt::Display for DubinsWord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// What was wrong with a Dubins query.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DubinsError {
    /// The turning radius must be positive and at most [`MAX_MAGNITUDE`].
    #[error("the turning radius must be positive and at most {MAX_MAGNITUDE:e}, got {0:?}")]
    InvalidRadius(f64),
    /// A pose has a NaN or infinite coordinate or heading, a coordinate beyond
    /// [`MAX_MAGNITUDE`] in magnitude, or a rotation that is not a unit complex number (its
    /// norm off 1 by more than 1e-6).
    #[error(
        "the {which} pose is not finite, within +-{MAX_MAGNITUDE:e}, with a unit rotation: ({x}, {y}), rotation ({cos}, {sin})"
    )]
    NonFinitePose {
        /// `"start"` or `"goal"`.
        which: &'static str,
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
        /// The cosine of its heading.
        cos: f64,
        /// The sine of its heading.
        sin: f64,
    },
    /// The requested word cannot join the two poses (the shortest path always exists).
    #[error("no {0} path joins these poses")]
    NoPath(DubinsWord),
    /// An arc length outside `[0, length]`.
    #[error("arc length {s} is outside the path, whose length is {length}")]
    OutOfRange {
        /// The arc length asked for.
        s: f64,
        /// The path's length.
        length: f64,
    },
    /// A sampling step must be positive and finite.
    #[error("the sampling step must be positive and finite, got {0}")]
    InvalidStep(f64),
    /// The poses are more than [`MAX_NORMALISED_DISTANCE`] turning radii apart: outside the
    /// supported range (see the [module documentation](self#supported-range)).
    #[error(
        "the poses are {distance:e} apart, more than {MAX_NORMALISED_DISTANCE:e} turning radii of {radius:e}: outside the supported range"
    )]
    OutOfScale {
        /// The distance between the poses.
        distance: f64,
        /// The turning radius.
        radius: f64,
    },
    /// Sampling the path with this step would take more than [`MAX_SAMPLES`] poses.
    #[error("sampling a path of length {length:e} every {step:e} takes more than {MAX_SAMPLES} poses")]
    TooManySamples {
        /// The path's length.
        length: f64,
        /// The step asked for.
        step: f64,
    },
    /// A deserialized path that no query could give: a radius, start or piece out of range.
    #[error("not a valid Dubins path: {0}")]
    InvalidPath(&'static str),
}

/// One piece of a Dubins path in world coordinates: what collision checks test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// A circular arc.
    Arc {
        /// The centre of the circle.
        center: Point,
        /// The radius (the path's turning radius).
        radius: f64,
        /// The angle of the arc's first point as seen from the centre, in radians.
        start_angle: f64,
        /// The signed angle swept: positive counter-clockwise (a left turn), negative clockwise.
        sweep: f64,
    },
    /// A straight segment.
    Segment {
        /// Where it starts.
        from: Point,
        /// Where it ends.
        to: Point,
    },
}

/// A Dubins path: a start pose, a turning radius, a word and the length of each of its three
/// pieces.
///
/// Serializes as `{"start": [x, y, heading], "turning_radius": r, "word": "LSL", "params": [t, p,
/// q]}`, with `params` the pieces' lengths divided by the radius (a turn's angle in radians).
/// Deserializing checks what a query would: the start and radius in the supported range, each
/// turn in `[0, 2π]`, the straight piece at most [`MAX_NORMALISED_DISTANCE`] + 4 radii
/// ([`DubinsError::InvalidPath`] otherwise).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "RawPath")]
pub struct DubinsPath {
    start: Start,
    turning_radius: f64,
    word: DubinsWord,
    params: [f64; 3],
}

/// A [`DubinsPath`] as written, before it is checked.
#[derive(Deserialize)]
struct RawPath {
    start: Start,
    turning_radius: f64,
    word: DubinsWord,
    params: [f64; 3],
}

impl TryFrom<RawPath> for DubinsPath {
    type Error = DubinsError;

    fn try_from(raw: RawPath) -> Result<Self, DubinsError> {
        let RawPath { start, turning_radius, word, params } = raw;
        check_radius(turning_radius)
            .map_err(|_| DubinsError::InvalidPath("the turning radius is out of range"))?;
        check_pose("start", &start.pose())
            .map_err(|_| DubinsError::InvalidPath("the start is out of range"))?;
        for (turn, param) in word.turns().into_iter().zip(params) {
            let max = if turn == Turn::Straight { MAX_STRAIGHT_PARAM } else { TAU };
            if !(0.0..=max).contains(&param) {
                return Err(DubinsError::InvalidPath("a piece is negative, not finite, or too long"));
            }
        }
        // What a query can give: at most the distance (< 3e300) plus three turns and four radii.
        let length = (params[0] + params[1] + params[2]) * turning_radius;
        if !(length.is_finite() && length <= 32.0 * MAX_MAGNITUDE) {
            return Err(DubinsError::InvalidPath("the path is longer than any in the supported range"));
        }
        Ok(DubinsPath { start, turning_radius, word, params })
    }
}

/// The start of a path as the caller's pose holds it: a position and the cosine and sine of
/// the heading. The heading's angle is taken only when the path is evaluated, so finding a
/// path costs no `atan2` for it. Serialized as `[x, y, heading]`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Start {
    x: f64,
    y: f64,
    cos: f64,
    sin: f64,
}

impl Start {
    fn of(pose: &Pose) -> Self {
        let v = pose.translation.vector;
        Start { x: v.x, y: v.y, cos: pose.rotation.re, sin: pose.rotation.im }
    }

    /// `[x, y, heading]`, the heading in `[0, 2π)`.
    fn array(&self) -> [f64; 3] {
        [self.x, self.y, mod_tau(self.sin.atan2(self.cos))]
    }

    fn pose(&self) -> Pose {
        let rotation = nalgebra::UnitComplex::from_cos_sin_unchecked(self.cos, self.sin);
        Pose::from_parts(nalgebra::Translation2::new(self.x, self.y), rotation)
    }
}

impl Serialize for Start {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.array().serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Start {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let [x, y, heading] = <[f64; 3]>::deserialize(deserializer)?;
        // A heading of any finite size has a finite sine and cosine; NaN ones are refused when
        // the path is checked.
        let (sin, cos) = heading.sin_cos();
        Ok(Start { x, y, cos, sin })
    }
}

/// A query in the normalised frame of Shkel and Lumelsky: the start at the origin, the goal on
/// the +x axis at distance `d` (in turning radii), headings `α` and `β` relative to the line
/// between them.
///
/// The headings are kept as cosines and sines, and only their difference `D = (β - α) mod 2π`
/// as an angle: every turn angle of every word is then one `atan2` of a vector turned by `-α`
/// (the first turn), and the last turn follows from `D` (the turns and the middle piece of a
/// word add up to `β - α` modulo 2π).
#[derive(Debug, Clone, Copy)]
struct Normalised {
    d: f64,
    sa: f64,
    ca: f64,
    sb: f64,
    cb: f64,
    /// `cos(β - α)`.
    cab: f64,
    /// `sin(β - α)`.
    sab: f64,
    /// `(β - α) mod 2π`.
    turns: f64,
}

/// `x` modulo 2π, in `[0, 2π)` (NaN for NaN or an infinity). Arguments are almost always within
/// a few turns of the range, where a loop of additions beats a division and a call to `floor`;
/// others take the remainder, so no argument makes the loop long.
#[inline]
fn mod_tau(mut x: f64) -> f64 {
    if x.is_nan() || x.abs() > 8.0 * TAU {
        let r = x.rem_euclid(TAU);
        return if r < TAU { r } else { 0.0 };
    }
    while x < 0.0 {
        x += TAU;
    }
    while x >= TAU {
        x -= TAU;
    }
    x
}

impl Normalised {
    fn new(start: &Pose, goal: &Pose, radius: f64) -> Result<Self, DubinsError> {
        check_radius(radius)?;
        check_pose("start", start)?;
        check_pose("goal", goal)?;
        let delta = goal.translation.vector - start.translation.vector;
        // Finite, both positions being within MAX_MAGNITUDE; by `hypot`, since the plain norm
        // squares the components and overflows beyond 1e154.
        let dist = delta.x.hypot(delta.y);
        if dist / radius > MAX_NORMALISED_DISTANCE {
            return Err(DubinsError::OutOfScale { distance: dist, radius });
        }
        // The direction of the line from start to goal (+x when they coincide).
        let (cphi, sphi) = if dist > 0.0 { (delta.x / dist, delta.y / dist) } else { (1.0, 0.0) };
        // Headings relative to that line, through the rotations' cosines and sines: no sin or
        // cos to evaluate.
        let (c0, s0) = (start.rotation.re, start.rotation.im);
        let (c1, s1) = (goal.rotation.re, goal.rotation.im);
        let (ca, sa) = (c0 * cphi + s0 * sphi, s0 * cphi - c0 * sphi);
        let (cb, sb) = (c1 * cphi + s1 * sphi, s1 * cphi - c1 * sphi);
        // β - α does not depend on the line: it is the goal's heading less the start's.
        let (cab, sab) = (c0 * c1 + s0 * s1, s1 * c0 - c1 * s0);
        Ok(Normalised { d: dist / radius, sa, ca, sb, cb, cab, sab, turns: mod_tau(sab.atan2(cab)) })
    }

    /// `(θ - α) mod 2π` for the direction `θ` of the vector `(x, y)`.
    #[inline]
    fn turn_after_alpha(&self, x: f64, y: f64) -> f64 {
        mod_tau((y * self.ca - x * self.sa).atan2(x * self.ca + y * self.sa))
    }

    /// `(α - θ) mod 2π` for the direction `θ` of the vector `(x, y)`.
    #[inline]
    fn turn_before_alpha(&self, x: f64, y: f64) -> f64 {
        mod_tau((x * self.sa - y * self.ca).atan2(x * self.ca + y * self.sa))
    }

    /// The normalised lengths of `word`'s three pieces, or `None` when it cannot join the poses.
    #[inline]
    fn params(&self, word: DubinsWord) -> Option<[f64; 3]> {
        let Normalised { d, sa, ca, sb, cb, turns, .. } = *self;
        match word {
            DubinsWord::Lsl | DubinsWord::Rsr => {
                // (x, y) runs along the straight piece and is exactly as long: its length is the
                // better-conditioned measure of p near 0 (the square's formula cancels terms of
                // size d² + 2), and shows that these two words always exist.
                let (_, x, y) = self.same_side(word);
                let p = (x * x + y * y).sqrt();
                // t = θ - α (LSL) or α - θ (RSR); the turns add up to `whole` modulo 2π.
                let (mut t, whole) = if word == DubinsWord::Lsl {
                    (self.turn_after_alpha(x, y), turns)
                } else {
                    (self.turn_before_alpha(x, y), mod_tau(-turns))
                };
                // The straight piece's direction is only as good as its coordinates over its
                // length: when that uncertainty could put t on the wrong side of `whole` (or of
                // 0), which would add a full turn, keep t in [0, whole]. The end moves by at most
                // p times the uncertainty. Once the coordinates' error reaches p (the two
                // circles are one, as for two poses on one arc), the direction is not known at
                // all: any t may be the true one.
                let ratio = 1e-14 * (2.0 + d) / p;
                let noise = if ratio >= 1.0 { std::f64::consts::PI } else { ratio.asin() };
                if t > whole && (t - whole <= noise || TAU - t <= noise) {
                    t = if t - whole <= TAU - t { whole } else { 0.0 };
                }
                Some([t, p, mod_tau(whole - t)])
            }
            DubinsWord::Lsr | DubinsWord::Rsl => {
                let p = self.opposite_side(word)?;
                // θ = atan2(-ca - cb, d + sa + sb) - atan2(-2, p) for LSR, atan2(ca + cb, d - sa
                // - sb) - atan2(2, p) for RSL, each as the angle of one product. t = θ - α (LSR)
                // or α - θ (RSL); q = t - D (LSR) or t + D (RSL).
                let (t, shift) = if word == DubinsWord::Lsr {
                    let (x, y) = (d + sa + sb, -ca - cb);
                    (self.turn_after_alpha(x * p - 2.0 * y, 2.0 * x + y * p), -turns)
                } else {
                    let (x, y) = (d - sa - sb, ca + cb);
                    (self.turn_before_alpha(x * p + 2.0 * y, y * p - 2.0 * x), turns)
                };
                // θ moves with p, which rounding blurs most when it is near 0 (the circles
                // touch): a turn that uncertainty leaves just below 2π is a turn of 0.
                let noise = self.p_noise(p) + 1e-14 * (1.0 + d);
                let t = if TAU - t <= noise { 0.0 } else { t };
                let q = mod_tau(t + shift);
                if TAU - q <= noise { Some([mod_tau(-shift), p, 0.0]) } else { Some([t, p, q]) }
            }
            DubinsWord::Rlr => {
                let p = self.middle_turn(word)?;
                let t = mod_tau(self.turn_before_alpha(d - sa + sb, ca - cb) + p / 2.0);
                Some([t, p, mod_tau(p - t - turns)])
            }
            DubinsWord::Lrl => {
                let p = self.middle_turn(word)?;
                let t = mod_tau(self.turn_after_alpha(d + sa - sb, cb - ca) + p / 2.0);
                Some([t, p, mod_tau(p - t + turns)])
            }
        }
    }

    /// A bound on the rounding error of the square of a straight piece's normalised length
    /// (some tens of units in the last place of `(2 + d)²`: the terms cancel down from there). A square that far below 0 is taken as 0:
    /// poses on one arc, or on two touching circles, come out on either side of it, and
    /// rejecting them would send the query to a word a full turn longer.
    #[inline]
    fn p2_noise(&self) -> f64 {
        1e-14 * (2.0 + self.d) * (2.0 + self.d)
    }

    /// The rounding error of a straight piece's normalised length `p`, from its square's.
    #[inline]
    fn p_noise(&self, p: f64) -> f64 {
        let e = self.p2_noise();
        if p * p <= e { e.sqrt() } else { e / (2.0 * p) }
    }

    /// For `LSR` or `RSL`: the straight piece's normalised length, `None` when the circles
    /// overlap so the word cannot join the poses.
    #[inline]
    fn opposite_side(&self, word: DubinsWord) -> Option<f64> {
        let Normalised { d, sa, sb, cab, .. } = *self;
        let sign = if word == DubinsWord::Lsr { 1.0 } else { -1.0 };
        let p2 = -2.0 + d * d + 2.0 * cab + sign * 2.0 * d * (sa + sb);
        (p2 >= -self.p2_noise()).then(|| p2.max(0.0).sqrt())
    }

    /// For `RLR` or `LRL`: the middle turn's angle, `None` when the poses are too far apart.
    #[inline]
    fn middle_turn(&self, word: DubinsWord) -> Option<f64> {
        let Normalised { d, sa, sb, cab, .. } = *self;
        let sign = if word == DubinsWord::Rlr { 1.0 } else { -1.0 };
        let c = (6.0 - d * d + 2.0 * cab + sign * 2.0 * d * (sa - sb)) / 8.0;
        (c.abs() <= 1.0).then(|| mod_tau(TAU - c.acos()))
    }

    /// The shortest word, its normalised length, and its parameters when they were evaluated
    /// on the way (one word always joins the poses). Ties go to the word first in
    /// [`DubinsWord::ALL`].
    ///
    /// `LSL` and `RSR` are measured without their turn angles (see [`Normalised::same_side`]),
    /// so they cost no `atan2`. A word whose length cannot beat the best so far is skipped
    /// without its `atan2`: `LSR` and `RSL` are at least their straight piece plus the smaller
    /// of `D` and `2π - D` (their turns differ by `D` modulo 2π), `RLR` and `LRL` at least
    /// their middle turn.
    fn shortest_word(&self) -> (DubinsWord, f64, Option<[f64; 3]>) {
        type Best = (DubinsWord, f64, Option<[f64; 3]>);
        fn offer(best: &mut Best, word: DubinsWord, length: f64, params: Option<[f64; 3]>) {
            let rank = |w: DubinsWord| DubinsWord::ALL.iter().position(|&a| a == w);
            if length < best.1 || (length == best.1 && rank(word) < rank(best.0)) {
                *best = (word, length, params);
            }
        }
        let mut best: Best = (DubinsWord::Lsl, f64::INFINITY, None);
        for word in [DubinsWord::Lsl, DubinsWord::Rsr] {
            match self.same_side_length(word) {
                Some(Some(length)) => offer(&mut best, word, length, None),
                Some(None) => {}
                None => {
                    if let Some(params) = self.params(word) {
                        offer(&mut best, word, params.iter().sum(), Some(params));
                    }
                }
            }
        }
        let least_turns = self.turns.min(TAU - self.turns);
        for word in [DubinsWord::Lsr, DubinsWord::Rsl] {
            if let Some(p) = self.opposite_side(word)
                && p + least_turns <= best.1
                && let Some(params) = self.params(word)
            {
                offer(&mut best, word, params.iter().sum(), Some(params));
            }
        }
        for word in [DubinsWord::Rlr, DubinsWord::Lrl] {
            if let Some(p) = self.middle_turn(word)
                && p <= best.1
                && let Some(params) = self.params(word)
            {
                offer(&mut best, word, params.iter().sum(), Some(params));
            }
        }
        best
    }

    /// The shortest word and its parameters; `None` only if rounding left no word, which the
    /// supported range rules out (`LSL` always joins the poses there).
    fn shortest(&self) -> Option<(DubinsWord, [f64; 3])> {
        let (word, length, params) = self.shortest_word();
        let params = params.or_else(|| self.params(word))?;
        debug_assert!(
            (params.iter().sum::<f64>() - length).abs() <= 1e-6 * (1.0 + length),
            "{word} measured {length} but evaluates to {params:?}",
        );
        Some((word, params))
    }

    /// The error for a query that rounding left without a path (see [`Normalised::shortest`]).
    fn unsolved(&self, radius: f64) -> DubinsError {
        DubinsError::OutOfScale { distance: self.d * radius, radius }
    }

    /// For `LSL` or `RSR` (which join any two poses): the square of the straight piece's
    /// normalised length, and the vector `(x, y)` of the straight piece, along its direction `θ`.
    ///
    /// The square is taken of the vector rather than expanded (`2 + d² - 2 cos(α - β) ±
    /// 2d (sin α - sin β)`), whose terms cancel between poses a small fraction of a radius apart.
    #[inline]
    fn same_side(&self, word: DubinsWord) -> (f64, f64, f64) {
        let Normalised { d, sa, ca, sb, cb, .. } = *self;
        let (x, y) = if word == DubinsWord::Lsl { (d + sa - sb, cb - ca) } else { (d - sa + sb, ca - cb) };
        (x * x + y * y, x, y)
    }

    /// The normalised length of `LSL` or `RSR` without evaluating their turn angles: `Some(None)`
    /// when the word cannot join the poses, `None` when the answer is too close to call (then
    /// [`Normalised::params`] decides).
    ///
    /// For `LSL`, the turns `t = θ - α` and `q = β - θ` (mod 2π) add up to `β - α` (mod 2π), so
    /// `t + q` is `D = (β - α) mod 2π`, or `D + 2π` when `t > D`. Whether `t > D` is an
    /// orientation test between two vectors, without an angle. `RSR` is its mirror image.
    #[inline]
    fn same_side_length(&self, word: DubinsWord) -> Option<Option<f64>> {
        let Normalised { sa, ca, cab, sab, turns, .. } = *self;
        let (p2, x, y) = self.same_side(word);
        let (x, y, turns, sin_turns) = match word {
            // (x, y) points along θ; turned by -α it points along t.
            DubinsWord::Lsl => (x * ca + y * sa, y * ca - x * sa, turns, sab),
            // The direction of α turned by -θ points along t = α - θ.
            _ => (ca * x + sa * y, sa * x - ca * y, mod_tau(-turns), -sab),
        };
        // A straight piece so short (or a square rounded below 0) that its direction is uncertain beyond the margin below:
        // let the full evaluation decide.
        if p2 <= 1e-10 * (1.0 + self.d) * (1.0 + self.d) {
            return None;
        }
        let p2 = p2.max(0.0);
        // t and D as the angles of vectors in [0, 2π): u for t, w for D.
        let (u, w) = ((x, y), (cab, sin_turns));
        const CLOSE: f64 = 1e-9;
        // Squared norms, compared with squares: no square roots.
        let (nu2, nw2) = (u.0 * u.0 + u.1 * u.1, w.0 * w.0 + w.1 * w.1);
        // Too close to call: t or D near 0 (where mod 2π jumps), or t near D.
        let cross = w.0 * u.1 - w.1 * u.0;
        let (hu, hw) = (lower_half(u), lower_half(w));
        const CLOSE2: f64 = CLOSE * CLOSE;
        if (u.1 * u.1 <= CLOSE2 * nu2 && u.0 > 0.0)
            || (w.1 * w.1 <= CLOSE2 * nw2 && w.0 > 0.0)
            || (hu == hw && cross * cross <= CLOSE2 * nu2 * nw2)
            || nu2 == 0.0
        {
            return None;
        }
        let t_beyond_d = if hu == hw { cross > 0.0 } else { hu };
        let extra = if t_beyond_d { TAU } else { 0.0 };
        Some(Some(p2.sqrt() + turns + extra))
    }
}

/// Whether the angle of `(x, y)` in `[0, 2π)` is at least π (as `atan2` then mod 2π says).
#[inline]
fn lower_half((x, y): (f64, f64)) -> bool {
    !(y > 0.0 || (y == 0.0 && x >= 0.0))
}

fn check_radius(radius: f64) -> Result<(), DubinsError> {
    if radius > 0.0 && radius <= MAX_MAGNITUDE { Ok(()) } else { Err(DubinsError::InvalidRadius(radius)) }
}

fn check_pose(which: &'static str, pose: &Pose) -> Result<(), DubinsError> {
    let (x, y) = (pose.translation.vector.x, pose.translation.vector.y);
    let (cos, sin) = (pose.rotation.re, pose.rotation.im);
    let in_range = x.abs() <= MAX_MAGNITUDE && y.abs() <= MAX_MAGNITUDE;
    // Written so that NaN fails; a finite cos and sin of a unit rotation are within [-1, 1].
    let unit = cos.abs() <= 1.5 && sin.abs() <= 1.5 && (cos * cos + sin * sin - 1.0).abs() <= 1e-6;
    if in_range && unit { Ok(()) } else { Err(DubinsError::NonFinitePose { which, x, y, cos, sin }) }
}

/// The pose after driving `length` (world units) along `turn` from `(x, y, heading)`.
#[inline]
fn advance(pose: [f64; 3], turn: Turn, length: f64, radius: f64) -> [f64; 3] {
    let [x, y, h] = pose;
    match turn {
        Turn::Straight => [x + length * h.cos(), y + length * h.sin(), h],
        Turn::Left => {
            let h2 = h + length / radius;
            [x + radius * (h2.sin() - h.sin()), y - radius * (h2.cos() - h.cos()), mod_tau(h2)]
        }
        Turn::Right => {
            let h2 = h - length / radius;
            [x - radius * (h2.sin() - h.sin()), y + radius * (h2.cos() - h.cos()), mod_tau(h2)]
        }
    }
}

fn to_pose([x, y, h]: [f64; 3]) -> Pose {
    Pose::new(Vector::new(x, y), h)
}

impl DubinsPath {
    /// The shortest path from `start` to `goal` for a vehicle whose turning radius is
    /// `turning_radius` (world units).
    ///
    /// Errors outside the [supported range](self#supported-range): a radius that is not
    /// positive or beyond [`MAX_MAGNITUDE`], a pose that is not finite or beyond it, poses more
    /// than [`MAX_NORMALISED_DISTANCE`] radii apart.
    pub fn shortest(start: &Pose, goal: &Pose, turning_radius: f64) -> Result<DubinsPath, DubinsError> {
        let n = Normalised::new(start, goal, turning_radius)?;
        let (word, params) = n.shortest().ok_or_else(|| n.unsolved(turning_radius))?;
        Ok(DubinsPath { start: Start::of(start), turning_radius, word, params })
    }

    /// The length of the shortest path from `start` to `goal`: [`DubinsPath::shortest`]'s
    /// length up to rounding, without building the path (when the shortest word is `LSL` or
    /// `RSR`, without evaluating a single angle of it).
    pub fn shortest_length(start: &Pose, goal: &Pose, turning_radius: f64) -> Result<f64, DubinsError> {
        let n = Normalised::new(start, goal, turning_radius)?;
        let (_, length, _) = n.shortest_word();
        let length = length * turning_radius;
        if length.is_finite() { Ok(length) } else { Err(n.unsolved(turning_radius)) }
    }

    /// The path of the given `word` from `start` to `goal`.
    ///
    /// Errors as [`DubinsPath::shortest`] does, and with [`DubinsError::NoPath`] when that word
    /// cannot join the poses (a `CSC` word whose circles overlap the wrong way, a `CCC` word for
    /// poses more than four radii apart).
    pub fn with_word(
        start: &Pose,
        goal: &Pose,
        turning_radius: f64,
        word: DubinsWord,
    ) -> Result<DubinsPath, DubinsError> {
        let n = Normalised::new(start, goal, turning_radius)?;
        let params = n.params(word).ok_or(DubinsError::NoPath(word))?;
        Ok(DubinsPath { start: Start::of(start), turning_radius, word, params })
    }

    /// The path's word.
    pub fn word(&self) -> DubinsWord {
        self.word
    }

    /// The turning radius, in world units.
    pub fn turning_radius(&self) -> f64 {
        self.turning_radius
    }

    /// The lengths of the three pieces divided by the turning radius: a turn's angle in
    /// radians, the straight piece's length in radii.
    pub fn normalised_params(&self) -> [f64; 3] {
        self.params
    }

    /// The lengths of the three pieces, in world units.
    pub fn segment_lengths(&self) -> [f64; 3] {
        self.params.map(|p| p * self.turning_radius)
    }

    /// The total length, in world units.
    pub fn length(&self) -> f64 {
        (self.params[0] + self.params[1] + self.params[2]) * self.turning_radius
    }

    /// The start pose.
    pub fn start(&self) -> Pose {
        self.start.pose()
    }

    /// The pose at the end of the path: the goal, up to rounding.
    pub fn end(&self) -> Pose {
        to_pose(self.end_array())
    }

    fn end_array(&self) -> [f64; 3] {
        let lengths = self.segment_lengths();
        let mut pose = self.start.array();
        for (turn, length) in self.word.turns().into_iter().zip(lengths) {
            pose = advance(pose, turn, length, self.turning_radius);
        }
        pose
    }

    /// The pose after driving `s` world units along the path, `0 <= s <= length()`.
    ///
    /// Errors with [`DubinsError::OutOfRange`] for any other `s` (NaN included).
    pub fn pose_at(&self, s: f64) -> Result<Pose, DubinsError> {
        self.check_arc_length(s)?;
        Ok(to_pose(self.pose_array_at(self.start.array(), s)))
    }

    /// `Ok` when `0 <= s <= length()`, else [`DubinsError::OutOfRange`].
    fn check_arc_length(&self, s: f64) -> Result<(), DubinsError> {
        let length = self.length();
        if (0.0..=length).contains(&s) { Ok(()) } else { Err(DubinsError::OutOfRange { s, length }) }
    }

    /// The pose at arc length `s` in `[0, length]`, from the start `[x, y, heading]`.
    fn pose_array_at(&self, start: [f64; 3], s: f64) -> [f64; 3] {
        let mut pose = start;
        let mut left = s;
        for (turn, length) in self.word.turns().into_iter().zip(self.segment_lengths()) {
            let step = left.min(length);
            pose = advance(pose, turn, step, self.turning_radius);
            left -= step;
            if left <= 0.0 {
                break;
            }
        }
        pose
    }

    /// Poses every `step` world units from the start, then the end pose: `ceil(length / step)
    /// + 1` poses (one for a path of length 0).
    ///
    /// Errors with [`DubinsError::InvalidStep`] unless `step` is positive and finite, and with
    /// [`DubinsError::TooManySamples`] when that would be more than [`MAX_SAMPLES`] poses
    /// (checked before anything is allocated).
    pub fn sample(&self, step: f64) -> Result<Vec<Pose>, DubinsError> {
        if !(step > 0.0 && step.is_finite()) {
            return Err(DubinsError::InvalidStep(step));
        }
        let length = self.length();
        let count = (length / step).ceil() + 1.0;
        // The loop below makes at most one pose more than `count` (when `k * step` rounds
        // below the length), so MAX_SAMPLES - 1 leaves room. (A path's length is finite.)
        if count.is_nan() || count >= MAX_SAMPLES as f64 {
            return Err(DubinsError::TooManySamples { length, step });
        }
        let start = self.start.array();
        // In range: count < MAX_SAMPLES.
        let mut poses = Vec::with_capacity(count as usize + 1);
        let mut k = 0u64;
        loop {
            let s = k as f64 * step;
            if s >= length {
                break;
            }
            poses.push(to_pose(self.pose_array_at(start, s)));
            k += 1;
        }
        poses.push(self.end());
        Ok(poses)
    }

    /// The first `s` world units of the path, `0 <= s <= length()`: a path with the same start,
    /// radius and word, ending at [`pose_at(s)`](DubinsPath::pose_at).
    ///
    /// Errors with [`DubinsError::OutOfRange`] for any other `s`.
    pub fn subpath(&self, s: f64) -> Result<DubinsPath, DubinsError> {
        self.check_arc_length(s)?;
        let mut left = s / self.turning_radius;
        let mut params = [0.0; 3];
        for (out, full) in params.iter_mut().zip(self.params) {
            *out = left.min(full);
            left -= *out;
        }
        Ok(DubinsPath { params, ..*self })
    }

    /// The three pieces in world coordinates (a piece of length 0 included), for exact
    /// collision checks.
    pub fn pieces(&self) -> [Piece; 3] {
        let r = self.turning_radius;
        let mut pose = self.start.array();
        let lengths = self.segment_lengths();
        let turns = self.word.turns();
        std::array::from_fn(|i| {
            let [x, y, h] = pose;
            let next = advance(pose, turns[i], lengths[i], r);
            pose = next;
            match turns[i] {
                Turn::Straight => Piece::Segment { from: Point::new(x, y), to: Point::new(next[0], next[1]) },
                Turn::Left => Piece::Arc {
                    center: Point::new(x - r * h.sin(), y + r * h.cos()),
                    radius: r,
                    start_angle: mod_tau(h - std::f64::consts::FRAC_PI_2),
                    sweep: self.params[i],
                },
                Turn::Right => Piece::Arc {
                    center: Point::new(x + r * h.sin(), y - r * h.cos()),
                    radius: r,
                    start_angle: mod_tau(h + std::f64::consts::FRAC_PI_2),
                    sweep: -self.params[i],
                },
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    fn pose(x: f64, y: f64, h: f64) -> Pose {
        Pose::new(Vector::new(x, y), h)
    }

    /// The angle between two headings, in `[0, π]`.
    fn angle_between(a: f64, b: f64) -> f64 {
        let d = mod_tau(a - b);
        d.min(TAU - d)
    }

    fn close(a: &Pose, b: &Pose, tol: f64) -> bool {
        (a.translation.vector - b.translation.vector).norm() <= tol
            && angle_between(a.rotation.angle(), b.rotation.angle()) <= tol
    }

    /// Poses 1e200 apart with a radius of 1e199 are ten radii apart, in range: the plain norm
    /// of their offset overflowed to infinity and called them out of range (a Dubins space with
    /// a radius of 4e210 then panicked when its planner's steps went past 1e154).
    #[test]
    fn huge_offsets_are_measured_without_overflow() {
        let far = pose(1e200, 0.0, 0.0);
        let path = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &far, 1e199).unwrap();
        assert!((path.length() - 1e200).abs() <= 1e-9 * 1e200, "{}", path.length());
    }

    /// A left arc of angle φ from the origin, then a straight piece as long, for φ down to 1e-6:
    /// the length is twice the arc's, to nine digits.
    #[test]
    fn short_curves_keep_their_length() {
        for radius in [1.0f64, 0.125, 1e6] {
            for phi in [1e-3f64, 1e-4, 1e-5, 1e-6] {
                // The arc, then as long a straight piece.
                let s = radius * phi;
                let goal =
                    pose(radius * phi.sin() + s * phi.cos(), radius * (1.0 - phi.cos()) + s * phi.sin(), phi);
                let length = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &goal, radius).unwrap().length();
                let expected = 2.0 * radius * phi;
                assert!(
                    (length - expected).abs() <= 1e-9 * expected,
                    "radius {radius}, angle {phi}: {length} vs {expected}"
                );
            }
        }
    }

    #[test]
    fn coincident_poses_give_an_empty_path() {
        let p = pose(3.0, -2.0, 1.0);
        let path = DubinsPath::shortest(&p, &p, 2.0).unwrap();
        assert_eq!(path.length(), 0.0);
        assert!(close(&path.end(), &p, 1e-12));
        assert_eq!(path.sample(0.5).unwrap().len(), 1);
    }

    /// A pose a short arc ahead (or one arc then its mirror) is reached along those arcs, not a
    /// full turn later: the straight piece between them has length ~0 and no reliable
    /// direction, and its square may round below 0.
    #[test]
    fn poses_on_one_or_two_touching_arcs_are_found_despite_rounding() {
        let mut worst: f64 = 0.0;
        for i in 0..3000 {
            let (x, y, h) = (f64::from(i % 37) * 0.37 - 5.0, f64::from(i % 23) * 0.51, f64::from(i) * 0.0137);
            let a = pose(x, y, h);
            let r = 0.3 + f64::from(i % 5) * 0.4;
            for (word, arcs) in [
                (DubinsWord::Lsl, [0.01, 0.0]),
                (DubinsWord::Rsr, [0.01, 0.0]),
                (DubinsWord::Lsl, [0.3, 0.0]),
                (DubinsWord::Lsl, [2.5, 0.0]),
                (DubinsWord::Lsr, [0.2, 0.1]),
                (DubinsWord::Rsl, [0.05, 0.4]),
            ] {
                let b = DubinsPath {
                    start: Start::of(&a),
                    turning_radius: r,
                    word,
                    params: [arcs[0], 0.0, arcs[1]],
                }
                .end();
                let length = DubinsPath::shortest_length(&a, &b, r).unwrap();
                let shortest = DubinsPath::shortest(&a, &b, r).unwrap();
                // Such poses are ill-conditioned: a straight piece of length ~0 comes out of a
                // square root of rounding noise, about √ε of a radius.
                assert!(
                    close(&shortest.end(), &b, 1e-7 * r),
                    "{i} {word}: ends at {:?}, not {b:?}",
                    shortest.end()
                );
                worst = worst.max(length - (arcs[0] + arcs[1]) * r);
            }
        }
        assert!(worst < 1e-6, "{worst}");
    }

    #[test]
    fn straight_ahead_is_a_segment() {
        let path = DubinsPath::shortest(&pose(1.0, 1.0, PI / 2.0), &pose(1.0, 6.0, PI / 2.0), 1.0).unwrap();
        assert!((path.length() - 5.0).abs() < 1e-12);
        assert!(path.normalised_params()[0].abs() < 1e-12);
        assert!(matches!(path.pieces()[1], Piece::Segment { .. }));
    }

    #[test]
    fn bad_input_is_an_error() {
        let (a, b) = (pose(0.0, 0.0, 0.0), pose(1.0, 0.0, 0.0));
        for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(DubinsPath::shortest(&a, &b, r), Err(DubinsError::InvalidRadius(_))));
        }
        let nan = pose(f64::NAN, 0.0, 0.0);
        assert!(matches!(
            DubinsPath::shortest(&a, &nan, 1.0),
            Err(DubinsError::NonFinitePose { which: "goal", .. })
        ));
        let path = DubinsPath::shortest(&a, &b, 1.0).unwrap();
        for s in [-0.1, 1.5, f64::NAN] {
            assert!(matches!(path.pose_at(s), Err(DubinsError::OutOfRange { .. })));
            assert!(matches!(path.subpath(s), Err(DubinsError::OutOfRange { .. })));
        }
        for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(path.sample(step), Err(DubinsError::InvalidStep(_))));
        }
        // Far apart: no three-turn path.
        let far = pose(10.0, 0.0, 0.0);
        assert_eq!(
            DubinsPath::with_word(&a, &far, 1.0, DubinsWord::Rlr),
            Err(DubinsError::NoPath(DubinsWord::Rlr))
        );
    }

    #[test]
    fn words_round_trip_through_json() {
        let path = DubinsPath::shortest(&pose(0.0, 0.0, 0.3), &pose(-2.0, 1.0, 2.0), 0.7).unwrap();
        let json = serde_json::to_string(&path).unwrap();
        assert!(json.contains(&format!("\"{}\"", path.word().name())));
        let back: DubinsPath = serde_json::from_str(&json).unwrap();
        // The heading is written as an angle, so the start comes back to within rounding.
        assert_eq!((back.word(), back.normalised_params()), (path.word(), path.normalised_params()));
        assert!(close(&back.start(), &path.start(), 1e-15));
        assert!(close(&back.end(), &path.end(), 1e-12));
        assert!(json.contains("\"start\":[0.0,0.0,0.3"), "{json}");
    }

    fn any_pose() -> impl Strategy<Value = Pose> {
        (-20.0..20.0f64, -20.0..20.0f64, -10.0..10.0f64).prop_map(|(x, y, h)| pose(x, y, h))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        /// The shortest path joins the poses, is at least the straight-line distance, and is no
        /// longer than any word that joins them (each of which joins them too).
        #[test]
        fn shortest_joins_the_poses_and_beats_every_word(
            a in any_pose(), b in any_pose(), r in 0.05..5.0f64,
        ) {
            let scale = 1.0 + a.translation.vector.norm() + b.translation.vector.norm();
            let tol = 1e-9 * scale / r.min(1.0);
            let best = DubinsPath::shortest(&a, &b, r).unwrap();
            prop_assert!(close(&best.start(), &a, 1e-12 * scale));
            prop_assert!(close(&best.end(), &b, tol), "{:?} ends at {:?}, not {:?}", best, best.end(), b);
            let euclid = (b.translation.vector - a.translation.vector).norm();
            prop_assert!(best.length() >= euclid - 1e-9 * scale);
            let length = DubinsPath::shortest_length(&a, &b, r).unwrap();
            prop_assert!((best.length() - length).abs() <= 1e-12 * length.max(1.0), "{} vs {}", best.length(), length);
            let mut joined = 0;
            for word in DubinsWord::ALL {
                if let Ok(path) = DubinsPath::with_word(&a, &b, r, word) {
                    joined += 1;
                    prop_assert!(close(&path.end(), &b, tol), "{} ends at {:?}", word, path.end());
                    // Words of equal length may be ranked either way by rounding.
                    prop_assert!(best.length() <= path.length() + 1e-12 * (1.0 + path.length()));
                }
            }
            prop_assert!(joined >= 1);
        }

        /// On poses with round coordinates and headings (collinear poses, equal headings, turns
        /// of exactly 0 or π: where the shortcut for `LSL` and `RSR` must defer to the full
        /// evaluation), the shortest length is the least over the six words.
        #[test]
        fn shortest_is_the_least_word_on_degenerate_poses(
            a in (-4i32..=4, -4i32..=4, 0i32..8), b in (-4i32..=4, -4i32..=4, 0i32..8), r in 1i32..=3,
        ) {
            let at = |(x, y, h): (i32, i32, i32)| pose(f64::from(x), f64::from(y), f64::from(h) * PI / 4.0);
            let (a, b, r) = (at(a), at(b), f64::from(r) / 2.0);
            let least = DubinsWord::ALL
                .into_iter()
                .filter_map(|w| DubinsPath::with_word(&a, &b, r, w).ok())
                .map(|p| p.length())
                .fold(f64::INFINITY, f64::min);
            let best = DubinsPath::shortest(&a, &b, r).unwrap();
            prop_assert!((best.length() - least).abs() <= 1e-9, "{} vs {least}", best.length());
        }

        /// Evaluating, cutting and sampling agree with one another.
        #[test]
        fn pose_at_subpath_and_sample_agree(a in any_pose(), b in any_pose(), r in 0.1..3.0f64, f in 0.0..=1.0f64) {
            let path = DubinsPath::shortest(&a, &b, r).unwrap();
            let s = f * path.length();
            let at = path.pose_at(s).unwrap();
            let cut = path.subpath(s).unwrap();
            prop_assert!((cut.length() - s).abs() <= 1e-9 * (1.0 + s));
            prop_assert!(close(&cut.end(), &at, 1e-9 * (1.0 + path.length())));
            prop_assert!(close(&path.pose_at(path.length()).unwrap(), &path.end(), 1e-9));
            let step = (path.length() / 7.3).max(0.01);
            let samples = path.sample(step).unwrap();
            prop_assert!(close(&samples[0], &a, 1e-9 * (1.0 + a.translation.vector.norm())));
            prop_assert!(close(samples.last().unwrap(), &path.end(), 0.0));
            for pair in samples.windows(2) {
                let gap = (pair[1].translation.vector - pair[0].translation.vector).norm();
                prop_assert!(gap <= step * (1.0 + 1e-9));
            }
        }

        /// The pieces chain: each ends where the next starts, arcs at the turning radius.
        #[test]
        fn pieces_chain(a in any_pose(), b in any_pose(), r in 0.1..3.0f64) {
            let path = DubinsPath::shortest(&a, &b, r).unwrap();
            let ends = path.pieces().map(|piece| match piece {
                Piece::Segment { from, to } => (from, to),
                Piece::Arc { center, radius, start_angle, sweep } => {
                    let at = |angle: f64| center + radius * Vector::new(angle.cos(), angle.sin());
                    (at(start_angle), at(start_angle + sweep))
                }
            });
            let tol = 1e-9 * (1.0 + path.length() + a.translation.vector.norm());
            prop_assert!((ends[0].0.coords - a.translation.vector).norm() <= tol);
            prop_assert!((ends[0].1 - ends[1].0).norm() <= tol);
            prop_assert!((ends[1].1 - ends[2].0).norm() <= tol);
            prop_assert!((ends[2].1.coords - path.end().translation.vector).norm() <= tol);
        }
    }
}
