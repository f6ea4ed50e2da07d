//! Visibility graphs: the shortest-path roadmap of a polygonal free space.
//!
//! The nodes are the convex obstacle vertices (where the free space turns by more than a half
//! turn, the only places a shortest path can bend); an edge joins two nodes wherever the straight
//! segment between them stays in free space (touching the boundary is allowed). A query adds
//! the start and goal as two more nodes, joined to every node they see and to each other. The
//! shortest path in this graph is the Euclidean shortest path in the free space.
//!
//! Construction is Lee's rotational sweep: around each node, the other vertices are sorted by
//! angle and a ray sweeps them once while a balanced tree keeps the obstacle edges it crosses,
//! ordered by distance; a vertex is visible when the nearest of them is farther away. That is
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
use trailmark_core::freespace::{Corner, FreeSpace, Location};
use trailmark_core::geometry::Point;
use trailmark_core::predicates::orient;

use crate::roadmap::{Roadmap, RoadmapQuery};

mod sweep;

use sweep::{Incidence, Ray, Sighting, Sweep, Wedge};

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

/// A node of a visibility graph: a convex obstacle corner.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    at: Point,
    position: u32,
    corner: Corner,
}

/// The visibility graph of a [`FreeSpace`]. Node `i` is a convex obstacle corner, at
/// [`VisibilityGraph::position`]; edges are undirected, with their Euclidean length as cost.
#[derive(Clone, Debug)]
pub struct VisibilityGraph {
    space: FreeSpace,
    nodes: Vec<Node>,
    /// Nodes at each position: `nodes_at[node_start[p]..node_start[p + 1]]`.
    node_start: Vec<u32>,
    nodes_at: Vec<u32>,
    /// The boundary edges at each position.
    incident: Incidence,
    offsets: Vec<u32>,
    targets: Vec<u32>,
    costs: Vec<Cost>,
    edges: Edges,
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
        let positions = space.positions();
        let mut nodes = Vec::new();
        let mut node_start = Vec::with_capacity(positions.len() + 1);
        let mut nodes_at = Vec::new();
        node_start.push(0);
        for (p, &at) in positions.iter().enumerate() {
            for &corner in space.corners(p) {
                if corner.is_convex_obstacle(at) {
                    nodes_at.push(nodes.len() as u32);
                    nodes.push(Node { at, position: p as u32, corner });
                }
            }
            node_start.push(nodes_at.len() as u32);
        }
        let incident = Incidence::of(&space);
        let mut graph = VisibilityGraph {
            space,
            nodes,
            node_start,
            nodes_at,
            incident,
            offsets: Vec::new(),
            targets: Vec::new(),
            costs: Vec::new(),
            edges,
        };
        let threads =
            if threads == 0 { std::thread::available_parallelism().map_or(1, |n| n.get()) } else { threads };
        graph.connect(threads.min(graph.nodes.len()).max(1));
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
        let n = self.nodes.len();
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
            let cost = (self.nodes[a as usize].at - self.nodes[b as usize].at).norm();
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
        for (v, node) in self.nodes.iter().enumerate().skip(first).step_by(step) {
            let depart = |q: Point| node.corner.admits(node.at, q);
            let (next, prev) = (node.corner.next, node.corner.prev);
            let free_wedge = Wedge { from: Ray::toward(next), to: Some(Ray::toward(prev)) };
            let wedges = match self.edges {
                // The free wedge of the corner.
                Edges::All => [Some(free_wedge), None],
                // Its two tangent parts: along each boundary edge, up to where the line through
                // the node starts to cut into the corner.
                Edges::Tangent => [
                    Some(Wedge { from: Ray::toward(next), to: Some(Ray::away_from(prev)) }),
                    Some(Wedge { from: Ray::away_from(next), to: Some(Ray::toward(prev)) }),
                ],
            };
            for wedge in wedges.into_iter().flatten() {
                sweep.run(
                    &self.space,
                    &self.incident,
                    node.at,
                    Some(node.position as usize),
                    wedge,
                    &depart,
                    None,
                    |target| {
                        let Sighting::Position(w) = target else { return };
                        for &u in self.nodes_at(w) {
                            if (u as usize) > v && self.joins(node, &self.nodes[u as usize]) {
                                pairs.push((v as u32, u));
                            }
                        }
                    },
                );
            }
        }
        pairs
    }

    /// Whether an edge between two mutually visible nodes is kept: the segment leaves each
    /// node within its free wedge, and (for tangent edges) grazes each corner.
    fn joins(&self, a: &Node, b: &Node) -> bool {
        a.corner.admits(a.at, b.at)
            && b.corner.admits(b.at, a.at)
            && (self.edges == Edges::All || (tangent(a, b.at) && tangent(b, a.at)))
    }

    /// Where node `node` is and the boundary corner it stands for.
    pub(crate) fn corner(&self, node: u32) -> (Point, Corner) {
        let n = &self.nodes[node as usize];
        (n.at, n.corner)
    }

    fn nodes_at(&self, position: usize) -> &[u32] {
        &self.nodes_at[self.node_start[position] as usize..self.node_start[position + 1] as usize]
    }

    /// The free space the graph was built on.
    pub fn space(&self) -> &FreeSpace {
        &self.space
    }

    /// The number of nodes (convex obstacle corners).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The number of undirected edges.
    pub fn edge_count(&self) -> usize {
        self.targets.len() / 2
    }

    /// Which edges this graph keeps.
    pub fn edges(&self) -> Edges {
        self.edges
    }

    /// The position of node `node`.
    ///
    /// # Panics
    ///
    /// If `node` is not below [`node_count`](Self::node_count): node ids are indices, as a
    /// slice's. [`get_position`](Self::get_position) is the checked form.
    pub fn position(&self, node: u32) -> Point {
        self.nodes[node as usize].at
    }

    /// The position of node `node`, `None` if the graph has no such node.
    pub fn get_position(&self, node: u32) -> Option<Point> {
        self.nodes.get(node as usize).map(|n| n.at)
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
        let start_location = self.space.locate(start);
        if start_location == Location::Blocked {
            return Err(VisibilityError::StartBlocked { x: start.x, y: start.y });
        }
        let goal_location = self.space.locate(goal);
        if goal_location == Location::Blocked {
            return Err(VisibilityError::GoalBlocked { x: goal.x, y: goal.y });
        }
        let n = self.nodes.len();
        let mut sweep = Sweep::default();
        let mut links = [vec![Cost::INFINITY; n], vec![Cost::INFINITY; n]];
        let mut direct = if start == goal { Some(0.0) } else { None };
        // Whether the goal may be entered from the start's direction (always, in open space).
        let goal_admits_start = self.space.departure(goal)(start);
        for (end, (at, location)) in [(start, start_location), (goal, goal_location)].into_iter().enumerate()
        {
            let position = if location == Location::Boundary { self.space.position_at(at) } else { None };
            let depart = self.space.departure(at);
            let other = if end == 0 && direct.is_none() { Some(goal) } else { None };
            let goal_position = other.and_then(|g| self.space.position_at(g));
            let extra = other.filter(|_| goal_position.is_none());
            let row = &mut links[end];
            sweep.run(&self.space, &self.incident, at, position, Wedge::full(at), &depart, extra, |target| {
                let w = match target {
                    Sighting::Extra => {
                        if goal_admits_start {
                            direct = Some((goal - at).norm());
                        }
                        return;
                    }
                    Sighting::Position(w) => w,
                };
                if goal_position == Some(w) && goal_admits_start {
                    direct = Some((goal - at).norm());
                }
                for &u in self.nodes_at(w) {
                    let node = &self.nodes[u as usize];
                    if node.corner.admits(node.at, at) && (self.edges == Edges::All || tangent(node, at)) {
                        row[u as usize] = (node.at - at).norm();
                    }
                }
            });
        }
        let [from_start, from_goal] = links;
        Ok(RoadmapQuery::new(self, (start, goal), from_start, from_goal, direct)
            .expect("a link per roadmap node"))
    }
}

/// Whether the segment from node `a` toward `q` grazes its corner: both neighbouring boundary
/// vertices on the same closed side of the line.
fn tangent(a: &Node, q: Point) -> bool {
    orient(a.at, q, a.corner.prev) * orient(a.at, q, a.corner.next) >= 0.0
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
        self.nodes.len()
    }

    fn position(&self, node: u32) -> Point {
        self.nodes[node as usize].at
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
