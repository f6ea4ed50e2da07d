//! `cargo xtask solve PROBLEM.json`: one problem in, one result document out; `cargo xtask
//! render PROBLEM.json OUT.svg`: the same, and a picture of the world, its graph and the path.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use trailmark::core::read::{MAX_DOCUMENT_BYTES, read_to_string_capped};
use trailmark::solve::ProblemSpec;

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
