//! Box worlds: every waypoint inside the bounds and outside every (closed) box, every motion
//! sampled every 1/200 of its length with each sample tested against the boxes directly and
//! clipped against each box (a motion may not run inside one for more than a billionth of its
//! length: sampling misses a motion that cuts a box's corner), the path from the start (to the
//! goal when solved), and the cost equal to the path's length.
//!
//! Walls: where the boxes that span a slab `c0 <= x[axis] <= c1` cover the bounds' whole cross
//! section (touching boxes block as their union: they are closed), no path may reach the far
//! side of the slab from a start on the near one. Found from the boxes alone, so that it holds
//! for every document, not only the walls the generator builds.

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

/// Whether the segment `a`-`b` runs inside the closed box `[lo, hi]` for more than a billionth
/// of its length (the slab test: the parameters where it lies within every axis's sides).
/// Written here again on purpose, apart from the library's `enters`: the check must not share
/// the code it checks.
fn clips(a: &[f64], b: &[f64], lo: &[f64], hi: &[f64]) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..a.len() {
        let d = b[i] - a[i];
        if d == 0.0 {
            if !(a[i] >= lo[i] && a[i] <= hi[i]) {
                return false;
            }
            continue;
        }
        let (u, v) = ((lo[i] - a[i]) / d, (hi[i] - a[i]) / d);
        t0 = t0.max(u.min(v));
        t1 = t1.min(u.max(v));
    }
    t1 - t0 > 1e-9
}

/// The most cells of the grid a wall's cross section is cut into to test that it is covered.
const MAX_SECTION_CELLS: usize = 4096;

/// The walls of `world`: `(axis, c0, c1)` where the boxes spanning `[c0, c1]` along `axis`
/// cover the bounds' cross section, every point of it. Each box's own span along each axis is a
/// candidate slab, and so is each of its faces (`c0 = c1`: where two boxes meet at a face or a
/// corner, only the plane they share may be covered by both). The cross section is cut at every
/// side of those boxes within the bounds; it is covered when every cell of that cut holds a box
/// (the boxes are closed: covering every cell's inside covers its edges too). Cuts of more than
/// [`MAX_SECTION_CELLS`] are not tried.
pub fn walls(world: &BoxesSpec) -> Vec<(usize, f64, f64)> {
    let n = world.bounds.len();
    let mut found = Vec::new();
    let candidates = world.obstacles.iter().flat_map(|[lo, hi]| {
        (0..n).flat_map(move |axis| {
            [(axis, lo[axis], hi[axis]), (axis, lo[axis], lo[axis]), (axis, hi[axis], hi[axis])]
        })
    });
    for (axis, lo, hi) in candidates {
        {
            let [b0, b1] = world.bounds[axis];
            let (c0, c1) = (lo.max(b0), hi.min(b1));
            if c0.is_nan() || c1.is_nan() || c0 > c1 {
                continue;
            }
            let spanning: Vec<&[Vec<f64>; 2]> =
                world.obstacles.iter().filter(|[l, h]| l[axis] <= c0 && h[axis] >= c1).collect();
            // Per other axis, the cuts: the bounds and every spanning box's sides inside them.
            let mut cuts: Vec<(usize, Vec<f64>)> = Vec::new();
            for i in (0..n).filter(|&i| i != axis) {
                let [b0, b1] = world.bounds[i];
                let mut c = vec![b0, b1];
                c.extend(spanning.iter().flat_map(|[l, h]| [l[i], h[i]]).filter(|&x| x > b0 && x < b1));
                c.sort_by(f64::total_cmp);
                c.dedup();
                cuts.push((i, c));
            }
            let count = cuts.iter().try_fold(1usize, |m, (_, c)| m.checked_mul(c.len() - 1));
            if count.is_none_or(|c| c > MAX_SECTION_CELLS) {
                continue;
            }
            let mut digits = vec![0usize; cuts.len()];
            let covered = 'cells: loop {
                // The middle of the cell `digits`, in each box's closed span?
                let held = spanning.iter().any(|[l, h]| {
                    cuts.iter().zip(&digits).all(|((i, c), &k)| {
                        let m = 0.5 * (c[k] + c[k + 1]);
                        m >= l[*i] && m <= h[*i]
                    })
                });
                if !held {
                    break 'cells false;
                }
                // The next cell, or done.
                let mut d = 0;
                loop {
                    if d == digits.len() {
                        break 'cells true;
                    }
                    digits[d] += 1;
                    if digits[d] + 1 < cuts[d].1.len() {
                        break;
                    }
                    digits[d] = 0;
                    d += 1;
                }
            };
            if covered {
                found.push((axis, c0, c1));
            }
        }
    }
    found.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    found.dedup();
    found
}

/// Asserts that `points`, a path from the problem's start, stay on the start's side of every
/// wall that parts the start from the goal.
fn check_walls(problem: &ProblemSpec, world: &BoxesSpec, points: &[&[f64]], status: Status) {
    let (start, goal) = (&problem.start, &problem.goal);
    for (axis, c0, c1) in walls(world) {
        let near: &dyn Fn(&[f64]) -> bool = if start[axis] < c0 && goal[axis] > c1 {
            &|p| p[axis] < c0
        } else if start[axis] > c1 && goal[axis] < c0 {
            &|p| p[axis] > c1
        } else {
            continue;
        };
        if let Some(p) = points.iter().find(|p| !near(p)) {
            panic!("{status:?} path reaches {p:?} beyond the wall {c0} <= x[{axis}] <= {c1}");
        }
    }
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
        if let Some([lo, hi]) = world.obstacles.iter().find(|[lo, hi]| clips(a, b, lo, hi)) {
            panic!("{a:?} -> {b:?} runs through the box {lo:?} - {hi:?}");
        }
        length += a.iter().zip(b).map(|(x, y)| (y - x) * (y - x)).sum::<f64>().sqrt();
    }
    // The path stays on the start's side of every wall between the start and the goal.
    check_walls(problem, world, &points, result.status);
    let cost = result.cost.expect("a path has a cost");
    assert!(close(cost, length, 1e-9), "cost {cost} against the path's length {length}");
}

#[cfg(test)]
mod tests {
    use trailmark::solve::solve;

    use super::*;

    fn problem(boxes: &str, start: &str, goal: &str) -> ProblemSpec {
        serde_json::from_str(&format!(
            r#"{{"world": {{"boxes": {{"bounds": [[0, 1], [0, 1]], "obstacles": {boxes}}}}},
                "start": {start}, "goal": {goal}, "space": "rn",
                "planner": {{"name": "rrt_connect", "max_iterations": 2000}}}}"#
        ))
        .unwrap()
    }

    fn world(problem: &ProblemSpec) -> &BoxesSpec {
        let trailmark::solve::WorldSpec::Boxes(world) = &problem.world else { unreachable!() };
        world
    }

    #[test]
    fn walls_of_touching_boxes_are_found() {
        // A wall at 0.5 <= x <= 0.625 in two pieces meeting at y = 0.25.
        let split =
            problem("[[[0.5, 0], [0.625, 0.25]], [[0.5, 0.25], [0.625, 1]]]", "[0.25, 0.5]", "[0.75, 0.5]");
        // The slab and each of its faces.
        assert_eq!(walls(world(&split)), vec![(0, 0.5, 0.5), (0, 0.5, 0.625), (0, 0.625, 0.625)]);
        // A gap between the pieces: no wall.
        let gap =
            problem("[[[0.5, 0], [0.625, 0.25]], [[0.5, 0.26], [0.625, 1]]]", "[0.25, 0.5]", "[0.75, 0.5]");
        assert!(walls(world(&gap)).is_empty());
        // Two boxes meeting at the corner (0.5, 0.5) from the bounds' corners: the plane x = 0.5
        // (and y = 0.5) is covered by their faces.
        let corner = problem("[[[0, 0], [0.5, 0.5]], [[0.5, 0.5], [1, 1]]]", "[0.25, 0.75]", "[0.75, 0.25]");
        let found = walls(world(&corner));
        assert!(found.contains(&(0, 0.5, 0.5)) && found.contains(&(1, 0.5, 0.5)), "{found:?}");
    }

    #[test]
    fn nothing_crosses_a_wall_of_touching_boxes() {
        for p in [
            problem("[[[0.5, 0], [0.625, 0.25]], [[0.5, 0.25], [0.625, 1]]]", "[0.25, 0.5]", "[0.75, 0.5]"),
            problem("[[[0, 0], [0.5, 0.5]], [[0.5, 0.5], [1, 1]]]", "[0.25, 0.75]", "[0.75, 0.25]"),
        ] {
            let result = solve(&p, ".").unwrap();
            assert_ne!(result.status, Status::Solved, "{result:?}");
            check_result(&p, world(&p), &result);
            // Through the slit between the pieces, or through the corner: every check fails it.
            let (start, goal) = (p.start.clone(), p.goal.clone());
            let through = if p.start[1] == 0.5 { vec![0.5625, 0.25] } else { vec![0.5, 0.5] };
            let mut wrong = result.clone();
            wrong.status = Status::Solved;
            wrong.path = [start, through.clone(), goal].into_iter().map(Waypoint::Point).collect();
            wrong.cost = Some(1.0);
            assert!(std::panic::catch_unwind(|| check_result(&p, world(&p), &wrong)).is_err());
            let points: Vec<&[f64]> = vec![&p.start, &through, &p.goal];
            assert!(
                std::panic::catch_unwind(|| check_walls(&p, world(&p), &points, Status::Solved)).is_err()
            );
        }
    }

    #[test]
    fn a_motion_cutting_a_corner_between_samples_is_caught() {
        let (lo, hi) = ([0.5, 0.5], [0.6, 0.6]);
        // Past the corner (0.5, 0.6) by a hair, between two samples of a long motion.
        assert!(clips(&[0.0, 0.1], &[1.0, 1.0999], &lo, &hi));
        assert!(!clips(&[0.0, 0.1], &[1.0, 1.1001], &lo, &hi));
        // Along a face: the face is the box's (closed).
        assert!(clips(&[0.5, 0.0], &[0.5, 1.0], &lo, &hi));
    }
}
