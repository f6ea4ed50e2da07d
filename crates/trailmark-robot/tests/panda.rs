//! The Panda of `../shared/mbm` (skipped with a message without it): forward kinematics against
//! Franka's published Denavit-Hartenberg parameters, and MotionBenchMaker problems read,
//! checked and planned.

use std::f64::consts::FRAC_PI_2;
use std::path::{Path, PathBuf};

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::termination::Termination;
use trailmark_robot::request::Request;
use trailmark_robot::scene::Scene;
use trailmark_robot::srdf::Srdf;
use trailmark_robot::{ArmChecker, BatchChecker, DEFAULT_STEP, Robot, Simd};
use trailmark_sample::{KdNearest, Planner, Problem, Rn, RrtConnect};

#[path = "../../../tests/support/shared_data.rs"]
mod shared_data;

fn panda() -> Option<PathBuf> {
    shared_data::shared_data("mbm", "the Panda and MotionBenchMaker's problems").map(|d| d.join("panda"))
}

fn srdf(dir: &Path) -> Srdf {
    Srdf::parse(&std::fs::read_to_string(dir.join("panda.srdf")).unwrap()).unwrap()
}

/// Franka's modified Denavit-Hartenberg parameters (Craig's convention: `a` and `alpha` of the
/// row before), from the Panda's documentation: the flange's pose for joint values `q`.
fn flange_by_dh(q: &[f64; 7]) -> Isometry3<f64> {
    let rows = [
        (0.0, 0.333, 0.0),
        (0.0, 0.0, -FRAC_PI_2),
        (0.0, 0.316, FRAC_PI_2),
        (0.0825, 0.0, FRAC_PI_2),
        (-0.0825, 0.384, -FRAC_PI_2),
        (0.0, 0.0, FRAC_PI_2),
        (0.088, 0.0, FRAC_PI_2),
    ];
    let step = |a: f64, d: f64, alpha: f64, theta: f64| {
        Isometry3::from_parts(
            Translation3::identity(),
            UnitQuaternion::from_axis_angle(&Vector3::x_axis(), alpha),
        ) * Translation3::new(a, 0.0, 0.0)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), theta)
            * Translation3::new(0.0, 0.0, d)
    };
    let mut pose = Isometry3::identity();
    for (i, &(a, d, alpha)) in rows.iter().enumerate() {
        pose *= step(a, d, alpha, q[i]);
    }
    pose * step(0.0, 0.107, 0.0, 0.0)
}

#[test]
fn forward_kinematics_agrees_with_frankas_dh_parameters() {
    let Some(dir) = panda() else { return };
    for file in ["panda.urdf", "panda_spherized.urdf"] {
        let robot = Robot::from_file(dir.join(file)).unwrap();
        let group = robot.group(&srdf(&dir), "panda_arm").unwrap();
        assert_eq!(group.names, (1..=7).map(|i| format!("panda_joint{i}")).collect::<Vec<_>>());
        let flange = robot.link_index("panda_link8").unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for _ in 0..200 {
            let q: [f64; 7] = std::array::from_fn(|i| rng.random_range(group.bounds[i].0..group.bounds[i].1));
            let mut values = vec![0.0; robot.urdf().joints.len()];
            for (&j, &v) in group.joints.iter().zip(&q) {
                values[j] = v;
            }
            let ours = robot.link_poses(&values).unwrap()[flange];
            let theirs = flange_by_dh(&q);
            let position = (ours.translation.vector - theirs.translation.vector).norm();
            let angle = ours.rotation.angle_to(&theirs.rotation);
            assert!(position < 1e-9 && angle < 1e-9, "{file} at {q:?}: {position} m, {angle} rad apart");
        }
    }
}

/// The problems of a set, `(scene, request)` file pairs in order.
fn problems(dir: &Path, set: &str) -> Vec<(PathBuf, PathBuf)> {
    let folder = dir.join("problems").join(format!("{set}_panda"));
    let mut requests: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with("request"))
        .collect();
    requests.sort();
    requests
        .into_iter()
        .map(|r| {
            let scene = folder.join(r.file_name().unwrap().to_string_lossy().replace("request", "scene"));
            (scene, r)
        })
        .collect()
}

const SETS: [&str; 7] =
    ["bookshelf_small", "bookshelf_tall", "bookshelf_thin", "box", "cage", "table_pick", "table_under_pick"];

/// Every scene and request of the seven sets reads, and its start and goal are in the group's
/// limits (within the documented tolerance).
#[test]
fn every_problem_file_reads() {
    let Some(dir) = panda() else { return };
    let robot = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let group = robot.group(&srdf(&dir), "panda_arm").unwrap();
    let mut count = 0;
    for set in SETS {
        for (scene, request) in problems(&dir, set) {
            let scene = Scene::from_file(&scene).unwrap();
            assert!(!scene.obstacles.is_empty());
            let request = Request::from_file(&request).unwrap();
            assert_eq!(request.group, "panda_arm");
            request.ends(&group).unwrap();
            count += 1;
        }
    }
    assert_eq!(count, 700);
}

/// RRT-Connect plans the first problem of every set on the spherized Panda, and the path holds
/// under a check ten times finer.
#[test]
fn rrt_connect_plans_a_problem_of_every_set() {
    let Some(dir) = panda() else { return };
    plan_sets(&dir, 1);
}

/// Ten problems a set (`cargo test --release -p trailmark-robot -- --ignored`).
#[test]
#[ignore]
fn rrt_connect_plans_ten_problems_of_every_set() {
    let Some(dir) = panda() else { return };
    plan_sets(&dir, 10);
}

fn plan_sets(dir: &Path, per_set: usize) {
    let robot = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let srdf = srdf(dir);
    let group = robot.group(&srdf, "panda_arm").unwrap();
    for set in SETS {
        for (scene_file, request_file) in problems(dir, set).into_iter().take(per_set) {
            let scene = Scene::from_file(&scene_file).unwrap();
            let request = Request::from_file(&request_file).unwrap();
            let start_values = request.start_values(&robot).unwrap();
            let (start, goal) = request.ends(&group).unwrap();
            let checker = ArmChecker::new(
                robot.clone(),
                &srdf,
                group.clone(),
                &scene,
                start_values.clone(),
                DEFAULT_STEP,
            )
            .unwrap();
            let finer = ArmChecker::new(
                robot.clone(),
                &srdf,
                group.clone(),
                &scene,
                start_values,
                DEFAULT_STEP / 10.0,
            )
            .unwrap();
            let name = request_file.display();
            assert!(checker.is_free(&start) && checker.is_free(&goal), "{name}: start or goal collides");
            let space = checker.space::<7>().unwrap();
            let to = |v: &[f64]| nalgebra::SVector::<f64, 7>::from_column_slice(v);
            let fast = BatchChecker::new(checker.clone());
            let mut planner = RrtConnect::new(KdNearest::<Rn<7>, 7>::new(&space).unwrap()).with_seed(1);
            let clock = std::time::Instant::now();
            let problem = Problem::new(&space, &checker, to(&start), to(&goal));
            let scalar = planner.solve(&problem, &Termination::iterations(50_000)).unwrap();
            let scalar_time = clock.elapsed().as_secs_f64();
            assert!(scalar.path().is_some(), "{name}: no path with the scalar checker");
            let mut planner = RrtConnect::new(KdNearest::<Rn<7>, 7>::new(&space).unwrap()).with_seed(1);
            let clock = std::time::Instant::now();
            let problem = Problem::new(&space, &fast, to(&start), to(&goal));
            let plan = planner.solve(&problem, &Termination::iterations(50_000)).unwrap();
            // Printed, not asserted (run with --nocapture).
            println!(
                "{name}: planned in {:.3} ms (scalar checker {:.3} ms)",
                clock.elapsed().as_secs_f64() * 1e3,
                scalar_time * 1e3
            );
            let path = plan.path().unwrap_or_else(|| panic!("{name}: no path"));
            assert_eq!(path[0].as_slice(), &start[..]);
            assert_eq!(path[path.len() - 1].as_slice(), &goal[..]);
            for m in path.windows(2) {
                assert!(finer.motion_is_free(m[0].as_slice(), m[1].as_slice()), "{name}: a motion collides");
            }
        }
    }
}

/// The batch checker, on both its codes, against the `f64` checker on the first problems of
/// every set: configurations drawn in the limits and near the start-goal line (where contacts
/// are close calls), and motions between them. Never free where the `f64` checker collides,
/// rarely colliding where it is free (only within the `f32` slack of a contact), and the vector
/// and portable codes always agree.
#[test]
fn the_batch_checker_is_conservative_and_its_codes_agree() {
    let Some(dir) = panda() else { return };
    let robot = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let srdf = srdf(&dir);
    let group = robot.group(&srdf, "panda_arm").unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (mut states, mut stricter) = (0usize, 0usize);
    for set in SETS {
        for (scene_file, request_file) in problems(&dir, set).into_iter().take(2) {
            let scene = Scene::from_file(&scene_file).unwrap();
            let request = Request::from_file(&request_file).unwrap();
            let start_values = request.start_values(&robot).unwrap();
            let (start, goal) = request.ends(&group).unwrap();
            let checker =
                ArmChecker::new(robot.clone(), &srdf, group.clone(), &scene, start_values, DEFAULT_STEP)
                    .unwrap();
            let vector = BatchChecker::new(checker.clone());
            let portable = vector.clone().with_simd(Simd::Portable);
            let draw = |rng: &mut ChaCha8Rng| -> Vec<f64> {
                if rng.random_bool(0.5) {
                    (0..7).map(|i| rng.random_range(group.bounds[i].0..group.bounds[i].1)).collect()
                } else {
                    let t: f64 = rng.random_range(0.0..1.0);
                    (0..7)
                        .map(|i| start[i] + (goal[i] - start[i]) * t + rng.random_range(-0.05..0.05))
                        .collect()
                }
            };
            for _ in 0..300 {
                let q = draw(&mut rng);
                let exact = checker.is_free(&q);
                let fast = vector.is_free(&q);
                assert_eq!(fast, portable.is_free(&q), "{q:?}");
                assert!(!fast || exact, "{}: free in f32 but not in f64 at {q:?}", request_file.display());
                states += 1;
                stricter += usize::from(exact && !fast);
                let r = draw(&mut rng);
                let exact = checker.motion_is_free(&q, &r);
                let fast = vector.motion_is_free(&q, &r);
                assert_eq!(fast, portable.motion_is_free(&q, &r));
                assert!(!fast || exact, "{}: a motion free in f32 but not in f64", request_file.display());
            }
        }
    }
    println!("{stricter} of {states} states colliding only in f32");
    assert!(stricter * 100 <= states, "{stricter} of {states} states colliding only in f32");
}
