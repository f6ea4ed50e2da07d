//! ROS maps: the YAML reader, the image decoder and the `nav_msgs/OccupancyGrid` reader never
//! panic, and what they accept writes back to the same thing. An image whose header (read
//! here) claims more cells than a map may have is refused, and YAML is read, within a bounded
//! allocation when the target measures it (YAML aliases expanded, or an image's claimed size
//! allocated before it is refused, took gigabytes).

use std::path::Path;

use trailmark_map::{
    MAX_IMAGE_SIDE, MAX_MAP_CELLS, MapMetadata, MapMode, OccupancyGrid, SaveOptions, decode_map, encode_map,
};

/// The largest image (by its header) decoded here: larger ones are legitimate and allocate
/// their size, which is not what the fuzzer looks for.
const MAX_FUZZ_PIXELS: u64 = 1 << 20;

/// Runs a closure and says how many bytes, at most, it held allocated beyond what was
/// allocated before it (0 where nothing measures: [`check`]).
pub type Measure<'a> = &'a dyn Fn(&mut dyn FnMut()) -> usize;

/// The most bytes reading an input of `len` bytes may hold: a few megabytes, and a few hundred
/// bytes per input byte (a map's YAML is a few lines; a refused image allocates nothing of the
/// size it claims).
fn allowance(len: usize) -> usize {
    (16 << 20) + 256 * len
}

/// The first byte picks the reader, the rest is its input.
pub fn check(data: &[u8]) {
    check_measured(data, &|f| {
        f();
        0
    });
}

/// [`check`], with the readers' allocations measured by `measure`.
pub fn check_measured(data: &[u8], measure: Measure<'_>) {
    let Some((&which, rest)) = data.split_first() else { return };
    match which % 3 {
        0 => check_yaml(rest, measure),
        1 => check_image(which, rest, measure),
        _ => check_message(rest),
    }
}

fn check_yaml(data: &[u8], measure: Measure<'_>) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut parsed = None;
    let held = measure(&mut || parsed = Some(MapMetadata::parse(text)));
    assert!(held <= allowance(data.len()), "reading {} bytes of YAML held {held} bytes", data.len());
    let Some(Ok(meta)) = parsed else { return };
    meta.check().expect("a parsed file is valid");
    assert_eq!(MapMetadata::parse(&meta.to_yaml()).expect("written YAML parses"), meta, "YAML round trip");
}

/// The size an image's header claims, read here: a PNG's IHDR, or a PGM's (P2, P5) width and
/// height when plain spaces, tabs and line ends alone separate them from the magic number and
/// each other. `None` otherwise (a comment, say): a header another reader could read
/// differently proves nothing.
fn claimed_size(data: &[u8]) -> Option<(u64, u64)> {
    if data.starts_with(b"\x89PNG\r\n\x1a\n") {
        let ihdr = data.get(12..24).filter(|c| &c[..4] == b"IHDR")?;
        let side = |b: &[u8]| u64::from(u32::from_be_bytes([b[0], b[1], b[2], b[3]]));
        return Some((side(&ihdr[4..8]), side(&ihdr[8..12])));
    }
    if !(data.starts_with(b"P5") || data.starts_with(b"P2")) {
        return None;
    }
    let mut rest = &data[2..];
    let mut number = || -> Option<u64> {
        let spaces = rest.iter().take_while(|c| matches!(c, b' ' | b'\t' | b'\n' | b'\r')).count();
        let digits = rest[spaces..].iter().take_while(|c| c.is_ascii_digit()).count();
        if spaces == 0 || digits == 0 {
            return None;
        }
        let value = rest[spaces..spaces + digits]
            .iter()
            .fold(0u64, |v, d| v.saturating_mul(10).saturating_add(u64::from(d - b'0')));
        rest = &rest[spaces + digits..];
        // The number ends at a separator (or the end), not in a letter or a comment.
        rest.first().is_none_or(|c| matches!(c, b' ' | b'\t' | b'\n' | b'\r')).then_some(value)
    };
    Some((number()?, number()?))
}

fn check_image(which: u8, data: &[u8], measure: Measure<'_>) {
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
    // Claimed larger than a map may be: refused from the header, nothing of its size allocated.
    if let Some((w, h)) = claimed_size(data) {
        let side = u64::from(MAX_IMAGE_SIDE);
        if w > side || h > side || w.saturating_mul(h) > MAX_MAP_CELLS as u64 {
            let mut read = None;
            let held = measure(&mut || read = Some(decode_map(&meta, data, Path::new("fuzz"))));
            assert!(read.is_some_and(|r| r.is_err()), "an image claiming {w} x {h} was read");
            assert!(held <= allowance(data.len()), "refusing an image claiming {w} x {h} held {held} bytes");
            return;
        }
    }
    let size = image::ImageReader::new(std::io::Cursor::new(data))
        .with_guessed_format()
        .ok()
        .and_then(|r| r.into_dimensions().ok());
    if size.is_none_or(|(w, h)| u64::from(w) * u64::from(h) > MAX_FUZZ_PIXELS) {
        return;
    }
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

#[cfg(test)]
mod tests {
    use trailmark_map::MapError;

    use super::*;

    const BOMB: &[u8] = include_bytes!("../seeds/ros_map/yaml-alias-bomb");
    const MERGE: &[u8] = include_bytes!("../seeds/ros_map/yaml-merge-key");
    const ANCHORED: &[u8] = include_bytes!("../seeds/ros_map/yaml-anchored-field");
    const PGM: &[u8] = include_bytes!("../seeds/ros_map/pgm-claims-16384");
    const PGM_ASCII: &[u8] = include_bytes!("../seeds/ros_map/pgm-ascii-claims-32769");
    const PNG: &[u8] = include_bytes!("../seeds/ros_map/png-claims-16384");

    #[test]
    fn yaml_anchors_and_aliases_are_typed_errors() {
        for seed in [BOMB, MERGE, ANCHORED] {
            let text = std::str::from_utf8(&seed[1..]).unwrap();
            assert!(matches!(MapMetadata::parse(text), Err(MapError::Yaml { .. })), "{text}");
            check(seed);
        }
    }

    #[test]
    fn headers_past_the_most_cells_are_read_here_and_refused() {
        assert_eq!(claimed_size(&PGM[1..]), Some((16384, 16384)));
        assert_eq!(claimed_size(&PGM_ASCII[1..]), Some((32769, 1)));
        assert_eq!(claimed_size(&PNG[1..]), Some((16384, 16384)));
        // A comment, a sign or a letter: not read here.
        assert_eq!(claimed_size(b"P5 #c\n16384 16384 255\n"), None);
        assert_eq!(claimed_size(b"P5 16384x 16384 255\n"), None);
        assert_eq!(claimed_size(b"P516384 16384 255\n"), None);
        for seed in [PGM, PGM_ASCII, PNG] {
            let meta = MapMetadata {
                image: "fuzz".into(),
                resolution: 0.05,
                origin: [0.0; 3],
                negate: false,
                occupied_thresh: 0.65,
                free_thresh: 0.25,
                mode: MapMode::Trinary,
            };
            let refused = decode_map(&meta, &seed[1..], Path::new("fuzz"));
            assert!(matches!(refused, Err(MapError::TooLarge { .. })), "{refused:?}");
            check(seed);
        }
    }
}
