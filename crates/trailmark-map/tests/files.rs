//! Map files: every mode loads back what it saved, on random maps; PGM and PNG variants read as
//! map_server reads them; every malformed input is a typed error.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use trailmark_map::{
    MapError, MapFrame, MapMetadata, MapMode, OccupancyGrid, SaveOptions, decode_map, encode_map, load_map,
};

fn meta(mode: MapMode, free: f64, occupied: f64) -> MapMetadata {
    MapMetadata {
        image: "map.pgm".into(),
        resolution: 0.05,
        origin: [-1.0, 2.5, 0.0],
        negate: false,
        occupied_thresh: occupied,
        free_thresh: free,
        mode,
    }
}

fn random_map(values: impl Strategy<Value = i8> + Clone) -> impl Strategy<Value = OccupancyGrid> {
    (1usize..20, 1usize..20).prop_flat_map(move |(w, h)| {
        proptest::collection::vec(values.clone(), w * h).prop_map(move |v| {
            OccupancyGrid::new(MapFrame::new(w, h, 0.05, [-1.0, 2.5, 0.0]).unwrap(), v).unwrap()
        })
    })
}

fn round_trip(map: &OccupancyGrid, options: &SaveOptions) -> OccupancyGrid {
    let (meta, bytes) = encode_map(map, "map", options).unwrap();
    decode_map(&meta, &bytes, Path::new("map")).unwrap()
}

proptest! {
    #[test]
    fn raw_maps_load_back(map in random_map(-1i8..=100)) {
        let options = SaveOptions { mode: MapMode::Raw, ..SaveOptions::default() };
        prop_assert_eq!(round_trip(&map, &options), map);
    }

    #[test]
    fn scale_maps_with_thresholds_0_and_1_load_back(map in random_map(-1i8..=100)) {
        let options = SaveOptions { mode: MapMode::Scale, free_thresh: 0.0, occupied_thresh: 1.0 };
        prop_assert_eq!(round_trip(&map, &options), map);
    }

    #[test]
    fn trinary_maps_load_back(
        map in random_map(prop_oneof![Just(-1i8), Just(0i8), Just(100i8)]),
        free in 0.01f64..0.5,
        gap in 0.01f64..0.45,
    ) {
        let options = SaveOptions { mode: MapMode::Trinary, free_thresh: free, occupied_thresh: free + gap };
        prop_assert_eq!(round_trip(&map, &options), map);
    }
}

#[test]
fn scale_mode_keeps_values_between_the_thresholds() {
    // Pixels 0, 128, 230 and a transparent one, in a gray+alpha PNG.
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image_bytes(&[0, 255, 128, 255, 230, 255, 255, 100], 4, 1)
        .unwrap();
    let map = decode_map(&meta(MapMode::Scale, 0.25, 0.65), &png, Path::new("map.png")).unwrap();
    // occupancy 1 - 128/255 = 0.498: rint((0.498 - 0.25) / 0.4 * 100) = 62; 1 - 230/255 = 0.098: free.
    assert_eq!(map.values(), &[100, 62, 0, -1]);
    // In trinary mode the alpha channel is averaged in: (230 + 230 + 230 + 255) / 4 = 236.25.
    let map = decode_map(&meta(MapMode::Trinary, 0.25, 0.65), &png, Path::new("map.png")).unwrap();
    assert_eq!(map.values()[2], 0);
    // Black with full alpha: (0 + 0 + 0 + 255) / 4, occupancy 0.75, still occupied.
    assert_eq!(map.values()[0], 100);
}

trait WriteBytes {
    fn write_image_bytes(self, bytes: &[u8], w: u32, h: u32) -> image::ImageResult<()>;
}

impl<W: std::io::Write> WriteBytes for image::codecs::png::PngEncoder<W> {
    fn write_image_bytes(self, bytes: &[u8], w: u32, h: u32) -> image::ImageResult<()> {
        use image::ImageEncoder;
        self.write_image(bytes, w, h, image::ExtendedColorType::La8)
    }
}

#[test]
fn pgm_variants_read_alike() {
    let m = meta(MapMode::Trinary, 0.196, 0.65);
    let ascii =
        decode_map(&m, b"P2\n# comment\n3 1\n# another\n255\n0 205 254\n", Path::new("a.pgm")).unwrap();
    let binary = decode_map(&m, b"P5 3 1 255\n\x00\xcd\xfe", Path::new("b.pgm")).unwrap();
    assert_eq!(ascii.values(), &[100, -1, 0]);
    assert_eq!(binary, ascii);
    let negated = MapMetadata { negate: true, ..m.clone() };
    assert_eq!(
        decode_map(&negated, b"P2 3 1 255 0 205 254", Path::new("c.pgm")).unwrap().values(),
        &[0, 100, 100]
    );
    let raw = meta(MapMode::Raw, 0.25, 0.65);
    assert_eq!(
        decode_map(&raw, b"P2 3 1 255 0 100 101", Path::new("d.pgm")).unwrap().values(),
        &[0, 100, -1]
    );
}

#[test]
fn images_other_than_pgm_and_png_are_refused_by_name() {
    let m = meta(MapMode::Trinary, 0.196, 0.65);
    let named = |bytes: &[u8]| match decode_map(&m, bytes, Path::new("map.pnm")) {
        Err(MapError::ImageFormat { path, format }) => {
            assert_eq!(path, Path::new("map.pnm"));
            format
        }
        other => panic!("expected a refused format, got {other:?}"),
    };
    // Each a valid image of its kind, black and white or colour: map_server (SDL_image) reads
    // them, but the documented contract is PGM and PNG.
    assert_eq!(named(b"P1\n2 1\n0 1\n"), "PBM (P1)");
    assert_eq!(named(b"P4\n2 1\n\x40"), "PBM (P4)");
    assert_eq!(named(b"P3\n1 1\n255\n0 0 0\n"), "PPM (P3)");
    assert_eq!(named(b"P6\n1 1\n255\n\x00\x00\x00"), "PPM (P6)");
    let pam = b"P7\nWIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nTUPLTYPE GRAYSCALE\nENDHDR\n\x00";
    assert_eq!(named(pam), "PAM (P7)");
    assert!(named(b"\xff\xd8\xff\xe0\x00\x10JFIF\x00").contains("JPEG"));
    assert!(named(b"hello").contains("68 65 6c 6c 6f"));
    assert!(named(b"").contains("empty"));
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trailmark-map-files-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn malformed_inputs_are_typed_errors() {
    let dir = scratch("errors");
    let yaml = "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n";
    let load = |text: &str, image: Option<&[u8]>| {
        std::fs::write(dir.join("map.yaml"), text).unwrap();
        let _ = std::fs::remove_file(dir.join("map.pgm"));
        if let Some(bytes) = image {
            std::fs::write(dir.join("map.pgm"), bytes).unwrap();
        }
        load_map(dir.join("map.yaml")).unwrap_err()
    };
    let pgm: &[u8] = b"P5 2 2 255\n\x00\x00\x00\x00";
    assert!(matches!(load("image: [", Some(pgm)), MapError::Yaml { .. }));
    assert!(matches!(load(yaml, None), MapError::Read(_)), "missing image");
    assert!(matches!(load(yaml, Some(b"P5 4 4 255\n\x00\x00")), MapError::Image { .. }), "short data");
    assert!(matches!(load(yaml, Some(b"hello")), MapError::ImageFormat { .. }), "not an image");
    assert!(matches!(load(&yaml.replace("0.65", "1.2"), Some(pgm)), MapError::Thresholds { .. }));
    assert!(matches!(load(&yaml.replace("0.25", "-0.2"), Some(pgm)), MapError::Thresholds { .. }));
    assert!(matches!(load(&yaml.replace("0.25", "0.8"), Some(pgm)), MapError::Thresholds { .. }));
    assert!(matches!(load(&yaml.replace("0.05", "-0.05"), Some(pgm)), MapError::Resolution { .. }));
    assert!(matches!(load(&yaml.replace("0.05", "0"), Some(pgm)), MapError::Resolution { .. }));
    assert!(matches!(load(&yaml.replace("[0, 0, 0]", "[0, .inf, 0]"), Some(pgm)), MapError::Origin { .. }));
    // A map reaching past 1e9 m is refused from the image's size, before its pixels are read
    // (this raster is empty).
    let far = yaml.replace("[0, 0, 0]", "[999999999, 0, 0]");
    assert!(matches!(load(&far, Some(b"P5 1000 1000 255\n")), MapError::Extent { width: 1000, .. }));
    // Huge images are refused from the header, before anything is allocated for them.
    assert!(matches!(load(yaml, Some(b"P5 70000 2 255\n\x00")), MapError::TooLarge { width: 70000, .. }));
    assert!(matches!(load(yaml, Some(b"P5 6000 60000 255\n\x00")), MapError::TooLarge { width: 6000, .. }));
    assert!(matches!(load(yaml, Some(b"P5 0 3 255\n")), MapError::Image { .. } | MapError::Grid(_)));
    // An image path that names a folder.
    std::fs::write(dir.join("map.yaml"), yaml).unwrap();
    let _ = std::fs::remove_file(dir.join("map.pgm"));
    std::fs::create_dir_all(dir.join("map.pgm")).unwrap();
    assert!(matches!(load_map(dir.join("map.yaml")), Err(MapError::Read(_))));
    std::fs::remove_dir_all(&dir).unwrap();
    // Saving with thresholds under which no shade reads back as free.
    let map = OccupancyGrid::new(MapFrame::new(1, 1, 0.1, [0.0; 3]).unwrap(), vec![0]).unwrap();
    let never_free = SaveOptions { mode: MapMode::Trinary, free_thresh: 0.0, occupied_thresh: 0.5 };
    assert!(matches!(encode_map(&map, "m", &never_free), Err(MapError::Save { .. })));
    let inverted = SaveOptions { mode: MapMode::Trinary, free_thresh: 0.6, occupied_thresh: 0.5 };
    assert!(matches!(encode_map(&map, "m", &inverted), Err(MapError::Thresholds { .. })));
}
