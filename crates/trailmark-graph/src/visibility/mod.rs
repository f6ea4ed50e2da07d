//! Visibility graphs: the shortest-path roadmap of a polygonal free space.
//!
//! The nodes are the convex obstacle vertices (where the free space turns by more than a half
//! turn, the only places a shortest path can bend); an edge joins two nodes wherever the straight
//! segment between them stays in free space (touching the boundary is allowed). A query adds
//! the start and goal as two more nodes, joined to every node they see and to each other. The
//! shortest path in this graph is the Euclidean shortest path in the free space.
//!
//! Construction is Lee's rotational sweep: around each node, the other vertices are sorted by
//! angle and a ray sweeps them once while an ordered status keeps the obstacle edges it crosses,
//! nearest first; a vertex is visible when the nearest of them is farther away. That is
//! O(n log n) per node, O(n² log n) in all, and a query's start and goal cost one sweep each.
//! Every test is an exact orientation predicate, so collinear vertices (grid maps are full of
//! them) and obstacles touching at a point are decided without tolerance.
//!
//! ```
//! use trailmark_core::freespace::FreeSpace;
//! use trailmark_core::geometry::Point;
//! use trailmark_core::{Grid, IndexedGraph};
//! use trailmark_graph::visibility::VisibilityGraph;
//!
//! // Blocked cells are unit squares (the GPPC any-angle convention).
//! let grid = Grid::from_rows(&["....", ".@@.", "...."])?;
//! let graph = VisibilityGraph::new(FreeSpace::from_grid(&grid));
//! assert_eq!(graph.node_count(), 4); // the four corners of the block
//!
//! let query = graph.query(Point::new(0.0, 1.5), Point::new(4.0, 1.5))?;
//! assert_eq!(query.node_bound(), 6); // plus the start and the goal
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::freespace::{Corner, FreeSpace};
use trailmark_core::geometry::Point;

use crate::roadmap::{Roadmap, RoadmapQuery};

mod lazy;
mod nodes;
mod scope;
mod sweep;

pub use lazy::{BoundedVisibility, LazyVisibilityGraph};
use nodes::VisibilityNodes;
use sweep::Sweep;

/// Which edges a [`VisibilityGraph`] keeps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Edges {
    /// Every pair of nodes that see each other.
    #[default]
    All,
    /// Only the edges along which a shortest path can run: at each node, the segment must not
    /// cut into the obstacle's corner (the *reduced* or tangent visibility graph). Shortest paths
    /// are the same; the graph is several times smaller.
    Tangent,
}

/// Why a visibility query was refused.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum VisibilityError {
    /// The start is not a finite point of the free space (or its boundary).
    #[error("the start ({x}, {y}) is not in free space")]
    StartBlocked {
        /// x of the start.
        x: f64,
        /// y of the start.
        y: f64,
    },
    /// The goal is not a finite point of the free space (or its boundary).
    #[error("the goal ({x}, {y}) is not in free space")]
    GoalBlocked {
        /// x of the goal.
        x: f64,
        /// y of the goal.
        y: f64,
    },
}

/// The visibility graph of a [`FreeSpace`]. Node `i` is a convex obstacle corner, at
/// [`VisibilityGraph::position`]; edges are undirected, with their Euclidean length as cost.
#[derive(Clone, Debug)]
pub struct VisibilityGraph {
    nodes: VisibilityNodes,
    offsets: Vec<u32>,
    targets: Vec<u32>,
    costs: Vec<Cost>,
}

impl VisibilityGraph {
    /// The full visibility graph of `space`.
    pub fn new(space: FreeSpace) -> Self {
        Self::with_edges(space, Edges::All)
    }

    /// The visibility graph of `space`, keeping the edges chosen by `edges`, built on every
    /// available core.
    pub fn with_edges(space: FreeSpace, edges: Edges) -> Self {
        Self::with_options(space, edges, 0)
    }

    /// The visibility graph of `space`, keeping the edges chosen by `edges`, with the sweeps
    /// shared among `threads` threads (`0`: as many as the machine has cores). The graph does
    /// not depend on the number of threads.
    pub fn with_options(space: FreeSpace, edges: Edges, threads: usize) -> Self {
        let mut graph = VisibilityGraph {
            nodes: VisibilityNodes::of(space, edges),
            offsets: Vec::new(),
            targets: Vec::new(),
            costs: Vec::new(),
        };
        let threads =
            if threads == 0 { std::thread::available_parallelism().map_or(1, |n| n.get()) } else { threads };
        graph.connect(threads.min(graph.nodes.nodes.len()).max(1));
        graph
    }

    /// Sweeps around every node and stores the edges in compressed rows.
    fn connect(&mut self, threads: usize) {
        let this = &*self;
        let mut pairs: Vec<(u32, u32)> = if threads == 1 {
            this.pairs_from(0, 1)
        } else {
            std::thread::scope(|scope| {
                let workers: Vec<_> =
                    (0..threads).map(|t| scope.spawn(move || this.pairs_from(t, threads))).collect();
                workers.into_iter().flat_map(|w| w.join().unwrap_or_default()).collect()
            })
        };
        pairs.sort_unstable();
        pairs.dedup();
        let n = self.nodes.nodes.len();
        let mut degree = vec![0u32; n + 1];
        for &(a, b) in &pairs {
            degree[a as usize + 1] += 1;
            degree[b as usize + 1] += 1;
        }
        for i in 0..n {
            degree[i + 1] += degree[i];
        }
        let mut fill = degree.clone();
        let mut targets = vec![0u32; pairs.len() * 2];
        let mut costs = vec![0.0; pairs.len() * 2];
        for &(a, b) in &pairs {
            let cost = (self.position(a) - self.position(b)).norm();
            for (from, to) in [(a, b), (b, a)] {
                let slot = fill[from as usize] as usize;
                targets[slot] = to;
                costs[slot] = cost;
                fill[from as usize] += 1;
            }
        }
        self.offsets = degree;
        self.targets = targets;
        self.costs = costs;
    }

    /// The edges `(v, u)`, `v < u`, found by sweeping around nodes `first`, `first + step`, ...
    fn pairs_from(&self, first: usize, step: usize) -> Vec<(u32, u32)> {
        let mut pairs = Vec::new();
        let mut sweep = Sweep::default();
        for v in (first..self.nodes.nodes.len()).step_by(step) {
            self.nodes.for_each_seen(&mut sweep, v as u32, None, |u| {
                if u as usize > v {
                    pairs.push((v as u32, u));
                }
            });
        }
        pairs
    }

    /// Where node `node` is and the boundary corner it stands for.
    pub(crate) fn corner(&self, node: u32) -> (Point, Corner) {
        let n = &self.nodes.nodes[node as usize];
        (n.at, n.corner)
    }

    /// The free space the graph was built on.
    pub fn space(&self) -> &FreeSpace {
        &self.nodes.space
    }

    /// The number of nodes (convex obstacle corners).
    pub fn node_count(&self) -> usize {
        self.nodes.nodes.len()
    }

    /// The number of undirected edges.
    pub fn edge_count(&self) -> usize {
        self.targets.len() / 2
    }

    /// Which edges this graph keeps.
    pub fn edges(&self) -> Edges {
        self.nodes.edges
    }

    /// The position of node `node`.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count): node ids are indices, as a
    /// slice's. [`get_position`](Self::get_position) is the checked form.
    pub fn position(&self, node: u32) -> Point {
        self.nodes.nodes[node as usize].at
    }

    /// The position of node `node`, `None` if the graph has no such node.
    pub fn get_position(&self, node: u32) -> Option<Point> {
        self.nodes.nodes.get(node as usize).map(|n| n.at)
    }

    /// The neighbours of `node` with the edge costs.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count).
    pub fn neighbours(&self, node: u32) -> impl Iterator<Item = (u32, Cost)> + '_ {
        let range = self.offsets[node as usize] as usize..self.offsets[node as usize + 1] as usize;
        self.targets[range.clone()].iter().copied().zip(self.costs[range].iter().copied())
    }

    /// The graph with `start` and `goal` added as nodes `node_count()` and `node_count() + 1`,
    /// joined to every node they see and to each other when they see each other. One sweep
    /// each: O(n log n) for n boundary vertices.
    pub fn query(&self, start: Point, goal: Point) -> Result<VisibilityQuery<'_>, VisibilityError> {
        let links = self.nodes.links(&mut Sweep::default(), (start, goal), None, |_| true)?;
        let [from_start, to_goal] = links.rows;
        Ok(RoadmapQuery::new(self, (start, goal), from_start, to_goal, links.direct)
            .expect("a link per roadmap node"))
    }
}

/// A visibility graph with a start and a goal: the graph to search for one query.
///
/// Nodes `0..n` are the graph's, `n` the start and `n + 1` the goal; it implements the graph
/// traits of `trailmark-core`, so every search algorithm runs on it.
pub type VisibilityQuery<'g> = RoadmapQuery<'g, VisibilityGraph>;

impl Roadmap for VisibilityGraph {
    type Position = Point;
    const DIRECTED: bool = false;

    fn node_count(&self) -> usize {
        self.nodes.nodes.len()
    }

    fn position(&self, node: u32) -> Point {
        self.nodes.nodes[node as usize].at
    }

    fn lower_bound(&self, a: Point, b: Point) -> Cost {
        (b - a).norm()
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for (u, c) in self.neighbours(node) {
            visit(u, c);
        }
    }
}
