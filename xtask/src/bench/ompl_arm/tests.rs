//! The OMPL + FCL arm driver against trailmark's checkers: the same verdicts on states, paths
//! that pass, the planners and roadmaps it runs.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::robot::nalgebra::Point3;
use trailmark::robot::request::Request;
use trailmark::robot::scene::Obstacle;
use trailmark::robot::{ArmChecker, DEFAULT_STEP};

use super::*;

/// How far from contact (metres) the two checkers may disagree.
const NEAR: f64 = 1e-6;

/// The signed distance of `c` from `o` (negative inside).
fn distance(o: &Obstacle, c: &Point3<f64>) -> f64 {
    let p = o.pose.inverse_transform_point(c);
    match o.shape {
        Shape::Box { half } => {
            let d = p.coords.abs() - half;
            let outside = d.map(|x| x.max(0.0)).norm();
            outside + d.max().min(0.0)
        }
        Shape::Cylinder { radius, half_height } => {
            let (radial, axial) = (p.x.hypot(p.y) - radius, p.z.abs() - half_height);
            radial.max(0.0).hypot(axial.max(0.0)) + radial.max(axial).min(0.0)
        }
        Shape::Sphere { radius } => p.coords.norm() - radius,
    }
}

/// How far the group at `q` is from contact: the least clearance of a sphere to an
/// obstacle, or of two spheres of links checked against each other (negative: overlap).
/// Every pair [`SphereModel::checks`] is counted: of the Panda's links, only `panda_link0`
/// stays still when its arm moves.
fn margin(world: &ArmWorld<'_>, group: &Group, q: &[f64]) -> f64 {
    let robot = world.robot;
    let model = SphereModel::new(robot, world.srdf, &world.scene.allowed).unwrap();
    let mut values = world.template.to_vec();
    for (&j, &v) in group.joints.iter().zip(q) {
        values[j] = v;
    }
    let poses = robot.link_poses(&values).unwrap();
    let centres: Vec<Point3<f64>> =
        model.spheres.iter().map(|s| poses[s.link] * Point3::from(s.centre)).collect();
    let mut least = f64::INFINITY;
    for (s, c) in model.spheres.iter().zip(&centres) {
        for o in &world.scene.obstacles {
            least = least.min(distance(o, c) - s.radius);
        }
    }
    for (a, sa) in model.spheres.iter().enumerate() {
        for (b, sb) in model.spheres.iter().enumerate().skip(a + 1) {
            if model.checks(sa.link, sb.link) {
                least = least.min((centres[a] - centres[b]).norm() - sa.radius - sb.radius);
            }
        }
    }
    least
}

/// OMPL's RRTConnect with FCL on three MotionBenchMaker problems: the driver's verdicts on
/// random states, on states within 1e-6 rad of contact and on the ends agree with
/// ArmChecker's, every path state is free for ArmChecker, and the figures are printed
/// (`cargo test -p xtask --release ompl_arm -- --ignored --nocapture`).
#[test]
#[ignore = "needs OMPL, FCL, Eigen and nlohmann-json, and ../shared/mbm/panda"]
fn rrt_connect_with_fcl_agrees_with_the_arm_checker() {
    let driver = match OmplArmDriver::build() {
        Ok(d) => d,
        Err(e) => return eprintln!("skipped: {e}"),
    };
    let dir = crate::workspace::root().join("../shared/mbm/panda");
    if !dir.is_dir() {
        return eprintln!("skipped: no {}", dir.display());
    }
    let robot = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let srdf = Srdf::from_file(dir.join("panda.srdf")).unwrap();
    let (mut times, mut rates, mut simplify_times) = (Vec::new(), Vec::new(), Vec::new());
    let (mut states, mut agree, mut near_agree, mut near) = (0, 0, 0, 0);
    let (mut motions, mut free_motions, mut simplified, mut free_simplified) = (0, 0, 0, 0);
    for number in 1..=3 {
        let set = dir.join("problems/bookshelf_small_panda");
        let scene = Scene::from_file(set.join(format!("scene{number:04}.yaml"))).unwrap();
        let request = Request::from_file(set.join(format!("request{number:04}.yaml"))).unwrap();
        let group = robot.group(&srdf, &request.group).unwrap();
        let template = request.start_values(&robot).unwrap();
        let (start, goal) = request.ends(&group).unwrap();
        let checker =
            ArmChecker::new(robot.clone(), &srdf, group.clone(), &scene, template.clone(), DEFAULT_STEP)
                .unwrap();
        assert!(checker.is_free(&start) && checker.is_free(&goal));
        let world = ArmWorld {
            robot: &robot,
            srdf: &srdf,
            group: &request.group,
            scene: &scene,
            template: &template,
        };
        let settings =
            OmplArmSettings { runs: 5, seed: number, simplify: true, ..OmplArmSettings::moveit(&group) };
        let mut input = ArmInput::new(&world, settings).unwrap();
        input.queries.push(ArmQuery { start: start.clone(), goal: goal.clone() });
        let mut rng = ChaCha8Rng::seed_from_u64(number);
        let mut random =
            || -> Vec<f64> { group.bounds.iter().map(|&(l, h)| rng.random_range(l..h)).collect() };
        let mut checked: Vec<Vec<f64>> = vec![start.clone(), goal.clone()];
        checked.extend((0..400).map(|_| random()));
        // States within 1e-6 rad of contact: bisections between a free and a colliding state.
        let (mut boundary, mut tries) = (Vec::new(), 0);
        while boundary.len() < 40 && tries < 10_000 {
            tries += 1;
            let (mut a, mut b) = (random(), random());
            if checker.is_free(&a) == checker.is_free(&b) {
                continue;
            }
            if !checker.is_free(&a) {
                std::mem::swap(&mut a, &mut b);
            }
            while a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) > 1e-6 {
                let m: Vec<f64> = a.iter().zip(&b).map(|(x, y)| (x + y) / 2.0).collect();
                if checker.is_free(&m) { a = m } else { b = m }
            }
            boundary.extend([a, b]);
        }
        let random_count = checked.len();
        checked.extend(boundary);
        input.states = checked.clone();
        let out = driver.run(&input).unwrap();
        assert!(out.valid[0] && out.valid[1], "the driver refuses the start or the goal");
        for (i, (q, &valid)) in checked.iter().zip(&out.valid).enumerate() {
            let same = checker.is_free(q) == valid;
            if i < random_count {
                states += 1;
                agree += usize::from(same);
                if !same {
                    let m = margin(&world, &group, q);
                    assert!(m.abs() < NEAR, "the checkers disagree {m} m from contact at {q:?}");
                }
            } else {
                near += 1;
                near_agree += usize::from(same);
            }
        }
        for run in &out.runs {
            assert!(run.exact(), "problem {number}: {}", run.status);
            times.push(run.time_s);
            rates.push(run.checks_per_second());
            simplify_times.push(run.simplify_time_s.unwrap_or(0.0));
            assert_eq!(
                (run.path[0].as_slice(), run.path.last().unwrap().as_slice()),
                (&start[..], &goal[..])
            );
            for q in run.path.iter().chain(&run.simplified) {
                assert!(checker.is_free(q) || margin(&world, &group, q).abs() < NEAR, "{q:?}");
            }
            for m in run.path.windows(2) {
                motions += 1;
                free_motions += usize::from(checker.motion_is_free(&m[0], &m[1]));
            }
            for m in run.simplified.windows(2) {
                simplified += 1;
                free_simplified += usize::from(checker.motion_is_free(&m[0], &m[1]));
            }
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    eprintln!(
        "OMPL {} FCL {}: median {:.2} ms a run, {:.0} checks/s, simplification {:.2} ms; \
         {agree}/{states} random states agree, {near_agree}/{near} within 1e-6 rad of contact; \
         motions free for ArmChecker: {free_motions}/{motions} planned, {free_simplified}/{simplified} simplified",
        driver.ompl_version,
        driver.fcl_version,
        median(&mut times) * 1e3,
        median(&mut rates),
        median(&mut simplify_times) * 1e3,
    );
}

/// The optimizing planners and PRMstar's build through the driver: paths from the start to
/// the goal, no shorter than the straight line, every state free for trailmark's checker;
/// a roadmap of the size asked; an unknown planner refused.
#[test]
#[ignore = "needs OMPL, FCL, Eigen and nlohmann-json, and ../shared/mbm/panda"]
fn optimizing_planners_and_roadmaps_through_the_driver() {
    let driver = match OmplArmDriver::build() {
        Ok(d) => d,
        Err(e) => return eprintln!("skipped: {e}"),
    };
    let dir = crate::workspace::root().join("../shared/mbm/panda");
    if !dir.is_dir() {
        return eprintln!("skipped: no {}", dir.display());
    }
    let robot = Robot::from_file(dir.join("panda_spherized.urdf")).unwrap();
    let srdf = Srdf::from_file(dir.join("panda.srdf")).unwrap();
    let set = dir.join("problems/table_pick_panda");
    let scene = Scene::from_file(set.join("scene0001.yaml")).unwrap();
    let request = Request::from_file(set.join("request0001.yaml")).unwrap();
    let group = robot.group(&srdf, &request.group).unwrap();
    let template = request.start_values(&robot).unwrap();
    let (start, goal) = request.ends(&group).unwrap();
    let checker =
        ArmChecker::new(robot.clone(), &srdf, group.clone(), &scene, template.clone(), DEFAULT_STEP).unwrap();
    let world =
        ArmWorld { robot: &robot, srdf: &srdf, group: &request.group, scene: &scene, template: &template };
    let straight = start.iter().zip(&goal).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
    let moveit = OmplArmSettings::moveit(&group);
    for planner in ["informed_rrt_star", "bit_star"] {
        let settings = OmplArmSettings { planner, time_limit_s: 2.0, range: 0.0, ..moveit.clone() };
        let run = driver.plan(&world, &start, &goal, settings).unwrap().remove(0);
        assert!(run.exact(), "{planner}: {}", run.status);
        assert_eq!((run.path[0].as_slice(), run.path.last().unwrap().as_slice()), (&start[..], &goal[..]));
        let length: f64 = run
            .path
            .windows(2)
            .map(|m| m[0].iter().zip(&m[1]).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt())
            .sum();
        let reported = run.length.unwrap();
        assert!((length - reported).abs() < 1e-9 * length && length >= straight - 1e-9, "{planner}");
        // Only a path as short as the straight line may end the run before its time.
        assert!(
            run.time_s >= 1.9 || length <= straight + 1e-9,
            "{planner} stopped at {length} after {} s",
            run.time_s
        );
        for q in &run.path {
            assert!(checker.is_free(q) || margin(&world, &group, q).abs() < NEAR, "{planner}: {q:?}");
        }
    }
    let settings = OmplArmSettings { planner: "prm_star", roadmap_size: 50, ..moveit.clone() };
    let run = driver.plan(&world, &start, &goal, settings).unwrap().remove(0);
    assert!(run.planner_built(50) && run.vertices < 60 && run.path.is_empty(), "{run:?}");
    let refused = driver.plan(&world, &start, &goal, OmplArmSettings { planner: "rrt_sharp", ..moveit });
    assert!(refused.is_err_and(|e| e.contains("unknown planner")));
}
