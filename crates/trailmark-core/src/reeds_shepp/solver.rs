//! The closed forms of Reeds and Shepp (1990) for the base word of each family, and the
//! symmetries that give the other words from them.
//!
//! Everything here is in units of the turning radius, with the start at the origin facing +x
//! and the goal at `(x, y)` facing `phi`. A base formula returns the normalised lengths of its
//! pieces (negative: driven in reverse), or `None` when its word cannot join the poses. The
//! symmetries (section 8 of the paper): *time flip* `(x, y, phi) -> (-x, y, -phi)` drives every
//! piece the other way; *reflection* `(x, y, phi) -> (x, -y, -phi)` swaps left and right turns;
//! *backwards* `(x, y, phi) -> (x cos phi + y sin phi, x sin phi - y cos phi, phi)` drives the
//! pieces in the reverse order.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::dubins::Turn;

/// A word of at most five pieces: each piece's turn and normalised signed length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Word {
    pub turns: [Turn; 5],
    pub params: [f64; 5],
    pub len: usize,
}

impl Word {
    pub fn new(turns: &[Turn], params: &[f64]) -> Self {
        debug_assert_eq!(turns.len(), params.len());
        let mut word = Word { turns: [Turn::Straight; 5], params: [0.0; 5], len: turns.len() };
        word.turns[..turns.len()].copy_from_slice(turns);
        word.params[..params.len()].copy_from_slice(params);
        word
    }

    /// The sum of the pieces' absolute lengths, in turning radii.
    pub fn length(&self) -> f64 {
        self.params[..self.len].iter().map(|p| p.abs()).sum()
    }

    fn flipped(mut self) -> Self {
        for p in &mut self.params[..self.len] {
            *p = -*p;
        }
        self
    }

    fn reflected(mut self) -> Self {
        for t in &mut self.turns[..self.len] {
            *t = match *t {
                Turn::Left => Turn::Right,
                Turn::Right => Turn::Left,
                Turn::Straight => Turn::Straight,
            };
        }
        self
    }

    fn reversed(mut self) -> Self {
        self.turns[..self.len].reverse();
        self.params[..self.len].reverse();
        self
    }
}

/// An angle in `(-pi, pi]`: `x` modulo 2π as `rem_euclid` gives it, then shifted. Arguments
/// within two turns (all but hostile ones) take the same steps without the division.
#[inline]
fn wrap(x: f64) -> f64 {
    let mut v = if x.abs() < 2.0 * TAU {
        let mut r = if x >= TAU { x - TAU } else { x };
        if r < 0.0 {
            r = if r <= -TAU { r + TAU } else { r } + TAU;
        }
        r
    } else {
        x.rem_euclid(TAU)
    };
    if v > PI {
        v -= TAU;
    }
    v
}

/// A problem in the start's frame: the goal at `(x, y)` facing `phi`, with `phi`'s sine and
/// cosine (computed once for the four mirror images, whose sines differ only in sign).
#[derive(Debug, Clone, Copy)]
struct Goal {
    x: f64,
    y: f64,
    phi: f64,
    sin: f64,
    cos: f64,
}

/// The polar coordinates `(r, theta)` of `(x, y)`.
#[inline]
fn polar(x: f64, y: f64) -> (f64, f64) {
    (x.hypot(y), y.atan2(x))
}

/// Rounding slack in the sign tests of the formulas: a piece of length `-1e-10` is a piece of
/// length 0 driven either way.
const SLACK: f64 = 1e-10;

use Turn::{Left as L, Right as R, Straight as S};

/// `L+ S+ L+` (formula 8.1).
fn lsl(g: Goal) -> Option<[f64; 3]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (u, t) = polar(x - sin, y - 1.0 + cos);
    if t >= -SLACK {
        let v = wrap(phi - t);
        if v >= -SLACK {
            return Some([t, u, v]);
        }
    }
    None
}

/// `L+ S+ R+` (formula 8.2).
fn lsr(g: Goal) -> Option<[f64; 3]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (u1, t1) = polar(x + sin, y - 1.0 - cos);
    let u1 = u1 * u1;
    if u1 >= 4.0 {
        let u = (u1 - 4.0).sqrt();
        let t = wrap(t1 + 2.0f64.atan2(u));
        let v = wrap(t - phi);
        if t >= -SLACK && v >= -SLACK {
            return Some([t, u, v]);
        }
    }
    None
}

/// `L+ R- L` (formula 8.3, the base of `C|C|C`, `C|CC` and `CC|C`).
fn lrl(g: Goal) -> Option<[f64; 3]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (u1, theta) = polar(x - sin, y - 1.0 + cos);
    if u1 <= 4.0 {
        let u = -2.0 * (0.25 * u1).asin();
        let t = wrap(theta + 0.5 * u + PI);
        let v = wrap(phi - t + u);
        if t >= -SLACK && u <= SLACK {
            return Some([t, u, v]);
        }
    }
    None
}

/// The first and last pieces of the four-turn words, given the middle two `u` and `v`
/// (the angles tau and omega of the paper).
fn tau_omega(u: f64, v: f64, xi: f64, eta: f64, phi: f64) -> (f64, f64) {
    let delta = wrap(u - v);
    let a = u.sin() - delta.sin();
    let b = u.cos() - delta.cos() - 1.0;
    let t1 = (eta * a - xi * b).atan2(xi * a + eta * b);
    let t2 = 2.0 * (delta.cos() - v.cos() - u.cos()) + 3.0;
    let tau = if t2 < 0.0 { wrap(t1 + PI) } else { wrap(t1) };
    (tau, wrap(tau - u + v - phi))
}

/// `L+ R+u L-u R-` (formula 8.7).
fn lrlr_same(g: Goal) -> Option<[f64; 4]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (xi, eta) = (x + sin, y - 1.0 - cos);
    let rho = 0.25 * (2.0 + xi.hypot(eta));
    if rho <= 1.0 {
        let u = rho.acos();
        let (t, v) = tau_omega(u, -u, xi, eta, phi);
        if t >= -SLACK && v <= SLACK {
            return Some([t, u, -u, v]);
        }
    }
    None
}

/// `L+ R-u L-u R+` (formula 8.8).
fn lrlr_opposite(g: Goal) -> Option<[f64; 4]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (xi, eta) = (x + sin, y - 1.0 - cos);
    let rho = (20.0 - xi * xi - eta * eta) / 16.0;
    if (0.0..=1.0).contains(&rho) {
        let u = -rho.acos();
        if u >= -FRAC_PI_2 {
            let (t, v) = tau_omega(u, u, xi, eta, phi);
            if t >= -SLACK && v >= -SLACK {
                return Some([t, u, u, v]);
            }
        }
    }
    None
}

/// `L+ R-(pi/2) S- L-` (formula 8.9).
fn lrsl(g: Goal) -> Option<[f64; 4]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (rho, theta) = polar(x - sin, y - 1.0 + cos);
    if rho >= 2.0 {
        let r = (rho * rho - 4.0).sqrt();
        let u = 2.0 - r;
        let t = wrap(theta + r.atan2(-2.0));
        let v = wrap(phi - FRAC_PI_2 - t);
        if t >= -SLACK && u <= SLACK && v <= SLACK {
            return Some([t, -FRAC_PI_2, u, v]);
        }
    }
    None
}

/// `L+ R-(pi/2) S- R-` (formula 8.10).
fn lrsr(g: Goal) -> Option<[f64; 4]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (xi, eta) = (x + sin, y - 1.0 - cos);
    let (rho, theta) = polar(-eta, xi);
    if rho >= 2.0 {
        let t = theta;
        let u = 2.0 - rho;
        let v = wrap(t + FRAC_PI_2 - phi);
        if t >= -SLACK && u <= SLACK && v <= SLACK {
            return Some([t, -FRAC_PI_2, u, v]);
        }
    }
    None
}

/// `L+ R-(pi/2) S- L-(pi/2) R+` (formula 8.11).
fn lrslr(g: Goal) -> Option<[f64; 5]> {
    let Goal { x, y, phi, sin, cos } = g;
    let (xi, eta) = (x + sin, y - 1.0 - cos);
    let (rho, _) = polar(xi, eta);
    if rho >= 2.0 {
        let u = 4.0 - (rho * rho - 4.0).sqrt();
        if u <= SLACK {
            let t = wrap(((4.0 - u) * xi - 2.0 * eta).atan2(-2.0 * xi + (u - 4.0) * eta));
            let v = wrap(t - phi);
            if t >= -SLACK && v >= -SLACK {
                return Some([t, -FRAC_PI_2, u, -FRAC_PI_2, v]);
            }
        }
    }
    None
}

/// Tries `base` at the goal `g` and at its time flip, reflection, and both, and gives `found`
/// each word that joins the poses, built from `turns` and the lengths `base` returns (reversed
/// when `reverse`: the problem was turned around).
fn with_flips<const N: usize>(
    found: &mut impl FnMut(Word),
    g: Goal,
    turns: [Turn; N],
    base: fn(Goal) -> Option<[f64; N]>,
    reverse: bool,
) {
    let Goal { x, y, phi, sin, cos } = g;
    let variants: [(Goal, bool, bool); 4] = [
        (g, false, false),
        (Goal { x: -x, y, phi: -phi, sin: -sin, cos }, true, false),
        (Goal { x, y: -y, phi: -phi, sin: -sin, cos }, false, true),
        (Goal { x: -x, y: -y, phi, sin, cos }, true, true),
    ];
    for (g, flip, reflect) in variants {
        if let Some(params) = base(g) {
            let mut word = Word::new(&turns, &params);
            if flip {
                word = word.flipped();
            }
            if reflect {
                word = word.reflected();
            }
            if reverse {
                word = word.reversed();
            }
            found(word);
        }
    }
}

/// Every word that joins the origin facing +x to `(x, y)` facing `phi`, all in turning radii,
/// in the order of the paper's families: `C S C`, `C C C`, `C C C C`, `C C S C` (and its reverse
/// `C S C C`) and `C C S C C`, each base formula under the time flip, the reflection and (for
/// the families that are not their own reverse) the reversal.
pub(super) fn each_word(x: f64, y: f64, phi: f64, mut found: impl FnMut(Word)) {
    let (sin, cos) = phi.sin_cos();
    let here = Goal { x, y, phi, sin, cos };
    // The reversed problem: the start seen from the goal's frame, driven backwards.
    let back = Goal { x: x * cos + y * sin, y: x * sin - y * cos, phi, sin, cos };
    let found = &mut found;
    with_flips(found, here, [L, S, L], lsl, false);
    with_flips(found, here, [L, S, R], lsr, false);
    with_flips(found, here, [L, R, L], lrl, false);
    with_flips(found, back, [L, R, L], lrl, true);
    with_flips(found, here, [L, R, L, R], lrlr_same, false);
    with_flips(found, here, [L, R, L, R], lrlr_opposite, false);
    with_flips(found, here, [L, R, S, L], lrsl, false);
    with_flips(found, here, [L, R, S, R], lrsr, false);
    with_flips(found, back, [L, R, S, L], lrsl, true);
    with_flips(found, back, [L, R, S, R], lrsr, true);
    with_flips(found, here, [L, R, S, L, R], lrslr, false);
}

/// The shortest word of [`each_word`]; among words of the same length, the first.
pub(super) fn shortest(x: f64, y: f64, phi: f64) -> Word {
    let mut best: Option<Word> = None;
    each_word(x, y, phi, |word| {
        if best.is_none_or(|b| word.length() < b.length()) {
            best = Some(word);
        }
    });
    best.expect("the C S C family always joins two poses")
}
