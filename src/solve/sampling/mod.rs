//! The sampling planners of [`solve`](super::solve): `rrt`, `rrt_connect` and `rrt_star` over
//! a polygon world (here), a box world (`boxes.rs`) or in a car's space (`car.rs`); over a polygon world in `"space": "r2"` (points), `"dubins"` (poses of a car that drives forward)
//! or `"reeds_shepp"` (poses of a car that also reverses).

pub(super) mod boxes;
mod car;
pub(super) mod robot;

use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use trailmark_core::geometry::Point;
use trailmark_core::smooth::smooth;
use trailmark_core::svg::WorldSvg;
use trailmark_core::termination::Termination;
use trailmark_core::world::PolygonWorld;
use trailmark_sample::sampler::{DEFAULT_ATTEMPTS, DEFAULT_SHARE, Draw};
use trailmark_sample::space::{DubinsCurves, ReedsSheppCurves};
use trailmark_sample::{
    Bridge, Gaussian, KdNearest, NearestNeighbors, Plan, Problem as PlanningProblem, R2, RrtOptions,
    Solution, StateSampler, StateSpace, shortcut, simplify,
};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::PlannerSpec;
use crate::solve::problem::{ProblemSpec, SpaceKind};
use crate::solve::result::{
    Coordinates, ImprovementRecord, ResultStats, SamplingStats, SmoothedRecord, SolveResult, Status, Waypoint,
};
use crate::solve::settings::{SamplerSpec, SamplingSpec};
use crate::solve::stop::stoppable;

/// The iterations of a sampling planner given neither `max_iterations` nor `time_limit_s`.
pub const DEFAULT_ITERATIONS: u64 = 10_000;

/// Random shortcut attempts when `simplify` is asked for (after the greedy pass).
pub const SHORTCUT_ATTEMPTS: usize = 100;

/// Solves a sampling-planner problem over `world`.
pub(in crate::solve) fn solve_sampling(
    problem: &ProblemSpec,
    world: &PolygonWorld,
    spec: &SamplingSpec,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let planner = problem.planner.name();
    // The roadmap's fields, except the turning radius, which a Dubins space takes too.
    if let Some(&field) = problem.roadmap_fields().iter().find(|&&f| f != "turning_radius") {
        return Err(DocumentError::NotForPlanner { field, planner }.into());
    }
    let space_kind = problem.space.unwrap_or(SpaceKind::R2);
    let checker = world.checker();
    let seed = problem.seed.unwrap_or(0);
    let run = SamplingRun {
        planner: &problem.planner,
        spec,
        checker: &checker,
        seed,
        smoothing_passes: 0,
        stop: None,
    };
    match space_kind {
        SpaceKind::Rn => Err(DocumentError::RnNeedsBoxes.into()),
        SpaceKind::R2 => {
            if problem.turning_radius.is_some() {
                return Err(DocumentError::NotForSpace { field: "turning_radius", space: "r2" }.into());
            }
            let space = R2::new(world.bounds());
            let state = |which, value: &[f64]| {
                space.state_from_coordinates(value).ok_or_else(|| DocumentError::NotAState {
                    which,
                    value: value.to_vec(),
                    space: "r2",
                })
            };
            let (start, goal) = (state("start", &problem.start)?, state("goal", &problem.goal)?);
            let (mut result, path) = run.plan(&space, KdNearest::<R2, 2>::new(&space)?, start, goal)?;
            if let (Some(method), Some(stats)) = (spec.smooth, result.stats.sampling.as_mut()) {
                let smoothed = smooth(&checker, &path, method)?;
                stats.smoothed = Some(SmoothedRecord {
                    method,
                    length: smoothed.length(),
                    kept: smoothed.kept,
                    pieces: smoothed
                        .pieces
                        .iter()
                        .map(|b| b.control_points().iter().map(|p| [p.x, p.y]).collect())
                        .collect(),
                });
                if let Some(picture) = picture {
                    // At most about 100,000 points for a picture.
                    let step = world_step(world).max(smoothed.length() / 1e5);
                    let curve = smoothed.sample(step).unwrap_or_default();
                    let legs = path.windows(2).map(|m| (m[0], m[1]));
                    *picture = sketch(world, planner, &curve, start, goal).edges(legs).to_svg();
                }
            } else if let Some(picture) = picture {
                *picture = sketch(world, planner, &path, start, goal).to_svg();
            }
            Ok(result)
        }
        SpaceKind::Dubins => {
            car::solve_in_car_space::<DubinsCurves>(&run, problem, world, space_kind.name(), picture)
        }
        SpaceKind::ReedsShepp => {
            car::solve_in_car_space::<ReedsSheppCurves>(&run, problem, world, space_kind.name(), picture)
        }
    }
}

/// A sampling planner's run: the planner, its settings, the world's validity and the seed.
struct SamplingRun<'a, V> {
    planner: &'a PlannerSpec,
    spec: &'a SamplingSpec,
    checker: &'a V,
    seed: u64,
    /// Corner-cutting passes after the shortcuts when `simplify` is asked for (0: shortcuts
    /// only).
    smoothing_passes: usize,
    /// Set by the caller to stop the planner at its next iteration, as at its limit.
    stop: Option<Arc<AtomicBool>>,
}

impl<V> SamplingRun<'_, V> {
    /// Plans from `start` to `goal` in `space`, simplifies when asked; the result and the path.
    fn plan<S, N>(
        &self,
        space: &S,
        nearest: N,
        start: S::State,
        goal: S::State,
    ) -> Result<(SolveResult, Vec<S::State>), SolveError>
    where
        S: StateSpace,
        S::State: Coordinates,
        N: NearestNeighbors<S> + Clone,
        V: trailmark_sample::Validity<S>,
    {
        let spec = self.spec;
        // A limit too large for a Duration has been refused by solve_inner.
        let time_limit = spec.time_limit_s.and_then(|t| Duration::try_from_secs_f64(t).ok());
        let termination = Termination {
            max_iterations: spec.max_iterations.or(time_limit.is_none().then_some(DEFAULT_ITERATIONS)),
            time_limit,
            ..Termination::default()
        };
        let termination = stoppable(termination, self.stop.as_ref());
        let defaults = RrtOptions::default();
        let options =
            RrtOptions { range: spec.range, goal_bias: spec.goal_bias.unwrap_or(defaults.goal_bias) };
        let problem = PlanningProblem::new(space, self.checker, start, goal);
        let limits = (&options, &termination);
        let sampler = match spec.sampler.unwrap_or_default() {
            SamplerSpec::Uniform {} => Chosen::Uniform(trailmark_sample::Uniform),
            SamplerSpec::Bridge { std_dev, share, attempts } => {
                let bridge = Bridge::new(std_dev)?.with_share(share.unwrap_or(DEFAULT_SHARE))?;
                Chosen::Bridge(bridge.with_attempts(attempts.unwrap_or(DEFAULT_ATTEMPTS))?)
            }
            SamplerSpec::Gaussian { std_dev, share, attempts } => {
                let gaussian = Gaussian::new(std_dev)?.with_share(share.unwrap_or(DEFAULT_SHARE))?;
                Chosen::Gaussian(gaussian.with_attempts(attempts.unwrap_or(DEFAULT_ATTEMPTS))?)
            }
        };
        let plan = self.run_planner(&problem, nearest, sampler, limits)?;
        let planned = plan.solution.any_path().map(<[S::State]>::to_vec).unwrap_or_default();
        let clock = Instant::now();
        let path = if spec.simplify != Some(true) || planned.len() < 3 {
            planned
        } else if self.smoothing_passes == 0 {
            shortcut(space, self.checker, &planned, SHORTCUT_ATTEMPTS, self.seed)
        } else {
            let (attempts, passes) = (SHORTCUT_ATTEMPTS, self.smoothing_passes);
            simplify(space, self.checker, &planned, attempts, passes, self.seed)
        };
        let simplify_time_s = clock.elapsed().as_secs_f64();
        // A fold from +0: an empty float sum is -0.0.
        let cost = plan
            .solution
            .any_path()
            .map(|_| path.windows(2).fold(0.0, |total, m| total + space.distance(&m[0], &m[1])));
        // Sampling planners never prove that no path exists: they stop at their limit. A plan
        // with a path short of the goal is approximate; one with none at all (the planners of
        // trailmark-sample always return at least the start) is stopped, never "no path".
        let (status, goal_distance, planned_cost) = match plan.solution {
            Solution::None => (Status::Stopped, f64::INFINITY, None),
            Solution::Approximate { cost, goal_distance, .. } => {
                (Status::Approximate, goal_distance, Some(cost))
            }
            Solution::Exact { cost, .. } => (Status::Solved, 0.0, Some(cost)),
        };
        let s = plan.stats;
        let stats = SamplingStats {
            iterations: s.iterations,
            tree_sizes: s.tree_sizes,
            collision_checks: s.collision_checks,
            time_to_solution_s: s.time_to_solution.map(|t| t.as_secs_f64()),
            improvements: plan
                .history
                .iter()
                .map(|b| ImprovementRecord {
                    iteration: b.iteration,
                    time_s: b.time.as_secs_f64(),
                    cost: b.cost,
                })
                .collect(),
            goal_distance,
            planned_cost,
            simplify_time_s,
            smoothed: None,
        };
        let result = SolveResult {
            status,
            cost,
            path: path.iter().map(|state| Waypoint::Point(state.coordinates())).collect(),
            stats: ResultStats {
                time_s: s.elapsed.as_secs_f64(),
                sampling: Some(stats),
                ..ResultStats::default()
            },
        };
        Ok((result, path))
    }

    /// The document's planner on `problem`, drawing from `sampler`.
    fn run_planner<S, N, Q>(
        &self,
        problem: &PlanningProblem<'_, S, V>,
        nearest: N,
        sampler: Q,
        (options, termination): (&RrtOptions, &Termination),
    ) -> Result<Plan<S::State>, SolveError>
    where
        S: StateSpace,
        N: NearestNeighbors<S> + Clone,
        Q: StateSampler<S>,
        V: trailmark_sample::Validity<S>,
    {
        let planner = self.planner.sampling_planner(nearest, sampler, *options, self.seed);
        let mut planner =
            planner.ok_or(DocumentError::NotASamplingPlanner { planner: self.planner.name() })?;
        Ok(planner.solve(problem, termination)?)
    }
}

/// The document's sampler: one type, so that each planner is compiled once per space rather
/// than once per sampler.
enum Chosen {
    Uniform(trailmark_sample::Uniform),
    Bridge(Bridge),
    Gaussian(Gaussian),
}

impl<S: StateSpace> StateSampler<S> for Chosen {
    fn sample<V: trailmark_sample::Validity<S>>(
        &self,
        space: &S,
        validity: &V,
        draw: &mut Draw<'_>,
    ) -> Option<S::State> {
        match self {
            Chosen::Uniform(uniform) => uniform.sample(space, validity, draw),
            Chosen::Bridge(bridge) => bridge.sample(space, validity, draw),
            Chosen::Gaussian(gaussian) => gaussian.sample(space, validity, draw),
        }
    }
}

/// A sampling step for drawing curves in `world`: 1/500 of its larger side.
fn world_step(world: &PolygonWorld) -> f64 {
    let size = world.bounds().max() - world.bounds().min();
    size.x.max(size.y) / 500.0
}

/// The world with its free space, the drawn path and its ends, titled by the planner.
fn sketch<'a>(
    world: &'a PolygonWorld,
    planner: &str,
    path: &[Point],
    start: Point,
    goal: Point,
) -> WorldSvg<'a> {
    WorldSvg::new(world)
        .free_space(&world.free_space())
        .path(path)
        .start(start)
        .goal(goal)
        .title(format!("{planner}: the path from start to goal"))
}
