//! The hierarchical abstraction: regions, the cells beside choke points, and the route segments
//! between them.
//!
//! Take the choke points out of the passable cells and what is left falls into connected
//! *regions*. Every route from the start to the goal alternates between runs inside one region
//! and runs through one choke point, and the cell before a run through a choke point (and the cell
//! after it) lies beside that choke point. So the abstraction keeps as its nodes the start, the
//! goal and every cell beside a choke point, and as its edges
//!
//! - *region segments* between two nodes of the same region, costed by a grid search confined to
//!   that region, computed on demand (one Dijkstra search per node, the first time a route leaves
//!   that node) and cached; until then an admissible estimate stands in: the straight-line grid
//!   distance times the cheapest terrain;
//! - *crossings* between two nodes beside the same choke point, costed by a grid search confined
//!   to the choke point and the cells beside it, usable only while that choke point is open.
//!
//! With every choke point open, the cheapest route in this graph costs exactly what the cheapest
//! route in the grid costs (`tests/abstraction.rs` checks it on random terrains).
//!
//! The graph forms a semantic network: regions and choke points, a choke point linked to the
//! regions it joins ([`Abstraction::regions_of_choke`]).

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};
use std::rc::Rc;

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, GridHeuristic};
use trailmark_search::Search;

use crate::regions::{NO_REGION, label_regions};
use crate::terrain::Terrain;
use crate::view::View;

/// A node of the abstraction: an index into [`Abstraction::nodes`].
pub type NodeId = u32;

/// A node: the start, the goal, or a cell beside a choke point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// The cell.
    pub cell: Cell,
    /// The region the cell belongs to.
    pub region: u32,
    /// The choke points beside the cell, as a bit mask: arriving here, the vehicle sees them.
    pub beside: u64,
}

/// The grid cells of a hop, first to last, and their cost.
pub type HopCells = (Vec<Cell>, Cost);

/// How a route moves from one node to the next.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Hop {
    /// Within one region.
    Region,
    /// Through the choke point with this id.
    Crossing(u8),
}

/// Cheapest routes from one node to every node, in a world where some choke points may be crossed.
#[derive(Debug, Clone)]
pub struct Routes {
    /// The cost to each node (`f64::INFINITY` if unreachable).
    pub cost: Vec<Cost>,
    /// The node before each node on its cheapest route, and how the route got from there.
    pub previous: Vec<Option<(NodeId, Hop)>>,
}

impl Routes {
    /// The nodes of the cheapest route to `to`, start first, with the hop into each; `None` when
    /// `to` cannot be reached.
    pub fn hops_to(&self, to: NodeId) -> Option<Vec<(NodeId, Hop)>> {
        if !self.cost[to as usize].is_finite() {
            return None;
        }
        let mut hops = vec![(to, Hop::Region)];
        let mut at = to;
        while let Some((prev, hop)) = self.previous[at as usize] {
            hops.last_mut().expect("not empty").1 = hop;
            hops.push((prev, Hop::Region));
            at = prev;
        }
        hops.reverse();
        Some(hops)
    }
}

/// What building and querying the abstraction cost.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AbstractionStats {
    /// Region-segment searches run (one per node whose segments were needed).
    pub segment_searches: usize,
    /// Grid cells those searches and the crossing searches expanded.
    pub grid_expansions: u64,
    /// Route computations over the abstract graph (cached per node and set of usable crossings).
    pub route_searches: usize,
}

/// Regions, nodes and route segments of a terrain, with the segment costs cached as they are
/// computed.
pub struct Abstraction<'t> {
    terrain: &'t Terrain,
    /// Row-major: the region of each passable cell outside the choke points.
    region_of: Vec<u32>,
    regions: usize,
    nodes: Vec<Node>,
    start: NodeId,
    goal: NodeId,
    /// The nodes of each region.
    region_nodes: Vec<Vec<NodeId>>,
    /// Each node's position in its region's list.
    slot: Vec<u32>,
    /// Per node: crossings to other nodes `(to, choke, cost)`.
    crossings: Vec<Vec<(NodeId, u8, Cost)>>,
    /// Per choke point: the regions it joins (by an actual crossing), sorted.
    choke_regions: Vec<Vec<u32>>,
    /// Per node: the exact region-segment costs to the nodes of its region, once computed.
    segments: Vec<Option<Box<[Cost]>>>,
    heuristic: GridHeuristic,
    min_cost: Cost,
    search: Search,
    routes: HashMap<(NodeId, u64), Rc<Routes>>,
    /// The grid cells and cost of each hop driven so far.
    hops: HashMap<(NodeId, NodeId, Hop), Rc<HopCells>>,
    /// Per node: the cost to the goal on the grid with every choke point open.
    goal_distance: Vec<Cost>,
    /// Per choke point: the nodes beside it.
    nodes_beside: Vec<Vec<NodeId>>,
    stats: AbstractionStats,
}

impl<'t> Abstraction<'t> {
    /// Finds the regions and nodes of `terrain` and costs its crossings. Region segments are
    /// costed later, when first needed.
    pub fn new(terrain: &'t Terrain) -> Self {
        let grid = terrain.grid();
        let width = grid.width() as usize;
        let index = |c: Cell| c.y as usize * width + c.x as usize;
        let graph = terrain.graph();

        let (region_of, regions) = label_regions(grid, graph, |c| terrain.choke_at(c).is_some());
        let regions = regions as u32;

        // Nodes: start, goal and the cells beside choke points, in row-major order.
        let mut node_of = HashMap::new();
        let mut nodes = Vec::new();
        for cell in grid.cells() {
            let beside = if region_of[index(cell)] == NO_REGION { 0 } else { terrain.chokes_beside(cell) };
            if beside != 0 || cell == terrain.start() || cell == terrain.goal() {
                node_of.insert(cell, nodes.len() as NodeId);
                nodes.push(Node { cell, region: region_of[index(cell)], beside });
            }
        }
        let mut region_nodes = vec![Vec::new(); regions as usize];
        let mut slot = Vec::with_capacity(nodes.len());
        for (id, node) in nodes.iter().enumerate() {
            let list = &mut region_nodes[node.region as usize];
            slot.push(list.len() as u32);
            list.push(id as NodeId);
        }

        let mut abstraction = Abstraction {
            terrain,
            region_of,
            regions: regions as usize,
            start: node_of[&terrain.start()],
            goal: node_of[&terrain.goal()],
            crossings: vec![Vec::new(); nodes.len()],
            segments: vec![None; nodes.len()],
            choke_regions: vec![Vec::new(); terrain.choke_points().len()],
            nodes,
            region_nodes,
            slot,
            heuristic: GridHeuristic::for_connectivity(terrain.connectivity()),
            min_cost: grid.min_cost().unwrap_or(1.0),
            search: Search::new(),
            routes: HashMap::new(),
            hops: HashMap::new(),
            goal_distance: Vec::new(),
            nodes_beside: vec![Vec::new(); terrain.choke_points().len()],
            stats: AbstractionStats::default(),
        };
        abstraction.cost_crossings();
        abstraction.measure_goal_distances();
        abstraction
    }

    /// Costs every node's distance to the goal on the whole grid with every choke point open:
    /// one Dijkstra search back from the goal.
    fn measure_goal_distances(&mut self) {
        let graph = self.terrain.graph();
        let found = self.search.dijkstra_all(graph, self.terrain.goal()).expect("the goal is passable");
        self.stats.grid_expansions += found.stats.expansions;
        self.goal_distance =
            self.nodes.iter().map(|n| self.search.cost_to(graph, n.cell).unwrap_or(f64::INFINITY)).collect();
    }

    /// Costs every crossing: from each node beside a choke point, a Dijkstra search confined to
    /// the choke point and the cells beside it.
    fn cost_crossings(&mut self) {
        let terrain = self.terrain;
        for choke in 0..terrain.choke_points().len() {
            let bit = 1u64 << choke;
            let beside: Vec<NodeId> = (0..self.nodes.len() as NodeId)
                .filter(|&n| self.nodes[n as usize].beside & bit != 0)
                .collect();
            let view = crossing_view(terrain, choke);
            let mut joined = Vec::new();
            self.nodes_beside[choke] = beside.clone();
            for &a in &beside {
                let found =
                    self.search.dijkstra_all(&view, self.nodes[a as usize].cell).expect("a node is passable");
                self.stats.grid_expansions += found.stats.expansions;
                for &b in &beside {
                    if a == b {
                        continue;
                    }
                    if let Some(cost) = self.search.cost_to(&view, self.nodes[b as usize].cell) {
                        self.crossings[a as usize].push((b, choke as u8, cost));
                        joined.push(self.nodes[a as usize].region);
                        joined.push(self.nodes[b as usize].region);
                    }
                }
            }
            joined.sort_unstable();
            joined.dedup();
            self.choke_regions[choke] = joined;
        }
    }

    /// The terrain.
    pub fn terrain(&self) -> &'t Terrain {
        self.terrain
    }

    /// The nodes: start, goal and the cells beside choke points.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The start's node.
    pub fn start(&self) -> NodeId {
        self.start
    }

    /// The goal's node.
    pub fn goal(&self) -> NodeId {
        self.goal
    }

    /// How many regions the choke points cut the passable cells into.
    pub fn region_count(&self) -> usize {
        self.regions
    }

    /// The region of a passable cell outside the choke points.
    pub fn region_at(&self, cell: Cell) -> Option<u32> {
        let grid = self.terrain.grid();
        if !grid.contains(cell) {
            return None;
        }
        let r = self.region_of[cell.y as usize * grid.width() as usize + cell.x as usize];
        (r != NO_REGION).then_some(r)
    }

    /// The regions a choke point joins: those of the nodes connected by a crossing through it.
    pub fn regions_of_choke(&self, choke: usize) -> &[u32] {
        &self.choke_regions[choke]
    }

    /// The nodes beside a choke point: where the vehicle sees it.
    pub fn nodes_beside(&self, choke: usize) -> &[NodeId] {
        &self.nodes_beside[choke]
    }

    /// The crossings from a node: `(to, choke, cost)`.
    pub fn crossings(&self, from: NodeId) -> &[(NodeId, u8, Cost)] {
        &self.crossings[from as usize]
    }

    /// What the abstraction has computed so far.
    pub fn stats(&self) -> AbstractionStats {
        self.stats
    }

    /// The admissible estimate of a region segment: the straight-line grid distance (octile on
    /// 8-connected grids, Manhattan on 4-connected) times the cheapest terrain.
    pub fn estimate(&self, a: NodeId, b: NodeId) -> Cost {
        let (p, q) = (self.nodes[a as usize].cell, self.nodes[b as usize].cell);
        self.heuristic.distance(p.x.abs_diff(q.x), p.y.abs_diff(q.y)) * self.min_cost
    }

    /// A lower bound on every route between `a` and `b`, whatever choke points are open: the
    /// larger of [`Abstraction::estimate`] and the difference of their distances to the goal with
    /// every choke point open (the grid's costs are symmetric, so by the triangle inequality no
    /// route between them costs less than that difference). Used for the region segments not
    /// computed yet, the second makes the goal bounds exact wherever the cheapest route with
    /// every choke point open is still usable.
    pub fn distance_bound(&self, a: NodeId, b: NodeId) -> Cost {
        let (da, db) = (self.goal_distance[a as usize], self.goal_distance[b as usize]);
        let difference = if da.is_finite() && db.is_finite() { (da - db).abs() } else { 0.0 };
        self.estimate(a, b).max(difference)
    }

    /// The region-segment cost from `a` to `b` (same region) if it has been computed.
    pub fn cached_segment(&self, a: NodeId, b: NodeId) -> Option<Cost> {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        debug_assert_eq!(na.region, nb.region);
        if let Some(row) = &self.segments[a as usize] {
            return Some(row[self.slot[b as usize] as usize]);
        }
        self.segments[b as usize].as_ref().map(|row| row[self.slot[a as usize] as usize])
    }

    /// The exact region-segment costs from `a` to every node of its region (computing and caching
    /// them on first use).
    pub fn segments_from(&mut self, a: NodeId) -> &[Cost] {
        if self.segments[a as usize].is_none() {
            let terrain = self.terrain;
            let region = self.nodes[a as usize].region;
            let view = region_view(terrain, &self.region_of, region);
            let found =
                self.search.dijkstra_all(&view, self.nodes[a as usize].cell).expect("a node is passable");
            self.stats.segment_searches += 1;
            self.stats.grid_expansions += found.stats.expansions;
            let row: Box<[Cost]> = self.region_nodes[region as usize]
                .iter()
                .map(|&b| self.search.cost_to(&view, self.nodes[b as usize].cell).unwrap_or(f64::INFINITY))
                .collect();
            self.segments[a as usize] = Some(row);
        }
        self.segments[a as usize].as_deref().expect("just computed")
    }

    /// The cheapest routes from `from` to every node when the choke points of `crossable` (a bit
    /// mask) may be crossed, with exact segment costs (computed as needed). Cached.
    pub fn routes(&mut self, from: NodeId, crossable: u64) -> Rc<Routes> {
        if let Some(routes) = self.routes.get(&(from, crossable)) {
            return Rc::clone(routes);
        }
        self.stats.route_searches += 1;
        let routes = Rc::new(self.dijkstra(from, crossable, Segments::Exact));
        self.routes.insert((from, crossable), Rc::clone(&routes));
        routes
    }

    /// Lower bounds on the cost from every node to the goal when the choke points of `crossable`
    /// may be crossed: a Dijkstra search back from the goal over exact segment costs where they
    /// are cached and lower bounds where they are not (the straight-line estimate, or the
    /// difference of the two nodes' distances to the goal with every choke point open, whichever
    /// is larger). Nothing new is computed on the grid. Returns the bounds and, for each node, the next hop of the bounding route.
    pub fn bounds_to_goal(&mut self, crossable: u64) -> Routes {
        // Segments and crossings are symmetric (the grid graph is), so searching forward from the
        // goal gives the costs back to it.
        self.dijkstra(self.goal, crossable, Segments::Bounds)
    }

    /// Dijkstra's algorithm over the abstract graph from `source`, crossing the choke points of
    /// `crossable`, with region segments costed as `segments` says.
    fn dijkstra(&mut self, source: NodeId, crossable: u64, segments: Segments) -> Routes {
        let n = self.nodes.len();
        let mut cost = vec![f64::INFINITY; n];
        let mut previous = vec![None; n];
        let mut done = vec![false; n];
        let mut heap = BinaryHeap::new();
        cost[source as usize] = 0.0;
        heap.push(Entry(0.0, source));
        while let Some(Entry(c, u)) = heap.pop() {
            if done[u as usize] {
                continue;
            }
            done[u as usize] = true;
            let region = self.nodes[u as usize].region as usize;
            let row: Vec<Cost> = match segments {
                Segments::Exact => self.segments_from(u).to_vec(),
                Segments::Bounds => self.region_nodes[region]
                    .iter()
                    .map(|&v| self.cached_segment(v, u).unwrap_or_else(|| self.distance_bound(v, u)))
                    .collect(),
            };
            let region_edges =
                self.region_nodes[region].iter().zip(row).map(|(&v, seg)| (v, Hop::Region, seg));
            let crossings = self.crossings[u as usize]
                .iter()
                .filter(|&&(_, choke, _)| crossable & (1 << choke) != 0)
                .map(|&(v, choke, seg)| (v, Hop::Crossing(choke), seg));
            for (v, hop, seg) in region_edges.chain(crossings) {
                let next = c + seg;
                if next < cost[v as usize] {
                    cost[v as usize] = next;
                    previous[v as usize] = Some((u, hop));
                    heap.push(Entry(next, v));
                }
            }
        }
        Routes { cost, previous }
    }

    /// The grid cells of one hop, `from` first and `to` last, and their cost (found by A* the
    /// first time, then cached: a plan tree drives the same hops in many branches).
    pub fn hop_cells(&mut self, from: NodeId, to: NodeId, hop: Hop) -> Rc<HopCells> {
        if let Some(found) = self.hops.get(&(from, to, hop)) {
            return Rc::clone(found);
        }
        let terrain = self.terrain;
        let (a, b) = (self.nodes[from as usize].cell, self.nodes[to as usize].cell);
        let h = terrain.graph().heuristic(self.heuristic, b);
        let found = match hop {
            Hop::Region => {
                let view = region_view(terrain, &self.region_of, self.nodes[from as usize].region);
                self.search.astar(&view, a, b, h)
            }
            Hop::Crossing(choke) => self.search.astar(&crossing_view(terrain, choke as usize), a, b, h),
        };
        let path = found.expect("nodes are passable").path.expect("a hop of a route is reachable");
        let found = Rc::new((path.nodes, path.cost));
        self.hops.insert((from, to, hop), Rc::clone(&found));
        found
    }

    /// The grid cells of a route given as hops (from [`Routes::hops_to`]), and its cost.
    pub fn route_cells(&mut self, hops: &[(NodeId, Hop)]) -> (Vec<Cell>, Cost) {
        let mut cells = vec![self.nodes[hops[0].0 as usize].cell];
        let mut cost = 0.0;
        for pair in hops.windows(2) {
            let part = self.hop_cells(pair[0].0, pair[1].0, pair[1].1);
            cells.extend_from_slice(&part.0[1..]);
            cost += part.1;
        }
        (cells, cost)
    }
}

/// How [`Abstraction::dijkstra`] costs region segments.
#[derive(Clone, Copy)]
enum Segments {
    /// Exactly, computing them on the grid as needed.
    Exact,
    /// Cached where computed, estimated where not: lower bounds, no grid search.
    Bounds,
}

/// The grid seen by a region segment: the cells of `region` only.
fn region_view<'a>(
    terrain: &'a Terrain,
    region_of: &'a [u32],
    region: u32,
) -> View<'a, impl Fn(Cell) -> bool + 'a> {
    let width = terrain.grid().width() as usize;
    View::new(terrain.graph(), move |c: Cell| region_of[c.y as usize * width + c.x as usize] == region)
}

/// The grid seen by a crossing: the cells of `choke` and the cells beside it.
fn crossing_view(terrain: &Terrain, choke: usize) -> View<'_, impl Fn(Cell) -> bool + '_> {
    let bit = 1u64 << choke;
    View::new(terrain.graph(), move |c: Cell| match terrain.choke_at(c) {
        Some(k) => k == choke,
        None => terrain.chokes_beside(c) & bit != 0,
    })
}

/// A heap entry ordered by least cost first, then by node id (for determinism).
#[derive(Clone, Copy, PartialEq)]
struct Entry(Cost, NodeId);

impl Eq for Entry {}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        other.0.total_cmp(&self.0).then_with(|| other.1.cmp(&self.1))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
