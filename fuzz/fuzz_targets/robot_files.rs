//! Bytes -> the robot readers (URDF, SRDF, MoveIt scene and request; the first byte picks one):
//! no panic, typed errors, finite models (`trailmark_fuzz::robot`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    trailmark_fuzz::robot::check(data);
});
