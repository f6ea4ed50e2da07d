//! PRM build times on generated worlds: `cargo run --release --example prm_scaling`.
//!
//! Random convex obstacles (hexagons) in a 1000 x 1000 square, robot radius 2; PRM* over
//! Halton samples (k = ⌈e(1 + 1/d) ln n⌉), each local path checked exactly. Prints the build
//! time, the graph's size and the local paths checked per second, and the same for a Dubins
//! roadmap (turning radius 10, 15 nearest).

use std::time::Instant;

use trailmark::core::generate::convex_obstacles;
use trailmark::sample::Dubins;
use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!(
        "{:>9} {:>8} {:>9} {:>10} {:>10} {:>12}",
        "obstacles", "samples", "edges", "components", "build ms", "checks/s"
    );
    for (obstacles, samples) in [(10, 1000), (100, 1000), (500, 1000), (100, 5000), (500, 5000)] {
        let world = convex_obstacles(1000.0, obstacles, 6, 2.0, 1)?;
        let options = PrmOptions {
            sampler: PrmSampler::Halton,
            connection: Connection::PrmStar,
            ..PrmOptions::default()
        };
        let clock = Instant::now();
        let mut prm = PolygonPrm::new(world, options)?;
        prm.grow(samples)?;
        report(obstacles, samples, prm.edge_count(), prm.component_count(), prm.local_paths_checked(), clock);
    }
    println!("Dubins roadmap (turning radius 10, 15 nearest):");
    for (obstacles, samples) in [(100, 1000), (500, 1000)] {
        let world = convex_obstacles(1000.0, obstacles, 6, 2.0, 1)?;
        let options = PrmOptions {
            sampler: PrmSampler::Halton,
            connection: Connection::Nearest { k: 15 },
            ..PrmOptions::default()
        };
        let clock = Instant::now();
        let space = Dubins::new(world.bounds(), 10.0)?;
        let mut prm = PolygonPrm::with_space(world, space, options)?;
        prm.grow(samples)?;
        report(obstacles, samples, prm.edge_count(), prm.component_count(), prm.local_paths_checked(), clock);
    }
    Ok(())
}

/// One row of the table.
fn report(obstacles: usize, samples: usize, edges: usize, components: usize, checks: u64, clock: Instant) {
    let seconds = clock.elapsed().as_secs_f64();
    println!(
        "{obstacles:>9} {samples:>8} {edges:>9} {components:>10} {:>10.1} {:>12.0}",
        seconds * 1e3,
        checks as f64 / seconds
    );
}
