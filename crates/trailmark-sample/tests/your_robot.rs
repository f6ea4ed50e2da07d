//! The how-to of `docs/your-robot.md`, run: a user's own state space (two joints that turn all
//! the way round, a torus with no coordinates for a k-d tree), their own validity checker, a
//! goal region, planners swapped at run time, and the benchmark runner on their planner.

use std::f64::consts::{PI, TAU};
use std::time::Duration;

use trailmark_core::termination::Termination;
use trailmark_sample::benchmark::benchmark;
use trailmark_sample::rand::RngExt;
use trailmark_sample::{
    BruteForce, ChaCha8Rng, Goal, Plan, PlanError, Planner, Prm, Problem, Rejection, Rrt, RrtConnect,
    RrtStar, StateSpace, Validity,
};

/// Two joints that turn freely: each angle in [-π, π], and -π is π.
#[derive(Debug, Clone, Copy)]
struct Torus;

/// The angle `a` in [-π, π].
fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(TAU) - PI
}

/// The short way from `a` to `b`, per joint.
fn turn(a: &[f64; 2], b: &[f64; 2]) -> [f64; 2] {
    [wrap(b[0] - a[0]), wrap(b[1] - a[1])]
}

impl StateSpace for Torus {
    type State = [f64; 2];
    const SYMMETRIC: bool = true;

    fn dimension(&self) -> usize {
        2
    }

    fn satisfies_bounds(&self, s: &[f64; 2]) -> bool {
        s.iter().all(|a| (-PI..=PI).contains(a))
    }

    fn enforce_bounds(&self, s: &mut [f64; 2]) {
        for a in s.iter_mut().filter(|a| a.is_finite()) {
            *a = wrap(*a);
        }
    }

    fn sample(&self, rng: &mut ChaCha8Rng) -> [f64; 2] {
        [rng.random_range(-PI..PI), rng.random_range(-PI..PI)]
    }

    fn distance(&self, a: &[f64; 2], b: &[f64; 2]) -> f64 {
        let [d0, d1] = turn(a, b);
        d0.hypot(d1)
    }

    fn interpolate(&self, a: &[f64; 2], b: &[f64; 2], t: f64) -> [f64; 2] {
        let [d0, d1] = turn(a, b);
        [wrap(a[0] + d0 * t), wrap(a[1] + d1 * t)]
    }

    fn extent(&self) -> f64 {
        PI * std::f64::consts::SQRT_2
    }

    fn measure(&self) -> f64 {
        TAU * TAU
    }

    fn coordinates(&self, s: &[f64; 2]) -> Vec<f64> {
        s.to_vec()
    }

    // Wrapping makes distances shorter than the straight line between the angles, so the
    // angles are no lower bound for a k-d tree: the planners use BruteForce.
    fn position<const D: usize>(&self, _: &[f64; 2]) -> Option<[f64; D]> {
        None
    }
}

/// The user's own checker: the first joint may not be within 0.3 of 1 rad while the second is
/// within 2 rad of 0 (the arm would hit a post); motions are checked every 0.01 rad.
struct Post;

impl Validity<Torus> for Post {
    fn state_is_valid(&self, _: &Torus, q: &[f64; 2]) -> bool {
        !((q[0] - 1.0).abs() < 0.3 && q[1].abs() < 2.0)
    }

    fn motion_is_valid(&self, space: &Torus, a: &[f64; 2], b: &[f64; 2]) -> bool {
        let steps = (space.distance(a, b) / 0.01).ceil().max(1.0) as usize;
        (0..=steps).all(|i| self.state_is_valid(space, &space.interpolate(a, b, i as f64 / steps as f64)))
    }
}

/// A goal region: the first joint anywhere within 0.1 of 2 rad, the second free.
struct Reach;

impl Goal<Torus> for Reach {
    fn is_satisfied(&self, _: &Torus, q: &[f64; 2]) -> bool {
        wrap(q[0] - 2.0).abs() <= 0.1
    }

    fn distance(&self, _: &Torus, q: &[f64; 2]) -> f64 {
        (wrap(q[0] - 2.0).abs() - 0.1).max(0.0)
    }

    fn sample(&self, space: &Torus, rng: &mut ChaCha8Rng) -> Option<[f64; 2]> {
        Some([2.0 + rng.random_range(-0.1..0.1), space.sample(rng)[1]])
    }
}

fn planners() -> Vec<Box<dyn Planner<Torus, Post>>> {
    vec![
        Box::new(Rrt::new(BruteForce::<Torus>::new())),
        Box::new(RrtConnect::new(BruteForce::<Torus>::new())),
        Box::new(RrtStar::new(BruteForce::<Torus>::new())),
        Box::new(Prm::star(BruteForce::<Torus>::new())),
    ]
}

fn check(plan: &Plan<[f64; 2]>, name: &str) -> f64 {
    let path = plan.path().unwrap_or_else(|| panic!("{name}: no path"));
    assert!(path.iter().all(|q| Torus.satisfies_bounds(q) && Post.state_is_valid(&Torus, q)), "{name}");
    assert!(path.windows(2).all(|m| Post.motion_is_valid(&Torus, &m[0], &m[1])), "{name}");
    plan.cost().expect("exact")
}

#[test]
fn every_planner_crosses_the_wrap_the_short_way() {
    // From 3 rad to -3 rad: 0.28 rad across ±π, against 6 rad the long way (through the post).
    let problem = Problem::new(&Torus, &Post, [3.0, 0.0], [-3.0, 0.0]);
    for mut planner in planners() {
        let plan = planner.solve(&problem, &Termination::iterations(1_000)).unwrap();
        let cost = check(&plan, planner.name());
        // RRT and RRT-Connect take the first path they find; RRT* improves it to within a
        // few percent of the short way.
        let bound = if planner.optimizes() { 0.3 } else { 3.0 };
        assert!(cost < bound, "{}: {cost}", planner.name());
    }
}

#[test]
fn every_planner_reaches_a_goal_region_around_the_post() {
    // From 0 rad to the region past the post at 1 rad: around it (|second joint| >= 2) or the
    // long way round.
    let problem = Problem::with_goal(&Torus, &Post, [0.0, 0.0], Reach);
    for mut planner in planners() {
        let plan = planner.solve(&problem, &Termination::iterations(2_000)).unwrap();
        check(&plan, planner.name());
        assert!(Reach.is_satisfied(&Torus, plan.path().unwrap().last().unwrap()), "{}", planner.name());
    }
}

#[test]
fn bad_ends_and_the_benchmark_runner() {
    let limit = Termination::iterations(100);
    for mut planner in planners() {
        let at_post = Problem::new(&Torus, &Post, [1.0, 0.0], [-3.0, 0.0]);
        assert_eq!(
            planner.solve(&at_post, &limit).unwrap_err(),
            PlanError::InvalidStart { index: 0, reason: Rejection::Invalid }
        );
        let wound = Problem::new(&Torus, &Post, [0.0, 0.0], [7.0, 0.0]);
        assert_eq!(
            planner.solve(&wound, &limit).unwrap_err(),
            PlanError::InvalidGoal(Rejection::OutOfBounds)
        );
    }
    // Ten seeded runs of each, as the harness runs its own.
    let problem = Problem::with_goal(&Torus, &Post, [0.0, 0.0], Reach);
    let limit = Termination::iterations(1_000).and_time(Duration::from_secs(5));
    for mut planner in planners() {
        let runs = benchmark(planner.as_mut(), &problem, &limit, 10, 1, None).unwrap();
        assert_eq!(runs.runs.len(), 10);
        assert!(runs.runs.iter().all(|r| r.solved), "{}", runs.planner);
        assert!(runs.plans.iter().all(|p| p.is_exact()));
        assert_eq!(runs.runs.iter().map(|r| r.seed).collect::<Vec<_>>(), (1..=10).collect::<Vec<u64>>());
    }
}
