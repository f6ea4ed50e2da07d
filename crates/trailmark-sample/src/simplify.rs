//! Path shortcutting: fewer, shorter motions with the same ends.
//!
//! [`shortcut`] removes the states between two states of a path wherever the direct motion
//! between them is valid and cheaper, first greedily from the start (each state joined to the
//! farthest one it reaches directly), then at random pairs (OMPL's `reduceVertices`), seeded
//! for reproducibility. Every motion of the result is checked, so it is valid whenever the
//! input was, its ends are the input's, and it never costs more.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::simplify::shortcut;
//! use trailmark_sample::space::{R2, StateSpace};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let checker = PolygonWorld::new(bounds, vec![], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let zigzag = vec![Point::new(1.0, 1.0), Point::new(3.0, 4.0), Point::new(5.0, 1.0), Point::new(9.0, 9.0)];
//! let short = shortcut(&space, &checker, &zigzag, 50, 1);
//! assert_eq!(short, [Point::new(1.0, 1.0), Point::new(9.0, 9.0)]); // nothing in the way
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::space::StateSpace;
use crate::validity::Validity;

/// `path` with shortcuts taken: a greedy pass from the start, then `attempts` random pairs
/// drawn from a ChaCha8 generator seeded with `seed`. A shortcut is taken only when its motion
/// is valid and cheaper than the part of the path it replaces.
pub fn shortcut<S: StateSpace, V: Validity<S>>(
    space: &S,
    validity: &V,
    path: &[S::State],
    attempts: usize,
    seed: u64,
) -> Vec<S::State> {
    let mut path = path.to_vec();
    if path.len() < 3 {
        return path;
    }
    let cost = |path: &[S::State], i: usize, j: usize| -> f64 {
        path[i..=j].windows(2).fold(0.0, |total, m| total + space.distance(&m[0], &m[1]))
    };
    // Greedy: from each kept state, the farthest state reachable in one cheaper motion.
    let mut kept = vec![path[0].clone()];
    let mut i = 0;
    while i + 1 < path.len() {
        let mut next = i + 1;
        for j in (i + 2..path.len()).rev() {
            if space.distance(&path[i], &path[j]) < cost(&path, i, j)
                && validity.motion_is_valid(space, &path[i], &path[j])
            {
                next = j;
                break;
            }
        }
        kept.push(path[next].clone());
        i = next;
    }
    path = kept;
    // Random pairs.
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for _ in 0..attempts {
        if path.len() < 3 {
            break;
        }
        let i = rng.random_range(0..path.len() - 2);
        let j = rng.random_range(i + 2..path.len());
        if space.distance(&path[i], &path[j]) < cost(&path, i, j)
            && validity.motion_is_valid(space, &path[i], &path[j])
        {
            path.drain(i + 1..j);
        }
    }
    path
}
