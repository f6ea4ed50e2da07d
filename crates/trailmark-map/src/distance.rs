//! The exact Euclidean distance transform in linear time (Felzenszwalb and Huttenlocher,
//! "Distance Transforms of Sampled Functions", 2012): for every cell, the squared distance in
//! cells from its centre to the centre of the nearest source cell.
//!
//! Two passes of the one-dimensional transform, down the columns and then along the rows; each
//! keeps the lower envelope of the parabolas rooted at the sources, so the whole transform costs
//! a few operations per cell, whatever the distances.
//!
//! ```
//! use trailmark_map::squared_distances;
//!
//! // A 4 x 3 map with one source at column 0, row 1.
//! let d = squared_distances(4, 3, |i| i == 4);
//! assert_eq!(d[4], 0.0);
//! assert_eq!(d[11], 10.0); // (3, 2): 3 across, 1 down
//! ```

/// The squared Euclidean distance, in cells, from each cell of a `width x height` row-major map
/// to the nearest cell for which `is_source(index)` holds; `f64::INFINITY` everywhere when
/// there is no source. Exact: the values are sums of two squares of integers.
pub fn squared_distances(width: usize, height: usize, is_source: impl Fn(usize) -> bool) -> Vec<f64> {
    let mut d: Vec<f64> =
        (0..width * height).map(|i| if is_source(i) { 0.0 } else { f64::INFINITY }).collect();
    let mut scratch = Envelope::with_capacity(width.max(height));
    let mut column = vec![0.0; height];
    let mut out = vec![0.0; width.max(height)];
    for x in 0..width {
        for (y, slot) in column.iter_mut().enumerate() {
            *slot = d[y * width + x];
        }
        scratch.transform(&column, &mut out[..height]);
        for (y, &v) in out[..height].iter().enumerate() {
            d[y * width + x] = v;
        }
    }
    let mut row = vec![0.0; width];
    for y in 0..height {
        row.copy_from_slice(&d[y * width..(y + 1) * width]);
        scratch.transform(&row, &mut d[y * width..(y + 1) * width]);
    }
    d
}

/// The lower envelope of parabolas of the one-dimensional transform, kept between calls so the
/// passes allocate nothing.
struct Envelope {
    /// The roots (positions of the sources) of the parabolas in the envelope.
    roots: Vec<usize>,
    /// Where each parabola of the envelope starts to be the lowest.
    starts: Vec<f64>,
}

impl Envelope {
    fn with_capacity(n: usize) -> Self {
        Envelope { roots: Vec::with_capacity(n), starts: Vec::with_capacity(n + 1) }
    }

    /// `out[q] = min over p of (q - p)^2 + f[p]`, over the `p` where `f[p]` is finite.
    fn transform(&mut self, f: &[f64], out: &mut [f64]) {
        self.roots.clear();
        self.starts.clear();
        for (q, &fq) in f.iter().enumerate() {
            if !fq.is_finite() {
                continue;
            }
            let qf = q as f64;
            let mut s = f64::NEG_INFINITY;
            while let Some(&p) = self.roots.last() {
                let pf = p as f64;
                // Where the parabola at q meets the one at p.
                s = ((fq + qf * qf) - (f[p] + pf * pf)) / (2.0 * qf - 2.0 * pf);
                if s <= *self.starts.last().expect("one start per root") {
                    self.roots.pop();
                    self.starts.pop();
                    s = f64::NEG_INFINITY;
                } else {
                    break;
                }
            }
            self.roots.push(q);
            self.starts.push(s);
        }
        if self.roots.is_empty() {
            out.fill(f64::INFINITY);
            return;
        }
        let mut k = 0;
        for (q, slot) in out.iter_mut().enumerate() {
            let qf = q as f64;
            while k + 1 < self.roots.len() && self.starts[k + 1] < qf {
                k += 1;
            }
            let p = self.roots[k];
            let dq = qf - p as f64;
            *slot = dq * dq + f[p];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn brute(width: usize, height: usize, sources: &[bool]) -> Vec<f64> {
        (0..width * height)
            .map(|i| {
                let (x, y) = ((i % width) as f64, (i / width) as f64);
                sources
                    .iter()
                    .enumerate()
                    .filter(|(_, s)| **s)
                    .map(|(j, _)| {
                        let (sx, sy) = ((j % width) as f64, (j / width) as f64);
                        (x - sx).powi(2) + (y - sy).powi(2)
                    })
                    .fold(f64::INFINITY, f64::min)
            })
            .collect()
    }

    fn world() -> impl Strategy<Value = (usize, usize, Vec<bool>)> {
        (1usize..24, 1usize..24, 0.0..0.5f64).prop_flat_map(|(w, h, p)| {
            (Just(w), Just(h), proptest::collection::vec(proptest::bool::weighted(p), w * h))
        })
    }

    proptest! {
        #[test]
        fn equals_brute_force((width, height, sources) in world()) {
            let fast = squared_distances(width, height, |i| sources[i]);
            prop_assert_eq!(fast, brute(width, height, &sources));
        }
    }

    #[test]
    fn no_source_is_infinitely_far() {
        assert!(squared_distances(3, 2, |_| false).iter().all(|d| d.is_infinite()));
    }
}
