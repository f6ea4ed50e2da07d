//! The one-shot searches over a graph given by closures, as the `pathfinding` crate takes one: a
//! start node, a closure giving each node's successors with their costs, a heuristic for A*, and
//! a test of whether a node is a goal. Nodes are any `Eq + Hash + Clone + Debug` values (a road
//! junction's id, a grid cell, a puzzle position), costs plain `f64`.
//!
//! The searches are the graph searches of this crate, on a graph whose nodes are numbered as they
//! are met (a hash map from node to number), with the same results, statistics and errors: a
//! negative or NaN cost is an error, never a wrong path.
//!
//! Jump point search has no closure form: it jumps along the rows and columns of a grid, which a
//! successor closure does not show. On a grid, hand the grid itself to [`Jps`](crate::Jps).
//!
//! ```
//! use trailmark_search::closures::astar;
//!
//! // A road network: junctions by name, roads with their lengths in km.
//! let roads = |junction: &&str| -> Vec<(&str, f64)> {
//!     match *junction {
//!         "depot" => vec![("bridge", 4.0), ("ford", 2.5)],
//!         "bridge" => vec![("depot", 4.0), ("market", 3.0)],
//!         "ford" => vec![("depot", 2.5), ("market", 6.0)],
//!         _ => vec![],
//!     }
//! };
//! let found = astar(&"depot", roads, |_| 0.0, |j| *j == "market")?;
//! let path = found.path.expect("the market is reachable");
//! assert_eq!(path.nodes, ["depot", "bridge", "market"]);
//! assert_eq!(path.cost, 7.0);
//! # Ok::<(), trailmark_search::SearchError<&str>>(())
//! ```

use std::cell::RefCell;
use std::collections::hash_map::Entry;
use std::fmt::Debug;
use std::hash::Hash;

use trailmark_core::cost::Cost;
use trailmark_core::graph::{Graph, IndexedGraph, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::limits::{MAX_NODES, MAX_WEIGHT};
use crate::one_shot::SearchResult;
use crate::one_shot::workspace::Search;

// Each search below states its closures' bounds in full, as `pathfinding` does, so a user reads
// one signature; the bodies are one line each onto `Implicit`.

// Each public search spells out its bounds: they are its public signature (Rust has no trait alias).
/// A least-cost path from `start` to a node for which `success` holds, by A* with `heuristic`
/// (admissible: never more than the least cost to a goal): `pathfinding::prelude::astar`'s
/// arguments, trailmark's result.
///
/// With no goal reachable, the search ends when every reachable node is expanded (an infinite
/// graph never ends); more than [`MAX_NODES`] nodes met is [`SearchError::TooManyNodes`].
///
/// ```
/// use trailmark_search::closures::astar;
///
/// // A grid of 8-connected cells, 20 x 20, with a wall at x = 10 from y = 0 to 15.
/// let free = |(x, y): (i32, i32)| (0..20).contains(&x) && (0..20).contains(&y) && !(x == 10 && y < 16);
/// let successors = |&(x, y): &(i32, i32)| {
///     let moves = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)];
///     moves
///         .into_iter()
///         .filter(move |&(dx, dy)| free((x + dx, y + dy)) && free((x + dx, y)) && free((x, y + dy)))
///         .map(move |(dx, dy)| ((x + dx, y + dy), if dx != 0 && dy != 0 { 2f64.sqrt() } else { 1.0 }))
/// };
/// let goal = (19, 0);
/// let octile = |&(x, y): &(i32, i32)| {
///     let (dx, dy) = (f64::from((goal.0 - x).abs()), f64::from((goal.1 - y).abs()));
///     dx.max(dy) + (2f64.sqrt() - 1.0) * dx.min(dy)
/// };
/// let found = astar(&(0, 0), successors, octile, |&c| c == goal)?;
/// let path = found.path.expect("around the wall");
/// assert!(path.nodes.contains(&(10, 16)));
/// # Ok::<(), trailmark_search::SearchError<(i32, i32)>>(())
/// ```
pub fn astar<N, FN, IN, FH, FS>(
    start: &N,
    successors: FN,
    heuristic: FH,
    success: FS,
) -> Result<SearchResult<N>, SearchError<N>>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
    FH: FnMut(&N) -> Cost,
    FS: FnMut(&N) -> bool,
{
    Implicit::new(start, successors).best_first(heuristic, success, 1.0, true)
}

/// A path from `start` to a node for which `success` holds costing at most `weight` times the
/// least, by weighted A* with a consistent `heuristic` (see [`astar`]); `weight` from 1 to
/// [`MAX_WEIGHT`], else [`SearchError::InvalidWeight`].
pub fn weighted_astar<N, FN, IN, FH, FS>(
    start: &N,
    successors: FN,
    heuristic: FH,
    success: FS,
    weight: f64,
) -> Result<SearchResult<N>, SearchError<N>>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
    FH: FnMut(&N) -> Cost,
    FS: FnMut(&N) -> bool,
{
    if !(1.0..=MAX_WEIGHT).contains(&weight) {
        return Err(SearchError::InvalidWeight(weight));
    }
    Implicit::new(start, successors).best_first(heuristic, success, weight, false)
}

/// A least-cost path from `start` to a node for which `success` holds, by Dijkstra's algorithm
/// (see [`astar`]).
pub fn dijkstra<N, FN, IN, FS>(
    start: &N,
    successors: FN,
    success: FS,
) -> Result<SearchResult<N>, SearchError<N>>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
    FS: FnMut(&N) -> bool,
{
    Implicit::new(start, successors).best_first(|_| 0.0, success, 1.0, true)
}

/// A path with the fewest moves from `start` to a node for which `success` holds, by
/// breadth-first search; its cost is the sum of its moves' costs (see [`astar`]).
///
/// ```
/// use trailmark_search::closures::bfs;
///
/// // A sliding puzzle on a row of four: the blank (0) swaps with a neighbour, each move costs 1.
/// let moves = |p: &[u8; 4]| {
///     let b = p.iter().position(|&t| t == 0).expect("a blank");
///     let mut next = Vec::new();
///     for n in [b.wrapping_sub(1), b + 1] {
///         if n < 4 {
///             let mut q = *p;
///             q.swap(b, n);
///             next.push((q, 1.0));
///         }
///     }
///     next
/// };
/// let found = bfs(&[3, 1, 2, 0], moves, |p| *p == [0, 3, 1, 2])?;
/// assert_eq!(found.path.map(|p| p.nodes.len() - 1), Some(3));
/// # Ok::<(), trailmark_search::SearchError<[u8; 4]>>(())
/// ```
pub fn bfs<N, FN, IN, FS>(start: &N, successors: FN, success: FS) -> Result<SearchResult<N>, SearchError<N>>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
    FS: FnMut(&N) -> bool,
{
    Implicit::new(start, successors).uninformed::<true>(success)
}

/// A path from `start` to a node for which `success` holds, by depth-first search (see
/// [`astar`]).
pub fn dfs<N, FN, IN, FS>(start: &N, successors: FN, success: FS) -> Result<SearchResult<N>, SearchError<N>>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
    FS: FnMut(&N) -> bool,
{
    Implicit::new(start, successors).uninformed::<false>(success)
}

/// The nodes met so far, numbered in the order met.
struct Table<N> {
    nodes: Vec<N>,
    numbers: rustc_hash::FxHashMap<N, u32>,
    /// Whether a node went unnumbered because [`MAX_NODES`] were met.
    full: bool,
}

impl<N: Eq + Hash + Clone> Table<N> {
    /// The number of `node`, numbering it if it is new (`None`: no number left).
    #[inline]
    fn number(&mut self, node: N) -> Option<u32> {
        let next = self.nodes.len();
        match self.numbers.entry(node) {
            Entry::Occupied(known) => Some(*known.get()),
            Entry::Vacant(_) if next >= MAX_NODES => {
                self.full = true;
                None
            }
            Entry::Vacant(new) => {
                self.nodes.push(new.key().clone());
                new.insert(next as u32);
                Some(next as u32)
            }
        }
    }
}

/// A graph given by a successor closure, over the numbers of its nodes.
struct Implicit<N, FN> {
    table: RefCell<Table<N>>,
    successors: RefCell<FN>,
}

impl<N, FN, IN> Implicit<N, FN>
where
    N: Eq + Hash + Clone + Debug,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
{
    fn new(start: &N, successors: FN) -> Self {
        let mut table = Table { nodes: Vec::new(), numbers: rustc_hash::FxHashMap::default(), full: false };
        table.number(start.clone());
        Implicit { table: RefCell::new(table), successors: RefCell::new(successors) }
    }

    /// A*, weighted A* (`reopen` false) or Dijkstra's algorithm (a zero heuristic) over this
    /// graph, from its start.
    fn best_first(
        self,
        mut heuristic: impl FnMut(&N) -> Cost,
        mut success: impl FnMut(&N) -> bool,
        weight: f64,
        reopen: bool,
    ) -> Result<SearchResult<N>, SearchError<N>> {
        let h = |u| self.ask(u, &mut heuristic);
        let found =
            Search::new().best_first(&self, 0, None, h, weight, reopen, |u| self.ask(u as u32, &mut success));
        self.finish(found)
    }

    /// Breadth-first or depth-first search over this graph, from its start.
    fn uninformed<const BREADTH_FIRST: bool>(
        self,
        mut success: impl FnMut(&N) -> bool,
    ) -> Result<SearchResult<N>, SearchError<N>> {
        let found = Search::new()
            .uninformed::<_, _, BREADTH_FIRST>(&self, 0, None, |u| self.ask(u as u32, &mut success));
        self.finish(found)
    }

    /// `f` of the node numbered `u`.
    fn ask<T>(&self, u: u32, f: &mut impl FnMut(&N) -> T) -> T {
        f(&self.table.borrow().nodes[u as usize])
    }

    /// The search's outcome over numbers as one over nodes.
    fn finish(
        self,
        found: Result<SearchResult<u32>, SearchError<u32>>,
    ) -> Result<SearchResult<N>, SearchError<N>> {
        let table = self.table.into_inner();
        let node = |u: u32| table.nodes[u as usize].clone();
        if table.full {
            return Err(SearchError::TooManyNodes(MAX_NODES));
        }
        match found {
            Ok(SearchResult { path, stats }) => {
                let path =
                    path.map(|p| Path { nodes: p.nodes.into_iter().map(node).collect(), cost: p.cost });
                Ok(SearchResult { path, stats })
            }
            Err(error) => Err(error.map_node(node)),
        }
    }
}

impl<N, FN> Graph for Implicit<N, FN> {
    type Node = u32;

    fn contains(&self, node: u32) -> bool {
        (node as usize) < self.table.borrow().nodes.len()
    }
}

impl<N, FN, IN> Successors for Implicit<N, FN>
where
    N: Eq + Hash + Clone,
    FN: FnMut(&N) -> IN,
    IN: IntoIterator<Item = (N, Cost)>,
{
    fn for_each_successor<F: FnMut(u32, Cost)>(&self, node: u32, mut visit: F) {
        // The closure's successors own their nodes (`IN` cannot borrow its argument), so the
        // table is free to number them once the closure has returned; each is numbered and
        // visited in turn (the visit asks the heuristic, which reads the table).
        let next = {
            let table = self.table.borrow();
            (self.successors.borrow_mut())(&table.nodes[node as usize])
        };
        for (n, cost) in next {
            let number = self.table.borrow_mut().number(n);
            if let Some(v) = number {
                visit(v, cost);
            }
        }
    }
}

impl<N, FN> IndexedGraph for Implicit<N, FN> {
    fn node_bound(&self) -> usize {
        self.table.borrow().nodes.len()
    }

    fn index_of(&self, node: u32) -> usize {
        node as usize
    }

    fn node_at(&self, index: usize) -> u32 {
        index as u32
    }
}
