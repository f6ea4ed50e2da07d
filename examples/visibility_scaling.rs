//! Visibility-graph build time against the number of obstacles: generated worlds of 10 to 500
//! random convex hexagons, each built on one thread and on all cores, and the exponent of the
//! fitted power law `time ~ n^k` in the number of boundary vertices n (Lee's sweep is
//! O(n² log n), so k should come out a little above 2).
//!
//! ```text
//! cargo run --release --example visibility_scaling
//! ```

use std::time::Instant;

use trailmark::core::generate;
use trailmark::graph::visibility::{Edges, VisibilityGraph};

/// The best of `runs` timings of `f`, in seconds.
fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let clock = Instant::now();
        let out = f();
        best = best.min(clock.elapsed().as_secs_f64());
        last = Some(out);
    }
    (best, last.expect("at least one run"))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!(
        "| obstacles | vertices | nodes | edges (all) | 1 thread | all cores | tangent edges | tangent, all cores |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut samples = Vec::new();
    for &count in &[10usize, 20, 50, 100, 200, 500] {
        let world = generate::convex_obstacles(1000.0, count, 6, 0.0, 42)?;
        let space = world.free_space();
        let vertices = space.positions().len();
        let runs = if count <= 100 { 5 } else { 3 };
        let (one, graph) = best_of(runs, || VisibilityGraph::with_options(space.clone(), Edges::All, 1));
        let (all, _) = best_of(runs, || VisibilityGraph::with_options(space.clone(), Edges::All, 0));
        let (tangent_time, tangent) =
            best_of(runs, || VisibilityGraph::with_options(space.clone(), Edges::Tangent, 0));
        println!(
            "| {count} | {vertices} | {} | {} | {:.1} ms | {:.1} ms | {} | {:.1} ms |",
            graph.node_count(),
            graph.edge_count(),
            one * 1e3,
            all * 1e3,
            tangent.edge_count(),
            tangent_time * 1e3
        );
        samples.push((vertices as f64, one));
    }
    // Least squares on log time = k log n + c.
    let n = samples.len() as f64;
    let (sx, sy) = samples.iter().fold((0.0, 0.0), |(a, b), &(v, t)| (a + v.ln(), b + t.ln()));
    let (mx, my) = (sx / n, sy / n);
    let (num, den) = samples
        .iter()
        .fold((0.0, 0.0), |(a, b), &(v, t)| (a + (v.ln() - mx) * (t.ln() - my), b + (v.ln() - mx).powi(2)));
    println!("\nfitted exponent (one thread, full graph): time ~ n^{:.2}", num / den);
    Ok(())
}
