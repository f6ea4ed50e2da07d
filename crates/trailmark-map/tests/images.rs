//! Map images pixel by pixel: samples above a PGM's maxval and palette indices past a PNG's
//! palette are refused, naming the pixel; every other PNG reads as the image crate decodes it,
//! interlaced or not.

use std::path::Path;

use image::GenericImageView;
use proptest::prelude::*;
use trailmark_map::{MapError, MapMetadata, MapMode, decode_map};

fn meta(mode: MapMode, free: f64, occupied: f64) -> MapMetadata {
    MapMetadata {
        image: "map".into(),
        resolution: 0.05,
        origin: [0.0; 3],
        negate: false,
        occupied_thresh: occupied,
        free_thresh: free,
        mode,
    }
}

#[test]
fn pgm_samples_above_the_maxval_are_refused_by_pixel() {
    let raw = meta(MapMode::Raw, 0.25, 0.65);
    let read = |bytes: &[u8]| decode_map(&raw, bytes, Path::new("map.pgm"));
    let above = |bytes: &[u8]| match read(bytes) {
        Err(MapError::PixelAboveMaxval { path, x, y, value, maxval }) => {
            assert_eq!(path, Path::new("map.pgm"));
            (x, y, value, maxval)
        }
        other => panic!("expected a pixel above the maxval, got {other:?}"),
    };
    // Binary, one byte a sample: 201 at column 1 of row 0.
    assert_eq!(above(b"P5 3 1 200\n\x00\xc9\x10"), (1, 0, 201, 200));
    // Binary, two bytes a sample (big-endian, maxval above 255): 1001.
    assert_eq!(above(b"P5 2 1 1000\n\x03\xe8\x03\xe9"), (1, 0, 1001, 1000));
    // ASCII: on the second row; beyond a byte under an 8-bit maxval; beyond 16 bits.
    assert_eq!(above(b"P2 2 2 100\n0 100\n101 5\n"), (0, 1, 101, 100));
    assert_eq!(above(b"P2 1 1 255\n300\n"), (0, 0, 300, 255));
    assert_eq!(above(b"P2 2 1 65535\n0 70000\n"), (1, 0, 70000, 65535));
    // At the maxval the sample is white: 255 in raw mode, unknown.
    assert_eq!(read(b"P5 2 1 1000\n\x03\xe8\x00\x00").unwrap().values(), &[-1, 0]);
    // Below 255 the maxval scales as SDL_image does for map_server: 2 * 255 / 200, truncated.
    assert_eq!(read(b"P2 1 1 200\n2\n").unwrap().values(), &[2]);
    // Comments in an ASCII raster are skipped, as SDL_image skips them.
    assert_eq!(read(b"P2 2 1 255\n7 # the first\n9\n").unwrap().values(), &[7, 9]);
}

#[test]
fn malformed_pgm_files_are_typed_errors() {
    let m = meta(MapMode::Trinary, 0.25, 0.65);
    let reason = |bytes: &[u8]| match decode_map(&m, bytes, Path::new("map.pgm")) {
        Err(MapError::Image { reason, .. }) => reason,
        other => panic!("expected an image error, got {other:?}"),
    };
    assert!(reason(b"P5 2 2 255\n\x00\x00\x00").contains("3 of the 4"), "short binary raster");
    assert!(reason(b"P2 2 2 255\n0 0 0").contains("3 of the 4"), "short ASCII raster");
    assert!(reason(b"P2 2 1 255\n0 x").contains("not a number"));
    assert!(reason(b"P5 2 1 0\n\x00\x00").contains("maxval"));
    assert!(reason(b"P5 2 1 65536\n\x00\x00\x00\x00").contains("maxval"));
    assert!(reason(b"P5 2 1").contains("maxval"));
    assert!(reason(b"P5 99999999999 1 255\n").contains("width"));
    assert!(reason(b"P5x 2 1 255\n\x00\x00").contains("magic"));
}

/// An indexed PNG of `width x height` from its indices (one a pixel, packed at `depth` bits),
/// a palette of `entries` grays and optionally alpha values for the first entries.
fn palette_png(width: u32, indices: &[u8], depth: u8, entries: usize, trns: Option<&[u8]>) -> Vec<u8> {
    let height = indices.len() as u32 / width;
    let palette: Vec<u8> = (0..entries).flat_map(|i| [(i * 255 / entries.max(2)) as u8; 3]).collect();
    let per_byte = 8 / usize::from(depth);
    let row_bytes = (width as usize).div_ceil(per_byte);
    let mut packed = vec![0u8; row_bytes * height as usize];
    for (k, &index) in indices.iter().enumerate() {
        let (x, y) = (k % width as usize, k / width as usize);
        let shift = 8 - usize::from(depth) * (x % per_byte + 1);
        packed[y * row_bytes + x / per_byte] |= index << shift;
    }
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Indexed);
    encoder.set_depth(png::BitDepth::from_u8(depth).unwrap());
    encoder.set_palette(palette);
    if let Some(alpha) = trns {
        encoder.set_trns(alpha.to_vec());
    }
    encoder.write_header().unwrap().write_image_data(&packed).unwrap();
    out
}

#[test]
fn palette_indices_past_the_palette_are_refused_by_pixel() {
    let m = meta(MapMode::Trinary, 0.196, 0.65);
    let outside = |png: &[u8]| match decode_map(&m, png, Path::new("map.png")) {
        Err(MapError::PixelOutsidePalette { path, x, y, index, entries }) => {
            assert_eq!(path, Path::new("map.png"));
            (x, y, index, entries)
        }
        other => panic!("expected an index outside the palette, got {other:?}"),
    };
    // Two bits a pixel and three entries: index 3 has none.
    assert_eq!(outside(&palette_png(4, &[0, 1, 2, 3], 2, 3, None)), (3, 0, 3, 3));
    // Eight bits, two entries, index 200 on the second row.
    assert_eq!(outside(&palette_png(2, &[0, 1, 1, 200], 8, 2, Some(&[0]))), (1, 1, 200, 2));
    // The same images without the stray index read, transparency averaged in trinary mode:
    // black (0, 0, 0, 255) occupied, white free, transparent white unknown.
    let fine = palette_png(3, &[0, 1, 2], 8, 3, Some(&[255, 255, 0]));
    let map = decode_map(&m, &fine, Path::new("map.png")).unwrap();
    assert_eq!(map.values(), &[100, -1, -1]);
}

/// CRC-32 (ISO-HDLC), as PNG chunks carry it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xedb8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = out.len();
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(&out[start..]);
    out.extend_from_slice(&crc.to_be_bytes());
}

/// An interlaced (Adam7) PNG of whole-byte pixels (`pixel` bytes each, row-major), written by
/// hand since the png crate's encoder writes no interlaced images: its zlib stream is stored,
/// not compressed.
fn interlaced_png(width: u32, height: u32, colour: u8, depth: u8, pixel: usize, pixels: &[u8]) -> Vec<u8> {
    const PASSES: [(usize, usize, usize, usize); 7] =
        [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)];
    let (w, h) = (width as usize, height as usize);
    let mut raw = Vec::new();
    for (x0, y0, dx, dy) in PASSES {
        if x0 >= w {
            continue;
        }
        for y in (y0..h).step_by(dy) {
            raw.push(0); // filter: none
            for x in (x0..w).step_by(dx) {
                raw.extend_from_slice(&pixels[(y * w + x) * pixel..][..pixel]);
            }
        }
    }
    let zlib = zlib_stored(&raw);
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&width.to_be_bytes());
    ihdr.extend_from_slice(&height.to_be_bytes());
    ihdr.extend_from_slice(&[depth, colour, 0, 0, 1]);
    chunk(&mut out, b"IHDR", &ihdr);
    if colour == 3 {
        let palette: Vec<u8> = (0..=255u8).flat_map(|i| [i, i / 2, 255 - i]).collect();
        chunk(&mut out, b"PLTE", &palette);
    }
    chunk(&mut out, b"IDAT", &zlib);
    chunk(&mut out, b"IEND", &[]);
    out
}

/// A stored (uncompressed) zlib stream of `raw`.
fn zlib_stored(raw: &[u8]) -> Vec<u8> {
    let mut zlib = vec![0x78, 0x01];
    let blocks: Vec<&[u8]> = raw.chunks(65535).collect();
    for (k, block) in blocks.iter().enumerate() {
        zlib.push(u8::from(k + 1 == blocks.len()));
        let len = block.len() as u16;
        zlib.extend_from_slice(&len.to_le_bytes());
        zlib.extend_from_slice(&(!len).to_le_bytes());
        zlib.extend_from_slice(block);
    }
    let (mut a, mut b) = (1u32, 0u32);
    for &byte in raw {
        a = (a + u32::from(byte)) % 65521;
        b = (b + a) % 65521;
    }
    zlib.extend_from_slice(&((b << 16) | a).to_be_bytes());
    zlib
}

/// A 4 x 2 animated PNG of gray pixels whose first frame, before the image data, claims
/// `width x height`.
fn animated_png(width: u32, height: u32) -> Vec<u8> {
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&4u32.to_be_bytes());
    ihdr.extend_from_slice(&2u32.to_be_bytes());
    ihdr.extend_from_slice(&[8, 0, 0, 0, 0]);
    chunk(&mut png, b"IHDR", &ihdr);
    chunk(&mut png, b"acTL", &[0, 0, 0, 1, 0, 0, 0, 0]);
    let mut fctl = vec![0, 0, 0, 0];
    for v in [width, height, 0, 0] {
        fctl.extend_from_slice(&v.to_be_bytes());
    }
    fctl.extend_from_slice(&[0, 1, 0, 100, 0, 0]);
    chunk(&mut png, b"fcTL", &fctl);
    chunk(&mut png, b"IDAT", &zlib_stored(&[0, 10, 20, 30, 40, 0, 1, 2, 3, 4]));
    chunk(&mut png, b"IEND", &[]);
    png
}

#[test]
fn an_animated_png_whose_first_frame_is_not_the_image_is_a_typed_error() {
    let m = meta(MapMode::Raw, 0.25, 0.65);
    let read = |png: &[u8]| decode_map(&m, png, Path::new("map.png"));
    assert_eq!(read(&animated_png(4, 2)).unwrap().values(), &[10, 20, 30, 40, 1, 2, 3, 4]);
    // Rows shorter than the image's would be read past their end.
    assert!(matches!(read(&animated_png(2, 1)), Err(MapError::Image { .. })));
}

/// A PNG of random pixels: colour type, bit depth, a tRNS chunk or none, interlaced or not.
fn any_png() -> impl Strategy<Value = Vec<u8>> {
    // (colour type, bit depth, interlaced)
    let kinds = prop_oneof![
        (Just(0u8), prop_oneof![Just(1u8), Just(2), Just(4), Just(8), Just(16)], Just(false)),
        (Just(0u8), prop_oneof![Just(8u8), Just(16)], Just(true)),
        (Just(2u8), prop_oneof![Just(8u8), Just(16)], any::<bool>()),
        (Just(3u8), prop_oneof![Just(1u8), Just(2), Just(4), Just(8)], Just(false)),
        (Just(3u8), Just(8u8), Just(true)),
        (Just(4u8), prop_oneof![Just(8u8), Just(16)], any::<bool>()),
        (Just(6u8), prop_oneof![Just(8u8), Just(16)], any::<bool>()),
    ];
    (kinds, 1u32..12, 1u32..12, any::<bool>(), any::<u64>()).prop_map(
        |((colour, depth, interlaced), width, height, trns, seed)| {
            let mut state = seed | 1;
            let mut next = move || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state
            };
            let samples = match colour {
                0 | 3 => 1,
                2 => 3,
                4 => 2,
                _ => 4,
            };
            let n = (width * height) as usize;
            if colour == 3 && !interlaced {
                let entries = 1usize << depth;
                let indices: Vec<u8> = (0..n).map(|_| (next() % entries as u64) as u8).collect();
                let alpha: Vec<u8> = (0..entries / 2).map(|_| next() as u8).collect();
                return palette_png(width, &indices, depth, entries, trns.then_some(alpha.as_slice()));
            }
            if interlaced {
                let pixel = samples * usize::from(depth / 8);
                let bytes: Vec<u8> = (0..n * pixel).map(|_| next() as u8).collect();
                return interlaced_png(width, height, colour, depth, pixel, &bytes);
            }
            let max = (1u64 << depth) - 1;
            let values: Vec<u16> = (0..n * samples).map(|_| (next() % (max + 1)) as u16).collect();
            let per_row = width as usize * samples;
            let mut data = Vec::new();
            for row in values.chunks(per_row) {
                match depth {
                    16 => row.iter().for_each(|v| data.extend_from_slice(&v.to_be_bytes())),
                    8 => data.extend(row.iter().map(|&v| v as u8)),
                    d => {
                        let per_byte = 8 / usize::from(d);
                        let mut bytes = vec![0u8; per_row.div_ceil(per_byte)];
                        for (k, &v) in row.iter().enumerate() {
                            bytes[k / per_byte] |= (v as u8) << (8 - usize::from(d) * (k % per_byte + 1));
                        }
                        data.extend(bytes);
                    }
                }
            }
            let mut out = Vec::new();
            let mut encoder = png::Encoder::new(&mut out, width, height);
            let colour_type = match colour {
                0 => png::ColorType::Grayscale,
                2 => png::ColorType::Rgb,
                4 => png::ColorType::GrayscaleAlpha,
                _ => png::ColorType::Rgba,
            };
            encoder.set_color(colour_type);
            encoder.set_depth(png::BitDepth::from_u8(depth).unwrap());
            if trns && matches!(colour, 0 | 2) {
                // The first pixel's colour is the transparent one.
                let first: Vec<u8> = values[..samples].iter().flat_map(|v| v.to_be_bytes()).collect();
                encoder.set_trns(first);
            }
            encoder.write_header().unwrap().write_image_data(&data).unwrap();
            out
        },
    )
}

/// The occupancy map_server's rule gives `image`'s pixels, from the image crate's decoding.
fn expected(image: &image::DynamicImage, m: &MapMetadata) -> Vec<i8> {
    let has_alpha = image.color().has_alpha();
    image
        .to_rgba16()
        .pixels()
        .map(|p| {
            let [r, g, b, a] = p.0.map(f64::from);
            let (sum, n) =
                if m.mode == MapMode::Trinary && has_alpha { (r + g + b + a, 4.0) } else { (r + g + b, 3.0) };
            let shade = sum / n / 65535.0;
            let occupancy = 1.0 - shade;
            match m.mode {
                MapMode::Raw => {
                    let v = (shade * 255.0).round();
                    if (0.0..=100.0).contains(&v) { v as i8 } else { -1 }
                }
                MapMode::Scale if a < 65535.0 => -1,
                _ if m.occupied_thresh < occupancy => 100,
                _ if occupancy < m.free_thresh => 0,
                MapMode::Scale => {
                    let t = (occupancy - m.free_thresh) / (m.occupied_thresh - m.free_thresh);
                    (t * 100.0).round_ties_even() as i8
                }
                MapMode::Trinary => -1,
            }
        })
        .collect()
}

proptest! {
    #[test]
    fn png_pixels_read_as_the_image_crate_decodes_them(png in any_png()) {
        let image = image::load_from_memory_with_format(&png, image::ImageFormat::Png).unwrap();
        for m in [meta(MapMode::Raw, 0.25, 0.65), meta(MapMode::Scale, 0.0, 1.0), meta(MapMode::Trinary, 0.3, 0.6)] {
            let map = decode_map(&m, &png, Path::new("map.png")).unwrap();
            prop_assert_eq!((map.frame().width(), map.frame().height()), image.dimensions());
            let want = expected(&image, &m);
            prop_assert_eq!(map.values(), want.as_slice(), "{:?}", m.mode);
        }
    }
}
