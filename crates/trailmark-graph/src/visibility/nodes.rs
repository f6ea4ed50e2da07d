//! The nodes of a visibility graph (the convex obstacle corners of a free space) and what every
//! visibility graph asks of them: where they are, which edges they keep, and the links of a
//! query's start and goal.

use trailmark_core::cost::Cost;
use trailmark_core::freespace::{Corner, FreeSpace, Location};
use trailmark_core::geometry::Point;
use trailmark_core::predicates::orient;

use super::scope::Scope;
use super::sweep::{Incidence, Ray, Sighting, Sweep, Wedge};
use super::{Edges, VisibilityError};

/// A node of a visibility graph: a convex obstacle corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Node {
    pub(super) at: Point,
    pub(super) position: u32,
    pub(super) corner: Corner,
}

/// A free space with its convex obstacle corners numbered: the node table a visibility graph
/// is built on, whether all at once or node by node.
#[derive(Clone, Debug)]
pub(super) struct VisibilityNodes {
    pub(super) space: FreeSpace,
    pub(super) nodes: Vec<Node>,
    /// Nodes at each position: `nodes_at[node_start[p]..node_start[p + 1]]`.
    node_start: Vec<u32>,
    nodes_at: Vec<u32>,
    /// The boundary edges at each position.
    pub(super) incident: Incidence,
    pub(super) edges: Edges,
}

/// The edges joining a query's start and goal to the nodes: `rows[0][u]` the length of the edge
/// start -> u, `rows[1][u]` that of u -> goal (infinite where there is none), and `direct` that of
/// start -> goal.
pub(super) struct Links {
    pub(super) rows: [Vec<Cost>; 2],
    pub(super) direct: Option<Cost>,
}

impl VisibilityNodes {
    /// The convex obstacle corners of `space`, keeping the edges chosen by `edges`.
    pub(super) fn of(space: FreeSpace, edges: Edges) -> Self {
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
        VisibilityNodes { space, nodes, node_start, nodes_at, incident, edges }
    }

    /// The nodes at boundary position `position`.
    pub(super) fn nodes_at(&self, position: usize) -> &[u32] {
        &self.nodes_at[self.node_start[position] as usize..self.node_start[position + 1] as usize]
    }

    /// The parts of the turn around `node` where its edges may leave: the corner's free wedge,
    /// or for tangent edges its two tangent parts (along each boundary edge, up to where the line
    /// through the node starts to cut into the corner).
    pub(super) fn wedges(&self, node: &Node) -> [Option<Wedge>; 2] {
        let (next, prev) = (node.corner.next, node.corner.prev);
        match self.edges {
            Edges::All => [Some(Wedge { from: Ray::toward(next), to: Some(Ray::toward(prev)) }), None],
            Edges::Tangent => [
                Some(Wedge { from: Ray::toward(next), to: Some(Ray::away_from(prev)) }),
                Some(Wedge { from: Ray::away_from(next), to: Some(Ray::toward(prev)) }),
            ],
        }
    }

    /// Sweeps around node `v` through its wedges and calls `found(u)` for every node `u` it sees
    /// that the graph joins to it, looking only at `scope`'s edges when one is given.
    pub(super) fn for_each_seen(
        &self,
        sweep: &mut Sweep,
        v: u32,
        scope: Option<&Scope>,
        mut found: impl FnMut(u32),
    ) {
        let node = &self.nodes[v as usize];
        let depart = |q: Point| node.corner.admits(node.at, q);
        for wedge in self.wedges(node).into_iter().flatten() {
            let centre = (node.at, Some(node.position as usize));
            sweep.run(&self.space, &self.incident, centre, wedge, &depart, None, scope, |target| {
                let Sighting::Position(w) = target else { return };
                for &u in self.nodes_at(w) {
                    if self.joins(node, &self.nodes[u as usize]) {
                        found(u);
                    }
                }
            });
        }
    }

    /// Whether an edge between two mutually visible nodes is kept: the segment leaves each
    /// node within its free wedge, and (for tangent edges) grazes each corner.
    pub(super) fn joins(&self, a: &Node, b: &Node) -> bool {
        a.corner.admits(a.at, b.at)
            && b.corner.admits(b.at, a.at)
            && (self.edges == Edges::All || (tangent(a, b.at) && tangent(b, a.at)))
    }

    /// Where the start and the goal lie; an error where one is blocked (or not finite).
    pub(super) fn check_ends(
        &self,
        start: Point,
        goal: Point,
    ) -> Result<(Location, Location), VisibilityError> {
        let start_location = self.space.locate(start);
        if start_location == Location::Blocked {
            return Err(VisibilityError::StartBlocked { x: start.x, y: start.y });
        }
        let goal_location = self.space.locate(goal);
        if goal_location == Location::Blocked {
            return Err(VisibilityError::GoalBlocked { x: goal.x, y: goal.y });
        }
        Ok((start_location, goal_location))
    }

    /// The links of a query from `start` to `goal`: each end joined to every node it sees
    /// (where the node keeps the edge) and for which `keep(node)` holds, and to each other. One
    /// sweep each, looking only at `scope`'s edges when one is given (the caller's `keep` then
    /// refuses every node the scope does not cover).
    pub(super) fn links(
        &self,
        sweep: &mut Sweep,
        (start, goal): (Point, Point),
        scope: Option<&Scope>,
        keep: impl Fn(Point) -> bool,
    ) -> Result<Links, VisibilityError> {
        let (start_location, goal_location) = self.check_ends(start, goal)?;
        let n = self.nodes.len();
        let mut rows = [vec![Cost::INFINITY; n], vec![Cost::INFINITY; n]];
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
            let row = &mut rows[end];
            sweep.run(
                &self.space,
                &self.incident,
                (at, position),
                Wedge::full(at),
                &depart,
                extra,
                scope,
                |target| {
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
                        if node.corner.admits(node.at, at)
                            && (self.edges == Edges::All || tangent(node, at))
                            && keep(node.at)
                        {
                            row[u as usize] = (node.at - at).norm();
                        }
                    }
                },
            );
        }
        Ok(Links { rows, direct })
    }
}

/// Whether the segment from node `a` toward `q` grazes its corner: both neighbouring boundary
/// vertices on the same closed side of the line.
fn tangent(a: &Node, q: Point) -> bool {
    orient(a.at, q, a.corner.prev) * orient(a.at, q, a.corner.next) >= 0.0
}
