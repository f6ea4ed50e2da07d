//! A 3-link planar arm planned in joint space: RRT-Connect over the joint angles (`Rn<3>`),
//! then shortcutting, among polygon obstacles; the plan is re-checked finely and drawn as SVG.
//!
//! `cargo run --release --example arm [OUT.svg]` (default: `docs/img/sample-arm.svg`)
//!
//! The arm ([`PlanarArm`]) stands at the middle of the floor of a 10 x 6 workspace. Its links
//! are capsules (segments between the joints, with a radius); the angles θ1..θ3 each lie in
//! [-π, π], θ1 measured from the +x axis and θ2, θ3 relative to the link before. A
//! configuration is valid ([`ArmChecker`]) when no link touches an obstacle (exact
//! capsule-polygon tests by the workspace's checker), link 1 and link 3 do not touch (parry2d
//! capsules; adjacent links share a joint and are not tested), and the joints stay in the
//! workspace (above the floor).
//!
//! Motions are checked by [`Sampled`]: states every 1/1000 of the joint space's extent
//! (about 0.011 rad). Between two checked states no point of the arm moves further than that
//! step times [`PlanarArm::max_speed`], so the planner checks the links grown by half of it
//! ([`PlanarArm::clearance`], about 0.04): every state between two checked ones is then free
//! for the true arm, and the fine re-check at the end (every 0.001 rad of any joint, true
//! radius) cannot fail unless the planner returns a motion it did not check.
//!
//! The scene: the arm starts tucked under a shelf on the left and must reach behind a post on
//! the right, past a block hanging from the ceiling, so it folds and hooks its way across.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::time::Instant;

use trailmark::core::geometry::Point;
use trailmark::core::termination::Termination;
use trailmark::core::world::{Bounds, PolygonWorld};
use trailmark::sample::arm::{ArmChecker, PlanarArm, densify};
use trailmark::sample::{
    KdNearest, Planner, Problem, Rn, RrtConnect, RrtOptions, Sampled, StateSpace, shortcut,
};
use trailmark::svg::WorldSvg;

/// A configuration: the three joint angles.
type Joints = <Rn<3> as StateSpace>::State;

/// Motions are checked every `RESOLUTION` x the joint space's extent.
const RESOLUTION: f64 = 1e-3;

/// The re-check of the final path: no joint turns more than this (radians) between checks.
const RECHECK_STEP: f64 = 1e-3;

/// The base and the ends of the three links at `q`.
fn joints(arm: &PlanarArm<3>, q: &Joints) -> [Point; 4] {
    let [a, b, c] = arm.joints(q);
    [arm.base(), a, b, c]
}

/// The sum of the joint-space lengths of the path's motions.
fn cost(space: &Rn<3>, path: &[Joints]) -> f64 {
    path.windows(2).map(|m| space.distance(&m[0], &m[1])).sum()
}

/// The workspace as [`WorldSvg`] draws it, with the arm at the start (green), at the goal (red)
/// and at `overlays` poses between (faint), and the trace of the end effector along `states`
/// (a finely cut path). The arm is drawn in world coordinates by a group whose transform flips
/// y, so +y is up as in [`WorldSvg`]; a link is a polyline as wide as the capsule.
fn draw(workspace: &PolygonWorld, arm: &PlanarArm<3>, states: &[Joints], overlays: usize) -> String {
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
    let width = 2.0 * arm.radius();
    let last = states.len() - 1;
    for i in 1..=overlays {
        let joints = joints(arm, &states[i * last / (overlays + 1)]);
        polyline(
            &mut svg,
            &joints,
            &format!(r##"stroke="#2e86c1" stroke-opacity="0.25" stroke-width="{width}""##),
        );
    }
    for (q, colour) in [(&states[0], "#27ae60"), (&states[last], "#c0392b")] {
        let joints = joints(arm, q);
        polyline(&mut svg, &joints, &format!(r#"stroke="{colour}" stroke-width="{width}""#));
        for p in &joints[1..3] {
            let (x, y, r) = (p.x, p.y, arm.radius() / 2.0);
            let _ = writeln!(svg, r#"<circle cx="{x:.3}" cy="{y:.3}" r="{r:.3}" fill="white"/>"#);
        }
    }
    let trace: Vec<Point> = states.iter().map(|q| arm.joints(q)[2]).collect();
    polyline(&mut svg, &trace, r##"stroke="#e1306c" stroke-width="0.05""##);
    let (x, y) = (arm.base().x, arm.base().y);
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
    let arm = PlanarArm::new(Point::new(5.0, 0.0), [2.5, 2.0, 1.5], 0.15)?;

    let space = Rn::new([-PI; 3], [PI; 3])?;
    let clearance = arm.clearance(&space, RESOLUTION);
    let planning = ArmChecker::new(arm, &workspace, clearance)?;
    let validity = Sampled::new(|q: &Joints| planning.is_free(q), RESOLUTION)?;
    // Tucked under the shelf, and hooked over the post with the hand behind it (degrees).
    let start = Joints::new(150.0, 30.0, -120.0).map(f64::to_radians);
    let goal = Joints::new(75.0, -50.0, -70.0).map(f64::to_radians);

    let problem = Problem::new(&space, &validity, start, goal);
    let nearest = KdNearest::<Rn<3>, 3>::new(&space)?;
    let options = RrtOptions { range: Some(0.5), ..RrtOptions::default() };
    let mut planner = RrtConnect::new(nearest).with_options(options).with_seed(1);
    let plan = planner.solve(&problem, &Termination::iterations(100_000))?;
    let path = plan.path().ok_or("RRT-Connect found no path")?.to_vec();
    let clock = Instant::now();
    let short = shortcut(&space, &validity, &path, 200, 1);
    let shortcut_time = clock.elapsed();
    let s = plan.stats;
    println!(
        "clearance for sampled motion checks: {clearance:.4} (resolution {RESOLUTION} of extent {:.3})",
        space.extent()
    );
    println!("solved: {}", plan.is_exact());
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
