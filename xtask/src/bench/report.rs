//! Writing the report: the goals table every section contributes a row to, the versions and
//! date of the header, and the report's folder (`report.md`, `results.json`, the figures and the
//! OMPL-format logs).

use std::path::Path;

use trailmark::sample::benchmark::{Experiment, log};

use crate::bench::stats::geometric_mean;

/// A figure of the report: its file name and SVG document.
pub type Figure = (&'static str, String);

/// One goal of the report and the figures measured for it.
pub struct GoalRow {
    /// What the goal asks.
    pub goal: &'static str,
    /// The measured figure of each case (none: not measured in this run).
    pub figures: Vec<(String, f64)>,
    /// The least figure that meets the goal.
    pub target: f64,
    /// The unit written after each figure.
    pub unit: &'static str,
    /// How to measure the goal when it was not.
    pub missing: &'static str,
}

impl GoalRow {
    /// The row of the goals table: the figures measured and whether the lowest reaches the
    /// target.
    fn markdown(&self) -> String {
        let (goal, unit) = (self.goal, self.unit);
        let Some(lowest) = self.figures.iter().min_by(|a, b| a.1.total_cmp(&b.1)) else {
            return format!("| {goal} | not measured: {} | - |\n", self.missing);
        };
        let mean = geometric_mean(self.figures.iter().map(|f| f.1));
        let met = lowest.1 >= self.target;
        format!(
            "| {goal} | geometric mean {mean:.2}{unit} over {} cases; lowest {:.2}{unit} ({}) | {} |\n",
            self.figures.len(),
            lowest.1,
            lowest.0,
            if met { "**met**" } else { "**not met**" }
        )
    }
}

/// The goals of the benchmark with the measured figure beside each.
pub fn goals_markdown(goals: &[GoalRow]) -> String {
    let mut s = String::from("## Goals\n\n| goal | measured | status |\n|---|---|---|\n");
    for goal in goals {
        s.push_str(&goal.markdown());
    }
    s.push_str(
        "\nA goal is met when its lowest case reaches it. Where one is not, the sections below give the \
         figures behind it (expansions, iterations, collision checks per query), and docs/benchmarks.md \
         the profile.\n\n",
    );
    s
}

/// A markdown table: its header line, its alignment line (`---` a column of text, `---:` one of
/// figures) and the line `line` writes for each of `rows`, every line given without its newline.
pub fn table<T>(
    header: &str,
    align: &str,
    rows: impl IntoIterator<Item = T>,
    line: impl Fn(T) -> String,
) -> String {
    let mut s = format!("{header}\n{align}\n");
    for row in rows {
        s.push_str(&line(row));
        s.push('\n');
    }
    s
}

/// The locked versions of `names`, read from the workspace's Cargo.lock.
pub fn locked_versions(names: &[&str]) -> Vec<(String, String)> {
    let lock = std::fs::read_to_string(crate::workspace::root().join("Cargo.lock")).unwrap_or_default();
    let mut lines = lock.lines();
    let mut out = Vec::new();
    while let Some(line) = lines.next() {
        let Some(name) = line.strip_prefix("name = \"").and_then(|l| l.strip_suffix('"')) else { continue };
        if names.contains(&name) {
            let version =
                lines.next().and_then(|l| l.strip_prefix("version = \"")).map(|v| v.trim_end_matches('"'));
            out.push((name.to_string(), version.unwrap_or("?").to_string()));
        }
    }
    out
}

/// Today's date (UTC) as YYYY-MM-DD, from the days since 1970 (Hinnant's civil-from-days).
pub fn today() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// Writes the report's folder: `report.md`, the figures, `ompl/<experiment>.log` for each of
/// `logs` (for ompl_benchmark_statistics and Planner Arena) and `results.json`.
pub fn write_folder(
    folder: &Path,
    markdown: &str,
    figures: &[Figure],
    logs: &[Experiment],
    json: &str,
) -> std::io::Result<()> {
    std::fs::create_dir_all(folder)?;
    std::fs::write(folder.join("report.md"), markdown)?;
    for (name, svg) in figures {
        std::fs::write(folder.join(name), svg)?;
    }
    let ompl = folder.join("ompl");
    std::fs::create_dir_all(&ompl)?;
    for e in logs {
        std::fs::write(ompl.join(format!("{}.log", e.name)), log::write(e))?;
    }
    std::fs::write(folder.join("results.json"), json)
}
