//! `cargo xtask navigate`: the unknown-terrain simulation from the command line, every chosen
//! planner on the same run, a JSON summary on stdout and optional SVGs.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args as ClapArgs, ValueEnum};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::generate;
use trailmark::movingai;
use trailmark::navigate::{Navigation, NavigationReport, Target, navigate, navigate_together};
use trailmark::prelude::*;
use trailmark::solve::{AnytimeSpec, PlannerSpec};

/// A generated map kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Generator {
    /// Random obstacles (`--density` of the cells).
    Random,
    /// A maze with corridors `--corridor` cells wide.
    Maze,
    /// Rooms `--room` cells wide joined by doors.
    Rooms,
}

/// The arguments of `cargo xtask navigate`.
#[derive(Debug, ClapArgs)]
pub struct Args {
    /// A MovingAI map file (otherwise a map is generated).
    #[arg(long)]
    map: Option<PathBuf>,
    /// The kind of map to generate without --map.
    #[arg(long, value_enum, default_value = "random")]
    generate: Generator,
    /// Width and height of a generated map.
    #[arg(long, default_value = "128x128", value_parser = parse_size)]
    size: (usize, usize),
    /// The obstacle fraction of a random map.
    #[arg(long, default_value_t = 0.25, allow_negative_numbers = true)]
    density: f64,
    /// Corridor width of a maze.
    #[arg(allow_negative_numbers = true, long, default_value_t = 4)]
    corridor: u32,
    /// Room width of a rooms map.
    #[arg(allow_negative_numbers = true, long, default_value_t = 16)]
    room: u32,
    /// The seed of the generated map and of the chosen start and goal.
    #[arg(allow_negative_numbers = true, long, default_value_t = 1)]
    seed: u64,
    /// The start cell `x,y` (default: chosen from the seed).
    #[arg(long, value_parser = parse_cell)]
    start: Option<Cell>,
    /// The goal cell `x,y` (default: chosen from the seed, far from the start).
    #[arg(long, value_parser = parse_cell)]
    goal: Option<Cell>,
    /// Greedy mapping instead of a goal: visit every reachable cell.
    #[arg(long, conflicts_with = "goal")]
    explore: bool,
    /// Sensor radius in cells (a square window).
    #[arg(allow_negative_numbers = true, long, default_value_t = 1)]
    radius: u32,
    /// The planners to run, each on the same world (comma-separated names of the solve
    /// registry's planners that replan: astar, lpa_star, dstar_lite, ad_star, adaptive_astar, mpgaa_star).
    #[arg(long, value_delimiter = ',', default_value = "astar,lpa_star,dstar_lite,ad_star", value_parser = parse_planner)]
    planner: Vec<PlannerSpec>,
    /// AD*'s initial inflation.
    #[arg(long, default_value_t = 3.0, allow_negative_numbers = true)]
    epsilon: f64,
    /// AD*'s inflation decrease per iteration.
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    epsilon_step: f64,
    /// AD*'s expansion budget per step (default: improve to epsilon 1 at every step).
    #[arg(allow_negative_numbers = true, long)]
    expansions_per_step: Option<u64>,
    /// An obstacle following the robot this many steps behind.
    #[arg(allow_negative_numbers = true, long)]
    follower: Option<u32>,
    /// Write the SVG of each run into this folder.
    #[arg(long)]
    svg: Option<PathBuf>,
    /// Let each planner drive its own robot. By default the first planner drives and the others
    /// are run along its trajectory, planning from the same cells with the same knowledge.
    #[arg(long)]
    independent: bool,
}

fn parse_size(s: &str) -> Result<(usize, usize), String> {
    let (w, h) = s.split_once('x').ok_or("expected WIDTHxHEIGHT, e.g. 128x128")?;
    let w: usize = w.parse().map_err(|e| format!("width: {e}"))?;
    let h: usize = h.parse().map_err(|e| format!("height: {e}"))?;
    // Refused before the world is generated: the generator would allocate it first.
    let max = trailmark::navigate::MAX_NAVIGATION_CELLS;
    if w.checked_mul(h).is_none_or(|cells| cells > max) {
        return Err(format!("{w}x{h} is too large to navigate: at most {max} cells (4096x4096)"));
    }
    Ok((w, h))
}

fn parse_cell(s: &str) -> Result<Cell, String> {
    let (x, y) = s.split_once(',').ok_or("expected x,y, e.g. 3,7")?;
    let x = x.trim().parse().map_err(|e| format!("x: {e}"))?;
    let y = y.trim().parse().map_err(|e| format!("y: {e}"))?;
    Ok(Cell::new(x, y))
}

/// One planner's run in the summary.
#[derive(Debug, Serialize)]
pub struct RunSummary {
    /// The planner.
    pub planner: String,
    /// How the run ended.
    pub outcome: trailmark::navigate::NavigationOutcome,
    /// Moves made.
    pub steps: usize,
    /// Cost of the trajectory.
    pub distance: f64,
    /// Plans made.
    pub plans: usize,
    /// Expansions over all plans.
    pub expansions: u64,
    /// Planning time over all plans, seconds.
    pub planning_time_s: f64,
    /// Mean planning time per plan, seconds.
    pub mean_plan_time_s: f64,
    /// Longest plan, seconds.
    pub max_plan_time_s: f64,
    /// Cells found different from the robot's map.
    pub discoveries: usize,
}

impl From<&NavigationReport> for RunSummary {
    fn from(r: &NavigationReport) -> Self {
        RunSummary {
            planner: r.planner.clone(),
            outcome: r.outcome,
            steps: r.steps,
            distance: r.distance,
            plans: r.plans,
            expansions: r.expansions,
            planning_time_s: r.planning_time.as_secs_f64(),
            mean_plan_time_s: r.mean_plan_time().as_secs_f64(),
            max_plan_time_s: r.max_plan_time.as_secs_f64(),
            discoveries: r.discoveries,
        }
    }
}

#[derive(Debug, Serialize)]
struct Summary {
    map: String,
    width: u32,
    height: u32,
    start: Cell,
    goal: Option<Cell>,
    sensor_radius: u32,
    follower: Option<u32>,
    seed: u64,
    /// Whether the planners planned along the first planner's trajectory (the same problems).
    same_run: bool,
    runs: Vec<RunSummary>,
}

/// A planner of the solve registry by its document name (`lpa-star` is read as `lpa_star`).
fn parse_planner(name: &str) -> Result<PlannerSpec, String> {
    let name = name.trim().replace('-', "_");
    serde_json::from_value(serde_json::json!({ "name": name })).map_err(|e| e.to_string())
}

/// The planner with the command line's AD* settings, when it is AD*.
fn with_ad_star_settings(planner: &PlannerSpec, args: &Args) -> PlannerSpec {
    match planner {
        PlannerSpec::AdStar(spec) => PlannerSpec::AdStar(AnytimeSpec {
            epsilon: Some(args.epsilon),
            epsilon_step: Some(args.epsilon_step),
            max_expansions: args.expansions_per_step,
            ..*spec
        }),
        other => other.clone(),
    }
}

fn simulate(args: &Args) -> Result<String, String> {
    let (name, truth) = match &args.map {
        Some(path) => (path.display().to_string(), movingai::read_map(path).map_err(|e| e.to_string())?),
        None => {
            let (w, h) = args.size;
            let grid = match args.generate {
                Generator::Random => generate::random(w, h, args.density, args.seed),
                Generator::Maze => generate::maze(w, h, args.corridor, args.seed),
                Generator::Rooms => generate::rooms(w, h, args.room, args.seed),
            };
            (
                format!("{:?}-{w}x{h}-s{}", args.generate, args.seed).to_lowercase(),
                grid.map_err(|e| e.to_string())?,
            )
        }
    };
    let mut rng = ChaCha8Rng::seed_from_u64(args.seed);
    let (start, goal) = match (args.start, args.goal) {
        (Some(s), Some(g)) => (s, Some(g)),
        (Some(s), None) if args.explore => (s, None),
        _ => {
            let (s, g) = crate::region::endpoints(&truth, &mut rng).ok_or("the map has no passable cell")?;
            (args.start.unwrap_or(s), if args.explore { None } else { Some(args.goal.unwrap_or(g)) })
        }
    };
    let prior = Grid::new(truth.width() as usize, truth.height() as usize).map_err(|e| e.to_string())?;
    let target = goal.map_or(Target::Explore, Target::Cell);
    let choices: Vec<PlannerSpec> = args.planner.iter().map(|p| with_ad_star_settings(p, args)).collect();
    let config = |planner| Navigation {
        planner,
        sensor_radius: args.radius,
        follower_lag: args.follower,
        max_steps: None,
    };
    let reports: Vec<NavigationReport> = if args.independent {
        choices
            .iter()
            .map(|p| navigate(&truth, &prior, start, target, &config(p.clone())))
            .collect::<Result<_, _>>()
            .map_err(|e| e.to_string())?
    } else {
        let (driver, others) = choices.split_first().ok_or("no planner")?;
        navigate_together(&truth, &prior, start, target, &config(driver.clone()), others)
            .map_err(|e| e.to_string())?
    };
    if let Some(dir) = &args.svg {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        // On one run every planner shares the driver's trajectory: one picture says it all.
        for report in if args.independent { &reports[..] } else { &reports[..1] } {
            let file = dir.join(format!("navigate-{}.svg", report.planner));
            std::fs::write(&file, report.svg(&truth, goal))
                .map_err(|e| format!("{}: {e}", file.display()))?;
        }
    }
    let runs: Vec<RunSummary> = reports.iter().map(RunSummary::from).collect();
    let summary = Summary {
        map: name,
        width: truth.width(),
        height: truth.height(),
        start,
        goal,
        sensor_radius: args.radius,
        follower: args.follower,
        seed: args.seed,
        same_run: !args.independent,
        runs,
    };
    serde_json::to_string_pretty(&summary).map_err(|e| e.to_string())
}

/// Runs the simulation and prints the summary, or an error document with exit code 2.
pub fn run(args: &Args) -> ExitCode {
    match simulate(args) {
        Ok(json) => {
            outln!("{json}");
            ExitCode::SUCCESS
        }
        Err(message) => crate::output::error_report(message),
    }
}
