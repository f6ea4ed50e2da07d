//! What the document tests read from results: a path's states, and a result without its
//! measured times. Included by path (`#[path = "support/results.rs"] mod results;`).

use trailmark::solve::{SolveResult, Waypoint};

/// The path's waypoints as coordinates (a cell is not one: panics).
pub fn states(result: &SolveResult) -> Vec<Vec<f64>> {
    result
        .path
        .iter()
        .map(|w| match w {
            Waypoint::Point(c) => c.clone(),
            Waypoint::Cell(c) => panic!("a cell {c:?}"),
        })
        .collect()
}

/// `result` with every measured time zeroed, for comparing runs.
pub fn without_times(mut result: SolveResult) -> SolveResult {
    result.stats.time_s = 0.0;
    if let Some(s) = result.stats.sampling.as_mut() {
        s.time_to_solution_s = s.time_to_solution_s.map(|_| 0.0);
        s.simplify_time_s = 0.0;
        s.improvements.iter_mut().for_each(|b| b.time_s = 0.0);
    }
    result
}
