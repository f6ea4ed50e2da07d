//! The `g` and `rhs` values of the incremental searches, one pair per node slot.

use trailmark_core::cost::Cost;

/// `g` and `rhs` per slot, side by side (the repair loop reads both of a node at once: one
/// cache line), `+inf` until set. Stored as bits XOR the bits of `+inf`, so that `+inf` is 0 and
/// a fresh table is zeroed memory: the allocator hands large zeroed blocks out without writing
/// them, so a planner made for one query on a large graph pays for the pages its search
/// touches, not for the whole graph.
///
/// The slots set since the last [`Values::reset`] are listed, so that a reset costs what the
/// search touched, not the size of the graph.
#[derive(Debug, Clone, Default)]
pub(super) struct Values {
    bits: Vec<[u64; 2]>,
    touched: Vec<u32>,
}

const INF_BITS: u64 = 0x7ff0_0000_0000_0000;

impl Values {
    #[inline]
    pub(super) fn g(&self, slot: usize) -> Cost {
        f64::from_bits(self.bits[slot][0] ^ INF_BITS)
    }

    #[inline]
    pub(super) fn rhs(&self, slot: usize) -> Cost {
        f64::from_bits(self.bits[slot][1] ^ INF_BITS)
    }

    #[inline]
    pub(super) fn set_g(&mut self, slot: usize, cost: Cost) {
        self.set(slot, 0, cost)
    }

    #[inline]
    pub(super) fn set_rhs(&mut self, slot: usize, cost: Cost) {
        self.set(slot, 1, cost)
    }

    #[inline]
    fn set(&mut self, slot: usize, which: usize, cost: Cost) {
        let pair = &mut self.bits[slot];
        if *pair == [0, 0] {
            self.touched.push(slot as u32);
        }
        pair[which] = cost.to_bits() ^ INF_BITS;
    }

    /// Every value back to `+inf`.
    pub(super) fn reset(&mut self) {
        for &slot in &self.touched {
            self.bits[slot as usize] = [0, 0];
        }
        self.touched.clear();
    }

    pub(super) fn len(&self) -> usize {
        self.bits.len()
    }

    pub(super) fn grow(&mut self, len: usize) {
        grow_zeroed(&mut self.bits, len);
    }

    /// Bytes held by the table (its capacity).
    pub(super) fn memory_bytes(&self) -> usize {
        self.bits.capacity() * 16
    }
}

/// Makes `v` `len` long, new entries 0; a first allocation is a zeroed one (see [`Values`]).
pub(super) fn grow_zeroed<T: Copy + Default + PartialEq>(v: &mut Vec<T>, len: usize) {
    if v.is_empty() {
        *v = vec![T::default(); len];
    } else if v.len() < len {
        v.resize(len, T::default());
    }
}
