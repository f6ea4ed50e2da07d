//! RRT and RRT-Connect on generated polygon worlds: every returned path starts and ends where
//! asked, each motion is valid by the exact checker and by an independent test sampled every
//! 1e-3, Dubins paths follow Dubins curves of the turning radius, the same seed gives the same
//! run, and bad input gives typed errors.

use proptest::prelude::*;
use trailmark_core::generate;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::world::PolygonWorld;
use trailmark_sample::nearest::{BruteForce, KdNearest, NearestNeighbors};
use trailmark_sample::simplify::{shortcut, simplify};
use trailmark_sample::space::{Car, CarCurves, Dubins, DubinsCurves, R2, ReedsSheppCurves, StateSpace};
use trailmark_sample::{
    Plan, PlanError, Planner, Problem, Rejection, Rrt, RrtConnect, RrtOptions, RrtStar, Solution,
};

mod common;
use common::world_and_ends;

fn check_r2(
    world: &PolygonWorld,
    plan: &Plan<Point>,
    start: Point,
    goal: Point,
) -> Result<(), TestCaseError> {
    let checker = world.checker();
    let (path, cost) = match &plan.solution {
        Solution::Exact { path, cost } => {
            prop_assert_eq!(*path.last().unwrap(), goal);
            (path, *cost)
        }
        Solution::Approximate { path, cost, goal_distance } => {
            prop_assert!(*goal_distance > 0.0);
            (path, *cost)
        }
        Solution::None => panic!("the tree planners return at least a start"),
    };
    prop_assert_eq!(path[0], start);
    for m in path.windows(2) {
        prop_assert!(checker.segment_is_free(m[0], m[1]), "{} -> {} collides", m[0], m[1]);
        let n = ((m[1] - m[0]).norm() / 1e-3).ceil().max(1.0) as usize;
        for i in 0..=n {
            let p = m[0] + (m[1] - m[0]) * (i as f64 / n as f64);
            prop_assert!(
                world.reference_is_clear(p, 1e-9),
                "{p} on {} -> {} is too close to an obstacle",
                m[0],
                m[1]
            );
        }
    }
    let measured: f64 = path.windows(2).map(|m| (m[1] - m[0]).norm()).sum();
    prop_assert!((measured - cost).abs() <= 1e-9 * cost.max(1.0));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn rrt_connect_and_rrt_paths_are_valid((world, start, goal) in (1usize..25, 0.0f64..1.0, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| world_and_ends(c, r, s)), seed in any::<u64>()) {
        let checker = world.checker();
        let space = R2::new(world.bounds());
        let kd = KdNearest::<R2, 2>::new(&space).unwrap();
        let problem = Problem::new(&space, &checker, start, goal);
        let plan = RrtConnect::new(kd.clone()).with_seed(seed).solve(&problem, &Termination::iterations(5000)).unwrap();
        check_r2(&world, &plan, start, goal)?;
        // Shortcuts keep the ends and validity, and never cost more.
        if let Some(path) = plan.path() {
            let short = shortcut(&space, &checker, path, 100, seed);
            let cost = |p: &[Point]| p.windows(2).map(|m| (m[1] - m[0]).norm()).sum::<f64>();
            let shortened = Plan { solution: Solution::Exact { path: short.clone(), cost: cost(&short) }, ..plan.clone() };
            check_r2(&world, &shortened, start, goal)?;
            prop_assert!(cost(&short) <= plan.cost().unwrap() + 1e-9);
            prop_assert!(short.len() <= path.len());
            // So do shortcuts followed by corner cutting.
            let round = simplify(&space, &checker, path, 100, 4, seed);
            let rounded = Plan { solution: Solution::Exact { path: round.clone(), cost: cost(&round) }, ..plan.clone() };
            check_r2(&world, &rounded, start, goal)?;
            prop_assert!(cost(&round) <= cost(&short) + 1e-9);
        }
        let options = RrtOptions { goal_bias: 0.1, ..RrtOptions::default() };
        let plan = Rrt::new(kd).with_options(options).with_seed(seed).solve(&problem, &Termination::iterations(3000)).unwrap();
        check_r2(&world, &plan, start, goal)?;
    }

    /// Dubins: each motion of the path is the shortest Dubins curve between its poses, free by
    /// the exact checker and by its poses sampled every 1e-2; the path starts and ends at the
    /// requested poses.
    #[test]
    fn dubins_rrt_connect_paths_follow_free_dubins_curves((world, start, goal) in (1usize..15, 0.0f64..0.5, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| world_and_ends(c, r, s)), seed in any::<u64>(), headings in any::<[u16; 2]>()) {
        car_paths_follow_free_curves::<DubinsCurves>(&world, start, goal, seed, headings)?;
    }

    /// Reeds-Shepp: the same, with pieces driven in reverse.
    #[test]
    fn reeds_shepp_rrt_connect_paths_follow_free_curves((world, start, goal) in (1usize..15, 0.0f64..0.5, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| world_and_ends(c, r, s)), seed in any::<u64>(), headings in any::<[u16; 2]>()) {
        car_paths_follow_free_curves::<ReedsSheppCurves>(&world, start, goal, seed, headings)?;
    }
}

/// RRT-Connect in the car space of the curves `C`: each motion of the path is the shortest curve
/// between its poses, free by the exact checker and by its poses sampled every 1e-2; the path
/// starts and ends at the requested poses, costs what it says, and stays so when shortcut.
fn car_paths_follow_free_curves<C: CarCurves>(
    world: &PolygonWorld,
    start: Point,
    goal: Point,
    seed: u64,
    headings: [u16; 2],
) -> Result<(), TestCaseError> {
    let space = Car::<C>::new(world.bounds(), 1.5).unwrap();
    let checker = world.checker();
    let heading = |h: u16| f64::from(h) / 65536.0 * std::f64::consts::TAU;
    let (a, b) =
        (Pose::new(start.coords, heading(headings[0])), Pose::new(goal.coords, heading(headings[1])));
    let kd = KdNearest::<Car<C>, 2>::new(&space).unwrap();
    let plan = RrtConnect::new(kd)
        .with_seed(seed)
        .solve(&Problem::new(&space, &checker, a, b), &Termination::iterations(4000))
        .unwrap();
    let path = plan.solution.any_path().expect("a path, exact or approximate").to_vec();
    prop_assert_eq!(path[0], a);
    if plan.is_exact() {
        prop_assert_eq!(*path.last().unwrap(), b);
    }
    for m in path.windows(2) {
        let curve = space.path(&m[0], &m[1]);
        prop_assert!(C::is_free(&checker, &curve));
        let length = C::path_length(&curve);
        let steps = (length / 1e-2).ceil() as u32;
        for k in 0..=steps {
            let p = C::pose_along(&curve, (f64::from(k) * 1e-2).min(length)).unwrap();
            prop_assert!(world.reference_is_clear(Point::from(p.translation.vector), 1e-9));
        }
    }
    let cost: f64 = path.windows(2).map(|m| space.distance(&m[0], &m[1])).sum();
    let (Solution::Exact { cost: planned, .. } | Solution::Approximate { cost: planned, .. }) = plan.solution
    else {
        unreachable!()
    };
    prop_assert!((cost - planned).abs() <= 1e-9 * cost.max(1.0));
    // Shortcut paths stay chains of free curves between the same poses.
    let short = shortcut(&space, &checker, &path, 50, seed);
    prop_assert_eq!((short[0], short.last()), (a, path.last()));
    prop_assert!(short.windows(2).all(|m| C::is_free(&checker, &space.path(&m[0], &m[1]))));
    let short_cost: f64 = short.windows(2).map(|m| space.distance(&m[0], &m[1])).sum();
    prop_assert!(short_cost <= cost + 1e-9);
    Ok(())
}

/// The same seed gives the same path and counts, with either nearest-neighbour structure.
#[test]
fn the_same_seed_gives_the_same_run() {
    let (world, start, goal) = world_and_ends(20, 0.5, 3).unwrap();
    let space = R2::new(world.bounds());
    fn connect<N: NearestNeighbors<R2> + Clone>(
        space: &R2,
        world: &PolygonWorld,
        nearest: N,
        ends: (Point, Point),
        seed: u64,
    ) -> Plan<Point> {
        let checker = world.checker();
        let problem = Problem::new(space, &checker, ends.0, ends.1);
        RrtConnect::new(nearest).with_seed(seed).solve(&problem, &Termination::iterations(5000)).unwrap()
    }
    let run = |seed: u64| {
        let plan = connect(&space, &world, KdNearest::<R2, 2>::new(&space).unwrap(), (start, goal), seed);
        let again = connect(&space, &world, BruteForce::<R2>::new(), (start, goal), seed);
        assert_eq!(plan.solution, again.solution, "k-d tree and brute force agree");
        let s = plan.stats;
        (plan.solution, s.iterations, s.tree_sizes, s.collision_checks)
    };
    assert_eq!(run(11), run(11));
    assert!(run(11).0.is_exact());
    assert_ne!(run(11).0, run(12).0);
}

#[test]
fn bad_input_is_a_typed_error() {
    let (world, start, goal) = world_and_ends(10, 0.5, 5).unwrap();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let kd = KdNearest::<R2, 2>::new(&space).unwrap();
    let inside = world.obstacles()[0].vertices().iter().fold(Point::origin(), |s, v| s + v.coords / 6.0);
    let ok = Termination::iterations(10);
    let planners = |o: RrtOptions| -> Vec<Box<dyn Planner<R2, _>>> {
        vec![
            Box::new(Rrt::new(kd.clone()).with_options(o)),
            Box::new(RrtConnect::new(kd.clone()).with_options(o)),
            Box::new(RrtStar::new(kd.clone()).with_options(o)),
        ]
    };
    for mut planner in planners(RrtOptions::default()) {
        let mut plan =
            |a: Point, b: Point, t: &Termination| planner.solve(&Problem::new(&space, &checker, a, b), t);
        let invalid = |reason| PlanError::InvalidStart { index: 0, reason };
        assert_eq!(plan(inside, goal, &ok).unwrap_err(), invalid(Rejection::Invalid));
        assert_eq!(plan(Point::new(-1.0, 5.0), goal, &ok).unwrap_err(), invalid(Rejection::OutOfBounds));
        assert_eq!(plan(Point::new(f64::NAN, 5.0), goal, &ok).unwrap_err(), invalid(Rejection::NotFinite));
        assert_eq!(plan(start, inside, &ok).unwrap_err(), PlanError::InvalidGoal(Rejection::Invalid));
        assert_eq!(
            plan(start, Point::new(5.0, 1e6), &ok).unwrap_err(),
            PlanError::InvalidGoal(Rejection::OutOfBounds)
        );
        assert_eq!(
            plan(start, Point::new(5.0, f64::INFINITY), &ok).unwrap_err(),
            PlanError::InvalidGoal(Rejection::NotFinite)
        );
        assert_eq!(plan(start, goal, &Termination::default()).unwrap_err(), PlanError::NoLimit);
    }
    for bad in [
        RrtOptions { range: Some(0.0), ..RrtOptions::default() },
        RrtOptions { range: Some(f64::NAN), ..RrtOptions::default() },
        RrtOptions { goal_bias: 1.5, ..RrtOptions::default() },
    ] {
        for mut planner in planners(bad) {
            let result = planner.solve(&Problem::new(&space, &checker, start, goal), &ok);
            assert!(matches!(result, Err(PlanError::InvalidOption { .. })), "{bad:?}");
        }
    }
    let tolerance = trailmark_sample::GoalState::within(goal, -1.0);
    let result = Rrt::new(kd.clone()).solve(&Problem::with_goal(&space, &checker, start, tolerance), &ok);
    assert!(matches!(result, Err(PlanError::InvalidOption { name: "goal tolerance", .. })));
}

/// A goal inside a closed ring of walls: no exact path, reported as such (the branch to the
/// nearest state, marked approximate), not as an error.
#[test]
fn a_walled_off_goal_gives_no_path() {
    let (world, _) = generate::walled_goal(0.2).unwrap();
    let bounds = world.bounds();
    let checker = world.checker();
    let space = R2::new(bounds);
    let kd = KdNearest::<R2, 2>::new(&space).unwrap();
    let (start, goal) = (Point::new(2.0, 2.0), Point::new(15.0, 15.0));
    let limit = Termination::iterations(2000);
    let problem = Problem::new(&space, &checker, start, goal);
    let connect = RrtConnect::new(kd.clone()).with_seed(1).solve(&problem, &limit).unwrap();
    assert_eq!(connect.stats.iterations, 2000);
    let plan = Rrt::new(kd).with_seed(1).solve(&problem, &limit).unwrap();
    for plan in [connect, plan] {
        assert_eq!(plan.stop, Stop::IterationLimit);
        assert_eq!((plan.path(), plan.cost()), (None, None), "nothing reads as an answer");
        let Solution::Approximate { path, cost, goal_distance } = plan.solution else {
            panic!("approximate")
        };
        let last = *path.last().unwrap();
        assert_eq!(path[0], start);
        assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
        assert!(goal_distance >= 5.2 - 1e-9, "{last} is inside the ring"); // the grown outer wall is 5.2 from the goal
        assert!((goal_distance - (goal - last).norm()).abs() < 1e-12);
        assert!((cost - path.windows(2).map(|m| (m[1] - m[0]).norm()).sum::<f64>()).abs() < 1e-9);
    }
}

/// A user condition stops a run: here after the 300th iteration, and with the progress it is
/// shown counting up one iteration at a time.
#[test]
fn a_user_condition_stops_the_run() {
    use std::sync::{Arc, Mutex};
    let (world, start, goal) = world_and_ends(10, 0.5, 5).unwrap();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let run = |limit: &Termination| {
        let kd = KdNearest::<R2, 2>::new(&space).unwrap();
        RrtStar::new(kd).with_seed(2).solve(&Problem::new(&space, &checker, start, goal), limit).unwrap()
    };
    let seen = Arc::new(Mutex::new(Vec::new()));
    let log = Arc::clone(&seen);
    let plan = run(&Termination::when(move |progress| {
        log.lock().unwrap().push(progress.iterations);
        progress.iterations >= 300
    }));
    assert_eq!((plan.stats.iterations, plan.stop), (300, Stop::Caller));
    // Asked before every iteration and within them (before the motion checks of the parent
    // search and rewiring): the count it sees never falls.
    let seen = seen.lock().unwrap();
    assert!(seen.windows(2).all(|w| w[0] <= w[1]));
    assert_eq!((seen[0], *seen.last().unwrap()), (0, 300));
    // The best cost reaches the condition once there is one.
    let costs = Arc::new(Mutex::new(Vec::new()));
    let log = Arc::clone(&costs);
    let plan = run(&Termination::iterations(2000).or_when(move |progress| {
        log.lock().unwrap().push(progress.best_cost);
        false
    }));
    let costs = costs.lock().unwrap();
    assert!(costs.len() >= 2000);
    assert_eq!(costs.last().copied().flatten(), plan.history.last().map(|b| b.cost));
}

mod star {
    use super::*;
    use trailmark_sample::rrt_star::neighbour_count;

    #[test]
    fn neighbour_count_is_the_published_formula() {
        // k_rrt = 1.1 · 2^3 · e · 1.5 for d = 2; ⌈k_rrt ln 1000⌉.
        let k_rrt = 1.1 * 8.0 * std::f64::consts::E * 1.5;
        assert_eq!(neighbour_count(1000, 2), (k_rrt * 1000f64.ln()).ceil() as usize);
        assert_eq!(neighbour_count(1, 2), 1);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(8))]

        /// RRT* paths are valid like RRT's; each recorded improvement is cheaper than the last
        /// and the final path costs what the last one says; the same seed gives the same run.
        #[test]
        fn rrt_star_paths_are_valid_and_improve((world, start, goal) in (1usize..20, 0.0f64..1.0, any::<u64>()).prop_filter_map("free ends", |(c, r, s)| world_and_ends(c, r, s)), seed in any::<u64>()) {
            let checker = world.checker();
            let space = R2::new(world.bounds());
            let run = || {
                let kd = KdNearest::<R2, 2>::new(&space).unwrap();
                RrtStar::new(kd).with_seed(seed).solve(&Problem::new(&space, &checker, start, goal), &Termination::iterations(1200)).unwrap()
            };
            let plan = run();
            check_r2(&world, &plan, start, goal)?;
            prop_assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost && w[1].iteration > w[0].iteration));
            if let Some(last) = plan.history.last() {
                prop_assert!(plan.is_exact());
                prop_assert!((last.cost - plan.cost().unwrap()).abs() <= 1e-9 * last.cost.max(1.0));
                prop_assert!(plan.cost().unwrap() >= (goal - start).norm() - 1e-9);
            } else {
                prop_assert!(!plan.is_exact());
            }
            let again = run();
            prop_assert_eq!((&plan.solution, plan.stats.collision_checks), (&again.solution, again.stats.collision_checks));
        }
    }

    /// A target cost ends the run as soon as a path that cheap is found.
    #[test]
    fn a_target_cost_stops_the_run() {
        let bounds = trailmark_core::world::Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        let world = PolygonWorld::new(bounds, vec![], 0.0).unwrap();
        let checker = world.checker();
        let space = R2::new(bounds);
        let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 9.0));
        let limit = Termination::iterations(100_000).and_target_cost(20.0);
        let plan = RrtStar::new(BruteForce::new()).with_seed(3).solve(&problem, &limit).unwrap();
        assert!(plan.cost().unwrap() <= 20.0);
        assert_eq!(plan.stop, Stop::TargetCost);
        assert!(plan.stats.iterations < 100_000);
        assert_eq!(plan.stats.iterations, plan.history.last().unwrap().iteration);
    }

    /// Dubins RRT*: a chain of free shortest Dubins curves from the start pose to the goal pose.
    #[test]
    fn dubins_rrt_star_follows_free_curves() {
        let (world, start, goal) = world_and_ends(8, 0.3, 9).unwrap();
        let checker = world.checker();
        let space = Dubins::new(world.bounds(), 1.0).unwrap();
        let (a, b) = (Pose::new(start.coords, 0.5), Pose::new(goal.coords, -2.0));
        let kd = KdNearest::<Dubins, 2>::new(&space).unwrap();
        let plan = RrtStar::new(kd)
            .with_seed(4)
            .solve(&Problem::new(&space, &checker, a, b), &Termination::iterations(1500))
            .unwrap();
        let path = plan.solution.any_path().unwrap();
        assert_eq!(path[0], a);
        if plan.is_exact() {
            assert_eq!(*path.last().unwrap(), b);
        }
        for m in path.windows(2) {
            let curve = space.path(&m[0], &m[1]);
            assert!(checker.dubins_is_free(&curve));
            assert!(
                curve
                    .sample(1e-2)
                    .unwrap()
                    .iter()
                    .all(|p| world.reference_is_clear(Point::from(p.translation.vector), 1e-9))
            );
        }
    }
}

/// A nearest-neighbour structure that already holds states is refused; a goal tolerance that the
/// start tree meets before the trees meet ends RRT-Connect with an exact path there; a huge `k`
/// neither overflows nor hangs.
#[test]
fn review_cases() {
    use trailmark_sample::prm::Connection;
    use trailmark_sample::{GoalState, Prm};
    let (world, start, goal) = world_and_ends(10, 0.5, 5).unwrap();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut used = KdNearest::<R2, 2>::new(&space).unwrap();
    used.insert(&space, start);
    let problem = Problem::new(&space, &checker, start, goal);
    let limit = Termination::iterations(100);
    let planners: Vec<Box<dyn Planner<R2, _>>> = vec![
        Box::new(Rrt::new(used.clone())),
        Box::new(RrtConnect::new(used.clone())),
        Box::new(RrtStar::new(used.clone())),
        Box::new(Prm::new(used.clone())),
    ];
    for mut planner in planners {
        let error = planner.solve(&problem, &limit).unwrap_err();
        assert!(matches!(error, PlanError::InvalidOption { name: "nearest", .. }), "{}", planner.name());
    }
    let kd = KdNearest::<R2, 2>::new(&space).unwrap();
    let tolerance = 0.45 * (goal - start).norm();
    let near = Problem::with_goal(&space, &checker, start, GoalState::within(goal, tolerance));
    let mut short = 0;
    for seed in 0..40 {
        let plan =
            RrtConnect::new(kd.clone()).with_seed(seed).solve(&near, &Termination::iterations(5000)).unwrap();
        let path = plan.path().expect("within the tolerance");
        assert!((path[path.len() - 1] - goal).norm() <= tolerance);
        // Where the start tree met the tolerance before the trees met, the path ends there,
        // short of the goal state the goal tree grows from.
        short += usize::from(path[path.len() - 1] != goal);
    }
    assert!(short > 0, "no run ended where the start tree met the tolerance");
    let mut huge = Prm::new(kd).with_connection(Connection::Nearest { k: usize::MAX });
    huge.solve(&problem, &Termination::iterations(50)).unwrap();
}
