//! Bytes -> `trailmark_core::movingai::parse_scenarios`: no panic, and every parsed query lies
//! inside the map size it declares with a finite, non-negative optimal length.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        trailmark_fuzz::movingai::check_scenarios(text);
    }
});
