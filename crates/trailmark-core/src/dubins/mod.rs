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
pub(crate) const MAX_STRAIGHT_PARAM: f64 = MAX_NORMALISED_DISTANCE + 4.0;

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
pub(crate) struct Start {
    x: f64,
    y: f64,
    cos: f64,
    sin: f64,
}

impl Start {
    pub(crate) fn of(pose: &Pose) -> Self {
        let v = pose.translation.vector;
        Start { x: v.x, y: v.y, cos: pose.rotation.re, sin: pose.rotation.im }
    }

    /// `[x, y, heading]`, the heading in `[0, 2π)`.
    pub(crate) fn array(&self) -> [f64; 3] {
        [self.x, self.y, mod_tau(self.sin.atan2(self.cos))]
    }

    pub(crate) fn pose(&self) -> Pose {
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

/// `x` modulo 2π, in `[0, 2π)` (NaN for NaN or an infinity). Arguments are almost always within
/// a few turns of the range, where a loop of additions beats a division and a call to `floor`;
/// others take the remainder, so no argument makes the loop long.
#[inline]
pub(crate) fn mod_tau(mut x: f64) -> f64 {
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

pub(crate) fn check_radius(radius: f64) -> Result<(), DubinsError> {
    if radius > 0.0 && radius <= MAX_MAGNITUDE { Ok(()) } else { Err(DubinsError::InvalidRadius(radius)) }
}

pub(crate) fn check_pose(which: &'static str, pose: &Pose) -> Result<(), DubinsError> {
    let (x, y) = (pose.translation.vector.x, pose.translation.vector.y);
    let (cos, sin) = (pose.rotation.re, pose.rotation.im);
    let in_range = x.abs() <= MAX_MAGNITUDE && y.abs() <= MAX_MAGNITUDE;
    // Written so that NaN fails; a finite cos and sin of a unit rotation are within [-1, 1].
    let unit = cos.abs() <= 1.5 && sin.abs() <= 1.5 && (cos * cos + sin * sin - 1.0).abs() <= 1e-6;
    if in_range && unit { Ok(()) } else { Err(DubinsError::NonFinitePose { which, x, y, cos, sin }) }
}

/// The checks of a query between two poses (the radius, each pose, and their distance in
/// radii), then the vector from the start to the goal and its length.
pub(crate) fn checked_offset(start: &Pose, goal: &Pose, radius: f64) -> Result<(Vector, f64), DubinsError> {
    check_radius(radius)?;
    check_pose("start", start)?;
    check_pose("goal", goal)?;
    let delta = goal.translation.vector - start.translation.vector;
    // Finite, both positions being within MAX_MAGNITUDE; by `hypot`, since the plain norm
    // squares the components and overflows beyond 1e154.
    let distance = delta.x.hypot(delta.y);
    if distance / radius > MAX_NORMALISED_DISTANCE {
        return Err(DubinsError::OutOfScale { distance, radius });
    }
    Ok((delta, distance))
}

/// The pose after driving `length` (world units, negative in reverse) along `turn` from
/// `(x, y, heading)`.
#[inline]
pub(crate) fn advance(pose: [f64; 3], turn: Turn, length: f64, radius: f64) -> [f64; 3] {
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

/// The pose after driving `length` (world units, negative in reverse) from `pose` along `turn`
/// at `turning_radius`: the one motion every Dubins and Reeds-Shepp piece is made of, for
/// planners that build paths of such pieces themselves (lattices, Hybrid A*). The heading of
/// the result is in `[0, 2π)`.
///
/// ```
/// use trailmark_core::dubins::{Turn, drive};
/// use trailmark_core::geometry::Pose;
///
/// // A quarter turn to the left at radius 2 from the origin facing +x ends at (2, 2) facing +y.
/// let end = drive(&Pose::identity(), Turn::Left, std::f64::consts::PI, 2.0);
/// assert!((end.translation.x - 2.0).abs() < 1e-12 && (end.translation.y - 2.0).abs() < 1e-12);
/// assert!((end.rotation.angle() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
/// ```
pub fn drive(pose: &Pose, turn: Turn, length: f64, turning_radius: f64) -> Pose {
    let start = [pose.translation.x, pose.translation.y, pose.rotation.angle()];
    to_pose(advance(start, turn, length, turning_radius))
}

pub(crate) fn to_pose([x, y, h]: [f64; 3]) -> Pose {
    Pose::new(Vector::new(x, y), h)
}

/// Why a path of Dubins or Reeds-Shepp pieces could not be sampled.
pub(crate) enum SampleFault {
    /// The step is not positive and finite.
    InvalidStep,
    /// More than [`MAX_SAMPLES`] poses.
    TooMany,
}

/// Poses every `step` world units along a path of `length` (`at(s)` the pose `[x, y, heading]`
/// at arc length `s`), then `end`: `ceil(length / step) + 1` poses, counted before anything is
/// allocated.
pub(crate) fn sample_arc_length(
    length: f64,
    step: f64,
    at: impl Fn(f64) -> [f64; 3],
    end: Pose,
) -> Result<Vec<Pose>, SampleFault> {
    if !(step > 0.0 && step.is_finite()) {
        return Err(SampleFault::InvalidStep);
    }
    let count = (length / step).ceil() + 1.0;
    // The loop below makes at most one pose more than `count` (when `k * step` rounds below
    // the length), so MAX_SAMPLES - 1 leaves room. (A path's length is finite.)
    if count.is_nan() || count >= MAX_SAMPLES as f64 {
        return Err(SampleFault::TooMany);
    }
    // In range: count < MAX_SAMPLES.
    let mut poses = Vec::with_capacity(count as usize + 1);
    let mut k = 0u64;
    loop {
        let s = k as f64 * step;
        if s >= length {
            break;
        }
        poses.push(to_pose(at(s)));
        k += 1;
    }
    poses.push(end);
    Ok(poses)
}

impl DubinsPath {
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
        let start = self.start.array();
        sample_arc_length(self.length(), step, |s| self.pose_array_at(start, s), self.end()).map_err(
            |fault| match fault {
                SampleFault::InvalidStep => DubinsError::InvalidStep(step),
                SampleFault::TooMany => DubinsError::TooManySamples { length: self.length(), step },
            },
        )
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
        let turns = self.word.turns();
        std::array::from_fn(|i| {
            let (piece, next) = piece_along(pose, turns[i], self.params[i], r);
            pose = next;
            piece
        })
    }
}

/// The piece that driving `param` turning radii (negative in reverse) along `turn` from `pose`
/// (`[x, y, heading]`) traces in world coordinates, and the pose where it ends: the pieces of
/// Dubins and Reeds-Shepp paths. An arc driven in reverse sweeps the other way round its circle.
pub(crate) fn piece_along(pose: [f64; 3], turn: Turn, param: f64, r: f64) -> (Piece, [f64; 3]) {
    let [x, y, h] = pose;
    let next = advance(pose, turn, param * r, r);
    let piece = match turn {
        Turn::Straight => Piece::Segment { from: Point::new(x, y), to: Point::new(next[0], next[1]) },
        Turn::Left => Piece::Arc {
            center: Point::new(x - r * h.sin(), y + r * h.cos()),
            radius: r,
            start_angle: mod_tau(h - std::f64::consts::FRAC_PI_2),
            sweep: param,
        },
        Turn::Right => Piece::Arc {
            center: Point::new(x + r * h.sin(), y - r * h.cos()),
            radius: r,
            start_angle: mod_tau(h + std::f64::consts::FRAC_PI_2),
            sweep: -param,
        },
    };
    (piece, next)
}

mod solver;

#[cfg(test)]
mod tests;
