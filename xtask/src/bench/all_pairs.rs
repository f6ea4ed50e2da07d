//! The all-pairs section: shortest distances between every pair of nodes kept right as edges
//! change (`AllPairs::update_edges`) beside recomputing them (a Dijkstra search from every node,
//! and Floyd-Warshall), on a road-network-like graph and on an 8-connected grid, for batches of
//! 1, 10 and 100 changes. After the batches the table must equal a fresh one.

use std::time::Instant;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::cost::Cost;
use trailmark::core::generate;
use trailmark::core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
use trailmark::prelude::*;
use trailmark::search::AllPairs;

use crate::bench::stats::median;
use crate::bench::suite::Suite;

/// Batches per change size; the median is reported.
const BATCHES: usize = 5;

/// One graph and one change size.
#[derive(Debug, Clone, Serialize)]
pub struct AllPairsRow {
    /// The graph.
    pub graph: String,
    /// Nodes.
    pub nodes: usize,
    /// Directed edges.
    pub edges: usize,
    /// What one change is.
    pub change: &'static str,
    /// Changes per batch.
    pub batch: usize,
    /// Edge changes told per batch (median).
    pub edges_changed: usize,
    /// The update of every row, milliseconds (median over the batches).
    pub update_ms: f64,
    /// Queue pops per update, summed over the rows (median).
    pub repaired: u64,
    /// A Dijkstra search from every node on the changed graph, milliseconds.
    pub dijkstra_ms: f64,
    /// Floyd-Warshall on the changed graph, milliseconds.
    pub floyd_warshall_ms: f64,
    /// Distances that differ from a fresh table after the batches (must be 0).
    pub errors: usize,
}

/// A directed graph in compressed rows, both ways, whose edge costs change.
struct Roads {
    /// `out[out_start[v]..out_start[v + 1]]`: (head, edge id).
    out_start: Vec<usize>,
    out: Vec<(u32, usize)>,
    into_start: Vec<usize>,
    into: Vec<(u32, usize)>,
    /// The tail and head of each edge.
    ends: Vec<(u32, u32)>,
    cost: Vec<Cost>,
}

impl Roads {
    /// `n` random crossroads in a square, each joined both ways to its four nearest; a road
    /// costs its length times a speed factor from 1 to 2.
    fn generate(n: usize, rng: &mut ChaCha8Rng) -> Roads {
        let points: Vec<(f64, f64)> =
            (0..n).map(|_| (rng.random_range(0.0..1.0), rng.random_range(0.0..1.0))).collect();
        let mut pairs = std::collections::BTreeMap::new();
        for (a, &(ax, ay)) in points.iter().enumerate() {
            let mut near: Vec<(f64, usize)> = points
                .iter()
                .enumerate()
                .filter(|&(b, _)| b != a)
                .map(|(b, &(bx, by))| ((ax - bx).hypot(ay - by), b))
                .collect();
            near.sort_by(|x, y| x.0.total_cmp(&y.0));
            for &(d, b) in near.iter().take(4) {
                let key = (a.min(b), a.max(b));
                pairs.entry(key).or_insert(d * rng.random_range(1.0..2.0));
            }
        }
        let mut edges = Vec::new();
        for (&(a, b), &c) in &pairs {
            edges.push((a as u32, b as u32, c));
            edges.push((b as u32, a as u32, c));
        }
        Roads::from_edges(n, &edges)
    }

    fn from_edges(n: usize, edges: &[(u32, u32, Cost)]) -> Roads {
        let rows = |key: fn(&(u32, u32, Cost)) -> (u32, u32)| {
            let mut start = vec![0usize; n + 1];
            for e in edges {
                start[key(e).0 as usize + 1] += 1;
            }
            for v in 0..n {
                start[v + 1] += start[v];
            }
            let mut fill = start.clone();
            let mut list = vec![(0u32, 0usize); edges.len()];
            for (id, e) in edges.iter().enumerate() {
                let (v, other) = key(e);
                list[fill[v as usize]] = (other, id);
                fill[v as usize] += 1;
            }
            (start, list)
        };
        let (out_start, out) = rows(|e| (e.0, e.1));
        let (into_start, into) = rows(|e| (e.1, e.0));
        Roads {
            out_start,
            out,
            into_start,
            into,
            ends: edges.iter().map(|e| (e.0, e.1)).collect(),
            cost: edges.iter().map(|e| e.2).collect(),
        }
    }
}

impl Graph for Roads {
    type Node = u32;
    fn contains(&self, node: u32) -> bool {
        (node as usize) + 1 < self.out_start.len()
    }
}

impl Successors for Roads {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &(w, id) in &self.out[self.out_start[node as usize]..self.out_start[node as usize + 1]] {
            visit(w, self.cost[id]);
        }
    }
}

impl Predecessors for Roads {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &(u, id) in &self.into[self.into_start[node as usize]..self.into_start[node as usize + 1]] {
            visit(u, self.cost[id]);
        }
    }
}

impl IndexedGraph for Roads {
    fn node_bound(&self) -> usize {
        self.out_start.len() - 1
    }
    fn index_of(&self, node: u32) -> usize {
        node as usize
    }
    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}

/// Floyd-Warshall over the compact nodes of `graph`, in milliseconds (the distances are
/// dropped: it is the cost of recomputing that is measured).
fn floyd_warshall_ms<G>(graph: &G, nodes: &[G::Node]) -> f64
where
    G: Successors + IndexedGraph,
{
    let clock = Instant::now();
    let n = nodes.len();
    let mut compact = vec![usize::MAX; graph.node_bound()];
    for (c, &v) in nodes.iter().enumerate() {
        compact[graph.index_of(v)] = c;
    }
    let mut d = vec![Cost::INFINITY; n * n];
    for (c, &v) in nodes.iter().enumerate() {
        d[c * n + c] = 0.0;
        if !graph.contains(v) {
            continue;
        }
        graph.for_each_successor(v, |w, cost| {
            let slot = &mut d[c * n + compact[graph.index_of(w)]];
            *slot = slot.min(cost);
        });
    }
    for k in 0..n {
        let through: Vec<Cost> = d[k * n..(k + 1) * n].to_vec();
        for i in 0..n {
            let ik = d[i * n + k];
            if ik == Cost::INFINITY {
                continue;
            }
            for (dij, &kj) in d[i * n..(i + 1) * n].iter_mut().zip(&through) {
                if ik + kj < *dij {
                    *dij = ik + kj;
                }
            }
        }
    }
    std::hint::black_box(&d);
    clock.elapsed().as_secs_f64() * 1e3
}

/// How many distances of `table` differ from `fresh` (relative 1e-9).
fn differences<N>(table: &AllPairs<N>, fresh: &AllPairs<N>) -> usize
where
    N: Copy + Eq + std::hash::Hash + std::fmt::Debug,
{
    let mut errors = 0;
    for s in fresh.sources() {
        let (a, b) = (table.row_from(s).unwrap_or(&[]), fresh.row_from(s).unwrap_or(&[]));
        errors += a.len().abs_diff(b.len());
        errors += a
            .iter()
            .zip(b)
            .filter(|(x, y)| {
                !(x == y || (x.is_finite() && y.is_finite() && (*x - *y).abs() <= 1e-9 * y.max(1.0)))
            })
            .count();
    }
    errors
}

/// Runs batches of `sizes` changes made by `change` on `graph`, updating a table, and times the
/// recomputations once on the graph the batches leave.
fn measure<G, N>(
    name: &str,
    (graph, nodes): (&mut G, &[N]),
    what: &'static str,
    sizes: &[usize],
    mut change: impl FnMut(&mut G, &mut Vec<EdgeChange<N>>),
) -> Result<Vec<AllPairsRow>, String>
where
    G: Successors<Node = N> + Predecessors + IndexedGraph<Node = N>,
    N: Copy + Eq + std::hash::Hash + std::fmt::Debug,
{
    let err = |e: &dyn std::fmt::Display| format!("{name}: {e}");
    let mut table = AllPairs::new(&*graph, nodes.iter().copied()).map_err(|e| err(&e))?;
    let mut edge_count = 0;
    for &v in nodes.iter().filter(|&&v| graph.contains(v)) {
        graph.for_each_successor(v, |_, _| edge_count += 1);
    }
    let mut rows = Vec::new();
    for &size in sizes {
        let (mut times, mut repaired, mut changed) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..BATCHES {
            let mut changes = Vec::new();
            for _ in 0..size {
                change(graph, &mut changes);
            }
            let stats = table.update_edges(&*graph, &changes).map_err(|e| err(&e))?;
            times.push(stats.elapsed.as_secs_f64() * 1e3);
            repaired.push(stats.expansions as f64);
            changed.push(changes.len() as f64);
        }
        let clock = Instant::now();
        let fresh = AllPairs::new(&*graph, nodes.iter().copied()).map_err(|e| err(&e))?;
        let dijkstra_ms = clock.elapsed().as_secs_f64() * 1e3;
        let floyd_warshall_ms = if size == sizes[0] { floyd_warshall_ms(&*graph, nodes) } else { f64::NAN };
        for list in [&mut times, &mut repaired, &mut changed] {
            list.sort_by(f64::total_cmp);
        }
        rows.push(AllPairsRow {
            graph: name.to_string(),
            nodes: nodes.len(),
            edges: edge_count,
            change: what,
            batch: size,
            edges_changed: median(&changed) as usize,
            update_ms: median(&times),
            repaired: median(&repaired) as u64,
            dijkstra_ms,
            floyd_warshall_ms,
            errors: differences(&table, &fresh),
        });
    }
    // Floyd-Warshall does not depend on the batch: measured once, shown on every row.
    let fw = rows.first().map_or(f64::NAN, |r| r.floyd_warshall_ms);
    rows.iter_mut().for_each(|r| r.floyd_warshall_ms = fw);
    Ok(rows)
}

/// Runs the section.
pub fn bench(suite: Suite, seed: u64) -> Result<Vec<AllPairsRow>, String> {
    let (crossroads, side) = match suite {
        Suite::Quick => (1000, 32),
        Suite::Full => (2500, 48),
    };
    let sizes = [1, 10, 100];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut roads = Roads::generate(crossroads, &mut rng);
    let road_count = roads.cost.len() / 2;
    // A road (both directions) gets slower or faster by up to 3x, or closes (1 in 10).
    let crossings: Vec<u32> = (0..crossroads as u32).collect();
    let mut rows =
        measure("roads", (&mut roads, &crossings), "a road's cost, both ways", &sizes, |g, changes| {
            let road = rng.random_range(0..road_count);
            let factor = if rng.random_bool(0.1) { Cost::INFINITY } else { rng.random_range(0.33..3.0) };
            for id in [2 * road, 2 * road + 1] {
                let base = if g.cost[id].is_finite() { g.cost[id] } else { 0.05 };
                g.cost[id] = base * factor;
                let (a, b) = g.ends[id];
                changes.push(EdgeChange::new(a, b));
            }
        })?;
    let grid = generate::random(side, side, 0.2, seed).map_err(|e| e.to_string())?;
    let mut graph = GridGraph::new(&grid, Connectivity::Eight);
    let free: Vec<Cell> = grid.cells().filter(|&c| grid.is_passable(c)).collect();
    let name = format!("grid {side}x{side}, 20% blocked");
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    let cells: Vec<Cell> = grid.cells().collect();
    rows.extend(measure(&name, (&mut graph, &cells), "a free cell's cost", &sizes, |g, changes| {
        let cell = free[rng.random_range(0..free.len())];
        let _ = g.set_cost(cell, rng.random_range(1.0..5.0));
        for other in g.cells_affected_by(cell) {
            changes.extend([EdgeChange::new(other, cell), EdgeChange::new(cell, other)]);
        }
    })?);
    Ok(rows)
}

/// The section of the report.
pub fn markdown(rows: &[AllPairsRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut out = String::from(
        "\n## All pairs under change\n\nShortest distances between every pair of nodes, kept by `AllPairs::update_edges` \
         (Ramalingam-Reps per source) as batches of changes arrive, beside recomputing them on the changed graph: a \
         Dijkstra search from every node, and Floyd-Warshall. Roads: crossroads in a square each joined both ways to its \
         four nearest, costs length x speed factor 1-2; a change makes a road up to 3x slower or faster, or closes it \
         (1 in 10). Grid: 8-connected, a change sets a free cell's cost (1-5). Update times are medians over 5 batches \
         applied in turn; after them the table must equal a fresh one.\n\n\
         | graph | nodes | edges | change | batch | change notices | update | queue pops | Dijkstra from every node | speedup | Floyd-Warshall | speedup | errors |\n\
         |---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {:.2} ms | {} | {:.0} ms | {:.1}x | {:.0} ms | {:.1}x | {} |\n",
            r.graph,
            r.nodes,
            r.edges,
            r.change,
            r.batch,
            r.edges_changed,
            r.update_ms,
            r.repaired,
            r.dijkstra_ms,
            r.dijkstra_ms / r.update_ms,
            r.floyd_warshall_ms,
            r.floyd_warshall_ms / r.update_ms,
            r.errors
        ));
    }
    out
}
