//! Roadmaps of a world whose obstacles change, with node ids that stay put, so that D* Lite can
//! repair its path from the edges that changed instead of planning again.
//!
//! A [`DynamicRoadmap`] holds a [`VisibilityGraph`] or a [`Trapezoids`] decomposition of a
//! [`PolygonWorld`], plus *pinned* points (a robot's position and goal) joined to it as a
//! query would join them. When an obstacle is added or removed, the roadmap of the new world is
//! built again and compared with the old one node by node: a node is the same node when its
//! [`NodeKey`] is (a visibility corner: its position and its two boundary neighbours; a
//! trapezoid node: its position and kind), so it keeps its id; nodes that appear get new ids,
//! nodes that disappear keep theirs with no edges left. The change returns every edge whose
//! cost changed as [`EdgeChange`]s, in both directions.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_graph::dynamic::DynamicRoadmap;
//! use trailmark_graph::visibility::{Edges, VisibilityGraph};
//! use trailmark_search::{DStarLite, dijkstra};
//!
//! let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 10.0)?, vec![], 0.0)?;
//! let mut roadmap = DynamicRoadmap::<VisibilityGraph>::new(world, Edges::Tangent);
//! let (start, goal) = (roadmap.pin(Point::new(1.0, 5.0)), roadmap.pin(Point::new(9.0, 5.0)));
//! let mut planner = DStarLite::new(&roadmap, start, goal, roadmap.heuristic_between())?;
//! planner.compute_shortest_path(&roadmap)?;
//! assert_eq!(planner.cost(), Some(8.0)); // straight across
//!
//! // A wall appears between them: D* Lite repairs from the changed edges.
//! let wall = vec![Point::new(4.0, 2.0), Point::new(6.0, 2.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let changes = roadmap.add_obstacle(wall)?;
//! planner.update_edges(&roadmap, &changes)?;
//! planner.compute_shortest_path(&roadmap)?;
//! let around = 2.0 * (9.0f64 + 9.0).sqrt() + 2.0; // up to a corner, along the top, down again
//! assert!((planner.cost().unwrap() - around).abs() < 1e-9);
//! assert_eq!(planner.cost(), dijkstra(&roadmap, start, goal)?.cost());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::collections::HashMap;
use std::sync::{Arc, PoisonError, RwLock};

use thiserror::Error;
use trailmark_core::cost::Cost;
use trailmark_core::geometry::Point;
use trailmark_core::graph::{EdgeChange, Graph, IndexedGraph, Predecessors, Successors};
use trailmark_core::world::{PolygonWorld, WorldError};

use crate::roadmap::{Roadmap, RoadmapQuery};
use crate::trapezoid::Trapezoids;
use crate::visibility::{Edges, VisibilityGraph};

/// What names a roadmap node across rebuilds: the bits of its coordinates and of what else
/// tells it apart (a corner's neighbours, a trapezoid node's kind).
pub type NodeKey = [u64; 6];

/// A roadmap that [`DynamicRoadmap`] can build again after a change: undirected, over points.
pub trait Rebuild: Roadmap<Position = Point> + Sized {
    /// What a build takes besides the world.
    type Options: Copy;

    /// The roadmap of `world`'s free space.
    fn build(world: &PolygonWorld, options: Self::Options) -> Self;

    /// The key of `node`: two nodes of two builds with equal keys are the same node.
    fn node_key(&self, node: u32) -> NodeKey;

    /// The roadmap with `a` and `b` joined as a query joins them, or `None` when either is not
    /// in the free space.
    fn join(&self, a: Point, b: Point) -> Option<RoadmapQuery<'_, Self>>;
}

fn point_bits(p: Point) -> [u64; 2] {
    // +0.0 and -0.0 name the same point.
    [(p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()]
}

impl Rebuild for VisibilityGraph {
    /// Which edges to keep.
    type Options = Edges;

    fn build(world: &PolygonWorld, edges: Edges) -> Self {
        VisibilityGraph::with_edges(world.free_space(), edges)
    }

    fn node_key(&self, node: u32) -> NodeKey {
        let (at, corner) = self.corner(node);
        let ([x, y], [px, py], [nx, ny]) = (point_bits(at), point_bits(corner.prev), point_bits(corner.next));
        [x, y, px, py, nx, ny]
    }

    fn join(&self, a: Point, b: Point) -> Option<RoadmapQuery<'_, Self>> {
        self.query(a, b).ok()
    }
}

impl Rebuild for Trapezoids {
    /// Nothing to choose.
    type Options = ();

    fn build(world: &PolygonWorld, (): ()) -> Self {
        Trapezoids::new(&world.free_space())
    }

    fn node_key(&self, node: u32) -> NodeKey {
        let [x, y] = point_bits(self.position(node));
        let portal = u64::from(node as usize >= self.cell_count());
        [x, y, portal, 0, 0, 0]
    }

    fn join(&self, a: Point, b: Point) -> Option<RoadmapQuery<'_, Self>> {
        self.query(a, b).ok()
    }
}

/// Why an obstacle change was refused (the roadmap is then unchanged).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DynamicError {
    /// The new obstacle is not a valid polygon, or the obstacle to remove is not there
    /// ([`WorldError::NoSuchObstacle`]).
    #[error(transparent)]
    World(#[from] WorldError),
    /// A pinned point is not finite.
    #[error("a pinned point must be finite, got ({x}, {y})")]
    NotFinite {
        /// Its x coordinate.
        x: f64,
        /// Its y coordinate.
        y: f64,
    },
}

/// A roadmap of a changing world, with stable node ids and pinned points; see the
/// [module](self) documentation. It implements the graph traits, so every search runs on it,
/// and D* Lite repairs from what [`add_obstacle`](Self::add_obstacle) and
/// [`remove_obstacle`](Self::remove_obstacle) return.
#[derive(Clone, Debug)]
pub struct DynamicRoadmap<R: Rebuild> {
    world: PolygonWorld,
    options: R::Options,
    roadmap: R,
    /// Node `u` of `roadmap` is node `ids[u]` here.
    ids: Vec<u32>,
    keys: HashMap<NodeKey, u32>,
    positions: Vec<Point>,
    /// The positions again, shared with the heuristics handed out (which must see the nodes
    /// later changes add).
    shared: Arc<RwLock<Vec<Point>>>,
    pins: Vec<u32>,
    /// Each node's edges, sorted by neighbour.
    adjacency: Vec<Vec<(u32, Cost)>>,
}

impl<R: Rebuild> DynamicRoadmap<R> {
    /// The roadmap of `world`, built with `options`.
    pub fn new(world: PolygonWorld, options: R::Options) -> Self {
        let roadmap = R::build(&world, options);
        let mut this = DynamicRoadmap {
            world,
            options,
            roadmap,
            ids: Vec::new(),
            keys: HashMap::new(),
            positions: Vec::new(),
            shared: Arc::default(),
            pins: Vec::new(),
            adjacency: Vec::new(),
        };
        this.adjacency = this.connect();
        this
    }

    /// Adds a node at `point`, joined to the roadmap as a query joins a start (and to the other
    /// pinned points it would join directly), now and after every change; returns its id. A
    /// point outside the free space gets no edges until a change frees it.
    pub fn pin(&mut self, point: Point) -> u32 {
        let id = self.positions.len() as u32;
        self.positions.push(point);
        self.share();
        self.pins.push(id);
        self.adjacency = self.connect();
        id
    }

    /// [`pin`](Self::pin), refusing a point that is not finite.
    pub fn try_pin(&mut self, point: Point) -> Result<u32, DynamicError> {
        if !(point.x.is_finite() && point.y.is_finite()) {
            return Err(DynamicError::NotFinite { x: point.x, y: point.y });
        }
        Ok(self.pin(point))
    }

    /// Adds an obstacle (checked like the world's); returns the edges that changed.
    pub fn add_obstacle(&mut self, vertices: Vec<Point>) -> Result<Vec<EdgeChange<u32>>, DynamicError> {
        let world = self.world.with_obstacle(vertices)?;
        Ok(self.change(world))
    }

    /// Removes obstacle `index`; returns the edges that changed.
    pub fn remove_obstacle(&mut self, index: usize) -> Result<Vec<EdgeChange<u32>>, DynamicError> {
        let (world, _) = self.world.without_obstacle(index)?;
        Ok(self.change(world))
    }

    /// The current world.
    pub fn world(&self) -> &PolygonWorld {
        &self.world
    }

    /// The roadmap of the current world (its own node numbering).
    pub fn roadmap(&self) -> &R {
        &self.roadmap
    }

    /// The id here of the current roadmap's node `node`.
    pub fn id_of(&self, node: u32) -> u32 {
        self.ids[node as usize]
    }

    /// Every id ever given: the current roadmap's nodes, the pinned points, and nodes that a
    /// change removed (left without edges).
    pub fn node_count(&self) -> usize {
        self.positions.len()
    }

    /// Where node `id` is.
    ///
    /// # Panics
    ///
    /// If `id` is not below [`node_count`](Self::node_count): node ids are indices, as a
    /// slice's. [`get_position`](Self::get_position) is the checked form.
    pub fn position(&self, id: u32) -> Point {
        self.positions[id as usize]
    }

    /// Where node `id` is, `None` if the roadmap has no such node.
    pub fn get_position(&self, id: u32) -> Option<Point> {
        self.positions.get(id as usize).copied()
    }

    /// The edges of node `id`, by neighbour id.
    ///
    /// # Panics
    ///
    /// If `id` is not below [`node_count`](Self::node_count).
    /// [`get_neighbours`](Self::get_neighbours) is the checked form.
    pub fn neighbours(&self, id: u32) -> &[(u32, Cost)] {
        &self.adjacency[id as usize]
    }

    /// The edges of node `id`, `None` if the roadmap has no such node.
    pub fn get_neighbours(&self, id: u32) -> Option<&[(u32, Cost)]> {
        self.adjacency.get(id as usize).map(Vec::as_slice)
    }

    /// The straight-line distance between two nodes: an admissible, consistent heuristic for
    /// LPA*, D* Lite and AD*. It does not borrow the roadmap, and knows the nodes that later
    /// changes add.
    pub fn heuristic_between(&self) -> impl Fn(u32, u32) -> Cost + Clone + Send + Sync + 'static {
        let positions = Arc::clone(&self.shared);
        move |a, b| {
            let p = positions.read().unwrap_or_else(PoisonError::into_inner);
            (p[b as usize] - p[a as usize]).norm()
        }
    }

    /// Copies the positions the heuristics do not know yet.
    fn share(&self) {
        let mut shared = self.shared.write().unwrap_or_else(PoisonError::into_inner);
        let known = shared.len();
        shared.extend_from_slice(&self.positions[known..]);
    }

    /// Builds the roadmap of `world` and returns the edges that differ from the current ones.
    fn change(&mut self, world: PolygonWorld) -> Vec<EdgeChange<u32>> {
        self.roadmap = R::build(&world, self.options);
        self.world = world;
        let adjacency = self.connect();
        let mut changes = Vec::new();
        for (u, (old, new)) in self.adjacency.iter().zip(&adjacency).enumerate() {
            diff(u as u32, old, new, &mut changes);
        }
        for (u, new) in adjacency.iter().enumerate().skip(self.adjacency.len()) {
            diff(u as u32, &[], new, &mut changes);
        }
        self.adjacency = adjacency;
        changes
    }

    /// Gives the current roadmap's nodes their ids (new keys get new ones) and returns every
    /// node's edges: the roadmap's, and the pinned points'.
    fn connect(&mut self) -> Vec<Vec<(u32, Cost)>> {
        let roadmap = &self.roadmap;
        self.ids.clear();
        for u in 0..roadmap.node_count() as u32 {
            let next = self.positions.len() as u32;
            let id = *self.keys.entry(roadmap.node_key(u)).or_insert(next);
            if id == next {
                self.positions.push(roadmap.position(u));
            }
            self.ids.push(id);
        }
        self.share();
        let mut adjacency = vec![Vec::new(); self.positions.len()];
        for u in 0..roadmap.node_count() as u32 {
            let from = self.ids[u as usize];
            roadmap.for_each_out(u, |v, cost| adjacency[from as usize].push((self.ids[v as usize], cost)));
        }
        let ids = &self.ids;
        let mut link = |a: u32, b: u32, cost: Cost| {
            adjacency[a as usize].push((b, cost));
            adjacency[b as usize].push((a, cost));
        };
        let mut link_row = |pin: u32, row: &[Cost]| {
            for (v, &cost) in row.iter().enumerate() {
                if cost.is_finite() {
                    link(pin, ids[v], cost);
                }
            }
        };
        // One query per pair of pins joins both to the roadmap (the roadmap is undirected, so
        // the edges into the goal are also out of it) and tells whether they see each other.
        // A pin in no pair that could be joined (alone, or beside blocked pins) is joined alone.
        let mut joined = vec![false; self.pins.len()];
        let mut direct = Vec::new();
        for (i, &a) in self.pins.iter().enumerate() {
            for (j, &b) in self.pins.iter().enumerate().skip(i + 1) {
                let (p, q) = (self.positions[a as usize], self.positions[b as usize]);
                let Some(query) = roadmap.join(p, q) else { continue };
                let (from_a, into_b, between) = query.links();
                if !std::mem::replace(&mut joined[i], true) {
                    link_row(a, from_a);
                }
                if !std::mem::replace(&mut joined[j], true) {
                    link_row(b, into_b);
                }
                if let Some(cost) = between {
                    direct.push((a, b, cost));
                }
            }
        }
        for (_, &pin) in self.pins.iter().enumerate().filter(|&(i, _)| !joined[i]) {
            let at = self.positions[pin as usize];
            if let Some(query) = roadmap.join(at, at) {
                link_row(pin, query.links().0);
            }
        }
        for (a, b, cost) in direct {
            link(a, b, cost);
        }
        for edges in &mut adjacency {
            edges.sort_unstable_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
            edges.dedup_by_key(|e| e.0);
        }
        adjacency
    }
}

/// Appends the edges out of `u` whose cost differs between `old` and `new` (both sorted by
/// neighbour).
fn diff(u: u32, old: &[(u32, Cost)], new: &[(u32, Cost)], changes: &mut Vec<EdgeChange<u32>>) {
    let (mut i, mut j) = (0, 0);
    loop {
        let (a, b) = (old.get(i), new.get(j));
        match (a, b) {
            (None, None) => break,
            (Some(&(v, _)), None) => {
                changes.push(EdgeChange::new(u, v));
                i += 1;
            }
            (None, Some(&(v, _))) => {
                changes.push(EdgeChange::new(u, v));
                j += 1;
            }
            (Some(&(v, c)), Some(&(w, d))) => {
                if v < w {
                    changes.push(EdgeChange::new(u, v));
                    i += 1;
                } else if w < v {
                    changes.push(EdgeChange::new(u, w));
                    j += 1;
                } else {
                    if c != d {
                        changes.push(EdgeChange::new(u, v));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
    }
}

impl<R: Rebuild> Graph for DynamicRoadmap<R> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.positions.len()
    }
}

impl<R: Rebuild> Successors for DynamicRoadmap<R> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for &(v, c) in &self.adjacency[node as usize] {
            visit(v, c);
        }
    }
}

impl<R: Rebuild> Predecessors for DynamicRoadmap<R> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_successor(node, visit);
    }
}

impl<R: Rebuild> IndexedGraph for DynamicRoadmap<R> {
    fn node_bound(&self) -> usize {
        self.positions.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trailmark_core::world::Bounds;

    fn square(x: f64, y: f64, s: f64) -> Vec<Point> {
        vec![Point::new(x, y), Point::new(x + s, y), Point::new(x + s, y + s), Point::new(x, y + s)]
    }

    #[test]
    fn unchanged_nodes_keep_their_ids_and_changes_are_exact() {
        let world =
            PolygonWorld::new(Bounds::new(0.0, 0.0, 20.0, 20.0).unwrap(), vec![square(2.0, 2.0, 3.0)], 0.0)
                .unwrap();
        let mut roadmap = DynamicRoadmap::<VisibilityGraph>::new(world, Edges::All);
        let before: Vec<(u32, Point)> =
            (0..roadmap.node_count() as u32).map(|u| (u, roadmap.position(u))).collect();
        let old = roadmap.adjacency.clone();
        let changes = roadmap.add_obstacle(square(12.0, 12.0, 3.0)).unwrap();
        // The first square's corners keep their ids and positions; the new one's come after.
        for &(u, p) in &before {
            assert_eq!(roadmap.position(u), p);
        }
        assert_eq!(roadmap.node_count(), before.len() + 4);
        // Every reported change is a real difference, and every difference is reported.
        let cost = |adj: &[Vec<(u32, Cost)>], u: u32, v: u32| {
            adj.get(u as usize).and_then(|e| e.iter().find(|x| x.0 == v)).map_or(Cost::INFINITY, |x| x.1)
        };
        for c in &changes {
            assert_ne!(cost(&old, c.from, c.to), cost(&roadmap.adjacency, c.from, c.to));
        }
        let n = roadmap.node_count() as u32;
        let differing = (0..n)
            .flat_map(|u| (0..n).map(move |v| (u, v)))
            .filter(|&(u, v)| cost(&old, u, v) != cost(&roadmap.adjacency, u, v))
            .count();
        assert_eq!(differing, changes.len());
        // Removing it again restores the old edges exactly; its corners stay, without edges.
        let back = roadmap.remove_obstacle(1).unwrap();
        assert_eq!(back.len(), changes.len());
        assert_eq!(roadmap.adjacency[..before.len()], old[..before.len()]);
        assert!(roadmap.adjacency[before.len()..].iter().all(Vec::is_empty));
        assert_eq!(
            roadmap.remove_obstacle(5),
            Err(DynamicError::World(WorldError::NoSuchObstacle { index: 5, count: 1 }))
        );
        assert!(matches!(roadmap.try_pin(Point::new(f64::NAN, 0.0)), Err(DynamicError::NotFinite { .. })));
    }
}
