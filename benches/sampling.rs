//! The inner loops of the sampling planners, seeded: nearest-neighbour queries (the k-d tree
//! against brute force, in R² and Dubins), a connect phase's queries and insertions (states
//! scattered, or in order along a line) and collision checks on a world of 60 random convex
//! hexagons in a 40 x 40 square, robot radius 0.25 (states, segments, Dubins curves, Bézier
//! curves). Run: `cargo bench --bench sampling`. `cargo xtask bench --sections sampling`
//! measures the planners themselves.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::core::curve::CubicHermite;
use trailmark::core::dubins::DubinsPath;
use trailmark::core::generate;
use trailmark::core::geometry::{Point, Vector};
use trailmark::sample::nearest::KdTree;
use trailmark::sample::{BruteForce, Direction, Dubins, KdNearest, NearestNeighbors, R2, StateSpace};

/// Queries per measured batch.
const BATCH: usize = 1000;

fn filled<S: StateSpace, N: NearestNeighbors<S>>(space: &S, mut set: N, n: usize, rng: &mut ChaCha8Rng) -> N {
    for _ in 0..n {
        set.insert(space, space.sample(rng));
    }
    set
}

fn nearest(c: &mut Criterion) {
    let mut group = c.benchmark_group("nearest");
    group.throughput(Throughput::Elements(BATCH as u64));
    let bounds = generate::convex_obstacles(40.0, 1, 6, 0.0, 1).expect("valid").bounds();
    let r2 = R2::new(bounds);
    let dubins = Dubins::new(bounds, 1.0).expect("a positive radius");
    for n in [1_000, 10_000, 100_000] {
        let mut rng = ChaCha8Rng::seed_from_u64(n as u64);
        let kd = filled(&r2, KdNearest::<R2, 2>::new(&r2).expect("R2 has positions"), n, &mut rng);
        let queries: Vec<Point> = (0..BATCH).map(|_| r2.sample(&mut rng)).collect();
        group.bench_with_input(BenchmarkId::new("r2_kdtree_nearest", n), &queries, |b, qs| {
            b.iter(|| {
                qs.iter()
                    .map(|q| kd.nearest(&r2, black_box(q), Direction::ToQuery).map_or(0, |x| x.0))
                    .sum::<u32>()
            })
        });
        group.bench_with_input(BenchmarkId::new("r2_kdtree_30_nearest", n), &queries, |b, qs| {
            b.iter(|| {
                qs.iter()
                    .map(|q| kd.k_nearest(&r2, black_box(q), 30, Direction::ToQuery).len())
                    .sum::<usize>()
            })
        });
        if n <= 10_000 {
            let brute = filled(&r2, BruteForce::new(), n, &mut ChaCha8Rng::seed_from_u64(n as u64));
            group.bench_with_input(BenchmarkId::new("r2_brute_force_nearest", n), &queries, |b, qs| {
                b.iter(|| {
                    qs.iter()
                        .map(|q| brute.nearest(&r2, black_box(q), Direction::ToQuery).map_or(0, |x| x.0))
                        .sum::<u32>()
                })
            });
            let kd = filled(
                &dubins,
                KdNearest::<Dubins, 2>::new(&dubins).expect("poses have positions"),
                n,
                &mut rng,
            );
            let poses: Vec<_> = (0..BATCH).map(|_| dubins.sample(&mut rng)).collect();
            group.bench_with_input(BenchmarkId::new("dubins_kdtree_nearest", n), &poses, |b, qs| {
                b.iter(|| {
                    qs.iter()
                        .map(|q| kd.nearest(&dubins, black_box(q), Direction::ToQuery).map_or(0, |x| x.0))
                        .sum::<u32>()
                })
            });
        }
    }
    group.finish();
}

/// A connect phase's nearest-neighbour work: from a tree of 1,000 scattered states, 10,000 more,
/// each asked for its nearest before it is stored; the states scattered, or in order along a
/// line in steps of 1e-4 of the extent (diagonal, or along an axis), as RRT-Connect's connect
/// phase adds them. `kd_nearest` is the structure the planners use (`KdNearest`: the k-d tree
/// beneath, states at equal positions grouped, the nearest by the space's distance); `kd_tree`
/// that k-d tree alone, and `kiddo` kiddo's growing k-d tree, on the same positions.
fn growth(c: &mut Criterion) {
    let mut group = c.benchmark_group("growth");
    const STEPS: usize = 10_000;
    group.throughput(Throughput::Elements(STEPS as u64));
    group.sample_size(10);
    let bounds = generate::convex_obstacles(40.0, 1, 6, 0.0, 1).expect("valid").bounds();
    let r2 = R2::new(bounds);
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let first: Vec<Point> = (0..1_000).map(|_| r2.sample(&mut rng)).collect();
    let mut base = KdNearest::<R2, 2>::new(&r2).expect("R2 has positions");
    let mut tree = KdTree::<2>::new();
    let mut peer = kiddo::KdTree::<f64, 2>::new();
    for (i, p) in first.iter().enumerate() {
        base.insert(&r2, *p);
        tree.insert([p.x, p.y], i as u32);
        peer.add(&[p.x, p.y], i as u64);
    }
    let step = 40.0 * 1e-4;
    let scattered: Vec<Point> = (0..STEPS).map(|_| r2.sample(&mut rng)).collect();
    let diagonal: Vec<Point> = (0..STEPS)
        .map(|i| Point::new(2.0, 2.0) + Vector::new(1.0, 1.0).normalize() * (step * i as f64))
        .collect();
    let axis: Vec<Point> = (0..STEPS).map(|i| Point::new(0.5 + step * i as f64, 20.0)).collect();
    for (name, states) in
        [("scattered", &scattered), ("collinear_diagonal", &diagonal), ("collinear_axis", &axis)]
    {
        group.bench_with_input(BenchmarkId::new(format!("kd_nearest_{name}"), STEPS), states, |b, states| {
            b.iter_batched(
                || base.clone(),
                |mut kd| {
                    let mut sum = 0u32;
                    for q in states {
                        sum = sum.wrapping_add(kd.nearest(&r2, q, Direction::ToQuery).map_or(0, |x| x.0));
                        kd.insert(&r2, *q);
                    }
                    sum
                },
                criterion::BatchSize::LargeInput,
            )
        });
        group.bench_with_input(BenchmarkId::new(format!("kd_tree_{name}"), STEPS), states, |b, states| {
            b.iter_batched(
                || tree.clone(),
                |mut kd| {
                    let mut sum = 0u32;
                    for (i, q) in states.iter().enumerate() {
                        sum = sum.wrapping_add(kd.nearest_one(&[q.x, q.y]).map_or(0, |x| x.0));
                        kd.insert([q.x, q.y], (1_000 + i) as u32);
                    }
                    sum
                },
                criterion::BatchSize::LargeInput,
            )
        });
        group.bench_with_input(BenchmarkId::new(format!("kiddo_{name}"), STEPS), states, |b, states| {
            b.iter_batched(
                || peer.clone(),
                |mut kd| {
                    let mut sum = 0u64;
                    for (i, q) in states.iter().enumerate() {
                        sum = sum.wrapping_add(kd.nearest_one::<kiddo::SquaredEuclidean>(&[q.x, q.y]).item);
                        kd.add(&[q.x, q.y], (1_000 + i) as u64);
                    }
                    sum
                },
                criterion::BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

fn collision(c: &mut Criterion) {
    let mut group = c.benchmark_group("collision");
    group.throughput(Throughput::Elements(BATCH as u64));
    let world = generate::convex_obstacles(40.0, 60, 6, 0.25, 3).expect("valid");
    let checker = world.checker();
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let mut point = || Point::new(rng.random_range(0.0..40.0), rng.random_range(0.0..40.0));
    let points: Vec<Point> = (0..BATCH).map(|_| point()).collect();
    // Segments of length up to 8 (RRT's default range here is 11.3), from free points.
    let segments: Vec<(Point, Point)> = points
        .iter()
        .filter(|&&p| checker.point_is_free(p))
        .cycle()
        .zip((0..).map(|i| f64::from(i) * 2.399))
        .map(|(&p, angle)| {
            (p, p + Vector::new(angle.cos(), angle.sin()) * (1.0 + (angle * 7.0).sin().abs() * 7.0))
        })
        .take(BATCH)
        .collect();
    group.bench_function("point", |b| {
        b.iter(|| points.iter().filter(|&&p| checker.point_is_free(black_box(p))).count())
    });
    group.bench_function("segment", |b| {
        b.iter(|| {
            segments.iter().filter(|&&(p, q)| checker.segment_is_free(black_box(p), black_box(q))).count()
        })
    });
    let curves: Vec<DubinsPath> = segments
        .iter()
        .enumerate()
        .map(|(i, &(p, q))| {
            let (a, b) = (i as f64, i as f64 * 1.7);
            let from = trailmark::core::geometry::Pose::new(p.coords, a);
            let to = trailmark::core::geometry::Pose::new(q.coords, b);
            DubinsPath::shortest(&from, &to, 1.0).expect("finite poses")
        })
        .collect();
    group.bench_function("dubins", |b| {
        b.iter(|| curves.iter().filter(|c| checker.dubins_is_free(black_box(c))).count())
    });
    let beziers: Vec<_> = segments
        .iter()
        .map(|&(p, q)| {
            let bend = Vector::new(q.y - p.y, p.x - q.x) * 0.5;
            CubicHermite::new(p, q - p + bend, q, q - p - bend).to_bezier()
        })
        .collect();
    group.bench_function("bezier", |b| {
        b.iter(|| beziers.iter().filter(|c| checker.bezier_is_free(black_box(c))).count())
    });
    group.finish();
}

criterion_group!(benches, nearest, growth, collision);
criterion_main!(benches);
