//! Box worlds: every waypoint inside the bounds and outside every (closed) box, every motion
//! sampled every 1/200 of its length with each sample tested against the boxes directly, the
//! path from the start (to the goal when solved), and the cost equal to the path's length.

use trailmark::solve::{BoxesSpec, ProblemSpec, SolveResult, Status, Waypoint};

use crate::close;

/// Samples per motion.
pub const SAMPLES_PER_MOTION: usize = 200;

/// Whether `q` is in the bounds and in no box (faces included: boxes are closed).
fn clear(world: &BoxesSpec, q: &[f64]) -> bool {
    let inside = |lo: &[f64], hi: &[f64]| q.iter().zip(lo.iter().zip(hi)).all(|(x, (l, h))| x >= l && x <= h);
    let in_bounds =
        q.len() == world.bounds.len() && q.iter().zip(&world.bounds).all(|(x, [l, h])| x >= l && x <= h);
    in_bounds && !world.obstacles.iter().any(|[lo, hi]| inside(lo, hi))
}

/// Checks the result of a box-world problem that `solve` accepted.
pub fn check_result(problem: &ProblemSpec, world: &BoxesSpec, result: &SolveResult) {
    match result.status {
        Status::Solved | Status::Approximate => {}
        Status::NoPath => panic!("a sampling planner claims to prove no path exists"),
        Status::Stopped => {
            assert!(result.path.is_empty() && result.cost.is_none(), "stopped with a path or cost");
            return;
        }
    }
    let points: Vec<&[f64]> = result
        .path
        .iter()
        .map(|w| match w {
            Waypoint::Point(p) => p.as_slice(),
            Waypoint::Cell(_) => panic!("a cell in a box world's path"),
        })
        .collect();
    assert_eq!(
        points.first().copied(),
        Some(problem.start.as_slice()),
        "the path does not begin at the start"
    );
    if result.status == Status::Solved {
        assert_eq!(
            points.last().copied(),
            Some(problem.goal.as_slice()),
            "a solved path does not end at the goal"
        );
    }
    let mut length = 0.0;
    for m in points.windows(2) {
        let (a, b) = (m[0], m[1]);
        for i in 0..=SAMPLES_PER_MOTION {
            let t = i as f64 / SAMPLES_PER_MOTION as f64;
            let q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + (y - x) * t).collect();
            assert!(clear(world, &q), "{q:?} on {a:?} -> {b:?} is out of bounds or in a box");
        }
        length += a.iter().zip(b).map(|(x, y)| (y - x) * (y - x)).sum::<f64>().sqrt();
    }
    let cost = result.cost.expect("a path has a cost");
    assert!(close(cost, length, 1e-9), "cost {cost} against the path's length {length}");
}
