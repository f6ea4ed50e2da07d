//! The Nav2 example maps in `../shared/rosmaps`: the loader against an independent reading of
//! the raw pixels, saving and loading back, and the inflation layer against a brute-force
//! distance at every cell of the warehouse map.
//!
//! Without the folder, each test says so and passes without checking anything.

use std::path::PathBuf;

use trailmark_map::{
    Costmap, CostmapOptions, Footprint, Inflation, MapMode, OccupancyGrid, SaveOptions, load_map,
    load_map_file, save_map,
};

const MAPS: [&str; 3] = ["warehouse", "depot", "tb3_sandbox"];

#[path = "../../../tests/support/shared_data.rs"]
mod shared_data;

fn data() -> Option<PathBuf> {
    shared_data::shared_data("rosmaps", "the Nav2 example maps")
}

/// A binary PGM read by hand: width, height and the 8-bit samples, row 0 at the top.
fn read_pgm(bytes: &[u8]) -> (usize, usize, Vec<u8>) {
    assert_eq!(&bytes[..2], b"P5", "these maps are binary PGMs");
    let mut fields = Vec::new();
    let mut i = 2;
    while fields.len() < 3 {
        match bytes[i] {
            b'#' => {
                while bytes[i] != b'\n' {
                    i += 1;
                }
            }
            c if c.is_ascii_whitespace() => i += 1,
            _ => {
                let start = i;
                while !bytes[i].is_ascii_whitespace() {
                    i += 1;
                }
                fields.push(std::str::from_utf8(&bytes[start..i]).unwrap().parse::<usize>().unwrap());
            }
        }
    }
    assert_eq!(fields[2], 255, "8-bit samples");
    let (w, h) = (fields[0], fields[1]);
    // One whitespace byte ends the header.
    let data = bytes[i + 1..].to_vec();
    assert_eq!(data.len(), w * h);
    (w, h, data)
}

/// The YAML's `key: number`, read by hand.
fn yaml_number(text: &str, key: &str) -> f64 {
    let line = text.lines().find(|l| l.starts_with(&format!("{key}:"))).unwrap();
    line[key.len() + 1..].trim().parse().unwrap()
}

#[test]
fn counts_equal_an_independent_reading_of_the_pixels() {
    let Some(dir) = data() else { return };
    for name in MAPS {
        let yaml = std::fs::read_to_string(dir.join(format!("{name}.yaml"))).unwrap();
        let (w, h, pixels) = read_pgm(&std::fs::read(dir.join(format!("{name}.pgm"))).unwrap());
        let (occ_th, free_th) = (yaml_number(&yaml, "occupied_thresh"), yaml_number(&yaml, "free_thresh"));
        // SOURCE.txt's rule: p = (255 - v) / 255; p > occupied is occupied, p < free is free.
        let expected: Vec<i8> = pixels
            .iter()
            .map(|&v| {
                let p = (255.0 - f64::from(v)) / 255.0;
                if p > occ_th {
                    100
                } else if p < free_th {
                    0
                } else {
                    -1
                }
            })
            .collect();
        let map = load_map(dir.join(format!("{name}.yaml"))).unwrap();
        assert_eq!((map.frame().width() as usize, map.frame().height() as usize), (w, h), "{name}");
        assert_eq!(map.frame().resolution(), yaml_number(&yaml, "resolution"), "{name}");
        let counts = map.counts();
        let count = |v: i8| expected.iter().filter(|&&e| e == v).count();
        assert_eq!(
            (counts.free, counts.occupied, counts.unknown),
            (count(0), count(100), count(-1)),
            "{name}"
        );
        assert_eq!(counts.between, 0);
        // Cell by cell too: image row 0 is the top of the map, as trailmark's row 0.
        assert!(map.values() == expected.as_slice(), "{name}: a cell differs");
        eprintln!(
            "{name}: {w} x {h}, {} free, {} occupied, {} unknown",
            counts.free, counts.occupied, counts.unknown
        );
    }
}

#[test]
fn the_warehouse_is_where_its_yaml_says() {
    let Some(dir) = data() else { return };
    let loaded = load_map_file(dir.join("warehouse.yaml")).unwrap();
    let frame = loaded.occupancy.frame();
    assert_eq!((frame.width(), frame.height(), frame.resolution()), (1006, 1674, 0.03));
    assert_eq!(frame.origin(), [-15.1, -25.0, 0.0]);
    // The lower-left pixel's centre is half a cell from the origin, up and right.
    let p = frame.centre(trailmark_core::grid::Cell::new(0, 1673));
    assert!((p.x - (-15.085)).abs() < 1e-12 && (p.y - (-24.985)).abs() < 1e-12);
    assert_eq!(loaded.metadata.mode, MapMode::Trinary);
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trailmark-map-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn saved_maps_load_back_identical() {
    let Some(dir) = data() else { return };
    let out = scratch("roundtrip");
    for name in MAPS {
        let map = load_map(dir.join(format!("{name}.yaml"))).unwrap();
        for options in [SaveOptions::default(), SaveOptions { mode: MapMode::Raw, ..SaveOptions::default() }]
        {
            let yaml = save_map(&map, out.join(name), &options).unwrap();
            let back = load_map(&yaml).unwrap();
            assert_eq!(back, map, "{name} in {:?}", options.mode);
        }
        // Nav2's default thresholds (free 0.25) read map_saver's unknown shade as free: the
        // saver picks a shade that reads back unknown.
        let nav2 = SaveOptions { free_thresh: 0.25, ..SaveOptions::default() };
        assert_eq!(load_map(save_map(&map, out.join(name), &nav2).unwrap()).unwrap(), map, "{name}");
    }
    std::fs::remove_dir_all(&out).unwrap();
}

/// The inflation cost of a cell `d` cell lengths from the nearest lethal cell: Nav2's
/// `InflationLayer::computeCost` as its documentation gives it, written out here.
fn nav2_cost(d: f64, resolution: f64, inscribed: f64, radius: f64, k: f64) -> u8 {
    if d == 0.0 {
        254
    } else if d > (radius / resolution).ceil() {
        0
    } else if d * resolution <= inscribed {
        253
    } else {
        (252.0 * (-k * (d * resolution - inscribed)).exp()) as u8
    }
}

#[test]
fn inflation_equals_the_formula_at_every_cell_of_the_warehouse() {
    let Some(dir) = data() else { return };
    let map: OccupancyGrid = load_map(dir.join("warehouse.yaml")).unwrap();
    let (inscribed, radius, k) = (0.2, 0.55, 10.0);
    let settings = CostmapOptions {
        inflation: Some(Inflation {
            inscribed_radius: inscribed,
            inflation_radius: radius,
            cost_scaling_factor: k,
        }),
        ..CostmapOptions::default()
    };
    let costmap = Costmap::from_occupancy(&map, &settings).unwrap();
    let frame = map.frame();
    let (w, h, res) = (frame.width() as i64, frame.height() as i64, frame.resolution());
    // Unknown cells are lethal by default.
    let lethal: Vec<bool> = map.values().iter().map(|&v| v == 100 || v == -1).collect();
    // Brute force: every lethal cell on an obstacle's edge stamps its distance on the cells within
    // the inflation radius (plus one) around it; the nearest lethal cell to any other cell is such an
    // edge cell, and cells farther than the radius cost 0 whatever their distance.
    let reach = (radius / res).ceil() as i64 + 1;
    let mut best = vec![f64::INFINITY; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            if !lethal[i] {
                continue;
            }
            let edge = [(1, 0), (-1, 0), (0, 1), (0, -1)].iter().any(|(dx, dy)| {
                let (nx, ny) = (x + dx, y + dy);
                nx >= 0 && ny >= 0 && nx < w && ny < h && !lethal[(ny * w + nx) as usize]
            });
            best[i] = 0.0;
            if !edge {
                continue;
            }
            for ny in (y - reach).max(0)..=(y + reach).min(h - 1) {
                for nx in (x - reach).max(0)..=(x + reach).min(w - 1) {
                    let d2 = ((nx - x).pow(2) + (ny - y).pow(2)) as f64;
                    let j = (ny * w + nx) as usize;
                    if d2 < best[j] {
                        best[j] = d2;
                    }
                }
            }
        }
    }
    let mut inflated = 0;
    for (i, (&cost, &d2)) in costmap.costs().iter().zip(&best).enumerate() {
        let expected = if d2.is_finite() { nav2_cost(d2.sqrt(), res, inscribed, radius, k) } else { 0 };
        assert_eq!(cost, expected, "cell ({}, {}) at {} cells", i as i64 % w, i as i64 / w, d2.sqrt());
        inflated += usize::from((1..=253).contains(&cost));
    }
    assert!(inflated > 100_000, "the warehouse has many inflated cells, got {inflated}");
    let _ = Footprint::Radius(inscribed);
}
