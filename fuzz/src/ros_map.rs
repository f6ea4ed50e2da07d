//! ROS maps: the YAML reader, the image decoder and the `nav_msgs/OccupancyGrid` reader never
//! panic, and what they accept writes back to the same thing.

use std::path::Path;

use trailmark_map::{MapMetadata, MapMode, OccupancyGrid, SaveOptions, decode_map, encode_map};

/// The largest image (by its header) decoded here: larger ones are legitimate and allocate
/// their size, which is not what the fuzzer looks for.
const MAX_FUZZ_PIXELS: u64 = 1 << 20;

/// The first byte picks the reader, the rest is its input.
pub fn check(data: &[u8]) {
    let Some((&which, rest)) = data.split_first() else { return };
    match which % 3 {
        0 => check_yaml(rest),
        1 => check_image(which, rest),
        _ => check_message(rest),
    }
}

fn check_yaml(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(meta) = MapMetadata::parse(text) else { return };
    meta.check().expect("a parsed file is valid");
    assert_eq!(MapMetadata::parse(&meta.to_yaml()).expect("written YAML parses"), meta, "YAML round trip");
}

fn check_image(which: u8, data: &[u8]) {
    let size = image::ImageReader::new(std::io::Cursor::new(data))
        .with_guessed_format()
        .ok()
        .and_then(|r| r.into_dimensions().ok());
    if size.is_none_or(|(w, h)| u64::from(w) * u64::from(h) > MAX_FUZZ_PIXELS) {
        return;
    }
    let mode = [MapMode::Trinary, MapMode::Scale, MapMode::Raw][usize::from(which / 3) % 3];
    let meta = MapMetadata {
        image: "fuzz".into(),
        resolution: 0.05,
        origin: [0.0; 3],
        negate: which & 0x80 != 0,
        occupied_thresh: 0.65,
        free_thresh: 0.25,
        mode,
    };
    let Ok(map) = decode_map(&meta, data, Path::new("fuzz")) else { return };
    if mode == MapMode::Trinary {
        assert!(map.values().iter().all(|v| [-1, 0, 100].contains(v)), "trinary values");
    }
    let raw = SaveOptions { mode: MapMode::Raw, ..SaveOptions::default() };
    let (meta, bytes) = encode_map(&map, "fuzz.pgm", &raw).expect("a loaded map saves");
    assert_eq!(
        decode_map(&meta, &bytes, Path::new("fuzz.pgm")).expect("a saved map loads"),
        map,
        "raw round trip"
    );
}

fn check_message(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(map) = OccupancyGrid::from_message_json(text) else { return };
    let again = OccupancyGrid::from_message_json(&map.to_message_json()).expect("a written message reads");
    assert_eq!(again.values(), map.values(), "message round trip");
    assert_eq!(again.frame().width(), map.frame().width());
}
