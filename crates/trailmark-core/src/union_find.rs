//! Connected components of a growing undirected graph: a union-find (disjoint-set forest).
//!
//! Roadmaps use it to answer "are these two nodes connected?" as they grow, and the
//! contingency planner to join regions through open choke points. The root of a set is always
//! its smallest element, so representatives do not depend on the order the edges came in (a
//! saved and reloaded roadmap reports the same components), and the structure holds no
//! interior mutability: it is `Send + Sync` like the graphs that keep one.
//!
//! ```
//! use trailmark_core::UnionFind;
//!
//! let mut sets = UnionFind::new(4); // {0} {1} {2} {3}
//! assert!(sets.union(3, 1)); //        {0} {1, 3} {2}
//! assert!(!sets.union(1, 3)); //       already joined
//! let four = sets.push(); //           {0} {1, 3} {2} {4}
//! sets.union(four, 3); //              {0} {1, 3, 4} {2}
//! assert_eq!(sets.root(four), 1); //   the smallest element is the root
//! assert!(sets.same(4, 1) && !sets.same(0, 1));
//! assert_eq!(sets.set_count(), 3);
//! ```

/// Disjoint sets of the elements `0..len()` (see the [module](self) documentation).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct UnionFind {
    /// Each element's parent; a root is its own parent and the smallest element of its set.
    parent: Vec<u32>,
    /// The number of disjoint sets.
    sets: usize,
}

impl UnionFind {
    /// `n` elements, each in a set of its own.
    ///
    /// # Panics
    ///
    /// If `n` exceeds `u32::MAX` (elements are numbered by `u32`).
    pub fn new(n: usize) -> Self {
        let n = u32::try_from(n).expect("at most u32::MAX elements");
        UnionFind { parent: (0..n).collect(), sets: n as usize }
    }

    /// Adds an element in a set of its own and returns it.
    ///
    /// # Panics
    ///
    /// If there are `u32::MAX` elements already.
    pub fn push(&mut self) -> u32 {
        let element = u32::try_from(self.parent.len()).expect("at most u32::MAX elements");
        self.parent.push(element);
        self.sets += 1;
        element
    }

    /// The number of elements.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there are no elements.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// The number of disjoint sets.
    pub fn set_count(&self) -> usize {
        self.sets
    }

    /// The root of `element`'s set (its smallest element), shortening the path walked (path
    /// halving) for the next query.
    ///
    /// # Panics
    ///
    /// If `element` is not below [`len`](Self::len).
    pub fn find(&mut self, mut element: u32) -> u32 {
        while self.parent[element as usize] != element {
            let grand = self.parent[self.parent[element as usize] as usize];
            self.parent[element as usize] = grand;
            element = grand;
        }
        element
    }

    /// The root of `element`'s set (its smallest element), without changing anything.
    ///
    /// # Panics
    ///
    /// If `element` is not below [`len`](Self::len).
    pub fn root(&self, mut element: u32) -> u32 {
        while self.parent[element as usize] != element {
            element = self.parent[element as usize];
        }
        element
    }

    /// Joins the sets of `a` and `b`; `true` if they were apart.
    ///
    /// # Panics
    ///
    /// If `a` or `b` is not below [`len`](Self::len).
    pub fn union(&mut self, a: u32, b: u32) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        // The smaller root stays the root, so representatives do not depend on the order of
        // the unions.
        self.parent[ra.max(rb) as usize] = ra.min(rb);
        self.sets -= 1;
        true
    }

    /// Whether `a` and `b` are in one set.
    ///
    /// # Panics
    ///
    /// If `a` or `b` is not below [`len`](Self::len).
    pub fn same(&mut self, a: u32, b: u32) -> bool {
        self.find(a) == self.find(b)
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::UnionFind;

    /// The sets by a plain labelling: after each union, relabel every element of one set.
    fn labels(n: usize, unions: &[(u32, u32)]) -> Vec<usize> {
        let mut label: Vec<usize> = (0..n).collect();
        for &(a, b) in unions {
            let (from, to) = (label[b as usize], label[a as usize]);
            for l in label.iter_mut() {
                if *l == from {
                    *l = to;
                }
            }
        }
        label
    }

    proptest! {
        #[test]
        fn matches_a_plain_labelling(n in 1usize..40, pairs in prop::collection::vec((0u32..40, 0u32..40), 0..60)) {
            let unions: Vec<(u32, u32)> =
                pairs.into_iter().map(|(a, b)| (a % n as u32, b % n as u32)).collect();
            let mut sets = UnionFind::new(n);
            for &(a, b) in &unions {
                sets.union(a, b);
            }
            let label = labels(n, &unions);
            let mut distinct = label.clone();
            distinct.sort_unstable();
            distinct.dedup();
            prop_assert_eq!(sets.set_count(), distinct.len());
            for a in 0..n as u32 {
                let members = (0..n as u32).filter(|&b| label[b as usize] == label[a as usize]);
                prop_assert_eq!(sets.root(a), members.min().unwrap());
                for b in 0..n as u32 {
                    prop_assert_eq!(sets.same(a, b), label[a as usize] == label[b as usize]);
                }
            }
        }
    }

    #[test]
    fn pushed_elements_start_alone() {
        let mut sets = UnionFind::default();
        assert!(sets.is_empty());
        let (a, b) = (sets.push(), sets.push());
        assert_eq!((a, b, sets.len(), sets.set_count()), (0, 1, 2, 2));
        assert!(sets.union(b, a));
        assert_eq!((sets.set_count(), sets.root(1)), (1, 0));
    }
}
