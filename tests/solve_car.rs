//! Hybrid A* through problem documents: a ROS-map world, poses `[x, y, heading]`, the path's
//! poses, length and cusps in the result, the footprint in the picture; bad documents give typed
//! errors.

use trailmark::car::CarError;
use trailmark::solve::{DocumentError, ProblemSpec, SolveError, Status, Waypoint, solve, solve_and_draw};

const EXAMPLES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/problems");

fn office(start: &str, goal: &str, planner: &str) -> ProblemSpec {
    let json = format!(
        r#"{{"world": {{"ros_map": {{"yaml": "../maps/office.yaml", "inflation_radius": 0.5}}}},
             "start": {start}, "goal": {goal}, "planner": {{"name": "hybrid_astar", {planner}}}}}"#
    );
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

const CAR: &str =
    r#""turning_radius": 0.5, "footprint": [[-0.15, -0.2], [0.45, -0.2], [0.45, 0.2], [-0.15, 0.2]]"#;

#[test]
fn a_car_crosses_the_office_to_an_exact_pose() {
    let problem = office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 3.0]", CAR);
    let (result, svg) = solve_and_draw(&problem, EXAMPLES).unwrap();
    assert_eq!(result.status, Status::Solved);
    let last = match result.path.last() {
        Some(Waypoint::Point(p)) => p.clone(),
        other => panic!("{other:?}"),
    };
    assert!((last[0] - 4.3).abs() < 1e-6 && (last[1] - 2.3).abs() < 1e-6);
    let turn = (last[2] - 3.0).rem_euclid(std::f64::consts::TAU);
    assert!(turn.min(std::f64::consts::TAU - turn) < 1e-6);
    let car = result.stats.car.expect("the car's record");
    // At least the straight line between the ends.
    assert!(car.length >= (8.5f64).hypot(4.5) - 1e-9);
    assert!(car.reverse_length <= car.length);
    assert!(result.cost.unwrap() >= car.length);
    assert!(result.stats.expansions.unwrap() > 0);
    // The footprint is drawn along the path.
    assert!(svg.matches("<polygon").count() > 10, "{}", svg.len());
}

#[test]
fn documents_name_what_is_wrong() {
    let err = |problem: ProblemSpec| solve(&problem, EXAMPLES).expect_err("an error");
    // A pose without a heading.
    match err(office("[-4.2, -2.2]", "[4.3, 2.3, 0.0]", CAR)) {
        SolveError::Document(DocumentError::NotAPoint { which: "start", .. }) => {}
        other => panic!("{other:?}"),
    }
    let mut infinite = office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", CAR);
    infinite.goal[2] = f64::INFINITY;
    match err(infinite) {
        SolveError::Document(DocumentError::NotAPoint { which: "goal", .. }) => {}
        other => panic!("{other:?}"),
    }
    // Settings out of range.
    for planner in [r#""turning_radius": 0"#, r#""turning_radius": 0.5, "heading_bins": 0"#] {
        match err(office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", planner)) {
            SolveError::Car(CarError::Setting { .. }) => {}
            other => panic!("{planner}: {other:?}"),
        }
    }
    // A footprint that is not a simple polygon.
    let bow = r#""turning_radius": 0.5, "footprint": [[0, 0], [0.4, 0.4], [0.4, 0], [0, 0.4]]"#;
    match err(office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", bow)) {
        SolveError::Document(DocumentError::Footprint(_)) => {}
        other => panic!("{other:?}"),
    }
    // A start on a wall.
    match err(office("[-5.0, -3.0, 0.0]", "[4.3, 2.3, 0.0]", CAR)) {
        SolveError::Car(CarError::InCollision { which: "start", .. }) => {}
        other => panic!("{other:?}"),
    }
    // Hybrid A* plans on ROS maps, not on grids of cells.
    let grid: ProblemSpec = serde_json::from_str(
        r#"{"world": {"grid": {"rows": ["....", "...."]}}, "start": [0, 0], "goal": [3, 1],
            "planner": {"name": "hybrid_astar", "turning_radius": 1}}"#,
    )
    .unwrap();
    match err(grid) {
        SolveError::Document(DocumentError::NotAGraphSearch { planner: "hybrid_astar" }) => {}
        other => panic!("{other:?}"),
    }
}
