//! The memory of loading and inflating a map, measured by a counting allocator against the
//! bounds per cell documented on `MAX_MAP_CELLS`; and sizes past the maximum refused from the
//! image's header, before anything is allocated for its pixels.

use std::path::Path;

use trailmark_map::{
    Costmap, CostmapOptions, Footprint, Inflation, MAX_MAP_CELLS, MapError, MapMetadata, MapMode, decode_map,
};

// The facade's counting allocator, the one file both memory tests include.
#[path = "../../../tests/support/counting_alloc.rs"]
mod counting_alloc;

use counting_alloc::peak_during;

fn meta() -> MapMetadata {
    MapMetadata {
        image: "map".into(),
        resolution: 0.05,
        origin: [0.0; 3],
        negate: false,
        occupied_thresh: 0.65,
        free_thresh: 0.196,
        mode: MapMode::Trinary,
    }
}

/// The pixels of a `side x side` map: walls round the edge and a grid of pillars.
fn shade(side: usize, i: usize) -> u8 {
    let (x, y) = (i % side, i / side);
    if x == 0 || y == 0 || x == side - 1 || y == side - 1 || (x % 40 < 2 && y % 40 < 2) { 0 } else { 254 }
}

/// A PNG of 16-bit RGBA pixels, the widest PNG pixel there is.
fn rgba16_png(side: usize) -> Vec<u8> {
    let mut data = Vec::with_capacity(side * side * 8);
    for i in 0..side * side {
        let v = u16::from(shade(side, i)) * 257;
        for _ in 0..4 {
            data.extend_from_slice(&v.to_be_bytes());
        }
    }
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, side as u32, side as u32);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Sixteen);
    encoder.write_header().unwrap().write_image_data(&data).unwrap();
    out
}

/// A PNG header (signature and IHDR, no pixels) claiming `width x height` gray pixels.
fn png_header(width: u32, height: u32) -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Grayscale);
    drop(encoder.write_header().unwrap());
    out
}

#[test]
fn loading_and_inflating_stay_within_their_bytes_per_cell() {
    // One test function, so no other test allocates while this one measures.
    sizes_past_the_maximum_are_refused_from_the_header();
    let side = 2048;
    let cells = side * side;
    let slack = 1 << 20;
    let m = meta();

    // A PGM: one byte a cell for the values, nothing for the pixels beyond the file.
    let mut pgm = format!("P5\n{side} {side}\n255\n").into_bytes();
    pgm.extend((0..cells).map(|i| shade(side, i)));
    let (map, peak) = peak_during(|| decode_map(&m, &pgm, Path::new("map.pgm")).unwrap());
    assert!(peak <= cells + slack, "PGM: {peak} bytes for {cells} cells");
    drop(pgm);

    // A PNG of the widest pixels, read a row at a time: the same.
    let png = rgba16_png(side);
    let (from_png, peak) = peak_during(|| decode_map(&m, &png, Path::new("map.png")).unwrap());
    assert!(peak <= cells + slack, "PNG: {peak} bytes for {cells} cells");
    assert_eq!(from_png, map);
    drop((png, from_png));

    // The costmap, one byte a cell, and its inflation, four more for the squared distances.
    let settings = CostmapOptions {
        inflation: Some(Inflation::around(&Footprint::Radius(0.2)).unwrap()),
        ..CostmapOptions::default()
    };
    let (costmap, peak) = peak_during(|| Costmap::from_occupancy(&map, &settings).unwrap());
    assert!(peak <= 5 * cells + slack, "costmap and inflation: {peak} bytes for {cells} cells");
    assert!(costmap.costs().contains(&253));
}

fn sizes_past_the_maximum_are_refused_from_the_header() {
    let m = meta();
    let too_large = |bytes: &[u8]| match decode_map(&m, bytes, Path::new("map")) {
        Err(MapError::TooLarge { width, height }) => (width, height),
        other => panic!("expected a map too large, got {other:?}"),
    };
    // Headers alone, their pixels missing: refused by the size they claim.
    let (size, peak) = peak_during(|| too_large(&png_header(16384, 16384)));
    assert_eq!(size, (16384, 16384));
    assert!(peak < 1 << 20, "{peak} bytes allocated for a header");
    assert_eq!(too_large(b"P5 8192 8193 255\n"), (8192, 8193));
    assert_eq!(too_large(b"P2\n40000 2\n255\n"), (40000, 2));
    assert_eq!(too_large(&png_header(1, 40000)), (1, 40000));
    const { assert!(MAX_MAP_CELLS == 8192 * 8192) };
}
