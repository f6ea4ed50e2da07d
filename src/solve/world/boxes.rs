//! Box worlds as documents give them: axis-aligned boxes in `N` dimensions (each dimension its
//! own type), and start and goal states.

use trailmark_core::geometry::SVector;
use trailmark_sample::BoxWorld;

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{BoxesSpec, ProblemSpec};

/// The most axes of a box world.
pub const MAX_BOX_DIMENSION: usize = 8;

/// `$f::<N>($args)` for the box world's dimension `N`: each dimension is its own type (the
/// states are fixed-size vectors), from 1 to [`MAX_BOX_DIMENSION`].
macro_rules! by_dimension {
    ($world:expr, $f:ident $args:tt) => {
        by_dimension!(@ $world, $f $args, 1 2 3 4 5 6 7 8)
    };
    (@ $world:expr, $f:ident $args:tt, $($n:literal)*) => {
        match $world.bounds.len() {
            $($n => $f::<$n> $args,)*
            d => Err(DocumentError::InvalidBoxes(format!(
                "has {d} axes; from 1 to {} are supported",
                $crate::solve::MAX_BOX_DIMENSION
            ))
            .into()),
        }
    };
}
pub(crate) use by_dimension;

/// The box world of a document, in `N` dimensions.
pub(crate) fn box_world<const N: usize>(world: &BoxesSpec) -> Result<BoxWorld<N>, SolveError> {
    let corner = |v: &[f64], what: &str| -> Result<[f64; N], SolveError> {
        <[f64; N]>::try_from(v).map_err(|_| {
            DocumentError::InvalidBoxes(format!("{what} has {} coordinates, not {N}", v.len())).into()
        })
    };
    let low: Vec<f64> = world.bounds.iter().map(|b| b[0]).collect();
    let high: Vec<f64> = world.bounds.iter().map(|b| b[1]).collect();
    let obstacles = world
        .obstacles
        .iter()
        .enumerate()
        .map(|(i, [lo, hi])| Ok((corner(lo, &format!("box {i}"))?, corner(hi, &format!("box {i}"))?)))
        .collect::<Result<Vec<_>, SolveError>>()?;
    Ok(BoxWorld::new(corner(&low, "bounds")?, corner(&high, "bounds")?, obstacles)?)
}

/// The start and goal of a box-world problem, in `N` dimensions.
pub(crate) fn box_ends<const N: usize>(
    problem: &ProblemSpec,
) -> Result<(SVector<f64, N>, SVector<f64, N>), SolveError> {
    let state = |which, value: &[f64]| {
        <[f64; N]>::try_from(value)
            .ok()
            .filter(|c| c.iter().all(|x| x.is_finite()))
            .map(SVector::from)
            .ok_or_else(|| DocumentError::NotAState { which, value: value.to_vec(), space: "rn" })
    };
    Ok((state("start", &problem.start)?, state("goal", &problem.goal)?))
}
