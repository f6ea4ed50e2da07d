//! Sampling planners through problem documents in a robot arm's joint space: the example arm of
//! `examples/problems/robot/`, and the Panda of `../shared/mbm` when present. Every path is
//! re-checked by the scalar sphere checker at a tenth of the planning step and its cost
//! recomputed; a request plans as its joint vectors do; every kind of bad document gives its
//! typed error.

use trailmark::solve::{
    DocumentError, ProblemSpec, SolveError, SolveResult, Status, WorldSpec, solve, solve_and_draw,
};

#[path = "support/results.rs"]
mod results;
use results::{states, without_times};

#[path = "support/shared_data.rs"]
mod shared_data;

/// The folder of the example problems, which the robot documents' paths are relative to.
fn examples() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/problems")
}

/// The example arm among its shelf scene, with `rest`.
fn arm_document(rest: &str) -> ProblemSpec {
    let json = format!(
        r#"{{"world": {{"robot": {{"urdf": "robot/arm.urdf", "srdf": "robot/arm.srdf", "group": "arm"}},
             "scene": "robot/shelf.yaml"}}, {rest}}}"#
    );
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

fn robot_of(problem: &mut ProblemSpec) -> &mut trailmark::solve::RobotWorldSpec {
    match &mut problem.world {
        WorldSpec::Robot(world) => world,
        _ => panic!("not a robot world"),
    }
}

/// The checker a robot path is checked again by, independent of the one planned with: the
/// scalar `f64` sphere checker at a tenth of the planning step.
fn arm_reference(
    dir: &std::path::Path,
    urdf: &str,
    srdf: &str,
    scene: &str,
    group: &str,
    template: Vec<f64>,
) -> trailmark::robot::ArmChecker {
    use trailmark::robot::{ArmChecker, DEFAULT_STEP, Robot, scene::Scene, srdf::Srdf};
    let robot = Robot::from_file(dir.join(urdf)).unwrap();
    let srdf = Srdf::from_file(dir.join(srdf)).unwrap();
    let scene = Scene::from_file(dir.join(scene)).unwrap();
    let group = robot.group(&srdf, group).unwrap();
    ArmChecker::new(robot, &srdf, group, &scene, template, DEFAULT_STEP / 10.0).unwrap()
}

/// Checks that `result` runs from `start` to `goal` through free motions of `reference`, each
/// joint within its limits, and costs the length of its path the short way round a continuous
/// joint.
fn check_arm_path(
    reference: &trailmark::robot::ArmChecker,
    result: &SolveResult,
    start: &[f64],
    goal: &[f64],
) {
    assert_eq!(result.status, Status::Solved, "{result:?}");
    let path = states(result);
    assert_eq!(path.first().map(Vec::as_slice), Some(start));
    assert_eq!(path.last().map(Vec::as_slice), Some(goal));
    let group = reference.group();
    for q in &path {
        for ((v, (low, high)), name) in q.iter().zip(&group.bounds).zip(&group.names) {
            assert!(low <= v && v <= high, "{name} = {v} outside [{low}, {high}]");
        }
    }
    let mut length = 0.0;
    for m in path.windows(2) {
        assert!(reference.motion_is_free(&m[0], &m[1]), "{:?} -> {:?} collides", m[0], m[1]);
        let squared: f64 = m[0]
            .iter()
            .zip(&m[1])
            .zip(&group.wraps)
            .map(|((a, b), &wraps)| {
                let d = (b - a).abs();
                let d = if wraps { d.min(std::f64::consts::TAU - d) } else { d };
                d * d
            })
            .sum();
        length += squared.sqrt();
    }
    let cost = result.cost.expect("a solved path has a cost");
    assert!((cost - length).abs() <= 1e-9 * length.max(1.0), "cost {cost} vs length {length}");
}

#[test]
fn robot_worlds_plan_free_paths_with_either_checker_and_every_sampling_planner() {
    let (start, goal) = ([1.2, 0.6, 1.2, 0.8], [-0.5, 0.9, 0.9, 0.3]);
    let reference = arm_reference(
        &examples(),
        "robot/arm.urdf",
        "robot/arm.srdf",
        "robot/shelf.yaml",
        "arm",
        vec![0.0; 4],
    );
    for planner in [
        "rrt",
        "rrt_connect",
        "rrt_star",
        "informed_rrt_star",
        "bit_star",
        "prm",
        "prm_star",
        "lazy_prm",
        "lazy_prm_star",
    ] {
        for checker in ["batch", "scalar"] {
            for simplify in [false, true] {
                let json = format!(
                    r#"{{"world": {{"robot": {{"urdf": "robot/arm.urdf", "srdf": "robot/arm.srdf", "group": "arm", "checker": "{checker}"}},
                         "scene": "robot/shelf.yaml"}}, "start": {start:?}, "goal": {goal:?}, "seed": 3,
                         "planner": {{"name": "{planner}", "max_iterations": 3000, "simplify": {simplify}}}}}"#
                );
                let problem: ProblemSpec = serde_json::from_str(&json).unwrap();
                let result =
                    solve(&problem, examples()).unwrap_or_else(|e| panic!("{planner} {checker}: {e}"));
                check_arm_path(&reference, &result, &start, &goal);
            }
        }
    }
}

#[test]
fn a_request_gives_the_same_plan_as_its_joint_vectors() {
    let by_vectors = arm_document(
        r#""start": [1.2, 0.6, 1.2, 0.8], "goal": [-0.5, 0.9, 0.9, 0.3],
           "planner": {"name": "rrt_connect", "range": 1.0}, "seed": 7"#,
    );
    let mut by_request = by_vectors.clone();
    (by_request.start, by_request.goal) = (Vec::new(), Vec::new());
    by_request.request = Some("robot/reach.yaml".into());
    let a = without_times(solve(&by_vectors, examples()).unwrap());
    let b = without_times(solve(&by_request, examples()).unwrap());
    assert_eq!(a, b);
    // The document reads back as written, the scene beside the robot.
    let json = serde_json::to_value(&by_request).unwrap();
    assert_eq!(json["world"]["scene"], "robot/shelf.yaml");
    assert_eq!(json["world"]["robot"]["group"], "arm");
    assert_eq!(serde_json::from_value::<ProblemSpec>(json).unwrap(), by_request);
}

#[test]
fn continuous_joints_take_any_turn_and_plan_the_short_way() {
    // The turret's yaw written whole turns away plans as its angle in [-π, π].
    let tau = std::f64::consts::TAU;
    let problem = arm_document(&format!(
        r#""start": [{}, 0.6, 1.2, 0.8], "goal": [{}, 0.9, 0.9, 0.3], "planner": {{"name": "rrt_connect"}}, "seed": 1"#,
        1.2 + 2.0 * tau,
        -0.5 - tau
    ));
    let result = solve(&problem, examples()).unwrap();
    let path = states(&result);
    assert!((path[0][0] - 1.2).abs() < 1e-12 && (path.last().unwrap()[0] + 0.5).abs() < 1e-12, "{path:?}");
}

#[test]
fn bad_robot_documents_give_typed_errors() {
    let error = |problem: &ProblemSpec| solve(problem, examples()).unwrap_err();
    let ends = r#""start": [1.2, 0.6, 1.2, 0.8], "goal": [-0.5, 0.9, 0.9, 0.3]"#;
    let rrt = format!(r#"{ends}, "planner": {{"name": "rrt_connect"}}"#);
    // Both ends and a request.
    let mut both = arm_document(&rrt);
    both.request = Some("robot/reach.yaml".into());
    assert!(matches!(error(&both), SolveError::Document(DocumentError::RequestAndEnds)));
    // A request's group that is not the world's.
    let mut other = arm_document(r#""planner": {"name": "rrt_connect"}"#);
    other.request = Some("robot/reach.yaml".into());
    robot_of(&mut other).robot.group = Some("legs".into());
    assert!(matches!(error(&other), SolveError::Document(DocumentError::GroupMismatch { .. })));
    // No group at all.
    robot_of(&mut other).robot.group = None;
    other.request = None;
    (other.start, other.goal) = (vec![0.0; 4], vec![0.0; 4]);
    assert!(matches!(error(&other), SolveError::Document(DocumentError::NoGroup)));
    // A group the SRDF does not have.
    robot_of(&mut other).robot.group = Some("legs".into());
    assert!(matches!(error(&other), SolveError::Robot(_)), "{}", error(&other));
    // Ends of the wrong length, outside the limits, or missing.
    let short = arm_document(r#""start": [1, 2, 3], "goal": [0, 0, 0, 0], "planner": {"name": "rrt"}"#);
    assert!(matches!(
        error(&short),
        SolveError::Document(DocumentError::NotAState { which: "start", space: "joints", .. })
    ));
    let outside =
        arm_document(r#""start": [0, 1.9, 0, 0], "goal": [0, 0, 0, 0], "planner": {"name": "rrt"}"#);
    assert!(error(&outside).to_string().contains("outside the joint's limits"), "{}", error(&outside));
    let no_goal = arm_document(r#""start": [0, 0, 0, 0], "planner": {"name": "rrt"}"#);
    assert!(matches!(error(&no_goal), SolveError::Document(DocumentError::NoEnd("goal"))));
    // A start in collision (the forearm folded into the table) is the planner's typed error.
    let blocked =
        arm_document(r#""start": [0, 1.6, 0, 0], "goal": [0, 0, 0, 0], "planner": {"name": "rrt"}"#);
    assert!(matches!(error(&blocked), SolveError::Plan(_)), "{}", error(&blocked));
    // Graph searches, Hybrid A*, roadmap and space fields, smoothing and pictures.
    for planner in [r#"{"name": "astar"}"#, r#"{"name": "hybrid_astar", "turning_radius": 1}"#] {
        let problem = arm_document(&format!(r#"{ends}, "planner": {planner}"#));
        assert!(
            matches!(error(&problem), SolveError::Document(DocumentError::RobotNeedsSampling { .. })),
            "{planner}: {}",
            error(&problem)
        );
    }
    for (field, extra) in [("space", r#""space": "rn""#), ("samples", r#""samples": 10"#)] {
        let problem = arm_document(&format!(r#"{rrt}, {extra}"#));
        assert!(error(&problem).to_string().contains(field), "{field}: {}", error(&problem));
    }
    let smoothed = arm_document(&format!(r#"{ends}, "planner": {{"name": "rrt", "smooth": "bezier"}}"#));
    assert!(matches!(
        error(&smoothed),
        SolveError::Document(DocumentError::NotForRobots { field: "smooth" })
    ));
    assert!(matches!(
        solve_and_draw(&arm_document(&rrt), examples()).unwrap_err(),
        SolveError::Document(DocumentError::Undrawable("robot"))
    ));
    // Files that are not there, or not a robot's.
    let mut missing = arm_document(&rrt);
    robot_of(&mut missing).scene = Some("robot/no-such-scene.yaml".into());
    assert!(matches!(error(&missing), SolveError::Robot(trailmark::robot::RobotError::Io { .. })));
    robot_of(&mut missing).scene = None;
    robot_of(&mut missing).robot.urdf = "robot/shelf.yaml".into();
    assert!(matches!(error(&missing), SolveError::Robot(_)));
    // A request beside another kind of world.
    let mut grid: ProblemSpec =
        serde_json::from_str(r#"{"world": {"grid": {"rows": [".."]}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "astar"}}"#)
            .unwrap();
    grid.request = Some("robot/reach.yaml".into());
    assert!(matches!(error(&grid), SolveError::Document(DocumentError::RequestNeedsRobot)));
    // Worlds of two kinds, a scene without its robot, and unknown keys are refused as read.
    for world in [
        r#"{"grid": {"rows": [".."]}, "robot": {"urdf": "a", "srdf": "b"}}"#,
        r#"{"grid": {"rows": [".."]}, "scene": "s.yaml"}"#,
        r#"{"robot": {"urdf": "a", "srdf": "b", "colour": "red"}}"#,
        r#"{"robot": {"urdf": "a", "srdf": "b"}, "scene": "s.yaml", "scene": "t.yaml"}"#,
        r#"{"planet": {}}"#,
        r#"{}"#,
    ] {
        let json =
            format!(r#"{{"world": {world}, "start": [0, 0], "goal": [1, 0], "planner": {{"name": "rrt"}}}}"#);
        assert!(serde_json::from_str::<ProblemSpec>(&json).is_err(), "{world} was read");
    }
}

#[test]
fn panda_requests_plan_as_documents() {
    let Some(mbm) = shared_data::shared_data("mbm", "the Panda's MotionBenchMaker problems") else {
        return;
    };
    let panda = mbm.join("panda");
    for set in ["bookshelf_small_panda", "cage_panda", "table_under_pick_panda"] {
        let dir = panda.join("problems").join(set);
        let json = format!(
            r#"{{"world": {{"robot": {{"urdf": {urdf:?}, "srdf": {srdf:?}}}, "scene": "scene0002.yaml"}},
                 "request": "request0002.yaml", "planner": {{"name": "rrt_connect", "range": 1.0, "time_limit_s": 10}}, "seed": 1}}"#,
            urdf = panda.join("panda_spherized.urdf"),
            srdf = panda.join("panda.srdf"),
        );
        let problem: ProblemSpec = serde_json::from_str(&json).unwrap();
        let result = solve(&problem, &dir).unwrap_or_else(|e| panic!("{set}: {e}"));
        let request = trailmark::robot::request::Request::from_file(dir.join("request0002.yaml")).unwrap();
        let robot = trailmark::robot::Robot::from_file(panda.join("panda_spherized.urdf")).unwrap();
        let template = request.start_values(&robot).unwrap();
        let reference = arm_reference(
            &dir,
            "../../panda_spherized.urdf",
            "../../panda.srdf",
            "scene0002.yaml",
            "panda_arm",
            template,
        );
        let (start, goal) = request.ends(reference.group()).unwrap();
        check_arm_path(&reference, &result, &start, &goal);
    }
}
