//! Point clouds as obstacles: a cloud answers as the same points given as sphere obstacles of
//! the scene do, in every checker (the `f64` spheres, the batches, the exact tier), and a
//! planner plans around one.

use proptest::prelude::*;
use trailmark_core::termination::Termination;
use trailmark_robot::cloud::PointCloud;
use trailmark_robot::nalgebra::{Isometry3, Point3};
use trailmark_robot::scene::{Obstacle, Scene, Shape};
use trailmark_robot::srdf::Srdf;
use trailmark_robot::urdf::Urdf;
use trailmark_robot::{ArmChecker, BatchChecker, DEFAULT_STEP, ExactChecker, Robot, RobotError};
use trailmark_sample::{Joints, KdNearest, Planner, Problem, RrtConnect};

#[path = "support/two_links.rs"]
mod two_links;
use two_links::{SRDF, URDF};

/// A patch of a wall seen by a camera: points 2 cm apart on the plane x = 0.55, with noise.
fn wall() -> Vec<Point3<f64>> {
    (0..20 * 25)
        .map(|i| {
            let (row, column) = ((i / 20) as f64, (i % 20) as f64);
            let jitter = ((i * 7919) % 13) as f64 * 1e-3;
            Point3::new(0.55 + jitter, 0.05 + column * 0.02, 0.25 + row * 0.02)
        })
        .collect()
}

const RADIUS: f64 = 0.01;

/// The checkers of the arm with the wall as a cloud, and with the wall as sphere obstacles.
fn checkers() -> (ArmChecker, ArmChecker, ExactChecker) {
    let robot = Robot::new(Urdf::parse(URDF).unwrap()).unwrap();
    let srdf = Srdf::parse(SRDF).unwrap();
    let group = robot.group(&srdf, "arm").unwrap();
    let mut cloudy = Scene::default();
    cloudy.add_cloud(PointCloud::new("camera", wall(), RADIUS).unwrap());
    let balls = Scene {
        obstacles: wall()
            .iter()
            .map(|p| Obstacle {
                id: "camera".into(),
                shape: Shape::Sphere { radius: RADIUS },
                pose: Isometry3::translation(p.x, p.y, p.z),
            })
            .collect(),
        ..Scene::default()
    };
    let make = |scene: &Scene| {
        ArmChecker::new(robot.clone(), &srdf, group.clone(), scene, vec![0.0; 2], DEFAULT_STEP).unwrap()
    };
    let exact = ExactChecker::new(
        robot.clone(),
        &srdf,
        group.clone(),
        &cloudy,
        vec![0.0; 2],
        ".".as_ref(),
        DEFAULT_STEP,
    )
    .unwrap();
    (make(&cloudy), make(&balls), exact)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// States and motions: the cloud answers as its points as obstacles do, in `f64` and in
    /// batches; the exact tier agrees on states away from contact.
    #[test]
    fn a_cloud_is_its_points_as_balls(a in (-3.0..3.0f64, -2.5..2.5f64), b in (-3.0..3.0f64, -2.5..2.5f64)) {
        let (cloud, balls, exact) = checkers();
        let batch = BatchChecker::new(cloud.clone());
        let (a, b) = ([a.0, a.1], [b.0, b.1]);
        prop_assert_eq!(cloud.is_free(&a), balls.is_free(&a));
        prop_assert_eq!(cloud.motion_is_free(&a, &b), balls.motion_is_free(&a, &b));
        // The batches are conservative: never free where the f64 spheres collide.
        if batch.is_free(&a) {
            prop_assert!(cloud.is_free(&a));
        }
        if batch.motion_is_free(&a, &b) {
            for i in 0..=200 {
                let t = i as f64 / 200.0;
                let q = [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
                prop_assert!(cloud.is_free(&q), "the batches passed {:?} -> {:?}, which collides at t = {}", a, b, t);
            }
        }
        let near = [1e-7, -1e-7].iter().any(|d| cloud.is_free(&[a[0] + d, a[1]]) != cloud.is_free(&a));
        if !near {
            prop_assert_eq!(cloud.is_free(&a), exact.is_free(&a), "{:?}: {:?}", a, exact.contacts(&a));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// Eight different states a batch answer as each does alone: within the limits or beyond,
    /// free or in the cloud, in batches of any length.
    #[test]
    fn states_in_batches_answer_as_alone(states in proptest::collection::vec((-4.0..4.0f64, -3.5..3.5f64), 0..30)) {
        let (cloud, _, _) = checkers();
        let batch = BatchChecker::new(cloud);
        let states: Vec<[f64; 2]> = states.into_iter().map(|(a, b)| [a, b]).collect();
        let mut free = Vec::new();
        batch.are_free(states.iter().map(|q| q.as_slice()), &mut free);
        let alone: Vec<bool> = states.iter().map(|q| batch.is_free(q)).collect();
        prop_assert_eq!(free, alone);
    }
}

#[test]
fn rrt_connect_plans_around_a_cloud() {
    let (cloud, _, exact) = checkers();
    let contacts = cloud.contacts(&[0.5, 0.0]).unwrap();
    assert!(contacts.iter().any(|c| c.with == "camera"), "{contacts:?}");
    let batch = BatchChecker::new(cloud.clone());
    let space = cloud.joint_space::<2>().unwrap();
    // From one side of the wall to the other, the arm stretched out.
    let (start, goal) = ([-0.3, 0.0].into(), [1.3, 0.0].into());
    let problem = Problem::new(&space, &batch, start, goal);
    let mut planner = RrtConnect::new(KdNearest::<Joints<2>, 2>::new(&space).unwrap()).with_seed(3);
    let plan = planner.solve(&problem, &Termination::iterations(20_000)).unwrap();
    let path = plan.path().expect("a way around the wall");
    for m in path.windows(2) {
        assert!(cloud.motion_is_free(m[0].as_slice(), m[1].as_slice()));
        assert!(exact.motion_is_free(m[0].as_slice(), m[1].as_slice()));
    }
}

#[test]
fn bad_clouds_are_typed_errors() {
    let nan = vec![Point3::new(0.0, f64::NAN, 0.0)];
    for (points, radius) in [(vec![], 0.01), (nan, 0.01), (wall(), -1.0), (wall(), f64::INFINITY)] {
        assert!(matches!(PointCloud::new("c", points, radius), Err(RobotError::Invalid { .. })));
    }
    // Any number of points on one plane, and repeated points, make a cloud.
    let flat: Vec<Point3<f64>> = (0..5000).map(|i| Point3::new((i % 7) as f64, 0.0, 0.0)).collect();
    let cloud = PointCloud::new("flat", flat, 0.0).unwrap();
    assert_eq!(cloud.clearance(&Point3::new(3.0, 0.0, 2.0)), 2.0);
}
