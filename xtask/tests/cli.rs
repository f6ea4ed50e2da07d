//! The xtask commands as a user runs them: exit codes and outputs of `solve` and `verify`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn xtask(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_xtask")).args(args).current_dir(dir).output().expect("xtask runs")
}

/// A fresh folder under the target directory's temporary space.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trailmark-xtask-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("stdout is not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)))
}

const MAP: &str = "type octile\nheight 3\nwidth 4\nmap\n....\n.@@.\n....\n";

#[test]
fn solve_prints_a_result() {
    let dir = scratch("solve");
    std::fs::write(dir.join("wall.map"), MAP).unwrap();
    let problems = [
        r#"{"world": {"grid": {"map": "wall.map"}}, "start": [0, 0], "goal": [3, 2], "planner": {"name": "astar"}, "seed": 1}"#,
        r#"{"world": {"grid": {"rows": ["....", ".@@.", "...."], "connectivity": 8, "corner_cutting": false}},
            "start": [0, 0], "goal": [3, 2], "planner": {"name": "dijkstra"}}"#,
    ];
    for text in problems {
        std::fs::write(dir.join("p.json"), text).unwrap();
        let out = xtask(&["solve", "p.json"], &dir);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let v = json(&out);
        assert_eq!(v["status"], "solved");
        assert_eq!(v["cost"], 5.0);
        assert_eq!(v["path"][0], serde_json::json!([0, 0]));
        assert_eq!(v["path"].as_array().unwrap().len(), 6);
        assert!(v["stats"]["expansions"].as_u64().is_some() && v["stats"]["time_s"].as_f64().is_some());
    }
    // No path is a result too.
    std::fs::write(dir.join("p.json"), r#"{"world": {"grid": {"rows": [".@."]}}, "start": [0, 0], "goal": [2, 0], "planner": {"name": "bfs"}}"#).unwrap();
    let out = xtask(&["solve", "p.json"], &dir);
    assert!(out.status.success());
    assert_eq!(
        json(&out),
        serde_json::json!({"status": "no_path", "cost": null, "path": [], "stats": json(&out)["stats"]})
    );
}

#[test]
fn bad_problems_exit_2_with_an_error_document() {
    let dir = scratch("bad");
    std::fs::write(dir.join("wall.map"), MAP).unwrap();
    std::fs::write(dir.join("broken.map"), "type octile\nheight 2\nwidth 2\nmap\n..\n.x\n").unwrap();
    let grid = r#"{"grid": {"rows": ["....", ".@@.", "...."]}}"#;
    let cases = [
        (format!(r#"{{"world": {grid}, "start": [0, 0], "goal": [3, 2], "planner": {{"name": "teleport"}}}}"#), "unknown variant"),
        (format!(r#"{{"world": {grid}, "start": [1, 1], "goal": [3, 2], "planner": {{"name": "astar"}}}}"#), "blocked"),
        (format!(r#"{{"world": {grid}, "start": [0, 0], "goal": [30, 2], "planner": {{"name": "astar"}}}}"#), "outside"),
        (format!(r#"{{"world": {grid}, "goal": [3, 2], "planner": {{"name": "astar"}}}}"#), "the problem needs a \"start\""),
        (r#"{"world": {"grid": {"map": "broken.map"}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "astar"}}"#.into(), "line 6"),
        (r#"{"world": {"grid": {"map": "nowhere.map"}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "astar"}}"#.into(), "nowhere.map"),
        ("{ not json".into(), "invalid problem"),
    ];
    for (text, expected) in cases {
        std::fs::write(dir.join("p.json"), &text).unwrap();
        let out = xtask(&["solve", "p.json"], &dir);
        assert_eq!(out.status.code(), Some(2), "{text}");
        let v = json(&out);
        assert_eq!(v["status"], "error", "{text}");
        let error = v["error"].as_str().unwrap();
        assert!(error.contains(expected), "{text}: {error}");
        assert!(out.stderr.is_empty() || !String::from_utf8_lossy(&out.stderr).contains("panicked"));
    }
    let out = xtask(&["solve", "absent.json"], &dir);
    assert_eq!(out.status.code(), Some(2));
    assert!(json(&out)["error"].as_str().unwrap().contains("absent.json"));
}

/// A MovingAI-shaped folder with one map and a scenario file.
fn benchmark_folder(name: &str, scen: &str) -> PathBuf {
    let dir = scratch(name);
    std::fs::create_dir_all(dir.join("maps/tiny")).unwrap();
    std::fs::create_dir_all(dir.join("scenarios/tiny")).unwrap();
    std::fs::write(dir.join("maps/tiny/wall.map"), MAP).unwrap();
    std::fs::write(dir.join("scenarios/tiny/wall.map.scen"), scen).unwrap();
    dir
}

#[test]
fn verify_counts_and_fails_on_a_wrong_optimum() {
    let good = "version 1\n0\tmaps/tiny/wall.map\t4\t3\t0\t0\t3\t2\t5\n0\tmaps/tiny/wall.map\t4\t3\t0\t1\t3\t1\t5.0\n";
    let dir = benchmark_folder("verify-good", good);
    let out = xtask(&["verify", "movingai", dir.to_str().unwrap(), "--algo", "astar,dijkstra"], &dir);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(stdout.trim_end().ends_with("4 passed, 0 failed"), "{stdout}");

    let wrong = "version 1\n0\tmaps/tiny/wall.map\t4\t3\t0\t0\t3\t2\t4.9\n";
    let dir = benchmark_folder("verify-wrong", wrong);
    let out = xtask(&["verify", "movingai", dir.to_str().unwrap()], &dir);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(stdout.trim_end().ends_with("0 passed, 1 failed"), "{stdout}");
    assert!(stdout.contains("published 4.9"), "{stdout}");

    let out = xtask(&["verify", "movingai", "/nonexistent/folder"], &dir);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(json(&out)["status"], "error");
    let out = xtask(&["verify", "anyangle", "/nonexistent/folder"], &dir);
    assert_eq!((out.status.code(), json(&out)["status"].as_str()), (Some(2), Some("error")));
}

#[test]
fn navigate_compares_the_planners_on_one_world() {
    let dir = scratch("navigate");
    let out = xtask(
        &["navigate", "--size", "48x32", "--seed", "4", "--radius", "2", "--svg", "svg", "--independent"],
        &dir,
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v = json(&out);
    let runs = v["runs"].as_array().unwrap();
    let names: Vec<&str> = runs.iter().map(|r| r["planner"].as_str().unwrap()).collect();
    assert_eq!(names, ["astar", "lpa_star", "dstar_lite", "ad_star"]);
    for run in runs {
        assert_eq!(run["outcome"], "reached", "{run}");
        assert!(run["expansions"].as_u64().unwrap() > 0 && run["planning_time_s"].as_f64().unwrap() > 0.0);
    }
    for name in names {
        let svg = std::fs::read_to_string(dir.join("svg").join(format!("navigate-{name}.svg"))).unwrap();
        assert!(svg.contains("<polyline"));
    }
    // By default the planners share the first one's run.
    let out = xtask(&["navigate", "--size", "48x32", "--seed", "4", "--radius", "2"], &dir);
    let v = json(&out);
    assert_eq!(v["same_run"], true);
    let runs = v["runs"].as_array().unwrap();
    assert!(runs.iter().all(|r| r["steps"] == runs[0]["steps"] && r["distance"] == runs[0]["distance"]));

    // A map file, explicit endpoints, greedy mapping.
    std::fs::write(dir.join("wall.map"), MAP).unwrap();
    let out = xtask(
        &["navigate", "--map", "wall.map", "--start", "0,0", "--goal", "3,2", "--planner", "dstar-lite"],
        &dir,
    );
    assert!(out.status.success());
    assert_eq!(json(&out)["runs"][0]["distance"], 5.0);
    let out = xtask(
        &["navigate", "--map", "wall.map", "--start", "0,0", "--explore", "--planner", "astar,dstar-lite"],
        &dir,
    );
    assert_eq!(json(&out)["runs"][1]["outcome"], "explored");
}

#[test]
fn navigate_errors_are_documents_with_exit_2() {
    let dir = scratch("navigate-errors");
    std::fs::write(dir.join("wall.map"), MAP).unwrap();
    for args in [
        vec!["navigate", "--map", "missing.map"],
        vec!["navigate", "--map", "wall.map", "--start", "1,1", "--goal", "3,2"],
        vec!["navigate", "--map", "wall.map", "--start", "0,0", "--goal", "3,2", "--radius", "0"],
        vec!["navigate", "--size", "16x16", "--planner", "ad-star", "--epsilon", "0.5"],
        vec!["navigate", "--size", "16384x16384"],
        vec!["navigate", "--size", "1x268435456"],
        vec!["navigate", "--size", "16x16", "--planner", "nope"],
        vec!["navigate", "--no-such-flag"],
    ] {
        let out = xtask(&args, &dir);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(json(&out)["status"], "error", "{args:?}");
    }
    let error = |args: &[&str]| json(&xtask(args, &dir))["error"].as_str().unwrap_or_default().to_string();
    // A negative number is a value to refuse, not an unknown flag.
    let negative = error(&["navigate", "--size", "16x16", "--density", "-0.5"]);
    assert!(negative.contains("-0.5") && !negative.contains("unexpected argument"), "{negative}");
    // A planner that does not replan is named as such, not for its heuristic.
    let theta = error(&["navigate", "--size", "16x16", "--planner", "theta_star"]);
    assert!(theta.contains("does not replan") && theta.contains("mpgaa_star"), "{theta}");
    assert!(error(&["navigate", "--size", "16384x16384"]).contains("at most 16777216 cells"));
}

/// Every subcommand reports bad input the same way: exit 2 and an error document on stdout.
#[test]
fn contingency_errors_are_documents_with_exit_2() {
    let dir = scratch("contingency-errors");
    std::fs::write(dir.join("bad.json"), r#"{"rows": ["..."], "surprise": 1}"#).unwrap();
    for args in [vec!["contingency", "missing.json"], vec!["contingency", "bad.json"], vec!["contingency"]] {
        let out = xtask(&args, &dir);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(json(&out)["status"], "error", "{args:?}");
    }
}

/// `--cell NaN` (or any size that is not a positive number of pixels) is refused.
#[test]
fn contingency_refuses_a_cell_size_that_is_not_a_size() {
    let dir = scratch("contingency-cell");
    for cell in ["NaN", "0", "-3", "inf", "1e9"] {
        let out = xtask(&["contingency", "--generate", "1", "--summary", &format!("--cell={cell}")], &dir);
        assert_eq!(out.status.code(), Some(2), "--cell {cell}");
        let error = json(&out)["error"].as_str().unwrap_or_default().to_string();
        assert!(error.contains("pixels per cell"), "--cell {cell}: {error}");
    }
}

/// Output into a full disk (or a closed pipe) ends with a message and exit 74, not a panic.
#[test]
fn a_full_standard_output_is_an_error_not_a_panic() {
    let Ok(full) = std::fs::File::create("/dev/full") else {
        eprintln!("skipped: /dev/full is not available here");
        return;
    };
    let dir = scratch("full");
    std::fs::write(dir.join("wall.map"), MAP).unwrap();
    std::fs::write(
        dir.join("p.json"),
        r#"{"world": {"grid": {"map": "wall.map"}}, "start": [0, 0], "goal": [3, 2], "planner": {"name": "astar"}}"#,
    )
    .unwrap();
    for args in [vec!["solve", "p.json"], vec!["solve", "missing.json"], vec!["navigate", "--size", "16x16"]]
    {
        let out = Command::new(env!("CARGO_BIN_EXE_xtask"))
            .args(&args)
            .current_dir(&dir)
            .stdout(full.try_clone().unwrap())
            .output()
            .expect("xtask runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(74), "{args:?}: {stderr}");
        assert!(stderr.contains("cannot write to standard output"), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
}

/// Files that are not documents: a device that never ends, a FIFO nobody writes to, a folder,
/// and a map that is some other file. Each is refused promptly with an error document, and no
/// message quotes the file's content.
#[test]
fn files_that_are_not_documents_are_refused_promptly() {
    let dir = scratch("not-documents");
    let fifo = dir.join("fifo");
    let made_fifo = Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success());
    std::fs::write(dir.join("secret.map"), "root:x:0:0:secret-content\n").unwrap();
    let naming = |map: &str| {
        format!(
            r#"{{"world": {{"grid": {{"map": "{map}"}}}}, "start": [0, 0], "goal": [1, 0], "planner": {{"name": "astar"}}}}"#
        )
    };
    std::fs::write(dir.join("zero-map.json"), naming("/dev/zero")).unwrap();
    std::fs::write(dir.join("fifo-map.json"), naming("fifo")).unwrap();
    std::fs::write(dir.join("secret-map.json"), naming("secret.map")).unwrap();
    let mut cases = vec![
        vec!["solve", "/dev/zero"],
        vec!["solve", "."],
        vec!["solve", "zero-map.json"],
        vec!["solve", "secret-map.json"],
        vec!["contingency", "/dev/zero"],
        vec!["navigate", "--map", "/dev/zero"],
        vec!["navigate", "--map", "secret.map"],
    ];
    if made_fifo {
        cases.extend([
            vec!["solve", "fifo"],
            vec!["solve", "fifo-map.json"],
            vec!["navigate", "--map", "fifo"],
        ]);
    } else {
        eprintln!("mkfifo is not available: the FIFO cases are skipped");
    }
    for args in cases {
        let clock = std::time::Instant::now();
        let out = xtask(&args, &dir);
        assert!(clock.elapsed().as_secs() < 30, "{args:?} took {:?}", clock.elapsed());
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let report = json(&out);
        assert_eq!(report["status"], "error", "{args:?}");
        assert!(!report["error"].as_str().unwrap().contains("secret-content"), "{args:?}: {report}");
    }
}
