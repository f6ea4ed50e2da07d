//! The batch test: forward kinematics of eight configurations at once, frame by frame, each
//! frame's spheres tested against the world as soon as it is placed (a sphere about the whole
//! frame first), then the sphere pairs of the robot (their frames' spheres first). Any lane
//! colliding ends the test.
//!
//! No closures and no `array::from_fn` or `map` here: each is a function of its own, compiled
//! without the CPU features of the function that called the kernel, and the vector intrinsics
//! inside would stay calls instead of single instructions.

use super::lanes::{LANES, Lanes, sin_cos};
use super::program::{Motion, Obstacle32, Pose32, Program, Shape32};

type Point<L> = [L; 3];

/// Where the kernel keeps placed frames and sphere centres between its steps: reused from call
/// to call, so no test allocates.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Per frame, its rotation rows and translation: 12 lanes.
    frames: Vec<[f32; LANES]>,
    /// Per sphere of a frame, its centre: 3 lanes.
    centres: Vec<[f32; LANES]>,
    /// Per frame, whether its centres are placed.
    filled: Vec<bool>,
}

impl Scratch {
    /// Room for `program`, every frame's centres marked unplaced.
    pub(crate) fn prepare(&mut self, program: &Program) {
        let frames = program.frames.len();
        self.frames.resize(frames * 12, [0.0; LANES]);
        self.centres.resize(program.sphere_count * 3, [0.0; LANES]);
        self.filled.clear();
        self.filled.resize(frames, false);
    }
}

/// A frame's pose in every lane: rotation rows and translation.
#[derive(Clone, Copy)]
struct Placed<L> {
    rotation: [[L; 3]; 3],
    translation: Point<L>,
}

impl<L: Lanes> Placed<L> {
    #[inline(always)]
    fn constant(pose: &Pose32) -> Self {
        let r = &pose.rotation;
        Placed { rotation: [splat3(r[0]), splat3(r[1]), splat3(r[2])], translation: splat3(pose.translation) }
    }

    /// `self * pose`.
    #[inline(always)]
    fn then(&self, pose: &Pose32) -> Self {
        let c = &pose.rotation;
        let columns = [[c[0][0], c[1][0], c[2][0]], [c[0][1], c[1][1], c[2][1]], [c[0][2], c[1][2], c[2][2]]];
        let zero = L::splat(0.0);
        let mut rotation = [[zero; 3]; 3];
        for (out, row) in rotation.iter_mut().zip(&self.rotation) {
            for (value, column) in out.iter_mut().zip(columns) {
                *value = dot(row, column, zero);
            }
        }
        Placed { rotation, translation: self.apply(pose.translation) }
    }

    /// `self * point`.
    #[inline(always)]
    fn apply(&self, point: [f32; 3]) -> Point<L> {
        let (r, t) = (&self.rotation, &self.translation);
        [dot(&r[0], point, t[0]), dot(&r[1], point, t[1]), dot(&r[2], point, t[2])]
    }

    #[inline(always)]
    fn store(&self, out: &mut [[f32; LANES]]) {
        for i in 0..3 {
            for j in 0..3 {
                self.rotation[i][j].store(&mut out[3 * i + j]);
            }
            self.translation[i].store(&mut out[9 + i]);
        }
    }

    #[inline(always)]
    fn load(from: &[[f32; LANES]]) -> Self {
        let zero = L::splat(0.0);
        let mut placed = Placed { rotation: [[zero; 3]; 3], translation: [zero; 3] };
        for i in 0..3 {
            for j in 0..3 {
                placed.rotation[i][j] = L::load(&from[3 * i + j]);
            }
            placed.translation[i] = L::load(&from[9 + i]);
        }
        placed
    }
}

#[inline(always)]
fn splat3<L: Lanes>(v: [f32; 3]) -> Point<L> {
    [L::splat(v[0]), L::splat(v[1]), L::splat(v[2])]
}

#[inline(always)]
fn load3<L: Lanes>(from: &[[f32; LANES]]) -> Point<L> {
    [L::load(&from[0]), L::load(&from[1]), L::load(&from[2])]
}

/// `row · v + plus`, from the last term to the first, each step rounded once.
#[inline(always)]
fn dot<L: Lanes>(row: &[L; 3], v: [f32; 3], plus: L) -> L {
    row[0].mul_add(L::splat(v[0]), row[1].mul_add(L::splat(v[1]), row[2].mul_add(L::splat(v[2]), plus)))
}

/// The row `i` of `inverse` applied to `c`.
#[inline(always)]
fn local_row<L: Lanes>(inverse: &Pose32, c: &Point<L>, i: usize) -> L {
    let m = &inverse.rotation[i];
    c[0].mul_add(
        L::splat(m[0]),
        c[1].mul_add(L::splat(m[1]), c[2].mul_add(L::splat(m[2]), L::splat(inverse.translation[i]))),
    )
}

/// Where the batch's lanes touch obstacle `o` with spheres at `c` of radius `r`: a bit a lane.
#[inline(always)]
fn touches<L: Lanes>(o: &Obstacle32, c: &Point<L>, r: L) -> u8 {
    let zero = L::splat(0.0);
    match o.shape {
        Shape32::Sphere { centre, radius } => {
            let d =
                [c[0].sub(L::splat(centre[0])), c[1].sub(L::splat(centre[1])), c[2].sub(L::splat(centre[2]))];
            let reach = r.add(L::splat(radius));
            squared(&d).le(reach.mul(reach))
        }
        Shape32::Box(half) => {
            let x = local_row(&o.inverse, c, 0).abs().sub(L::splat(half[0])).max(zero);
            let y = local_row(&o.inverse, c, 1).abs().sub(L::splat(half[1])).max(zero);
            let z = local_row(&o.inverse, c, 2).abs().sub(L::splat(half[2])).max(zero);
            squared(&[x, y, z]).le(r.mul(r))
        }
        Shape32::Cylinder { radius, half_height } => {
            let (x, y) = (local_row(&o.inverse, c, 0), local_row(&o.inverse, c, 1));
            let z = local_row(&o.inverse, c, 2);
            let radial = x.mul_add(x, y.mul(y)).sqrt().sub(L::splat(radius)).max(zero);
            let axial = z.abs().sub(L::splat(half_height)).max(zero);
            radial.mul_add(radial, axial.mul(axial)).le(r.mul(r))
        }
    }
}

#[inline(always)]
fn squared<L: Lanes>(d: &Point<L>) -> L {
    d[0].mul_add(d[0], d[1].mul_add(d[1], d[2].mul(d[2])))
}

/// Where spheres at `a` and `b` with radii adding to `reach` touch: a bit a lane.
#[inline(always)]
fn meet<L: Lanes>(a: &Point<L>, b: &Point<L>, reach: L) -> u8 {
    let d = [a[0].sub(b[0]), a[1].sub(b[1]), a[2].sub(b[2])];
    squared(&d).le(reach.mul(reach))
}

/// Places frame `f`'s sphere centres in `s`, once per test.
#[inline(always)]
fn fill<L: Lanes>(p: &Program, s: &mut Scratch, f: usize) {
    if s.filled[f] {
        return;
    }
    s.filled[f] = true;
    let frame = &p.frames[f];
    let placed = Placed::<L>::load(&s.frames[12 * f..12 * f + 12]);
    for (k, sphere) in frame.spheres.iter().enumerate() {
        let c = placed.apply(sphere.0);
        let at = 3 * (frame.first + k);
        for (i, coordinate) in c.into_iter().enumerate() {
            coordinate.store(&mut s.centres[at + i]);
        }
    }
}

/// Which of the eight configurations `q` (per group joint, its eight values) collide, a bit a
/// lane, with frame `f`'s spheres grown by `grow` times `scale[f]` in each lane against
/// obstacles, and the pairs of pair test `t` by `grow` times `scale[frames + t]` (and all by the
/// slack). A lane of `stop` colliding ends the search at once (other lanes not set then may
/// collide too). `s` must be [prepared](Scratch::prepare) for `p`.
#[inline(always)]
pub(crate) fn hits<L: Lanes>(
    p: &Program,
    q: &[[f32; LANES]],
    grow: &[f32; LANES],
    scale: &[f32],
    stop: u8,
    s: &mut Scratch,
) -> u8 {
    let mut top_grow = 0.0f32;
    for &g in grow {
        top_grow = top_grow.max(g);
    }
    let mut found = 0u8;
    let grow = L::load(grow);
    let slack = L::splat(p.slack);
    for (f, frame) in p.frames.iter().enumerate() {
        let pad = grow.mul_add(L::splat(scale[f]), slack);
        let above = match frame.parent {
            Some(parent) => Placed::<L>::load(&s.frames[12 * parent..12 * parent + 12]).then(&frame.constant),
            None => Placed::constant(&frame.constant),
        };
        let value = L::load(&q[frame.variable]).mul_add(L::splat(frame.multiplier), L::splat(frame.offset));
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
        at.store(&mut s.frames[12 * f..12 * f + 12]);
        let tests = &p.world[f];
        if tests.is_empty() {
            continue;
        }
        let (bound_centre, bound_radius) = frame.bound;
        let bound = at.apply(bound_centre);
        for test in tests {
            let o = &p.obstacles[test.obstacle];
            if touches(o, &bound, pad.add(L::splat(bound_radius))) == 0 {
                continue;
            }
            fill::<L>(p, s, f);
            // One group is (nearly) the frame itself: its bound was just tested.
            let several = test.groups.len() > 1;
            for (group_bound, spheres) in &test.groups {
                if several && touches(o, &at.apply(group_bound.0), pad.add(L::splat(group_bound.1))) == 0 {
                    continue;
                }
                for &i in spheres {
                    let at = 3 * (frame.first + i as usize);
                    let c = load3::<L>(&s.centres[at..at + 3]);
                    let hit = touches(o, &c, pad.add(L::splat(frame.spheres[i as usize].1)));
                    found |= hit;
                    if found & stop != 0 {
                        return found;
                    }
                }
            }
        }
    }
    for (t, test) in p.pairs.iter().enumerate() {
        // The most any lane grows these pairs: pairs whose floor is beyond cannot touch.
        let limit = top_grow * scale[p.frames.len() + t] + 2.0 * p.slack;
        if test.floor > limit {
            continue;
        }
        let frame = &p.frames[test.frame];
        let placed = Placed::<L>::load(&s.frames[12 * test.frame..12 * test.frame + 12]);
        let bound = placed.apply(frame.bound.0);
        // The pair's growth, and both sides' slack.
        let pad = grow.mul_add(L::splat(scale[p.frames.len() + t]), slack.add(slack));
        let (other, other_radius) = match test.other {
            Some(o) => {
                let placed = Placed::<L>::load(&s.frames[12 * o..12 * o + 12]);
                (placed.apply(p.frames[o].bound.0), p.frames[o].bound.1)
            }
            None => (splat3(test.still_bound.0), test.still_bound.1),
        };
        if meet(&bound, &other, pad.add(L::splat(frame.bound.1 + other_radius))) == 0 {
            continue;
        }
        fill::<L>(p, s, test.frame);
        let other_placed = match test.other {
            Some(o) => {
                fill::<L>(p, s, o);
                Placed::<L>::load(&s.frames[12 * o..12 * o + 12])
            }
            None => Placed::constant(&Pose32::IDENTITY),
        };
        let several = test.links.len() > 1;
        for link in &test.links {
            if link.floor > limit {
                continue;
            }
            let b = other_placed.apply(link.other_bound.0);
            if several
                && meet(&placed.apply(link.bound.0), &b, pad.add(L::splat(link.bound.1 + link.other_bound.1)))
                    == 0
            {
                continue;
            }
            for row in &link.rows {
                if row.floor > limit {
                    continue;
                }
                let at = 3 * (frame.first + row.sphere as usize);
                let a = load3::<L>(&s.centres[at..at + 3]);
                let ra = frame.spheres[row.sphere as usize].1;
                if meet(&a, &b, pad.add(L::splat(ra + link.other_bound.1))) == 0 {
                    continue;
                }
                for &(j, floor) in &row.others {
                    if floor > limit {
                        continue;
                    }
                    let (c, rb) = match test.other {
                        Some(o) => {
                            let other = &p.frames[o];
                            let at = 3 * (other.first + j as usize);
                            (load3::<L>(&s.centres[at..at + 3]), other.spheres[j as usize].1)
                        }
                        None => (splat3(p.still[j as usize].0), p.still[j as usize].1),
                    };
                    let hit = meet(&a, &c, pad.add(L::splat(ra + rb)));
                    found |= hit;
                    if found & stop != 0 {
                        return found;
                    }
                }
            }
        }
    }
    found
}
