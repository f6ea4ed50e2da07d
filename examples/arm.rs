//! A 3-link planar arm planned in joint space: RRT-Connect over the joint angles (`Rn<3>`),
//! then shortcutting, among polygon obstacles; the plan is re-checked finely and drawn as SVG.
//!
//! `cargo run --release --example arm [OUT.svg]` (default: `docs/img/sample-arm.svg`)
//!
//! The arm stands at the middle of the floor of a 10 x 6 workspace. Its links are capsules
//! (segments between the joints, with a radius); the angles θ1..θ3 each lie in [-π, π], θ1
//! measured from the +x axis and θ2, θ3 relative to the link before. A configuration is valid
//! when no link touches an obstacle (exact capsule-polygon tests by the workspace's
//! [`CollisionChecker`]), link 1 and link 3 do not touch (parry2d capsules; adjacent links share
//! a joint and are not tested), and the joints stay in the workspace (above the floor).
//!
//! Motions are checked by [`Sampled`]: states every 1/1000 of the joint space's extent
//! (about 0.011 rad). Between two checked states no point of the arm moves further than that
//! step times [`Arm::max_speed`], so the planner checks the links grown by half of it (a
//! clearance of about 0.04): every state between two checked ones is then free for the true
//! arm, and the fine re-check at the end (every 0.001 rad of any joint, true radius) cannot
//! fail unless the planner returns a motion it did not check.
//!
//! The scene: the arm starts tucked under a shelf on the left and must reach behind a post on
//! the right, past a block hanging from the ceiling, so it folds and hooks its way across.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::time::Instant;

use parry2d_f64::math::{Pose2, Vector2};
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::Capsule;
use trailmark::core::geometry::{Point, Vector};
use trailmark::core::world::{Bounds, CollisionChecker, PolygonWorld};
use trailmark::sample::{
    KdNearest, Query, Rn, RrtOptions, Sampled, StateSpace, Termination, rrt_connect, shortcut,
};
use trailmark::svg::WorldSvg;

/// A configuration: the three joint angles, in radians.
type Joints = <Rn<3> as StateSpace>::State;

/// Motions are checked every `RESOLUTION` x the joint space's extent.
const RESOLUTION: f64 = 1e-3;

/// The re-check of the final path: no joint turns more than this (radians) between checks.
const RECHECK_STEP: f64 = 1e-3;

/// A planar arm of three revolute joints with its base fixed.
#[derive(Debug, Clone, Copy)]
struct Arm {
    /// Where joint 1 is.
    base: Point,
    /// The link lengths, from the base out.
    lengths: [f64; 3],
    /// The links' half thickness: each link is a capsule of this radius.
    radius: f64,
}

impl Arm {
    /// Forward kinematics: the base, the two elbows and the end effector at `q`.
    fn joints(&self, q: &Joints) -> [Point; 4] {
        let mut points = [self.base; 4];
        let mut heading = 0.0;
        for i in 0..3 {
            heading += q[i];
            points[i + 1] = points[i] + self.lengths[i] * Vector::new(heading.cos(), heading.sin());
        }
        points
    }

    /// The most any point of the arm moves per unit of joint-space (Euclidean) distance: joint i
    /// swings points at most `lengths[i] + ... + lengths[2]` away from it, and by Cauchy-Schwarz
    /// the sum over the joints is at most the norm of those lever arms times the distance.
    fn max_speed(&self) -> f64 {
        let [a, b, c] = self.lengths;
        ((a + b + c).powi(2) + (b + c).powi(2) + c.powi(2)).sqrt()
    }
}

/// Exact tests of whole arm configurations, with the links grown by a clearance.
struct ArmChecker {
    arm: Arm,
    /// The obstacles grown by the link radius plus the clearance.
    obstacles: CollisionChecker,
    /// The region the joints must stay in: the workspace shrunk by the clearance.
    inner: Bounds,
    /// The link radius plus the clearance.
    thickness: f64,
}

impl ArmChecker {
    /// Tests of `arm` in `workspace` with every link grown by `clearance`.
    fn new(arm: Arm, workspace: &PolygonWorld, clearance: f64) -> Result<Self, Box<dyn std::error::Error>> {
        let thickness = arm.radius + clearance;
        let obstacles = workspace.obstacles().iter().map(|o| o.vertices().to_vec()).collect();
        let obstacles = PolygonWorld::new(workspace.bounds(), obstacles, thickness)?.checker();
        let (lo, hi) = (workspace.bounds().min(), workspace.bounds().max());
        let inner = Bounds::new(lo.x + clearance, lo.y + clearance, hi.x - clearance, hi.y - clearance)?;
        Ok(ArmChecker { arm, obstacles, inner, thickness })
    }

    /// Whether the arm at `q` is in the workspace and touches neither an obstacle nor itself.
    fn is_free(&self, q: &Joints) -> bool {
        let j = self.arm.joints(q);
        j[1..].iter().all(|&p| self.inner.contains(p))
            && j.windows(2).all(|link| self.obstacles.segment_is_free(link[0], link[1]))
            && !self.links_touch(j[0], j[1], j[2], j[3])
    }

    /// Whether link `a-b` and link `c-d`, as parry2d capsules of the grown thickness, touch.
    fn links_touch(&self, a: Point, b: Point, c: Point, d: Point) -> bool {
        let capsule =
            |p: Point, q: Point| Capsule::new(Vector2::new(p.x, p.y), Vector2::new(q.x, q.y), self.thickness);
        let here = Pose2::IDENTITY;
        // Capsule-capsule is always supported; an unsupported pair would count as touching.
        intersection_test(&here, &capsule(a, b), &here, &capsule(c, d)).map_or(true, |hit| hit.intersecting)
    }
}

/// The states along `path`, each motion cut so that no joint turns more than `step` from one
/// state to the next (the ends of every motion included).
fn densify(space: &Rn<3>, path: &[Joints], step: f64) -> Vec<Joints> {
    let mut states = vec![path[0]];
    for m in path.windows(2) {
        let n = ((m[1] - m[0]).amax() / step).ceil().max(1.0) as usize;
        states.extend((1..=n).map(|i| space.interpolate(&m[0], &m[1], i as f64 / n as f64)));
    }
    states
}

/// The sum of the joint-space lengths of the path's motions.
fn cost(space: &Rn<3>, path: &[Joints]) -> f64 {
    path.windows(2).map(|m| space.distance(&m[0], &m[1])).sum()
}

/// The workspace as [`WorldSvg`] draws it, with the arm at the start (green), at the goal (red)
/// and at `overlays` poses between (faint), and the trace of the end effector along `states`
/// (a finely cut path). The arm is drawn in world coordinates by a group whose transform flips
/// y, so +y is up as in [`WorldSvg`]; a link is a polyline as wide as the capsule.
fn draw(workspace: &PolygonWorld, arm: &Arm, states: &[Joints], overlays: usize) -> String {
    const SCALE: f64 = 50.0;
    let (lo, hi) = (workspace.bounds().min(), workspace.bounds().max());
    let world = WorldSvg::new(workspace).scale(SCALE).title("A 3-link arm planned in joint space").to_svg();
    let mut svg = world.strip_suffix("</svg>\n").expect("an SVG document").to_string();
    let _ = writeln!(
        svg,
        r#"<g transform="translate({} {}) scale({SCALE} -{SCALE})" fill="none" stroke-linecap="round" stroke-linejoin="round">"#,
        -lo.x * SCALE,
        hi.y * SCALE
    );
    let polyline = |svg: &mut String, points: &[Point], style: &str| {
        let points: Vec<String> = points.iter().map(|p| format!("{:.3},{:.3}", p.x, p.y)).collect();
        let _ = writeln!(svg, r#"<polyline points="{}" {style}/>"#, points.join(" "));
    };
    let width = 2.0 * arm.radius;
    let last = states.len() - 1;
    for i in 1..=overlays {
        let joints = arm.joints(&states[i * last / (overlays + 1)]);
        polyline(
            &mut svg,
            &joints,
            &format!(r##"stroke="#2e86c1" stroke-opacity="0.25" stroke-width="{width}""##),
        );
    }
    for (q, colour) in [(&states[0], "#27ae60"), (&states[last], "#c0392b")] {
        let joints = arm.joints(q);
        polyline(&mut svg, &joints, &format!(r#"stroke="{colour}" stroke-width="{width}""#));
        for p in &joints[1..3] {
            let (x, y, r) = (p.x, p.y, arm.radius / 2.0);
            let _ = writeln!(svg, r#"<circle cx="{x:.3}" cy="{y:.3}" r="{r:.3}" fill="white"/>"#);
        }
    }
    let trace: Vec<Point> = states.iter().map(|q| arm.joints(q)[3]).collect();
    polyline(&mut svg, &trace, r##"stroke="#e1306c" stroke-width="0.05""##);
    let (x, y) = (arm.base.x, arm.base.y);
    let (left, right, top) = (x - 0.4, x + 0.4, y + 0.4);
    let _ = writeln!(svg, r##"<polygon points="{left},{y} {right},{y} {x},{top}" fill="#2f3640"/>"##);
    svg.push_str("</g>\n</svg>\n");
    svg
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| format!("{}/docs/img/sample-arm.svg", env!("CARGO_MANIFEST_DIR")));
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| {
        vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
    };
    let shelf = rect(0.5, 3.0, 3.0, 3.6);
    let post = rect(7.2, 0.0, 7.8, 2.5);
    let block = rect(3.9, 3.3, 6.1, 6.0);
    let workspace = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 6.0)?, vec![shelf, post, block], 0.0)?;
    let arm = Arm { base: Point::new(5.0, 0.0), lengths: [2.5, 2.0, 1.5], radius: 0.15 };

    let space = Rn::new([-PI; 3], [PI; 3])?;
    let clearance = 0.5 * RESOLUTION * space.extent() * arm.max_speed();
    let planning = ArmChecker::new(arm, &workspace, clearance)?;
    let validity = Sampled::new(|q: &Joints| planning.is_free(q), RESOLUTION)?;
    // Tucked under the shelf, and hooked over the post with the hand behind it (degrees).
    let start = Joints::new(150.0, 30.0, -120.0).map(f64::to_radians);
    let goal = Joints::new(75.0, -50.0, -70.0).map(f64::to_radians);

    let query = Query::new(&space, &validity, start, goal);
    let nearest = KdNearest::<Rn<3>, 3>::new(&space)?;
    let options = RrtOptions { range: Some(0.5), ..RrtOptions::default() };
    let plan = rrt_connect(&query, nearest, &options, &Termination::iterations(100_000), 1)?;
    let path = plan.path.filter(|_| !plan.approximate).ok_or("RRT-Connect found no path")?;
    let clock = Instant::now();
    let short = shortcut(&space, &validity, &path, 200, 1);
    let shortcut_time = clock.elapsed();
    let s = plan.stats;
    println!(
        "clearance for sampled motion checks: {clearance:.4} (resolution {RESOLUTION} of extent {:.3})",
        space.extent()
    );
    println!("solved: {}", !plan.approximate);
    println!("iterations: {}, tree sizes: {} + {}", s.iterations, s.tree_sizes[0], s.tree_sizes[1]);
    println!("collision checks: {}, planning time: {:.2?}", s.collision_checks, s.elapsed);
    println!(
        "path: {} states, cost {:.3} rad -> shortcut: {} states, cost {:.3} rad ({:.2?})",
        path.len(),
        cost(&space, &path),
        short.len(),
        cost(&space, &short),
        shortcut_time
    );

    // An independent re-check with the true arm (no clearance), every 0.001 rad of any joint,
    // of the planner's path and of the shortcut one.
    let exact = ArmChecker::new(arm, &workspace, 0.0)?;
    for (name, p) in [("planned", &path), ("shortcut", &short)] {
        let fine = densify(&space, p, RECHECK_STEP);
        assert_eq!((fine[0], fine[fine.len() - 1]), (start, goal), "the {name} path has other ends");
        assert!(fine.iter().all(|q| exact.is_free(q)), "the {name} path collides");
        println!("re-checked the {name} path at {} states: collision-free", fine.len());
    }

    if let Some(dir) = std::path::Path::new(&out).parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(&out, draw(&workspace, &arm, &densify(&space, &short, 0.02), 11))?;
    println!("wrote {out}");
    Ok(())
}
