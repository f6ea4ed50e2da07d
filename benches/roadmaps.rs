//! Roadmap construction on generated worlds of 10 to 500 random convex hexagons in a 1000 x 1000
//! square (seeded): the full visibility graph on one thread (Lee's sweep, O(n² log n) in the n
//! boundary vertices), the trapezoidal decomposition, and PRM* with 1,000 Halton samples (robot
//! radius 2). Throughput is in boundary vertices (visibility, trapezoids) or samples (PRM*).
//! Run: `cargo bench --bench roadmaps`. `cargo xtask bench --sections roadmaps` measures the
//! same builders and fits the exponent of the visibility graph's growth.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use trailmark::core::generate;
use trailmark::graph::Trapezoids;
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

const COUNTS: [usize; 5] = [10, 50, 100, 200, 500];

fn visibility(c: &mut Criterion) {
    let mut group = c.benchmark_group("visibility_build");
    group.sample_size(10);
    for count in COUNTS {
        let space = generate::convex_obstacles(1000.0, count, 6, 0.0, 1).expect("valid").free_space();
        group.throughput(Throughput::Elements(space.positions().len() as u64));
        group.bench_with_input(BenchmarkId::from_parameter(count), &space, |b, space| {
            b.iter(|| VisibilityGraph::with_options(black_box(space.clone()), Edges::All, 1).edge_count())
        });
    }
    group.finish();
}

fn trapezoids(c: &mut Criterion) {
    let mut group = c.benchmark_group("trapezoid_build");
    for count in COUNTS {
        let space = generate::convex_obstacles(1000.0, count, 6, 0.0, 1).expect("valid").free_space();
        group.throughput(Throughput::Elements(space.positions().len() as u64));
        group.bench_with_input(BenchmarkId::from_parameter(count), &space, |b, space| {
            b.iter(|| Trapezoids::new(black_box(space)).cell_count())
        });
    }
    group.finish();
}

fn prm(c: &mut Criterion) {
    let mut group = c.benchmark_group("prm_star_build");
    group.sample_size(10);
    group.throughput(Throughput::Elements(1000));
    for count in [10, 100, 500] {
        let world = generate::convex_obstacles(1000.0, count, 6, 2.0, 1).expect("valid");
        let options = PrmOptions {
            sampler: PrmSampler::Halton,
            connection: Connection::PrmStar,
            ..PrmOptions::default()
        };
        group.bench_with_input(BenchmarkId::from_parameter(count), &world, |b, world| {
            b.iter(|| {
                let mut prm = PolygonPrm::new(black_box(world.clone()), options).expect("valid options");
                prm.grow(1000).expect("free space to sample");
                prm.edge_count()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, visibility, trapezoids, prm);
criterion_main!(benches);
