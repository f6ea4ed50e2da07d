//! The sampling planners over a box world, in `"space": "rn"`.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use trailmark_sample::{KdNearest, Rn, Validity};

use super::SamplingRun;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{BoxesSpec, ProblemSpec, SpaceKind, WorldSpec};
use crate::solve::result::SolveResult;
use crate::solve::settings::SamplingSpec;
use crate::solve::world::boxes::{box_ends, box_world, by_dimension};

/// Solves a sampling-planner problem over a box world, in `"space": "rn"`.
pub(in crate::solve) fn solve_boxes(
    problem: &ProblemSpec,
    world: &BoxesSpec,
    spec: &SamplingSpec,
) -> Result<SolveResult, SolveError> {
    check_settings(problem, spec)?;
    by_dimension!(world, boxes(problem, world, spec))
}

/// The settings a sampling planner in a box world does not take.
fn check_settings(problem: &ProblemSpec, spec: &SamplingSpec) -> Result<(), SolveError> {
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
    Ok(())
}

/// Solves a box-world problem as [`solve`](crate::solve::solve) does, with its states and
/// motions further restricted by the caller's `validity`: a robot whose collision test the
/// caller owns (a function of another language, a simulator), planned in the `N` axes of the
/// world's bounds. Motions are free when both the world and `validity` say so; `validity`
/// decides how finely it checks them (e.g.
/// [`Sampled`](trailmark_space::validity::Sampled) or
/// [`Batched`](trailmark_space::validity::Batched)). Setting `stop` (when given) stops the
/// planner at its next iteration, as its limit would: for a caller whose validity failed, or
/// whose user asked to stop.
///
/// ```
/// use trailmark::solve::{ProblemSpec, Status, solve_boxes_with};
/// use trailmark::space::validity::Sampled;
/// use trailmark::space::SVector;
///
/// let problem: ProblemSpec = serde_json::from_str(r#"{
///     "world": {"boxes": {"bounds": [[0, 10], [0, 10]]}},
///     "start": [1, 1], "goal": [9, 1], "planner": {"name": "rrt_connect"}
/// }"#)?;
/// // A wall the world does not know: x in [4.5, 5.5], y below 8.
/// let wall = |p: &SVector<f64, 2>| !(p[0] >= 4.5 && p[0] <= 5.5 && p[1] <= 8.0);
/// let result = solve_boxes_with::<2, _>(&problem, &Sampled::new(wall, 0.001)?, None)?;
/// assert_eq!(result.status, Status::Solved);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_boxes_with<const N: usize, V: Validity<Rn<N>>>(
    problem: &ProblemSpec,
    validity: &V,
    stop: Option<Arc<AtomicBool>>,
) -> Result<SolveResult, SolveError> {
    let planner = &problem.planner;
    planner.check_limits()?;
    let spec = planner.sampling().ok_or(DocumentError::NotASamplingPlanner { planner: planner.name() })?;
    let WorldSpec::Boxes(world) = &problem.world else {
        return Err(
            DocumentError::InvalidBoxes("is not given: \"world\" must be {\"boxes\": ...}".into()).into()
        );
    };
    check_settings(problem, spec)?;
    let world = box_world::<N>(world)?;
    let (start, goal) = box_ends::<N>(problem)?;
    let space = world.space();
    let checker = Both(&world, validity);
    let seed = problem.seed.unwrap_or(0);
    let run = SamplingRun { planner, spec, checker: &checker, seed, smoothing_passes: 0, stop };
    let (result, _) = run.plan(&space, KdNearest::<Rn<N>, N>::new(&space)?, start, goal)?;
    Ok(result)
}

/// States and motions that two validities both allow; the first is asked first.
struct Both<'a, A, B>(&'a A, &'a B);

impl<const N: usize, A: Validity<Rn<N>>, B: Validity<Rn<N>>> Validity<Rn<N>> for Both<'_, A, B> {
    fn state_is_valid(&self, space: &Rn<N>, state: &<Rn<N> as trailmark_sample::StateSpace>::State) -> bool {
        self.0.state_is_valid(space, state) && self.1.state_is_valid(space, state)
    }

    fn motion_is_valid(
        &self,
        space: &Rn<N>,
        from: &<Rn<N> as trailmark_sample::StateSpace>::State,
        to: &<Rn<N> as trailmark_sample::StateSpace>::State,
    ) -> bool {
        self.0.motion_is_valid(space, from, to) && self.1.motion_is_valid(space, from, to)
    }
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
    let seed = problem.seed.unwrap_or(0);
    let planner = &problem.planner;
    let run = SamplingRun { planner, spec, checker: &world, seed, smoothing_passes: 0, stop: None };
    let (result, _) = run.plan(&space, KdNearest::<Rn<N>, N>::new(&space)?, start, goal)?;
    Ok(result)
}
