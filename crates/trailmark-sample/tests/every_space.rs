//! Every planner in every space: R², Rⁿ (n = 2..8), SE(2), Dubins and the planar arm. Each state
//! of each returned path is in bounds and valid, each motion valid by a check the planners do
//! not use (exact segment tests against the true boxes in Rⁿ, dense samples against the true
//! obstacles elsewhere); starts and goals out of bounds, not finite or in collision are typed
//! errors for every planner.

use std::f64::consts::PI;

use nalgebra::SVector;
use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::termination::Termination;
use trailmark_core::world::{Bounds, PolygonWorld};
use trailmark_sample::arm::{ArmChecker, PlanarArm, densify};
use trailmark_sample::{
    Dubins, KdNearest, NearestNeighbors, PlanError, Planner, Prm, Problem, R2, ReedsShepp, Rejection, Rn,
    Rrt, RrtConnect, RrtStar, Sampled, Se2, Solution, StateSpace, Validity,
};

/// RRT, RRT-Connect, RRT*, PRM and PRM* over clones of `nearest`.
fn planners<S, V, N>(nearest: N, seed: u64) -> Vec<Box<dyn Planner<S, V>>>
where
    S: StateSpace + 'static,
    V: Validity<S> + 'static,
    N: NearestNeighbors<S> + Clone + 'static,
{
    vec![
        Box::new(Rrt::new(nearest.clone()).with_seed(seed)),
        Box::new(RrtConnect::new(nearest.clone()).with_seed(seed)),
        Box::new(RrtStar::new(nearest.clone()).with_seed(seed)),
        Box::new(Prm::new(nearest.clone()).with_seed(seed)),
        Box::new(Prm::star(nearest).with_seed(seed)),
    ]
}

/// Runs every planner from `start` to `goal` and checks each path: it begins at `start`, an
/// exact one ends at `goal`, each state is in bounds and `state_ok`, each motion `motion_ok`.
#[allow(clippy::too_many_arguments)]
fn every_path_is_valid<S, V, N>(
    space: &S,
    validity: &V,
    nearest: N,
    start: S::State,
    goal: S::State,
    iterations: u64,
    seed: u64,
    state_ok: impl Fn(&S::State) -> bool,
    motion_ok: impl Fn(&S::State, &S::State) -> bool,
) -> Result<usize, TestCaseError>
where
    S: StateSpace + 'static,
    V: Validity<S> + 'static,
    N: NearestNeighbors<S> + Clone + 'static,
{
    let problem = Problem::new(space, validity, start.clone(), goal.clone());
    let mut exact = 0;
    for mut planner in planners(nearest, seed) {
        let plan = planner.solve(&problem, &Termination::iterations(iterations)).unwrap();
        let path = match &plan.solution {
            Solution::Exact { path, .. } => {
                prop_assert_eq!(path.last(), Some(&goal), "{}", planner.name());
                exact += 1;
                path
            }
            Solution::Approximate { path, .. } => path,
            Solution::None => {
                // Only the roadmaps have nothing to return (before a start and a goal connect).
                prop_assert!(planner.name().starts_with("PRM"), "{}: no solution", planner.name());
                continue;
            }
        };
        prop_assert_eq!(&path[0], &start);
        for s in path {
            prop_assert!(space.satisfies_bounds(s), "{}: {s:?} out of bounds", planner.name());
            prop_assert!(state_ok(s), "{}: {s:?} not valid", planner.name());
        }
        for m in path.windows(2) {
            prop_assert!(motion_ok(&m[0], &m[1]), "{}: {:?} -> {:?} not valid", planner.name(), m[0], m[1]);
        }
    }
    Ok(exact)
}

/// Every planner refuses each of `bad` as the start and as the goal, for its reason.
fn bad_ends_are_refused<S, V, N>(
    space: &S,
    validity: &V,
    nearest: N,
    (start, goal): (S::State, S::State),
    bad: &[(S::State, Rejection)],
) where
    S: StateSpace + 'static,
    V: Validity<S> + 'static,
    N: NearestNeighbors<S> + Clone + 'static,
{
    let limit = Termination::iterations(100);
    for mut planner in planners(nearest, 1) {
        for (state, reason) in bad {
            let as_start = planner.solve(&Problem::new(space, validity, state.clone(), goal.clone()), &limit);
            assert_eq!(
                as_start.unwrap_err(),
                PlanError::InvalidStart { index: 0, reason: *reason },
                "{}",
                planner.name()
            );
            let as_goal = planner.solve(&Problem::new(space, validity, start.clone(), state.clone()), &limit);
            assert_eq!(
                as_goal.unwrap_err(),
                PlanError::InvalidGoal(*reason),
                "{}: {state:?}",
                planner.name()
            );
            // A second start that is bad is refused by its index.
            let two = Problem::new(space, validity, start.clone(), goal.clone()).and_start(state.clone());
            assert_eq!(
                planner.solve(&two, &limit).unwrap_err(),
                PlanError::InvalidStart { index: 1, reason: *reason }
            );
        }
    }
}

mod common;
use common::world_and_ends as polygon_world;

/// Whether the segment `a`-`b` is clear of `world`'s obstacles, sampled every 1e-3.
fn densely_clear(world: &PolygonWorld, a: Point, b: Point) -> bool {
    let n = ((b - a).norm() / 1e-3).ceil().max(1.0) as usize;
    (0..=n).all(|i| world.reference_is_clear(a + (b - a) * (i as f64 / n as f64), 1e-9))
}

fn position(pose: &Pose) -> Point {
    Point::from(pose.translation.vector)
}

/// The centre of obstacle 0: a point in collision.
fn inside(world: &PolygonWorld) -> Point {
    let vertices = world.obstacles()[0].vertices();
    vertices.iter().fold(Point::origin(), |s, v| s + v.coords / vertices.len() as f64)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    #[test]
    fn r2_paths_are_valid((world, a, b) in (1usize..20, 0.0f64..1.0, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| polygon_world(c, r, s)), seed in any::<u64>()) {
        let checker = world.checker();
        let space = R2::new(world.bounds());
        let kd = KdNearest::<R2, 2>::new(&space).unwrap();
        every_path_is_valid(&space, &checker, kd, a, b, 1500, seed, |p| world.reference_is_clear(*p, 1e-9), |p, q| densely_clear(&world, *p, *q))?;
    }

    #[test]
    fn se2_paths_are_valid((world, a, b) in (1usize..20, 0.0f64..1.0, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| polygon_world(c, r, s)), seed in any::<u64>(), headings in any::<[u16; 2]>()) {
        let checker = world.checker();
        let space = Se2::new(world.bounds());
        let heading = |h: u16| f64::from(h) / 65536.0 * std::f64::consts::TAU - PI;
        let (a, b) = (Pose::new(a.coords, heading(headings[0])), Pose::new(b.coords, heading(headings[1])));
        let kd = KdNearest::<Se2, 2>::new(&space).unwrap();
        every_path_is_valid(&space, &checker, kd, a, b, 1500, seed, |s| world.reference_is_clear(position(s), 1e-9), |s, t| densely_clear(&world, position(s), position(t)))?;
    }

    #[test]
    fn dubins_paths_are_valid((world, a, b) in (1usize..12, 0.0f64..0.5, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| polygon_world(c, r, s)), seed in any::<u64>(), headings in any::<[u16; 2]>()) {
        let checker = world.checker();
        let space = Dubins::new(world.bounds(), 1.5).unwrap();
        let heading = |h: u16| f64::from(h) / 65536.0 * std::f64::consts::TAU - PI;
        let (a, b) = (Pose::new(a.coords, heading(headings[0])), Pose::new(b.coords, heading(headings[1])));
        let kd = KdNearest::<Dubins, 2>::new(&space).unwrap();
        let curve_clear = |s: &Pose, t: &Pose| {
            let curve = space.path(s, t);
            curve.sample(1e-2).unwrap().iter().all(|p| world.reference_is_clear(position(p), 1e-9))
        };
        every_path_is_valid(&space, &checker, kd, a, b, 1200, seed, |s| world.reference_is_clear(position(s), 1e-9), curve_clear)?;
    }

    #[test]
    fn reeds_shepp_paths_are_valid((world, a, b) in (1usize..12, 0.0f64..0.5, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| polygon_world(c, r, s)), seed in any::<u64>(), headings in any::<[u16; 2]>()) {
        let checker = world.checker();
        let space = ReedsShepp::new(world.bounds(), 1.5).unwrap();
        let heading = |h: u16| f64::from(h) / 65536.0 * std::f64::consts::TAU - PI;
        let (a, b) = (Pose::new(a.coords, heading(headings[0])), Pose::new(b.coords, heading(headings[1])));
        let kd = KdNearest::<ReedsShepp, 2>::new(&space).unwrap();
        let curve_clear = |s: &Pose, t: &Pose| {
            let curve = space.path(s, t);
            curve.sample(1e-2).unwrap().iter().all(|p| world.reference_is_clear(position(p), 1e-9))
        };
        every_path_is_valid(&space, &checker, kd, a, b, 1200, seed, |s| world.reference_is_clear(position(s), 1e-9), curve_clear)?;
    }

    #[test]
    fn arm_paths_are_valid(seed in any::<u64>()) {
        let post = vec![Point::new(7.0, 0.0), Point::new(7.5, 0.0), Point::new(7.5, 2.0), Point::new(7.0, 2.0)];
        let room = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 6.0).unwrap(), vec![post], 0.0).unwrap();
        let arm = PlanarArm::new(Point::new(5.0, 0.0), [2.5, 2.0, 1.5], 0.15).unwrap();
        let space = Rn::new([-PI; 3], [PI; 3]).unwrap();
        let resolution = 1e-3;
        let planning = ArmChecker::new(arm, &room, arm.clearance(&space, resolution)).unwrap();
        let exact = ArmChecker::new(arm, &room, 0.0).unwrap();
        let validity = Sampled::new(move |q: &SVector<f64, 3>| planning.is_free(q), resolution).unwrap();
        let (a, b) = ([2.6, -0.5, -0.5].into(), [1.0, -0.7, -1.5].into());
        let kd = KdNearest::<Rn<3>, 3>::new(&space).unwrap();
        let dense = |p: &SVector<f64, 3>, q: &SVector<f64, 3>| densify(&space, &[*p, *q], 1e-3).iter().all(|s| exact.is_free(s));
        every_path_is_valid(&space, &validity, kd, a, b, 1500, seed, |q| exact.is_free(q), dense)?;
    }
}

/// Axis-aligned boxes in the unit cube of `N` dimensions, as in the BIT* papers' random worlds.
#[derive(Clone, Debug)]
struct Boxes<const N: usize> {
    boxes: Vec<([f64; N], [f64; N])>,
}

impl<const N: usize> Boxes<N> {
    fn random(count: usize, rng: &mut ChaCha8Rng) -> Self {
        let boxes = (0..count)
            .map(|_| {
                let low: [f64; N] = std::array::from_fn(|_| rng.random_range(0.0..0.8));
                let high = std::array::from_fn(|i| low[i] + rng.random_range(0.05..0.2));
                (low, high)
            })
            .collect();
        Boxes { boxes }
    }

    /// Whether `q` is outside every box grown by `margin`.
    fn clear(&self, q: &SVector<f64, N>, margin: f64) -> bool {
        self.boxes.iter().all(|(lo, hi)| (0..N).any(|i| q[i] < lo[i] - margin || q[i] > hi[i] + margin))
    }

    /// Whether the segment `a`-`b` misses every box, exactly (the slab test).
    fn segment_clear(&self, a: &SVector<f64, N>, b: &SVector<f64, N>) -> bool {
        self.boxes.iter().all(|(lo, hi)| {
            let (mut t0, mut t1) = (0.0f64, 1.0f64);
            for i in 0..N {
                let d = b[i] - a[i];
                if d == 0.0 {
                    if a[i] < lo[i] || a[i] > hi[i] {
                        return true;
                    }
                } else {
                    let (u, v) = ((lo[i] - a[i]) / d, (hi[i] - a[i]) / d);
                    t0 = t0.max(u.min(v));
                    t1 = t1.min(u.max(v));
                    if t0 > t1 {
                        return true;
                    }
                }
            }
            false
        })
    }
}

/// Rⁿ among random boxes: the planners check motions by sampling at a resolution, against the
/// boxes grown by half a step (so no segment between two checked states can enter a true box);
/// the paths are then checked exactly against the true boxes.
fn rn_paths_are_valid<const N: usize>(seed: u64) -> Result<(), TestCaseError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let world = Boxes::<N>::random(4 * N, &mut rng);
    let space = Rn::<N>::new([0.0; N], [1.0; N]).unwrap();
    let resolution = 2e-3;
    let margin = resolution * space.extent() / 2.0 * (1.0 + 1e-9);
    let planning = world.clone();
    let validity = Sampled::new(move |q: &SVector<f64, N>| planning.clear(q, margin), resolution).unwrap();
    let mut free = || loop {
        let q = space.sample(&mut rng);
        if world.clear(&q, margin) {
            return q;
        }
    };
    let (a, b) = (free(), free());
    let kd = KdNearest::<Rn<N>, N>::new(&space).unwrap();
    every_path_is_valid(
        &space,
        &validity,
        kd.clone(),
        a,
        b,
        800,
        seed,
        |q| world.clear(q, 0.0),
        |p, q| world.segment_clear(p, q),
    )?;
    let blocked = loop {
        let q = space.sample(&mut rng);
        if !world.clear(&q, 0.0) {
            break q;
        }
    };
    let mut nan = a;
    nan[N - 1] = f64::NAN;
    let mut outside = a;
    outside[0] = 1.5;
    let bad = [(outside, Rejection::OutOfBounds), (nan, Rejection::NotFinite), (blocked, Rejection::Invalid)];
    bad_ends_are_refused(&space, &validity, kd, (a, b), &bad);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3))]

    #[test]
    fn rn_paths_are_valid_in_2_to_8_dimensions(seed in any::<u64>()) {
        rn_paths_are_valid::<2>(seed)?;
        rn_paths_are_valid::<3>(seed)?;
        rn_paths_are_valid::<4>(seed)?;
        rn_paths_are_valid::<5>(seed)?;
        rn_paths_are_valid::<6>(seed)?;
        rn_paths_are_valid::<7>(seed)?;
        rn_paths_are_valid::<8>(seed)?;
    }
}

#[test]
fn bad_ends_are_typed_errors_in_every_space() {
    let (world, a, b) = polygon_world(10, 0.5, 5).unwrap();
    let checker = world.checker();
    let blocked = inside(&world);
    let r2 = R2::new(world.bounds());
    let bad = [
        (Point::new(-1.0, 5.0), Rejection::OutOfBounds),
        (Point::new(5.0, 1e9), Rejection::OutOfBounds),
        (Point::new(f64::NAN, 5.0), Rejection::NotFinite),
        (Point::new(5.0, f64::NEG_INFINITY), Rejection::NotFinite),
        (blocked, Rejection::Invalid),
    ];
    bad_ends_are_refused(&r2, &checker, KdNearest::<R2, 2>::new(&r2).unwrap(), (a, b), &bad);
    let pose = |p: Point| Pose::new(p.coords, 0.3);
    let poses: Vec<(Pose, Rejection)> = bad.iter().map(|&(p, r)| (pose(p), r)).collect();
    let se2 = Se2::new(world.bounds());
    bad_ends_are_refused(&se2, &checker, KdNearest::<Se2, 2>::new(&se2).unwrap(), (pose(a), pose(b)), &poses);
    let dubins = Dubins::new(world.bounds(), 1.0).unwrap();
    let kd = KdNearest::<Dubins, 2>::new(&dubins).unwrap();
    bad_ends_are_refused(&dubins, &checker, kd, (pose(a), pose(b)), &poses);
}

/// The arm with joint limits of ±π: a start at `[1000; 6]` (the joints wound far past their
/// limits), or NaN that the user's own test accepts, is refused, not planned from.
#[test]
fn an_arm_start_beyond_its_joint_limits_is_refused() {
    let space = Rn::new([-PI; 6], [PI; 6]).unwrap();
    let accept_all = Sampled::new(|_: &SVector<f64, 6>| true, 1e-3).unwrap();
    let kd = KdNearest::<Rn<6>, 6>::new(&space).unwrap();
    let (a, b) = (SVector::from([0.5; 6]), SVector::from([-0.5; 6]));
    let bad = [
        (SVector::from([1000.0; 6]), Rejection::OutOfBounds),
        (SVector::from([1e6; 6]), Rejection::OutOfBounds),
        (SVector::from([f64::NAN; 6]), Rejection::NotFinite),
    ];
    bad_ends_are_refused(&space, &accept_all, kd, (a, b), &bad);
}
