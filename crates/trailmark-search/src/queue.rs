//! An indexed priority queue: a d-ary min-heap of items `0..n` with changeable keys.
//!
//! Each item is a small integer (a node index), present at most once. Besides push and pop, the
//! queue changes the key of an item in place (decrease-key, or increase) and removes an item from
//! the middle, both in `O(log n)`: the operations incremental planners (LPA*, D* Lite) rely on.
//! Positions live in a dense `Vec` indexed by item, so no operation hashes or allocates once the
//! queue has grown to its working size.
//!
//! ```
//! use trailmark_search::IndexedHeap;
//!
//! let mut q = IndexedHeap::new();
//! q.push(7, 5.0);
//! q.push(3, 2.0);
//! q.push(9, 4.0);
//! q.push(7, 1.0); // 7 is already queued: its key decreases to 1
//! assert_eq!(q.remove(9), Some(4.0));
//! assert_eq!(q.pop(), Some((7, 1.0)));
//! assert_eq!(q.pop(), Some((3, 2.0)));
//! assert!(q.is_empty());
//! ```

/// The position of an item that is not in the queue.
const ABSENT: u32 = u32::MAX;

/// The number of children of each heap node: 4 keeps the tree shallow and the children of a node
/// in one or two cache lines.
const ARITY: usize = 4;

/// A heap entry: the key beside the item, so comparisons never leave the heap array.
#[derive(Debug, Clone, Copy)]
struct Entry<K> {
    key: K,
    item: u32,
}

/// A min-priority queue of items `0..u32::MAX - 1` with keys of type `K`, supporting
/// decrease-key, increase-key and removal.
///
/// Keys are compared with `<` (`PartialOrd`) and must be totally ordered among the keys in the
/// queue: no NaN. Among equal keys, the order of removal is unspecified.
#[derive(Debug, Clone)]
pub struct IndexedHeap<K> {
    heap: Vec<Entry<K>>,
    /// `pos[item]`: the heap position of `item`, or `ABSENT`.
    pos: Vec<u32>,
}

impl<K> Default for IndexedHeap<K> {
    fn default() -> Self {
        IndexedHeap { heap: Vec::new(), pos: Vec::new() }
    }
}

impl<K: Copy + PartialOrd> IndexedHeap<K> {
    /// The largest item the queue accepts.
    pub const MAX_ITEM: usize = ABSENT as usize - 1;

    /// An empty queue.
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty queue ready for items `0..items` without reallocating its position table.
    pub fn with_item_capacity(items: usize) -> Self {
        IndexedHeap { heap: Vec::new(), pos: vec![ABSENT; items] }
    }

    /// The number of queued items.
    #[inline]
    pub fn len(&self) -> usize {
        self.heap.len()
    }

    /// Whether no item is queued.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.heap.is_empty()
    }

    /// Whether `item` is queued.
    #[inline]
    pub fn contains(&self, item: usize) -> bool {
        self.pos.get(item).is_some_and(|&p| p != ABSENT)
    }

    /// The key of `item`, if it is queued.
    #[inline]
    pub fn key(&self, item: usize) -> Option<K> {
        match self.pos.get(item) {
            Some(&p) if p != ABSENT => Some(self.heap[p as usize].key),
            _ => None,
        }
    }

    /// The item with the smallest key, and its key.
    #[inline]
    pub fn peek(&self) -> Option<(usize, K)> {
        self.heap.first().map(|e| (e.item as usize, e.key))
    }

    /// Queues `item` with `key`, or, when it is queued already, changes its key to `key` (up or
    /// down). Returns the previous key.
    ///
    /// # Panics
    ///
    /// If `item > Self::MAX_ITEM`.
    #[inline]
    pub fn push(&mut self, item: usize, key: K) -> Option<K> {
        if item >= self.pos.len() {
            self.grow(item);
        }
        match self.pos[item] {
            ABSENT => {
                self.insert(item, key);
                None
            }
            p => {
                let p = p as usize;
                let old = self.heap[p].key;
                self.heap[p].key = key;
                if key < old {
                    self.sift_up(p);
                } else if old < key {
                    self.sift_down(p);
                }
                Some(old)
            }
        }
    }

    /// Queues `item`, which the caller knows is not queued, with `key`: [`IndexedHeap::push`]
    /// without reading the item's position first (for a node the search has just met, that
    /// read is a cache miss).
    #[inline]
    pub(crate) fn push_absent(&mut self, item: usize, key: K) {
        if item >= self.pos.len() {
            self.grow(item);
        }
        debug_assert_eq!(self.pos[item], ABSENT, "push_absent of a queued item");
        self.insert(item, key);
    }

    /// Adds `item`, not queued and within the position table, with `key`.
    #[inline]
    fn insert(&mut self, item: usize, key: K) {
        let p = self.heap.len();
        self.heap.push(Entry { key, item: item as u32 });
        // `sift_up` records the item's final position.
        self.sift_up(p);
    }

    /// Makes room in the position table for `item`.
    #[cold]
    fn grow(&mut self, item: usize) {
        assert!(item <= Self::MAX_ITEM, "IndexedHeap item {item} exceeds {}", Self::MAX_ITEM);
        self.pos.resize((item + 1).max(2 * self.pos.len()), ABSENT);
    }

    /// Prepares the position table for items `0..items`, so that pushing them never reallocates.
    pub fn reserve_items(&mut self, items: usize) {
        if items > self.pos.len() {
            self.pos.resize(items, ABSENT);
        }
    }

    /// Removes and returns the item with the smallest key.
    #[inline]
    pub fn pop(&mut self) -> Option<(usize, K)> {
        let last = self.heap.pop()?;
        self.pos[last.item as usize] = ABSENT;
        if self.heap.is_empty() {
            return Some((last.item as usize, last.key));
        }
        let top = std::mem::replace(&mut self.heap[0], last);
        self.pos[top.item as usize] = ABSENT;
        self.pos[last.item as usize] = 0;
        self.sift_down(0);
        Some((top.item as usize, top.key))
    }

    /// Removes `item` from the queue and returns its key, or `None` if it was not queued.
    pub fn remove(&mut self, item: usize) -> Option<K> {
        let p = match self.pos.get(item) {
            Some(&p) if p != ABSENT => p as usize,
            _ => return None,
        };
        let removed = self.heap[p].key;
        self.pos[item] = ABSENT;
        let last = self.heap.pop().expect("a queued item means a non-empty heap");
        if p < self.heap.len() {
            self.heap[p] = last;
            self.pos[last.item as usize] = p as u32;
            if last.key < removed {
                self.sift_up(p);
            } else {
                self.sift_down(p);
            }
        }
        Some(removed)
    }

    /// Removes every item, in time proportional to the number queued.
    pub fn clear(&mut self) {
        for e in self.heap.drain(..) {
            self.pos[e.item as usize] = ABSENT;
        }
    }

    /// The queued items and their keys, in no particular order.
    pub fn iter(&self) -> impl Iterator<Item = (usize, K)> + '_ {
        self.heap.iter().map(|e| (e.item as usize, e.key))
    }

    /// Bytes held by the queue's buffers (their capacity, not just their length).
    pub fn memory_bytes(&self) -> usize {
        self.heap.capacity() * std::mem::size_of::<Entry<K>>() + self.pos.capacity() * 4
    }

    #[inline]
    fn sift_up(&mut self, mut p: usize) {
        let moving = self.heap[p];
        while p > 0 {
            let parent = (p - 1) / ARITY;
            let above = self.heap[parent];
            if moving.key >= above.key {
                break;
            }
            self.heap[p] = above;
            self.pos[above.item as usize] = p as u32;
            p = parent;
        }
        self.heap[p] = moving;
        self.pos[moving.item as usize] = p as u32;
    }

    #[inline]
    fn sift_down(&mut self, mut p: usize) {
        let moving = self.heap[p];
        let n = self.heap.len();
        loop {
            let first = p * ARITY + 1;
            if first >= n {
                break;
            }
            let (best, best_key) = if first + ARITY <= n {
                // A tournament between the four children, with keys kept in registers: two
                // independent comparisons, then one; selected by conditional moves, since which
                // child is least is unpredictable.
                let h = &self.heap[first..first + ARITY];
                let (ab, kab) = if h[1].key < h[0].key { (1, h[1].key) } else { (0, h[0].key) };
                let (cd, kcd) = if h[3].key < h[2].key { (3, h[3].key) } else { (2, h[2].key) };
                if kcd < kab { (first + cd, kcd) } else { (first + ab, kab) }
            } else {
                let mut best = first;
                for c in first + 1..n {
                    if self.heap[c].key < self.heap[best].key {
                        best = c;
                    }
                }
                (best, self.heap[best].key)
            };
            if best_key >= moving.key {
                break;
            }
            self.heap[p] = self.heap[best];
            self.pos[self.heap[p].item as usize] = p as u32;
            p = best;
        }
        self.heap[p] = moving;
        self.pos[moving.item as usize] = p as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::collections::BTreeMap;

    #[derive(Debug, Clone)]
    enum Op {
        Push(usize, u32),
        Pop,
        Remove(usize),
        Clear,
    }

    fn op() -> impl Strategy<Value = Op> {
        prop_oneof![
            6 => (0usize..40, 0u32..50).prop_map(|(i, k)| Op::Push(i, k)),
            3 => Just(Op::Pop),
            2 => (0usize..40).prop_map(Op::Remove),
            1 => Just(Op::Clear),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        /// The heap behaves like a map from item to key whose minimum is popped first.
        #[test]
        fn matches_a_sorted_map(ops in prop::collection::vec(op(), 0..200)) {
            let mut heap = IndexedHeap::new();
            let mut model: BTreeMap<usize, u32> = BTreeMap::new();
            for op in ops {
                match op {
                    Op::Push(i, k) => prop_assert_eq!(heap.push(i, k), model.insert(i, k)),
                    Op::Pop => {
                        let min = model.values().min().copied();
                        match heap.pop() {
                            None => prop_assert!(model.is_empty()),
                            Some((i, k)) => {
                                prop_assert_eq!(Some(k), min);
                                prop_assert_eq!(model.remove(&i), Some(k));
                            }
                        }
                    }
                    Op::Remove(i) => prop_assert_eq!(heap.remove(i), model.remove(&i)),
                    Op::Clear => {
                        heap.clear();
                        model.clear();
                    }
                }
                prop_assert_eq!(heap.len(), model.len());
                for i in 0..40 {
                    prop_assert_eq!(heap.key(i), model.get(&i).copied());
                }
                prop_assert_eq!(heap.peek().map(|p| p.1), model.values().min().copied());
            }
        }
    }

    #[test]
    fn absent_items_are_harmless() {
        let mut heap: IndexedHeap<f64> = IndexedHeap::with_item_capacity(4);
        assert_eq!(heap.remove(2), None);
        assert_eq!(heap.remove(1000), None);
        assert_eq!(heap.key(1000), None);
        assert!(!heap.contains(3));
        assert_eq!(heap.pop(), None);
    }
}
