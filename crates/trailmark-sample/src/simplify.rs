//! Path simplification: fewer, shorter motions with the same ends, then rounder corners.
//!
//! [`shortcut`] removes the states between two states of a path wherever the direct motion
//! between them is valid and cheaper, first greedily from the start (each state joined to the
//! farthest one it reaches directly), then at random pairs (OMPL's `reduceVertices`), seeded
//! for reproducibility. [`smooth`] cuts corners: it puts a state in the middle of every motion
//! and moves each old state toward the middle of its new neighbours where both motions to it
//! stay valid (Chaikin's corner cutting, as in OMPL's `smoothBSpline`). [`simplify`] runs the
//! two in turn. Every motion of a result is checked, so it is valid whenever the input was,
//! its ends are the input's, and it never costs more.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::simplify::{shortcut, smooth};
//! use trailmark_sample::space::{R2, StateSpace};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let checker = PolygonWorld::new(bounds, vec![], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let zigzag = vec![Point::new(1.0, 1.0), Point::new(3.0, 4.0), Point::new(5.0, 1.0), Point::new(9.0, 9.0)];
//! let short = shortcut(&space, &checker, &zigzag, 50, 1);
//! assert_eq!(short, [Point::new(1.0, 1.0), Point::new(9.0, 9.0)]); // nothing in the way
//!
//! // Around a wall's end: no shortcut, but the corner can be cut.
//! let wall = vec![vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 6.0), Point::new(4.0, 6.0)]];
//! let checker = PolygonWorld::new(bounds, wall, 0.0)?.checker();
//! let around = vec![Point::new(1.0, 1.0), Point::new(5.0, 9.5), Point::new(9.0, 1.0)];
//! let length = |p: &[Point]| p.windows(2).map(|m| (m[1] - m[0]).norm()).sum::<f64>();
//! assert_eq!(shortcut(&space, &checker, &around, 50, 1), around);
//! let round = smooth(&space, &checker, &around, 4);
//! assert!(length(&round) < length(&around) - 0.5);
//! assert!(round.windows(2).all(|m| checker.segment_is_free(m[0], m[1])));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::space::StateSpace;
use crate::validity::Validity;

/// `path` with shortcuts taken: a greedy pass from the start, then `attempts` random pairs
/// drawn from a ChaCha8 generator seeded with `seed`. A shortcut is taken only when its motion
/// is valid and no dearer than the part of the path it replaces (within 1e-12 of its cost, so
/// that states lying on a straight motion go, whatever the rounding of their distances).
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
            if shorter(space.distance(&path[i], &path[j]), cost(&path, i, j))
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
        if shorter(space.distance(&path[i], &path[j]), cost(&path, i, j))
            && validity.motion_is_valid(space, &path[i], &path[j])
        {
            path.drain(i + 1..j);
        }
    }
    path
}

/// Whether a direct motion of cost `direct` is worth taking instead of a part of a path costing
/// `part`: no dearer, within rounding.
fn shorter(direct: f64, part: f64) -> bool {
    direct <= part * (1.0 + 1e-12)
}

/// `path` with its corners cut, `passes` times at most: each pass puts a state in the middle
/// of every motion, then moves each of the path's previous states (not its ends) to the
/// middle of the corner it makes with the two new states beside it, where both motions to the
/// moved state are valid and the two together are shorter. The halves of motions no moved
/// state touches are checked too (a conservative checker may refuse part of a motion it
/// passed whole): if one fails, the pass is undone and smoothing ends. A pass that moves no
/// state ends it as well. Each pass about doubles the states (a few passes suffice; the final
/// shortcut pass of [`simplify`] removes those on straight motions). The result has the
/// input's ends; in a space whose interpolation follows its distance (Rⁿ, a joint space) it
/// never costs more.
pub fn smooth<S: StateSpace, V: Validity<S>>(
    space: &S,
    validity: &V,
    path: &[S::State],
    passes: usize,
) -> Vec<S::State> {
    let mut path = path.to_vec();
    for _ in 0..passes {
        if path.len() < 3 {
            break;
        }
        // Every motion split in two: the old states at the even places.
        let mut split = Vec::with_capacity(2 * path.len() - 1);
        for m in path.windows(2) {
            split.push(m[0].clone());
            split.push(space.interpolate(&m[0], &m[1], 0.5));
        }
        split.extend(path.last().cloned());
        // Per motion of `split`, whether it has been checked.
        let mut checked = vec![false; split.len() - 1];
        for i in (2..split.len() - 1).step_by(2) {
            let (before, corner, after) = (&split[i - 1], &split[i], &split[i + 1]);
            let middle = space.interpolate(before, after, 0.5);
            let cut = space.interpolate(corner, &middle, 0.5);
            let old = space.distance(before, corner) + space.distance(corner, after);
            let new = space.distance(before, &cut) + space.distance(&cut, after);
            if new < old
                && validity.motion_is_valid(space, before, &cut)
                && validity.motion_is_valid(space, &cut, after)
            {
                split[i] = cut;
                (checked[i - 1], checked[i]) = (true, true);
            }
        }
        if !checked.contains(&true) {
            break;
        }
        let halves_valid = checked
            .iter()
            .enumerate()
            .all(|(k, &done)| done || validity.motion_is_valid(space, &split[k], &split[k + 1]));
        if !halves_valid {
            break;
        }
        path = split;
    }
    path
}

/// [`shortcut`], then [`smooth`] with `passes`, then the greedy pass of [`shortcut`] again
/// (the middles smoothing added where a straight motion does as well): OMPL's
/// `simplifyMax` in three steps. Valid whenever `path` is, with its ends; in a space whose
/// interpolation follows its distance it never costs more.
pub fn simplify<S: StateSpace, V: Validity<S>>(
    space: &S,
    validity: &V,
    path: &[S::State],
    attempts: usize,
    passes: usize,
    seed: u64,
) -> Vec<S::State> {
    let short = shortcut(space, validity, path, attempts, seed);
    let round = smooth(space, validity, &short, passes);
    shortcut(space, validity, &round, 0, seed)
}
