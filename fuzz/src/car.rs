//! Hybrid A* documents on grid and polygon worlds: a solved path starts at the start pose and
//! ends at the goal pose, every pose it lists keeps the footprint free by a test written here
//! (on grids: the footprint polygon, as it is, apart from every blocked cell taken as a closed
//! square, or the reference point alone in no closed blocked cell; on polygon worlds: the
//! footprint inside the bounds and apart from every obstacle), its length is at least the
//! straight distance, its cost at least its length at the cheapest cell's price; no path means
//! an empty one. The reference point is held to the obstacles only when the footprint holds it
//! (a footprint ahead of its reference point, a forklift's forks, may have it over an
//! obstacle). On grids with a point footprint, `no_path` is checked by a breadth-first search
//! over the open cells; `stopped` must say why.

use std::collections::VecDeque;

use trailmark::solve::{HybridSpec, ProblemSpec, SolveResult, Status, Waypoint};
use trailmark_core::geometry::Point;
use trailmark_core::termination::Stop;
use trailmark_core::world::PolygonWorld;

use crate::grid::RefGrid;

/// The tolerance of positions and headings compared.
const TOLERANCE: f64 = 1e-6;

/// The footprint's polygon in the robot's frame, if the planner gives one.
fn local_polygon(spec: &HybridSpec) -> Option<Vec<Point>> {
    spec.footprint.as_ref().map(|v| v.iter().map(|p| Point::new(p[0], p[1])).collect())
}

/// `points` (robot frame) with the robot at the pose `[x, y, heading]`.
fn placed(points: &[Point], pose: &[f64]) -> Vec<Point> {
    let (s, c) = pose[2].sin_cos();
    points.iter().map(|p| Point::new(pose[0] + c * p.x - s * p.y, pose[1] + s * p.x + c * p.y)).collect()
}

fn orient(p: Point, q: Point, r: Point) -> f64 {
    (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)
}

/// Whether the closed segments `a`-`b` and `c`-`d` cross properly.
fn cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    orient(c, d, a) * orient(c, d, b) < 0.0 && orient(a, b, c) * orient(a, b, d) < 0.0
}

/// Whether `p`, on the line through `a` and `b`, lies within their box.
fn within(a: Point, b: Point, p: Point) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

/// Whether the closed segments `a`-`b` and `c`-`d` share a point (crossing, touching or
/// overlapping).
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (d1, d2, d3, d4) = (orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d));
    (d1 * d2 < 0.0 && d3 * d4 < 0.0)
        || (d1 == 0.0 && within(c, d, a))
        || (d2 == 0.0 && within(c, d, b))
        || (d3 == 0.0 && within(a, b, c))
        || (d4 == 0.0 && within(a, b, d))
}

/// Whether the closed polygon `v` holds `p`: on an edge, or inside by the crossing rule (a ray
/// to +x crosses the outline an odd number of times).
pub fn polygon_holds(v: &[Point], p: Point) -> bool {
    let n = v.len();
    let mut inside = false;
    for k in 0..n {
        let (a, b) = (v[k], v[(k + 1) % n]);
        if orient(a, b, p) == 0.0 && within(a, b, p) {
            return true;
        }
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether the closed polygon `v` meets the closed square `[x0, x1] x [y0, y1]`: an edge of one
/// meets an edge of the other, or a vertex of one lies in the other.
fn polygon_meets_square(v: &[Point], (x0, y0, x1, y1): (f64, f64, f64, f64)) -> bool {
    let corners = [Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)];
    let n = v.len();
    v.iter().any(|p| p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)
        || corners.iter().any(|&c| polygon_holds(v, c))
        || (0..n)
            .any(|k| (0..4).any(|m| segments_meet(v[k], v[(k + 1) % n], corners[m], corners[(m + 1) % 4])))
}

/// The width of a grid world's cells.
fn cell_width(spec: &HybridSpec) -> f64 {
    spec.resolution.unwrap_or(1.0)
}

/// Whether grid cell `(i, j)` (column, row from the bottom) is blocked; `None` off the grid.
fn blocked(grid: &RefGrid, i: i64, j: i64) -> Option<bool> {
    let inside = i >= 0 && j >= 0 && (i as usize) < grid.width && (j as usize) < grid.height;
    inside.then(|| !grid.costs[(grid.height - 1 - j as usize) * grid.width + i as usize].is_finite())
}

/// Whether `p` lies on the grid (cells `res` wide, y up from the bottom edge) and in no blocked
/// cell taken as a closed square (a point on the edge of a blocked cell touches it).
fn grid_point_free(grid: &RefGrid, res: f64, p: Point) -> bool {
    let (w, h) = (grid.width as f64 * res, grid.height as f64 * res);
    if !(p.x >= 0.0 && p.y >= 0.0 && p.x <= w && p.y <= h) {
        return false;
    }
    let (i, j) = ((p.x / res).floor() as i64, (p.y / res).floor() as i64);
    (i - 1..=i).all(|i| {
        (j - 1..=j).all(|j| {
            let touches = |k: i64, v: f64| v >= k as f64 * res && v <= (k + 1) as f64 * res;
            blocked(grid, i, j) != Some(true) || !(touches(i, p.x) && touches(j, p.y))
        })
    })
}

/// Whether a grid world's pose keeps the footprint on the grid and off every blocked cell
/// (cells `resolution` wide, y up from the bottom row): the polygon exactly, each blocked cell a
/// closed square, and the reference point too when the polygon holds it; without a polygon,
/// the reference point.
fn grid_pose_free(grid: &RefGrid, spec: &HybridSpec, pose: &[f64]) -> bool {
    let res = cell_width(spec);
    let reference = Point::new(pose[0], pose[1]);
    let Some(local) = local_polygon(spec) else { return grid_point_free(grid, res, reference) };
    let (w, h) = (grid.width as f64 * res, grid.height as f64 * res);
    // The planner prices every pose by its reference point's cell: it is on the grid.
    if !(reference.x >= 0.0 && reference.y >= 0.0 && reference.x <= w && reference.y <= h) {
        return false;
    }
    if polygon_holds(&local, Point::origin()) && !grid_point_free(grid, res, reference) {
        return false;
    }
    let v = placed(&local, pose);
    // The grid is a rectangle: the polygon is on it when its vertices are.
    if !v.iter().all(|p| p.x >= 0.0 && p.y >= 0.0 && p.x <= w && p.y <= h) {
        return false;
    }
    // The cells the polygon's box reaches, one more on the low sides (a vertex on a cell's low
    // edge touches the cell below it too).
    let (lo, hi) = v
        .iter()
        .fold(((f64::INFINITY, f64::INFINITY), (f64::NEG_INFINITY, f64::NEG_INFINITY)), |(l, h), p| {
            ((l.0.min(p.x), l.1.min(p.y)), (h.0.max(p.x), h.1.max(p.y)))
        });
    let (i0, i1) = ((lo.0 / res).floor() as i64 - 1, (hi.0 / res).floor() as i64);
    let (j0, j1) = ((lo.1 / res).floor() as i64 - 1, (hi.1 / res).floor() as i64);
    (j0..=j1).all(|j| {
        (i0..=i1).all(|i| {
            let square = (i as f64 * res, j as f64 * res, (i + 1) as f64 * res, (j + 1) as f64 * res);
            blocked(grid, i, j) != Some(true) || !polygon_meets_square(&v, square)
        })
    })
}

/// Whether a polygon world's pose keeps the footprint in the bounds and off the obstacles: a
/// disc of the world's radius about the reference point, or the planner's polygon (no edge of it
/// crossing an obstacle's, no vertex of either inside the other), with its reference point when
/// the polygon holds it.
fn polygon_pose_free(world: &PolygonWorld, spec: &HybridSpec, pose: &[f64]) -> bool {
    let (lo, hi) = (world.bounds().min(), world.bounds().max());
    let centre = Point::new(pose[0], pose[1]);
    let Some(local) = local_polygon(spec) else {
        return world.reference_is_clear(centre, TOLERANCE)
            && centre.x - lo.x >= world.robot_radius() - TOLERANCE
            && hi.x - centre.x >= world.robot_radius() - TOLERANCE
            && centre.y - lo.y >= world.robot_radius() - TOLERANCE
            && hi.y - centre.y >= world.robot_radius() - TOLERANCE;
    };
    let corners = placed(&local, pose);
    let n = corners.len();
    let mut points = corners.clone();
    if polygon_holds(&local, Point::origin()) {
        points.push(centre);
    }
    let in_bounds = points.iter().all(|c| c.x >= lo.x && c.y >= lo.y && c.x <= hi.x && c.y <= hi.y);
    in_bounds
        && world.obstacles().iter().all(|o| {
            let v = o.vertices();
            let crossing = (0..n).any(|k| {
                let (a, b) = (corners[k], corners[(k + 1) % n]);
                (0..v.len()).any(|m| cross(a, b, v[m], v[(m + 1) % v.len()]))
            });
            let footprint_inside = points.iter().any(|&c| o.contains_strictly(c));
            let obstacle_inside = v.iter().any(|&p| polygon_holds(&corners, p));
            !(crossing || footprint_inside || obstacle_inside)
        })
}

/// Whether the goal's cell can be reached from the start's by a point moving through open
/// cells: side moves, and diagonal moves through a corner when one of the two cells beside it
/// is open (a point needs no more). Poses in metres, cells `res` wide, y up from the bottom.
fn cells_connect(grid: &RefGrid, res: f64, start: &[f64], goal: &[f64]) -> bool {
    let cell = |p: &[f64]| ((p[0] / res).floor() as i64, (p[1] / res).floor() as i64);
    let open = |(i, j): (i64, i64)| blocked(grid, i, j) == Some(false);
    let (from, to) = (cell(start), cell(goal));
    if !open(from) || !open(to) {
        return false;
    }
    let index = |(i, j): (i64, i64)| j as usize * grid.width + i as usize;
    let mut seen = vec![false; grid.width * grid.height];
    seen[index(from)] = true;
    let mut queue = VecDeque::from([from]);
    while let Some((i, j)) = queue.pop_front() {
        if (i, j) == to {
            return true;
        }
        for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)] {
            let next = (i + di, j + dj);
            let diagonal = di != 0 && dj != 0;
            if !open(next) || (diagonal && !open((i + di, j)) && !open((i, j + dj))) || seen[index(next)] {
                continue;
            }
            seen[index(next)] = true;
            queue.push_back(next);
        }
    }
    false
}

/// Which world a Hybrid A* document planned on.
pub enum CarWorld<'a> {
    /// A grid, read by the reference.
    Grid(&'a RefGrid),
    /// A polygon world.
    Polygons(&'a PolygonWorld),
}

/// Checks the result of a Hybrid A* problem that `solve` accepted.
pub fn check_result(problem: &ProblemSpec, spec: &HybridSpec, world: CarWorld<'_>, result: &SolveResult) {
    let free = |pose: &[f64]| match world {
        CarWorld::Grid(grid) => grid_pose_free(grid, spec, pose),
        CarWorld::Polygons(w) => polygon_pose_free(w, spec, pose),
    };
    if let (Some(most), Some(done)) = (spec.max_expansions, result.stats.expansions) {
        assert!(done <= most, "{done} expansions past the limit of {most}");
    }
    match result.status {
        Status::Solved => {
            assert!(result.stats.stop.is_none(), "solved, yet stopped by {:?}", result.stats.stop)
        }
        Status::Approximate => panic!("hybrid_astar gave an approximate path"),
        Status::NoPath | Status::Stopped => {
            assert!(
                result.path.is_empty() && result.cost.is_none(),
                "{:?} with a path or cost",
                result.status
            );
        }
    }
    match (result.status, result.stats.stop) {
        // Nothing proved: the limit or the lattice that ended the search is named.
        (Status::Stopped, Some(Stop::LatticeExhausted | Stop::ExpansionLimit | Stop::TimeLimit)) => return,
        (Status::Stopped, stop) => panic!("stopped with the stop {stop:?}"),
        (Status::NoPath, Some(stop)) => panic!("no_path (a proof) named the stop {stop:?}"),
        (Status::NoPath, None) => {
            // A point on a grid: no_path holds only when no chain of open cells joins the ends.
            if let (CarWorld::Grid(grid), None) = (&world, &spec.footprint) {
                assert!(
                    !cells_connect(grid, cell_width(spec), &problem.start, &problem.goal),
                    "no_path, but open cells join the start {:?} to the goal {:?}",
                    problem.start,
                    problem.goal
                );
            }
            return;
        }
        _ => {}
    }
    let poses: Vec<&[f64]> = result
        .path
        .iter()
        .map(|w| match w {
            Waypoint::Point(p) if p.len() == 3 => p.as_slice(),
            other => panic!("a car path holds {other:?}"),
        })
        .collect();
    // Headings compared by their sines and cosines: a heading of 1e306 is a direction too, and
    // the difference of two such numbers says nothing about it. Positions to the tolerance, or
    // to a billionth of the largest length at play (coarse cells reach 1e4 m a cell).
    let scale = [problem.start[0], problem.start[1], problem.goal[0], problem.goal[1], spec.turning_radius]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let near = TOLERANCE.max(1e-9 * scale);
    let same = |p: &[f64], q: &[f64]| {
        let ((sp, cp), (sq, cq)) = (p[2].sin_cos(), q[2].sin_cos());
        (p[0] - q[0]).hypot(p[1] - q[1]) < near && (sp - sq).hypot(cp - cq) < TOLERANCE
    };
    assert!(poses.first().is_some_and(|p| same(p, &problem.start)), "the path does not start at the start");
    assert!(poses.last().is_some_and(|p| same(p, &problem.goal)), "the path does not end at the goal");
    for pose in &poses {
        assert!(free(pose), "the footprint at {pose:?} touches an obstacle");
    }
    let car = result.stats.car.as_ref().expect("a solved car path without its record");
    let straight = (problem.goal[0] - problem.start[0]).hypot(problem.goal[1] - problem.start[1]);
    assert!(car.length >= straight * (1.0 - 1e-9), "length {} below the straight {straight}", car.length);
    assert!(car.reverse_length <= car.length * (1.0 + 1e-12), "more in reverse than in all");
    // Every metre costs at least the cheapest cell's price (1 on a polygon world).
    let least = match world {
        CarWorld::Grid(grid) => {
            grid.costs.iter().copied().filter(|c| c.is_finite()).fold(f64::INFINITY, f64::min)
        }
        CarWorld::Polygons(_) => 1.0,
    };
    let cost = result.cost.expect("a solved result without a cost");
    assert!(
        cost >= car.length * least * (1.0 - 1e-9),
        "cost {cost} below the length {} at {least}",
        car.length
    );
}

#[cfg(test)]
mod tests {
    use trailmark::solve::{PlannerSpec, solve};

    use super::*;

    fn lot(goal: &str) -> ProblemSpec {
        serde_json::from_str(&format!(
            r#"{{"world": {{"polygons": {{"bounds": [0, 0, 12, 8],
                  "obstacles": [[[1, 0.5], [5, 0.5], [5, 2.3], [1, 2.3]], [[7.4, 0.5], [11, 0.5], [11, 2.3], [7.4, 2.3]]]}}}},
                "start": [2, 5, 0], "goal": {goal},
                "planner": {{"name": "hybrid_astar", "turning_radius": 1.2, "max_expansions": 20000,
                            "footprint": [[-0.2, -0.4], [1.0, -0.4], [1.0, 0.4], [-0.2, 0.4]]}}}}"#
        ))
        .unwrap()
    }

    #[test]
    fn a_solved_lot_passes_and_a_pose_in_a_car_fails() {
        let problem = lot("[6.2, 1.2, 1.5707963267948966]");
        assert!(crate::budget::problem_is_quick(&problem));
        crate::solve_and_check(&problem);
        let PlannerSpec::HybridAStar(spec) = &problem.planner else { unreachable!() };
        let trailmark::solve::WorldSpec::Polygons(world) = &problem.world else { unreachable!() };
        assert!(polygon_pose_free(world, spec, &[6.2, 1.2, 1.0]));
        // Inside a parked car, across its edge, and past the bounds.
        assert!(!polygon_pose_free(world, spec, &[3.0, 1.4, 0.0]));
        assert!(!polygon_pose_free(world, spec, &[4.5, 2.5, -1.0]));
        assert!(!polygon_pose_free(world, spec, &[11.5, 6.0, 0.0]));
        let mut result = solve(&problem, ".").unwrap();
        result.path.insert(1, Waypoint::Point(vec![3.0, 1.4, 0.0]));
        let caught = std::panic::catch_unwind(|| {
            check_result(&problem, spec, CarWorld::Polygons(world), &result);
        });
        assert!(caught.is_err(), "a pose inside a parked car passed");
    }

    #[test]
    fn a_grid_pose_on_a_blocked_cell_fails() {
        let problem: ProblemSpec = serde_json::from_str(
            r#"{"world": {"grid": {"rows": ["....", ".@..", "...."]}}, "start": [0.5, 0.5, 0], "goal": [3.5, 2.5, 0],
                "planner": {"name": "hybrid_astar", "turning_radius": 0.5, "max_expansions": 1000}}"#,
        )
        .unwrap();
        let grid = RefGrid::from_world(match &problem.world {
            trailmark::solve::WorldSpec::Grid(w) => w,
            _ => unreachable!(),
        })
        .unwrap();
        let PlannerSpec::HybridAStar(spec) = &problem.planner else { unreachable!() };
        // Row 1 from the top is row 1 from the bottom of a 3-row grid; its column 1 is blocked.
        assert!(!grid_pose_free(&grid, spec, &[1.5, 1.5, 0.0]));
        assert!(grid_pose_free(&grid, spec, &[2.5, 1.5, 0.0]));
        crate::solve_and_check(&problem);
    }

    fn grid_problem(rows: &[&str], start: [f64; 3], goal: [f64; 3], planner: &str) -> ProblemSpec {
        serde_json::from_value(serde_json::json!({
            "world": {"grid": {"rows": rows}}, "start": start, "goal": goal,
            "planner": serde_json::from_str::<serde_json::Value>(planner).unwrap(),
        }))
        .unwrap()
    }

    fn parts(problem: &ProblemSpec) -> (RefGrid, &HybridSpec) {
        let trailmark::solve::WorldSpec::Grid(world) = &problem.world else { unreachable!() };
        let PlannerSpec::HybridAStar(spec) = &problem.planner else { unreachable!() };
        (RefGrid::from_world(world).unwrap(), spec)
    }

    fn panics(f: impl FnOnce() + std::panic::UnwindSafe) -> bool {
        std::panic::catch_unwind(f).is_err()
    }

    #[test]
    fn containment_and_closed_squares() {
        let square = |x0: f64, y0: f64, x1: f64, y1: f64| {
            vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
        };
        let ahead = square(0.5, -0.5, 1.5, 0.5);
        assert!(!polygon_holds(&ahead, Point::origin()));
        assert!(polygon_holds(&square(-1.0, -0.5, 1.0, 0.5), Point::origin()));
        // On an edge and at a vertex: held (closed).
        assert!(polygon_holds(&square(0.0, -0.5, 1.0, 0.5), Point::origin()));
        assert!(polygon_holds(&square(0.0, 0.0, 1.0, 1.0), Point::origin()));
        // A thin triangle pointing at x = 10: its tip region, but not beside it.
        let thin = [Point::new(0.0, -0.1), Point::new(10.0, 0.0), Point::new(0.0, 0.1)];
        assert!(polygon_holds(&thin, Point::new(9.0, 0.0)));
        assert!(!polygon_holds(&thin, Point::new(9.0, 0.05)));
        // A square touching the cell [2, 3] x [0, 1] at its edge or corner meets it; apart, not.
        assert!(polygon_meets_square(&square(1.0, 0.0, 2.0, 1.0), (2.0, 0.0, 3.0, 1.0)));
        assert!(polygon_meets_square(&square(1.0, 1.0, 2.0, 2.0), (2.0, 0.0, 3.0, 1.0)));
        assert!(!polygon_meets_square(&square(1.0, 1.0, 1.9, 2.0), (2.0, 0.0, 3.0, 1.0)));
        // The cell inside the polygon, and the polygon inside the cell.
        assert!(polygon_meets_square(&square(0.0, -1.0, 5.0, 2.0), (2.0, 0.0, 3.0, 1.0)));
        assert!(polygon_meets_square(&square(2.2, 0.2, 2.4, 0.4), (2.0, 0.0, 3.0, 1.0)));
        // The thin triangle's edge across a cell none of its vertices is in.
        assert!(polygon_meets_square(&thin, (4.0, 0.0, 5.0, 1.0)));
    }

    #[test]
    fn a_point_on_the_edge_of_a_blocked_cell_touches_it() {
        let problem = grid_problem(
            &["...", ".@.", "..."],
            [0.5, 0.5, 0.0],
            [2.5, 2.5, 0.0],
            r#"{"name": "hybrid_astar", "turning_radius": 1, "max_expansions": 100}"#,
        );
        let (grid, spec) = parts(&problem);
        // The blocked cell spans [1, 2] x [1, 2].
        assert!(grid_pose_free(&grid, spec, &[0.99, 1.5, 0.0]));
        assert!(!grid_pose_free(&grid, spec, &[1.0, 1.5, 0.0]));
        assert!(!grid_pose_free(&grid, spec, &[2.0, 2.0, 0.0]));
        assert!(grid_pose_free(&grid, spec, &[2.01, 2.01, 0.0]));
        assert!(!grid_pose_free(&grid, spec, &[3.01, 1.0, 0.0]), "off the grid");
    }

    #[test]
    fn an_offset_footprint_over_an_obstacle_cell_passes() {
        // The reference point starts over the blocked cell (1, 1); the square ahead of it, 1 m
        // to 1.8 m in front, is on open cells and drives to the goal.
        let rows = ["..........", "..........", ".@........", ".........."];
        let planner = r#"{"name": "hybrid_astar", "turning_radius": 2, "max_expansions": 2000,
                         "footprint": [[1.0, -0.4], [1.8, -0.4], [1.8, 0.4], [1.0, 0.4]]}"#;
        let problem = grid_problem(&rows, [1.5, 1.5, 0.0], [6.5, 1.5, 0.0], planner);
        let (grid, spec) = parts(&problem);
        assert!(!polygon_holds(&local_polygon(spec).unwrap(), Point::origin()));
        assert!(!grid_point_free(&grid, 1.0, Point::new(1.5, 1.5)), "the reference point is over the wall");
        assert!(grid_pose_free(&grid, spec, &[1.5, 1.5, 0.0]));
        // Backed up until the square covers the blocked cell.
        assert!(!grid_pose_free(&grid, spec, &[0.5, 1.5, 0.0]));
        assert!(crate::budget::problem_is_quick(&problem));
        let result = solve(&problem, ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{result:?}");
        check_result(&problem, spec, CarWorld::Grid(&grid), &result);
        // Moved back onto the blocked cell, it fails.
        let mut wrong = result.clone();
        wrong.path.insert(1, Waypoint::Point(vec![0.5, 1.5, 0.0]));
        assert!(panics(|| check_result(&problem, spec, CarWorld::Grid(&grid), &wrong)));
    }

    #[test]
    fn an_edge_across_a_blocked_cell_between_open_corners_fails() {
        // A 3 m bar, its reference point at its back edge; the blocked cell (4, 1).
        let rows = [".........", ".........", ".........", "....@....", "........."];
        let planner = r#"{"name": "hybrid_astar", "turning_radius": 2, "max_expansions": 2000,
                         "footprint": [[0, -0.1], [3, -0.1], [3, 0.1], [0, 0.1]]}"#;
        let problem = grid_problem(&rows, [1.5, 3.5, 0.0], [4.5, 3.5, 0.0], planner);
        let (grid, spec) = parts(&problem);
        let across = [2.5, 1.5, 0.0];
        // Its corners (x 2.5 and 5.5, y 1.4 and 1.6) and its reference point are on open cells:
        // the cells under them alone (the old check) let it pass.
        let corners = placed(&local_polygon(spec).unwrap(), &across);
        assert!(corners.iter().chain([&Point::new(2.5, 1.5)]).all(|&p| grid_point_free(&grid, 1.0, p)));
        assert!(!grid_pose_free(&grid, spec, &across));
        assert!(grid_pose_free(&grid, spec, &[2.5, 3.5, 0.0]));
        let result = solve(&problem, ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{result:?}");
        check_result(&problem, spec, CarWorld::Grid(&grid), &result);
        let mut wrong = result.clone();
        wrong.path.insert(1, Waypoint::Point(across.to_vec()));
        assert!(panics(|| check_result(&problem, spec, CarWorld::Grid(&grid), &wrong)));
    }

    #[test]
    fn no_path_is_checked_by_the_cells_and_stopped_must_say_why() {
        let planner =
            r#"{"name": "hybrid_astar", "turning_radius": 1, "max_expansions": 3000, "resolution": 0.5}"#;
        // A wall across: proved unreachable, and the search over the cells agrees.
        let walled =
            grid_problem(&["..@..", "..@..", "..@.."], [0.25, 0.25, 0.0], [2.25, 1.25, 0.0], planner);
        let (grid, spec) = parts(&walled);
        assert!(!cells_connect(&grid, 0.5, &walled.start, &walled.goal));
        let result = solve(&walled, ".").unwrap();
        assert_eq!(result.status, Status::NoPath, "{result:?}");
        check_result(&walled, spec, CarWorld::Grid(&grid), &result);
        // A gap at a corner cell: connected (y up: the gap is the top row's).
        let gap = grid_problem(&[".....", "..@..", "..@.."], [0.25, 0.25, 0.0], [2.25, 0.25, 0.0], planner);
        let (grid, spec) = parts(&gap);
        assert!(cells_connect(&grid, 0.5, &gap.start, &gap.goal));
        let result = solve(&gap, ".").unwrap();
        check_result(&gap, spec, CarWorld::Grid(&grid), &result);
        // A no_path the cells disprove, and a stop that names no reason, fail.
        let mut fake = result.clone();
        (fake.status, fake.cost, fake.stats.stop, fake.stats.car) = (Status::NoPath, None, None, None);
        fake.path.clear();
        assert!(panics(|| check_result(&gap, spec, CarWorld::Grid(&grid), &fake)));
        let mut silent = fake.clone();
        silent.status = Status::Stopped;
        assert!(panics(|| check_result(&gap, spec, CarWorld::Grid(&grid), &silent)));
        let mut stopped = silent.clone();
        stopped.stats.stop = Some(Stop::ExpansionLimit);
        check_result(&gap, spec, CarWorld::Grid(&grid), &stopped);
        // Diagonal cells touching at a corner only, both others blocked: not connected.
        let pinched = grid_problem(&["@.", ".@"], [0.25, 0.25, 0.0], [0.75, 0.75, 0.0], planner);
        let (grid, _) = parts(&pinched);
        assert!(!cells_connect(&grid, 0.5, &pinched.start, &pinched.goal));
    }

    #[test]
    fn an_offset_footprint_on_a_polygon_world_may_have_its_reference_point_over_an_obstacle() {
        let problem: ProblemSpec = serde_json::from_str(
            r#"{"world": {"polygons": {"bounds": [0, 0, 10, 4], "obstacles": [[[0.5, 1], [1.5, 1], [1.5, 2], [0.5, 2]]]}},
                "start": [1, 1.5, 0], "goal": [5, 1.5, 0],
                "planner": {"name": "hybrid_astar", "turning_radius": 1.5, "max_expansions": 3000, "resolution": 0.1,
                            "footprint": [[1, -0.3], [1.6, -0.3], [1.6, 0.3], [1, 0.3]]}}"#,
        )
        .unwrap();
        let PlannerSpec::HybridAStar(spec) = &problem.planner else { unreachable!() };
        let trailmark::solve::WorldSpec::Polygons(world) = &problem.world else { unreachable!() };
        assert!(polygon_pose_free(world, spec, &[1.0, 1.5, 0.0]));
        assert!(!polygon_pose_free(world, spec, &[0.0, 1.5, 0.0]));
        let result = solve(&problem, ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{result:?}");
        check_result(&problem, spec, CarWorld::Polygons(world), &result);
    }
}
