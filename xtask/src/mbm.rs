//! `cargo xtask verify mbm DIR --urdf FILE --srdf FILE`: every MotionBenchMaker problem of a
//! folder (a `requestNNNN.yaml` beside its `sceneNNNN.yaml`, at any depth) planned for the
//! request's group, each returned path checked again by the `f64` sphere checker at a tenth of
//! the planning step (start, goal, joint limits, every motion), and one JSON line a problem.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use serde_json::json;
use trailmark::core::termination::Termination;
use trailmark::robot::cover::{cover, spherize};
use trailmark::robot::nalgebra::SVector;
use trailmark::robot::request::Request;
use trailmark::robot::scene::Scene;
use trailmark::robot::srdf::Srdf;
use trailmark::robot::{ArmChecker, BatchChecker, DEFAULT_STEP, ExactChecker, Robot, RobotError};
use trailmark::sample::{
    BitStar, InformedRrtStar, Joints, KdNearest, Plan, PlanError, Planner, Prm, Problem, RrtConnect,
    RrtOptions, paths, simplify,
};

/// The arguments of `verify mbm`.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The folder of problems (searched at any depth).
    pub dir: PathBuf,
    /// The robot's URDF (with spheres, or primitives).
    #[arg(long)]
    pub urdf: PathBuf,
    /// The robot's SRDF.
    #[arg(long)]
    pub srdf: PathBuf,
    /// The planner.
    #[arg(long, value_enum, default_value = "rrt_connect")]
    pub planner: ArmPlanner,
    /// The collision checker planned with.
    #[arg(long, value_enum, default_value = "batch")]
    pub checker: CheckerKind,
    /// Each problem's time limit, in seconds.
    #[arg(long, default_value_t = 1.0)]
    pub time_limit: f64,
    /// The planner's seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The longest motion the tree planners add at once, in joint-space units (radians for
    /// revolute joints). Default: 1.0 for RRT-Connect (VAMP's for the Panda; the planners' own
    /// default, a fifth of the joint space's extent, 2.6 for the Panda, spends long motions near
    /// obstacles), Informed RRT*'s own (a fifth of the extent, as the harness and OMPL run it).
    /// BIT* and PRM* take none.
    #[arg(long)]
    pub range: Option<f64>,
    /// Simplify every path (shortcuts, then corner cutting: `trailmark::sample::simplify`) and
    /// report the time with simplification too; the simplified path is the one checked.
    #[arg(long)]
    pub simplify: bool,
    /// Check every K-th problem of each folder only.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    pub every: u64,
    /// A file to write one JSON line a problem to.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// The robot with its own collision geometry (meshes, primitives): every path that passes
    /// the sphere check is checked again by the exact tier (`ExactChecker`) with it.
    #[arg(long)]
    pub exact: Option<PathBuf>,
    /// Plan with the spheres of `--urdf` covering the geometry of `--exact` (`cover::cover`:
    /// spheres added where it sticks out, all grown by 1 mm), so that the sphere checkers are
    /// conservative for the robot's own shapes.
    #[arg(long, requires = "exact")]
    pub cover: bool,
    /// Plan with spheres made from `--urdf`'s own geometry (`cover::spherize`, 2 mm sampling,
    /// 1 mm tolerance): for a URDF of meshes without a spherized twin.
    #[arg(long, conflicts_with = "cover")]
    pub spherize: bool,
}

/// A planner `verify mbm` and the harness run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ArmPlanner {
    /// RRT-Connect: stops at its first path.
    #[value(name = "rrt_connect")]
    RrtConnect,
    /// Informed RRT*: improves its path until the time limit.
    #[value(name = "informed_rrt_star")]
    InformedRrtStar,
    /// BIT*: improves its path until the time limit.
    #[value(name = "bit_star")]
    BitStar,
    /// PRM*: a roadmap of [`ROADMAP_SIZE`] milestones (its build timed, within the time limit),
    /// then the query on it.
    #[value(name = "prm_star")]
    PrmStar,
}

/// The milestones of [`ArmPlanner::PrmStar`]'s roadmap.
pub const ROADMAP_SIZE: usize = 500;

/// The collision checker planned with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CheckerKind {
    /// Eight configurations at once in `f32` lanes ([`BatchChecker`]).
    Batch,
    /// One configuration at a time in `f64` ([`ArmChecker`]).
    Scalar,
}

/// One problem: its name (`<folder>/<requestNNNN>`), scene and request.
#[derive(Debug, Clone)]
pub struct MbmProblem {
    pub name: String,
    pub scene: PathBuf,
    pub request: PathBuf,
}

/// Every request of `dir` with its scene, in name order.
pub fn problems(dir: &Path) -> Result<Vec<MbmProblem>, String> {
    let mut found = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let entries =
            std::fs::read_dir(&folder).map_err(|e| format!("cannot list {}: {e}", folder.display()))?;
        for entry in entries {
            let path = entry.map_err(|e| e.to_string())?.path();
            let name = path.file_name().unwrap_or_default().to_string_lossy().into_owned();
            if path.is_dir() {
                folders.push(path);
            } else if let Some(number) = name.strip_prefix("request").and_then(|n| n.strip_suffix(".yaml")) {
                let scene = folder.join(format!("scene{number}.yaml"));
                let set = folder.file_name().unwrap_or_default().to_string_lossy().into_owned();
                let name = format!("{set}/request{number}");
                found.push(MbmProblem { name, scene, request: path });
            }
        }
    }
    found.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(found)
}

/// What planning one problem gave.
pub struct Outcome {
    /// `solved`, `no_path`, `stopped` or `error`.
    pub status: &'static str,
    /// Planning time, without reading the files and compiling the checker.
    pub time: Duration,
    /// The time simplifying the path took (zero when it was not asked for).
    pub simplify_time: Duration,
    /// The joint-space length of the planner's path (before simplification; 0 without one).
    pub planned_length: f64,
    /// The length of the path returned (simplified when asked for).
    pub length: f64,
    pub path: Vec<Vec<f64>>,
    /// Validity calls (states and motions) while planning.
    pub checks: u64,
    /// States the batch checker tested while planning (0 with the scalar checker).
    pub states: u64,
    /// The group's joints, in the path's order.
    pub joints: Vec<String>,
    /// Why the path fails the independent check, or the error.
    pub failure: Option<String>,
}

impl Outcome {
    /// A problem that could not be planned, and why.
    pub fn failed(why: String) -> Outcome {
        Outcome {
            status: "error",
            time: Duration::ZERO,
            simplify_time: Duration::ZERO,
            planned_length: 0.0,
            length: 0.0,
            path: Vec::new(),
            checks: 0,
            states: 0,
            joints: Vec::new(),
            failure: Some(why),
        }
    }
}

/// The robot and its semantic description, read once.
pub struct Arm {
    pub robot: Robot,
    pub srdf: Srdf,
}

impl Arm {
    pub fn read(urdf: &Path, srdf: &Path) -> Result<Arm, RobotError> {
        Ok(Arm { robot: Robot::from_file(urdf)?, srdf: Srdf::from_file(srdf)? })
    }
}

/// How `verify mbm` and the harness plan a problem.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// The planner.
    pub planner: ArmPlanner,
    /// The checker planned with.
    pub checker: CheckerKind,
    /// The time limit of a problem.
    pub limit: Duration,
    /// The planner's seed.
    pub seed: u64,
    /// The tree planners' range (`None`: the planner's default, a fifth of the space's extent).
    pub range: Option<f64>,
    /// Whether to simplify the path.
    pub simplify: bool,
}

/// The sampling and tolerance of `--cover` and `--spherize`: 2 mm (1.2 mm for what lies between samples) and
/// 1 mm; coarser covers make the Panda's neighbouring links touch at its home pose.
const COVER_RESOLUTION: f64 = 0.002;
const COVER_TOLERANCE: f64 = 0.001;

/// Random shortcut attempts when simplifying (after the greedy pass).
const SHORTCUT_ATTEMPTS: usize = 20;
/// Corner-cutting passes when simplifying: on the Panda problems two take the median path from
/// 5.42 to 4.93 radians, five to 4.89 at twice the time.
const SMOOTHING_PASSES: usize = 2;

/// A problem read: its scene, the robot's start values, the group's start and goal, the
/// checker planned with and the one a path is checked again by (a tenth of the step).
pub struct Prepared {
    pub scene: Scene,
    /// A value per joint of the robot (the request's start state).
    pub template: Vec<f64>,
    pub start: Vec<f64>,
    pub goal: Vec<f64>,
    pub scalar: ArmChecker,
    pub reference: ArmChecker,
}

impl Prepared {
    /// Reads `problem`'s files and builds its checkers.
    pub fn new(arm: &Arm, problem: &MbmProblem) -> Result<Prepared, RobotError> {
        let scene = Scene::from_file(&problem.scene)?;
        let request = Request::from_file(&problem.request)?;
        let group = arm.robot.group(&arm.srdf, &request.group)?;
        let template = request.start_values(&arm.robot)?;
        let (start, goal) = request.ends(&group)?;
        let scalar = ArmChecker::new(
            arm.robot.clone(),
            &arm.srdf,
            group.clone(),
            &scene,
            template.clone(),
            DEFAULT_STEP,
        )?;
        let reference = ArmChecker::new(
            arm.robot.clone(),
            &arm.srdf,
            group,
            &scene,
            template.clone(),
            DEFAULT_STEP / 10.0,
        )?;
        Ok(Prepared { scene, template, start, goal, scalar, reference })
    }
}

/// Plans `problem` with the settings' kind of checker and checks the path independently.
pub fn solve(arm: &Arm, problem: &MbmProblem, settings: Settings) -> Outcome {
    let error = |e: RobotError| Outcome::failed(e.to_string());
    let Prepared { scalar, reference, start, goal, .. } = match Prepared::new(arm, problem) {
        Ok(s) => s,
        Err(e) => return error(e),
    };
    for (end, q) in [("start", &start), ("goal", &goal)] {
        if let Ok(contacts) = reference.contacts(q)
            && !contacts.is_empty()
        {
            let list: Vec<String> = contacts
                .iter()
                .map(|c| format!("{} with {} ({:.2} mm deep)", c.link, c.with, c.depth * 1e3))
                .collect();
            return Outcome {
                status: "no_path",
                failure: Some(format!("the {end} collides: {}", list.join(", "))),
                ..error(RobotError::Dimension { expected: 0, found: 0 })
            };
        }
    }
    let batch = BatchChecker::new(scalar.clone());
    // A k-d tree over the joints' positions: N coordinates, twice that with continuous joints
    // (their cosines and sines).
    let wraps = scalar.group().wraps.contains(&true);
    let (tested, none) = (|| batch.states(), || 0);
    macro_rules! by_dimension {
        ($($n:literal)*) => {
            match (scalar.group().joints.len(), wraps) {
                $(($n, false) => match settings.checker {
                    CheckerKind::Batch => plan::<$n, $n>(&scalar, &batch, &start, &goal, settings, &tested),
                    CheckerKind::Scalar => plan::<$n, $n>(&scalar, &scalar, &start, &goal, settings, &none),
                },
                ($n, true) => match settings.checker {
                    CheckerKind::Batch => plan::<$n, { 2 * $n }>(&scalar, &batch, &start, &goal, settings, &tested),
                    CheckerKind::Scalar => plan::<$n, { 2 * $n }>(&scalar, &scalar, &start, &goal, settings, &none),
                },)*
                (n, _) => Err(RobotError::Dimension { expected: 7, found: n }),
            }
        };
    }
    let outcome = by_dimension!(1 2 3 4 5 6 7 8 9 10 11 12);
    let mut outcome = match outcome {
        Ok(o) => o,
        Err(e) => return error(e),
    };
    outcome.joints = scalar.group().names.clone();
    if outcome.status == "solved" {
        outcome.failure = check_path(&reference, &outcome.path, &start, &goal);
    }
    outcome
}

/// Plans from `start` to `goal` with `validity`; `tested()` counts the states it tested, read
/// before simplifying. Either checker through `dyn`: one planner compiled for both.
fn plan<const N: usize, const D: usize>(
    scalar: &ArmChecker,
    validity: &dyn trailmark::sample::Validity<Joints<N>>,
    start: &[f64],
    goal: &[f64],
    settings: Settings,
    tested: &dyn Fn() -> u64,
) -> Result<Outcome, RobotError> {
    let space = scalar.joint_space::<N>()?;
    let to = |v: &[f64]| trailmark::robot::nalgebra::SVector::<f64, N>::from_column_slice(v);
    let problem = Problem::new(&space, &validity, to(start), to(goal));
    let nearest = KdNearest::<Joints<N>, D>::new(&space).map_err(|e| RobotError::Invalid {
        element: scalar.group().name.clone(),
        attribute: "limits",
        reason: "a joint space the nearest-neighbour search takes",
        value: e.to_string(),
    })?;
    let options = RrtOptions { range: settings.range, ..RrtOptions::default() };
    let limit = Termination::time(settings.limit);
    let mut planner: Box<dyn Planner<_, _>> = match settings.planner {
        ArmPlanner::RrtConnect => {
            Box::new(RrtConnect::new(nearest).with_seed(settings.seed).with_options(options))
        }
        ArmPlanner::InformedRrtStar => {
            Box::new(InformedRrtStar::new(nearest).with_seed(settings.seed).with_options(options))
        }
        ArmPlanner::BitStar => Box::new(BitStar::new(nearest).with_seed(settings.seed)),
        ArmPlanner::PrmStar => {
            // The roadmap's build is what is timed; the query on it checks that it holds a path.
            let mut prm = Prm::star(nearest).with_seed(settings.seed);
            let clock = Instant::now();
            let grown = prm.grow(&space, &validity, ROADMAP_SIZE, &limit);
            let outcome =
                Outcome { time: clock.elapsed(), states: tested(), ..Outcome::failed(String::new()) };
            match grown {
                Ok(growth) if growth.stop.is_none() => {}
                Ok(_) => return Ok(Outcome { status: "stopped", ..outcome }),
                Err(e) => return Ok(Outcome { status: "no_path", failure: Some(e.to_string()), ..outcome }),
            }
            let result = prm.solve(&problem, &Termination::iterations(0));
            // A whole roadmap without a path between the ends is built, not stopped.
            let outcome = finish(result, outcome, &space, &validity, settings)?;
            return Ok(if outcome.status == "stopped" {
                Outcome { status: "built", ..outcome }
            } else {
                outcome
            });
        }
    };
    let clock = Instant::now();
    let result = planner.solve(&problem, &limit);
    let outcome = Outcome { time: clock.elapsed(), states: tested(), ..Outcome::failed(String::new()) };
    finish(result, outcome, &space, &validity, settings)
}

/// The outcome of a plan: its path (simplified when asked), or why there is none.
fn finish<const N: usize>(
    result: Result<Plan<SVector<f64, N>>, PlanError>,
    mut outcome: Outcome,
    space: &Joints<N>,
    validity: &dyn trailmark::sample::Validity<Joints<N>>,
    settings: Settings,
) -> Result<Outcome, RobotError> {
    let plan = match result {
        Ok(plan) => plan,
        Err(e) => return Ok(Outcome { status: "no_path", failure: Some(e.to_string()), ..outcome }),
    };
    outcome.checks = plan.stats.collision_checks;
    let Some(planned) = plan.path() else {
        return Ok(Outcome { status: "stopped", failure: None, ..outcome });
    };
    let mut path = planned.to_vec();
    if settings.simplify {
        let clock = Instant::now();
        path = simplify(space, &validity, planned, SHORTCUT_ATTEMPTS, SMOOTHING_PASSES, settings.seed);
        outcome.simplify_time = clock.elapsed();
    }
    Ok(Outcome {
        status: "solved",
        failure: None,
        planned_length: paths::length(space, planned),
        length: paths::length(space, &path),
        path: path.iter().map(|q| q.as_slice().to_vec()).collect(),
        ..outcome
    })
}

/// Why `path` fails the independent check, if it does.
pub fn check_path(reference: &ArmChecker, path: &[Vec<f64>], start: &[f64], goal: &[f64]) -> Option<String> {
    if path.first().map(Vec::as_slice) != Some(start) || path.last().map(Vec::as_slice) != Some(goal) {
        return Some("the path does not run from the start to the goal".into());
    }
    let bounds = &reference.group().bounds;
    for q in path {
        if q.iter().zip(bounds).any(|(v, (low, high))| v < low || v > high) {
            return Some(format!("a state beyond the joint limits: {q:?}"));
        }
    }
    for (i, m) in path.windows(2).enumerate() {
        if !reference.motion_is_free(&m[0], &m[1]) {
            return Some(format!("motion {i} collides under the fine check"));
        }
    }
    None
}

/// Why `path` fails the exact check with `robot` (read from `urdf`, meshes beside it), if it
/// does: the first motion a link's own shapes cannot be proven clear along, and what touches
/// at its ends.
pub fn exact_failure(
    robot: &Robot,
    urdf: &Path,
    arm: &Arm,
    problem: &MbmProblem,
    path: &[Vec<f64>],
) -> Option<String> {
    let checker = (|| {
        let scene = Scene::from_file(&problem.scene)?;
        let request = Request::from_file(&problem.request)?;
        let group = robot.group(&arm.srdf, &request.group)?;
        let template = request.start_values(robot)?;
        let dir = urdf.parent().unwrap_or(Path::new("."));
        ExactChecker::new(robot.clone(), &arm.srdf, group, &scene, template, dir, DEFAULT_STEP)
    })();
    let checker = match checker {
        Ok(c) => c,
        Err(e) => return Some(format!("the exact check: {e}")),
    };
    for (i, m) in path.windows(2).enumerate() {
        if !checker.motion_is_free(&m[0], &m[1]) {
            let touching = |q: &[f64]| checker.contacts(q).unwrap_or_default();
            return Some(format!(
                "motion {i} is not clear under the exact check (at its start {:?}, at its end {:?})",
                touching(&m[0]),
                touching(&m[1])
            ));
        }
    }
    None
}

/// `verify mbm`: prints a line a failure and `N passed, M failed`, with the times.
pub fn run(args: &Args) -> ExitCode {
    let problems = match problems(&args.dir) {
        Ok(p) => p,
        Err(e) => return crate::output::error_report(e),
    };
    let mut arm = match Arm::read(&args.urdf, &args.srdf) {
        Ok(a) => a,
        Err(e) => return crate::output::error_report(e),
    };
    if !(args.time_limit.is_finite() && args.time_limit > 0.0) {
        return crate::output::error_report("--time-limit must be a positive number of seconds");
    }
    if args.range.is_some() && matches!(args.planner, ArmPlanner::BitStar | ArmPlanner::PrmStar) {
        return crate::output::error_report("--range is for rrt_connect and informed_rrt_star only");
    }
    let mut out = match &args.out {
        Some(path) => match std::fs::File::create(path) {
            Ok(f) => Some(std::io::BufWriter::new(f)),
            Err(e) => return crate::output::error_report(format!("cannot write {}: {e}", path.display())),
        },
        None => None,
    };
    let exact = match args.exact.as_ref().map(Robot::from_file).transpose() {
        Ok(robot) => robot,
        Err(e) => return crate::output::error_report(e),
    };
    let mut exact_time = 0.0;
    if args.spherize {
        let dir = args.urdf.parent().unwrap_or(Path::new("."));
        match spherize(&arm.robot, dir, COVER_RESOLUTION, COVER_TOLERANCE).and_then(Robot::new) {
            Ok(robot) => {
                let count: usize = robot.urdf().links.iter().map(|l| l.collisions.len()).sum();
                println!("spheres made from the URDF's own geometry: {count}");
                arm.robot = robot;
            }
            Err(e) => return crate::output::error_report(e),
        }
    }
    if let (true, Some(geometry), Some(urdf)) = (args.cover, &exact, &args.exact) {
        let dir = urdf.parent().unwrap_or(Path::new("."));
        let covered = cover(&arm.robot, geometry, dir, COVER_RESOLUTION, COVER_TOLERANCE)
            .and_then(|(urdf, added)| Ok((Robot::new(urdf)?, added)));
        match covered {
            Ok((robot, added)) => {
                println!("covering spheres: {} added", added.iter().sum::<usize>());
                arm.robot = robot;
            }
            Err(e) => return crate::output::error_report(e),
        }
    }
    let settings = Settings {
        planner: args.planner,
        checker: args.checker,
        limit: Duration::from_secs_f64(args.time_limit),
        seed: args.seed,
        range: args.range.or((args.planner == ArmPlanner::RrtConnect).then_some(1.0)),
        simplify: args.simplify,
    };
    let (mut passed, mut failed) = (0u64, 0u64);
    let (mut times, mut with_simplification) = (Vec::new(), Vec::new());
    let (mut planned_lengths, mut lengths) = (Vec::new(), Vec::new());
    let mut checks = 0u64;
    let mut states = 0u64;
    // The time spent planning, each problem at its own time.
    let mut total = 0.0;
    for problem in problems.iter().step_by(args.every as usize) {
        let mut outcome = solve(&arm, problem, settings);
        if let (Some(robot), Some(urdf)) = (&exact, &args.exact)
            && outcome.status == "solved"
            && outcome.failure.is_none()
        {
            let clock = Instant::now();
            outcome.failure = exact_failure(robot, urdf, &arm, problem, &outcome.path);
            exact_time += clock.elapsed().as_secs_f64();
        }
        let ok = outcome.status == "solved" && outcome.failure.is_none();
        if ok {
            passed += 1;
        } else {
            failed += 1;
            println!("{}: {} {}", problem.name, outcome.status, outcome.failure.as_deref().unwrap_or(""));
        }
        // Problems not solved count at the time limit (those refused before planning too).
        let (time, simplified) = if ok {
            (outcome.time, outcome.time + outcome.simplify_time)
        } else {
            (settings.limit.max(outcome.time), settings.limit.max(outcome.time))
        };
        times.push(time.as_secs_f64());
        total += outcome.time.as_secs_f64();
        with_simplification.push(simplified.as_secs_f64());
        if ok {
            planned_lengths.push(outcome.planned_length);
            lengths.push(outcome.length);
        }
        checks += outcome.checks;
        states += outcome.states;
        if let Some(out) = &mut out {
            let line = json!({
                "problem": problem.name,
                "status": if outcome.status == "solved" && outcome.failure.is_some() { "error" } else { outcome.status },
                "time_s": outcome.time.as_secs_f64(),
                "joints": outcome.joints,
                "path": outcome.path,
            });
            if writeln!(out, "{line}").is_err() {
                return crate::output::error_report("cannot write the results");
            }
        }
    }
    let at = |times: &mut Vec<f64>, q: f64| {
        times.sort_by(f64::total_cmp);
        times.get(((times.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0.0) * 1e6
    };
    println!(
        "{passed} passed, {failed} failed; planning time median {:.1} µs, 95th percentile {:.1} µs, max {:.1} µs; {checks} checks, {states} states tested in {total:.3} s",
        at(&mut times, 0.5),
        at(&mut times, 0.95),
        at(&mut times, 1.0),
    );
    println!("path length (joint space, radians) median {:.3}", at(&mut planned_lengths, 0.5) / 1e6);
    if exact.is_some() {
        println!("every path passing was checked by the exact tier too, in {exact_time:.1} s");
    }
    if args.simplify {
        println!(
            "with simplification: median {:.1} µs, 95th percentile {:.1} µs; path length median {:.3}",
            at(&mut with_simplification, 0.5),
            at(&mut with_simplification, 0.95),
            at(&mut lengths, 0.5) / 1e6
        );
    }
    if failed == 0 { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
