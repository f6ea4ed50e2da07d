//! The queries of [`KdTree`]: the nearest point, those nearly as near, the `n` nearest, all
//! within a radius. One search serves them all: it goes down the near side of a node first and
//! visits the far side only if the squared distance to its cell, kept up to date one coordinate
//! at a time (the incremental distance of Arya and Mount), is within the query's bound so far.

use super::KdTree;
use super::kd_tree::LEAF;

/// What a query keeps as the search offers it points.
trait Gather {
    /// Offers a point's item and squared distance.
    fn offer(&mut self, item: u32, squared: f64);

    /// The squared distance beyond which no point can be kept (it may shrink as points come).
    fn bound(&self) -> f64;
}

/// Whether a cell whose squared distance is `rd` may hold a point within `bound`: also when
/// `rd` is NaN (distances too large for `f64`), so that such a cell is searched, not lost. The
/// cell's distance is summed in another order than a point's (and one coordinate's term taken
/// out and put back), so it may exceed the distance of a point on the cell's corner by a few
/// units in the last place: `bound` is widened by that much.
#[inline(always)]
fn within_reach<const D: usize>(rd: f64, bound: f64) -> bool {
    rd <= bound * (1.0 + 4.0 * (D + 1) as f64 * f64::EPSILON) || rd.is_nan()
}

/// The nearest point so far of [`KdTree::nearest_one`] (none while the distance is infinite).
struct Best {
    squared: f64,
    item: u32,
}

impl Gather for Best {
    #[inline(always)]
    fn offer(&mut self, item: u32, squared: f64) {
        if squared < self.squared {
            *self = Best { squared, item };
        }
    }

    fn bound(&self) -> f64 {
        self.squared
    }
}

/// The points of [`KdTree::nearest_within`] so far: each within `slack` of the nearest at the
/// time it was measured (those that fall behind a later, nearer one are dropped at the end).
struct Close {
    found: Vec<(u32, f64)>,
    best: f64,
    slack: f64,
}

impl Gather for Close {
    #[inline(always)]
    fn offer(&mut self, item: u32, squared: f64) {
        if squared <= self.best * self.slack {
            self.found.push((item, squared));
            if squared < self.best {
                self.best = squared;
            }
        }
    }

    fn bound(&self) -> f64 {
        self.best * self.slack
    }
}

/// The `n` nearest points so far of [`KdTree::nearest_n`]: candidates gathered unsorted, cut
/// back to the `n` nearest (ties by item) whenever `2n` are held, sorted at the end.
struct Nearest {
    found: Vec<(f64, u32)>,
    n: usize,
    /// The `n`-th nearest's squared distance at the last cut (infinity before): no point
    /// farther can be among the `n` nearest.
    worst: f64,
}

impl Gather for Nearest {
    /// Keeps the point if it may be among the `n` nearest (a NaN distance never is).
    #[inline(always)]
    fn offer(&mut self, item: u32, squared: f64) {
        if squared <= self.worst {
            self.found.push((squared, item));
            if self.found.len() >= 2 * self.n {
                self.cut();
            }
        }
    }

    fn bound(&self) -> f64 {
        self.worst
    }
}

impl Nearest {
    fn cut(&mut self) {
        self.found.select_nth_unstable_by(self.n - 1, Self::order);
        self.found.truncate(self.n);
        self.worst = self.found[self.n - 1].0;
    }

    fn order(a: &(f64, u32), b: &(f64, u32)) -> std::cmp::Ordering {
        a.0.total_cmp(&b.0).then(a.1.cmp(&b.1))
    }

    /// The `n` nearest, nearest first, as items and squared distances.
    fn finish(mut self) -> Vec<(u32, f64)> {
        self.found.sort_unstable_by(Self::order);
        self.found.truncate(self.n);
        self.found.into_iter().map(|(d, item)| (item, d)).collect()
    }
}

/// Every point within a squared radius, for [`KdTree::within`].
struct Within {
    found: Vec<(u32, f64)>,
    radius_squared: f64,
}

impl Gather for Within {
    #[inline(always)]
    fn offer(&mut self, item: u32, squared: f64) {
        if squared <= self.radius_squared {
            self.found.push((item, squared));
        }
    }

    fn bound(&self) -> f64 {
        self.radius_squared
    }
}

impl<const D: usize> KdTree<D> {
    /// Offers `gather` every point that may be within its bound: the tree's, then those kept
    /// beside it.
    fn search<G: Gather>(&self, query: &[f64; D], gather: &mut G) {
        let mut offsets = [0.0; D];
        self.search_in(self.root, query, &mut offsets, 0.0, gather);
        self.loose.measure(query, |item, d| gather.offer(item, d));
    }

    fn search_in<G: Gather>(
        &self,
        link: u32,
        query: &[f64; D],
        offsets: &mut [f64; D],
        rd: f64,
        gather: &mut G,
    ) {
        if link & LEAF != 0 {
            self.leaves[(link & !LEAF) as usize].measure(query, |item, d| gather.offer(item, d));
            return;
        }
        let node = &self.nodes[link as usize];
        let dim = node.dim as usize;
        let diff = query[dim] - node.split;
        let (near, far) = if diff < 0.0 { (node.below, node.above) } else { (node.above, node.below) };
        self.search_in(near, query, offsets, rd, gather);
        let old = offsets[dim];
        let far_rd = rd - old * old + diff * diff;
        if within_reach::<D>(far_rd, gather.bound()) {
            offsets[dim] = diff;
            self.search_in(far, query, offsets, far_rd, gather);
            offsets[dim] = old;
        }
    }

    /// The nearest point's item and squared distance, one of the equally near points (`None` if
    /// no point is at a finite distance, e.g. for a query with a NaN coordinate).
    pub fn nearest_one(&self, query: &[f64; D]) -> Option<(u32, f64)> {
        let mut best = Best { squared: f64::INFINITY, item: 0 };
        self.search(query, &mut best);
        (best.squared < f64::INFINITY).then_some((best.item, best.squared))
    }

    /// The nearest points: every point whose squared distance is at most the nearest's times
    /// `slack` (finite and at least 1; any other is taken as 1), in no order, and that bound;
    /// every other point is farther than it. Empty (and an infinite bound) if no point is at a
    /// finite distance. One search, where [`nearest_one`](Self::nearest_one) and then
    /// [`within`](Self::within) would be two.
    pub fn nearest_within(&self, query: &[f64; D], slack: f64) -> (Vec<(u32, f64)>, f64) {
        let slack = if slack >= 1.0 && slack.is_finite() { slack } else { 1.0 };
        let mut close = Close { found: Vec::new(), best: f64::INFINITY, slack };
        self.search(query, &mut close);
        if close.best == f64::INFINITY {
            return (Vec::new(), f64::INFINITY);
        }
        let bound = close.best * slack;
        close.found.retain(|n| n.1 <= bound);
        (close.found, bound)
    }

    /// The `n` nearest points' items and squared distances, nearest first (ties by item).
    /// Points farther than every returned one are at least as far as the last.
    pub fn nearest_n(&self, query: &[f64; D], n: usize) -> Vec<(u32, f64)> {
        if n == 0 {
            return Vec::new();
        }
        let n = n.min(self.len().max(1));
        let mut nearest = Nearest { found: Vec::with_capacity(2 * n), n, worst: f64::INFINITY };
        self.search(query, &mut nearest);
        nearest.finish()
    }

    /// Every point within squared distance `radius_squared` (inclusive), in no order.
    pub fn within(&self, query: &[f64; D], radius_squared: f64) -> Vec<(u32, f64)> {
        let mut within = Within { found: Vec::new(), radius_squared };
        if !radius_squared.is_nan() {
            self.search(query, &mut within);
        }
        within.found
    }
}
