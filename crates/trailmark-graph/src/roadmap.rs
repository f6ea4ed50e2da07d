//! What the continuous-space builders share: a roadmap of positioned nodes and the query graph
//! that joins a start and a goal to it.
//!
//! A [`Roadmap`] is built once (a visibility graph, a PRM, a Dubins roadmap, a trapezoidal
//! decomposition) and queried many times. A query must not change the roadmap, so it is a
//! separate graph, [`RoadmapQuery`]: the roadmap's nodes `0..n`, the start as node `n` and the
//! goal as node `n + 1`, with the edges that join them to the roadmap. It implements the graph
//! traits of `trailmark-core`, so every search algorithm runs on it.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Predecessors, Successors};

/// A graph of positioned nodes `0..node_count()`, as built by the roadmap builders.
pub trait Roadmap {
    /// Where a node is: a point, or a pose for a car-like robot.
    type Position: Copy;

    /// Whether an edge `u -> v` may lack its reverse `v -> u` (Dubins edges do).
    const DIRECTED: bool;

    /// The number of nodes.
    fn node_count(&self) -> usize;

    /// Where `node` is.
    fn position(&self, node: u32) -> Self::Position;

    /// The number of edges; an undirected edge counts once.
    fn count_edges(&self) -> usize {
        let mut links = 0;
        for node in 0..self.node_count() as u32 {
            self.for_each_out(node, |_, _| links += 1);
        }
        if Self::DIRECTED { links } else { links / 2 }
    }

    /// Each edge `u -> v` once (for an undirected roadmap, with `u < v`) as the pair of its end
    /// positions: what a picture of the roadmap draws.
    fn edge_ends(&self) -> Vec<(Self::Position, Self::Position)> {
        let mut edges = Vec::new();
        for u in 0..self.node_count() as u32 {
            self.for_each_out(u, |v, _| {
                if Self::DIRECTED || u < v {
                    edges.push((self.position(u), self.position(v)));
                }
            });
        }
        edges
    }

    /// A lower bound on the cost of any path from `a` to `b` (the straight-line distance), for
    /// an A* heuristic.
    fn lower_bound(&self, a: Self::Position, b: Self::Position) -> Cost;

    /// Calls `visit(v, cost)` for each edge `node -> v`.
    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, visit: F);

    /// Calls `visit(u, cost)` for each edge `u -> node` (its cost in the forward direction).
    /// Undirected roadmaps need not override it.
    fn for_each_in<F: FnMut(u32, Cost)>(&self, node: u32, visit: F) {
        self.for_each_out(node, visit)
    }
}

/// A roadmap with a start and a goal joined to it: the graph to search for one query.
///
/// Nodes `0..n` are the roadmap's, `n` is the start and `n + 1` the goal. Built by each
/// roadmap's `query` method.
#[derive(Clone, Debug)]
pub struct RoadmapQuery<'g, R: Roadmap> {
    roadmap: &'g R,
    start: R::Position,
    goal: R::Position,
    /// `from_start[v]`: the cost of the edge `start -> v`, infinite where there is none.
    from_start: Vec<Cost>,
    /// `to_goal[v]`: the cost of the edge `v -> goal`, infinite where there is none.
    to_goal: Vec<Cost>,
    /// The cost of the edge `start -> goal`, if there is one.
    direct: Option<Cost>,
}

impl<'g, R: Roadmap> RoadmapQuery<'g, R> {
    /// The query graph of `roadmap` with the given links: `from_start[v]` the cost of the edge
    /// `start -> v`, `to_goal[v]` that of `v -> goal` (infinite: no edge), `direct` that of
    /// `start -> goal`. `None` unless both have one entry per roadmap node. Each roadmap's
    /// `query` method builds it; a roadmap of another crate does too.
    pub fn new(
        roadmap: &'g R,
        (start, goal): (R::Position, R::Position),
        from_start: Vec<Cost>,
        to_goal: Vec<Cost>,
        direct: Option<Cost>,
    ) -> Option<Self> {
        let n = roadmap.node_count();
        (from_start.len() == n && to_goal.len() == n).then_some(Self {
            roadmap,
            start,
            goal,
            from_start,
            to_goal,
            direct,
        })
    }

    /// The roadmap the query was made on.
    pub fn roadmap(&self) -> &'g R {
        self.roadmap
    }

    /// The start node.
    pub fn start(&self) -> u32 {
        self.roadmap.node_count() as u32
    }

    /// The goal node.
    pub fn goal(&self) -> u32 {
        self.roadmap.node_count() as u32 + 1
    }

    /// Where `node` is.
    ///
    /// # Panics
    ///
    /// If `node` is neither a node of the roadmap nor the start or goal (below the roadmap's
    /// node count plus 2): node ids are indices, as a slice's.
    pub fn position(&self, node: u32) -> R::Position {
        match node as usize {
            n if n == self.roadmap.node_count() => self.start,
            n if n == self.roadmap.node_count() + 1 => self.goal,
            _ => self.roadmap.position(node),
        }
    }

    /// Where each of `nodes` is: a searched path's nodes as the polyline (or pose sequence) the
    /// robot follows.
    pub fn positions(&self, nodes: &[u32]) -> Vec<R::Position> {
        nodes.iter().map(|&n| self.position(n)).collect()
    }

    /// The straight-line distance from `node` to the goal: an admissible, consistent heuristic.
    pub fn heuristic(&self) -> impl Fn(u32) -> Cost + '_ {
        move |node| self.roadmap.lower_bound(self.position(node), self.goal)
    }

    /// The straight-line distance between two nodes: the heuristic of the incremental searches
    /// (LPA*, D* Lite, AD*), admissible and consistent.
    pub fn heuristic_between(&self) -> impl Fn(u32, u32) -> Cost + Copy + '_ {
        move |a, b| self.roadmap.lower_bound(self.position(a), self.position(b))
    }

    /// The edges out of the start and into the goal (by roadmap node, infinite where there is
    /// none), and the direct edge.
    pub(crate) fn links(&self) -> (&[Cost], &[Cost], Option<Cost>) {
        (&self.from_start, &self.to_goal, self.direct)
    }

    /// Whether an edge joins the start to the goal directly.
    pub fn sees_goal(&self) -> bool {
        self.direct.is_some()
    }

    /// The number of roadmap nodes joined to the start (out of it) and to the goal (into it).
    pub fn link_counts(&self) -> (usize, usize) {
        let count = |row: &[Cost]| row.iter().filter(|c| c.is_finite()).count();
        (count(&self.from_start), count(&self.to_goal))
    }
}

/// Calls `visit` for each finite entry of `row`.
fn for_each_link<F: FnMut(u32, Cost)>(row: &[Cost], visit: &mut F) {
    for (u, &c) in row.iter().enumerate() {
        if c.is_finite() {
            visit(u as u32, c);
        }
    }
}

impl<R: Roadmap> Graph for RoadmapQuery<'_, R> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.roadmap.node_count() + 2
    }
}

impl<R: Roadmap> Successors for RoadmapQuery<'_, R> {
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        let n = self.roadmap.node_count();
        let (start, goal) = (n as u32, n as u32 + 1);
        match node as usize {
            i if i == n => {
                for_each_link(&self.from_start, &mut visit);
                if let Some(c) = self.direct {
                    visit(goal, c);
                }
            }
            i if i == n + 1 => {
                if !R::DIRECTED {
                    for_each_link(&self.to_goal, &mut visit);
                    if let Some(c) = self.direct {
                        visit(start, c);
                    }
                }
            }
            i => {
                self.roadmap.for_each_out(node, &mut visit);
                if self.to_goal[i].is_finite() {
                    visit(goal, self.to_goal[i]);
                }
                if !R::DIRECTED && self.from_start[i].is_finite() {
                    visit(start, self.from_start[i]);
                }
            }
        }
    }
}

impl<R: Roadmap> Predecessors for RoadmapQuery<'_, R> {
    fn for_each_predecessor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        if !R::DIRECTED {
            return self.for_each_successor(node, visit);
        }
        let n = self.roadmap.node_count();
        match node as usize {
            i if i == n => {}
            i if i == n + 1 => {
                for_each_link(&self.to_goal, &mut visit);
                if let Some(c) = self.direct {
                    visit(n as u32, c);
                }
            }
            i => {
                self.roadmap.for_each_in(node, &mut visit);
                if self.from_start[i].is_finite() {
                    visit(n as u32, self.from_start[i]);
                }
            }
        }
    }
}

impl<R: Roadmap> IndexedGraph for RoadmapQuery<'_, R> {
    fn node_bound(&self) -> usize {
        self.roadmap.node_count() + 2
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}
