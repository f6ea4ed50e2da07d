//! `cargo xtask solve PROBLEM.json`: one problem in, one result document out.

use std::io::Read;
use std::path::Path;
use std::process::ExitCode;

use trailmark::problem::{ErrorReport, Problem};

/// Prints the result of the problem in `path` (or standard input for `-`); on a bad problem,
/// prints `{"status": "error", "error": ...}` and exits with 2.
pub fn run(path: &Path) -> ExitCode {
    match solve(path) {
        Ok(json) => {
            println!("{json}");
            ExitCode::SUCCESS
        }
        Err(message) => {
            let report = serde_json::to_string(&ErrorReport::new(message)).expect("a report serializes");
            println!("{report}");
            ExitCode::from(2)
        }
    }
}

fn solve(path: &Path) -> Result<String, String> {
    let (text, base) = if path == Path::new("-") {
        let mut text = String::new();
        std::io::stdin().read_to_string(&mut text).map_err(|e| format!("cannot read standard input: {e}"))?;
        (text, std::env::current_dir().map_err(|e| e.to_string())?)
    } else {
        let text =
            std::fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        (text, path.parent().map(Path::to_path_buf).unwrap_or_default())
    };
    let problem: Problem =
        serde_json::from_str(&text).map_err(|e| format!("{}: invalid problem: {e}", path.display()))?;
    let result = trailmark::solve::solve(&problem, base).map_err(|e| e.to_string())?;
    serde_json::to_string(&result).map_err(|e| e.to_string())
}
