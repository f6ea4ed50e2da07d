//! The batch test: forward kinematics of eight configurations at once, frame by frame, each
//! frame's spheres tested against the world as soon as it is placed (a sphere about the whole
//! frame first), then the sphere pairs of the robot (their frames' spheres first). Any lane
//! colliding ends the test.

use super::lanes::{LANES, Lanes, sin_cos};
use super::program::{Motion, Obstacle32, Pose32, Program, Shape32};

type Point<L> = [L; 3];

/// A frame's pose in every lane: rotation rows and translation.
#[derive(Clone, Copy)]
struct Placed<L> {
    rotation: [[L; 3]; 3],
    translation: Point<L>,
}

impl<L: Lanes> Placed<L> {
    #[inline(always)]
    fn constant(pose: &Pose32) -> Self {
        Placed {
            rotation: pose.rotation.map(|row| row.map(L::splat)),
            translation: pose.translation.map(L::splat),
        }
    }

    /// `self * pose`.
    #[inline(always)]
    fn then(&self, pose: &Pose32) -> Self {
        let r = &self.rotation;
        let c = &pose.rotation;
        let rotation = std::array::from_fn(|i| {
            std::array::from_fn(|j| dot(&r[i], [c[0][j], c[1][j], c[2][j]], L::splat(0.0)))
        });
        let translation = std::array::from_fn(|i| dot(&r[i], pose.translation, self.translation[i]));
        Placed { rotation, translation }
    }

    /// `self * point`.
    #[inline(always)]
    fn apply(&self, point: [f32; 3]) -> Point<L> {
        std::array::from_fn(|i| dot(&self.rotation[i], point, self.translation[i]))
    }
}

/// `row · v + plus`, from the last term to the first, each step rounded once.
#[inline(always)]
fn dot<L: Lanes>(row: &[L; 3], v: [f32; 3], plus: L) -> L {
    row[0].mul_add(L::splat(v[0]), row[1].mul_add(L::splat(v[1]), row[2].mul_add(L::splat(v[2]), plus)))
}

/// Where the batch's lanes touch obstacle `o` with spheres at `c` of radius `r`: a bit a lane.
#[inline(always)]
fn touches<L: Lanes>(o: &Obstacle32, c: &Point<L>, r: f32) -> u8 {
    let zero = L::splat(0.0);
    let local = |inverse: &Pose32| -> Point<L> {
        let m = &inverse.rotation;
        std::array::from_fn(|i| {
            c[0].mul_add(
                L::splat(m[i][0]),
                c[1].mul_add(
                    L::splat(m[i][1]),
                    c[2].mul_add(L::splat(m[i][2]), L::splat(inverse.translation[i])),
                ),
            )
        })
    };
    match o.shape {
        Shape32::Sphere { centre, radius } => {
            let d: Point<L> = std::array::from_fn(|i| c[i].sub(L::splat(centre[i])));
            let reach = radius + r;
            squared(&d).le(L::splat(reach * reach))
        }
        Shape32::Box(half) => {
            let p = local(&o.inverse);
            let d: Point<L> = std::array::from_fn(|i| p[i].abs().sub(L::splat(half[i])).max(zero));
            squared(&d).le(L::splat(r * r))
        }
        Shape32::Cylinder { radius, half_height } => {
            let p = local(&o.inverse);
            let radial = p[0].mul_add(p[0], p[1].mul(p[1])).sqrt().sub(L::splat(radius)).max(zero);
            let axial = p[2].abs().sub(L::splat(half_height)).max(zero);
            radial.mul_add(radial, axial.mul(axial)).le(L::splat(r * r))
        }
    }
}

#[inline(always)]
fn squared<L: Lanes>(d: &Point<L>) -> L {
    d[0].mul_add(d[0], d[1].mul_add(d[1], d[2].mul(d[2])))
}

/// Whether spheres at `a` and `b` with radii adding to `reach` are apart in every lane.
#[inline(always)]
fn apart<L: Lanes>(a: &Point<L>, b: &Point<L>, reach: f32) -> bool {
    let d: Point<L> = std::array::from_fn(|i| a[i].sub(b[i]));
    squared(&d).le(L::splat(reach * reach)) == 0
}

/// Whether all eight configurations `q` (per group joint, its eight values) are free with every
/// sphere grown by `grow`.
#[inline(always)]
pub(crate) fn all_free<L: Lanes>(p: &Program, q: &[[f32; LANES]], grow: f32) -> bool {
    let grow64 = f64::from(grow) + f64::from(p.slack);
    if p.still_clearance <= grow64 || p.fixed_gap <= 2.0 * grow64 {
        return false;
    }
    let pad = p.slack + grow;
    let mut placed: Vec<Placed<L>> = Vec::with_capacity(p.frames.len());
    // Each frame's sphere centres, placed when first needed.
    let mut centres: Vec<Vec<Point<L>>> = vec![Vec::new(); p.frames.len()];
    let fill = |centres: &mut Vec<Vec<Point<L>>>, placed: &[Placed<L>], f: usize| {
        if centres[f].is_empty() {
            centres[f] = p.frames[f].spheres.iter().map(|(c, _)| placed[f].apply(*c)).collect();
        }
    };
    for (f, frame) in p.frames.iter().enumerate() {
        let above = match frame.parent {
            Some(parent) => placed[parent].then(&frame.constant),
            None => Placed::constant(&frame.constant),
        };
        let value =
            L::from_array(q[frame.variable]).mul_add(L::splat(frame.multiplier), L::splat(frame.offset));
        let mut at = above;
        match frame.motion {
            Motion::Turn => {
                let (sin, cos) = sin_cos(value);
                for row in &mut at.rotation {
                    let (x, y) = (row[0], row[1]);
                    row[0] = y.mul_add(sin, x.mul(cos));
                    row[1] = y.mul_add(cos, L::splat(0.0).sub(x.mul(sin)));
                }
            }
            Motion::Slide(axis) => {
                for i in 0..3 {
                    let along = dot(&above.rotation[i], axis, L::splat(0.0));
                    at.translation[i] = along.mul_add(value, above.translation[i]);
                }
            }
        }
        placed.push(at);
        let tests = &p.world[f];
        if tests.is_empty() {
            continue;
        }
        let (bound_centre, bound_radius) = frame.bound;
        let bound = at.apply(bound_centre);
        for test in tests {
            let o = &p.obstacles[test.obstacle];
            if touches(o, &bound, bound_radius + pad) == 0 {
                continue;
            }
            fill(&mut centres, &placed, f);
            for &i in &test.spheres {
                if touches(o, &centres[f][i as usize], frame.spheres[i as usize].1 + pad) != 0 {
                    return false;
                }
            }
        }
    }
    for test in &p.pairs {
        let frame = &p.frames[test.frame];
        let bound = placed[test.frame].apply(frame.bound.0);
        let (other, other_radius) = match test.other {
            Some(o) => (placed[o].apply(p.frames[o].bound.0), p.frames[o].bound.1),
            None => (test.still_bound.0.map(L::splat), test.still_bound.1),
        };
        if apart(&bound, &other, frame.bound.1 + other_radius + 2.0 * pad) {
            continue;
        }
        fill(&mut centres, &placed, test.frame);
        if let Some(o) = test.other {
            fill(&mut centres, &placed, o);
        }
        for &(i, j) in &test.pairs {
            let a = &centres[test.frame][i as usize];
            let (b, rb) = match test.other {
                Some(o) => (centres[o][j as usize], p.frames[o].spheres[j as usize].1),
                None => (p.still[j as usize].0.map(L::splat), p.still[j as usize].1),
            };
            if !apart(a, &b, frame.spheres[i as usize].1 + rb + 2.0 * pad) {
                return false;
            }
        }
    }
    true
}
