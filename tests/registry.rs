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
    let generator = read("fuzz/src/generate.rs");
    assert!(
        generator.contains("u.choose(PlannerName::ALL)"),
        "fuzz/src/generate.rs draws its planners from the registry's list"
    );
    assert!(!generator.contains("enum PlannerName"), "the fuzzer keeps no list of its own");
    for planner in PlannerName::ALL {
        assert!(
            generator.contains(&format!("PlannerName::{planner:?}")),
            "fuzz/src/generate.rs gives {planner} no settings"
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
