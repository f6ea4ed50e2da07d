//! The samplers: bridge-test samples fall in the doors of a narrow-passage world, Gaussian
//! samples are free and beside obstacles, every validity test is counted, runs are seeded,
//! settings out of range are refused, `sample_near` stays near, and RRT-Connect with the bridge
//! sampler gets through six doors where uniform sampling often does not.

use std::cell::Cell;

use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::generate;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::termination::Termination;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_sample::nearest::KdNearest;
use trailmark_sample::sampler::{Bridge, Draw, Gaussian, SamplerError, StateSampler, Uniform};
use trailmark_sample::space::{Dubins, R2, Se2, StateSpace};
use trailmark_sample::validity::Validity;
use trailmark_sample::{Planner, Problem, RrtConnect};

const SIZE: f64 = 40.0;
const WALLS: usize = 6;
const DOOR: f64 = 1.5;
const RADIUS: f64 = 0.25;

fn narrow() -> PolygonWorld {
    generate::narrow_passages(SIZE, WALLS, DOOR, RADIUS, 2).expect("a world")
}

/// A door: the x range of its wall and the y range of its gap.
type Door = ((f64, f64), (f64, f64));

/// The doors of `world`: the free gap between a wall's two pieces.
fn doors(world: &PolygonWorld) -> Vec<Door> {
    world
        .obstacles()
        .chunks(2)
        .map(|pieces| {
            let xs = pieces[0].vertices().iter().map(|p| p.x);
            let (x0, x1) = xs.fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
            let below = pieces[0].vertices().iter().map(|p| p.y).fold(f64::MIN, f64::max);
            let above = pieces[1].vertices().iter().map(|p| p.y).fold(f64::MAX, f64::min);
            ((x0, x1), (below, above))
        })
        .collect()
}

/// Within `margin` of a door's gap.
fn in_a_door(doors: &[Door], p: Point, margin: f64) -> bool {
    doors
        .iter()
        .any(|&((x0, x1), (y0, y1))| p.x >= x0 - margin && p.x <= x1 + margin && p.y >= y0 && p.y <= y1)
}

/// A checker that counts its state tests.
struct Counting<'a> {
    checker: &'a CollisionChecker,
    states: Cell<u64>,
}

impl Validity<R2> for Counting<'_> {
    fn state_is_valid(&self, space: &R2, state: &Point) -> bool {
        self.states.set(self.states.get() + 1);
        self.checker.state_is_valid(space, state)
    }

    fn motion_is_valid(&self, space: &R2, from: &Point, to: &Point) -> bool {
        self.checker.motion_is_valid(space, from, to)
    }
}

/// `n` samples of `sampler` in `world`, with the checks they cost.
fn draw<Q: StateSampler<R2>>(
    world: &PolygonWorld,
    sampler: &Q,
    n: usize,
    seed: u64,
) -> (Vec<Point>, u64, u64) {
    let checker = world.checker();
    let counting = Counting { checker: &checker, states: Cell::new(0) };
    let space = R2::new(world.bounds());
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut checks = 0;
    let mut draw = Draw::new(&mut rng, &mut checks);
    let samples =
        (0..n).map(|_| sampler.sample(&space, &counting, &mut draw).expect("no limit to stop it")).collect();
    (samples, checks, counting.states.get())
}

#[test]
fn bridge_samples_fall_in_the_doors() {
    let world = narrow();
    let doors = doors(&world);
    assert_eq!(doors.len(), WALLS);
    let checker = world.checker();
    // Partners about a door's width away: midpoints across a door, rarely across the 4.4 of
    // free space between two walls.
    let bridge = Bridge::new(0.75).unwrap().with_share(1.0).unwrap().with_attempts(100_000).unwrap();
    let (samples, checks, counted) = draw(&world, &bridge, 2000, 1);
    assert_eq!(checks, counted, "every test is counted");
    assert!(samples.iter().all(|&p| checker.point_is_free(p)), "midpoints are free");
    // The doors (with the walls' grown thickness around them) are 0.2% of the world; the
    // bridge test puts most of its samples there.
    let inside = samples.iter().filter(|&&p| in_a_door(&doors, p, RADIUS)).count();
    assert!(inside * 10 >= samples.len() * 9, "{inside} of {} in a door", samples.len());
    let (uniform, checks, _) = draw(&world, &Uniform, 2000, 1);
    let by_chance = uniform.iter().filter(|&&p| in_a_door(&doors, p, RADIUS)).count();
    assert!(by_chance * 100 <= uniform.len(), "{by_chance} uniform samples in a door");
    assert_eq!(checks, 0, "uniform samples test nothing");
}

#[test]
fn gaussian_samples_are_free_and_beside_obstacles() {
    let world = narrow();
    let std_dev = 0.25;
    let gaussian = Gaussian::new(std_dev).unwrap().with_share(1.0).unwrap().with_attempts(100_000).unwrap();
    let (samples, checks, counted) = draw(&world, &gaussian, 2000, 3);
    assert_eq!(checks, counted);
    let checker = world.checker();
    assert!(samples.iter().all(|&p| checker.point_is_free(p)));
    // The same obstacles grown by 4 standard deviations more: a sample beside an obstacle is
    // inside them (or beside the bounds, which the partner may leave).
    let obstacles: Vec<Vec<Point>> = world.obstacles().iter().map(|o| o.vertices().to_vec()).collect();
    let grown = PolygonWorld::new(world.bounds(), obstacles, RADIUS + 4.0 * std_dev).unwrap().checker();
    let (lo, hi) = (world.bounds().min(), world.bounds().max());
    let beside = |p: &&Point| {
        !grown.point_is_free(**p)
            || [p.x - lo.x, hi.x - p.x, p.y - lo.y, hi.y - p.y].iter().any(|&d| d <= 4.0 * std_dev)
    };
    let near = samples.iter().filter(beside).count();
    assert!(near * 1000 >= samples.len() * 995, "{near} of {} beside an obstacle", samples.len());
    let (uniform, _, _) = draw(&world, &Uniform, 2000, 3);
    let by_chance = uniform.iter().filter(beside).count();
    assert!(by_chance * 10 <= uniform.len() * 7, "{by_chance} uniform samples beside an obstacle");
}

#[test]
fn the_share_splits_the_samples() {
    // With share 0, no tests; with share 0.5, about half the samples test states.
    let world = narrow();
    let (_, checks, _) = draw(&world, &Bridge::new(1.0).unwrap().with_share(0.0).unwrap(), 500, 5);
    assert_eq!(checks, 0);
    let once = Bridge::new(1.0).unwrap().with_attempts(1).unwrap();
    let space = R2::new(world.bounds());
    let checker = world.checker();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let tested = (0..4000)
        .filter(|_| {
            let mut checks = 0;
            once.sample(&space, &checker, &mut Draw::new(&mut rng, &mut checks));
            checks > 0
        })
        .count();
    assert!((1800..=2200).contains(&tested), "{tested} of 4000 tested");
}

#[test]
fn samples_are_seeded() {
    let world = narrow();
    let bridge = Bridge::new(1.5).unwrap();
    let gaussian = Gaussian::new(1.5).unwrap();
    assert_eq!(draw(&world, &bridge, 300, 9), draw(&world, &bridge, 300, 9));
    assert_ne!(draw(&world, &bridge, 300, 9).0, draw(&world, &bridge, 300, 10).0);
    assert_eq!(draw(&world, &gaussian, 300, 9), draw(&world, &gaussian, 300, 9));
}

#[test]
fn settings_out_of_range_are_refused() {
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(Bridge::new(bad), Err(SamplerError::StdDev(_))), "{bad}");
    }
    assert!(matches!(Gaussian::new(f64::NAN), Err(SamplerError::StdDev(_))));
    for bad in [-0.1, 1.1, f64::NAN] {
        assert!(matches!(Bridge::new(1.0).unwrap().with_share(bad), Err(SamplerError::Share(_))));
        assert!(matches!(Gaussian::new(1.0).unwrap().with_share(bad), Err(SamplerError::Share(_))));
    }
    assert_eq!(Bridge::new(1.0).unwrap().with_attempts(0), Err(SamplerError::NoAttempts));
    let set = Gaussian::new(0.5).unwrap().with_share(0.25).unwrap().with_attempts(7).unwrap();
    assert_eq!((set.std_dev(), set.share(), set.attempts()), (0.5, 0.25, 7));
    assert!(!SamplerError::Share(2.0).to_string().is_empty());
}

proptest! {
    #[test]
    fn constructors_accept_exactly_their_ranges(
        std_dev in any::<f64>(),
        share in any::<f64>(),
        attempts in prop_oneof![0u32..4, 99_999u32..100_002, Just(u32::MAX)],
    ) {
        let made = Bridge::new(std_dev).and_then(|b| b.with_share(share)).and_then(|b| b.with_attempts(attempts));
        let valid = std_dev > 0.0
            && std_dev.is_finite()
            && (0.0..=1.0).contains(&share)
            && (1..=100_000).contains(&attempts);
        prop_assert_eq!(made.is_ok(), valid);
    }
}

#[test]
fn sample_near_stays_near() {
    let bounds = trailmark_core::world::Bounds::new(0.0, 0.0, 20.0, 20.0).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let std_dev = 0.5;
    // R²: each coordinate normal about the centre.
    let r2 = R2::new(bounds);
    let centre = Point::new(10.0, 10.0);
    let near: Vec<Point> = (0..20_000).map(|_| r2.sample_near(&centre, std_dev, &mut rng)).collect();
    let mean = near.iter().fold(Point::origin().coords, |s, p| s + p.coords) / near.len() as f64;
    assert!((mean - centre.coords).norm() < 0.02, "mean {mean:?}");
    let var = near.iter().map(|p| (p.x - centre.x).powi(2)).sum::<f64>() / near.len() as f64;
    assert!((var.sqrt() - std_dev).abs() < 0.02, "standard deviation {}", var.sqrt());
    // SE(2) and Dubins (the default: a step toward a uniform state): within a few deviations.
    let se2 = Se2::new(bounds);
    let dubins = Dubins::new(bounds, 1.0).unwrap();
    let pose = Pose::new(centre.coords, 0.3);
    for _ in 0..2000 {
        let s = se2.sample_near(&pose, std_dev, &mut rng);
        assert!(se2.distance(&pose, &s) <= 6.0 * std_dev + 1e-9);
        let d = dubins.sample_near(&pose, std_dev, &mut rng);
        assert!(dubins.distance(&pose, &d) <= 6.0 * std_dev + 1e-9);
    }
}

#[test]
fn bridge_sampling_gets_rrt_connect_through_six_doors() {
    let world = narrow();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let nearest = KdNearest::<R2, 2>::new(&space).unwrap();
    let bridge = Bridge::new(2.0).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let gap = SIZE / (WALLS + 1) as f64 - SIZE / 50.0;
    let mut free = |x0: f64, x1: f64| loop {
        let p = Point::new(rng.random_range(x0..x1), rng.random_range(0.0..SIZE));
        if checker.point_is_free(p) {
            return p;
        }
    };
    let limit = Termination::iterations(10_000);
    let (mut uniform, mut bridged) = (0, 0);
    let queries = 12;
    for seed in 0..queries {
        let (a, b) = (free(0.0, gap), free(SIZE - gap, SIZE));
        let problem = Problem::new(&space, &checker, a, b);
        let plan = RrtConnect::new(nearest.clone()).with_seed(seed).solve(&problem, &limit).unwrap();
        uniform += usize::from(plan.is_exact());
        let mut planner = RrtConnect::new(nearest.clone()).with_sampler(&bridge).with_seed(seed);
        let plan = planner.solve(&problem, &limit).unwrap();
        bridged += usize::from(plan.is_exact());
        let path = plan.path().unwrap();
        assert!(path.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
    }
    assert_eq!(bridged, queries as usize, "bridge sampling solved {bridged} of {queries}");
    assert!(uniform <= bridged, "uniform {uniform}, bridge {bridged}");
}

/// Halton's first elements are the van der Corput sequences in bases 2 and 3 (computed by hand
/// from the definition), mapped onto the bounds; a sequence resumed after `k` elements draws
/// what the whole one draws from element `k + 1`; beyond 32 dimensions it draws nothing.
#[test]
fn halton_is_the_van_der_corput_sequence_per_axis_and_resumes() {
    use trailmark_sample::Halton;
    use trailmark_sample::space::Rn;
    let space = R2::new(trailmark_core::world::Bounds::new(0.0, 0.0, 2.0, 6.0).unwrap());
    let world = narrow();
    let checker = world.checker();
    let (mut rng, mut checks) = (ChaCha8Rng::seed_from_u64(0), 0);
    let halton = Halton::new();
    let mut draw = Draw::new(&mut rng, &mut checks);
    let got: Vec<Point> = (0..4).map(|_| halton.sample(&space, &checker, &mut draw).unwrap()).collect();
    // Base 2: 1/2, 1/4, 3/4, 1/8; base 3: 1/3, 2/3, 1/9, 4/9.
    let want = [(0.5, 1.0 / 3.0), (0.25, 2.0 / 3.0), (0.75, 1.0 / 9.0), (0.125, 4.0 / 9.0)];
    for (p, (u, v)) in got.iter().zip(want) {
        assert!((p.x - 2.0 * u).abs() < 1e-12 && (p.y - 6.0 * v).abs() < 1e-12, "{p}");
    }
    assert_eq!(halton.drawn(), 4);
    let resumed = Halton::after(2);
    assert_eq!(resumed.sample(&space, &checker, &mut draw), Some(got[2]));
    let wide = Rn::<33>::new([0.0; 33], [1.0; 33]).unwrap();
    let always = |_: &<Rn<33> as StateSpace>::State| true;
    let validity = trailmark_sample::Sampled::new(always, 0.01).unwrap();
    assert_eq!(Halton::new().sample(&wide, &validity, &mut draw), None);
}

/// Uniform samples, recording the best cost each draw was told.
#[derive(Default)]
struct Told(std::cell::RefCell<Vec<f64>>);

impl StateSampler<R2> for Told {
    fn sample<V: Validity<R2>>(&self, space: &R2, _: &V, draw: &mut Draw<'_>) -> Option<Point> {
        self.0.borrow_mut().push(draw.best_cost());
        Some(space.sample(draw.rng()))
    }
}

#[test]
fn an_optimizing_planner_tells_its_sampler_the_best_cost_so_far() {
    let world = narrow();
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let problem = Problem::new(&space, &checker, Point::new(1.0, 20.0), Point::new(39.0, 20.0));
    let told = Told::default();
    let mut planner = trailmark_sample::RrtStar::new(KdNearest::<R2, 2>::new(&space).expect("a tree"))
        .with_sampler(&told)
        .with_seed(4);
    let plan = planner.solve(&problem, &Termination::iterations(20_000)).expect("a run");
    let told = told.0.into_inner();
    let costs: Vec<f64> = plan.history.iter().map(|b| b.cost).collect();
    assert!(costs.len() >= 2, "RRT* improves its first solution here: {costs:?}");
    // Infinite until the first solution, then each solution's cost, in the order found.
    assert_eq!(told[0], f64::INFINITY);
    let mut seen: Vec<f64> = told.iter().copied().filter(|c| c.is_finite()).collect();
    seen.dedup();
    assert!(told.iter().skip_while(|c| c.is_infinite()).all(|c| c.is_finite()));
    // The last improvement may come after the last draw.
    assert!(seen.len() + 1 >= costs.len() && costs.starts_with(&seen), "told {seen:?}, found {costs:?}");
}
