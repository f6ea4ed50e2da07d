//! The sampling planners in a space of car poses over a polygon world: `"space": "dubins"` (a
//! car that drives forward) or `"reeds_shepp"` (one that also reverses).

use trailmark_core::geometry::Point;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_sample::space::{Car, CarCurves};
use trailmark_sample::{KdNearest, StateSpace};

use super::{SamplingRun, sketch};
use crate::solve::curves::car_curve;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::ProblemSpec;
use crate::solve::result::SolveResult;

/// The sampling planners in a space of car poses (`space` its name in documents), joined by
/// the shortest curves of the family `C` of the problem's turning radius.
pub(super) fn solve_in_car_space<C: CarCurves>(
    run: &SamplingRun<'_, CollisionChecker>,
    problem: &ProblemSpec,
    world: &PolygonWorld,
    space_name: &'static str,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if run.spec.smooth.is_some() {
        return Err(DocumentError::NotForSpace { field: "smooth", space: space_name }.into());
    }
    let radius = problem.turning_radius.ok_or(DocumentError::NoTurningRadius)?;
    let space = Car::<C>::new(world.bounds(), radius)?;
    let state = |which, value: &[f64]| {
        space.state_from_coordinates(value).ok_or_else(|| DocumentError::NotAState {
            which,
            value: value.to_vec(),
            space: space_name,
        })
    };
    let (start, goal) = (state("start", &problem.start)?, state("goal", &problem.goal)?);
    let (result, path) = run.plan(&space, KdNearest::<Car<C>, 2>::new(&space)?, start, goal)?;
    if let Some(picture) = picture {
        let curve = car_curve(&space, &path);
        let ends = (Point::from(start.translation.vector), Point::from(goal.translation.vector));
        *picture = sketch(world, run.planner.name(), &curve, ends.0, ends.1).poses(path).to_svg();
    }
    Ok(result)
}
