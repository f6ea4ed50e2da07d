//! Bytes -> the ROS map readers (YAML, PGM/PNG images, `nav_msgs/OccupancyGrid` JSON): no
//! panic, and what is read writes back the same.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    trailmark_fuzz::ros_map::check(data);
});
