//! A k-d tree over points of `D` coordinates that stays shallow whatever order the points
//! arrive in.
//!
//! A full leaf splits at the median of its points, the coordinates taken in turn down the tree
//! (skipping one in which the points do not differ). Alone, that rule keeps a tree balanced
//! only for points that arrive scattered: states that arrive in order along a line (a tree
//! planner's connect phase) always fill the last leaf, and the tree grows a chain, one level per
//! half bucket. So the tree is also a scapegoat tree (Galperin and Rivest): when a point lands
//! deeper than `3 ⌈log2(n / 16)⌉ + 2` levels, the lowest ancestor whose subtree is too deep for
//! its size is rebuilt balanced. Depth stays logarithmic in the number of points whatever their
//! order, and each distinct point is rebuilt about a logarithmic number of times, amortized. A leaf whose
//! newest point lies beyond all its others splits that point off alone, so that points in order
//! leave full leaves behind them (and the chain grows half as fast).
//!
//! Points with a coordinate that is not finite stay outside the tree, in a list every query
//! measures.
//!
//! ```
//! use trailmark_space::nearest::KdTree;
//!
//! let mut tree = KdTree::<2>::new();
//! // 10,000 points in order along a line: the depth stays logarithmic.
//! for i in 0..10_000u32 {
//!     tree.insert([f64::from(i) * 1e-3, 0.5], i);
//! }
//! assert!(tree.depth() <= 32);
//! assert_eq!(tree.nearest_one(&[2.0004, 0.0]).map(|(item, _)| item), Some(2_000));
//! ```

use super::kd_leaf::{BUCKET, Leaf};

/// A child link with this bit set names a leaf (the rest of the bits its index); without it,
/// an inner node.
pub(super) const LEAF: u32 = 1 << 31;

/// An inner node: points below `split` in coordinate `dim` are under `below`, the others under
/// `above`; `size` points in all.
#[derive(Debug, Clone)]
pub(super) struct Node {
    pub(super) split: f64,
    pub(super) dim: u32,
    size: u32,
    pub(super) below: u32,
    pub(super) above: u32,
}

/// A point and its item.
type Entry<const D: usize> = ([f64; D], u32);

/// A k-d tree of points with a `u32` item each, answering the nearest, the `n` nearest and all
/// within a radius by squared straight-line distance. Equal points may be stored (as separate
/// entries); nothing is removed.
#[derive(Debug, Clone)]
pub struct KdTree<const D: usize> {
    pub(super) nodes: Vec<Node>,
    pub(super) leaves: Vec<Leaf<D>>,
    pub(super) root: u32,
    /// Points with a coordinate that is not finite.
    pub(super) loose: Leaf<D>,
    len: usize,
    /// Nodes and leaves of rebuilt subtrees, for reuse.
    free_nodes: Vec<u32>,
    free_leaves: Vec<u32>,
    /// The nodes on the way down of the last insertion (kept: no allocation per insertion).
    path: Vec<u32>,
}

impl<const D: usize> Default for KdTree<D> {
    fn default() -> Self {
        KdTree {
            nodes: Vec::new(),
            leaves: vec![Leaf::default()],
            root: LEAF,
            loose: Leaf::default(),
            len: 0,
            free_nodes: Vec::new(),
            free_leaves: Vec::new(),
            path: Vec::new(),
        }
    }
}

/// The depth a subtree of `size` points may reach before it is rebuilt: three times a balanced
/// tree's, `log2(size / (BUCKET / 2))`, plus two. (With twice, points in order were rebuilt
/// about half again as often, for trees barely shallower.)
fn allowed_depth(size: usize) -> usize {
    let balanced = (size as f64 / (BUCKET / 2) as f64).log2().max(0.0);
    3 * balanced.ceil() as usize + 2
}

impl<const D: usize> KdTree<D> {
    /// An empty tree.
    pub fn new() -> Self {
        Self::default()
    }

    /// The number of points stored.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no point is stored.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The largest number of inner nodes above a leaf.
    pub fn depth(&self) -> usize {
        let mut deepest = 0;
        let mut stack = vec![(self.root, 0)];
        while let Some((link, depth)) = stack.pop() {
            if link & LEAF == 0 {
                let node = &self.nodes[link as usize];
                stack.push((node.below, depth + 1));
                stack.push((node.above, depth + 1));
            } else {
                deepest = deepest.max(depth);
            }
        }
        deepest
    }

    /// Stores `point` with `item`.
    pub fn insert(&mut self, point: [f64; D], item: u32) {
        self.len += 1;
        if !point.iter().all(|c| c.is_finite()) {
            self.loose.push(point, item);
            return;
        }
        self.path.clear();
        let mut link = self.root;
        while link & LEAF == 0 {
            self.path.push(link);
            let node = &mut self.nodes[link as usize];
            node.size = node.size.saturating_add(1);
            link = if point[node.dim as usize] >= node.split { node.above } else { node.below };
        }
        let leaf = &self.leaves[(link & !LEAF) as usize];
        // A leaf already over a bucket holds points all equal (it could not split): an equal
        // one joins them; another is split off alone beside them, nothing moved (moving them
        // for every such point would cost their number each time).
        let equal = if leaf.len() > BUCKET { leaf.points().next().map(|(p, _)| p) } else { None };
        let built = match equal {
            Some(equal) if equal == point => {
                self.leaves[(link & !LEAF) as usize].push(point, item);
                return;
            }
            Some(equal) => self.beside(link, equal, point, item),
            None => {
                let leaf = &mut self.leaves[(link & !LEAF) as usize];
                leaf.push(point, item);
                if leaf.len() <= BUCKET {
                    return;
                }
                let entries: Vec<Entry<D>> = leaf.points().collect();
                self.release(link);
                self.build(entries, self.path.len(), Some(point))
            }
        };
        self.relink(self.path.last().copied(), link, built);
        // The new points' leaves are one level deeper than the leaf was.
        let depth = self.path.len() + 1;
        if depth > allowed_depth(self.len - self.loose.len()) {
            self.rebuild_scapegoat(depth);
        }
    }

    /// A node parting `point` (with `item`, in a leaf of its own) from the leaf `equal_leaf` of
    /// points all at `equal`, in a coordinate where they differ.
    fn beside(&mut self, equal_leaf: u32, equal: [f64; D], point: [f64; D], item: u32) -> u32 {
        let dim = (0..D).find(|&d| point[d] != equal[d]).expect("the point differs from the equal ones");
        let alone = self.new_leaf();
        self.leaves[(alone & !LEAF) as usize].push(point, item);
        let size = u32::try_from(self.leaves[(equal_leaf & !LEAF) as usize].len() + 1).unwrap_or(u32::MAX);
        // Below a split lie the points under it: the lower of the two goes below.
        let node = if point[dim] > equal[dim] {
            Node { split: point[dim], dim: dim as u32, size, below: equal_leaf, above: alone }
        } else {
            Node { split: equal[dim], dim: dim as u32, size, below: alone, above: equal_leaf }
        };
        self.new_node(node)
    }

    /// Points the link to `was` (from `parent`, or the root's) to `link`.
    fn relink(&mut self, parent: Option<u32>, was: u32, link: u32) {
        match parent {
            None => self.root = link,
            Some(parent) => {
                let parent = &mut self.nodes[parent as usize];
                if parent.above == was {
                    parent.above = link;
                } else {
                    parent.below = link;
                }
            }
        }
    }

    /// Rebuilds the lowest node of the path whose subtree is deeper (down to the new points'
    /// leaves, `depth` levels below the root) than its size allows. The root's always is, when
    /// the whole tree is too deep.
    fn rebuild_scapegoat(&mut self, depth: usize) {
        for at in (0..self.path.len()).rev() {
            let node = self.path[at];
            let size = self.nodes[node as usize].size as usize;
            if depth - at > allowed_depth(size) {
                let mut entries = Vec::with_capacity(size);
                self.collect(node, &mut entries);
                let built = self.build(entries, at, None);
                let parent = at.checked_sub(1).map(|i| self.path[i]);
                self.relink(parent, node, built);
                return;
            }
        }
    }

    /// Moves every point under `link` to `entries`, releasing its nodes and leaves for reuse.
    fn collect(&mut self, link: u32, entries: &mut Vec<Entry<D>>) {
        let mut stack = vec![link];
        while let Some(link) = stack.pop() {
            if link & LEAF == 0 {
                let node = &self.nodes[link as usize];
                stack.push(node.below);
                stack.push(node.above);
                self.free_nodes.push(link);
            } else {
                entries.extend(self.leaves[(link & !LEAF) as usize].points());
                self.release(link);
            }
        }
    }

    /// Empties the leaf `link` and keeps it for reuse.
    fn release(&mut self, link: u32) {
        self.leaves[(link & !LEAF) as usize].clear();
        self.free_leaves.push(link & !LEAF);
    }

    /// A balanced subtree of `entries` at `depth`: split at the median, the coordinates in
    /// turn, until a bucket's worth (or points all equal) remain. A full leaf's points are
    /// split past the `newest` instead where it lies beyond all the others (see [`Self::part`]).
    fn build(&mut self, mut entries: Vec<Entry<D>>, depth: usize, newest: Option<[f64; D]>) -> u32 {
        self.build_in(&mut entries, depth, newest)
    }

    fn build_in(&mut self, entries: &mut [Entry<D>], depth: usize, newest: Option<[f64; D]>) -> u32 {
        let parted = if entries.len() > BUCKET { Self::part(entries, depth, newest) } else { None };
        let Some((dim, split, cut)) = parted else {
            let link = self.new_leaf();
            let leaf = &mut self.leaves[(link & !LEAF) as usize];
            for &(p, item) in entries.iter() {
                leaf.push(p, item);
            }
            return link;
        };
        let (lower, upper) = entries.split_at_mut(cut);
        let below = self.build_in(lower, depth + 1, None);
        let above = self.build_in(upper, depth + 1, None);
        let size = u32::try_from(lower.len() + upper.len()).unwrap_or(u32::MAX);
        self.new_node(Node { split, dim: dim as u32, size, below, above })
    }

    fn new_node(&mut self, node: Node) -> u32 {
        match self.free_nodes.pop() {
            Some(free) => {
                self.nodes[free as usize] = node;
                free
            }
            None => {
                self.nodes.push(node);
                self.nodes.len() as u32 - 1
            }
        }
    }

    /// Orders `entries` below and above a split at their median in coordinate `depth % D` (or
    /// the next in which they differ): the coordinate, the split, and how many are below it (at
    /// least one on each side). `None` if the points are all equal.
    ///
    /// Where `newest` lies beyond all the other points in that coordinate (points arriving in
    /// order, as a connect phase adds them), it goes alone to its side and the others stay one
    /// full leaf: the next points follow it, and the leaves left behind, which will receive no
    /// more, are full rather than half full (half the leaves, half the levels to rebuild).
    fn part(entries: &mut [Entry<D>], depth: usize, newest: Option<[f64; D]>) -> Option<(usize, f64, usize)> {
        // The first coordinate in turn in which the points differ (most differ at the first
        // pair: no pass over them all), then its extent.
        let first = entries[0].0;
        let dim = (depth..depth + D).map(|d| d % D).find(|&d| entries.iter().any(|e| e.0[d] != first[d]))?;
        let (low, high) =
            entries.iter().fold((first[dim], first[dim]), |(lo, hi), e| (lo.min(e.0[dim]), hi.max(e.0[dim])));
        let alone = |value: f64| entries.iter().filter(|e| e.0[dim] == value).count() == 1;
        let mut split = match newest.map(|p| p[dim]) {
            Some(v) if v == high && alone(v) => v,
            Some(v) if v == low && alone(v) => {
                entries.iter().map(|e| e.0[dim]).filter(|&c| c > v).fold(f64::INFINITY, f64::min)
            }
            _ => {
                let half = entries.len() / 2;
                entries.select_nth_unstable_by(half, |a, b| a.0[dim].total_cmp(&b.0[dim])).1.0[dim]
            }
        };
        if split == low {
            // Half or more share the least value: split just above it instead.
            split = entries.iter().map(|e| e.0[dim]).filter(|&c| c > split).fold(f64::INFINITY, f64::min);
        }
        let mut cut = 0;
        for i in 0..entries.len() {
            if entries[i].0[dim] < split {
                entries.swap(i, cut);
                cut += 1;
            }
        }
        Some((dim, split, cut))
    }

    fn new_leaf(&mut self) -> u32 {
        match self.free_leaves.pop() {
            Some(free) => free | LEAF,
            None => {
                self.leaves.push(Leaf::default());
                (self.leaves.len() as u32 - 1) | LEAF
            }
        }
    }
}
