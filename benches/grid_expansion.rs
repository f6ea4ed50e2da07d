//! Expanding a node of an 8-connected grid: generating its moves (no corner cutting, costs 1 and
//! √2) for every passable cell of a 512 x 512 map. trailmark's implicit [`GridGraph`], through
//! its callback (`for_each_successor`, what the searches use) and its iterator (`neighbours`,
//! what the `pathfinding` peers are given), beside the same graph stored explicitly as a
//! `petgraph` adjacency list. Every way must produce the same moves and total cost before
//! anything is timed. Throughput is in cells expanded. Run: `cargo bench --bench grid_expansion`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use petgraph::graph::{DiGraph, NodeIndex};
use trailmark::core::generate;
use trailmark::prelude::*;

/// Moves and their total cost over every passable cell, through the callback.
fn callback(graph: &GridGraph, cells: &[Cell]) -> (usize, f64) {
    let (mut n, mut total) = (0, 0.0);
    for &c in cells {
        graph.for_each_successor(c, |_, cost| {
            n += 1;
            total += cost;
        });
    }
    (n, total)
}

/// The same through the iterator.
fn iterator(graph: &GridGraph, cells: &[Cell]) -> (usize, f64) {
    let (mut n, mut total) = (0, 0.0);
    for &c in cells {
        for (_, cost) in graph.neighbours(c) {
            n += 1;
            total += cost;
        }
    }
    (n, total)
}

/// The same over an explicit adjacency list.
fn adjacency(pg: &DiGraph<Cell, f64>) -> (usize, f64) {
    let (mut n, mut total) = (0, 0.0);
    for node in pg.node_indices() {
        for e in pg.edges(node) {
            n += 1;
            total += *e.weight();
        }
    }
    (n, total)
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("grid_expansion");
    let maps = [
        ("random512-25", generate::random(512, 512, 0.25, 1)),
        ("maze512-4", generate::maze(512, 512, 4, 1)),
        ("rooms512-31", generate::rooms(512, 512, 31, 1)),
    ];
    for (name, grid) in maps {
        let grid = grid.expect("valid generator arguments");
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let cells: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
        let mut pg = DiGraph::new();
        let w = grid.width() as usize;
        let mut ids: Vec<Option<NodeIndex>> = vec![None; grid.len()];
        for &c in &cells {
            ids[c.y as usize * w + c.x as usize] = Some(pg.add_node(c));
        }
        for &c in &cells {
            let from = ids[c.y as usize * w + c.x as usize].expect("passable");
            graph.for_each_successor(c, |next, cost| {
                pg.add_edge(from, ids[next.y as usize * w + next.x as usize].expect("passable"), cost);
            });
        }
        let reference = callback(&graph, &cells);
        assert_eq!(iterator(&graph, &cells), reference, "{name}: iterator");
        let explicit = adjacency(&pg);
        assert_eq!(explicit.0, reference.0, "{name}: adjacency list");
        assert!((explicit.1 - reference.1).abs() <= 1e-9 * reference.1, "{name}: adjacency costs");
        group.throughput(Throughput::Elements(cells.len() as u64));
        group.bench_with_input(BenchmarkId::new("trailmark_callback", name), &cells, |b, cells| {
            b.iter(|| callback(black_box(&graph), cells))
        });
        group.bench_with_input(BenchmarkId::new("trailmark_iterator", name), &cells, |b, cells| {
            b.iter(|| iterator(black_box(&graph), cells))
        });
        group.bench_function(BenchmarkId::new("petgraph_adjacency", name), |b| {
            b.iter(|| adjacency(black_box(&pg)))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
