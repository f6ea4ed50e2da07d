//! Continuous joints: planned in a joint space that wraps them, moved the short way round by
//! both checkers, and requests' angles taken modulo whole turns.

use std::f64::consts::{PI, TAU};

use trailmark_core::termination::Termination;
use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::urdf::Urdf;
use trailmark_robot::{ArmChecker, BatchChecker, DEFAULT_STEP, Robot, RobotError};
use trailmark_sample::{Joints, KdNearest, Planner, Problem, RrtConnect};

/// A post with an arm turning forever about z (a sphere 0.5 m out), and a revolute elbow.
const URDF: &str = r#"
<robot name="turner">
  <link name="base"/>
  <link name="arm"><collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="hand"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="turn" type="continuous"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/></joint>
  <joint name="elbow" type="revolute"><parent link="arm"/><child link="hand"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 0 1"/><limit lower="-0.5" upper="0.5"/></joint>
</robot>"#;

const SRDF: &str =
    r#"<robot name="turner"><group name="arm"><chain base_link="base" tip_link="hand"/></group></robot>"#;

/// A ball of radius 0.1 on the circle the arm's sphere sweeps, at angle `at`.
fn scene(at: f64) -> Scene {
    Scene::parse(&format!(
        "world:\n  collision_objects:\n    - id: ball\n      primitives: [{{type: sphere, dimensions: [0.1]}}]\n      primitive_poses: [{{position: [{}, {}, 0.5], orientation: [0, 0, 0, 1]}}]\n",
        0.5 * at.cos(),
        0.5 * at.sin()
    ))
    .unwrap()
}

fn checker(ball_at: f64) -> ArmChecker {
    let robot = Robot::new(Urdf::parse(URDF).unwrap()).unwrap();
    let srdf = Srdf::parse(SRDF).unwrap();
    let group = robot.group(&srdf, "arm").unwrap();
    assert_eq!(group.wraps, [true, false]);
    assert_eq!(group.bounds[0], (-PI, PI));
    ArmChecker::new(robot, &srdf, group, &scene(ball_at), vec![0.0; 2], DEFAULT_STEP).unwrap()
}

#[test]
fn a_continuous_joint_turns_the_short_way_round() {
    // The ball at angle 0: the way from 2.5 to -2.5 through π is free, the way through 0 is not.
    let behind = checker(0.0);
    // The ball at π: the short way is blocked.
    let ahead = checker(PI);
    let (a, b) = ([2.5, 0.0], [-2.5, 0.0]);
    for c in [&behind, &ahead] {
        assert!(c.is_free(&a) && c.is_free(&b));
    }
    assert!(behind.motion_is_free(&a, &b) && behind.motion_is_free(&b, &a));
    assert!(!ahead.motion_is_free(&a, &b) && !ahead.motion_is_free(&b, &a));
    let (behind, ahead) = (BatchChecker::new(behind), BatchChecker::new(ahead));
    assert!(behind.motion_is_free(&a, &b) && behind.motion_is_free(&b, &a));
    assert!(!ahead.motion_is_free(&a, &b) && !ahead.motion_is_free(&b, &a));
}

#[test]
fn a_box_space_refuses_a_continuous_joint_and_the_joint_space_wraps_it() {
    let c = checker(0.0);
    assert!(matches!(c.space::<2>(), Err(RobotError::UnsupportedJoint { .. })));
    let space = c.joint_space::<2>().unwrap();
    assert_eq!(space.wraps(), [true, false]);
}

#[test]
fn rrt_connect_plans_across_the_turn_and_every_state_between_is_free() {
    // The ball at 0: from 2.5 to -2.5 only the way across ±π is open.
    let c = checker(0.0);
    let space: Joints<2> = c.joint_space().unwrap();
    let fast = BatchChecker::new(c.clone());
    let problem = Problem::new(&space, &fast, [2.5, 0.0].into(), [-2.5, 0.0].into());
    let mut planner = RrtConnect::new(KdNearest::<Joints<2>, 3>::new(&space).unwrap()).with_seed(3);
    let plan = planner.solve(&problem, &Termination::iterations(5000)).unwrap();
    let path = plan.path().expect("the way across ±π");
    // Independently of the motion rule: states 0.1 mrad apart the short way round.
    for m in path.windows(2) {
        let turn = (m[1][0] - m[0][0]) - TAU * ((m[1][0] - m[0][0]) / TAU).round();
        let bend = m[1][1] - m[0][1];
        for k in 0..=10_000 {
            let t = f64::from(k) / 10_000.0;
            assert!(c.is_free(&[m[0][0] + turn * t, m[0][1] + bend * t]), "{m:?} at {t}");
        }
    }
    // It turns through π, not through 0: no state of the path is near 0.
    assert!(path.iter().all(|q| q[0].abs() > 0.5));
}

#[test]
fn a_request_angle_of_a_continuous_joint_is_taken_modulo_turns() {
    let robot = Robot::new(Urdf::parse(URDF).unwrap()).unwrap();
    let group = robot.group(&Srdf::parse(SRDF).unwrap(), "arm").unwrap();
    let request = Request::parse(
        "group_name: arm\nstart_state:\n  joint_state:\n    name: [turn, elbow]\n    position: [7.0, 0.1]\ngoal_constraints:\n  - joint_constraints:\n      - {joint_name: turn, position: -4.0}\n      - {joint_name: elbow, position: 0.2}\n",
    )
    .unwrap();
    let (start, goal) = request.ends(&group).unwrap();
    assert!((start[0] - (7.0 - TAU)).abs() < 1e-12 && start[1] == 0.1);
    assert!((goal[0] - (-4.0 + TAU)).abs() < 1e-12 && goal[1] == 0.2);
}

#[test]
fn a_joint_mimicking_a_continuous_one_by_part_of_a_turn_is_refused() {
    let mimic = |multiplier: &str| {
        let urdf = URDF.replace(
            "</robot>",
            &format!(
                r#"<link name="finger"/><joint name="finger" type="revolute"><parent link="hand"/><child link="finger"/>
                   <axis xyz="0 0 1"/><limit lower="-9" upper="9"/><mimic joint="turn" multiplier="{multiplier}"/></joint></robot>"#
            ),
        );
        let robot = Robot::new(Urdf::parse(&urdf).unwrap()).unwrap();
        robot.group(&Srdf::parse(SRDF).unwrap(), "arm")
    };
    // Whole turns: the robot looks the same a turn later.
    assert!(mimic("2").is_ok() && mimic("-1").is_ok());
    assert!(matches!(mimic("0.5"), Err(RobotError::UnsupportedJoint { .. })));
}
