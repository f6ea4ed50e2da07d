//! How far a straight line may skip from each cell of a grid graph: the chessboard distance to
//! the nearest *edge cell* (a blocked cell, or an open one with a neighbour that is blocked or
//! costs differently). Every cell of the square of radius `d` around a cell at distance `d` is
//! then open and costs what that cell costs (those within `d - 1` are no edge cells, and each
//! at `d` neighbours one of them), so a line through the square crosses nothing
//! that can block it or change its price per unit length; `sight.rs` crosses such squares in
//! one step instead of cell by cell.

/// The distance of each padded cell from the nearest edge cell (0 for an edge cell), capped at
/// `u16::MAX`, by the two passes of the chessboard distance transform (exact for that metric
/// with the eight neighbours at distance 1).
pub(crate) fn open_squares(open: &[bool], costs: Option<&[f64]>, stride: usize) -> Vec<u16> {
    let n = open.len();
    let cost = |i: usize| costs.map_or(1.0, |c| c[i]);
    let rows = n / stride;
    let mut d = vec![u16::MAX; n];
    for y in 0..rows {
        for x in 0..stride {
            let i = y * stride + x;
            let inner = x > 0 && x + 1 < stride && y > 0 && y + 1 < rows;
            // The padded border is blocked, so an inner cell's eight neighbours all exist.
            let edge = !open[i]
                || !inner
                || [
                    i - stride - 1,
                    i - stride,
                    i - stride + 1,
                    i - 1,
                    i + 1,
                    i + stride - 1,
                    i + stride,
                    i + stride + 1,
                ]
                .iter()
                .any(|&j| !open[j] || cost(j) != cost(i));
            if edge {
                d[i] = 0;
            }
        }
    }
    let step = |a: u16| a.saturating_add(1);
    for y in 1..rows {
        for x in 1..stride - 1 {
            let i = y * stride + x;
            let best = d[i - 1].min(d[i - stride - 1]).min(d[i - stride]).min(d[i - stride + 1]);
            d[i] = d[i].min(step(best));
        }
    }
    for y in (0..rows - 1).rev() {
        for x in (1..stride - 1).rev() {
            let i = y * stride + x;
            let best = d[i + 1].min(d[i + stride + 1]).min(d[i + stride]).min(d[i + stride - 1]);
            d[i] = d[i].min(step(best));
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the definition: the smallest chessboard distance to an edge cell, found by
    /// looking at every cell, on grids of random blocks and two costs.
    #[test]
    fn matches_the_distance_to_the_nearest_edge_cell() {
        let mut seed = 7u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as u32
        };
        for _ in 0..20 {
            let (w, h) = (3 + next() as usize % 20, 3 + next() as usize % 20);
            let stride = w + 2;
            let n = stride * (h + 2);
            let mut open = vec![false; n];
            let mut costs = vec![f64::INFINITY; n];
            for y in 1..=h {
                for x in 1..=w {
                    let r = next() % 100;
                    open[y * stride + x] = r >= 8;
                    costs[y * stride + x] = if r < 8 {
                        f64::INFINITY
                    } else if r < 12 {
                        3.0
                    } else {
                        1.0
                    };
                }
            }
            let d = open_squares(&open, Some(&costs), stride);
            let edge = |i: usize| {
                let (x, y) = (i % stride, i / stride);
                if !open[i] || x == 0 || y == 0 || x + 1 == stride || y == h + 1 {
                    return true;
                }
                (-1isize..=1).any(|dy| {
                    (-1isize..=1).any(|dx| {
                        let j = (i as isize + dy * stride as isize + dx) as usize;
                        !open[j] || costs[j] != costs[i]
                    })
                })
            };
            for (i, &got) in d.iter().enumerate() {
                let (x, y) = ((i % stride) as isize, (i / stride) as isize);
                let want = (0..n)
                    .filter(|&j| edge(j))
                    .map(|j| ((j % stride) as isize - x).abs().max(((j / stride) as isize - y).abs()))
                    .min()
                    .unwrap();
                assert_eq!(got as isize, want, "cell {i} of a {w} x {h} grid");
            }
        }
    }
}
