//! The sampling planners over a box world, in `"space": "rn"`.

use trailmark_sample::{KdNearest, Rn};

use super::SamplingRun;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::SamplingSpec;
use crate::solve::problem::{BoxesSpec, ProblemSpec, SpaceKind};
use crate::solve::result::SolveResult;
use crate::solve::world::boxes::{box_ends, box_world, by_dimension};

/// Solves a sampling-planner problem over a box world, in `"space": "rn"`.
pub(in crate::solve) fn solve_boxes(
    problem: &ProblemSpec,
    world: &BoxesSpec,
    spec: &SamplingSpec,
) -> Result<SolveResult, SolveError> {
    let planner = problem.planner.name();
    // The space first: a car's space brings its turning radius, which is not the fault.
    let space = problem.space.unwrap_or(SpaceKind::Rn);
    if space != SpaceKind::Rn {
        return Err(DocumentError::InvalidBoxes(format!(
            "takes \"space\": \"rn\", not \"{}\"",
            space.name()
        ))
        .into());
    }
    if let Some(&field) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForPlanner { field, planner }.into());
    }
    if spec.smooth.is_some() {
        return Err(DocumentError::NotForSpace { field: "smooth", space: "rn" }.into());
    }
    by_dimension!(world, boxes(problem, world, spec))
}

/// [`solve_boxes`] in `N` dimensions.
fn boxes<const N: usize>(
    problem: &ProblemSpec,
    world: &BoxesSpec,
    spec: &SamplingSpec,
) -> Result<SolveResult, SolveError> {
    let world = box_world::<N>(world)?;
    let (start, goal) = box_ends::<N>(problem)?;
    let space = world.space();
    let run =
        SamplingRun { problem, spec, checker: &world, seed: problem.seed.unwrap_or(0), smoothing_passes: 0 };
    let (result, _) = run.plan(&space, KdNearest::<Rn<N>, N>::new(&space)?, start, goal)?;
    Ok(result)
}
