//! `cargo xtask solve PROBLEM.json`: one problem in, one result document out; `cargo xtask
//! render PROBLEM.json OUT.svg`: the same, and a picture of the world, its graph and the path.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use std::time::Instant;
use trailmark::core::read::{MAX_DOCUMENT_BYTES, read_to_string_capped};

use trailmark::core::grid::{Cell, CornerCutting};
use trailmark::search::Search;
use trailmark::solve::{PreparedGrid, ProblemSpec, RobotWorld, WorldSpec, load_grid};

/// Prints the result of the problem in `path` (or standard input for `-`); on a bad problem,
/// prints `{"status": "error", "error": ...}` and exits with 2.
pub fn run(path: &Path) -> ExitCode {
    match solve(path) {
        Ok(json) => {
            outln!("{json}");
            ExitCode::SUCCESS
        }
        Err(message) => crate::output::error_report(message),
    }
}

/// Solves the problem in `path` (or standard input for `-`), writes its picture to `out` and
/// prints the result; on a bad problem, prints the error report and exits with 2.
pub fn render(path: &Path, out: &Path) -> ExitCode {
    let drawn = read(path).and_then(|(problem, base)| {
        let (result, svg) = trailmark::solve::solve_and_draw(&problem, base).map_err(|e| e.to_string())?;
        std::fs::write(out, svg).map_err(|e| format!("cannot write {}: {e}", out.display()))?;
        serde_json::to_string(&result).map_err(|e| e.to_string())
    });
    match drawn {
        Ok(json) => {
            outln!("{json}");
            errln!("wrote {}", out.display());
            ExitCode::SUCCESS
        }
        Err(message) => crate::output::error_report(message),
    }
}

/// Times `repeat` solves of the problem in `path`, each reading and parsing it (with `prepared`:
/// only the search on its grid, or the plan in its robot world, prepared once) and prints `{"repeat", "median_s", "min_s", "status", "cost"}`.
pub fn time(path: &Path, repeat: usize, prepared: bool) -> ExitCode {
    match time_solves(path, repeat.max(1), prepared) {
        Ok(json) => {
            outln!("{json}");
            ExitCode::SUCCESS
        }
        Err(message) => crate::output::error_report(message),
    }
}

fn time_solves(path: &Path, repeat: usize, prepared: bool) -> Result<String, String> {
    let (problem, base) = read(path)?;
    let mut times = Vec::with_capacity(repeat);
    let mut last = None;
    if let (true, WorldSpec::Robot(world)) = (prepared, &problem.world) {
        if problem.request.is_some() {
            return Err(
                "--prepared takes a robot world's start and goal as joint vectors, not a request".into()
            );
        }
        let robot = RobotWorld::load(world, &base).map_err(|e| e.to_string())?;
        let seed = problem.seed.unwrap_or(0);
        for _ in 0..repeat {
            let clock = Instant::now();
            let result = robot
                .plan(&problem.planner, &problem.start, &problem.goal, seed, None)
                .map_err(|e| e.to_string())?;
            times.push(clock.elapsed().as_secs_f64());
            last = Some(result);
        }
    } else if prepared {
        let WorldSpec::Grid(world) = &problem.world else {
            return Err("--prepared times grid and robot worlds only".into());
        };
        let grid = load_grid(world, &base).map_err(|e| e.to_string())?;
        let rule = if world.corner_cutting { CornerCutting::Allowed } else { CornerCutting::Forbidden };
        let ends = (cell(&problem.start)?, cell(&problem.goal)?);
        let (prepared, mut workspace) = (PreparedGrid::new(grid, world.connectivity, rule), Search::new());
        for _ in 0..repeat {
            let clock = Instant::now();
            let result =
                prepared.search(&mut workspace, &problem.planner, ends).map_err(|e| e.to_string())?;
            times.push(clock.elapsed().as_secs_f64());
            last = Some(result);
        }
    } else {
        for _ in 0..repeat {
            // Read and parsed each time, as a caller with a document in hand does.
            let clock = Instant::now();
            let (problem, base) = read(path)?;
            let result = trailmark::solve::solve(&problem, &base).map_err(|e| e.to_string())?;
            times.push(clock.elapsed().as_secs_f64());
            last = Some(result);
        }
    }
    times.sort_by(f64::total_cmp);
    let result = last.ok_or("nothing was solved")?;
    let report = serde_json::json!({
        "repeat": repeat,
        "median_s": times[times.len() / 2],
        "min_s": times[0],
        "status": result.status,
        "cost": result.cost,
    });
    Ok(report.to_string())
}

/// A grid cell `[x, y]` of a document.
fn cell(value: &[f64]) -> Result<Cell, String> {
    let whole = |v: f64| (v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v)).then_some(v as u32);
    match value {
        [x, y] => match (whole(*x), whole(*y)) {
            (Some(x), Some(y)) => Ok(Cell::new(x, y)),
            _ => Err(format!("{value:?} is not a grid cell")),
        },
        _ => Err(format!("{value:?} is not a grid cell")),
    }
}

fn solve(path: &Path) -> Result<String, String> {
    let (problem, base) = read(path)?;
    let result = trailmark::solve::solve(&problem, base).map_err(|e| e.to_string())?;
    serde_json::to_string(&result).map_err(|e| e.to_string())
}

/// The problem in `path` and the folder its relative paths are relative to.
fn read(path: &Path) -> Result<(ProblemSpec, PathBuf), String> {
    let (text, base) = if path == Path::new("-") {
        let mut text = String::new();
        // At most one byte past the cap, so that an endless input is refused, not read.
        std::io::stdin()
            .take(MAX_DOCUMENT_BYTES + 1)
            .read_to_string(&mut text)
            .map_err(|e| format!("cannot read standard input: {e}"))?;
        if text.len() as u64 > MAX_DOCUMENT_BYTES {
            return Err(format!("standard input is longer than {MAX_DOCUMENT_BYTES} bytes"));
        }
        (text, std::env::current_dir().map_err(|e| e.to_string())?)
    } else {
        let text = read_to_string_capped(path, MAX_DOCUMENT_BYTES).map_err(|e| e.to_string())?;
        (text, path.parent().map(Path::to_path_buf).unwrap_or_default())
    };
    let problem: ProblemSpec =
        serde_json::from_str(&text).map_err(|e| format!("{}: invalid problem: {e}", path.display()))?;
    Ok((problem, base))
}
