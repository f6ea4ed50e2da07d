//! The vertices of an undirected graph that lie on some simple path between two of them.

/// Which vertices of an undirected graph (adjacency lists, no parallel edges) lie on some simple
/// path from `s` to `t`: the vertices of the blocks (biconnected components, found by Tarjan's
/// algorithm) on the path from `s` to `t` in the block-cut tree. None when `t` cannot be reached.
pub(crate) fn on_simple_paths(adjacency: &[Vec<usize>], s: usize, t: usize) -> Vec<bool> {
    let n = adjacency.len();
    let mut on_path = vec![false; n];
    if s == t {
        on_path[s] = true;
        return on_path;
    }
    let mut tarjan = Tarjan {
        adjacency,
        order: vec![0; n],
        low: vec![0; n],
        time: 0,
        edges: Vec::new(),
        blocks: Vec::new(),
    };
    tarjan.visit(s, usize::MAX);
    if tarjan.order[t] == 0 {
        return on_path;
    }
    // The block-cut tree as vertex-block incidences: a breadth-first search from `s` to `t`
    // over them follows the tree's only path.
    let blocks = tarjan.blocks;
    let mut blocks_of = vec![Vec::new(); n];
    for (b, block) in blocks.iter().enumerate() {
        for &v in block {
            blocks_of[v].push(b);
        }
    }
    let mut came_from_block = vec![usize::MAX; n];
    let mut came_from_vertex = vec![usize::MAX; blocks.len()];
    let mut queue = std::collections::VecDeque::from([s]);
    came_from_block[s] = blocks.len();
    while let Some(v) = queue.pop_front() {
        if v == t {
            break;
        }
        for &b in &blocks_of[v] {
            if came_from_vertex[b] != usize::MAX {
                continue;
            }
            came_from_vertex[b] = v;
            for &w in &blocks[b] {
                if came_from_block[w] == usize::MAX {
                    came_from_block[w] = b;
                    queue.push_back(w);
                }
            }
        }
    }
    let mut v = t;
    while v != s {
        let b = came_from_block[v];
        for &w in &blocks[b] {
            on_path[w] = true;
        }
        v = came_from_vertex[b];
    }
    on_path
}

/// Tarjan's biconnected components, by depth-first search with a stack of edges.
struct Tarjan<'a> {
    adjacency: &'a [Vec<usize>],
    /// Discovery order, from 1 (0: not visited).
    order: Vec<usize>,
    low: Vec<usize>,
    time: usize,
    edges: Vec<(usize, usize)>,
    /// The vertices of each block.
    blocks: Vec<Vec<usize>>,
}

impl Tarjan<'_> {
    fn visit(&mut self, u: usize, parent: usize) {
        self.time += 1;
        self.order[u] = self.time;
        self.low[u] = self.time;
        for &v in &self.adjacency[u] {
            if self.order[v] == 0 {
                self.edges.push((u, v));
                self.visit(v, u);
                self.low[u] = self.low[u].min(self.low[v]);
                if self.low[v] >= self.order[u] {
                    let mut block = Vec::new();
                    while let Some((a, b)) = self.edges.pop() {
                        block.extend([a, b]);
                        if (a, b) == (u, v) {
                            break;
                        }
                    }
                    block.sort_unstable();
                    block.dedup();
                    self.blocks.push(block);
                }
            } else if v != parent && self.order[v] < self.order[u] {
                self.edges.push((u, v));
                self.low[u] = self.low[u].min(self.order[v]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::on_simple_paths;
    use proptest::prelude::*;

    /// Marks every vertex of every simple path from `at` to `t` by trying them all.
    fn brute_force(adjacency: &[Vec<usize>], at: usize, t: usize, path: &mut Vec<usize>, found: &mut [bool]) {
        path.push(at);
        if at == t {
            for &v in path.iter() {
                found[v] = true;
            }
        } else {
            for &v in &adjacency[at] {
                if !path.contains(&v) {
                    brute_force(adjacency, v, t, path, found);
                }
            }
        }
        path.pop();
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        /// The block-cut tree finds exactly the vertices on simple paths that trying every
        /// path finds.
        #[test]
        fn simple_paths_match_brute_force(
            n in 2usize..9,
            edges in proptest::collection::vec((0usize..9, 0usize..9), 0..16),
        ) {
            let mut adjacency = vec![Vec::new(); n];
            for (a, b) in edges {
                let (a, b) = (a % n, b % n);
                if a != b && !adjacency[a].contains(&b) {
                    adjacency[a].push(b);
                    adjacency[b].push(a);
                }
            }
            let mut expected = vec![false; n];
            brute_force(&adjacency, 0, n - 1, &mut Vec::new(), &mut expected);
            prop_assert_eq!(on_simple_paths(&adjacency, 0, n - 1), expected);
        }
    }
}
