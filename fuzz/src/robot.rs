//! The robot readers (URDF, SRDF, MoveIt scene and request, OBJ and STL meshes): whatever the bytes, a typed error
//! or a model whose every number is finite and in range; a URDF that reads builds a robot
//! (or is refused) whose link poses at zero are finite, and the sphere checker of a robot
//! that reads answers without panicking.

use trailmark::robot::mesh::Mesh;
use trailmark::robot::request::Request;
use trailmark::robot::scene::{Scene, Shape};
use trailmark::robot::srdf::Srdf;
use trailmark::robot::urdf::{Geometry, Urdf};
use trailmark::robot::{ArmChecker, BatchChecker, DEFAULT_STEP, Robot};

/// The first byte picks the reader (250 and up: the mesh readers, OBJ then STL), the rest is
/// its text or bytes.
pub fn check(data: &[u8]) {
    let Some((&which, rest)) = data.split_first() else { return };
    if which >= 250 {
        let mesh = if which < 253 { Mesh::parse_obj(&String::from_utf8_lossy(rest)) } else { Mesh::parse_stl(rest) };
        if let Ok(mesh) = mesh {
            assert!(!mesh.triangles.is_empty());
            assert!(mesh.vertices.iter().all(|v| v.coords.iter().all(|x| x.is_finite())));
            assert!(mesh.triangles.iter().flatten().all(|&i| (i as usize) < mesh.vertices.len()));
        }
        return;
    }
    let Ok(text) = std::str::from_utf8(rest) else { return };
    match which % 4 {
        0 => check_urdf(text),
        1 => {
            if let Ok(srdf) = Srdf::parse(text) {
                assert!(srdf.disabled.iter().all(|(a, b)| !a.is_empty() && !b.is_empty()));
            }
        }
        2 => check_scene(text),
        _ => {
            if let Ok(request) = Request::parse(text) {
                assert!(request.start.iter().chain(&request.goal).all(|(_, v)| v.is_finite()));
            }
        }
    }
}

fn check_urdf(text: &str) {
    let Ok(urdf) = Urdf::parse(text) else { return };
    for link in &urdf.links {
        for c in &link.collisions {
            assert!(c.origin.translation.vector.iter().all(|v| v.is_finite()));
            let positive = |v: f64| v.is_finite() && v > 0.0;
            match &c.geometry {
                Geometry::Sphere { radius } => assert!(positive(*radius)),
                Geometry::Box { size } => assert!(size.iter().all(|&v| positive(v))),
                Geometry::Cylinder { radius, length } => assert!(positive(*radius) && positive(*length)),
                Geometry::Capsule { radius, length } => {
                    assert!(positive(*radius) && length.is_finite() && *length >= 0.0)
                }
                Geometry::Mesh { scale, .. } => assert!(scale.iter().all(|v| v.is_finite())),
            }
        }
    }
    for joint in &urdf.joints {
        assert!(joint.axis.iter().all(|v| v.is_finite()));
        if let Some(l) = joint.limits {
            assert!(l.lower.is_finite() && l.upper.is_finite() && l.lower <= l.upper);
        }
    }
    let Ok(robot) = Robot::new(urdf) else { return };
    let zeros = vec![0.0; robot.urdf().joints.len()];
    let poses = robot.link_poses(&zeros).expect("zeros, one a joint, are a configuration");
    assert!(poses.iter().all(|p| p.translation.vector.iter().all(|v| v.is_finite())));
    // Every joint of the robot as one group; the checker answers for its start.
    let srdf_text = format!(
        r#"<robot name="r"><group name="all">{}</group></robot>"#,
        robot
            .urdf()
            .joints
            .iter()
            .map(|j| format!(r#"<joint name="{}"/>"#, escape(&j.name)))
            .collect::<String>()
    );
    let Ok(srdf) = Srdf::parse(&srdf_text) else { return };
    let Ok(group) = robot.group(&srdf, "all") else { return };
    let Ok(checker) =
        ArmChecker::new(robot.clone(), &srdf, group.clone(), &Scene::default(), zeros, DEFAULT_STEP)
    else {
        return;
    };
    let q: Vec<f64> = group.bounds.iter().map(|(low, high)| (low + high) / 2.0).collect();
    let free = checker.is_free(&q);
    let fast = BatchChecker::new(checker);
    assert!(!fast.is_free(&q) || free, "free in f32, colliding in f64");
    let _ = fast.motion_is_free(&q, &q);
}

fn check_scene(text: &str) {
    let Ok(scene) = Scene::parse(text) else { return };
    for o in &scene.obstacles {
        assert!(o.pose.translation.vector.iter().chain(o.pose.rotation.coords.iter()).all(|v| v.is_finite()));
        let positive = |v: f64| v.is_finite() && v > 0.0;
        match o.shape {
            Shape::Box { half } => assert!(half.iter().all(|&v| positive(v))),
            Shape::Cylinder { radius, half_height } => assert!(positive(radius) && positive(half_height)),
            Shape::Sphere { radius } => assert!(positive(radius)),
        }
    }
}

/// `name` inside an XML attribute.
fn escape(name: &str) -> String {
    name.replace('&', "&amp;").replace('"', "&quot;").replace('<', "&lt;")
}
