//! The registry is the one list of planners: the fuzzer draws its documents' planners from it
//! and its dictionary knows every name, so a registered planner cannot be left out of either.
//! (The harness holds its half in `xtask`: `every_registered_planner_is_measured`.)

use std::fs;
use std::path::Path;

use trailmark::solve::PlannerName;

fn read(path: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn the_fuzzer_draws_every_registered_planner() {
    // The generator's files, read as one.
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/src/generate");
    let mut files: Vec<_> =
        fs::read_dir(&folder).expect("fuzz/src/generate/").map(|e| e.expect("an entry").path()).collect();
    files.sort();
    let generator: String = files
        .iter()
        .map(|f| fs::read_to_string(f).unwrap_or_else(|e| panic!("{}: {e}", f.display())))
        .collect();
    assert!(files.len() > 1 && generator.contains("fn planner_spec"), "the generator's files are read");
    assert!(
        generator.contains("u.choose(PlannerName::ALL)"),
        "fuzz/src/generate/ draws its planners from the registry's list"
    );
    assert!(!generator.contains("enum PlannerName"), "the fuzzer keeps no list of its own");
    for planner in PlannerName::ALL {
        assert!(
            generator.contains(&format!("PlannerName::{planner:?}")),
            "fuzz/src/generate/ gives {planner} no settings"
        );
    }
}

#[test]
fn the_fuzzers_dictionary_knows_every_registered_name() {
    let dictionary = read("fuzz/dict/problem_json.dict");
    let missing: Vec<&str> = PlannerName::ALL
        .iter()
        .map(|p| p.name())
        .filter(|name| !dictionary.lines().any(|line| line == format!("\"\\\"{name}\\\"\"")))
        .collect();
    assert!(missing.is_empty(), "fuzz/dict/problem_json.dict lacks {missing:?}");
}
