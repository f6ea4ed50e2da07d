//! Bytes -> `trailmark_core::movingai::parse_map`: no panic, and a parsed grid has no more cells
//! than the text has bytes and survives `write_map` unchanged.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // `read_map` hands the parser UTF-8 text only.
    if let Ok(text) = std::str::from_utf8(data) {
        trailmark_fuzz::movingai::check_map(text);
    }
});
