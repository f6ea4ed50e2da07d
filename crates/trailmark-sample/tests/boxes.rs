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

/// A wall across the unit square (or cube) at `x` in `[0.4, 0.6]`, cut into boxes that share
/// faces at `cuts` along the second axis: closed obstacles, it blocks as one box would.
fn cut_wall<const N: usize>(cuts: &[f64]) -> BoxWorld<N> {
    let mut edges = vec![0.0];
    edges.extend(cuts.iter().copied());
    edges.push(1.0);
    edges.sort_by(f64::total_cmp);
    edges.dedup();
    let boxes = edges
        .windows(2)
        .map(|w| {
            let lo = std::array::from_fn(|i| [0.4, w[0]].get(i).copied().unwrap_or(0.0));
            let hi = std::array::from_fn(|i| [0.6, w[1]].get(i).copied().unwrap_or(1.0));
            (lo, hi)
        })
        .collect();
    BoxWorld::new([0.0; N], [1.0; N], boxes).unwrap()
}

/// RRT, RRT-Connect, RRT* and PRM* in a box world, on the nearest neighbours `kd`.
fn every_planner<const N: usize>(kd: KdNearest<Rn<N>, N>) -> Vec<Box<dyn Planner<Rn<N>, BoxWorld<N>>>> {
    vec![
        Box::new(Rrt::new(kd.clone())),
        Box::new(RrtConnect::new(kd.clone())),
        Box::new(RrtStar::new(kd.clone())),
        Box::new(Prm::star(kd)),
    ]
}

/// Every planner from left of the wall to right of it: none may return a path (a path's
/// states are left and right of a wall that spans the square, so it crossed the wall).
fn no_planner_crosses<const N: usize>(world: &BoxWorld<N>, a: SVector<f64, N>, b: SVector<f64, N>) {
    let space: Rn<N> = world.space();
    let kd = KdNearest::<Rn<N>, N>::new(&space).unwrap();
    let problem = Problem::new(&space, world, a, b);
    let planners = every_planner(kd);
    for mut planner in planners {
        let plan = planner.solve(&problem, &Termination::iterations(600)).unwrap();
        let solved = matches!(plan.solution, Solution::Exact { .. });
        assert!(
            !solved,
            "{} crossed a wall of touching boxes: {:?}",
            planner.name(),
            plan.solution.any_path()
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Boxes that share faces block as their union: no planner passes the slit between them,
    /// in two dimensions and three.
    #[test]
    fn touching_boxes_block_as_their_union(cuts in prop::collection::vec(0.05f64..0.95, 1..6), y in 0.05f64..0.95) {
        let a2 = SVector::from([0.1, y]);
        let b2 = SVector::from([0.9, y]);
        no_planner_crosses(&cut_wall::<2>(&cuts), a2, b2);
        // The straight segment along a cut meets both boxes' faces.
        let along = SVector::from([0.1, cuts[0]]);
        prop_assert!(!cut_wall::<2>(&cuts).segment_is_free(&along, &SVector::from([0.9, cuts[0]])));
        let a3 = SVector::from([0.1, y, 0.5]);
        let b3 = SVector::from([0.9, y, 0.5]);
        no_planner_crosses(&cut_wall::<3>(&cuts), a3, b3);
    }

    /// Two boxes touching at a corner leave no way through the corner point: the square's two
    /// other quarters are not joined.
    #[test]
    fn boxes_touching_at_a_corner_block_it(cx in 0.2f64..0.8, cy in 0.2f64..0.8) {
        let world = BoxWorld::new([0.0; 2], [1.0; 2], vec![([0.0, 0.0], [cx, cy]), ([cx, cy], [1.0, 1.0])]).unwrap();
        // The segment through the corner point itself, rounding and all.
        let (a, b) = (SVector::from([cx - 0.1, cy + 0.1]), SVector::from([cx + 0.1, cy - 0.1]));
        prop_assert!(world.is_free(&a) && world.is_free(&b));
        prop_assert!(!world.segment_is_free(&a, &b));
        no_planner_crosses(&world, a, b);
    }
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
fn boxes_are_closed_and_bad_boxes_are_errors() {
    let world = BoxWorld::new([0.0; 2], [1.0; 2], vec![([0.4, 0.4], [0.6, 0.6])]).unwrap();
    let p = |x: f64, y: f64| SVector::from([x, y]);
    // Along a face, through a corner, and inside: all meet the closed box.
    assert!(!world.segment_is_free(&p(0.4, 0.0), &p(0.4, 1.0)));
    assert!(!world.segment_is_free(&p(0.2, 0.8), &p(0.8, 0.2)));
    assert!(!world.segment_is_free(&p(0.3, 0.5), &p(0.5, 0.7)));
    assert!(!world.segment_is_free(&p(0.3, 0.7), &p(0.5, 0.5)));
    // Beside it, and touching nothing.
    assert!(world.segment_is_free(&p(0.39, 0.0), &p(0.39, 1.0)));
    assert!(world.segment_is_free(&p(0.3, 0.71), &p(0.5, 0.9)));
    assert!(!world.is_free(&p(0.5, 0.5)) && !world.is_free(&p(0.6, 0.5)) && world.is_free(&p(0.61, 0.5)));
    assert!(!world.segment_is_free(&p(0.5, 0.5), &p(0.5, 0.5)));
    // An inverted box is named as a box, not as the bounds.
    let inverted = vec![([0.1, 0.1], [0.2, 0.2]), ([0.5, 0.7], [0.6, 0.6])];
    assert_eq!(
        BoxWorld::new([0.0; 2], [1.0; 2], inverted),
        Err(SpaceError::InvalidBox { index: 1, axis: 1, low: 0.7, high: 0.6 })
    );
    assert!(matches!(
        BoxWorld::new([0.0; 2], [f64::NAN, 1.0], vec![]),
        Err(SpaceError::InvalidBounds { .. })
    ));
    // Sides each finite, a diagonal that is not: named as such, not as a planner's range.
    assert!(matches!(BoxWorld::new([-1e300; 3], [1e300; 3], vec![]), Err(SpaceError::RegionTooLarge { .. })));
    assert!(matches!(
        BoxWorld::<8>::new([0.0; 8], [1e-50; 8], vec![]),
        Err(SpaceError::RegionTooLarge { .. })
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
    let planners = every_planner(kd);
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
