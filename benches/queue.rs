//! The open list under a Dijkstra workload: trailmark's indexed 4-ary heap (decrease-key in
//! place) beside `std::collections::BinaryHeap` with lazy deletion (a new entry per improvement,
//! stale entries skipped when popped), the scheme of the `pathfinding` crate and of
//! `petgraph::algo::dijkstra`.
//!
//! The workload is Dijkstra's algorithm itself on a seeded random graph (100,000 nodes, four
//! out-edges each with integer costs 1 to 1,000), so the mix of pushes, decreases and pops is
//! the one a search produces. Both queues must give the same distances before anything is
//! timed. Throughput is in nodes settled. Run: `cargo bench --bench queue`.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::search::IndexedHeap;

const NODES: usize = 100_000;
const DEGREE: usize = 4;

/// Out-edges of every node, `DEGREE` per node, as (target, cost).
fn graph(seed: u64) -> Vec<[(u32, u64); DEGREE]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..NODES)
        .map(|_| std::array::from_fn(|_| (rng.random_range(0..NODES as u32), rng.random_range(1..=1000))))
        .collect()
}

/// Dijkstra from node 0 with decrease-key; returns the sum of the finite distances.
fn indexed(edges: &[[(u32, u64); DEGREE]], heap: &mut IndexedHeap<u64>, dist: &mut [u64]) -> u64 {
    dist.fill(u64::MAX);
    heap.clear();
    dist[0] = 0;
    heap.push(0, 0);
    let mut sum = 0;
    while let Some((u, d)) = heap.pop() {
        sum += d;
        for &(v, c) in &edges[u] {
            let nd = d + c;
            if nd < dist[v as usize] {
                dist[v as usize] = nd;
                heap.push(v as usize, nd);
            }
        }
    }
    sum
}

/// Dijkstra from node 0 with lazy deletion; returns the sum of the finite distances.
fn lazy(edges: &[[(u32, u64); DEGREE]], heap: &mut BinaryHeap<Reverse<(u64, u32)>>, dist: &mut [u64]) -> u64 {
    dist.fill(u64::MAX);
    heap.clear();
    dist[0] = 0;
    heap.push(Reverse((0, 0)));
    let mut sum = 0;
    while let Some(Reverse((d, u))) = heap.pop() {
        if d > dist[u as usize] {
            continue; // stale: the node was reached more cheaply since
        }
        sum += d;
        for &(v, c) in &edges[u as usize] {
            let nd = d + c;
            if nd < dist[v as usize] {
                dist[v as usize] = nd;
                heap.push(Reverse((nd, v)));
            }
        }
    }
    sum
}

fn bench(c: &mut Criterion) {
    let edges = graph(1);
    let mut dist = vec![0; NODES];
    let mut heap = IndexedHeap::with_item_capacity(NODES);
    let mut binary = BinaryHeap::new();
    let ours = indexed(&edges, &mut heap, &mut dist);
    let settled = dist.iter().filter(|&&d| d != u64::MAX).count();
    let theirs = lazy(&edges, &mut binary, &mut dist);
    assert_eq!(ours, theirs, "both queues give the same distances");
    eprintln!("queue: {settled} of {NODES} nodes reachable, distance sum {ours}");
    let mut group = c.benchmark_group("priority_queue/dijkstra_100k");
    group.throughput(Throughput::Elements(settled as u64));
    group.bench_function("trailmark_indexed_heap", |b| {
        b.iter(|| indexed(black_box(&edges), &mut heap, &mut dist))
    });
    group.bench_function("std_binary_heap_lazy", |b| {
        b.iter(|| lazy(black_box(&edges), &mut binary, &mut dist))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
