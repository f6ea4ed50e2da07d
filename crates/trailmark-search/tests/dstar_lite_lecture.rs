//! The five-node example used to teach D* Lite (MIT 16.412J, "incremental path planning"):
//! nodes A, B, C, D, G; undirected edges A-B, B-C, B-D, C-D, C-G of cost 1 and D-G of cost 10;
//! the robot starts at A for the goal G; the heuristic is the number of hops between nodes.
//! An obstacle appears at C when the robot reaches B, then follows the robot (to B, then to D).
//!
//! The expected values below were worked out by hand from the algorithm of Koenig and
//! Likhachev ("D* Lite", AAAI 2002, the optimized version of figure 4), one step at a time:
//! the g and rhs values, the key of every expanded node in expansion order, the queue left
//! behind, k_m, and the robot's next move at each step.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};
use trailmark_search::{Consistency, DStarLite, EdgeChange, Key};

const A: usize = 0;
const B: usize = 1;
const C: usize = 2;
const D: usize = 3;
const G: usize = 4;
const INF: Cost = f64::INFINITY;

const EDGES: [(usize, usize, Cost); 6] =
    [(A, B, 1.0), (B, C, 1.0), (B, D, 1.0), (C, D, 1.0), (C, G, 1.0), (D, G, 10.0)];

/// Hops between nodes: a consistent heuristic here, since every edge costs at least 1.
const HOPS: [[Cost; 5]; 5] = [
    [0.0, 1.0, 2.0, 2.0, 3.0],
    [1.0, 0.0, 1.0, 1.0, 2.0],
    [2.0, 1.0, 0.0, 1.0, 1.0],
    [2.0, 1.0, 1.0, 0.0, 1.0],
    [3.0, 2.0, 1.0, 1.0, 0.0],
];

/// The lecture graph with at most one node occupied by the obstacle (its edges are gone).
struct Lecture {
    obstacle: Option<usize>,
}

impl Lecture {
    fn cost(&self, a: usize, b: usize) -> Cost {
        if self.obstacle == Some(a) || self.obstacle == Some(b) {
            return INF;
        }
        EDGES.iter().find(|&&(x, y, _)| (x, y) == (a, b) || (y, x) == (a, b)).map_or(INF, |e| e.2)
    }

    /// The directed edges whose cost differs between `self` and `after`.
    fn changes_to(&self, after: &Lecture) -> Vec<EdgeChange<usize>> {
        let mut changes = Vec::new();
        for &(a, b, _) in &EDGES {
            for (from, to) in [(a, b), (b, a)] {
                if self.cost(from, to) != after.cost(from, to) {
                    changes.push(EdgeChange::new(from, to));
                }
            }
        }
        changes
    }
}

impl Graph for Lecture {
    type Node = usize;
    fn contains(&self, node: usize) -> bool {
        node <= G
    }
}

impl Successors for Lecture {
    fn for_each_successor<F: FnMut(usize, Cost)>(&self, node: usize, mut visit: F) {
        for next in A..=G {
            let c = self.cost(node, next);
            if c < INF {
                visit(next, c);
            }
        }
    }
}

impl Predecessors for Lecture {
    fn for_each_predecessor<F: FnMut(usize, Cost)>(&self, node: usize, visit: F) {
        self.for_each_successor(node, visit) // undirected
    }
}

impl IndexedGraph for Lecture {
    fn node_bound(&self) -> usize {
        5
    }
    fn index_of(&self, node: usize) -> usize {
        node
    }
    fn node_at(&self, index: usize) -> usize {
        index
    }
}

type Planner = DStarLite<usize, fn(usize, usize) -> Cost>;

fn hops(a: usize, b: usize) -> Cost {
    HOPS[a][b]
}

/// Runs one search and checks everything the lecture tabulates.
#[allow(clippy::too_many_arguments)]
fn step(
    planner: &mut Planner,
    graph: &Lecture,
    expansions: &[(usize, [Cost; 2], Consistency)],
    g: [Cost; 5],
    rhs: [Cost; 5],
    queue: &[(usize, [Cost; 2])],
    path: &[usize],
    cost: Cost,
) {
    let mut seen = Vec::new();
    let stats = planner
        .compute_shortest_path_traced(graph, |e| {
            seen.push((e.node, [e.key.primary, e.key.secondary], e.kind))
        })
        .unwrap();
    assert_eq!(seen, expansions, "expansions, in order, with their keys");
    assert_eq!(stats.expansions, expansions.len() as u64);
    for n in A..=G {
        assert_eq!(planner.g(graph, n).unwrap(), g[n], "g of node {n}");
        assert_eq!(planner.rhs(graph, n).unwrap(), rhs[n], "rhs of node {n}");
    }
    // The queue as the lecture lists it: by key, equal keys by node (the planner may order
    // equal keys either way).
    let queue: Vec<(usize, Key)> = queue.iter().map(|&(n, [a, b])| (n, Key::new(a, b))).collect();
    let mut queued = planner.queue(graph);
    queued.sort_by(|a, b| {
        (a.1.primary, a.1.secondary, a.0).partial_cmp(&(b.1.primary, b.1.secondary, b.0)).unwrap()
    });
    assert_eq!(queued, queue, "queue after the search");
    assert_eq!(planner.cost(), Some(cost));
    assert_eq!(planner.path(graph).unwrap().nodes, path);
    assert_eq!(planner.next_step(graph), path.get(1).copied());
}

#[test]
fn the_lecture_example_step_by_step() {
    use Consistency::{Overconsistent as Over, Underconsistent as Under};
    let free = Lecture { obstacle: None };
    let mut planner: Planner = DStarLite::new(&free, A, G, hops as fn(usize, usize) -> Cost).unwrap();
    assert_eq!(planner.queue(&free), [(G, Key::new(3.0, 0.0))]);

    // The first search, from G back to A: the path A B C G of cost 3.
    step(
        &mut planner,
        &free,
        &[(G, [3.0, 0.0], Over), (C, [3.0, 1.0], Over), (B, [3.0, 2.0], Over), (A, [3.0, 3.0], Over)],
        [3.0, 2.0, 1.0, INF, 0.0],
        [3.0, 2.0, 1.0, 2.0, 0.0],
        &[(D, [4.0, 2.0])],
        &[A, B, C, G],
        3.0,
    );

    // The robot moves to B and sees the obstacle at C: k_m = h(A, B) = 1. B's and A's values
    // rose, so they are repaired (underconsistent) before D's route to G is propagated.
    planner.move_start(&free, B).unwrap();
    let blocked_c = Lecture { obstacle: Some(C) };
    planner.update_edges(&blocked_c, &free.changes_to(&blocked_c)).unwrap();
    assert_eq!(planner.key_modifier(), 1.0);
    step(
        &mut planner,
        &blocked_c,
        &[
            (C, [3.0, 1.0], Under),
            (B, [3.0, 2.0], Under),
            (A, [5.0, 3.0], Under),
            (D, [12.0, 10.0], Over),
            (B, [12.0, 11.0], Over),
        ],
        [INF, 11.0, INF, 10.0, 0.0],
        [12.0, 11.0, INF, 10.0, 0.0],
        &[(A, [14.0, 12.0])],
        &[B, D, G],
        11.0,
    );

    // The robot moves to D; the obstacle follows it to B, freeing C: k_m = 1 + h(B, D) = 2.
    planner.move_start(&blocked_c, D).unwrap();
    let blocked_b = Lecture { obstacle: Some(B) };
    planner.update_edges(&blocked_b, &blocked_c.changes_to(&blocked_b)).unwrap();
    assert_eq!(planner.key_modifier(), 2.0);
    step(
        &mut planner,
        &blocked_b,
        &[(C, [4.0, 1.0], Over), (D, [4.0, 2.0], Over)],
        [INF, 11.0, 1.0, 2.0, 0.0],
        [INF, INF, 1.0, 2.0, 0.0],
        &[(B, [14.0, 11.0])],
        &[D, C, G],
        2.0,
    );

    // The robot moves to C; the obstacle follows it to D, freeing B: k_m = 3. Nothing that
    // changed can improve on C's value, so the search expands nothing; the changes wait in
    // the queue.
    planner.move_start(&blocked_b, C).unwrap();
    let blocked_d = Lecture { obstacle: Some(D) };
    planner.update_edges(&blocked_d, &blocked_b.changes_to(&blocked_d)).unwrap();
    assert_eq!(planner.key_modifier(), 3.0);
    step(
        &mut planner,
        &blocked_d,
        &[],
        [INF, 11.0, 1.0, 2.0, 0.0],
        [12.0, 2.0, 1.0, INF, 0.0],
        &[(B, [6.0, 2.0]), (D, [6.0, 2.0]), (A, [17.0, 12.0])],
        &[C, G],
        1.0,
    );

    planner.move_start(&blocked_d, G).unwrap();
    assert_eq!(planner.next_step(&blocked_d), None);
    assert_eq!(planner.compute_shortest_path(&blocked_d).unwrap().expansions, 0);
    assert_eq!(planner.cost(), Some(0.0));
}
