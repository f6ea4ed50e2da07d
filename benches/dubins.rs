//! Dubins shortest-path queries per second (goal: at least 5 million on one core).
//!
//! 4,096 random pose pairs (seeded) in a 20 x 20 square with a turning radius of 1: far enough
//! apart that the straight words usually win, close enough that the three-turn words are often
//! feasible and must be evaluated. Run: `cargo bench --bench dubins`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::core::dubins::DubinsPath;
use trailmark::core::geometry::{Pose, Vector};

fn poses(n: usize) -> Vec<(Pose, Pose)> {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut pose = || {
        let (x, y, h) =
            (rng.random_range(0.0..20.0), rng.random_range(0.0..20.0), rng.random_range(-3.2..3.2));
        Pose::new(Vector::new(x, y), h)
    };
    (0..n).map(|_| (pose(), pose())).collect()
}

fn bench(c: &mut Criterion) {
    let pairs = poses(4096);
    let mut group = c.benchmark_group("dubins");
    group.throughput(Throughput::Elements(pairs.len() as u64));
    group.bench_function("shortest_path", |b| {
        b.iter(|| {
            pairs
                .iter()
                .map(|(a, g)| DubinsPath::shortest(a, g, 1.0).map_or(0.0, |p| p.length()))
                .sum::<f64>()
        })
    });
    group.bench_function("shortest_length", |b| {
        b.iter(|| {
            pairs
                .iter()
                .map(|(a, g)| DubinsPath::shortest_length(black_box(a), g, 1.0).unwrap_or(0.0))
                .sum::<f64>()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
