//! Bytes -> a contingency `TerrainSpec` -> `build`, and for small terrains `plan` (a small
//! `max_states`): no panic; the plan drivable in every world, its expected cost the mean of
//! what it drives and, for tiny terrains, the reference solver's optimum.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    trailmark_fuzz::terrain::terrain_bytes(data);
});
