//! `"graph": "prm"` over a box world: a PRM roadmap of `trailmark-sample` in Rⁿ (the boxes'
//! exact slab test for every motion), grown to the problem's number of samples, the start and
//! the goal joined to it as milestones, then searched by the problem's planner.

use std::time::Instant;

use trailmark_core::termination::Termination;
use trailmark_sample::paths::PathFault;
use trailmark_sample::prm::Connection;
use trailmark_sample::{
    BoxWorld, Halton, KdNearest, PlanError, Prm, Rn, StateSampler, StateSpace, Uniform, paths,
};

use trailmark_sample::{MAX_ROADMAP_NODES, PrmError};

use trailmark_core::grid::GridHeuristic;

use super::roadmap::DEFAULT_SAMPLES;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{BoxesSpec, GraphKind, ProblemSpec, SamplerKind};
use crate::solve::result::{GraphStats, SolveResult, Status, Waypoint, same_length, states_of};
use crate::solve::world::boxes::{box_ends, box_world, by_dimension};

/// The draws a roadmap may make per sample asked for, as the polygon roadmap's default.
const ATTEMPTS_PER_SAMPLE: u64 = 1_000;

/// Solves a box-world problem on a PRM roadmap.
pub(in crate::solve) fn solve_box_roadmap(
    problem: &ProblemSpec,
    world: &BoxesSpec,
) -> Result<SolveResult, SolveError> {
    let kind = problem.graph.unwrap_or(GraphKind::Prm);
    if kind != GraphKind::Prm {
        return Err(DocumentError::InvalidBoxes(format!(
            "takes \"graph\": \"prm\", not \"{}\"",
            kind.name()
        ))
        .into());
    }
    if problem.turning_radius.is_some() {
        return Err(DocumentError::NotForGraph { field: "turning_radius", graph: kind.name() }.into());
    }
    if problem.space.is_some() {
        return Err(DocumentError::NotForPlanner { field: "space", planner: problem.planner.name() }.into());
    }
    let (asked, _) = problem.planner.heuristic();
    if let Some(heuristic) = asked.filter(|&h| h != GridHeuristic::Euclidean) {
        return Err(DocumentError::NotEuclidean { heuristic }.into());
    }
    by_dimension!(world, roadmap(problem, world))
}

/// [`solve_box_roadmap`] in `N` dimensions.
fn roadmap<const N: usize>(problem: &ProblemSpec, world: &BoxesSpec) -> Result<SolveResult, SolveError> {
    let world = box_world::<N>(world)?;
    let (start, goal) = box_ends::<N>(problem)?;
    let connection = match (problem.k, problem.radius) {
        (Some(_), Some(_)) => return Err(DocumentError::KAndRadius.into()),
        (Some(k), None) => Connection::Nearest { k },
        (None, Some(radius)) => Connection::Radius { radius },
        (None, None) => Connection::PrmStar,
    };
    let space = world.space();
    let prm = Prm::star(KdNearest::<Rn<N>, N>::new(&space)?)
        .with_connection(connection)
        .with_seed(problem.seed.unwrap_or(0));
    match problem.sampler.unwrap_or(SamplerKind::Uniform) {
        SamplerKind::Uniform => query(problem, &world, prm.with_sampler(Uniform), (start, goal)),
        SamplerKind::Halton => query(problem, &world, prm.with_sampler(Halton::new()), (start, goal)),
    }
}

/// Grows `prm`, joins the ends, searches and re-checks the path.
fn query<const N: usize, Q: StateSampler<Rn<N>>>(
    problem: &ProblemSpec,
    world: &BoxWorld<N>,
    mut prm: Prm<Rn<N>, KdNearest<Rn<N>, N>, Q>,
    (start, goal): (<Rn<N> as StateSpace>::State, <Rn<N> as StateSpace>::State),
) -> Result<SolveResult, SolveError> {
    let space = world.space();
    let samples = problem.samples.unwrap_or(DEFAULT_SAMPLES);
    if samples > MAX_ROADMAP_NODES {
        return Err(SolveError::Prm(PrmError::TooManyNodes));
    }
    let clock = Instant::now();
    let draws = Termination::iterations(ATTEMPTS_PER_SAMPLE.saturating_mul(samples as u64));
    let growth = prm.grow(&space, world, samples, &draws)?;
    if growth.stop.is_some() {
        return Err(SolveError::SamplingExhausted { requested: samples, added: prm.node_count() });
    }
    let built = clock.elapsed();
    let (nodes, edges) = (prm.node_count(), prm.edge_count());
    let s = prm
        .insert(&space, world, start)
        .map_err(|reason| SolveError::Plan(PlanError::InvalidStart { index: 0, reason }))?;
    let g =
        prm.insert(&space, world, goal).map_err(|reason| SolveError::Plan(PlanError::InvalidGoal(reason)))?;
    let joined = clock.elapsed() - built;
    let heuristic = |a: u32, b: u32| space.distance(prm.state(a), prm.state(b));
    let waypoint = |n: u32| Waypoint::Point(space.coordinates(prm.state(n)));
    let mut result = problem.planner.search(&prm, (s, g), heuristic, waypoint, None)?;
    // A sampled roadmap without a path proves nothing: more samples may find one.
    if result.status == Status::NoPath {
        result.status = Status::Stopped;
    }
    if let Some(cost) = result.cost {
        let path = states_of(&space, &result);
        let rejected =
            |segment, reason| SolveError::PathRejected { graph: GraphKind::Prm.name(), segment, reason };
        paths::check(&space, world, &path).map_err(|fault| match fault {
            PathFault::State { index, .. } => rejected(index, "a state is invalid or out of bounds"),
            PathFault::Motion { index } => rejected(index, "the robot collides"),
            _ => rejected(0, "the path is empty"),
        })?;
        if !same_length(cost, paths::length(&space, &path)) {
            return Err(rejected(0, "the cost is not the path's length"));
        }
    }
    result.stats.graph = Some(GraphStats {
        nodes,
        edges,
        build_time_s: built.as_secs_f64(),
        query_time_s: joined.as_secs_f64(),
    });
    Ok(result)
}
