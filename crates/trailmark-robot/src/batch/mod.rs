//! The fast checker: the [`ArmChecker`]'s spheres tested for eight configurations at once in
//! `f32` lanes (AVX2 with FMA where the CPU has them, found at run time; the same operations on
//! arrays elsewhere, giving the same answers).
//!
//! **Conservative**: every radius is grown by a bound on the `f32` rounding (a ten-thousandth
//! of the largest coordinate met, at least 0.1 mm), so a configuration the `f64` [`ArmChecker`]
//! calls colliding is never free here; a configuration within that bound of touching may be
//! called colliding here and free there.
//!
//! **Motions** are checked at exactly the states the [`ArmChecker`] checks (the same step
//! bound, the same growth by half a step, so nothing is missed between them), eight a batch in
//! VAMP's "rake" order: the first batch spread over the whole motion, each next one shifted by
//! a state, so a collision anywhere is met within a few batches.

mod kernel;
mod lanes;
mod program;

use std::cell::RefCell;

use nalgebra::SVector;
use trailmark_space::{Rn, Validity};

use crate::checker::{ArmChecker, along};
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
#[derive(Debug, Clone)]
pub struct BatchChecker {
    checker: ArmChecker,
    program: Program,
    simd: Simd,
}

impl BatchChecker {
    /// The fast checker of what `checker` checks, on the fastest code this CPU runs.
    pub fn new(checker: ArmChecker) -> BatchChecker {
        let program = Program::new(&checker);
        BatchChecker { checker, program, simd: Simd::detect() }
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

    /// The `f64` checker this one was compiled from.
    pub fn checker(&self) -> &ArmChecker {
        &self.checker
    }

    /// Whether the group at `q` (a value per group joint) is free; `false` for a `q` of another
    /// length or not finite.
    pub fn is_free(&self, q: &[f64]) -> bool {
        let dims = self.checker.group.joints.len();
        if q.len() != dims || !q.iter().all(|v| v.is_finite()) {
            return false;
        }
        let lanes: Vec<[f32; LANES]> = q.iter().map(|&v| [v as f32; LANES]).collect();
        self.run(&lanes, 0.0)
    }

    /// Whether the straight motion from `a` to `b` is free, checked at the [`ArmChecker`]'s
    /// states in rake order.
    pub fn motion_is_free(&self, a: &[f64], b: &[f64]) -> bool {
        if !a.iter().chain(b).all(|v| v.is_finite()) {
            return false;
        }
        let Some(n) = self.checker.motion_steps(a, b) else { return false };
        let grow = (self.checker.step / 2.0) as f32;
        let batches = (n + 1).div_ceil(LANES);
        let mut lanes = vec![[0.0f32; LANES]; a.len()];
        for k in 0..batches {
            for l in 0..LANES {
                let i = (l * batches + k).min(n);
                for (d, lane) in lanes.iter_mut().enumerate() {
                    lane[l] = along(a[d], b[d], i, n) as f32;
                }
            }
            if !self.run(&lanes, grow) {
                return false;
            }
        }
        true
    }

    fn run(&self, q: &[[f32; LANES]], grow: f32) -> bool {
        SCRATCH.with_borrow_mut(|s| {
            s.prepare(&self.program);
            match self.simd {
                // SAFETY: `Simd::Avx2` is only ever set after `Simd::detect` found AVX2 and FMA.
                #[cfg(target_arch = "x86_64")]
                Simd::Avx2 => unsafe { all_free_avx2(&self.program, q, grow, s) },
                _ => kernel::all_free::<Portable>(&self.program, q, grow, s),
            }
        })
    }
}

thread_local! {
    /// The kernel's working space, one per thread.
    static SCRATCH: RefCell<Scratch> = RefCell::default();
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn all_free_avx2(program: &Program, q: &[[f32; LANES]], grow: f32, s: &mut Scratch) -> bool {
    kernel::all_free::<lanes::Avx>(program, q, grow, s)
}

impl<const N: usize> Validity<Rn<N>> for BatchChecker {
    fn state_is_valid(&self, _: &Rn<N>, q: &SVector<f64, N>) -> bool {
        self.is_free(q.as_slice())
    }

    fn motion_is_valid(&self, _: &Rn<N>, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.motion_is_free(a.as_slice(), b.as_slice())
    }
}
