//! A counting global allocator: the harness's measure of peak memory. Every allocation of the
//! process goes through it, so a run's peak is the most heap it held at once above what was
//! held when the run began (what a planner and its peers allocate alike; OMPL runs in its own
//! process and is not counted).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the bytes held and their peak.
pub struct Counting;

static HELD: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

fn grew(bytes: usize) {
    let now = HELD.fetch_add(bytes, Ordering::Relaxed) + bytes;
    PEAK.fetch_max(now, Ordering::Relaxed);
}

// SAFETY: every call is forwarded to the system allocator unchanged; only counters are added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's layout contract is passed on.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as for alloc.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: ptr was allocated by this allocator with this layout.
        unsafe { System.dealloc(ptr, layout) };
        HELD.fetch_sub(layout.size(), Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract is passed on.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                grew(new_size - layout.size());
            } else {
                HELD.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        p
    }
}

/// A point to measure a peak from.
#[derive(Clone, Copy)]
pub struct Mark(usize);

/// Starts a measurement: the peak is reset to the bytes held now.
pub fn mark() -> Mark {
    let held = HELD.load(Ordering::Relaxed);
    PEAK.store(held, Ordering::Relaxed);
    Mark(held)
}

/// The most bytes held at once since `mark`, above what was held then.
pub fn peak_since(mark: Mark) -> usize {
    PEAK.load(Ordering::Relaxed).saturating_sub(mark.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vector_of_a_million_bytes_peaks_at_least_there() {
        let start = mark();
        let v = vec![7u8; 1_000_000];
        let during = peak_since(start);
        drop(v);
        // Other test threads can only add to the peak.
        assert!(during >= 1_000_000, "{during}");
    }
}
