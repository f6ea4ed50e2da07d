//! Lazy PRM and Lazy PRM* against the eager roadmap grown from the same samples: the same
//! milestones, the same shortest path through the free motions, far fewer motions checked,
//! every motion of the path free; and the roadmap keeps what a query learnt.

use trailmark_core::geometry::Point;
use trailmark_core::termination::Termination;
use trailmark_core::world::PolygonWorld;
use trailmark_sample::{Dubins, KdNearest, Planner, Prm, Problem, R2, StateSpace, Validity};

/// A world of 24 random convex obstacles, robot radius 0.25.
fn world() -> PolygonWorld {
    trailmark_core::generate::convex_obstacles(40.0, 24, 6, 0.25, 11).unwrap()
}

/// The free point nearest `p` on a grid of half units, a unit inside the world's bounds.
fn free_near(world: &PolygonWorld, p: Point) -> Point {
    let checker = world.checker();
    let mut candidates: Vec<Point> = (2..=78)
        .flat_map(|i| (2..=78).map(move |j| Point::new(f64::from(i) * 0.5, f64::from(j) * 0.5)))
        .filter(|q| checker.point_is_free(*q))
        .collect();
    candidates.sort_by(|a, b| (a - p).norm().total_cmp(&(b - p).norm()));
    candidates[0]
}

/// Every motion of `path` is free by the world's exact checker.
fn free<S: StateSpace, V: Validity<S>>(space: &S, validity: &V, path: &[S::State]) -> bool {
    path.windows(2).all(|w| validity.motion_is_valid(space, &w[0], &w[1]))
}

#[test]
fn lazy_prm_star_finds_the_eager_roadmaps_shortest_path() {
    let world = world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let at = |x: f64, y: f64| free_near(&world, Point::new(x, y));
    let queries = [(at(1.0, 1.0), at(39.0, 39.0)), (at(1.0, 39.0), at(39.0, 2.0))];
    for seed in 0..4 {
        let kd = KdNearest::<R2, 2>::new(&space).unwrap();
        let mut eager = Prm::star(kd.clone()).with_seed(seed);
        let mut lazy = Prm::lazy_star(kd).with_seed(seed);
        let grown = eager.grow(&space, &checker, 1_500, &Termination::iterations(1_000_000)).unwrap();
        let lazily = lazy.grow(&space, &checker, 1_500, &Termination::iterations(1_000_000)).unwrap();
        assert_eq!(eager.node_count(), lazy.node_count());
        assert!(lazily.collision_checks * 2 < grown.collision_checks, "{lazily:?} vs {grown:?}");
        assert!(lazy.edge_count() >= eager.edge_count(), "the lazy roadmap holds every free motion and more");
        for (a, b) in queries {
            let problem = Problem::new(&space, &checker, a, b);
            let once = Termination::iterations(0);
            let (p, q) = (eager.solve(&problem, &once).unwrap(), lazy.solve(&problem, &once).unwrap());
            let (x, y) = (p.cost().expect("eager finds a path"), q.cost().expect("lazy finds a path"));
            assert!((x - y).abs() <= 1e-9 * x, "seed {seed}: eager {x}, lazy {y}");
            if let Some(path) = q.path() {
                assert!(free(&space, &checker, path), "seed {seed}: a blocked motion on the lazy path");
            }
        }
    }
}

#[test]
fn a_lazy_roadmap_remembers_what_its_queries_checked() {
    let world = world();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let mut prm = Prm::lazy(KdNearest::<R2, 2>::new(&space).unwrap()).with_seed(2);
    assert!(prm.is_lazy());
    assert_eq!(Planner::<R2, trailmark_core::world::CollisionChecker>::name(&prm), "Lazy PRM");
    let (a, b) = (free_near(&world, Point::new(1.0, 1.0)), free_near(&world, Point::new(39.0, 39.0)));
    let problem = Problem::new(&space, &checker, a, b);
    let first = prm.solve(&problem, &Termination::iterations(5_000)).unwrap();
    let path = first
        .path()
        .unwrap_or_else(|| {
            panic!(
                "no path: {:?} {:?} nodes {} edges {}",
                first.stop,
                first.stats,
                prm.node_count(),
                prm.edge_count()
            )
        })
        .to_vec();
    assert!(free(&space, &checker, &path));
    // The same query again: the path's motions are known free, none is checked again.
    let again = prm.solve(&problem, &Termination::iterations(0)).unwrap();
    assert_eq!(again.cost(), first.cost());
    // Three state checks (the start, the goal, the goal drawn once more) and no motion.
    assert_eq!(again.stats.collision_checks, 3, "{:?}", again.stats);
}

#[test]
fn a_lazy_dubins_roadmap_follows_free_curves() {
    let world = world();
    let checker = world.checker();
    let space = Dubins::new(world.bounds(), 1.0).unwrap();
    let mut prm = Prm::lazy_star(KdNearest::<Dubins, 2>::new(&space).unwrap()).with_seed(4);
    let pose = |x: f64, y: f64, h: f64| trailmark_core::geometry::Pose::new(Point::new(x, y).coords, h);
    let (p, q) = (free_near(&world, Point::new(2.0, 2.0)), free_near(&world, Point::new(38.0, 38.0)));
    let (a, b) = (pose(p.x, p.y, 0.0), pose(q.x, q.y, 1.5));
    let plan = prm.solve(&Problem::new(&space, &checker, a, b), &Termination::iterations(3_000)).unwrap();
    let path = plan.path().expect("a path within 3,000 samples");
    assert!(free(&space, &checker, path));
    for m in path.windows(2) {
        assert!(checker.dubins_is_free(&space.path(&m[0], &m[1])));
    }
}

#[test]
fn a_walled_off_goal_gives_no_solution_and_splits_the_roadmap() {
    let (world, _) = trailmark_core::generate::walled_goal(0.2).unwrap();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let problem = Problem::new(&space, &checker, Point::new(2.0, 2.0), Point::new(15.0, 15.0));
    for mut prm in [
        Prm::lazy(KdNearest::<R2, 2>::new(&space).unwrap()),
        Prm::lazy_star(KdNearest::<R2, 2>::new(&space).unwrap()),
    ] {
        let plan = prm.solve(&problem, &Termination::iterations(600)).unwrap();
        assert_eq!(plan.solution, trailmark_sample::Solution::None);
        // The motions through the wall were dropped as the searches met them: the goal's side
        // is a component of its own again.
        assert!(prm.component_count() >= 2, "{} components", prm.component_count());
    }
}
