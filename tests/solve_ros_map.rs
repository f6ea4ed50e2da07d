//! ROS-map worlds through problem documents: every grid planner and Theta* on the example office
//! map and on the Nav2 warehouse map (when `../shared/rosmaps` is present). Paths are in metres;
//! every point along every segment, sampled every centimetre, lies in a cell the robot may occupy
//! (below the inscribed cost); each waypoint maps back to a cell centre; consecutive waypoints of a
//! grid path are neighbouring cells; A*, Dijkstra, LPA* and D* Lite agree on the least cost and
//! Theta* never costs more; every smoothing method keeps the path on cells below a chosen cost.
//! Bad documents give typed errors.

use std::path::{Path, PathBuf};

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::core::geometry::Point;
use trailmark::core::grid::Cell;
use trailmark::map::{Costmap, INSCRIBED};
use trailmark::solve::{
    DocumentError, ProblemSpec, SolveError, Status, Waypoint, WorldSpec, ros_costmap, solve,
};

const EXAMPLES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/problems");

fn office(planner: &str, start: [f64; 2], goal: [f64; 2]) -> ProblemSpec {
    let json = format!(
        r#"{{"world": {{"ros_map": {{"yaml": "../maps/office.yaml", "robot_radius": 0.15, "inflation_radius": 0.5}}}},
             "start": [{}, {}], "goal": [{}, {}], "planner": {planner}}}"#,
        start[0], start[1], goal[0], goal[1]
    );
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

fn points(path: &[Waypoint]) -> Vec<Point> {
    path.iter()
        .map(|w| match w {
            Waypoint::Point(p) => Point::new(p[0], p[1]),
            Waypoint::Cell(c) => panic!("a cell {c:?} where metres were expected"),
        })
        .collect()
}

/// Checks a path in metres over `costmap`: every waypoint is a cell centre, every point of every
/// segment (every centimetre) lies in a cell of cost below the inscribed cost, and for a grid
/// path consecutive cells are neighbours. Returns the path's length in metres.
fn check_path(costmap: &Costmap, path: &[Point], any_angle: bool) -> f64 {
    let frame = costmap.frame();
    let cell = |p: Point| frame.try_cell_at(p).unwrap_or_else(|| panic!("{p:?} is outside the map"));
    let mut length = 0.0;
    for (k, &p) in path.iter().enumerate() {
        let c = cell(p);
        assert!((frame.centre(c) - p).norm() < 1e-9, "waypoint {k} {p:?} is not the centre of {c}");
    }
    for pair in path.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let (ca, cb) = (cell(a), cell(b));
        if !any_angle {
            assert!(ca.x.abs_diff(cb.x) <= 1 && ca.y.abs_diff(cb.y) <= 1, "{ca} -> {cb} are not neighbours");
        }
        let d = (b - a).norm();
        length += d;
        let n = (d / 0.01).ceil().max(1.0) as usize;
        for i in 0..=n {
            let p = a + (b - a) * (i as f64 / n as f64);
            let (gx, gy) = frame.point_to_grid(p);
            // Points on a cell boundary belong to two cells: the line may pass between two
            // cells' corners only where the grid's corner rule allows, checked by the planner.
            if (gx - gx.round()).abs() < 1e-9 || (gy - gy.round()).abs() < 1e-9 {
                continue;
            }
            let cost = costmap.cost(cell(p)).unwrap();
            assert!(cost < INSCRIBED, "{p:?} between {a:?} and {b:?} lies in a cell of cost {cost}");
        }
    }
    length
}

fn costmap_of(problem: &ProblemSpec, base: &Path) -> Costmap {
    let WorldSpec::RosMap(world) = &problem.world else { panic!("not a ROS map") };
    ros_costmap(world, base).unwrap()
}

#[test]
fn every_grid_planner_plans_on_the_office_map() {
    let base = PathBuf::from(EXAMPLES);
    let (start, goal) = ([-4.2, -2.2], [4.3, 2.3]);
    let costmap = costmap_of(&office(r#"{"name": "astar"}"#, start, goal), &base);
    let mut costs = Vec::new();
    for planner in [
        r#"{"name": "astar"}"#,
        r#"{"name": "dijkstra"}"#,
        r#"{"name": "lpa_star"}"#,
        r#"{"name": "dstar_lite"}"#,
        r#"{"name": "ara_star", "epsilon": 2.0}"#,
        r#"{"name": "ad_star", "epsilon": 2.0}"#,
        r#"{"name": "weighted_astar", "weight": 1.5}"#,
        r#"{"name": "bfs"}"#,
        r#"{"name": "dfs"}"#,
        r#"{"name": "theta_star"}"#,
    ] {
        let result = solve(&office(planner, start, goal), &base).unwrap();
        assert_eq!(result.status, Status::Solved, "{planner}");
        let path = points(&result.path);
        check_path(&costmap, &path, planner.contains("theta"));
        costs.push((planner, result.cost.unwrap()));
    }
    let least = costs[0].1;
    for (planner, cost) in &costs[..6] {
        assert!((cost - least).abs() <= 1e-9 * least, "{planner}: {cost} against A*'s {least}");
    }
    let theta = costs.last().unwrap().1;
    assert!(theta <= least * (1.0 + 1e-9), "Theta* {theta} above A* {least}");
    // Over free cells a move costs its length in metres: the cost is at least the straight line.
    let straight = (Point::from(goal) - Point::from(start)).norm();
    assert!(theta >= straight - 0.1, "{theta} below the straight line {straight}");
}

#[path = "support/shared_data.rs"]
mod shared_data;

fn data() -> Option<PathBuf> {
    shared_data::shared_data("rosmaps", "the Nav2 example maps")
}

#[test]
fn warehouse_queries_agree_and_stay_clear() {
    let Some(dir) = data() else { return };
    let problem = |planner: &str, s: Point, g: Point| -> ProblemSpec {
        let json = format!(
            r#"{{"world": {{"ros_map": {{"yaml": "warehouse.yaml", "robot_radius": 0.2, "inflation_radius": 0.55,
                 "cost_scaling_factor": 10, "unknown": "lethal"}}}},
                 "start": [{}, {}], "goal": [{}, {}], "planner": {{"name": "{planner}"}}}}"#,
            s.x, s.y, g.x, g.y
        );
        serde_json::from_str(&json).unwrap()
    };
    let costmap = costmap_of(&problem("astar", Point::origin(), Point::origin()), &dir);
    let frame = *costmap.frame();
    let mut rng = ChaCha8Rng::seed_from_u64(26);
    let mut free_point = || loop {
        let cell = Cell::new(rng.random_range(0..frame.width()), rng.random_range(0..frame.height()));
        if costmap.cost(cell).is_some_and(|c| c < INSCRIBED) {
            return frame.centre(cell);
        }
    };
    for _ in 0..4 {
        let (s, g) = (free_point(), free_point());
        let astar = solve(&problem("astar", s, g), &dir).unwrap();
        let dijkstra = solve(&problem("dijkstra", s, g), &dir).unwrap();
        let theta = solve(&problem("theta_star", s, g), &dir).unwrap();
        assert_eq!(astar.status, dijkstra.status);
        assert_eq!(astar.status, theta.status);
        let (Some(a), Some(d), Some(t)) = (astar.cost, dijkstra.cost, theta.cost) else { continue };
        assert!((a - d).abs() <= 1e-9 * d, "A* {a} against Dijkstra {d}");
        assert!(t <= a * (1.0 + 1e-9), "Theta* {t} above A* {a}");
        check_path(&costmap, &points(&astar.path), false);
        check_path(&costmap, &points(&theta.path), true);
    }
}

#[test]
fn smoothed_paths_stay_on_cells_below_the_chosen_cost() {
    use trailmark::core::smooth::{Smoothing, smooth};
    use trailmark::map::{CostmapClearance, TravelCost};
    use trailmark::prelude::*;
    let base = PathBuf::from(EXAMPLES);
    let costmap = costmap_of(&office(r#"{"name": "astar"}"#, [0.0, 0.0], [0.0, 0.0]), &base);
    let frame = *costmap.frame();
    // Keep well clear: only cells below cost 128, a band beyond the inscribed one.
    for below in [INSCRIBED, 128] {
        let graph = GridGraph::new(
            &costmap.to_grid(&TravelCost { blocked_from: below, ..TravelCost::default() }).unwrap(),
            Connectivity::Eight,
        );
        let (s, g) =
            (frame.cell_at(Point::new(-4.2, -2.2)).unwrap(), frame.cell_at(Point::new(4.3, 2.3)).unwrap());
        let path = astar(&graph, s, g, graph.heuristic(GridHeuristic::Octile, g)).unwrap().path.unwrap();
        let corners: Vec<Point> = graph.shortcut(&path.nodes).iter().map(|&c| frame.centre(c)).collect();
        let clear = CostmapClearance::new(&costmap, below);
        for method in Smoothing::ALL {
            let smoothed = smooth(&clear, &corners, method).unwrap();
            assert_eq!(
                (smoothed.start(), smoothed.end()),
                (corners.first().copied(), corners.last().copied())
            );
            for piece in &smoothed.pieces {
                for k in 0..=2000 {
                    let p = piece.point(f64::from(k) / 2000.0);
                    let (gx, gy) = frame.point_to_grid(p);
                    if (gx - gx.round()).abs() < 1e-9 || (gy - gy.round()).abs() < 1e-9 {
                        continue;
                    }
                    let cost = costmap.cost(frame.try_cell_at(p).unwrap()).unwrap();
                    assert!(
                        cost < below,
                        "{method:?}: {p:?} lies in a cell of cost {cost} (must be below {below})"
                    );
                }
            }
        }
    }
}

#[test]
fn bad_documents_are_typed_errors() {
    let base = PathBuf::from(EXAMPLES);
    let astar = r#"{"name": "astar"}"#;
    let err = |p: ProblemSpec| solve(&p, &base).unwrap_err();
    assert!(matches!(
        err(office(astar, [-40.0, 0.0], [4.3, 2.3])),
        SolveError::Document(DocumentError::OutsideMap { which: "start", .. })
    ));
    // The outer walls of the office are 4 cells of unknown (lethal by default) and a wall.
    assert!(matches!(
        err(office(astar, [-4.2, -2.2], [-4.99, 2.3])),
        SolveError::Document(DocumentError::BlockedPoint { which: "goal", cost: 254, .. })
    ));
    let mut p = office(astar, [-4.2, -2.2], [4.3, 2.3]);
    p.start = vec![1.0];
    assert!(matches!(err(p), SolveError::Document(DocumentError::NotAPoint { .. })));
    let mut p = office(astar, [-4.2, -2.2], [4.3, 2.3]);
    if let WorldSpec::RosMap(world) = &mut p.world {
        world.footprint = Some(vec![[0.1, 0.1], [-0.1, 0.1], [-0.1, -0.1]]);
    }
    assert!(matches!(err(p), SolveError::Document(DocumentError::RadiusAndFootprint)));
    let mut p = office(astar, [-4.2, -2.2], [4.3, 2.3]);
    if let WorldSpec::RosMap(world) = &mut p.world {
        world.yaml = "../maps/missing.yaml".into();
    }
    assert!(matches!(err(p), SolveError::RosMap(_)));
    let mut p = office(astar, [-4.2, -2.2], [4.3, 2.3]);
    if let WorldSpec::RosMap(world) = &mut p.world {
        world.inflation_radius = Some(-1.0);
    }
    assert!(matches!(err(p), SolveError::RosMap(_)));
    // A cost factor is named as given, not scaled by the map's resolution.
    for factor in [-1.0, 2e6, f64::NAN] {
        let mut p = office(astar, [-4.2, -2.2], [4.3, 2.3]);
        if let WorldSpec::RosMap(world) = &mut p.world {
            world.cost_factor = Some(factor);
        }
        let message = err(p).to_string();
        assert!(message.contains("cost_factor") && message.contains(&format!("{factor}")), "{message}");
    }
    // Jump point search is for grid worlds of uniform cost: the ROS map is named, not the
    // connectivity it has.
    for jumps in [r#"{"name": "jps"}"#, r#"{"name": "jps_plus"}"#] {
        let message = err(office(jumps, [-4.2, -2.2], [4.3, 2.3])).to_string();
        assert!(message.contains("ROS-map") && !message.contains("\"connectivity\": 8"), "{message}");
    }
    assert!(matches!(
        err(office(r#"{"name": "rrt"}"#, [-4.2, -2.2], [4.3, 2.3])),
        SolveError::Document(DocumentError::NeedsPolygons { .. })
    ));
    let polygons: ProblemSpec = serde_json::from_str(
        r#"{"world": {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": []}},
            "start": [1, 1], "goal": [9, 9], "planner": {"name": "theta_star"}}"#,
    )
    .unwrap();
    assert!(matches!(err(polygons), SolveError::Document(DocumentError::NeedsLines { .. })));
}
