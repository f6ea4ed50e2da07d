//! Benchmark logs in OMPL's format, so that OMPL's `ompl_benchmark_statistics` script turns
//! trailmark's runs (and OMPL's, side by side) into the database Planner Arena reads.
//!
//! One log holds one experiment (one world and its queries): a header, then for each planner
//! its run properties (`NAME TYPE` lines), one line per run (`value; ` for each property) and,
//! for optimizing planners, the progress of each run (`time,best cost,;` samples), then `.`.

use std::fmt::Write;

use super::RunRecord;

/// A planner's runs in an experiment.
#[derive(Debug, Clone)]
pub struct PlannerRuns {
    /// The planner's name in the log, e.g. `trailmark_RRTConnect`.
    pub name: String,
    /// Whether to log the progress of each run.
    pub optimizing: bool,
    /// The runs.
    pub runs: Vec<RunRecord>,
}

/// One experiment: one world, its queries, and the planners run on them.
#[derive(Debug, Clone)]
pub struct Experiment {
    /// The experiment's name.
    pub name: String,
    /// What was run, in words (the log's setup text).
    pub setup: String,
    /// The seed.
    pub seed: u64,
    /// The longest a run may take, seconds.
    pub time_limit_s: f64,
    /// The date, `YYYY-MM-DD`.
    pub date: String,
    /// The planners.
    pub planners: Vec<PlannerRuns>,
}

/// The property names and types of every run, in the order of the run lines.
const PROPERTIES: [&str; 9] = [
    "time REAL",
    "solved BOOLEAN",
    "approximate solution BOOLEAN",
    "status ENUM",
    "memory REAL",
    "graph states INTEGER",
    "solution length REAL",
    "iterations INTEGER",
    "collision checks INTEGER",
];

/// The status enum, as OMPL's `PlannerStatus` numbers it.
const STATUS: &str = "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|Approximate solution|Exact solution|Crash|Abort|Infeasible";

fn status(run: &RunRecord) -> u8 {
    match (run.solved, run.approximate) {
        (true, _) => 6,
        (false, true) => 5,
        (false, false) => 4,
    }
}

fn value(v: Option<f64>) -> String {
    v.filter(|v| v.is_finite()).map_or_else(|| "nan".into(), |v| format!("{v}"))
}

/// The experiment as an OMPL benchmark log.
pub fn write(e: &Experiment) -> String {
    let mut s = String::new();
    let total: f64 = e.planners.iter().flat_map(|p| &p.runs).map(|r| r.time_s).sum();
    let runs = e.planners.iter().map(|p| p.runs.len()).max().unwrap_or(0);
    // Writing to a String cannot fail.
    let _ = writeln!(s, "trailmark version {}", env!("CARGO_PKG_VERSION"));
    let _ = writeln!(s, "Experiment {}", e.name.replace(char::is_whitespace, "_"));
    let _ = writeln!(s, "0 experiment properties");
    let _ = writeln!(s, "Running on {}", hostname());
    let _ = writeln!(s, "Starting at {} 00:00:00", e.date);
    let _ = writeln!(s, "<<<|\n{}\n|>>>", e.setup.trim_end());
    let _ =
        writeln!(s, "<<<|\n{} core(s)\n|>>>", std::thread::available_parallelism().map_or(1, |n| n.get()));
    let _ = writeln!(s, "{} is the random seed", e.seed);
    let _ = writeln!(s, "{} seconds per run", e.time_limit_s);
    let _ = writeln!(s, "0 MB per run");
    let _ = writeln!(s, "{runs} runs per planner");
    let _ = writeln!(s, "{total} seconds spent to collect the data");
    let _ = writeln!(s, "1 enum type");
    let _ = writeln!(s, "{STATUS}");
    let _ = writeln!(s, "{} planners", e.planners.len());
    for p in &e.planners {
        let _ = writeln!(s, "{}", p.name.replace(char::is_whitespace, "_"));
        let _ = writeln!(s, "0 common properties");
        let _ = writeln!(s, "{} properties for each run", PROPERTIES.len());
        for prop in PROPERTIES {
            let _ = writeln!(s, "{prop}");
        }
        let _ = writeln!(s, "{} runs", p.runs.len());
        for r in &p.runs {
            let fields = [
                format!("{}", r.time_s),
                u8::from(r.solved).to_string(),
                u8::from(r.approximate).to_string(),
                status(r).to_string(),
                value(r.memory_bytes.map(|b| b as f64 / 1_048_576.0)),
                r.graph_states.to_string(),
                value(r.solution_length),
                r.iterations.to_string(),
                r.collision_checks.to_string(),
            ];
            for f in fields {
                let _ = write!(s, "{f}; ");
            }
            s.push('\n');
        }
        if p.optimizing {
            let _ = writeln!(s, "2 progress properties for each run");
            let _ = writeln!(s, "time REAL");
            let _ = writeln!(s, "best cost REAL");
            let _ = writeln!(s, "{} runs", p.runs.len());
            for r in &p.runs {
                for (t, c) in &r.progress {
                    let _ = write!(s, "{t},{c},;");
                }
                s.push('\n');
            }
        }
        s.push_str(".\n");
    }
    s
}

fn hostname() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .map(|h| h.trim().to_string())
        .ok()
        .filter(|h| !h.is_empty() && !h.contains(char::is_whitespace))
        .unwrap_or_else(|| "localhost".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reader that follows the grammar OMPL's statistics script reads (ompl/scripts/
    /// ompl_benchmark_statistics.py, `readBenchmarkLog`): token positions, counts and
    /// terminators as that script expects them. Returns per planner its name and run rows.
    /// A planner as read back: its name, its run rows, and how many runs had progress lines.
    type Parsed = (String, Vec<Vec<String>>, usize);

    fn parse(log: &str) -> Result<Vec<Parsed>, String> {
        let mut lines = log.lines().peekable();
        let mut next = || lines.next().ok_or("unexpected end of log");
        let tokens = |l: &str| l.split_whitespace().map(str::to_string).collect::<Vec<_>>();
        let first = tokens(next()?);
        if first.get(1).map(String::as_str) != Some("version") {
            return Err("no version line".into());
        }
        let exp = tokens(next()?);
        if exp.first().map(String::as_str) != Some("Experiment") || exp.len() != 2 {
            return Err("no experiment name".into());
        }
        let props = tokens(next()?);
        if props[props.len() - 2..] != ["experiment", "properties"] || props[0] != "0" {
            return Err("experiment properties".into());
        }
        if !next()?.starts_with("Running on ") || !next()?.starts_with("Starting") {
            return Err("host or date".into());
        }
        for _ in 0..2 {
            if next()? != "<<<|" {
                return Err("multiline value".into());
            }
            while next()? != "|>>>" {}
        }
        let expect = |l: &str, tail: &[&str]| -> Result<String, String> {
            let t = tokens(l);
            if t.len() <= tail.len() || t[t.len() - tail.len()..] != *tail {
                return Err(format!("expected '... {}' in '{l}'", tail.join(" ")));
            }
            Ok(t[0].clone())
        };
        expect(next()?, &["random", "seed"])?.parse::<u64>().map_err(|e| e.to_string())?;
        expect(next()?, &["seconds", "per", "run"])?.parse::<f64>().map_err(|e| e.to_string())?;
        expect(next()?, &["MB", "per", "run"])?.parse::<f64>().map_err(|e| e.to_string())?;
        expect(next()?, &["runs", "per", "planner"])?.parse::<usize>().map_err(|e| e.to_string())?;
        expect(next()?, &["collect", "the", "data"])?.parse::<f64>().map_err(|e| e.to_string())?;
        let enums: usize = expect(next()?, &["enum", "type"])?.parse().map_err(|_| "enum count")?;
        for _ in 0..enums {
            if next()?.split('|').count() < 2 {
                return Err("enum line".into());
            }
        }
        let planners: usize = expect(next()?, &["planners"])?.parse().map_err(|_| "planner count")?;
        let mut out = Vec::new();
        for _ in 0..planners {
            let name = next()?.to_string();
            let common: usize = tokens(next()?)[0].parse().map_err(|_| "common count")?;
            for _ in 0..common {
                next()?;
            }
            let count: usize = tokens(next()?)[0].parse().map_err(|_| "property count")?;
            for _ in 0..count {
                let field = tokens(next()?);
                let kind = field.last().ok_or("empty property")?;
                if !["REAL", "BOOLEAN", "INTEGER", "ENUM", "VARCHAR(128)"].contains(&kind.as_str()) {
                    return Err(format!("property type {kind}"));
                }
            }
            let runs: usize = tokens(next()?)[0].parse().map_err(|_| "run count")?;
            let mut rows = Vec::new();
            for _ in 0..runs {
                let line = next()?;
                // The script splits on "; " and drops the piece after the last separator.
                let mut values: Vec<String> = line.split("; ").map(str::to_string).collect();
                values.pop();
                if values.len() != count {
                    return Err(format!("{} values for {count} properties: '{line}'", values.len()));
                }
                rows.push(values);
            }
            let mut progress_runs = 0;
            let after = next()?.trim().to_string();
            if after != "." {
                let n: usize = tokens(&after)[0].parse().map_err(|_| "progress property count")?;
                for _ in 0..n {
                    next()?;
                }
                progress_runs = tokens(next()?)[0].parse().map_err(|_| "progress run count")?;
                for _ in 0..progress_runs {
                    for sample in next()?.split(';').filter(|s| !s.is_empty()) {
                        let mut parts: Vec<&str> = sample.split(',').collect();
                        parts.pop();
                        if parts.len() != n || parts.iter().any(|p| p.parse::<f64>().is_err()) {
                            return Err(format!("progress sample '{sample}'"));
                        }
                    }
                }
                if next()?.trim() != "." {
                    return Err("no '.' after the progress".into());
                }
            }
            out.push((name, rows, progress_runs));
        }
        if lines.next().is_some() {
            return Err("text after the last planner".into());
        }
        Ok(out)
    }

    #[test]
    fn logs_follow_the_grammar_of_the_statistics_script() {
        let run = |solved: bool, progress: Vec<(f64, f64)>| RunRecord {
            time_s: 0.25,
            solved,
            approximate: !solved,
            memory_bytes: solved.then_some(2_097_152),
            graph_states: 120,
            solution_length: solved.then_some(12.5),
            iterations: 300,
            collision_checks: 410,
            progress,
            ..RunRecord::default()
        };
        let e = Experiment {
            name: "narrow 3".into(),
            setup: "a world\nof walls".into(),
            seed: 7,
            time_limit_s: 10.0,
            date: "2026-11-23".into(),
            planners: vec![
                PlannerRuns {
                    name: "trailmark_RRTConnect".into(),
                    optimizing: false,
                    runs: vec![run(true, vec![]), run(false, vec![])],
                },
                PlannerRuns {
                    name: "OMPL RRTstar".into(),
                    optimizing: true,
                    runs: vec![run(true, vec![(0.1, 14.0), (0.2, 12.5)]), run(false, vec![])],
                },
            ],
        };
        let log = write(&e);
        let parsed = parse(&log).unwrap_or_else(|err| panic!("{err}\n{log}"));
        assert_eq!(parsed.len(), 2);
        assert_eq!(parsed[0].0, "trailmark_RRTConnect");
        assert_eq!(parsed[1].0, "OMPL_RRTstar");
        assert_eq!(parsed[1].2, 2);
        // time, solved, approximate, status, memory (MB), states, length, iterations, checks
        assert_eq!(parsed[0].1[0], ["0.25", "1", "0", "6", "2", "120", "12.5", "300", "410"]);
        assert_eq!(parsed[0].1[1], ["0.25", "0", "1", "5", "nan", "120", "nan", "300", "410"]);
        assert!(log.contains("\n1 enum type\nstatus|Unknown status|"));
    }

    #[test]
    fn the_reader_refuses_a_broken_log() {
        let e = Experiment {
            name: "w".into(),
            setup: "s".into(),
            seed: 1,
            time_limit_s: 1.0,
            date: "2026-11-23".into(),
            planners: vec![PlannerRuns {
                name: "p".into(),
                optimizing: false,
                runs: vec![RunRecord { solved: true, ..RunRecord::default() }],
            }],
        };
        let log = write(&e);
        assert!(parse(&log).is_ok());
        // A run line missing its last separator, a missing terminator, a bad count.
        assert!(parse(&log.replacen("0; \n.", "0\n.", 1)).is_err());
        assert!(parse(log.trim_end_matches(".\n")).is_err());
        assert!(parse(&log.replace("1 planners", "2 planners")).is_err());
    }
}
