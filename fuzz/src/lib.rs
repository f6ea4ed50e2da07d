//! The checks shared by trailmark's fuzz targets (`fuzz_targets/*.rs`).
//!
//! Every check here is independent of the code it checks: grid paths are re-costed and compared
//! with a Dijkstra search and a breadth-first search written here ([`grid`]), polygon paths are
//! sampled and each sample tested with the plain O(n) distance test
//! [`PolygonWorld::reference_is_clear`](trailmark_core::world::PolygonWorld::reference_is_clear)
//! ([`polygon`]). A failed check panics, which libFuzzer reports as a crash with the input.
//!
//! Inputs that would take long (large grids, many samples or iterations) are skipped, never
//! edited: [`budget::problem_is_quick`] says which.

pub mod boxes;
pub mod budget;
pub mod car;
pub mod generate;
pub mod grid;
pub mod movingai;
pub mod polygon;
pub mod robot;
pub mod ros_map;
pub mod terrain;

use std::path::Path;

use trailmark::solve::{PlannerSpec, ProblemSpec, WorldSpec};
use trailmark_core::footprint::MAX_FOOTPRINT_VERTICES;

/// The folder relative map paths are resolved against: one that does not exist, so that no
/// map file is ever read (absolute paths are skipped by [`budget::problem_is_quick`]).
pub const NO_DIR: &str = "/nonexistent-dir";

/// Whether `a` and `b` agree to `rel` relative to the larger of them (or are both tiny).
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()) + 16.0 * f64::MIN_POSITIVE
}

/// Solves `problem` when it is quick enough, and checks every path it returns.
pub fn solve_and_check(problem: &ProblemSpec) {
    if !budget::problem_is_quick(problem) {
        return;
    }
    // A footprint past the documented most vertices is refused, whatever else the document says.
    if let PlannerSpec::HybridAStar(spec) = &problem.planner
        && let Some(count) = spec.footprint.as_ref().map(Vec::len).filter(|&n| n > MAX_FOOTPRINT_VERTICES)
    {
        let solved = trailmark::solve::solve(problem, Path::new(NO_DIR));
        assert!(solved.is_err(), "a footprint of {count} vertices was accepted: {solved:?}");
        return;
    }
    let Ok(result) = trailmark::solve::solve(problem, Path::new(NO_DIR)) else {
        return;
    };
    if let PlannerSpec::HybridAStar(spec) = &problem.planner {
        let grid = match &problem.world {
            WorldSpec::Grid(world) => Some(
                grid::RefGrid::from_world(world)
                    .unwrap_or_else(|why| panic!("solve accepted a grid world the reference rejects: {why}")),
            ),
            _ => None,
        };
        let world = match (&problem.world, &grid) {
            (WorldSpec::Polygons(world), _) => car::CarWorld::Polygons(world),
            (_, Some(grid)) => car::CarWorld::Grid(grid),
            _ => panic!("hybrid_astar solved a {:?} world", problem.world),
        };
        car::check_result(problem, spec, world, &result);
        return;
    }
    match &problem.world {
        WorldSpec::Grid(world) => grid::check_result(problem, world, &result),
        WorldSpec::Polygons(world) => polygon::check_result(problem, world, &result),
        WorldSpec::Boxes(world) => boxes::check_result(problem, world, &result),
        // Its map would be a file below NO_DIR, which does not exist.
        WorldSpec::RosMap(_) => panic!("a ROS map was solved without its file"),
        WorldSpec::Robot(_) => panic!("a robot world was solved without its files"),
    }
}

/// Parses `bytes` as a problem document and, when it is one, runs [`solve_and_check`].
pub fn problem_bytes(bytes: &[u8]) {
    if let Ok(problem) = serde_json::from_slice::<ProblemSpec>(bytes) {
        solve_and_check(&problem);
    }
}
