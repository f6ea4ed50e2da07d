//! Reeds-Shepp curves: the shortest paths of a car that drives forward and in reverse, at unit
//! speed, with a bounded turning radius.
//!
//! Reeds and Shepp (1990) showed that such a shortest path between two poses is made of at most
//! five pieces, each a left turn (`L`), a right turn (`R`) or a straight segment (`S`), driven
//! forward (`+`) or in reverse (`-`), in one of 48 words of nine families (`C|C|C`, `CC|C`,
//! `CSC`, `CCu|CuC`, `C|CuCu|C`, `C|C(pi/2)SC`, `CSC(pi/2)|C`, `C|C(pi/2)SC(pi/2)|C`, and their
//! reflections and reversals). [`ReedsSheppPath::shortest`] tries every word through the closed
//! forms of the paper's section 8 and keeps the shortest; where the car changes gear the path
//! has a *cusp* ([`ReedsSheppPath::cusps`]). A path is measured, evaluated at any arc length,
//! sampled, cut ([`ReedsSheppPath::subpath`]) and taken apart into exact arcs and segments
//! ([`ReedsSheppPath::pieces`]) as a Dubins path is.
//!
//! Poses are [`Pose`]s (nalgebra `Isometry2`), headings counter-clockwise from +x; lengths are
//! in world units. The supported range is that of Dubins curves (see
//! [`dubins`](crate::dubins#supported-range)): coordinates and radius at most
//! [`MAX_MAGNITUDE`](crate::dubins::MAX_MAGNITUDE), poses at most [`MAX_NORMALISED_DISTANCE`](crate::dubins::MAX_NORMALISED_DISTANCE) radii apart.
//!
//! ```
//! use trailmark_core::dubins::DubinsPath;
//! use trailmark_core::geometry::{Pose, Vector};
//! use trailmark_core::reeds_shepp::ReedsSheppPath;
//!
//! // Parallel parking: one radius to the side, facing the same way.
//! let start = Pose::new(Vector::new(0.0, 0.0), 0.0);
//! let goal = Pose::new(Vector::new(0.0, 1.0), 0.0);
//! let path = ReedsSheppPath::shortest(&start, &goal, 1.0)?;
//! assert!(!path.cusps().is_empty()); // the car reverses on the way
//! let end = path.end();
//! assert!((end.translation.vector - goal.translation.vector).norm() < 1e-9);
//! // Reversing never makes the shortest path longer than driving forward only.
//! let forward = DubinsPath::shortest(&start, &goal, 1.0).unwrap();
//! assert!(path.length() <= forward.length());
//! // The length alone, for a heuristic.
//! assert_eq!(ReedsSheppPath::shortest_length(&start, &goal, 1.0)?, path.length());
//! # Ok::<(), trailmark_core::reeds_shepp::ReedsSheppError>(())
//! ```

mod solver;

use thiserror::Error;

pub use crate::dubins::Turn;
use std::f64::consts::TAU;

use crate::dubins::{
    DubinsError, MAX_STRAIGHT_PARAM, Piece, SampleFault, Start, advance, check_pose, check_radius,
    checked_offset, piece_along, sample_arc_length, to_pose,
};
use crate::geometry::Pose;

/// Which way the car drives along a piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Gear {
    /// Forward: the heading points where the car goes.
    Forward,
    /// In reverse: the car goes against its heading.
    Reverse,
}

/// One piece of a Reeds-Shepp path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// A left or right turn at the turning radius, or a straight segment.
    pub turn: Turn,
    /// Which way the car drives.
    pub gear: Gear,
    /// The length driven, in world units (not negative).
    pub length: f64,
}

/// What was wrong with a Reeds-Shepp query: a turning radius, a pose, a distance between poses,
/// an arc length or a sampling step out of range. The checks are those of Dubins curves, and
/// the error inside says which failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ReedsSheppError {
    /// A value out of range (never [`DubinsError::NoPath`] or [`DubinsError::InvalidPath`]).
    #[error(transparent)]
    Query(#[from] DubinsError),
    /// A deserialized path that no query could give: a radius, start or piece out of range.
    #[error("not a valid Reeds-Shepp path: {0}")]
    InvalidPath(&'static str),
}

/// A [`ReedsSheppPath`] as written.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPath {
    start: Start,
    turning_radius: f64,
    turns: String,
    params: Vec<f64>,
}

impl From<ReedsSheppPath> for RawPath {
    fn from(path: ReedsSheppPath) -> Self {
        let word = path.word;
        let turns = word.turns[..word.len].iter().map(|&t| turn_letter(t)).collect();
        RawPath {
            start: path.start,
            turning_radius: path.turning_radius,
            turns,
            params: word.params[..word.len].to_vec(),
        }
    }
}

impl TryFrom<RawPath> for ReedsSheppPath {
    type Error = ReedsSheppError;

    fn try_from(raw: RawPath) -> Result<Self, ReedsSheppError> {
        let invalid = ReedsSheppError::InvalidPath;
        check_radius(raw.turning_radius).map_err(|_| invalid("the turning radius is out of range"))?;
        check_pose("start", &raw.start.pose()).map_err(|_| invalid("the start is out of range"))?;
        let turns: Vec<Turn> = raw
            .turns
            .chars()
            .map(|c| match c {
                'L' => Ok(Turn::Left),
                'S' => Ok(Turn::Straight),
                'R' => Ok(Turn::Right),
                _ => Err(invalid("a turn is not L, S or R")),
            })
            .collect::<Result<_, _>>()?;
        if turns.is_empty() || turns.len() > 5 || turns.len() != raw.params.len() {
            return Err(invalid("one to five pieces, a length for each"));
        }
        for (&turn, &param) in turns.iter().zip(&raw.params) {
            let max = if turn == Turn::Straight { MAX_STRAIGHT_PARAM } else { TAU };
            if !(-max..=max).contains(&param) {
                return Err(invalid("a piece is not finite, or too long"));
            }
        }
        Ok(ReedsSheppPath {
            start: raw.start,
            turning_radius: raw.turning_radius,
            word: solver::Word::new(&turns, &raw.params),
        })
    }
}

/// The letter of a turn in a word: `L`, `S` or `R`.
fn turn_letter(turn: Turn) -> char {
    match turn {
        Turn::Left => 'L',
        Turn::Right => 'R',
        Turn::Straight => 'S',
    }
}

/// A piece shorter than this many turning radii is no change of gear: the closed forms leave
/// pieces of a few units in the last place where the exact piece is empty.
const CUSP_SLACK: f64 = 1e-12;

/// A Reeds-Shepp path: a start pose, a turning radius and up to five pieces.
///
/// Serializes as `{"start": [x, y, heading], "turning_radius": r, "turns": "LRSL", "params": [t,
/// u, v, w]}`, with `params` the pieces' lengths divided by the radius, negative for a piece
/// driven in reverse (a turn's angle in radians). Deserializing checks what a query would: the
/// start and radius in the supported range, one to five pieces, each turn within a full circle
/// and each straight piece at most the supported distance plus four radii
/// ([`ReedsSheppError::InvalidPath`] otherwise).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "RawPath", into = "RawPath")]
pub struct ReedsSheppPath {
    start: Start,
    turning_radius: f64,
    word: solver::Word,
}

/// The goal in the start's frame, in turning radii, and the heading change.
fn normalise(start: &Pose, goal: &Pose, radius: f64) -> Result<(f64, f64, f64), ReedsSheppError> {
    let (delta, _) = checked_offset(start, goal, radius)?;
    let (c, s) = (start.rotation.re, start.rotation.im);
    let x = (c * delta.x + s * delta.y) / radius;
    let y = (c * delta.y - s * delta.x) / radius;
    let (c1, s1) = (goal.rotation.re, goal.rotation.im);
    let phi = (s1 * c - c1 * s).atan2(c1 * c + s1 * s);
    Ok((x, y, phi))
}

impl ReedsSheppPath {
    /// The shortest Reeds-Shepp path from `start` to `goal` with `turning_radius`. Among words of
    /// the same length, the first in the order of the paper's families is kept.
    ///
    /// Errors when the radius is not positive or beyond [`MAX_MAGNITUDE`](crate::dubins::MAX_MAGNITUDE), a pose is not finite
    /// or out of range, or the poses are more than [`MAX_NORMALISED_DISTANCE`](crate::dubins::MAX_NORMALISED_DISTANCE) radii apart.
    pub fn shortest(start: &Pose, goal: &Pose, turning_radius: f64) -> Result<Self, ReedsSheppError> {
        let (x, y, phi) = normalise(start, goal, turning_radius)?;
        Ok(ReedsSheppPath { start: Start::of(start), turning_radius, word: solver::shortest(x, y, phi) })
    }

    /// The length of the shortest path alone (for heuristics and distances), with the checks of
    /// [`ReedsSheppPath::shortest`].
    pub fn shortest_length(start: &Pose, goal: &Pose, turning_radius: f64) -> Result<f64, ReedsSheppError> {
        let (x, y, phi) = normalise(start, goal, turning_radius)?;
        Ok(solver::shortest(x, y, phi).length() * turning_radius)
    }

    /// Every Reeds-Shepp path from `start` to `goal` that the closed forms give (each word of
    /// each family that joins the poses; the shortest is [`ReedsSheppPath::shortest`]), with its
    /// checks: for tests, and for a caller that wants another path of the same length.
    pub fn candidates(start: &Pose, goal: &Pose, turning_radius: f64) -> Result<Vec<Self>, ReedsSheppError> {
        let (x, y, phi) = normalise(start, goal, turning_radius)?;
        let start = Start::of(start);
        let mut paths = Vec::new();
        solver::each_word(x, y, phi, |word| paths.push(ReedsSheppPath { start, turning_radius, word }));
        Ok(paths)
    }

    /// The turning radius, in world units.
    pub fn turning_radius(&self) -> f64 {
        self.turning_radius
    }

    /// The total length driven, forward and in reverse, in world units.
    pub fn length(&self) -> f64 {
        self.word.length() * self.turning_radius
    }

    /// The pieces, in order (a piece of length 0 included).
    pub fn segments(&self) -> impl Iterator<Item = Segment> + '_ {
        let r = self.turning_radius;
        (0..self.word.len).map(move |i| {
            let p = self.word.params[i];
            let gear = if p < 0.0 { Gear::Reverse } else { Gear::Forward };
            Segment { turn: self.word.turns[i], gear, length: p.abs() * r }
        })
    }

    /// The start pose.
    pub fn start(&self) -> Pose {
        self.start.pose()
    }

    /// The pose at the end of the path: the goal, up to rounding.
    pub fn end(&self) -> Pose {
        to_pose(self.pose_array_at(self.length()))
    }

    /// The arc lengths (world units, from the start) where the car changes gear, in order.
    pub fn cusps(&self) -> Vec<f64> {
        let mut cusps = Vec::new();
        let mut gear = None;
        let mut driven = 0.0;
        for i in 0..self.word.len {
            let p = self.word.params[i];
            if p.abs() > CUSP_SLACK {
                let this = p > 0.0;
                if gear.is_some_and(|g| g != this) {
                    cusps.push(driven * self.turning_radius);
                }
                gear = Some(this);
            }
            driven += p.abs();
        }
        cusps
    }

    /// The first `s` world units of the path, `0 <= s <= length()`: a path with the same start,
    /// radius and pieces, cut where [`pose_at(s)`](ReedsSheppPath::pose_at) is.
    ///
    /// Errors with [`DubinsError::OutOfRange`] for any other `s`.
    pub fn subpath(&self, s: f64) -> Result<ReedsSheppPath, ReedsSheppError> {
        self.check_arc_length(s)?;
        let mut left = s / self.turning_radius;
        let mut word = self.word;
        for p in &mut word.params[..word.len] {
            let kept = left.min(p.abs());
            left -= kept;
            *p = kept.copysign(*p);
        }
        Ok(ReedsSheppPath { word, ..*self })
    }

    /// The pieces in world coordinates (a piece of length 0 included), for exact collision
    /// checks: an arc driven in reverse sweeps the other way round its circle.
    pub fn pieces(&self) -> Vec<Piece> {
        let mut pose = self.start.array();
        (0..self.word.len)
            .map(|i| {
                let (piece, next) =
                    piece_along(pose, self.word.turns[i], self.word.params[i], self.turning_radius);
                pose = next;
                piece
            })
            .collect()
    }

    /// The pose after driving `s` world units along the path, `0 <= s <= length()`.
    ///
    /// Errors with [`DubinsError::OutOfRange`] for any other `s` (NaN included).
    pub fn pose_at(&self, s: f64) -> Result<Pose, ReedsSheppError> {
        self.check_arc_length(s)?;
        Ok(to_pose(self.pose_array_at(s)))
    }

    /// `Ok` when `0 <= s <= length()`, else [`DubinsError::OutOfRange`].
    fn check_arc_length(&self, s: f64) -> Result<(), ReedsSheppError> {
        let length = self.length();
        if (0.0..=length).contains(&s) { Ok(()) } else { Err(DubinsError::OutOfRange { s, length }.into()) }
    }

    /// The pose at arc length `s` in `[0, length]`, as `[x, y, heading]`.
    fn pose_array_at(&self, s: f64) -> [f64; 3] {
        let r = self.turning_radius;
        let mut pose = self.start.array();
        let mut left = s;
        for i in 0..self.word.len {
            let p = self.word.params[i];
            let step = left.min(p.abs() * r);
            pose = advance(pose, self.word.turns[i], step.copysign(p), r);
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
    /// Errors with [`DubinsError::InvalidStep`] unless `step` is positive and finite, and
    /// with [`DubinsError::TooManySamples`] when that would be more than [`MAX_SAMPLES`](crate::curve::MAX_SAMPLES)
    /// poses (checked before anything is allocated).
    pub fn sample(&self, step: f64) -> Result<Vec<Pose>, ReedsSheppError> {
        let length = self.length();
        sample_arc_length(length, step, |s| self.pose_array_at(s), self.end()).map_err(|fault| match fault {
            SampleFault::InvalidStep => DubinsError::InvalidStep(step).into(),
            SampleFault::TooMany => DubinsError::TooManySamples { length, step }.into(),
        })
    }
}

impl std::fmt::Display for ReedsSheppPath {
    /// The word with each piece's gear, as in the literature: `L+R-S-L-`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        for segment in self.segments() {
            let turn = turn_letter(segment.turn);
            let gear = if segment.gear == Gear::Forward { '+' } else { '-' };
            write!(f, "{turn}{gear}")?;
        }
        Ok(())
    }
}
