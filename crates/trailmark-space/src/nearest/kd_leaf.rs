//! A leaf of [`KdTree`](super::KdTree): a bucket of points stored in place, each point's
//! coordinates together.

/// The points a leaf holds before it splits.
pub(super) const BUCKET: usize = 32;

/// The squared distance between two points.
#[inline]
pub(super) fn squared<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let mut sum = 0.0;
    for d in 0..D {
        let t = a[d] - b[d];
        sum += t * t;
    }
    sum
}

/// A leaf's points and the item stored with each: a bucket's worth in place, any more in a
/// list.
/// The count first, beside the first points: a query reads it before the points.
#[derive(Debug, Clone)]
#[repr(C)]
pub(super) struct Leaf<const D: usize> {
    pub(super) len: usize,
    points: [[f64; D]; BUCKET],
    pub(super) items: [u32; BUCKET],
    /// Points beyond a bucket: a leaf about to split, or one whose points cannot be parted.
    pub(super) more: Vec<([f64; D], u32)>,
}

impl<const D: usize> Default for Leaf<D> {
    fn default() -> Self {
        Leaf { points: [[0.0; D]; BUCKET], items: [0; BUCKET], len: 0, more: Vec::new() }
    }
}

impl<const D: usize> Leaf<D> {
    pub(super) fn len(&self) -> usize {
        self.len + self.more.len()
    }

    /// Empties the leaf (kept for reuse).
    pub(super) fn clear(&mut self) {
        self.len = 0;
        self.more.clear();
    }

    pub(super) fn push(&mut self, point: [f64; D], item: u32) {
        if self.len < BUCKET {
            self.points[self.len] = point;
            self.items[self.len] = item;
            self.len += 1;
        } else {
            self.more.push((point, item));
        }
    }

    /// Every point and its item.
    pub(super) fn points(&self) -> impl Iterator<Item = ([f64; D], u32)> + '_ {
        let bucket = self.points[..self.len].iter().copied().zip(self.items[..self.len].iter().copied());
        bucket.chain(self.more.iter().copied())
    }

    /// Calls `visit` with each point's item and squared distance to `query`.
    #[inline(always)]
    pub(super) fn measure(&self, query: &[f64; D], mut visit: impl FnMut(u32, f64)) {
        for (p, &item) in self.points[..self.len].iter().zip(&self.items[..self.len]) {
            visit(item, squared(p, query));
        }
        for (p, item) in &self.more {
            visit(*item, squared(p, query));
        }
    }
}
