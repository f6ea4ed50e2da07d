//! Plans a MotionBenchMaker problem for the Franka Panda from its URDF, SRDF, scene and request
//! (`../shared/mbm`), and draws the arm along its path seen from the side and from above:
//! `cargo run --release --example arm_panda [SET NUMBER]` writes `docs/img/arms-panda.svg`.

use std::fmt::Write;
use std::path::Path;

use trailmark::core::termination::Termination;
use trailmark::robot::nalgebra::{Point3, Vector3};
use trailmark::robot::request::Request;
use trailmark::robot::scene::{Scene, Shape};
use trailmark::robot::srdf::Srdf;
use trailmark::robot::{ArmChecker, DEFAULT_STEP, Robot, SphereModel};
use trailmark::sample::{KdNearest, Planner, Problem, Rn, RrtConnect, SVector};

/// The world's box of interest, in metres: x, y, z from and to.
const VIEW: [(f64, f64); 3] = [(-0.4, 1.2), (-0.8, 0.8), (-0.6, 1.2)];
const SCALE: f64 = 300.0;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (set, number) = match args.as_slice() {
        [set, number] => (set.clone(), number.parse::<u32>()?),
        _ => ("bookshelf_small".to_string(), 1),
    };
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/mbm/panda");
    if !dir.is_dir() {
        println!("skipped: {} not found (the Panda and MotionBenchMaker's problems)", dir.display());
        return Ok(());
    }
    let robot = Robot::from_file(dir.join("panda_spherized.urdf"))?;
    let srdf = Srdf::parse(&std::fs::read_to_string(dir.join("panda.srdf"))?)?;
    let group = robot.group(&srdf, "panda_arm")?;
    let problem_dir = dir.join(format!("problems/{set}_panda"));
    let scene = Scene::from_file(problem_dir.join(format!("scene{number:04}.yaml")))?;
    let request = Request::from_file(problem_dir.join(format!("request{number:04}.yaml")))?;
    let values = request.start_values(&robot)?;
    let checker = ArmChecker::new(robot.clone(), &srdf, group.clone(), &scene, values.clone(), DEFAULT_STEP)?;
    let space = checker.space::<7>()?;
    let (start, goal) = request.ends(&group)?;
    let problem =
        Problem::new(&space, &checker, SVector::from_column_slice(&start), SVector::from_column_slice(&goal));
    let mut planner = RrtConnect::new(KdNearest::<Rn<7>, 7>::new(&space)?).with_seed(1);
    let plan = planner.solve(&problem, &Termination::iterations(50_000))?;
    let path = plan.path().ok_or("no path")?;
    println!("{set} {number}: {} waypoints", path.len());

    // The arm at states evenly spaced along the path in joint space.
    let lengths: Vec<f64> = path.windows(2).map(|m| (m[1] - m[0]).norm()).collect();
    let total: f64 = lengths.iter().sum();
    let frames = 9;
    let model = SphereModel::new(&robot, &srdf, &scene.allowed)?;
    let mut arms = Vec::new();
    for f in 0..frames {
        let mut along = total * f as f64 / (frames - 1) as f64;
        let mut i = 0;
        while i + 1 < lengths.len() && along > lengths[i] {
            along -= lengths[i];
            i += 1;
        }
        let t = if lengths[i] > 0.0 { (along / lengths[i]).min(1.0) } else { 0.0 };
        let q = path[i] + (path[i + 1] - path[i]) * t;
        let mut all = values.clone();
        for (&j, &v) in group.joints.iter().zip(q.iter()) {
            all[j] = v;
        }
        let poses = robot.link_poses(&all)?;
        arms.push(
            model
                .spheres
                .iter()
                .map(|s| (poses[s.link] * Point3::from(s.centre), s.radius))
                .collect::<Vec<_>>(),
        );
    }

    let panels = [("side (x, z)", 0, 2), ("above (x, y)", 0, 1)];
    let width = |a: usize| (VIEW[a].1 - VIEW[a].0) * SCALE;
    let (w, h) = (width(0) * 2.0 + 60.0, width(2).max(width(1)) + 60.0);
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w:.0}\" height=\"{h:.0}\" viewBox=\"0 0 {w:.0} {h:.0}\">\n<title>The Panda along its path, {set} problem {number}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    for (p, &(name, a, b)) in panels.iter().enumerate() {
        let left = 20.0 + p as f64 * (width(0) + 20.0);
        let at = |v: &Point3<f64>| (left + (v[a] - VIEW[a].0) * SCALE, 40.0 + (VIEW[b].1 - v[b]) * SCALE);
        writeln!(
            svg,
            "<text x=\"{left:.0}\" y=\"25\" font-family=\"sans-serif\" font-size=\"16\">{name}</text>"
        )?;
        writeln!(
            svg,
            "<rect x=\"{left:.0}\" y=\"40\" width=\"{:.0}\" height=\"{:.0}\" fill=\"none\" stroke=\"#ccc\"/>",
            width(a),
            width(b)
        )?;
        for o in &scene.obstacles {
            match o.shape {
                Shape::Sphere { radius } => {
                    let (x, y) = at(&(o.pose * Point3::origin()));
                    writeln!(
                        svg,
                        "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{:.1}\" fill=\"#999\"/>",
                        radius * SCALE
                    )?;
                }
                Shape::Box { half } => {
                    let corners: Vec<Point3<f64>> = (0..8)
                        .map(|c| {
                            let s = |bit: usize| if c >> bit & 1 == 1 { 1.0 } else { -1.0 };
                            o.pose * Point3::from(half.component_mul(&Vector3::new(s(0), s(1), s(2))))
                        })
                        .collect();
                    polygon(&mut svg, corners.iter().map(at).collect())?;
                }
                Shape::Cylinder { radius, half_height } => {
                    let rim: Vec<Point3<f64>> = (0..32)
                        .map(|k| {
                            let angle = std::f64::consts::TAU * f64::from(k % 16) / 16.0;
                            let z = if k < 16 { -half_height } else { half_height };
                            o.pose * Point3::new(radius * angle.cos(), radius * angle.sin(), z)
                        })
                        .collect();
                    polygon(&mut svg, rim.iter().map(at).collect())?;
                }
            }
        }
        for (f, arm) in arms.iter().enumerate() {
            let hue = 220.0 - 200.0 * f as f64 / (frames - 1) as f64;
            for (c, r) in arm {
                let (x, y) = at(c);
                writeln!(
                    svg,
                    "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{:.1}\" fill=\"hsl({hue:.0}, 70%, 50%)\" fill-opacity=\"0.18\"/>",
                    r * SCALE
                )?;
            }
        }
    }
    svg.push_str("</svg>\n");
    let out = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/img/arms-panda.svg");
    std::fs::write(&out, svg)?;
    println!("wrote {}", out.display());
    Ok(())
}

/// The convex hull of `points`, filled.
fn polygon(svg: &mut String, mut points: Vec<(f64, f64)>) -> std::fmt::Result {
    points.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    let cross =
        |o: (f64, f64), a: (f64, f64), b: (f64, f64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut hull: Vec<(f64, f64)> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let ordered: Vec<(f64, f64)> =
            if pass == 0 { points.clone() } else { points.iter().rev().copied().collect() };
        for p in ordered {
            while hull.len() >= start + 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    let list: Vec<String> = hull.iter().map(|(x, y)| format!("{x:.1},{y:.1}")).collect();
    writeln!(svg, "<polygon points=\"{}\" fill=\"#999\" fill-opacity=\"0.6\"/>", list.join(" "))
}
