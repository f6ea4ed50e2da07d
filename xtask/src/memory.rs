//! A counting global allocator: the harness's measure of peak memory. Every allocation of the
//! process goes through it, so a run's peak is the most heap its thread held at once above what
//! it held when the run began (what a planner and its peers allocate alike; OMPL runs in its own
//! process and is not counted).
//!
//! The counts are per thread, in plain thread-local cells: an atomic counter shared by all
//! threads costs a locked instruction or two per allocation, which a planner allocating a few
//! times per iteration pays in its measured time (OMPL, counted by no one, would not). The
//! harness runs its planners on one thread.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting the bytes held by each thread and their peak.
pub struct Counting;

thread_local! {
    /// Bytes allocated minus bytes freed by this thread (negative when it frees what another
    /// thread allocated).
    static HELD: Cell<isize> = const { Cell::new(0) };
    /// The most `HELD` has been since the last `mark`.
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn changed(bytes: isize) {
    // The cells have no destructor, so they are there for the whole life of the thread; a
    // failed access is ignored rather than allowed to panic inside the allocator.
    let _ = HELD.try_with(|held| {
        let now = held.get() + bytes;
        held.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

// SAFETY: every call is forwarded to the system allocator unchanged; only counters are added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's layout contract is passed on.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            changed(layout.size() as isize);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as for alloc.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            changed(layout.size() as isize);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: ptr was allocated by this allocator with this layout.
        unsafe { System.dealloc(ptr, layout) };
        changed(-(layout.size() as isize));
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract is passed on.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            changed(new_size as isize - layout.size() as isize);
        }
        p
    }
}

/// A point to measure a peak from.
#[derive(Clone, Copy)]
pub struct Mark(isize);

/// Starts a measurement on this thread: the peak is reset to the bytes held now.
pub fn mark() -> Mark {
    let held = HELD.with(Cell::get);
    PEAK.with(|peak| peak.set(held));
    Mark(held)
}

/// The most bytes this thread held at once since `mark`, above what it held then.
pub fn peak_since(mark: Mark) -> usize {
    (PEAK.with(Cell::get) - mark.0).max(0) as usize
}

/// The counting allocator as the library's benchmark runner asks it: the mark of the run under
/// way.
#[derive(Default)]
pub struct Probe(Cell<Option<Mark>>);

impl trailmark::sample::benchmark::MemoryProbe for Probe {
    fn begin(&self) {
        self.0.set(Some(mark()));
    }

    fn peak_bytes(&self) -> usize {
        self.0.get().map_or(0, peak_since)
    }
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
        assert!(during >= 1_000_000, "{during}");
        // A later measurement starts from what is held then: the freed million is not in it.
        let again = mark();
        let w = vec![7u8; 1000];
        let small = peak_since(again);
        drop(w);
        assert!((1000..1_000_000).contains(&small), "{small}");
    }
}
