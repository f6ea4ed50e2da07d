//! Structured input: `trailmark_fuzz::generate::ProblemDoc` builds a valid-shaped problem
//! document with hostile values from the bytes; it is serialized to JSON and run as
//! `problem_json` runs its input, with the same checks.
#![no_main]

use libfuzzer_sys::fuzz_target;
use trailmark_fuzz::generate::ProblemDoc;

fuzz_target!(|doc: ProblemDoc| {
    let text = serde_json::to_vec(&doc.0).expect("a JSON value serializes");
    trailmark_fuzz::problem_bytes(&text);
});
