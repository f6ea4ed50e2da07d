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

use std::cmp::Ordering;

use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::freespace::{Corner, FreeSpace, Location};
use trailmark_core::geometry::Point;
use trailmark_core::predicates::{orient, wedge_holds};

use crate::roadmap::{Roadmap, RoadmapQuery};

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
    /// Edges incident to each position: `incident[incident_start[p]..incident_start[p + 1]]`.
    incident_start: Vec<u32>,
    incident: Vec<u32>,
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
        let mut incident_start = vec![0u32; positions.len() + 1];
        for &[a, b] in space.edges() {
            incident_start[a as usize + 1] += 1;
            incident_start[b as usize + 1] += 1;
        }
        for p in 0..positions.len() {
            incident_start[p + 1] += incident_start[p];
        }
        let mut fill = incident_start.clone();
        let mut incident = vec![0u32; space.edges().len() * 2];
        for (e, &[a, b]) in space.edges().iter().enumerate() {
            for v in [a, b] {
                incident[fill[v as usize] as usize] = e as u32;
                fill[v as usize] += 1;
            }
        }
        let mut graph = VisibilityGraph {
            space,
            nodes,
            node_start,
            nodes_at,
            incident_start,
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
                sweep.run(self, node.at, Some(node.position as usize), wedge, &depart, None, |target| {
                    let Target::Position(w) = target else { return };
                    for &u in self.nodes_at(w) {
                        if (u as usize) > v && self.joins(node, &self.nodes[u as usize]) {
                            pairs.push((v as u32, u));
                        }
                    }
                });
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

    fn incident(&self, position: usize) -> &[u32] {
        &self.incident[self.incident_start[position] as usize..self.incident_start[position + 1] as usize]
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
            sweep.run(self, at, position, Wedge::full(at), &depart, extra, |target| {
                let w = match target {
                    Target::Extra => {
                        if goal_admits_start {
                            direct = Some((goal - at).norm());
                        }
                        return;
                    }
                    Target::Position(w) => w,
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
        Ok(RoadmapQuery::new(self, (start, goal), from_start, from_goal, direct))
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

/// What a sweep found visible.
enum Target {
    /// A boundary vertex position.
    Position(usize),
    /// The extra point of the sweep.
    Extra,
}

/// An edge crossed by the sweep ray, ordered by its distance from the centre along the ray.
#[derive(Clone, Copy, Debug)]
struct Active {
    a: Point,
    b: Point,
    /// `orient(a, b, centre)`: which side of the edge's line the centre is on (never 0: edges
    /// in line with the centre never enter the status). Fixed for the whole sweep.
    side: f64,
    id: u32,
}

impl Active {
    fn new(centre: Point, a: Point, b: Point, id: u32) -> Self {
        Active { a, b, side: orient(a, b, centre), id }
    }

    /// Nearer edges first. Two edges in the status never cross and both cross the current
    /// ray, so which is nearer does not depend on the ray: it is decided by which side of one
    /// edge's line the other edge and the centre lie. Ties (collinear edges) by id.
    fn order(&self, other: &Self) -> Ordering {
        if self.id == other.id {
            return Ordering::Equal;
        }
        nearer(self, other).then(self.id.cmp(&other.id))
    }
}

/// `Less` when edge `e` is nearer to the centre than edge `f` along a ray from the centre that
/// crosses both (edges that do not cross each other).
fn nearer(e: &Active, f: &Active) -> Ordering {
    let same = |x: f64, y: f64| (x > 0.0) == (y > 0.0);
    let verdict = |e_is_nearer: bool| if e_is_nearer { Ordering::Less } else { Ordering::Greater };
    let (a, b) = (e.a, e.b);
    let (p, q) = (f.a, f.b);
    // A shared endpoint s: compare the other ends, from the line s -> (f's other end), whose
    // side of the centre is f's own, or its opposite when the line runs q -> p.
    let shared = if a == p {
        Some((a, b, q, f.side))
    } else if a == q {
        Some((a, b, p, -f.side))
    } else if b == p {
        Some((b, a, q, f.side))
    } else if b == q {
        Some((b, a, p, -f.side))
    } else {
        None
    };
    if let Some((s, e_other, f_other, centre_side)) = shared {
        let side = orient(s, f_other, e_other);
        if side == 0.0 {
            return Ordering::Equal;
        }
        return verdict(same(side, centre_side));
    }
    let (sa, sb) = (orient(p, q, a), orient(p, q, b));
    if sa * sb >= 0.0 {
        // e lies on one side of f's line: nearer when the centre is on that side.
        let side = if sa != 0.0 { sa } else { sb };
        if side == 0.0 {
            return Ordering::Equal;
        }
        verdict(same(side, f.side))
    } else {
        // e straddles f's line, so f lies on one side of e's line.
        let (sp, sq) = (orient(a, b, p), orient(a, b, q));
        let side = if sp != 0.0 { sp } else { sq };
        if side == 0.0 {
            return Ordering::Equal;
        }
        verdict(!same(side, e.side))
    }
}

/// The edges crossed by the sweep ray, nearest first: a sorted vector (it holds few edges, so
/// shifting beats a tree's allocations and pointer chasing).
#[derive(Default)]
struct Status {
    edges: Vec<Active>,
}

impl Status {
    fn clear(&mut self) {
        self.edges.clear();
    }

    fn insert(&mut self, edge: Active) {
        let at = self.edges.partition_point(|x| x.order(&edge) == Ordering::Less);
        self.edges.insert(at, edge);
    }

    /// Removes the edge `id`; returns where it was.
    fn remove(&mut self, id: u32) -> Option<usize> {
        let at = self.edges.iter().position(|x| x.id == id)?;
        self.edges.remove(at);
        Some(at)
    }

    /// Inserts `edge` at `at`, where the edge it continues (ending at the vertex `edge` starts
    /// from) was: every other edge crossing the ray is nearer or farther than that vertex, so
    /// the order is unchanged. Where the neighbours say otherwise (boundary rings that cross
    /// after rounding), the edge is inserted by search instead.
    fn replace_at(&mut self, at: usize, edge: Active) {
        let after_previous =
            at == 0 || self.edges.get(at - 1).is_some_and(|x| x.order(&edge) == Ordering::Less);
        let before_next = self.edges.get(at).is_none_or(|x| x.order(&edge) == Ordering::Greater);
        if after_previous && before_next {
            self.edges.insert(at, edge);
        } else {
            self.insert(edge);
        }
    }

    fn first(&self) -> Option<&Active> {
        self.edges.first()
    }
}

/// The scratch space of Lee's rotational sweep, reused between sweeps.
#[derive(Default)]
struct Sweep {
    ignored: Vec<u32>,
    keyed: Vec<((f64, f64), u32)>,
    events: Vec<u32>,
    status: Status,
}

/// A ray from a sweep's centre: toward `through`, or exactly away from it when `reversed`.
/// (Reversing by flipping signs keeps the tests exact, where a reflected point would round.)
#[derive(Clone, Copy, Debug)]
struct Ray {
    through: Point,
    reversed: bool,
}

impl Ray {
    fn toward(through: Point) -> Self {
        Ray { through, reversed: false }
    }

    fn away_from(through: Point) -> Self {
        Ray { through, reversed: true }
    }

    fn sign(&self) -> f64 {
        if self.reversed { -1.0 } else { 1.0 }
    }

    /// The orientation of `p` relative to the ray (positive on its left). Exact sign.
    fn side(&self, centre: Point, p: Point) -> f64 {
        self.sign() * orient(centre, self.through, p)
    }

    /// Whether `p` lies on the ray (not behind the centre).
    fn holds(&self, centre: Point, p: Point) -> bool {
        self.side(centre, p) == 0.0 && self.sign() * (p - centre).dot(&(self.through - centre)) > 0.0
    }

    /// An approximate point on the ray, for floating-point sort keys only.
    fn approximate_point(&self, centre: Point) -> Point {
        if self.reversed { centre - (self.through - centre) } else { self.through }
    }
}

/// The part of the turn around a sweep's centre to look at: the closed wedge counter-clockwise
/// from ray `from` to ray `to` (the full turn when `to` is `None`).
#[derive(Clone, Copy, Debug)]
struct Wedge {
    from: Ray,
    to: Option<Ray>,
}

impl Wedge {
    fn full(centre: Point) -> Self {
        Wedge { from: Ray::toward(Point::new(centre.x + 1.0, centre.y)), to: None }
    }

    /// Whether the direction toward `p` lies in the wedge. Exact.
    fn contains(&self, centre: Point, p: Point) -> bool {
        let Some(to) = self.to else { return true };
        let from = self.from;
        // The orientation of `to` relative to `from`, with the rays' signs.
        let turn = -from.sign() * to.side(centre, from.through);
        let aligned = || from.sign() * to.sign() * (from.through - centre).dot(&(to.through - centre)) > 0.0;
        wedge_holds(turn, aligned, from.side(centre, p), to.side(centre, p))
    }
}

impl Sweep {
    /// Sweeps a ray around `centre` through `wedge`, calling `found` for every boundary vertex
    /// position (and the `extra` point, if any) in the wedge that the open segment from `centre`
    /// reaches through free space, leaving `centre` in a direction that `depart` accepts.
    /// Whether the segment may *end* there is the caller's test. `skip` is the position at
    /// `centre`, if it is a vertex.
    #[allow(clippy::too_many_arguments)]
    fn run(
        &mut self,
        graph: &VisibilityGraph,
        centre: Point,
        skip: Option<usize>,
        wedge: Wedge,
        depart: &dyn Fn(Point) -> bool,
        extra: Option<Point>,
        mut found: impl FnMut(Target),
    ) {
        let space = &graph.space;
        let positions = space.positions();
        let extra_id = positions.len() as u32;
        let point = |id: u32| if id == extra_id { extra.unwrap_or(centre) } else { positions[id as usize] };
        // Edges at the centre (a vertex, or a start on an edge) never block anything.
        self.ignored.clear();
        if let Some(p) = skip {
            self.ignored.extend_from_slice(graph.incident(p));
        } else {
            self.ignored.extend(space.edges_through(centre).map(|e| e as u32));
        }
        let ignored_edges = &self.ignored;
        let ignored = |e: usize| ignored_edges.contains(&(e as u32));

        // The events in the wedge, sorted by a floating-point pseudo-angle from the wedge's first
        // direction and by distance; an insertion pass with the exact order then repairs the few
        // near-ties that rounding got wrong.
        let origin = sweep_key(centre, wedge.from.approximate_point(centre)).0;
        self.keyed.clear();
        let candidates = (0..positions.len() as u32)
            .filter(|&i| Some(i as usize) != skip)
            .chain(extra.filter(|&x| x != centre).map(|_| extra_id));
        for id in candidates {
            let p = point(id);
            if wedge.contains(centre, p) {
                let (angle, distance) = sweep_key(centre, p);
                let relative = if angle < origin { angle + 4.0 - origin } else { angle - origin };
                self.keyed.push(((relative, distance), id));
            }
        }
        self.keyed.sort_unstable_by(|a, b| a.0.0.total_cmp(&b.0.0).then(a.0.1.total_cmp(&b.0.1)));
        self.events.clear();
        self.events.extend(self.keyed.iter().map(|&(_, id)| id));
        let exact = |i: u32, j: u32| {
            let (p, q) = (point(i), point(j));
            angular_order_from(centre, wedge.from, p, q).then_with(|| {
                let d = |r: Point| ((r.x - centre.x).abs(), (r.y - centre.y).abs());
                d(p).partial_cmp(&d(q)).unwrap_or(Ordering::Equal)
            })
        };
        for k in 1..self.events.len() {
            let mut j = k;
            while j > 0 && exact(self.events[j - 1], self.events[j]) == Ordering::Greater {
                self.events.swap(j - 1, j);
                j -= 1;
            }
        }

        // The edges crossing the first ray of the wedge, just before it.
        self.status.clear();
        let first = wedge.from;
        let on_ray = |p: Point| first.holds(centre, p);
        for e in 0..space.edges().len() {
            if ignored(e) {
                continue;
            }
            let (a, b) = space.edge_points(e);
            let (sa, sb) = (first.side(centre, a), first.side(centre, b));
            let active = (sa < 0.0 && sb > 0.0 && orient(a, b, centre) > 0.0)
                || (sb < 0.0 && sa > 0.0 && orient(b, a, centre) > 0.0)
                || (sb < 0.0 && on_ray(a))
                || (sa < 0.0 && on_ray(b));
            if active {
                self.status.insert(Active::new(centre, a, b, e as u32));
            }
        }

        let mut start = 0;
        while start < self.events.len() {
            // The group of events on one ray, nearest first.
            let direction = point(self.events[start]);
            let mut end = start + 1;
            while end < self.events.len() && exact_same_ray(centre, direction, point(self.events[end])) {
                end += 1;
            }
            let group = start..end;
            start = end;

            // Edges ending on this ray leave the tree.
            let vacancy = update_status(
                &mut self.status,
                graph,
                centre,
                &self.events[group.clone()],
                &self.ignored,
                None,
            );

            // Visibility along the ray: blocked by the nearest crossing edge, or at a vertex the
            // ray cannot pass through.
            let mut open = depart(direction);
            let mut previous: Option<u32> = None;
            for &id in &self.events[group.clone()] {
                if !open {
                    break;
                }
                let w = point(id);
                if let Some(p) = previous.filter(|&p| p != extra_id) {
                    open = space.passes_through(p as usize, centre, w);
                }
                if open && let Some(nearest) = self.status.first() {
                    let side = orient(nearest.a, nearest.b, centre);
                    open = side * orient(nearest.a, nearest.b, w) >= 0.0;
                }
                if open {
                    found(if id == extra_id { Target::Extra } else { Target::Position(id as usize) });
                }
                previous = Some(id);
            }

            // Edges starting on this ray enter the tree.
            update_status(&mut self.status, graph, centre, &self.events[group], &self.ignored, Some(vacancy));
        }
    }
}

/// Removes from the status the edges that end at the vertices `group` (on the current ray)
/// and lie clockwise of it (`entering` is `None`), or inserts those that start there and lie
/// counter-clockwise (`entering` holds what the removal returned). Edges in `ignored`, and the
/// extra point, are passed over.
///
/// The removal returns where its edge was when the group is one vertex with exactly one edge
/// ending there: the usual case of a ray passing a vertex of a boundary chain, whose one
/// entering edge then takes that place without a search.
fn update_status(
    status: &mut Status,
    graph: &VisibilityGraph,
    centre: Point,
    group: &[u32],
    ignored: &[u32],
    entering: Option<Option<usize>>,
) -> Option<usize> {
    let space = &graph.space;
    let positions = space.positions();
    let single = group.len() == 1;
    let (mut count, mut vacancy, mut entered) = (0, None, None);
    for &id in group.iter().filter(|&&id| (id as usize) < positions.len()) {
        let w = positions[id as usize];
        for &e in graph.incident(id as usize).iter().filter(|e| !ignored.contains(e)) {
            let (a, b) = space.edge_points(e as usize);
            let other = if a == w { b } else { a };
            let side = orient(centre, w, other);
            match entering {
                Some(place) if side > 0.0 => {
                    let edge = Active::new(centre, a, b, e);
                    count += 1;
                    match (place, count) {
                        // Hold the first edge back until it is known to be the only one.
                        (Some(_), 1) if single => entered = Some(edge),
                        _ => {
                            status.insert(edge);
                            if let Some(held) = entered.take() {
                                status.insert(held);
                            }
                        }
                    }
                }
                None if side < 0.0 => {
                    count += 1;
                    vacancy = status.remove(e);
                }
                _ => {}
            }
        }
    }
    if let (Some(edge), Some(Some(at))) = (entered, entering) {
        status.replace_at(at, edge);
    }
    if single && count == 1 { vacancy } else { None }
}

/// Whether `q` lies on the ray from `centre` through `p`. Exact.
fn exact_same_ray(centre: Point, p: Point, q: Point) -> bool {
    orient(centre, p, q) == 0.0 && (p - centre).dot(&(q - centre)) > 0.0
}

/// The order of the directions from `at` toward `p` and `q`, counter-clockwise starting from
/// ray `from`. Exact.
fn angular_order_from(at: Point, from: Ray, p: Point, q: Point) -> Ordering {
    let half = |r: Point| {
        let side = from.side(at, r);
        if side > 0.0 || (side == 0.0 && from.holds(at, r)) { 0 } else { 1 }
    };
    half(p).cmp(&half(q)).then_with(|| 0.0.partial_cmp(&orient(at, p, q)).unwrap_or(Ordering::Equal))
}

/// An approximate sort key for `p` around `centre`: a pseudo-angle in `[0, 4)` that increases
/// with the angle counter-clockwise from +x (the "diamond angle", no trigonometry), then the
/// distance in the L1 norm. Rounding may misorder near-ties; the sweep repairs them exactly.
fn sweep_key(centre: Point, p: Point) -> (f64, f64) {
    let (dx, dy) = (p.x - centre.x, p.y - centre.y);
    let l1 = dx.abs() + dy.abs();
    if l1 == 0.0 {
        return (0.0, 0.0);
    }
    let t = dy / l1;
    let angle = if dy > 0.0 || (dy == 0.0 && dx > 0.0) {
        if dx >= 0.0 { t } else { 2.0 - t }
    } else if dx < 0.0 {
        2.0 - t
    } else {
        4.0 + t
    };
    (angle, l1)
}
