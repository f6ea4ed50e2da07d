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
        e @ SolveError::Document(DocumentError::NotAPose {
            which: "start", planner: "hybrid_astar", ..
        }) => {
            assert!(e.to_string().contains("expects [x, y, heading]"), "{e}");
        }
        other => panic!("{other:?}"),
    }
    let mut infinite = office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", CAR);
    infinite.goal[2] = f64::INFINITY;
    match err(infinite) {
        SolveError::Document(DocumentError::NotAPose { which: "goal", .. }) => {}
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
    // The resolution of a ROS map is its YAML's.
    let fine = format!("{CAR}, \"resolution\": 0.01");
    match err(office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", &fine)) {
        SolveError::Document(DocumentError::NotForRosMaps { field: "resolution" }) => {}
        other => panic!("{other:?}"),
    }
    // A roadmap's field.
    let mut roadmap = office("[-4.2, -2.2, 0.0]", "[4.3, 2.3, 0.0]", CAR);
    roadmap.samples = Some(100);
    match err(roadmap) {
        SolveError::Document(DocumentError::NotForPlanner { field: "samples", planner: "hybrid_astar" }) => {}
        other => panic!("{other:?}"),
    }
    // A polygon world's robot radius beside a footprint; a resolution that is not one; a box
    // world.
    let polygons = |world: &str, planner: &str| -> ProblemSpec {
        let json = format!(
            r#"{{"world": {{"polygons": {{"bounds": [0, 0, 10, 6], "obstacles": [], {world}}}}},
                 "start": [1, 1, 0], "goal": [8, 4, 0], "planner": {{"name": "hybrid_astar", {planner}}}}}"#
        );
        serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
    };
    match err(polygons(r#""robot_radius": 0.3"#, CAR)) {
        SolveError::Document(DocumentError::RadiusAndFootprint) => {}
        other => panic!("{other:?}"),
    }
    for resolution in ["0", "-1", "1e-300"] {
        let planner = format!(r#""turning_radius": 1, "resolution": {resolution}"#);
        match err(polygons(r#""robot_radius": 0.3"#, &planner)) {
            SolveError::Car(CarError::Map(_) | CarError::Setting { setting: "resolution", .. }) => {}
            other => panic!("{resolution}: {other:?}"),
        }
    }
    let boxes: ProblemSpec = serde_json::from_str(
        r#"{"world": {"boxes": {"bounds": [[0, 4], [0, 4], [0, 4]]}}, "start": [1, 1, 1], "goal": [3, 3, 3],
            "planner": {"name": "hybrid_astar", "turning_radius": 1}}"#,
    )
    .unwrap();
    match err(boxes) {
        SolveError::Document(DocumentError::InvalidBoxes(why)) if why.contains("hybrid_astar") => {}
        other => panic!("{other:?}"),
    }
}

/// The pose a result ends at.
fn last_pose(path: &[Waypoint]) -> [f64; 3] {
    match path.last() {
        Some(Waypoint::Point(p)) => [p[0], p[1], p[2]],
        other => panic!("{other:?}"),
    }
}

/// Whether two headings agree within `tolerance` radians.
fn same_heading(a: f64, b: f64, tolerance: f64) -> bool {
    let turn = (a - b).rem_euclid(std::f64::consts::TAU);
    turn.min(std::f64::consts::TAU - turn) < tolerance
}

#[test]
fn a_car_turns_around_in_a_grid_world() {
    // A 30 x 12 grid of 0.5 m cells, a wall down the middle from the top leaving a 2 m gap at
    // the bottom; the car starts facing up on the left and must end facing up on the right.
    let mut rows = vec![".".repeat(30); 12];
    for row in rows.iter_mut().take(8) {
        row.replace_range(14..16, "@@");
    }
    let json = format!(
        r#"{{"world": {{"grid": {{"rows": {rows:?}}}}}, "start": [3, 4, 1.5707963267948966],
             "goal": [12, 4, 1.5707963267948966],
             "planner": {{"name": "hybrid_astar", "turning_radius": 1.0, "resolution": 0.5,
                         "footprint": [[-0.3, -0.3], [0.6, -0.3], [0.6, 0.3], [-0.3, 0.3]]}}}}"#
    );
    let problem: ProblemSpec = serde_json::from_str(&json).unwrap();
    let (result, svg) = solve_and_draw(&problem, EXAMPLES).unwrap();
    assert_eq!(result.status, Status::Solved);
    let [x, y, heading] = last_pose(&result.path);
    assert!((x - 12.0).abs() < 1e-6 && (y - 4.0).abs() < 1e-6, "{x} {y}");
    assert!(same_heading(heading, std::f64::consts::FRAC_PI_2, 1e-6));
    // Through the gap at the bottom (y below 2 m), at least twice the wall's distance.
    let car = result.stats.car.expect("the car's record");
    assert!(car.length >= 9.0, "{}", car.length);
    let lowest = result
        .path
        .iter()
        .filter_map(|w| match w {
            Waypoint::Point(p) => Some(p[1]),
            Waypoint::Cell(_) => None,
        })
        .fold(f64::INFINITY, f64::min);
    assert!(lowest < 2.0, "{lowest}");
    assert!(svg.contains("<polygon") && svg.contains("<polyline"));
}

#[test]
fn a_start_at_the_goal_is_a_path_of_one_pose() {
    let problem: ProblemSpec = serde_json::from_str(
        r#"{"world": {"grid": {"rows": ["........"]}}, "start": [4.8, 0.6, 2.35], "goal": [4.8, 0.6, 2.35],
            "planner": {"name": "hybrid_astar", "turning_radius": 1.2}}"#,
    )
    .unwrap();
    let result = solve(&problem, EXAMPLES).unwrap();
    assert_eq!(result.status, Status::Solved);
    assert_eq!(result.path, vec![Waypoint::Point(vec![4.8, 0.6, 2.35])]);
    let car = result.stats.car.expect("the car's record");
    assert!(car.length == 0.0 && car.length.is_sign_positive() && car.cusps.is_empty());
}

#[test]
fn a_car_parks_between_polygons() {
    // Two parked cars 2.4 m apart along the bottom of a 12 x 8 lot; the car backs in between
    // them, facing out.
    let json = r#"{"world": {"polygons": {"bounds": [0, 0, 12, 8],
                    "obstacles": [[[1, 0.5], [5, 0.5], [5, 2.3], [1, 2.3]], [[7.4, 0.5], [11, 0.5], [11, 2.3], [7.4, 2.3]]]}},
                   "start": [2, 5.5, 0], "goal": [6.2, 1.2, 1.5707963267948966],
                   "planner": {"name": "hybrid_astar", "turning_radius": 1.2,
                               "footprint": [[-0.2, -0.4], [1.0, -0.4], [1.0, 0.4], [-0.2, 0.4]]}}"#;
    let problem: ProblemSpec = serde_json::from_str(json).unwrap();
    let (result, svg) = solve_and_draw(&problem, EXAMPLES).unwrap();
    assert_eq!(result.status, Status::Solved);
    let [x, y, heading] = last_pose(&result.path);
    assert!((x - 6.2).abs() < 1e-6 && (y - 1.2).abs() < 1e-6);
    assert!(same_heading(heading, std::f64::consts::FRAC_PI_2, 1e-6));
    let car = result.stats.car.expect("the car's record");
    assert!(car.length >= (4.2f64).hypot(4.3) - 1e-9);
    // Facing out of the bay at the end, it must have reversed into it.
    assert!(car.reverse_length > 0.0 && !car.cusps.is_empty());
    // The world's obstacles, the footprints and the path are drawn.
    assert!(svg.matches("<polygon").count() > 5 && svg.contains("<polyline"));
}
