//! What the planners' tests share.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_core::generate;
use trailmark_core::geometry::Point;
use trailmark_core::world::PolygonWorld;

/// A generated world of random convex obstacles (40 x 40) and two free points in it.
pub fn world_and_ends(count: usize, radius: f64, seed: u64) -> Option<(PolygonWorld, Point, Point)> {
    let world = generate::convex_obstacles(40.0, count, 6, radius, seed).ok()?;
    let checker = world.checker();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut free = || {
        (0..1000)
            .map(|_| Point::new(rng.random_range(0.0..40.0), rng.random_range(0.0..40.0)))
            .find(|&p| checker.point_is_free(p))
    };
    Some((world.clone(), free()?, free()?))
}
