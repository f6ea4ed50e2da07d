//! Bad robot, semantic, scene and request files give typed errors, never a panic.

use proptest::prelude::*;
use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::urdf::Urdf;
use trailmark_robot::{Robot, RobotError};

/// A two-link robot with `joints` between its links `a`, `b`, `c`.
fn robot(joints: &str) -> Result<Robot, RobotError> {
    Robot::new(Urdf::parse(&format!(
        r#"<robot name="r"><link name="a"/><link name="b"/><link name="c"/>{joints}</robot>"#
    ))?)
}

fn revolute(name: &str, parent: &str, child: &str) -> String {
    format!(
        r#"<joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/><limit lower="-1" upper="1"/></joint>"#
    )
}

#[test]
fn a_well_formed_tree_is_taken() {
    let r = robot(&(revolute("j1", "a", "b") + &revolute("j2", "b", "c"))).unwrap();
    assert_eq!(r.root(), 0);
}

#[test]
fn the_tree_is_checked() {
    let cycle = revolute("j1", "b", "c") + &revolute("j2", "c", "b");
    assert!(matches!(robot(&cycle), Err(RobotError::NotATree(_))));
    let two_roots = revolute("j1", "a", "b");
    assert!(matches!(robot(&two_roots), Err(RobotError::NotATree(_))));
    let two_parents = revolute("j1", "a", "c") + &revolute("j2", "b", "c");
    assert!(matches!(robot(&two_parents), Err(RobotError::NotATree(_))));
    let unknown = revolute("j1", "a", "b") + &revolute("j2", "b", "nowhere");
    assert_eq!(robot(&unknown).err(), Some(RobotError::UnknownLink("nowhere".into())));
    let twice = revolute("j1", "a", "b") + &revolute("j1", "b", "c");
    assert!(matches!(robot(&twice), Err(RobotError::Duplicate { kind: "joint", .. })));
    let mimic = revolute("j1", "a", "b")
        + r#"<joint name="j2" type="revolute"><parent link="b"/><child link="c"/><limit lower="-1" upper="1"/><mimic joint="j2"/></joint>"#;
    assert_eq!(robot(&mimic).err(), Some(RobotError::MimicChain("j2".into())));
}

#[test]
fn bad_values_are_typed_errors() {
    let bad = [
        "not xml at all",
        r#"<robot><link name="a"/></robot>"#,
        r#"<scene name="r"/>"#,
        r#"<robot name="r"><link name="a"><collision><geometry><sphere radius="0"/></geometry></collision></link></robot>"#,
        r#"<robot name="r"><link name="a"><collision><geometry><sphere radius="NaN"/></geometry></collision></link></robot>"#,
        r#"<robot name="r"><link name="a"><collision><geometry><box size="1 1"/></geometry></collision></link></robot>"#,
        r#"<robot name="r"><link name="a"><collision><origin xyz="0 0 inf"/><geometry><sphere radius="1"/></geometry></collision></link></robot>"#,
        r#"<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="hinge"><parent link="a"/><child link="b"/></joint></robot>"#,
        r#"<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint></robot>"#,
        r#"<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/><limit lower="1" upper="-1"/></joint></robot>"#,
        r#"<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 0"/><limit lower="-1" upper="1"/></joint></robot>"#,
    ];
    for text in bad {
        assert!(Urdf::parse(text).is_err(), "{text}");
    }
}

#[test]
fn groups_are_checked() {
    let r = robot(&(revolute("j1", "a", "b") + &revolute("j2", "b", "c"))).unwrap();
    let srdf = Srdf::parse(
        r#"<robot name="r">
             <group name="up"><chain base_link="c" tip_link="a"/></group>
             <group name="loop"><group name="loop"/></group>
             <group name="ghost"><joint name="j9"/></group>
           </robot>"#,
    )
    .unwrap();
    assert!(matches!(r.group(&srdf, "up"), Err(RobotError::NoChain { .. })));
    assert_eq!(r.group(&srdf, "loop").err(), Some(RobotError::GroupCycle("loop".into())));
    assert_eq!(r.group(&srdf, "ghost").err(), Some(RobotError::UnknownJoint("j9".into())));
    assert_eq!(r.group(&srdf, "none").err(), Some(RobotError::UnknownGroup("none".into())));
}

#[test]
fn bad_scenes_and_requests_are_typed_errors() {
    let object = |primitive: &str, pose: &str| {
        format!(
            "world:\n  collision_objects:\n    - id: o\n      primitives: [{primitive}]\n      primitive_poses: [{pose}]\n"
        )
    };
    let pose = "{position: [0, 0, 0], orientation: [0, 0, 0, 1]}";
    assert!(Scene::parse(&object("{type: box, dimensions: [1, 1, 1]}", pose)).is_ok());
    for bad in [
        object("{type: box, dimensions: [1, 1]}", pose),
        object("{type: box, dimensions: [1, 0, 1]}", pose),
        object("{type: cone, dimensions: [1, 1]}", pose),
        object("{type: sphere, dimensions: [.nan]}", pose),
        object("{type: sphere, dimensions: [1]}", "{position: [0, 0, .inf], orientation: [0, 0, 0, 1]}"),
        object("{type: sphere, dimensions: [1]}", "{position: [0, 0, 0], orientation: [0, 0, 0, 0]}"),
        "a: &x [1]\nb: *x\n".to_string(),
        "allowed_collision_matrix: {entry_names: [a, b], entry_values: [[false, true]]}\n".to_string(),
    ] {
        assert!(Scene::parse(&bad).is_err(), "{bad}");
    }
    assert!(Request::parse("start_state: {joint_state: {name: [a, b], position: [0]}}\n").is_err());
    assert!(
        Request::parse("goal_constraints: [{joint_constraints: [{joint_name: a, position: .nan}]}]\n")
            .is_err()
    );
}

#[test]
fn request_values_outside_the_limits_by_more_than_the_tolerance_are_refused() {
    let r = robot(&(revolute("j1", "a", "b") + &revolute("j2", "b", "c"))).unwrap();
    let srdf =
        Srdf::parse(r#"<robot name="r"><group name="g"><chain base_link="a" tip_link="c"/></group></robot>"#)
            .unwrap();
    let group = r.group(&srdf, "g").unwrap();
    let request = |v: f64| {
        Request::parse(&format!(
            "start_state: {{joint_state: {{name: [j1, j2], position: [0, {v}]}}}}\ngoal_constraints: [{{joint_constraints: [{{joint_name: j1, position: 0}}, {{joint_name: j2, position: 0}}]}}]\n"
        ))
        .unwrap()
    };
    assert_eq!(request(1.00005).ends(&group).unwrap().0, [0.0, 1.0]);
    assert!(matches!(request(1.001).ends(&group), Err(RobotError::JointValue { .. })));
}

proptest! {
    #[test]
    fn no_text_makes_a_reader_panic(text in ".{0,400}") {
        let _ = Urdf::parse(&text);
        let _ = Srdf::parse(&text);
        let _ = Scene::parse(&text);
        let _ = Request::parse(&text);
    }

    #[test]
    fn no_edit_of_a_valid_robot_makes_it_panic(cut in 0usize..400, insert in "[<>/\"= a-z0-9.-]{0,6}") {
        let text = r#"<robot name="r"><link name="a"/><link name="b"><collision><origin xyz="0 0 1" rpy="0 0 0"/><geometry><cylinder radius="0.1" length="0.5"/></geometry></collision></link><joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" upper="1"/></joint></robot>"#;
        let cut = cut.min(text.len());
        let cut = (0..=cut).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
        let edited = format!("{}{}{}", &text[..cut], insert, &text[cut..]);
        if let Ok(urdf) = Urdf::parse(&edited) {
            let _ = Robot::new(urdf);
        }
    }
}
