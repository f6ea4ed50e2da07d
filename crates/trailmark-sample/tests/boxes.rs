//! Box worlds: the exact segment test against dense samples of the state test, and every
//! planner's paths in R⁴ and R⁸ random box worlds valid by dense samples.

use nalgebra::SVector;
use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::termination::Termination;
use trailmark_sample::{
    BoxWorld, KdNearest, Planner, Prm, Problem, Rn, Rrt, RrtConnect, RrtStar, Solution, SpaceError, Validity,
};

/// Whether `q` is within `margin` of a box's interior.
fn near_a_box<const N: usize>(world: &BoxWorld<N>, q: &SVector<f64, N>, margin: f64) -> bool {
    world.boxes().iter().any(|(lo, hi)| (0..N).all(|i| q[i] > lo[i] - margin && q[i] < hi[i] + margin))
}

/// States every `step` along `a`-`b`, both ends included.
fn samples<const N: usize>(a: &SVector<f64, N>, b: &SVector<f64, N>, step: f64) -> Vec<SVector<f64, N>> {
    let n = ((b - a).norm() / step).ceil().max(1.0) as usize;
    (0..=n).map(|i| a + (b - a) * (i as f64 / n as f64)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A segment the slab test calls free has every sample free; one it calls blocked has a
    /// sample within a step of a box's interior.
    #[test]
    fn the_slab_test_agrees_with_dense_samples(seed in any::<u64>(), count in 1usize..12) {
        let world = BoxWorld::<3>::random(count, 0.1..0.4, seed).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 1);
        for _ in 0..50 {
            let a = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(0.0..1.0));
            let b = SVector::<f64, 3>::from_fn(|_, _| rng.random_range(0.0..1.0));
            let step = 1e-3;
            let dense = samples(&a, &b, step);
            if world.segment_is_free(&a, &b) {
                prop_assert!(dense.iter().all(|q| world.is_free(q)), "{a:?} -> {b:?}");
            } else {
                prop_assert!(dense.iter().any(|q| near_a_box(&world, q, step)), "{a:?} -> {b:?}");
            }
        }
    }
}

#[test]
fn touching_is_allowed_and_bad_boxes_are_errors() {
    let world = BoxWorld::new([0.0; 2], [1.0; 2], vec![([0.4, 0.4], [0.6, 0.6])]).unwrap();
    let p = |x: f64, y: f64| SVector::from([x, y]);
    // Along a face, through a corner, and inside.
    assert!(world.segment_is_free(&p(0.4, 0.0), &p(0.4, 1.0)));
    assert!(!world.segment_is_free(&p(0.2, 0.8), &p(0.8, 0.2)));
    assert!(world.segment_is_free(&p(0.3, 0.5), &p(0.5, 0.7)));
    assert!(!world.is_free(&p(0.5, 0.5)) && world.is_free(&p(0.6, 0.5)));
    assert!(!world.segment_is_free(&p(0.5, 0.5), &p(0.5, 0.5)));
    assert!(matches!(
        BoxWorld::new([0.0; 2], [1.0; 2], vec![([0.5, 0.5], [0.5, 0.6])]),
        Err(SpaceError::InvalidBounds { .. })
    ));
    assert!(matches!(
        BoxWorld::new([0.0; 2], [f64::NAN, 1.0], vec![]),
        Err(SpaceError::InvalidBounds { .. })
    ));
}

/// Every planner in a random box world of `N` dimensions, from near one corner to near the
/// other: each path's states free and in bounds, its motions free by samples every 1e-3.
fn planners_in<const N: usize>(count: usize, seed: u64) {
    let world = BoxWorld::<N>::random(count, 0.1..0.3, seed).unwrap();
    let space: Rn<N> = world.space();
    let kd = KdNearest::<Rn<N>, N>::new(&space).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut free_near = |c: f64| loop {
        let q = SVector::<f64, N>::from_fn(|_, _| (c + rng.random_range(-0.1..0.1)).clamp(0.0, 1.0));
        if world.is_free(&q) {
            return q;
        }
    };
    let (a, b) = (free_near(0.1), free_near(0.9));
    let problem = Problem::new(&space, &world, a, b);
    let planners: Vec<Box<dyn Planner<Rn<N>, BoxWorld<N>>>> = vec![
        Box::new(Rrt::new(kd.clone())),
        Box::new(RrtConnect::new(kd.clone())),
        Box::new(RrtStar::new(kd.clone())),
        Box::new(Prm::star(kd)),
    ];
    for mut planner in planners {
        let plan = planner.solve(&problem, &Termination::iterations(1_500)).unwrap();
        let Some(path) = plan.solution.any_path() else {
            assert!(matches!(plan.solution, Solution::None));
            continue;
        };
        for m in path.windows(2) {
            assert!(samples(&m[0], &m[1], 1e-3).iter().all(|q| world.is_free(q)), "{}", planner.name());
            assert!(world.motion_is_valid(&space, &m[0], &m[1]));
        }
    }
}

#[test]
fn every_planner_in_four_and_eight_dimensions() {
    planners_in::<4>(30, 1);
    planners_in::<8>(60, 2);
}
