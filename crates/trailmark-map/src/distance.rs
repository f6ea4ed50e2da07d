//! The exact Euclidean distance transform in linear time (Felzenszwalb and Huttenlocher,
//! "Distance Transforms of Sampled Functions", 2012): for every cell, the squared distance in
//! cells from its centre to the centre of the nearest source cell.
//!
//! Two passes of the one-dimensional transform, down the columns and then along the rows; each
//! keeps the lower envelope of the parabolas rooted at the sources, so the whole transform costs
//! a few operations per cell, whatever the distances. Squared distances between cell centres are
//! sums of two squared integers, so they are kept as integers, 4 bytes a cell, and computed in
//! integers throughout: exact.
//!
//! ```
//! use trailmark_map::{MapFrame, NO_SOURCE, squared_distances};
//!
//! // A 4 x 3 map with one source at column 0, row 1.
//! let frame = MapFrame::new(4, 3, 0.05, [0.0; 3])?;
//! let d = squared_distances(&frame, |i| i == 4);
//! assert_eq!(d[4], 0);
//! assert_eq!(d[11], 10); // (3, 2): 3 across, 1 down
//! assert!(squared_distances(&frame, |_| false).iter().all(|&d| d == NO_SOURCE));
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use crate::frame::{MAX_IMAGE_SIDE, MapFrame};

/// The squared distance [`squared_distances`] gives every cell of a map without a source.
pub const NO_SOURCE: u32 = u32::MAX;

// The farthest two cells of a map are (MAX_IMAGE_SIDE - 1) apart along each axis.
const _: () = assert!(2 * (MAX_IMAGE_SIDE as u64 - 1).pow(2) < NO_SOURCE as u64);

/// The squared Euclidean distance, in cells, from each cell of `frame` (row-major, row 0 at the
/// top) to the nearest cell for which `is_source(index)` holds; [`NO_SOURCE`] everywhere when
/// there is no source. Exact, and a `u32`: a map's sides are at most [`MAX_IMAGE_SIDE`] cells,
/// so no squared distance reaches [`NO_SOURCE`].
pub fn squared_distances(frame: &MapFrame, is_source: impl Fn(usize) -> bool) -> Vec<u32> {
    let (width, height) = (frame.width() as usize, frame.height() as usize);
    let mut d: Vec<u32> = (0..width * height).map(|i| if is_source(i) { 0 } else { NO_SOURCE }).collect();
    let longest = width.max(height);
    let mut envelope = Envelope::with_capacity(longest);
    let mut line = vec![0; longest];
    let mut out = vec![0; longest];
    for x in 0..width {
        for (y, slot) in line[..height].iter_mut().enumerate() {
            *slot = d[y * width + x];
        }
        envelope.transform(&line[..height], &mut out[..height]);
        for (y, &v) in out[..height].iter().enumerate() {
            d[y * width + x] = v;
        }
    }
    for row in d.chunks_exact_mut(width) {
        line[..width].copy_from_slice(row);
        envelope.transform(&line[..width], row);
    }
    d
}

/// The lower envelope of parabolas of the one-dimensional transform, kept between calls so the
/// passes allocate nothing.
struct Envelope {
    /// The roots (positions of the sources) of the parabolas in the envelope.
    roots: Vec<usize>,
    /// The first position at which each parabola of the envelope is the lowest.
    starts: Vec<i64>,
}

impl Envelope {
    fn with_capacity(n: usize) -> Self {
        Envelope { roots: Vec::with_capacity(n), starts: Vec::with_capacity(n) }
    }

    /// `out[q] = min over p of (q - p)^2 + f[p]`, over the `p` where `f[p]` is not
    /// [`NO_SOURCE`]. The envelope is kept at whole positions only, which is all it is asked
    /// at, so every step is exact integer arithmetic.
    fn transform(&mut self, f: &[u32], out: &mut [u32]) {
        self.roots.clear();
        self.starts.clear();
        // (q - p)^2 + f[p] < f[q] read as 2 (q - p) x < (f[q] + q^2) - (f[p] + p^2).
        let lift = |p: usize| i64::from(f[p]) + (p * p) as i64;
        for (q, &fq) in f.iter().enumerate() {
            if fq == NO_SOURCE {
                continue;
            }
            let mut start = 0;
            while let (Some(&p), Some(&p_start)) = (self.roots.last(), self.starts.last()) {
                // The first position from which the parabola at q lies strictly below the one
                // at p (q > p, so it stays below from there on).
                start = (lift(q) - lift(p)).div_euclid(2 * (q - p) as i64) + 1;
                if start > p_start {
                    break;
                }
                // Below p wherever p was lowest: p is not in the envelope.
                self.roots.pop();
                self.starts.pop();
                start = 0;
            }
            self.roots.push(q);
            self.starts.push(start);
        }
        if self.roots.is_empty() {
            out.fill(NO_SOURCE);
            return;
        }
        let mut k = 0;
        for (q, slot) in out.iter_mut().enumerate() {
            while k + 1 < self.roots.len() && self.starts[k + 1] <= q as i64 {
                k += 1;
            }
            let p = self.roots[k];
            let dq = q.abs_diff(p) as u64;
            // At most the largest squared distance of a map, below NO_SOURCE.
            *slot = (dq * dq + u64::from(f[p])) as u32;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn brute(width: usize, height: usize, sources: &[bool]) -> Vec<u32> {
        (0..width * height)
            .map(|i| {
                let (x, y) = (i % width, i / width);
                sources
                    .iter()
                    .enumerate()
                    .filter(|(_, s)| **s)
                    .map(|(j, _)| {
                        let (dx, dy) = (x.abs_diff(j % width), y.abs_diff(j / width));
                        (dx * dx + dy * dy) as u32
                    })
                    .fold(NO_SOURCE, u32::min)
            })
            .collect()
    }

    fn frame(width: usize, height: usize) -> MapFrame {
        MapFrame::new(width, height, 0.05, [0.0; 3]).unwrap()
    }

    fn world() -> impl Strategy<Value = (usize, usize, Vec<bool>)> {
        (1usize..24, 1usize..24, 0.0..0.5f64).prop_flat_map(|(w, h, p)| {
            (Just(w), Just(h), proptest::collection::vec(proptest::bool::weighted(p), w * h))
        })
    }

    proptest! {
        #[test]
        fn equals_brute_force((width, height, sources) in world()) {
            let fast = squared_distances(&frame(width, height), |i| sources[i]);
            prop_assert_eq!(fast, brute(width, height, &sources));
        }
    }

    #[test]
    fn no_source_is_infinitely_far() {
        assert!(squared_distances(&frame(3, 2), |_| false).iter().all(|&d| d == NO_SOURCE));
    }

    #[test]
    fn the_farthest_cells_of_the_longest_map_are_exact() {
        // A source at one end of the longest row, and one in the corner of a square map.
        let side = MAX_IMAGE_SIDE as usize;
        let d = squared_distances(&frame(side, 2), |i| i == 0);
        assert_eq!(d[2 * side - 1], ((side - 1) * (side - 1) + 1) as u32);
        let d = squared_distances(&frame(2048, 2048), |i| i == 2048 * 2048 - 1);
        assert_eq!(d[0], 2 * 2047 * 2047);
        // Sources far apart whose parabolas meet between whole positions, and ties.
        let d = squared_distances(&frame(side, 1), |i| i == 5 || i == side - 3);
        assert_eq!(d[side / 2], ((side / 2 - 5).min(side - 3 - side / 2) as u32).pow(2));
    }
}
