//! The exact tier: parry3d's answers on spheres agree with the sphere checker's own formulas;
//! a motion it proves free is free at every state along it; and on the Panda (when
//! `../shared/mbm` is present) the spherized model's spheres, grown by what they leave
//! uncovered, cover the meshes: every state they call free, the mesh model does too.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_robot::cover::{cover, spherize, uncovered};
use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::urdf::Urdf;
use trailmark_robot::{ArmChecker, DEFAULT_STEP, ExactChecker, Robot, RobotError};

#[path = "../../../tests/support/shared_data.rs"]
mod shared_data;

#[path = "support/two_links.rs"]
mod two_links;
use two_links::{SRDF, URDF};

const SCENE: &str = "
world:
  collision_objects:
    - id: block
      primitives: [{type: box, dimensions: [0.2, 0.3, 0.4]}]
      primitive_poses: [{position: [0.6, 0.3, 0.4], orientation: [0, 0, 0.38268343, 0.92387953]}]
    - id: pole
      primitives: [{type: cylinder, dimensions: [0.8, 0.05]}]
      primitive_poses: [{position: [-0.5, 0.4, 0.4], orientation: [0.258819, 0, 0, 0.9659258]}]
    - id: ball
      primitives: [{type: sphere, dimensions: [0.12]}]
      primitive_poses: [{position: [0.1, -0.7, 0.6], orientation: [0, 0, 0, 1]}]
";

fn checkers() -> (ArmChecker, ExactChecker) {
    let robot = Robot::new(Urdf::parse(URDF).unwrap()).unwrap();
    let srdf = Srdf::parse(SRDF).unwrap();
    let group = robot.group(&srdf, "arm").unwrap();
    let scene = Scene::parse(SCENE).unwrap();
    let spheres =
        ArmChecker::new(robot.clone(), &srdf, group.clone(), &scene, vec![0.0; 2], DEFAULT_STEP).unwrap();
    let exact =
        ExactChecker::new(robot, &srdf, group, &scene, vec![0.0; 2], Path::new("."), DEFAULT_STEP).unwrap();
    (spheres, exact)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// On a robot of spheres, parry's answer is the sphere checker's (away from contact, where
    /// rounding may tell them apart).
    #[test]
    fn on_spheres_the_exact_tier_agrees_with_the_sphere_checker(yaw in -3.0..3.0f64, pitch in -2.5..2.5f64) {
        let (spheres, exact) = checkers();
        let q = [yaw, pitch];
        let near = [1e-7, -1e-7].iter().any(|d| spheres.is_free(&[yaw + d, pitch]) != spheres.is_free(&q));
        prop_assume!(!near);
        prop_assert_eq!(spheres.is_free(&q), exact.is_free(&q), "{:?}: {:?}", q, exact.contacts(&q));
    }

    /// A motion the exact tier proves free is free at 2,000 states along it.
    #[test]
    fn a_motion_proven_free_is_free_at_every_state(a in (-3.0..3.0f64, -2.5..2.5f64), b in (-3.0..3.0f64, -2.5..2.5f64)) {
        let (_, exact) = checkers();
        let (a, b) = ([a.0, a.1], [b.0, b.1]);
        if exact.motion_is_free(&a, &b) {
            for i in 0..=2000 {
                let t = i as f64 / 2000.0;
                let q = [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
                prop_assert!(exact.is_free(&q), "{:?} -> {:?} collides at t = {}", a, b, t);
            }
        }
    }
}

#[test]
fn motions_through_an_obstacle_are_refused() {
    let (spheres, exact) = checkers();
    // Yaw sweeps the upper arm through the block (at 45°, 0.6 m out).
    let (a, b) = ([-0.5, 0.0], [1.5, 0.0]);
    assert!(exact.is_free(&a) && exact.is_free(&b), "{:?} {:?}", exact.contacts(&a), exact.contacts(&b));
    assert!(!spheres.motion_is_free(&a, &b));
    assert!(!exact.motion_is_free(&a, &b));
    assert!(!exact.contacts(&[0.6, 0.0]).unwrap().is_empty());
    assert!(matches!(exact.contacts(&[0.0]), Err(RobotError::Dimension { .. })));
    assert!(!exact.is_free(&[f64::NAN, 0.0]));
}

#[test]
fn mesh_files_are_found_beside_the_urdf_and_bad_ones_refused() {
    let dir = std::env::temp_dir().join(format!("trailmark-exact-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("robot/meshes")).unwrap();
    // A tetrahedron, 0.1 m, as the fore link's mesh.
    let tetra = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    std::fs::write(dir.join("robot/meshes/tip.obj"), tetra).unwrap();
    std::fs::write(dir.join("robot/meshes/bad.stl"), b"solid x\nfacet normal\n").unwrap();
    let with_mesh = |filename: &str| {
        let urdf = URDF.replace(
            r#"<geometry><sphere radius="0.04"/></geometry>"#,
            &format!(r#"<geometry><mesh filename="{filename}" scale="2 2 2"/></geometry>"#),
        );
        let robot = Robot::new(Urdf::parse(&urdf).unwrap()).unwrap();
        let srdf = Srdf::parse(SRDF).unwrap();
        let group = robot.group(&srdf, "arm").unwrap();
        let scene = Scene::parse(SCENE).unwrap();
        ExactChecker::new(robot, &srdf, group, &scene, vec![0.0; 2], &dir.join("robot"), DEFAULT_STEP)
    };
    for name in ["package://robot/meshes/tip.obj", "package://anything/meshes/tip.obj", "meshes/tip.obj"] {
        let exact = with_mesh(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(exact.is_free(&[-0.5, 0.0]));
    }
    for name in ["package://robot/meshes/none.obj", "meshes/bad.stl", "meshes/tip.dae"] {
        assert!(matches!(with_mesh(name), Err(RobotError::Mesh { .. })), "{name}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

fn panda() -> Option<PathBuf> {
    shared_data::shared_data("mbm", "the Panda's meshes and MotionBenchMaker's problems")
        .map(|d| d.join("panda"))
}

/// On the Panda, the spherized URDF's spheres leave parts of the meshes outside (by
/// centimetres, between spheres); covered (`cover::cover`: spheres added where the meshes stick
/// out, all grown by the tolerance) they contain them: at random states of a problem's scene,
/// every state the covering spheres call free, the meshes call free.
#[test]
fn the_pandas_covered_spheres_contain_its_meshes() {
    let Some(dir) = panda() else { return };
    let srdf = Srdf::from_file(dir.join("panda.srdf")).unwrap();
    let spherized = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let meshes = Robot::from_file(dir.join("panda.urdf")).unwrap();
    // A coarse sampling keeps the test quick (its bound is part of the cover).
    let resolution = 0.002;
    let growth = uncovered(&spherized, &meshes, &dir, resolution).unwrap();
    let link = |name: &str| growth[spherized.link_index(name).unwrap()];
    assert!(link("panda_link6") > 0.01 && link("panda_hand") > 0.005, "{growth:?}");
    let (urdf, added) = cover(&spherized, &meshes, &dir, resolution, 0.001).unwrap();
    let covered = Robot::new(urdf).unwrap();
    assert!(uncovered(&covered, &meshes, &dir, resolution).unwrap().iter().all(|&g| g <= 1e-12));
    assert!(added.iter().sum::<usize>() > 0);
    let problem = dir.join("problems/bookshelf_small_panda");
    let scene = Scene::from_file(problem.join("scene0001.yaml")).unwrap();
    let request = Request::from_file(problem.join("request0001.yaml")).unwrap();
    let group = covered.group(&srdf, &request.group).unwrap();
    let template = request.start_values(&covered).unwrap();
    let spheres =
        ArmChecker::new(covered, &srdf, group.clone(), &scene, template.clone(), DEFAULT_STEP).unwrap();
    let mesh_group = meshes.group(&srdf, &request.group).unwrap();
    let exact = ExactChecker::new(meshes, &srdf, mesh_group, &scene, template, &dir, DEFAULT_STEP).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let (mut free, mut mesh_only) = (0, 0);
    for _ in 0..300 {
        let q: Vec<f64> = group.bounds.iter().map(|&(lo, hi)| rng.random_range(lo..hi)).collect();
        match (spheres.is_free(&q), exact.is_free(&q)) {
            (true, exact_free) => {
                assert!(exact_free, "{q:?}: the spheres are free, the meshes touch {:?}", exact.contacts(&q));
                free += 1;
            }
            (false, true) => mesh_only += 1,
            (false, false) => {}
        }
    }
    // Both kinds of state occur: the test compares something.
    assert!(free > 10 && mesh_only > 3, "{free} free, {mesh_only} free for the meshes only");
}

/// A robot of primitives and a mesh, spherized from its own geometry: the spheres contain it
/// (nothing left uncovered), and where they are free, the exact shapes are.
#[test]
fn spheres_made_from_a_robots_own_shapes_contain_them() {
    let dir = std::env::temp_dir().join(format!("trailmark-spherize-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A thin tetrahedron 0.3 m long, as the forearm's mesh.
    let tetra =
        "v 0 -0.03 -0.03\nv 0 0.03 -0.03\nv 0 0 0.04\nv 0.3 0 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    std::fs::write(dir.join("fore.obj"), tetra).unwrap();
    let urdf = URDF
        .replace(
            r#"<collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.06"/></geometry></collision>"#,
            r#"<collision><origin xyz="0.2 0 0" rpy="0 1.5708 0"/><geometry><cylinder radius="0.05" length="0.3"/></geometry></collision>"#,
        )
        .replace(
            r#"<collision><origin xyz="0.15 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>"#,
            r#"<collision><geometry><mesh filename="fore.obj"/></geometry></collision>"#,
        )
        .replace(r#"<geometry><sphere radius="0.04"/></geometry>"#, r#"<geometry><box size="0.05 0.05 0.05"/></geometry>"#);
    let shapes = Robot::new(Urdf::parse(&urdf).unwrap()).unwrap();
    let spheres = Robot::new(spherize(&shapes, &dir, 0.002, 0.001).unwrap()).unwrap();
    assert!(uncovered(&spheres, &shapes, &dir, 0.002).unwrap().iter().all(|&g| g <= 1e-12));
    let srdf = Srdf::parse(SRDF).unwrap();
    let scene = Scene::parse(SCENE).unwrap();
    let group = spheres.group(&srdf, "arm").unwrap();
    let fast = ArmChecker::new(spheres, &srdf, group.clone(), &scene, vec![0.0; 2], DEFAULT_STEP).unwrap();
    let exact =
        ExactChecker::new(shapes, &srdf, group.clone(), &scene, vec![0.0; 2], &dir, DEFAULT_STEP).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(2);
    let mut free = 0;
    for _ in 0..300 {
        let q: Vec<f64> = group.bounds.iter().map(|&(lo, hi)| rng.random_range(lo..hi)).collect();
        if fast.is_free(&q) {
            assert!(exact.is_free(&q), "{q:?}: {:?}", exact.contacts(&q));
            free += 1;
        }
    }
    assert!(free > 30, "{free}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A robot whose frames are too far out for a speed bound (the norm of `(1e308, 1e308, 0)`
/// is not finite): its motions are refused at once, never checked without end.
#[test]
fn motions_without_a_finite_speed_bound_are_refused() {
    let urdf = URDF.replace(r#"<origin xyz="0.45 0 0"/>"#, r#"<origin xyz="1e308 1e308 0"/>"#);
    let robot = Robot::new(Urdf::parse(&urdf).unwrap()).unwrap();
    let srdf = Srdf::parse(SRDF).unwrap();
    let group = robot.group(&srdf, "arm").unwrap();
    let scene = Scene::parse(SCENE).unwrap();
    let exact =
        ExactChecker::new(robot, &srdf, group, &scene, vec![0.0; 2], Path::new("."), DEFAULT_STEP).unwrap();
    assert!(!exact.motion_is_free(&[0.0, 0.0], &[0.1, 0.1]));
}
