//! The shortest Dubins path: the closed forms of the six words (Shkel and Lumelsky 2001), in
//! units of the turning radius, with the rounding of each accounted for.

use std::f64::consts::TAU;

use super::{DubinsError, DubinsPath, DubinsWord, Start, checked_offset, mod_tau};
use crate::geometry::Pose;

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
    /// The scale of the rounding of the frame's coordinates, in turning radii: `2 + d` and the
    /// poses' largest coordinate. Positions far from the origin carry absolute errors of their
    /// own size times ε, which the frame turned onto the line between two close poses passes
    /// on to every coordinate (at 20 radii from the origin, poses 0.05 radius apart on one arc
    /// came out with their two circles 3e-14 apart in a direction rounding chose).
    scale: f64,
}

impl Normalised {
    fn new(start: &Pose, goal: &Pose, radius: f64) -> Result<Self, DubinsError> {
        let (delta, dist) = checked_offset(start, goal, radius)?;
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
        let (p0, p1) = (start.translation.vector, goal.translation.vector);
        let far = p0.x.abs().max(p0.y.abs()).max(p1.x.abs()).max(p1.y.abs()) / radius;
        let d = dist / radius;
        Ok(Normalised { d, sa, ca, sb, cb, cab, sab, turns: mod_tau(sab.atan2(cab)), scale: 2.0 + d + far })
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
                let ratio = 1e-14 * self.scale / p;
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
                let noise = self.p_noise(p) + 1e-14 * self.scale;
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
    /// (some tens of units in the last place of the scale's square: the terms cancel down from
    /// there). A square that far below 0 is taken as 0:
    /// poses on one arc, or on two touching circles, come out on either side of it, and
    /// rejecting them would send the query to a word a full turn longer.
    #[inline]
    fn p2_noise(&self) -> f64 {
        // The square's terms are of size (2 + d)²; an input error of δ radii moves it by about
        // (2 + d) δ, so the poses' distance from the origin enters once, not squared (squared,
        // it had let words whose circles overlap join poses 1e8 radii out).
        1e-14 * (2.0 + self.d) * self.scale
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
        // (Below this square the full evaluation may snap the turn by more than CLOSE: the two
        // must agree on whether a word takes a full turn.)
        if p2 <= 1e-10 * self.scale * self.scale {
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

impl DubinsPath {
    /// The shortest path from `start` to `goal` for a vehicle whose turning radius is
    /// `turning_radius` (world units).
    ///
    /// Errors outside the [supported range](crate::dubins#supported-range): a radius that is not
    /// positive or beyond [`MAX_MAGNITUDE`](super::MAX_MAGNITUDE), a pose that is not finite or beyond it, poses more
    /// than [`MAX_NORMALISED_DISTANCE`](super::MAX_NORMALISED_DISTANCE) radii apart.
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
}
