//! The part of a free space a bounded sweep looks at: the boundary edges that may meet an
//! ellipse, and their ends.
//!
//! A segment from `a` whose every point p has |ap| + |pb| ≤ r lies in the ellipse with foci `a`
//! and `b`; only edges meeting that ellipse can block it. A sweep over those edges alone (their
//! ends as its events) finds every vertex of the ellipse that the full sweep finds.

use trailmark_core::freespace::FreeSpace;
use trailmark_core::geometry::Point;

/// The edges of a free space that may meet an ellipse, with their end positions, and marks to
/// test membership in O(1). Reused between sweeps.
#[derive(Clone, Debug, Default)]
pub(super) struct Scope {
    edges: Vec<u32>,
    positions: Vec<u32>,
    /// `edge_mark[e] == generation`: edge `e` is in the scope.
    edge_mark: Vec<u32>,
    position_mark: Vec<u32>,
    generation: u32,
}

impl Scope {
    /// Gathers the edges of `space` that may meet the ellipse {p : |a p| + |p b| ≤ reach}: every
    /// edge that does, and a few more (the test is on bounding boxes, with a margin for rounding).
    pub(super) fn ellipse(&mut self, space: &FreeSpace, (a, b): (Point, Point), reach: f64) {
        if self.edge_mark.len() != space.edges().len() || self.position_mark.len() != space.positions().len()
        {
            self.edge_mark = vec![0; space.edges().len()];
            self.position_mark = vec![0; space.positions().len()];
            self.generation = 0;
        }
        if self.generation == u32::MAX {
            self.edge_mark.fill(0);
            self.position_mark.fill(0);
            self.generation = 0;
        }
        self.generation += 1;
        self.edges.clear();
        self.positions.clear();
        // The distances below are rounded to a few units in the last place; the margin keeps
        // every box that truly meets the ellipse.
        let scale = reach.abs() + a.x.abs().max(a.y.abs()) + b.x.abs().max(b.y.abs());
        let reach = reach + 1e-9 * scale;
        let meets = |min: Point, max: Point| box_distance(a, min, max) + box_distance(b, min, max) <= reach;
        for e in space.edges_where(meets) {
            self.edge_mark[e] = self.generation;
            self.edges.push(e as u32);
            for p in space.edges()[e] {
                if self.position_mark[p as usize] != self.generation {
                    self.position_mark[p as usize] = self.generation;
                    self.positions.push(p);
                }
            }
        }
    }

    /// The edges in the scope.
    pub(super) fn edges(&self) -> &[u32] {
        &self.edges
    }

    /// The ends of the scope's edges.
    pub(super) fn positions(&self) -> &[u32] {
        &self.positions
    }

    /// Whether edge `e` is in the scope.
    pub(super) fn holds(&self, e: u32) -> bool {
        self.edge_mark.get(e as usize) == Some(&self.generation)
    }
}

/// The distance from `p` to the box `min..max` (0 inside).
fn box_distance(p: Point, min: Point, max: Point) -> f64 {
    let dx = (min.x - p.x).max(p.x - max.x).max(0.0);
    let dy = (min.y - p.y).max(p.y - max.y).max(0.0);
    (dx * dx + dy * dy).sqrt()
}
