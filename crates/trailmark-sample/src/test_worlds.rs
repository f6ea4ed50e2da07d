//! Worlds the unit tests of several planners share, with their known optima.

use trailmark_core::geometry::Point;
use trailmark_core::world::{Bounds, CollisionChecker, PolygonWorld};

use crate::R2;

/// A 4 x 10 block between a start and a goal in a 40 x 40 room: the shortest path runs to a
/// corner of the block, along its side and down, 2√89 + 4. Its informed set soon shrinks to an
/// eighth of the room.
pub(crate) struct Block {
    pub(crate) space: R2,
    pub(crate) checker: CollisionChecker,
    pub(crate) start: Point,
    pub(crate) goal: Point,
    pub(crate) optimum: f64,
}

pub(crate) fn block() -> Block {
    let bounds = Bounds::new(0.0, 0.0, 40.0, 40.0).expect("valid bounds");
    let block =
        vec![Point::new(18.0, 15.0), Point::new(22.0, 15.0), Point::new(22.0, 25.0), Point::new(18.0, 25.0)];
    Block {
        space: R2::new(bounds),
        checker: PolygonWorld::new(bounds, vec![block], 0.0).expect("a valid world").checker(),
        start: Point::new(10.0, 20.0),
        goal: Point::new(30.0, 20.0),
        optimum: 2.0 * 89f64.sqrt() + 4.0,
    }
}
