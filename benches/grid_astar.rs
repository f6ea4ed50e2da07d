//! Grid A* on MovingAI maps: trailmark beside `pathfinding` and `petgraph`, same queries, same
//! graph semantics (8-connected, no corner cutting, costs 1 and sqrt(2) as `f64`, octile
//! heuristic).
//!
//! Each benchmark solves a fixed batch of scenarios (every k-th of the map's scenario file, so
//! all difficulty buckets are represented); the throughput is in queries per second. Before
//! timing, every implementation's cost is checked against the published optimum.
//!
//! Needs `../shared/movingai` beside the project; without it the benchmark says so and does
//! nothing. Run: `cargo bench --bench grid_astar`.

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use ordered_float::OrderedFloat;
use petgraph::graph::{DiGraph, NodeIndex};
use trailmark::movingai::{self, Scenario};
use trailmark::prelude::*;

/// The maps and how many queries to take from each.
const MAPS: [(&str, &str, usize); 3] =
    [("dao", "brc202d", 100), ("bg512", "AR0011SR", 100), ("mazes", "maze512-4-0", 40)];

fn data_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/movingai")
}

/// Every k-th scenario, `n` in all.
fn sample(scenarios: Vec<Scenario>, n: usize) -> Vec<Scenario> {
    let step = (scenarios.len() / n).max(1);
    scenarios.into_iter().step_by(step).take(n).collect()
}

/// The graph's moves out of `c`, as the `pathfinding` crate takes them (no allocation).
fn neighbours(graph: &GridGraph, c: Cell) -> impl Iterator<Item = (Cell, OrderedFloat<f64>)> + '_ {
    graph.neighbours(c).map(|(next, cost)| (next, OrderedFloat(cost)))
}

fn octile(a: Cell, b: Cell) -> f64 {
    trailmark::core::cost::octile(a.x.abs_diff(b.x), a.y.abs_diff(b.y))
}

/// The grid as a petgraph graph, with the cell of every node.
fn petgraph_of(graph: &GridGraph, grid: &Grid) -> (DiGraph<Cell, f64>, Vec<Option<NodeIndex>>) {
    let mut g = DiGraph::new();
    let ids: Vec<Option<NodeIndex>> =
        grid.cells().map(|c| grid.is_passable(c).then(|| g.add_node(c))).collect();
    let w = grid.width() as usize;
    for c in grid.cells().filter(|&c| grid.is_passable(c)) {
        let from = ids[c.y as usize * w + c.x as usize].expect("passable");
        graph.for_each_successor(c, |next, cost| {
            g.add_edge(from, ids[next.y as usize * w + next.x as usize].expect("passable"), cost);
        });
    }
    (g, ids)
}

fn bench(c: &mut Criterion) {
    let dir = data_dir();
    if !dir.is_dir() {
        eprintln!("grid_astar: {} not found; skipping the MovingAI benchmarks", dir.display());
        return;
    }
    for (set, name, n) in MAPS {
        let grid = movingai::read_map(dir.join(format!("maps/{set}/{name}.map"))).expect("map");
        let scen =
            movingai::read_scenarios(dir.join(format!("scenarios/{set}/{name}.map.scen"))).expect("scen");
        let queries = sample(scen, n);
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let (pg, ids) = petgraph_of(&graph, &grid);
        let w = grid.width() as usize;
        let id = |c: Cell| ids[c.y as usize * w + c.x as usize].expect("passable");

        let mut search = Search::new();
        let trailmark_batch = |search: &mut Search| {
            let mut expansions = 0;
            for q in &queries {
                let h = graph.heuristic(GridHeuristic::Octile, q.goal);
                let found = search.astar(&graph, q.start, q.goal, h).expect("valid query");
                expansions += found.stats.expansions;
                black_box(found.cost());
            }
            expansions
        };
        let pathfinding_one = |q: &Scenario| {
            pathfinding::prelude::astar(
                &q.start,
                |&p| neighbours(&graph, p),
                |&p| OrderedFloat(octile(p, q.goal)),
                |&p| p == q.goal,
            )
        };
        let petgraph_one = |q: &Scenario| {
            let goal = id(q.goal);
            petgraph::algo::astar(&pg, id(q.start), |n| n == goal, |e| *e.weight(), |n| octile(pg[n], q.goal))
        };

        // Correctness first: every implementation matches the published optimum.
        for q in &queries {
            let tol = 1e-4 * q.optimal_length.max(1.0) + 0.006;
            let h = graph.heuristic(GridHeuristic::Octile, q.goal);
            let ours = search.astar(&graph, q.start, q.goal, h).unwrap().cost().unwrap();
            let theirs = pathfinding_one(q).unwrap().1.0;
            let pet = petgraph_one(q).unwrap().0;
            for cost in [ours, theirs, pet] {
                assert!((cost - q.optimal_length).abs() <= tol, "{name}: {cost} vs {}", q.optimal_length);
            }
        }
        let expansions = trailmark_batch(&mut search);
        eprintln!(
            "grid_astar/{name}: {} queries, {expansions} trailmark expansions per batch",
            queries.len()
        );

        let mut group = c.benchmark_group(format!("grid_astar/{name}"));
        group.throughput(Throughput::Elements(queries.len() as u64));
        group.sample_size(10);
        group.bench_function("trailmark", |b| b.iter(|| trailmark_batch(&mut search)));
        group.bench_function("pathfinding", |b| {
            b.iter(|| queries.iter().filter_map(|q| pathfinding_one(q).map(|p| p.1.0)).sum::<f64>())
        });
        group.bench_function("petgraph", |b| {
            b.iter(|| queries.iter().filter_map(|q| petgraph_one(q).map(|p| p.0)).sum::<f64>())
        });
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
