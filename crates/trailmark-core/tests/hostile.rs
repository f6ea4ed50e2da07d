//! Issue 23: hostile input never gives a wrong answer, a crash, a hang or unbounded memory.
//!
//! This test binary runs under an allocator that refuses any single request above
//! [`REFUSE_ABOVE`] bytes (the process then aborts with "memory allocation failed": the test
//! fails instead of exhausting the machine) and measures the peak memory each thread holds, so
//! a test can check that a parser's memory is bounded by its input.

use std::time::Duration;

use proptest::prelude::*;
use trailmark_core::curve::{BSpline, Bezier, CurveError};
use trailmark_core::dubins::{DubinsError, DubinsPath, DubinsWord, MAX_NORMALISED_DISTANCE};
use trailmark_core::generate::{self, GenerateError};
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::grid::{Cell as GridCell, Grid, GridError, MAX_CELL_COST};
use trailmark_core::movingai::{
    MAX_MAP_FILE_BYTES, MAX_SCENARIO_FILE_BYTES, ParseErrorKind, ReadError, parse_map, parse_scenarios,
    read_map, read_scenarios,
};
use trailmark_core::read::{MAX_DOCUMENT_BYTES, ReadFileError, read_to_string_capped};
use trailmark_core::smooth::Smoothed;

#[path = "common/guard.rs"]
mod guard;

use guard::{peak_during, within};

fn pose(x: f64, y: f64, h: f64) -> Pose {
    Pose::new(Vector::new(x, y), h)
}

// ---- 1. MovingAI parsers ----------------------------------------------------------------------

#[test]
fn a_map_header_claiming_a_huge_grid_allocates_by_the_input() {
    for (w, h) in [(60_000usize, 60_000usize), (16_000, 16_000), (1 << 28, 1), (3, 1 << 27)] {
        let text = format!("type octile\nheight {h}\nwidth {w}\nmap\n...\n");
        let (result, peak) = peak_during(|| parse_map(&text));
        let kind = result.unwrap_err().kind;
        if w.checked_mul(h).is_some_and(|n| n <= Grid::MAX_CELLS) {
            assert!(
                matches!(kind, ParseErrorKind::RowLength { .. } | ParseErrorKind::MissingRows { .. }),
                "{kind:?}"
            );
        } else {
            assert!(matches!(kind, ParseErrorKind::Grid(GridError::TooLarge { .. })), "{kind:?}");
        }
        assert!(
            peak <= 64 * text.len() + 4096,
            "{w} x {h}: {peak} bytes held for {} bytes of input",
            text.len()
        );
    }
}

#[test]
fn duplicate_header_lines_are_refused() {
    for text in [
        "height 2\nheight 2\nwidth 2\nmap\n..\n..\n",
        "width 2\nheight 2\nwidth 2\nmap\n..\n..\n",
        "type octile\ntype octile\nheight 1\nwidth 1\nmap\n.\n",
    ] {
        assert!(matches!(parse_map(text).unwrap_err().kind, ParseErrorKind::DuplicateHeader(_)), "{text:?}");
    }
    assert_eq!(parse_map("height 2\nheight 2\nwidth 2\nmap\n..\n..\n").unwrap_err().line, 2);
}

/// A problem document may name any file as its map: what is in the file never shows in the
/// error message.
#[test]
fn error_messages_never_quote_the_file() {
    const SECRET: &str = "s3cr3t";
    let maps = [
        format!("root:{SECRET}:19000:0:99999:7:::\n"),
        format!("{SECRET}\n"),
        format!("height {SECRET}\nwidth 2\nmap\n"),
        format!("height 1\nwidth {SECRET}\nmap\n"),
        format!("type octile\nheight 1\nwidth 1\nmap {SECRET}\n"),
        format!("type octile\nheight 1\nwidth 1\nmap\n{SECRET}\n"),
        format!("height 1\nwidth 1\nmap\n.\n{SECRET}\n"),
    ];
    for text in &maps {
        let shown = parse_map(text).unwrap_err().to_string();
        assert!(!shown.contains(SECRET), "{shown}");
    }
    // One character of a row is content too.
    let shown = parse_map("height 1\nwidth 3\nmap\n.#.\n").unwrap_err().to_string();
    assert!(!shown.contains('#'), "{shown}");
    let scenarios = [
        format!("version {SECRET}\n"),
        format!("version 1\nversion {SECRET}\n"),
        format!("{SECRET} m 2 2 0 0 1 1 1\n"),
        format!("0 m {SECRET} 2 0 0 1 1 1\n"),
        format!("0 m 2 2 0 {SECRET} 1 1 1\n"),
        format!("0 m 2 2 0 0 1 1 {SECRET}\n"),
        format!("0 {SECRET} 2 2 0 0 1 1\n"),
    ];
    for text in &scenarios {
        let shown = parse_scenarios(text).unwrap_err().to_string();
        assert!(!shown.contains(SECRET), "{shown}");
    }
    // Read from disk: the path is shown, the content is not.
    let dir = std::env::temp_dir().join(format!("trailmark-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("shadow");
    std::fs::write(&file, format!("root:{SECRET}:19000:0:99999:7:::\n")).unwrap();
    let shown = read_map(&file).unwrap_err().to_string();
    assert!(shown.contains("shadow") && !shown.contains(SECRET), "{shown}");
    let shown = read_scenarios(&file).unwrap_err().to_string();
    assert!(!shown.contains(SECRET), "{shown}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn scenario_numbers_out_of_range_are_typed_errors() {
    for line in [
        "0 m 4294967296 2 0 0 1 1 1",
        "99999999999999999999 m 2 2 0 0 1 1 1",
        "0 m 2 2 0 0 1 1 1e999",
        "0 m 2 2 0 0 1 1 inf",
        "0 m 2 2 0 0 1 1 NaN",
        "0 m 2 2 0 0 1 1 -0.5",
        "0 m 4000000000 4000000000 0 0 1 1 1",
        "0 m 0 5 0 0 1 1 1",
    ] {
        assert!(parse_scenarios(line).is_err(), "{line}");
    }
    assert!(matches!(
        parse_scenarios("0 m 4000000000 4000000000 0 0 1 1 1").unwrap_err().kind,
        ParseErrorKind::Grid(GridError::TooLarge { .. })
    ));
    assert!(matches!(
        parse_scenarios("0 m 2 2 0 0 1 1 1e999").unwrap_err().kind,
        ParseErrorKind::BadField { field: "optimal length", .. }
    ));
}

// ---- 2. Reading files -------------------------------------------------------------------------

#[cfg(unix)]
#[test]
fn reading_dev_zero_is_refused_not_endless() {
    let (refused, peak) =
        within(20, "read_map(/dev/zero)", || peak_during(|| read_map("/dev/zero").is_err()));
    assert!(refused && peak < 1 << 20, "{peak} bytes");
    let (refused, peak) =
        within(20, "read_scenarios(/dev/zero)", || peak_during(|| read_scenarios("/dev/zero").is_err()));
    assert!(refused && peak < 1 << 20, "{peak} bytes");
}

#[cfg(unix)]
#[test]
fn reading_a_fifo_is_refused_not_a_hang() {
    let dir = std::env::temp_dir().join(format!("trailmark-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("pipe.map");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success());
    if !made {
        eprintln!("skipped: mkfifo is not available");
        return;
    }
    let path = fifo.clone();
    assert!(within(20, "read_map(fifo)", move || read_map(&path).is_err()));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn reading_a_directory_is_refused() {
    assert!(matches!(
        read_map(std::env::temp_dir()),
        Err(ReadError::File(ReadFileError::NotAFile { kind: "a directory", .. }))
    ));
}

#[cfg(unix)]
#[test]
fn read_to_string_capped_refuses_fifos_devices_and_large_files() {
    let dir = std::env::temp_dir().join(format!("trailmark-capped-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("pipe");
    if std::process::Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success()) {
        let path = fifo.clone();
        let r = within(20, "read_to_string_capped(fifo)", move || read_to_string_capped(&path, 100));
        assert!(matches!(r, Err(ReadFileError::NotAFile { kind: "a FIFO", .. })), "{r:?}");
    }
    let r = read_to_string_capped("/dev/zero", u64::MAX);
    assert!(matches!(r, Err(ReadFileError::NotAFile { kind: "a character device", .. })), "{r:?}");
    let big = dir.join("big.map");
    std::fs::write(&big, "x".repeat(5000)).unwrap();
    let (r, peak) = peak_during(|| read_to_string_capped(&big, 4999));
    assert!(matches!(r, Err(ReadFileError::TooLarge { max_bytes: 4999, .. })), "{r:?}");
    assert!(peak < 64 << 10, "{peak}");
    assert_eq!(read_to_string_capped(&big, 5000).unwrap().len(), 5000);
    // The caps the readers use are documented constants; the map cap holds the largest map.
    const { assert!(MAX_MAP_FILE_BYTES >= 3 * Grid::MAX_CELLS as u64 + 4096) };
    const { assert!(MAX_SCENARIO_FILE_BYTES > 0 && MAX_DOCUMENT_BYTES > 0) };
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 3. Generators and grids ------------------------------------------------------------------

#[test]
fn generators_check_the_size_before_allocating() {
    let (r, peak) = peak_during(|| generate::random(100_000, 100_000, 0.3, 1));
    assert!(
        matches!(r, Err(GenerateError::Grid(GridError::TooLarge { .. }))) && peak < 1 << 20,
        "random: {peak} bytes"
    );
    let (r, peak) = peak_during(|| generate::maze(100_000, 100_000, 3, 1));
    assert!(r.is_err() && peak < 1 << 20, "maze: {peak} bytes");
    let (r, peak) = peak_during(|| generate::rooms(100_000, 100_000, 8, 1));
    assert!(r.is_err() && peak < 1 << 20, "rooms: {peak} bytes");
}

#[test]
fn generator_sizes_that_overflow_are_errors() {
    assert!(generate::random(usize::MAX, 2, 0.3, 1).is_err());
    assert!(generate::maze(usize::MAX, 2, 3, 1).is_err());
    assert!(generate::rooms(usize::MAX, 2, 8, 1).is_err());
}

#[test]
fn polygon_generators_bound_their_counts() {
    assert!(generate::convex_obstacles(100.0, usize::MAX, 6, 0.0, 1).is_err());
    assert!(generate::convex_obstacles(100.0, 1, usize::MAX, 0.0, 1).is_err());
    assert!(generate::narrow_passages(40.0, usize::MAX, 1.0, 0.25, 1).is_err());
}

#[test]
fn grids_beyond_the_documented_maximum_are_refused() {
    let (r, peak) = peak_during(|| Grid::new(1 << 15, 1 << 14));
    assert!(matches!(r, Err(GridError::TooLarge { .. })), "{r:?}");
    assert!(peak < 1 << 20);
}

#[test]
fn ragged_rows_allocate_by_the_rows_given() {
    let mut rows = vec![".".repeat(1 << 14)];
    rows.extend(std::iter::repeat_n(".".to_string(), (1 << 14) - 1));
    let (r, peak) = peak_during(|| Grid::from_rows(&rows));
    assert!(matches!(r, Err(GridError::RaggedRow { row: 1, .. })), "{r:?}");
    assert!(peak < 4 << 20, "{peak} bytes");
}

#[test]
fn cell_costs_beyond_the_maximum_are_refused() {
    let mut grid = Grid::new(2, 2).unwrap();
    for cost in [1e300, f64::MAX, 1e13] {
        assert!(
            matches!(grid.set_cost(GridCell::new(0, 0), cost), Err(GridError::InvalidCost { .. })),
            "{cost}"
        );
        assert!(Grid::from_costs(1, 1, vec![cost]).is_err(), "{cost}");
    }
    assert!(grid.set_cost(GridCell::new(0, 0), 1e6).is_ok());
    assert!(grid.set_cost(GridCell::new(0, 0), MAX_CELL_COST).is_ok());
}

// ---- 4. Curves --------------------------------------------------------------------------------

#[test]
fn tiny_turning_radii_are_errors_not_panics() {
    let (a, b) = (pose(0.0, 0.0, 0.0), pose(1.0, 0.0, 0.5));
    for r in [1e-200, 1e-300, f64::MIN_POSITIVE, 1e-15] {
        assert!(matches!(DubinsPath::shortest(&a, &b, r), Err(DubinsError::OutOfScale { .. })), "{r}");
        assert!(DubinsPath::shortest_length(&a, &b, r).is_err(), "{r}");
        for word in DubinsWord::ALL {
            assert!(DubinsPath::with_word(&a, &b, r, word).is_err(), "{r} {word}");
        }
    }
    // Coordinates whose difference overflows.
    let far = pose(-1e308, 0.0, 0.0);
    assert!(matches!(
        DubinsPath::shortest(&pose(1e308, 0.0, 0.0), &far, 1.0),
        Err(DubinsError::NonFinitePose { which: "start", .. })
    ));
    // At the edge of the supported range, a path is found and joins the poses.
    let r = 1.0 / MAX_NORMALISED_DISTANCE;
    let edge = DubinsPath::shortest(&a, &pose(0.999, 0.0, 0.5), r).unwrap();
    assert!((edge.end().translation.vector - Vector::new(0.999, 0.0)).norm() < 1e-12);
    // Not a unit rotation (nalgebra's unchecked constructors, or a deserialized pose).
    let squashed = Pose::from_parts(
        nalgebra::Translation2::new(0.0, 0.0),
        nalgebra::UnitComplex::new_unchecked(nalgebra::Complex::new(1e200, 0.0)),
    );
    assert!(matches!(DubinsPath::shortest(&squashed, &b, 1.0), Err(DubinsError::NonFinitePose { .. })));
    // A huge radius whose turns would be longer than any f64.
    let turn = DubinsPath::shortest(&a, &pose(0.0, 0.0, 3.0), 1e308);
    assert!(turn.as_ref().map_or(true, |p| p.length().is_finite()), "{turn:?}");
}

#[test]
fn dubins_sampling_with_a_tiny_step_is_an_error_not_a_petabyte() {
    let path = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &pose(10.0, 0.0, 0.0), 1.0).unwrap();
    for step in [1e-300, 1e-9, f64::MIN_POSITIVE] {
        let (r, peak) = peak_during(|| path.sample(step));
        assert!(matches!(r, Err(DubinsError::TooManySamples { .. })), "{step}: {r:?}");
        assert!(peak < 1 << 20, "{step}: {peak} bytes");
    }
    assert!(path.sample(1e-3).is_ok());
}

#[test]
fn hostile_dubins_json_is_refused_or_quick() {
    let texts = [
        r#"{"start":[0,0,0],"turning_radius":1,"word":"LSL","params":[1e300,0,0]}"#,
        r#"{"start":[0,0,0],"turning_radius":1,"word":"LSL","params":[0,1e300,0]}"#,
        r#"{"start":[0,0,1e300],"turning_radius":1,"word":"LSL","params":[1,1,1]}"#,
        r#"{"start":[0,0,0],"turning_radius":-1,"word":"LSL","params":[1,1,1]}"#,
        r#"{"start":[0,0,0],"turning_radius":1e-300,"word":"RLR","params":[1,1,1]}"#,
        r#"{"start":[1e308,0,0],"turning_radius":1e308,"word":"LSL","params":[6,6,6]}"#,
    ];
    for text in texts {
        let ok = within(20, text, move || match serde_json::from_str::<DubinsPath>(text) {
            Err(_) => true,
            Ok(path) => {
                let end = path.end();
                let _ = path.sample(path.length() / 10.0);
                let _ = path.pieces();
                end.translation.vector.iter().all(|v| v.is_finite()) && path.length().is_finite()
            }
        });
        assert!(ok, "{text}");
    }
}

#[test]
fn bezier_sampling_with_a_tiny_step_is_refused() {
    let line = Bezier::line(Point::new(0.0, 0.0), Point::new(1.0, 0.0));
    for step in [1e-300, 1e-9] {
        let (r, peak) = peak_during(|| line.sample(step));
        assert!(matches!(r, Err(CurveError::TooManySamples { .. })), "{step}: {r:?}");
        assert!(peak < 1 << 20, "{step}: {peak} bytes");
    }
    // Control points so far apart that their distance overflows.
    let wide = Bezier::new(vec![Point::new(-1e308, 0.0), Point::new(1e308, 0.0)]).unwrap();
    assert!(matches!(wide.sample(1.0), Err(CurveError::TooManySamples { .. })));
    assert!(matches!(line.sample(0.0), Err(CurveError::InvalidStep(_))));
    assert_eq!(line.sample(0.25).unwrap().len(), 5);
}

#[test]
fn smoothed_sampling_bounds_the_total() {
    let pieces = (0..40)
        .map(|i| Bezier::line(Point::new(f64::from(i), 0.0), Point::new(f64::from(i + 1), 0.0)))
        .collect();
    let smoothed = Smoothed { pieces, kept: 0 };
    let (r, peak) = peak_during(|| smoothed.sample(1.0 / 9_000_000.0));
    assert!(matches!(r, Err(CurveError::TooManySamples { .. })), "{r:?}");
    assert_eq!(smoothed.sample(0.5).unwrap().len(), 81);
    assert!(peak < 1 << 20, "{peak} bytes");
}

#[test]
fn bezier_length_of_a_small_curve_far_from_the_origin_ends() {
    let shape = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, -3.0)];
    let exact = Bezier::new(shape.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().length();
    // Before the fix, rounding noise kept the subdivision going to its full depth: 5 s at an
    // offset of 1e4 (off by 1e-5), 566 s at 1e6 (off by 0.05), 18 s at 1e8.
    for offset in [1e2, 1e4, 1e6, 1e7, 1e8, 1e10, 1e12] {
        let curve =
            Bezier::new(shape.iter().map(|&(x, y)| Point::new(offset + x, offset + y)).collect()).unwrap();
        let started = std::time::Instant::now();
        let length = within(60, "Bezier::length", move || curve.length());
        let took = started.elapsed();
        assert!(took < Duration::from_secs(2), "offset {offset}: {took:?}");
        // As close as the rounding of the coordinates allows.
        if offset <= 1e8 {
            assert!((length - exact).abs() <= 1e-9 * exact + 1e-11 * offset, "{offset}: {length} vs {exact}");
        }
    }
}

#[test]
fn bezier_length_work_is_bounded_for_any_degree() {
    // A curve of high degree zig-zagging wildly: subdivision is capped, the answer finite.
    let points: Vec<Point> =
        (0..200).map(|i| Point::new(f64::from(i), if i % 2 == 0 { 0.0 } else { 1e6 })).collect();
    let curve = Bezier::new(points).unwrap();
    let length = within(120, "Bezier::length of a wild curve", move || curve.length());
    assert!(length.is_finite() && length > 0.0);
    let huge =
        Bezier::new(vec![Point::new(-1e308, 0.0), Point::new(0.0, 1e308), Point::new(1e308, 0.0)]).unwrap();
    let _ = within(20, "Bezier::length of a huge curve", move || huge.length());
}

#[test]
fn clamped_uniform_with_a_huge_degree_is_an_error() {
    let points = vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(2.0, 1.0)];
    assert!(BSpline::clamped_uniform(usize::MAX, points.clone()).is_err());
    assert!(BSpline::clamped_uniform(usize::MAX - 1, points).is_err());
}

// ---- Properties -------------------------------------------------------------------------------

/// A map header with any size, then some rows (the rows rarely match the size).
fn claimed_map() -> impl Strategy<Value = String> {
    let size = prop_oneof![0u64..40, 0u64..100_000, 0u64..u64::MAX];
    let rows = prop::collection::vec("[.@TGx]{0,12}", 0..12);
    (size.clone(), size, rows, any::<bool>()).prop_map(|(w, h, rows, crlf)| {
        let nl = if crlf { "\r\n" } else { "\n" };
        let mut text = format!("type octile{nl}height {h}{nl}width {w}{nl}map{nl}");
        for row in rows {
            text.push_str(&row);
            text.push_str(nl);
        }
        text
    })
}

fn scale() -> impl Strategy<Value = f64> {
    // Magnitudes from 1e-300 to 1e300, either sign.
    (-300.0..300.0f64, any::<bool>())
        .prop_map(|(e, negative)| if negative { -(10f64.powf(e)) } else { 10f64.powf(e) })
}

fn world_point() -> impl Strategy<Value = Point> {
    prop_oneof![
        (0.0..10.0f64, 0.0..10.0f64).prop_map(|(x, y)| Point::new(x, y)),
        (scale(), scale()).prop_map(|(x, y)| Point::new(x, y)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Smoothing any finite path, at any scale, never panics and samples boundedly.
    #[test]
    fn smoothing_at_any_scale_never_panics(path in prop::collection::vec(world_point(), 0..6)) {
        use trailmark_core::smooth::{Smoothing, smooth};
        use trailmark_core::world::{Bounds, PolygonWorld};
        let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 6.0), Point::new(4.0, 6.0)];
        let checker = PolygonWorld::new(bounds, vec![wall], 0.5).unwrap().checker();
        for method in Smoothing::ALL {
            if let Ok(smoothed) = smooth(&checker, &path, method) {
                let _ = smoothed.length();
                let (_, peak) = peak_during(|| smoothed.sample(0.01));
                prop_assert!(peak < 200 << 20);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// A parse never panics, and the memory it holds (and the grid it returns) is bounded by its
    /// input, whatever size the header claims.
    #[test]
    fn parse_map_memory_is_bounded_by_the_input(text in claimed_map()) {
        let (result, peak) = peak_during(|| parse_map(&text));
        prop_assert!(peak <= 64 * text.len() + 4096, "{} bytes held for {} bytes of input", peak, text.len());
        if let Ok(grid) = result {
            prop_assert!(grid.len() <= text.len());
        }
    }

    /// Arbitrary bytes never make either parser panic.
    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        let text = String::from_utf8_lossy(&bytes);
        let (result, peak) = peak_during(|| parse_map(&text));
        prop_assert!(peak <= 64 * text.len() + 4096);
        if let Ok(grid) = result {
            prop_assert!(grid.len() <= text.len());
        }
        let _ = parse_scenarios(&text);
    }

    /// Dubins queries at any scale never panic; a path that is found has a finite length and end,
    /// and sampling it is bounded.
    #[test]
    fn dubins_at_any_scale_never_panics(
        x0 in scale(), y0 in scale(), x1 in scale(), y1 in scale(),
        h0 in -10.0..10.0f64, h1 in -10.0..10.0f64, r in scale(),
    ) {
        let (a, b, r) = (pose(x0, y0, h0), pose(x1, y1, h1), r.abs());
        match DubinsPath::shortest(&a, &b, r) {
            Ok(path) => {
                prop_assert!(path.length().is_finite());
                let end = path.end();
                prop_assert!(end.translation.vector.iter().all(|v| v.is_finite()));
                let (samples, peak) = peak_during(|| path.sample(path.length() / 50.0 + f64::MIN_POSITIVE));
                prop_assert!(peak < 64 << 20);
                if let Ok(samples) = samples {
                    prop_assert!(!samples.is_empty());
                }
                let _ = path.pieces();
                let _ = path.pose_at(path.length() / 2.0);
            }
            Err(e) => prop_assert!(!matches!(e, DubinsError::NoPath(_)), "{:?}", e),
        }
        let _ = DubinsPath::shortest_length(&a, &b, r);
        for word in DubinsWord::ALL {
            let _ = DubinsPath::with_word(&a, &b, r, word);
        }
    }
}

#[test]
fn parse_kinds_are_typed() {
    // A smoke test that the kinds stay matchable (the messages are checked above).
    assert!(matches!(
        parse_map("height x\n").unwrap_err().kind,
        ParseErrorKind::BadHeaderValue { key: "height", .. }
    ));
}
