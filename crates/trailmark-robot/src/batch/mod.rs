//! The fast checker: the [`ArmChecker`]'s spheres tested for eight configurations at once in
//! `f32` lanes (AVX2 with FMA where the CPU has them, found at run time; the same operations on
//! arrays elsewhere, giving the same answers).
//!
//! **Conservative**: every radius is grown by a bound on the `f32` rounding (a ten-thousandth
//! of the largest coordinate met, at least 0.1 mm, and the rounding of the joint values times
//! the arm's reach), so a configuration the `f64` [`ArmChecker`] calls colliding is never free
//! here; a configuration within that bound of touching may be called colliding here and free
//! there. A group whose joint values reach beyond 10,000 (radians or metres) has nothing free
//! here: check it with the [`ArmChecker`].
//!
//! **Motions** follow the [`ArmChecker`]'s rule (states covering the motion with grown
//! spheres, so nothing is missed between them; [`checker`](crate::checker)), eight states a
//! batch, the first batches in VAMP's "rake" order: spread over the whole motion, each next
//! one shifted by a state, so a collision anywhere is met within a few batches. A frame's
//! spheres are grown by the speed of its fastest sphere.
//!
//! **Point clouds** ([`PointCloud`](crate::cloud::PointCloud)) are tested after the lanes, in
//! `f64`, for the states the lanes found free: the same answers on every CPU.

mod kernel;
mod lanes;
mod program;

use std::cell::{Cell, RefCell};
use std::sync::atomic::{AtomicU64, Ordering};

use nalgebra::SVector;
use trailmark_space::{Joints, Rn, Validity};

use crate::checker::{ArmChecker, along, motion_delta, speed};
use crate::motion;
use kernel::Scratch;
use lanes::{LANES, Portable};
use program::Program;

/// Which code the batches run on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Simd {
    /// Arrays of eight `f32`, on every CPU.
    Portable,
    /// AVX2 and FMA registers (x86-64 CPUs since 2013).
    Avx2,
}

impl Simd {
    /// The fastest this CPU runs.
    pub fn detect() -> Simd {
        #[cfg(target_arch = "x86_64")]
        if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
            return Simd::Avx2;
        }
        Simd::Portable
    }
}

/// An [`ArmChecker`] compiled for batches, as the [module](self) says.
#[derive(Debug)]
pub struct BatchChecker {
    checker: ArmChecker,
    program: Program,
    simd: Simd,
    /// Batches tested so far.
    batches: AtomicU64,
    /// States tested so far (the lanes of the batches that held one).
    states: AtomicU64,
}

impl Clone for BatchChecker {
    /// The same checker, its counts from zero.
    fn clone(&self) -> Self {
        BatchChecker {
            checker: self.checker.clone(),
            program: self.program.clone(),
            simd: self.simd,
            batches: AtomicU64::new(0),
            states: AtomicU64::new(0),
        }
    }
}

impl BatchChecker {
    /// The fast checker of what `checker` checks, on the fastest code this CPU runs.
    pub fn new(checker: ArmChecker) -> BatchChecker {
        let program = Program::new(&checker);
        BatchChecker {
            checker,
            program,
            simd: Simd::detect(),
            batches: AtomicU64::new(0),
            states: AtomicU64::new(0),
        }
    }

    /// The same checker on `simd`'s code; [`Simd::Portable`] where this CPU cannot run it.
    pub fn with_simd(mut self, simd: Simd) -> BatchChecker {
        self.simd = if simd == Simd::Avx2 && Simd::detect() != Simd::Avx2 { Simd::Portable } else { simd };
        self
    }

    /// The code the batches run on.
    pub fn simd(&self) -> Simd {
        self.simd
    }

    /// How many batches of eight states it has tested (a state check is one batch): a
    /// measure of the work done, for collision checks per second.
    pub fn batches(&self) -> u64 {
        self.batches.load(Ordering::Relaxed)
    }

    /// How many states it has tested: the lanes of its batches that held one (a state check
    /// is one, a batch of a motion up to eight), for states checked per second.
    pub fn states(&self) -> u64 {
        self.states.load(Ordering::Relaxed)
    }

    /// The `f64` checker this one was compiled from.
    pub fn checker(&self) -> &ArmChecker {
        &self.checker
    }

    /// Whether the group at `q` (a value per group joint) is free; `false` for a `q` of another
    /// length, not finite, or beyond the joints' limits (the checks it passes over assume
    /// them).
    pub fn is_free(&self, q: &[f64]) -> bool {
        if self.program.blocked || !self.within_limits(q) {
            return false;
        }
        let lanes: Vec<[f32; LANES]> = q.iter().map(|&v| [v as f32; LANES]).collect();
        let scale = vec![0.0; self.program.frames.len() + self.program.pairs.len()];
        self.run(&lanes, &[0.0; LANES], &scale, u8::MAX, 1) == 0 && !self.checker.meets_cloud(q, &[])
    }

    /// Whether each of `states` is free, as [`is_free`](Self::is_free) answers for it, eight
    /// different states a batch: `free[i]` for `states[i]`.
    pub fn are_free<'a>(&self, states: impl IntoIterator<Item = &'a [f64]>, free: &mut Vec<bool>) {
        free.clear();
        let scale = vec![0.0; self.program.frames.len() + self.program.pairs.len()];
        let dims = self.checker.group.bounds.len();
        let mut lanes = vec![[0.0f32; LANES]; dims];
        let mut batch: Vec<&[f64]> = Vec::with_capacity(LANES);
        let mut states = states.into_iter().peekable();
        while states.peek().is_some() {
            let first = free.len();
            batch.clear();
            // The states of the batch: those the lanes can test (the others are not free).
            for q in states.by_ref().take(LANES) {
                let testable = !self.program.blocked && self.within_limits(q);
                free.push(testable);
                if testable {
                    batch.push(q);
                }
            }
            if batch.is_empty() {
                continue;
            }
            for l in 0..LANES {
                // Lanes beyond the batch repeat its first state; no lane stops the others.
                let q = batch.get(l).unwrap_or(&batch[0]);
                for (lane, &v) in lanes.iter_mut().zip(q.iter()) {
                    lane[l] = v as f32;
                }
            }
            let hits = self.run(&lanes, &[0.0; LANES], &scale, 0, batch.len());
            let mut tested = (0..batch.len()).map(|l| hits & (1 << l) == 0);
            // The testable states in order take the lanes' answers, then the clouds'.
            let mut k = 0;
            for answer in free[first..].iter_mut() {
                if *answer {
                    *answer = tested.next().unwrap_or(false) && !self.checker.meets_cloud(batch[k], &[]);
                    k += 1;
                }
            }
        }
    }

    /// Whether the straight motion from `a` to `b` is free, by the rule the [`ArmChecker`]
    /// follows ([`checker`](crate::checker)), eight states a batch.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        // Both ends within the limits: so is every state between (the limits are a box; a
        // continuous joint turns at most half a turn from within ±π).
        if self.program.blocked || !self.within_limits(a) || !self.within_limits(b) {
            return false;
        }
        // The buffers of the thread's last motion, kept for the next (none when one is in use).
        let (mut delta, mut speeds, mut scale, mut lanes) = BUFFERS.take();
        motion_delta(&self.checker.group, a, b, &mut delta);
        speeds.clear();
        speeds.extend(self.program.frames.iter().map(|f| speed(&f.reach, &delta)));
        let rate = speeds.iter().fold(0.0, |m: f64, &v| m.max(v));
        speeds.extend(self.program.pairs.iter().map(|t| speed(&t.reach, &delta)));
        scale.clear();
        scale.extend(speeds.iter().map(|&v| if rate > 0.0 { (v / rate) as f32 } else { 0.0 }));
        lanes.clear();
        lanes.resize(a.len(), [0.0f32; LANES]);
        let mut grow = [0.0f32; LANES];
        // Point clouds are tested in `f64` after the lanes, each sphere grown by its own speed.
        let clouds = !self.checker.clouds.is_empty();
        let sphere_speeds: Vec<f64> =
            if clouds { self.checker.reach.iter().map(|r| speed(r, &delta)).collect() } else { Vec::new() };
        let (mut q, mut grows) = (vec![0.0; a.len()], vec![0.0; sphere_speeds.len()]);
        let free = motion::covered(rate, self.checker.step / 2.0, LANES, |batch, stop| {
            for l in 0..LANES {
                // Lanes beyond the batch repeat its first state.
                let sample = batch.get(l).unwrap_or(&batch[0]);
                for (d, lane) in lanes.iter_mut().enumerate() {
                    lane[l] = along(a[d], delta[d], sample.t) as f32;
                }
                grow[l] = sample.grow as f32;
            }
            // Lanes beyond the batch repeat its first state: they stop when it does.
            let beyond = u8::MAX.checked_shl(batch.len() as u32).unwrap_or(0);
            let stop = if stop & 1 != 0 { stop as u8 | beyond } else { stop as u8 };
            let mut hits = self.run(&lanes, &grow, &scale, stop, batch.len()) & !beyond;
            if clouds {
                for (l, sample) in batch.iter().enumerate() {
                    if hits & (1 << l) != 0 {
                        continue;
                    }
                    for (d, v) in q.iter_mut().enumerate() {
                        *v = along(a[d], delta[d], sample.t);
                    }
                    for (g, v) in grows.iter_mut().zip(&sphere_speeds) {
                        *g = if rate > 0.0 { sample.grow * v / rate } else { 0.0 };
                    }
                    if self.checker.meets_cloud(&q, &grows) {
                        hits |= 1 << l;
                    }
                }
            }
            u32::from(hits)
        });
        BUFFERS.set((delta, speeds, scale, lanes));
        free
    }

    /// Whether `q` is within the group's limits ([`Group::within_limits`](crate::Group::within_limits)).
    fn within_limits(&self, q: &[f64]) -> bool {
        self.checker.group.within_limits(q)
    }

    /// The kernel on `q` (`states` of its lanes holding states of their own).
    fn run(&self, q: &[[f32; LANES]], grow: &[f32; LANES], scale: &[f32], stop: u8, states: usize) -> u8 {
        self.batches.fetch_add(1, Ordering::Relaxed);
        self.states.fetch_add(states as u64, Ordering::Relaxed);
        SCRATCH.with_borrow_mut(|s| {
            s.prepare(&self.program);
            match self.simd {
                // SAFETY: `Simd::Avx2` is only ever set after `Simd::detect` found AVX2 and FMA.
                #[cfg(target_arch = "x86_64")]
                Simd::Avx2 => unsafe { hits_avx2(&self.program, q, grow, scale, stop, s) },
                _ => kernel::hits::<Portable>(&self.program, q, grow, scale, stop, s),
            }
        })
    }
}

thread_local! {
    /// The kernel's working space, one per thread.
    static SCRATCH: RefCell<Scratch> = RefCell::default();
    /// A motion's buffers, between motions.
    static BUFFERS: Cell<MotionBuffers> = const { Cell::new((Vec::new(), Vec::new(), Vec::new(), Vec::new())) };
}

/// A motion's joint differences, speeds, growth scales and lanes of joint values.
type MotionBuffers = (Vec<f64>, Vec<f64>, Vec<f32>, Vec<[f32; LANES]>);

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn hits_avx2(
    program: &Program,
    q: &[[f32; LANES]],
    grow: &[f32; LANES],
    scale: &[f32],
    stop: u8,
    s: &mut Scratch,
) -> u8 {
    kernel::hits::<lanes::Avx>(program, q, grow, scale, stop, s)
}

impl<const N: usize> Validity<Rn<N>> for BatchChecker {
    fn state_is_valid(&self, _: &Rn<N>, q: &SVector<f64, N>) -> bool {
        self.is_free(q.as_slice())
    }

    fn motion_is_valid(&self, _: &Rn<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.motion_is_free(a.as_slice(), b.as_slice())
    }
}

impl<const N: usize> Validity<Joints<N>> for BatchChecker {
    fn state_is_valid(&self, _: &Joints<N>, q: &SVector<f64, N>) -> bool {
        self.is_free(q.as_slice())
    }

    fn motion_is_valid(&self, _: &Joints<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.motion_is_free(a.as_slice(), b.as_slice())
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::robot::Robot;
    use crate::scene::Scene;
    use crate::srdf::Srdf;
    use crate::urdf::Urdf;

    /// A three-joint arm on a post (turning about z, then two about y), two spheres a link, and
    /// a scene of one box, one cylinder and one sphere where the strategy puts them.
    /// A three-joint arm among a box, a can and a ball; its first joint continuous or not.
    fn world(obstacles: [(f64, f64, f64); 3], size: f64, continuous: bool) -> (ArmChecker, BatchChecker) {
        let link = |name: &str, length: f64| {
            format!(
                r#"<link name="{name}"><collision><origin xyz="{} 0 0"/><geometry><sphere radius="0.02"/></geometry></collision>
                   <collision><origin xyz="{length} 0 0"/><geometry><sphere radius="0.01"/></geometry></collision></link>"#,
                length / 2.0
            )
        };
        let urdf = format!(
            r#"<robot name="arm"><link name="base"/>{}{}{}
              <joint name="a" type="{}"><parent link="base"/><child link="one"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
              <joint name="b" type="revolute"><parent link="one"/><child link="two"/><origin xyz="0.4 0 0"/><axis xyz="0 1 0"/><limit lower="-2.5" upper="2.5"/></joint>
              <joint name="c" type="revolute"><parent link="two"/><child link="three"/><origin xyz="0.35 0 0"/><axis xyz="0 1 0"/><limit lower="-2.5" upper="2.5"/></joint>
            </robot>"#,
            link("one", 0.4),
            link("two", 0.35),
            link("three", 0.3),
            if continuous { "continuous" } else { "revolute" },
        );
        let srdf = Srdf::parse(r#"<robot name="arm"><group name="arm"><chain base_link="base" tip_link="three"/></group></robot>"#)
            .unwrap();
        let [(bx, by, bz), (cx, cy, cz), (sx, sy, sz)] = obstacles;
        let scene = Scene::parse(&format!(
            "
world:
  collision_objects:
    - id: box
      primitives: [{{type: box, dimensions: [{size}, {size}, {size}]}}]
      primitive_poses: [{{position: [{bx}, {by}, {bz}], orientation: [0, 0.3826834, 0, 0.9238795]}}]
    - id: can
      primitives: [{{type: cylinder, dimensions: [{size}, {}]}}]
      primitive_poses: [{{position: [{cx}, {cy}, {cz}], orientation: [0, 0, 0, 1]}}]
    - id: ball
      primitives: [{{type: sphere, dimensions: [{}]}}]
      primitive_poses: [{{position: [{sx}, {sy}, {sz}], orientation: [0, 0, 0, 1]}}]
",
            size / 3.0,
            size / 2.0
        ))
        .unwrap();
        let robot = Robot::new(Urdf::parse(&urdf).unwrap()).unwrap();
        let group = robot.group(&srdf, "arm").unwrap();
        let checker =
            ArmChecker::new(robot, &srdf, group, &scene, vec![0.0; 3], crate::DEFAULT_STEP).unwrap();
        (checker.clone(), BatchChecker::new(checker))
    }

    /// A prismatic joint outside the group keeps its start value, even beyond its limits: the
    /// reach that culls obstacles counts that value, not the limits.
    #[test]
    fn a_joint_held_beyond_its_limits_reaches_as_far_as_it_is() {
        let urdf = r#"<robot name="r"><link name="base"/><link name="one"/>
            <link name="two"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
            <joint name="a" type="revolute"><parent link="base"/><child link="one"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
            <joint name="p" type="prismatic"><parent link="one"/><child link="two"/><axis xyz="1 0 0"/><limit lower="0" upper="0.1"/></joint>
          </robot>"#;
        let srdf =
            Srdf::parse(r#"<robot name="r"><group name="arm"><joint name="a"/></group></robot>"#).unwrap();
        let scene = Scene::parse(
            "
world:
  collision_objects:
    - id: box
      primitives: [{type: box, dimensions: [0.1, 0.1, 0.1]}]
      primitive_poses: [{position: [1, 0, 0.3], orientation: [0, 0, 0, 1]}]
",
        )
        .unwrap();
        let robot = Robot::new(Urdf::parse(urdf).unwrap()).unwrap();
        let group = robot.group(&srdf, "arm").unwrap();
        let exact =
            ArmChecker::new(robot, &srdf, group, &scene, vec![0.0, 1.0], crate::DEFAULT_STEP).unwrap();
        let fast = BatchChecker::new(exact.clone());
        assert!(!exact.is_free(&[0.0]));
        assert!(!fast.is_free(&[0.0]));
        assert!(exact.is_free(&[1.0]) && fast.is_free(&[1.0]));
        assert!(!fast.motion_is_free(&[1.0], &[-1.0]) && !exact.motion_is_free(&[1.0], &[-1.0]));
    }

    /// Where the arm reaches: around the post, about the shoulder's height.
    fn place() -> impl Strategy<Value = (f64, f64, f64)> {
        (0.2..1.0f64, -3.2..3.2f64, 0.0..0.6f64)
            .prop_map(|(r, angle, z)| (r * angle.cos(), r * angle.sin(), z))
    }

    fn joints() -> impl Strategy<Value = Vec<f64>> {
        prop::collection::vec(-2.5..2.5f64, 3)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// States: never free where the `f64` checker collides; the two codes agree.
        #[test]
        fn states_are_never_freer_than_in_f64(
            obstacles in [place(), place(), place()],
            size in 0.05..0.6f64,
            qs in prop::collection::vec(joints(), 40),
            continuous in any::<bool>(),
        ) {
            let (exact, fast) = world(obstacles, size, continuous);
            let portable = fast.clone().with_simd(Simd::Portable);
            for q in &qs {
                let free = fast.is_free(q);
                prop_assert_eq!(free, portable.is_free(q));
                prop_assert!(!free || exact.is_free(q), "free in f32, colliding in f64 at {:?}", q);
            }
        }

        /// Motions: one called free by either checker has every state along it free (sampled a
        /// thousand times, far finer than either checks; a continuous first joint turned the
        /// short way round), and the two codes agree. Small obstacles, which a motion checked
        /// too sparsely would pass through.
        #[test]
        fn free_motions_are_free_all_along(
            obstacles in [place(), place(), place()],
            size in 0.005..0.2f64,
            ends in prop::collection::vec((joints(), joints()), 30),
            continuous in any::<bool>(),
        ) {
            let (exact, fast) = world(obstacles, size, continuous);
            let portable = fast.clone().with_simd(Simd::Portable);
            for (a, b) in &ends {
                let free = fast.motion_is_free(a, b);
                prop_assert_eq!(free, portable.motion_is_free(a, b));
                for called in [free, exact.motion_is_free(a, b)] {
                    if called {
                        for i in 0..=1000 {
                            let turn = |d: usize| {
                                let delta = b[d] - a[d];
                                let short = delta - std::f64::consts::TAU * (delta / std::f64::consts::TAU).round();
                                if d == 0 && continuous { short } else { delta }
                            };
                            let q: Vec<f64> = (0..3).map(|d| a[d] + turn(d) * (i as f64 / 1000.0)).collect();
                            prop_assert!(exact.is_free(&q), "a free motion collides at {}", i);
                        }
                    }
                }
            }
        }
    }
}
