//! Paths of states in any space, as the planners return them: their length, the same path
//! interpolated to a resolution, and a re-check of every state and motion.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::paths::{PathFault, check, interpolate, length};
//! use trailmark_sample::R2;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let over = [Point::new(1.0, 1.0), Point::new(4.0, 9.0), Point::new(6.0, 9.0), Point::new(9.0, 1.0)];
//! assert!((length(&space, &over) - (2.0 * 73f64.sqrt() + 2.0)).abs() < 1e-12);
//! assert_eq!(check(&space, &checker, &over), Ok(()));
//! let fine = interpolate(&space, &over, 0.5)?; // no motion longer than 0.5
//! assert!(fine.windows(2).all(|m| (m[1] - m[0]).norm() <= 0.5 + 1e-12));
//! let through = [Point::new(1.0, 1.0), Point::new(9.0, 1.0)];
//! assert_eq!(check(&space, &checker, &through), Err(PathFault::Motion { index: 0 }));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use thiserror::Error;

use crate::plan::Rejection;
use crate::problem::admit;
use crate::space::StateSpace;
use crate::validity::Validity;

/// What is wrong with a path.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum PathFault {
    /// The path has no state.
    #[error("the path is empty")]
    Empty,
    /// A state is not finite, outside the bounds or invalid.
    #[error("state {index} is {reason}")]
    State {
        /// The state's index.
        index: usize,
        /// Why.
        reason: Rejection,
    },
    /// The motion from state `index` to the next is not valid.
    #[error("the motion from state {index} to the next is not valid")]
    Motion {
        /// The first state's index.
        index: usize,
    },
    /// [`interpolate`] at this resolution would return more than [`MAX_INTERPOLATED`] states.
    #[error("interpolating at {resolution} would give more than {max} states", max = MAX_INTERPOLATED)]
    TooManyStates {
        /// The resolution asked for.
        resolution: f64,
    },
    /// The resolution of [`interpolate`] is not positive and finite.
    #[error("the resolution must be positive and finite, got {0}")]
    Resolution(f64),
}

/// The most states [`interpolate`] returns.
pub const MAX_INTERPOLATED: usize = 10_000_000;

/// The length of `path`: its motions' distances summed (0 for one state or none).
pub fn length<S: StateSpace>(space: &S, path: &[S::State]) -> f64 {
    // A fold from +0: an empty float sum is -0.0, which a one-state path would report.
    path.windows(2).fold(0.0, |total, m| total + space.distance(&m[0], &m[1]))
}

/// `path` with states added along each motion (by the space's interpolation) so that none is
/// longer than `resolution`; the path's own states are all kept.
pub fn interpolate<S: StateSpace>(
    space: &S,
    path: &[S::State],
    resolution: f64,
) -> Result<Vec<S::State>, PathFault> {
    if !(resolution > 0.0 && resolution.is_finite()) {
        return Err(PathFault::Resolution(resolution));
    }
    let Some(first) = path.first() else { return Ok(Vec::new()) };
    let mut states = vec![first.clone()];
    for (index, m) in path.windows(2).enumerate() {
        let n = (space.distance(&m[0], &m[1]) / resolution).ceil().max(1.0);
        if !n.is_finite() {
            return Err(PathFault::Motion { index });
        }
        if states.len() as f64 + n > MAX_INTERPOLATED as f64 {
            return Err(PathFault::TooManyStates { resolution });
        }
        let n = n as usize;
        states.extend((1..n).map(|i| space.interpolate(&m[0], &m[1], i as f64 / n as f64)));
        states.push(m[1].clone());
    }
    Ok(states)
}

/// Whether every state of `path` is finite, in bounds and valid, and every motion valid: the
/// first fault found, states first.
pub fn check<S: StateSpace, V: Validity<S>>(
    space: &S,
    validity: &V,
    path: &[S::State],
) -> Result<(), PathFault> {
    if path.is_empty() {
        return Err(PathFault::Empty);
    }
    for (index, state) in path.iter().enumerate() {
        admit(space, validity, state).map_err(|reason| PathFault::State { index, reason })?;
    }
    match path.windows(2).position(|m| !validity.motion_is_valid(space, &m[0], &m[1])) {
        Some(index) => Err(PathFault::Motion { index }),
        None => Ok(()),
    }
}
