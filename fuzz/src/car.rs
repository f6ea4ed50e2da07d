//! Hybrid A* documents on grid and polygon worlds: a solved path starts at the start pose and
//! ends at the goal pose, every pose it lists keeps the footprint free by a test written here
//! (on grids: the cells under the footprint's corners and reference point open; on polygon
//! worlds: the footprint inside the bounds and apart from every obstacle), its length is at least
//! the straight distance, its cost at least its length at the cheapest cell's price; no path
//! means an empty one.

use trailmark::solve::{HybridSpec, ProblemSpec, SolveResult, Status, Waypoint};
use trailmark_core::geometry::Point;
use trailmark_core::world::PolygonWorld;

use crate::grid::RefGrid;

/// The tolerance of positions and headings compared.
const TOLERANCE: f64 = 1e-6;

/// The footprint's outline at a pose `[x, y, heading]`: the planner's polygon moved there, or
/// the reference point alone.
fn outline(spec: &HybridSpec, pose: &[f64]) -> Vec<Point> {
    let (s, c) = pose[2].sin_cos();
    let at = |x: f64, y: f64| Point::new(pose[0] + c * x - s * y, pose[1] + s * x + c * y);
    let mut points: Vec<Point> = spec.footprint.iter().flatten().map(|p| at(p[0], p[1])).collect();
    points.push(at(0.0, 0.0));
    points
}

/// Whether a grid world's pose keeps the cells under its outline open (cells `resolution` wide,
/// y up from the bottom row).
fn grid_pose_free(grid: &RefGrid, spec: &HybridSpec, pose: &[f64]) -> bool {
    let res = spec.resolution.unwrap_or(1.0);
    outline(spec, pose).iter().all(|p| {
        let (i, j) = ((p.x / res).floor(), (p.y / res).floor());
        let inside = i >= 0.0 && j >= 0.0 && i < grid.width as f64 && j < grid.height as f64;
        inside && grid.costs[(grid.height - 1 - j as usize) * grid.width + i as usize].is_finite()
    })
}

fn orient(p: Point, q: Point, r: Point) -> f64 {
    (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)
}

/// Whether the closed segments `a`-`b` and `c`-`d` cross properly.
fn cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    orient(c, d, a) * orient(c, d, b) < 0.0 && orient(a, b, c) * orient(a, b, d) < 0.0
}

/// Whether a polygon world's pose keeps the footprint in the bounds and off the obstacles: a
/// disc of the world's radius about the reference point, or the planner's polygon (no edge of it
/// crossing an obstacle's, no vertex of either inside the other).
fn polygon_pose_free(world: &PolygonWorld, spec: &HybridSpec, pose: &[f64]) -> bool {
    let (lo, hi) = (world.bounds().min(), world.bounds().max());
    let centre = Point::new(pose[0], pose[1]);
    let Some(corners) = spec.footprint.as_ref().map(|_| outline(spec, pose)) else {
        return world.reference_is_clear(centre, TOLERANCE)
            && centre.x - lo.x >= world.robot_radius() - TOLERANCE
            && hi.x - centre.x >= world.robot_radius() - TOLERANCE
            && centre.y - lo.y >= world.robot_radius() - TOLERANCE
            && hi.y - centre.y >= world.robot_radius() - TOLERANCE;
    };
    let n = corners.len() - 1; // the last is the reference point
    let in_bounds = corners.iter().all(|c| c.x >= lo.x && c.y >= lo.y && c.x <= hi.x && c.y <= hi.y);
    in_bounds
        && world.obstacles().iter().all(|o| {
            let v = o.vertices();
            let crossing = (0..n).any(|k| {
                let (a, b) = (corners[k], corners[(k + 1) % n]);
                (0..v.len()).any(|m| cross(a, b, v[m], v[(m + 1) % v.len()]))
            });
            let footprint_inside = corners.iter().any(|&c| o.contains_strictly(c));
            let obstacle_inside = trailmark_core::world::Polygon::new(corners[..n].to_vec())
                .is_ok_and(|f| v.iter().any(|&p| f.contains_strictly(p)));
            !(crossing || footprint_inside || obstacle_inside)
        })
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
    if result.status != Status::Solved {
        assert!(result.path.is_empty() && result.cost.is_none(), "{:?} with a path or cost", result.status);
        return;
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
    // the difference of two such numbers says nothing about it.
    let same = |p: &[f64], q: &[f64]| {
        let ((sp, cp), (sq, cq)) = (p[2].sin_cos(), q[2].sin_cos());
        (p[0] - q[0]).hypot(p[1] - q[1]) < TOLERANCE && (sp - sq).hypot(cp - cq) < TOLERANCE
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
}
