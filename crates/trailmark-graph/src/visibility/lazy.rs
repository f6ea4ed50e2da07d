//! Visibility graphs found as a search asks: a node's edges are swept when the search first
//! expands it, and only where a path no longer than a bound could run.
//!
//! With a start `s`, a goal `g` and a bound `U`, the graph keeps the edge `u -> w` only when
//! `|su| + |uw| + |wg| ≤ U`. That is every edge of every path of length at most `U` (a path's
//! prefix is no shorter than the straight line, nor its suffix), so a search that finds a path
//! of length at most `U` has found the shortest path of the full graph. Every point of such an
//! edge lies in the ellipse with foci `u` and `g` and sum `U - |su|`, so the sweep around `u`
//! looks only at the boundary edges near that ellipse: a few hundred where the full sweep looks
//! at every vertex. Rounds of growing bounds end at infinity (the plain lazy graph): the first
//! round whose path is within its bound has the answer, and a round that found a longer path
//! bounds the next by its length.

use std::cell::RefCell;

use trailmark_core::cost::Cost;
use trailmark_core::freespace::FreeSpace;
use trailmark_core::geometry::Point;

use super::nodes::{Links, VisibilityNodes};
use super::scope::Scope;
use super::sweep::Sweep;
use super::{Edges, VisibilityError};
use crate::roadmap::{Roadmap, RoadmapQuery};

/// How far past the shortest conceivable length (the straight line) the rounds look at most, as
/// fractions of it, before the unbounded round.
const ROUNDS: [f64; 4] = [1.0 / 128.0, 1.0 / 16.0, 0.5, 4.0];

/// The relative slack of the bound test, far above the rounding of a sum of three lengths: an
/// edge of a path no longer than the bound is never refused by rounding.
const SLACK: f64 = 1e-12;

/// A visibility graph whose edges are found on demand: the node table of a [`FreeSpace`] (its
/// convex obstacle corners, as [`VisibilityGraph`](super::VisibilityGraph) numbers them), built in
/// linear time, and one bounded graph per query ([`within`](Self::within)) whose nodes are
/// swept when first expanded. For one query among thousands of obstacles; the full graph is
/// the better choice for many queries on one world.
///
/// ```
/// use trailmark_core::freespace::FreeSpace;
/// use trailmark_core::geometry::Point;
/// use trailmark_core::{Grid, IndexedGraph};
/// use trailmark_graph::LazyVisibilityGraph;
/// use trailmark_search::astar;
///
/// let grid = Grid::from_rows(&["......", ".@@.@.", "......"])?;
/// let graph = LazyVisibilityGraph::new(FreeSpace::from_grid(&grid));
/// let (start, goal) = (Point::new(0.0, 1.5), Point::new(6.0, 1.5));
/// let mut bound = LazyVisibilityGraph::first_bound(start, goal);
/// let shortest = loop {
///     let bounded = graph.within(start, goal, bound)?;
///     let query = bounded.query();
///     let found = astar(&query, query.start(), query.goal(), query.heuristic())?;
///     let cost = found.path.map(|path| path.cost);
///     match bounded.next_bound(cost) {
///         Some(next) => bound = next,
///         None => break cost,
///     }
/// };
/// // Around the two blocks: up to their corners, along them, and back to the middle.
/// let expected = 2.0 * 0.5f64.hypot(1.0) + 4.0;
/// assert!((shortest.unwrap() - expected).abs() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct LazyVisibilityGraph {
    nodes: VisibilityNodes,
}

impl LazyVisibilityGraph {
    /// The lazy visibility graph of `space` with tangent edges (the shortest paths' edges).
    pub fn new(space: FreeSpace) -> Self {
        Self::with_edges(space, Edges::Tangent)
    }

    /// The lazy visibility graph of `space`, keeping the edges chosen by `edges`.
    pub fn with_edges(space: FreeSpace, edges: Edges) -> Self {
        LazyVisibilityGraph { nodes: VisibilityNodes::of(space, edges) }
    }

    /// The free space the graph stands on.
    pub fn space(&self) -> &FreeSpace {
        &self.nodes.space
    }

    /// The number of nodes (convex obstacle corners).
    pub fn node_count(&self) -> usize {
        self.nodes.nodes.len()
    }

    /// Which edges this graph keeps.
    pub fn edges(&self) -> Edges {
        self.nodes.edges
    }

    /// The bound of a query's first round: the straight-line distance from `start` to `goal`
    /// and 1/128 of it. [`BoundedVisibility::next_bound`] gives the next.
    pub fn first_bound(start: Point, goal: Point) -> Cost {
        let line = (goal - start).norm();
        line + line * ROUNDS[0]
    }

    /// The graph of a query from `start` to `goal` keeping only the edges of paths no longer
    /// than `bound` (infinity: every edge), with the start and the goal linked to the nodes. Two
    /// sweeps, over the boundary near the ellipse of the bound; the other sweeps wait for the
    /// search.
    ///
    /// # Errors
    ///
    /// [`VisibilityError`] when the start or the goal is not in free space.
    pub fn within(
        &self,
        start: Point,
        goal: Point,
        bound: Cost,
    ) -> Result<BoundedVisibility<'_>, VisibilityError> {
        let mut cache = Cache { out: vec![UNSWEPT; self.node_count()], ..Cache::default() };
        cache.into = cache.out.clone();
        let line = (goal - start).norm();
        let bounded = bound.is_finite();
        let reach = slack(bound);
        if bounded {
            cache.scope.ellipse(&self.nodes.space, (start, goal), reach);
        }
        let scope = bounded.then_some(&cache.scope);
        let keep = |p: Point| (p - start).norm() + (goal - p).norm() <= reach;
        let links = if line <= reach {
            self.nodes.links(&mut cache.sweep, (start, goal), scope, keep)?
        } else {
            // No path is that short (or the bound is no number): no edge at all, once the ends
            // are known to be free.
            self.nodes.check_ends(start, goal)?;
            let n = self.node_count();
            Links { rows: [vec![Cost::INFINITY; n], vec![Cost::INFINITY; n]], direct: None }
        };
        Ok(BoundedVisibility { graph: self, start, goal, bound, links, cache: RefCell::new(cache) })
    }
}

/// The bound with the slack of [`SLACK`].
fn slack(bound: Cost) -> Cost {
    bound + bound * SLACK
}

/// A node's edges not yet swept.
const UNSWEPT: (u32, u32) = (u32::MAX, u32::MAX);

/// What a bounded graph has swept so far, and the scratch space of its sweeps.
#[derive(Default)]
struct Cache {
    sweep: Sweep,
    scope: Scope,
    /// `out[v]`: the range of `out_edges` holding the edges out of `v`, [`UNSWEPT`] until swept.
    out: Vec<(u32, u32)>,
    out_edges: Vec<(u32, Cost)>,
    /// The same for the edges into each node.
    into: Vec<(u32, u32)>,
    into_edges: Vec<(u32, Cost)>,
}

/// A [`LazyVisibilityGraph`] for one query and one bound: a [`Roadmap`] (directed: the bound
/// keeps `u -> w` where it may drop `w -> u`) whose edges are swept when a search first asks for
/// them, and remembered. [`query`](Self::query) joins the start and the goal.
pub struct BoundedVisibility<'g> {
    graph: &'g LazyVisibilityGraph,
    start: Point,
    goal: Point,
    bound: Cost,
    links: Links,
    cache: RefCell<Cache>,
}

impl std::fmt::Debug for BoundedVisibility<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BoundedVisibility")
            .field("start", &self.start)
            .field("goal", &self.goal)
            .field("bound", &self.bound)
            .field("swept", &self.swept())
            .finish_non_exhaustive()
    }
}

impl<'g> BoundedVisibility<'g> {
    /// The graph to search: the nodes, the start as node `node_count()`, the goal as node
    /// `node_count() + 1`.
    pub fn query(&self) -> RoadmapQuery<'_, Self> {
        let [from_start, to_goal] = self.links.rows.clone();
        RoadmapQuery::new(self, (self.start, self.goal), from_start, to_goal, self.links.direct)
            .expect("a link per roadmap node")
    }

    /// The graph this query was made on.
    pub fn graph(&self) -> &'g LazyVisibilityGraph {
        self.graph
    }

    /// The bound on the length of the paths this graph keeps.
    pub fn bound(&self) -> Cost {
        self.bound
    }

    /// Whether a path of length `cost` found by an optimal search of this graph is the shortest
    /// of the full visibility graph: it is no longer than the bound.
    pub fn certifies(&self, cost: Cost) -> bool {
        cost <= self.bound
    }

    /// What to do after searching this graph, which found a path of length `found` (`None`: no
    /// path): `None` when the search is over (the path is no longer than the bound, so it is the
    /// full graph's shortest when the search is optimal; or the bound was already infinite, so
    /// the answer is the full graph's), else the next round's bound. That is the length found,
    /// when a path was (the shortest is no longer, so an optimal search of that round ends), but
    /// at most the next of the straight line times 1 + 1/16, 1.5, 5, then infinity; after a
    /// round bounded by a length found, that next step: a search that finds no path, or paths
    /// longer than the shortest, still ends within ten rounds.
    pub fn next_bound(&self, found: Option<Cost>) -> Option<Cost> {
        if self.bound == Cost::INFINITY || found.is_some_and(|c| self.certifies(c)) {
            return None;
        }
        let line = (self.goal - self.start).norm();
        let mut steps = ROUNDS.iter().map(|r| line + line * r);
        let grown = steps.clone().find(|&b| b > self.bound).unwrap_or(Cost::INFINITY);
        // A bound that is no step of the sequence was a length found: after it, the next step,
        // so that a search returning ever longer paths meets every step in turn.
        let stepped = steps.any(|b| b == self.bound);
        Some(found.filter(|_| stepped).map_or(grown, |c| c.min(grown)))
    }

    /// The number of nodes whose edges (out or in) have been swept.
    pub fn swept(&self) -> usize {
        let cache = self.cache.borrow();
        cache.out.iter().zip(&cache.into).filter(|(o, i)| **o != UNSWEPT || **i != UNSWEPT).count()
    }

    /// The edges `node -> u` (`into`: `u -> node`), swept on the first call and remembered.
    fn edges(&self, node: u32, into: bool) -> Vec<(u32, Cost)> {
        let mut guard = self.cache.borrow_mut();
        let cache = &mut *guard;
        let (ranges, edges) = if into {
            (&mut cache.into, &mut cache.into_edges)
        } else {
            (&mut cache.out, &mut cache.out_edges)
        };
        let Some(&range) = ranges.get(node as usize) else { return Vec::new() };
        if range != UNSWEPT {
            return edges[range.0 as usize..range.1 as usize].to_vec();
        }
        let nodes = &self.graph.nodes;
        let at = nodes.nodes[node as usize].at;
        let first = edges.len();
        let reach = slack(self.bound);
        // The path start -> node (straight at best) and node -> goal, for an edge out of or into
        // `node`; the ellipse holding the edge's other part.
        let (before, after) = ((at - self.start).norm(), (self.goal - at).norm());
        let foci = if into { (self.start, at) } else { (at, self.goal) };
        let scoped = self.bound.is_finite();
        if before + after <= reach {
            if scoped {
                cache.scope.ellipse(&nodes.space, foci, reach - if into { after } else { before });
            }
            let scope = scoped.then_some(&cache.scope);
            nodes.for_each_seen(&mut cache.sweep, node, scope, |u| {
                let there = nodes.nodes[u as usize].at;
                let length = (there - at).norm();
                let rest = if into {
                    (there - self.start).norm() + after
                } else {
                    before + (self.goal - there).norm()
                };
                if rest + length <= reach {
                    edges.push((u, length));
                }
            });
        }
        ranges[node as usize] = (first as u32, edges.len() as u32);
        edges[first..].to_vec()
    }

    /// Every edge swept so far, out of or into a node, as a pair of nodes (the smaller first:
    /// the full graph's edges are undirected), each once.
    fn swept_edges(&self) -> Vec<(u32, u32)> {
        let cache = self.cache.borrow();
        let mut pairs = Vec::new();
        for (v, &(a, b)) in cache.out.iter().enumerate().filter(|(_, r)| **r != UNSWEPT) {
            pairs.extend(cache.out_edges[a as usize..b as usize].iter().map(|&(u, _)| ordered(v as u32, u)));
        }
        for (v, &(a, b)) in cache.into.iter().enumerate().filter(|(_, r)| **r != UNSWEPT) {
            pairs.extend(cache.into_edges[a as usize..b as usize].iter().map(|&(u, _)| ordered(u, v as u32)));
        }
        pairs.sort_unstable();
        pairs.dedup();
        pairs
    }
}

/// The pair `(a, b)` with the smaller first.
fn ordered(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

impl Roadmap for BoundedVisibility<'_> {
    type Position = Point;
    const DIRECTED: bool = true;

    fn node_count(&self) -> usize {
        self.graph.node_count()
    }

    fn position(&self, node: u32) -> Point {
        self.graph.nodes.nodes[node as usize].at
    }

    /// The edges swept so far (the graph's other edges are never looked at), each pair of
    /// nodes once.
    fn count_edges(&self) -> usize {
        self.swept_edges().len()
    }

    /// The edges swept so far, each pair of nodes once.
    fn edge_ends(&self) -> Vec<(Point, Point)> {
        self.swept_edges().into_iter().map(|(u, v)| (self.position(u), self.position(v))).collect()
    }

    fn lower_bound(&self, a: Point, b: Point) -> Cost {
        (b - a).norm()
    }

    fn for_each_out<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for (u, c) in self.edges(node, false) {
            visit(u, c);
        }
    }

    fn for_each_in<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        for (u, c) in self.edges(node, true) {
            visit(u, c);
        }
    }
}
