//! PRM and PRM* over state spaces: the roadmap's every edge is a valid motion costing the
//! space's distance (both ways in symmetric spaces, one way in Dubins), queries share one
//! roadmap, PRM* improves toward the optimum, A* on the roadmap agrees with Dijkstra, a walled
//! goal gives no solution, and bad settings are typed errors.

use trailmark_core::geometry::{Point, Pose};
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::world::{Bounds, PolygonWorld};
use trailmark_sample::prm::Connection;
use trailmark_sample::{Dubins, KdNearest, PlanError, Planner, Prm, Problem, R2, Solution, StateSpace};
use trailmark_search::{astar, dijkstra};

fn wall_world() -> PolygonWorld {
    let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
    let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
    PolygonWorld::new(bounds, vec![wall], 0.0).unwrap()
}

/// Every edge of `prm` is a valid motion that costs the space's distance; in a symmetric space
/// it is there both ways at the same cost.
fn edges_are_valid<S: StateSpace, V: trailmark_sample::Validity<S>, N, Q>(
    prm: &Prm<S, N, Q>,
    space: &S,
    validity: &V,
) where
    N: trailmark_sample::NearestNeighbors<S> + Clone,
{
    let mut count = 0;
    for u in 0..prm.node_count() as u32 {
        assert!(space.satisfies_bounds(prm.state(u)) && validity.state_is_valid(space, prm.state(u)));
        for &(v, cost) in prm.edges_from(u) {
            let (a, b) = (prm.state(u), prm.state(v));
            assert!(validity.motion_is_valid(space, a, b), "{a:?} -> {b:?}");
            assert_eq!(cost, space.distance(a, b));
            if S::SYMMETRIC {
                assert!(prm.edges_from(v).iter().any(|&(w, c)| w == u && c == cost));
            }
            count += 1;
        }
    }
    let expected = if S::SYMMETRIC { 2 * prm.edge_count() } else { prm.edge_count() };
    assert_eq!(count, expected);
}

#[test]
fn queries_share_one_roadmap_and_prm_star_approaches_the_optimum() {
    let world = wall_world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut prm = Prm::star(KdNearest::<R2, 2>::new(&space).unwrap()).with_seed(5);
    let optimum = 2.0 * 58f64.sqrt() + 2.0; // up to the wall's corners, across, down
    let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
    let plan = prm.solve(&problem, &Termination::iterations(3_000)).unwrap();
    let cost = plan.cost().expect("over the wall");
    assert!(cost >= optimum - 1e-9 && cost < 1.1 * optimum, "{cost} against {optimum}");
    assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost));
    assert_eq!(plan.stop, Stop::IterationLimit);
    edges_are_valid(&prm, &space, &checker);
    // A second query on the same roadmap: it keeps what the first grew.
    let grown = prm.node_count();
    let other = Problem::new(&space, &checker, Point::new(1.0, 9.0), Point::new(9.0, 9.0));
    let plan = prm.solve(&other, &Termination::iterations(10)).unwrap();
    assert!(plan.is_exact(), "the roadmap already spans the world");
    assert!(prm.node_count() >= grown);
    // Cleared, it starts again.
    prm.clear();
    assert_eq!((prm.node_count(), prm.edge_count()), (0, 0));
}

#[test]
fn prm_stops_at_its_first_path() {
    let world = wall_world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut prm = Prm::new(KdNearest::<R2, 2>::new(&space).unwrap()).with_seed(2);
    let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
    let plan = prm.solve(&problem, &Termination::iterations(100_000)).unwrap();
    assert_eq!(plan.stop, Stop::Solved);
    assert!(plan.stats.iterations < 100_000);
    let path = plan.path().unwrap();
    assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
}

#[test]
fn astar_on_the_roadmap_agrees_with_dijkstra() {
    let world = wall_world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut prm = Prm::star(KdNearest::<R2, 2>::new(&space).unwrap())
        .with_connection(Connection::Radius { radius: 2.0 });
    let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
    prm.solve(&problem, &Termination::iterations(800)).unwrap();
    assert!(prm.node_count() > 250);
    edges_are_valid(&prm, &space, &checker);
    for u in 0..prm.node_count() as u32 {
        assert!(prm.edges_from(u).iter().all(|&(_, c)| c <= 2.0));
    }
    for (s, g) in [(0, 1), (3, 17), (40, 2), (100, 250)] {
        let h = |n: u32| space.distance(prm.state(n), prm.state(g));
        let a = astar(&prm, s, g, h).unwrap().cost();
        let d = dijkstra(&prm, s, g).unwrap().cost();
        match (a, d) {
            (Some(a), Some(d)) => assert!((a - d).abs() <= 1e-9 * d.max(1.0), "{a} against {d}"),
            (a, d) => assert_eq!(a, d),
        }
    }
}

#[test]
fn a_dubins_roadmap_is_directed_and_follows_free_curves() {
    let world = wall_world();
    let checker = world.checker();
    let space = Dubins::new(world.bounds(), 0.8).unwrap();
    let mut prm = Prm::star(KdNearest::<Dubins, 2>::new(&space).unwrap()).with_seed(1);
    let problem = Problem::new(
        &space,
        &checker,
        Pose::new(Point::new(1.0, 1.0).coords, 1.5),
        Pose::new(Point::new(9.0, 1.0).coords, -1.5),
    );
    let plan = prm.solve(&problem, &Termination::iterations(1_500)).unwrap();
    edges_are_valid(&prm, &space, &checker);
    let path = plan.path().expect("over the wall");
    for m in path.windows(2) {
        assert!(checker.dubins_is_free(&space.path(&m[0], &m[1])));
    }
    let cost: f64 = path.windows(2).map(|m| space.distance(&m[0], &m[1])).sum();
    assert!((cost - plan.cost().unwrap()).abs() < 1e-9);
}

#[test]
fn a_walled_off_goal_gives_no_solution_and_bad_settings_are_errors() {
    let (world, _) = trailmark_core::generate::walled_goal(0.2).unwrap();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let kd = KdNearest::<R2, 2>::new(&space).unwrap();
    let problem = Problem::new(&space, &checker, Point::new(2.0, 2.0), Point::new(15.0, 15.0));
    let plan = Prm::new(kd.clone()).solve(&problem, &Termination::iterations(500)).unwrap();
    assert_eq!((plan.solution, plan.stop), (Solution::None, Stop::IterationLimit));
    for connection in [
        Connection::Nearest { k: 0 },
        Connection::Radius { radius: -1.0 },
        Connection::Radius { radius: f64::NAN },
    ] {
        let result =
            Prm::new(kd.clone()).with_connection(connection).solve(&problem, &Termination::iterations(5));
        assert!(matches!(result, Err(PlanError::InvalidOption { .. })), "{connection:?}");
    }
}

/// `grow` builds the roadmap before any query, from the stream the queries go on with: a
/// roadmap grown then queried with no further iterations answers from what was grown, and a
/// termination stops the growth early.
#[test]
fn a_roadmap_grown_first_answers_queries_without_growing() {
    let world = wall_world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut prm = Prm::star(KdNearest::<R2, 2>::new(&space).unwrap()).with_seed(8);
    let growth = prm.grow(&space, &checker, 500, &Termination::iterations(100_000)).unwrap();
    assert_eq!(growth.stop, None);
    assert_eq!(prm.node_count(), 500);
    assert!(growth.collision_checks >= 500);
    edges_are_valid(&prm, &space, &checker);
    let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
    let plan = prm.solve(&problem, &Termination::iterations(0)).unwrap();
    let optimum = 2.0 * 58f64.sqrt() + 2.0;
    assert!(plan.cost().is_some_and(|c| c >= optimum - 1e-9 && c < 1.2 * optimum), "{plan:?}");
    assert_eq!(prm.node_count(), 502, "only the start and the goal were added");
    let stopped = prm.grow(&space, &checker, 10_000, &Termination::iterations(50)).unwrap();
    assert_eq!(stopped.stop, Some(Stop::IterationLimit));
    assert!(prm.node_count() <= 552);
    assert!(matches!(
        prm.grow(&space, &checker, 10, &Termination::default().and_target_cost(1.0)),
        Err(PlanError::NoLimit)
    ));
}
