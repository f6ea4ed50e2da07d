//! Eight `f32` lanes: the operations the batch checker is written in, once portably and once in
//! AVX2 with FMA. Every operation is one IEEE operation rounded once (the fused multiply-add
//! included), so both give the same bits for finite inputs, and the checker's answers agree.

/// How many configurations a batch holds.
pub(crate) const LANES: usize = 8;

/// Eight `f32` values and the operations on them, lane by lane.
pub(crate) trait Lanes: Copy {
    /// Every lane `x`.
    fn splat(x: f32) -> Self;
    /// The lanes of `x`.
    fn load(x: &[f32; LANES]) -> Self;
    /// Writes the lanes to `out`.
    fn store(self, out: &mut [f32; LANES]);
    /// `self + b`.
    fn add(self, b: Self) -> Self;
    /// `self - b`.
    fn sub(self, b: Self) -> Self;
    /// `self * b`.
    fn mul(self, b: Self) -> Self;
    /// `self * b + c`, rounded once.
    fn mul_add(self, b: Self, c: Self) -> Self;
    /// The larger of `self` and `b` (finite lanes only).
    fn max(self, b: Self) -> Self;
    /// `|self|`.
    fn abs(self) -> Self;
    /// `√self`, rounded once.
    fn sqrt(self) -> Self;
    /// The nearest integer, ties to even.
    fn round(self) -> Self;
    /// A bit per lane (lane `i` is bit `i`): set where `self <= b`.
    fn le(self, b: Self) -> u8;
}

/// The lanes as an array: the fallback on every CPU, and the reference the vector path is
/// tested against.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Portable([f32; LANES]);

impl Portable {
    #[inline(always)]
    fn map2(self, b: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        Portable(std::array::from_fn(|i| f(self.0[i], b.0[i])))
    }
}

impl Lanes for Portable {
    #[inline(always)]
    fn splat(x: f32) -> Self {
        Portable([x; LANES])
    }
    #[inline(always)]
    fn load(x: &[f32; LANES]) -> Self {
        Portable(*x)
    }
    #[inline(always)]
    fn store(self, out: &mut [f32; LANES]) {
        *out = self.0;
    }
    #[inline(always)]
    fn add(self, b: Self) -> Self {
        self.map2(b, |x, y| x + y)
    }
    #[inline(always)]
    fn sub(self, b: Self) -> Self {
        self.map2(b, |x, y| x - y)
    }
    #[inline(always)]
    fn mul(self, b: Self) -> Self {
        self.map2(b, |x, y| x * y)
    }
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        Portable(std::array::from_fn(|i| self.0[i].mul_add(b.0[i], c.0[i])))
    }
    #[inline(always)]
    fn max(self, b: Self) -> Self {
        // As `vmaxps`: the second operand unless the first is larger.
        self.map2(b, |x, y| if x > y { x } else { y })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Portable(self.0.map(f32::abs))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Portable(self.0.map(f32::sqrt))
    }
    #[inline(always)]
    fn round(self) -> Self {
        Portable(self.0.map(f32::round_ties_even))
    }
    #[inline(always)]
    fn le(self, b: Self) -> u8 {
        (0..LANES).fold(0, |bits, i| bits | (u8::from(self.0[i] <= b.0[i]) << i))
    }
}

#[cfg(target_arch = "x86_64")]
pub(crate) use avx::Avx;

#[cfg(target_arch = "x86_64")]
mod avx {
    use std::arch::x86_64::*;

    use super::{LANES, Lanes};

    /// The lanes in one AVX register. A value exists only inside a function compiled with
    /// `avx2` and `fma` and entered after `is_x86_feature_detected!` said the CPU has both,
    /// which is what makes the intrinsics below sound to call.
    #[derive(Debug, Clone, Copy)]
    pub(crate) struct Avx(__m256);

    impl Lanes for Avx {
        #[inline(always)]
        fn splat(x: f32) -> Self {
            Avx(unsafe { _mm256_set1_ps(x) })
        }
        #[inline(always)]
        fn load(x: &[f32; LANES]) -> Self {
            Avx(unsafe { _mm256_loadu_ps(x.as_ptr()) })
        }
        #[inline(always)]
        fn store(self, out: &mut [f32; LANES]) {
            unsafe { _mm256_storeu_ps(out.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn add(self, b: Self) -> Self {
            Avx(unsafe { _mm256_add_ps(self.0, b.0) })
        }
        #[inline(always)]
        fn sub(self, b: Self) -> Self {
            Avx(unsafe { _mm256_sub_ps(self.0, b.0) })
        }
        #[inline(always)]
        fn mul(self, b: Self) -> Self {
            Avx(unsafe { _mm256_mul_ps(self.0, b.0) })
        }
        #[inline(always)]
        fn mul_add(self, b: Self, c: Self) -> Self {
            Avx(unsafe { _mm256_fmadd_ps(self.0, b.0, c.0) })
        }
        #[inline(always)]
        fn max(self, b: Self) -> Self {
            Avx(unsafe { _mm256_max_ps(self.0, b.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            Avx(unsafe { _mm256_andnot_ps(_mm256_set1_ps(-0.0), self.0) })
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            Avx(unsafe { _mm256_sqrt_ps(self.0) })
        }
        #[inline(always)]
        fn round(self) -> Self {
            Avx(unsafe { _mm256_round_ps::<{ _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC }>(self.0) })
        }
        #[inline(always)]
        fn le(self, b: Self) -> u8 {
            unsafe { _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(self.0, b.0)) as u8 }
        }
    }
}

/// `2π` split in two: the first with few significant bits, so `k * TAU_HIGH` is exact for the
/// turn counts joint limits allow, the second the rest.
const TAU_HIGH: f32 = 6.28125;
const TAU_LOW: f32 = (std::f64::consts::TAU - 6.28125) as f32;

/// The sine and cosine of every lane: reduced to `[-π, π]` by whole turns, then Taylor series to
/// the 17th and 18th powers (their remainders below 3e-8 there). The turn count is exact to
/// 2^16 turns; the compiled checker refuses joint values beyond `MAX_JOINT_VALUE` (about 1,600
/// turns) and its slack covers the rounding below that.
#[inline(always)]
pub(crate) fn sin_cos<L: Lanes>(x: L) -> (L, L) {
    let turns = x.mul(L::splat(std::f32::consts::FRAC_1_PI * 0.5)).round();
    let r = turns.mul_add(L::splat(-TAU_HIGH), x);
    let r = turns.mul_add(L::splat(-TAU_LOW), r);
    let r2 = r.mul(r);
    // Coefficients from the highest power down: (-1)^k / (2k+1)! and (-1)^k / (2k)!, k ≥ 1.
    const SIN: [f64; 8] = [
        1.0 / 355_687_428_096_000.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 39_916_800.0,
        1.0 / 362_880.0,
        -1.0 / 5040.0,
        1.0 / 120.0,
        -1.0 / 6.0,
    ];
    const COS: [f64; 9] = [
        -1.0 / 6_402_373_705_728_000.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 479_001_600.0,
        -1.0 / 3_628_800.0,
        1.0 / 40_320.0,
        -1.0 / 720.0,
        1.0 / 24.0,
        -0.5,
    ];
    let mut s = L::splat(0.0);
    for c in SIN {
        s = s.mul_add(r2, L::splat(c as f32));
    }
    // sin r = r + r * r² * (…)
    let sin = r.mul(r2).mul_add(s, r);
    let mut c = L::splat(0.0);
    for k in COS {
        c = c.mul_add(r2, L::splat(k as f32));
    }
    let cos = c.mul_add(r2, L::splat(1.0));
    (sin, cos)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sine_and_cosine_are_within_a_few_millionths_over_the_joint_range() {
        let mut worst = 0.0f64;
        for i in -4000..=4000 {
            let x = i as f64 * 0.005;
            let (s, c) = sin_cos(Portable::splat(x as f32));
            let x32 = x as f32 as f64;
            worst = worst.max((s.0[0] as f64 - x32.sin()).abs()).max((c.0[0] as f64 - x32.cos()).abs());
        }
        assert!(worst < 2e-6, "{worst}");
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_vector_lanes_give_the_portable_lanes_bits() {
        if !(is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma")) {
            eprintln!("skipped: this CPU has no AVX2 with FMA");
            return;
        }
        #[target_feature(enable = "avx2,fma")]
        fn vector(x: [f32; LANES]) -> ([f32; LANES], [f32; LANES]) {
            let (s, c) = sin_cos(Avx::load(&x));
            let mut out = ([0.0; LANES], [0.0; LANES]);
            s.store(&mut out.0);
            c.store(&mut out.1);
            out
        }
        for i in 0..1000 {
            let x: [f32; LANES] = std::array::from_fn(|l| (i * LANES + l) as f32 * 0.0137 - 50.0);
            let (s, c) = sin_cos(Portable::load(&x));
            let (vs, vc) = unsafe { vector(x) };
            assert_eq!(s.0.map(f32::to_bits), vs.map(f32::to_bits));
            assert_eq!(c.0.map(f32::to_bits), vc.map(f32::to_bits));
        }
    }
}
