//! Issue 23 for terrains: hostile options and descriptions give typed errors, never a crash, a
//! hang or unbounded memory.
//!
//! This test binary runs under an allocator that refuses any single request above
//! [`REFUSE_ABOVE`] bytes (the process then aborts: the test fails instead of exhausting the
//! machine) and measures the peak memory each thread holds.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::collections::BTreeMap;
use std::sync::mpsc;
use std::time::Duration;

use trailmark_contingency::generate::{RiverOptions, river_terrain};
use trailmark_contingency::terrain::grid_from_rows;
use trailmark_contingency::{TerrainError, TerrainSpec};
use trailmark_core::grid::{Cell as GridCell, GridError, MAX_CELL_COST};

/// Larger single allocations are refused: every test here should need far less.
const REFUSE_ABOVE: usize = 256 << 20;

struct Guarded;

thread_local! {
    static LIVE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn track(delta: isize) {
    let _ = LIVE.try_with(|live| {
        let now = live.get() + delta;
        live.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

// SAFETY: every call is forwarded to `System` unchanged (or refused with a null pointer, which
// the `GlobalAlloc` contract allows); the bookkeeping touches only const thread-locals.
unsafe impl GlobalAlloc for Guarded {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if layout.size() > REFUSE_ABOVE {
            return std::ptr::null_mut();
        }
        // SAFETY: forwarded with the caller's layout.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            track(layout.size() as isize);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if layout.size() > REFUSE_ABOVE {
            return std::ptr::null_mut();
        }
        // SAFETY: forwarded with the caller's layout.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            track(layout.size() as isize);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded with the caller's pointer and layout.
        unsafe { System.dealloc(ptr, layout) };
        track(-(layout.size() as isize));
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if new_size > REFUSE_ABOVE {
            return std::ptr::null_mut();
        }
        // SAFETY: forwarded with the caller's pointer, layout and size.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            track(new_size as isize - layout.size() as isize);
        }
        p
    }
}

#[global_allocator]
static GUARDED: Guarded = Guarded;

/// `f`'s result and the most memory this thread held beyond what it held before, in bytes.
fn peak_during<T>(f: impl FnOnce() -> T) -> (T, usize) {
    let before = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(before));
    let out = f();
    let peak = PEAK.with(Cell::get);
    (out, (peak - before).max(0) as usize)
}

/// `f`'s result, or a failure when it takes longer than `seconds` (a hang).
fn within<T: Send + 'static>(seconds: u64, what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(f());
    });
    match receive.recv_timeout(Duration::from_secs(seconds)) {
        Ok(out) => out,
        Err(_) => panic!("{what}: no answer within {seconds} s"),
    }
}

#[test]
fn huge_river_terrains_are_refused_before_allocating() {
    for (width, height) in [(100_000, 100_000), (u32::MAX, u32::MAX), (1 << 16, 1 << 13)] {
        let options = RiverOptions { width, height, ..RiverOptions::default() };
        let (r, peak) = peak_during(|| river_terrain(1, &options));
        assert!(
            matches!(r, Err(TerrainError::Grid(GridError::TooLarge { .. }))),
            "{width} x {height}: {r:?}"
        );
        assert!(peak < 1 << 20, "{width} x {height}: {peak} bytes");
    }
}

#[test]
fn huge_forest_and_choke_point_counts_are_refused_quickly() {
    for options in [
        RiverOptions { forests: u32::MAX, ..RiverOptions::default() },
        RiverOptions { forests: 1_000_000, roads: 0, ..RiverOptions::default() },
        RiverOptions { width: 4000, height: 4000, rivers: 100, bridges: 100, ..RiverOptions::default() },
        RiverOptions { width: 4000, height: 4000, rivers: 2, bridges: u32::MAX, ..RiverOptions::default() },
    ] {
        let shown = format!("{options:?}");
        let r = within(20, &shown, move || river_terrain(1, &options).map(|_| ()));
        assert!(r.is_err(), "{shown}");
    }
    // The defaults and other modest options still work.
    assert!(river_terrain(1, &RiverOptions::default()).is_ok());
    assert!(river_terrain(2, &RiverOptions { forests: 12, roads: 2, ..RiverOptions::default() }).is_ok());
}

#[test]
fn river_costs_beyond_the_maximum_are_refused() {
    for cost in [1e300, f64::MAX, MAX_CELL_COST * 2.0] {
        let ford = RiverOptions { ford_cost: cost, ..RiverOptions::default() };
        assert!(river_terrain(1, &ford).is_err(), "ford {cost}");
        let forest = RiverOptions { forest_cost: cost, ..RiverOptions::default() };
        assert!(river_terrain(1, &forest).is_err(), "forest {cost}");
    }
}

#[test]
fn ragged_legend_rows_allocate_by_the_rows_given() {
    let mut rows = vec![".".repeat(1 << 14)];
    rows.extend(std::iter::repeat_n(".".to_string(), (1 << 14) - 1));
    let legend: BTreeMap<char, Option<f64>> = [('.', Some(1.0))].into_iter().collect();
    let (r, peak) = peak_during(|| grid_from_rows(&rows, Some(&legend)));
    assert!(matches!(r, Err(TerrainError::Grid(GridError::RaggedRow { row: 1, .. }))), "{r:?}");
    assert!(peak < 4 << 20, "{peak} bytes");
}

#[test]
fn legend_costs_beyond_the_maximum_are_refused() {
    let legend: BTreeMap<char, Option<f64>> = [('.', Some(1.0)), ('~', Some(1e300))].into_iter().collect();
    let r = grid_from_rows(&["..~", "..."], Some(&legend));
    assert!(matches!(r, Err(TerrainError::Grid(GridError::InvalidCost { .. }))), "{r:?}");
}

#[cfg(unix)]
#[test]
fn a_terrain_naming_dev_zero_or_a_directory_as_its_map_is_refused() {
    for map in ["/dev/zero", "/"] {
        let spec = TerrainSpec {
            rows: None,
            legend: None,
            movingai: Some(map.to_string()),
            connectivity: 8,
            start: GridCell::new(0, 0),
            goal: GridCell::new(1, 0),
            choke_points: Vec::new(),
            detect: None,
        };
        let (r, peak) =
            within(20, map, move || peak_during(|| spec.build(std::path::Path::new(".")).map(|_| ())));
        assert!(matches!(r, Err(TerrainError::Spec(_))), "{map}: {r:?}");
        assert!(peak < 1 << 20, "{map}: {peak} bytes");
    }
}
