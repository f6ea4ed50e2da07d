//! Bytes -> a `Problem` document -> `trailmark::solve::solve` (with a base folder that does not
//! exist, so no map file is read), when the document is small enough to be quick; every path
//! returned is checked independently (`trailmark_fuzz::grid`, `trailmark_fuzz::polygon`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    trailmark_fuzz::problem_bytes(data);
});
