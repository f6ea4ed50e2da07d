//! What every roadmap search of a polygon world shares: the PRM's options from the document,
//! its growth, and the search of a joined roadmap into a result.

use std::time::Duration;

use trailmark_graph::{Roadmap, RoadmapQuery};
use trailmark_sample::{Connection, PlanarSpace, PolygonPrm, PrmOptions, PrmSampler};

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{GraphKind, ProblemSpec, SamplerKind};
use crate::solve::result::{Coordinates, GraphStats, SolveResult, Status, Waypoint};

/// The number of samples of a sampled roadmap when the problem gives none.
pub const DEFAULT_SAMPLES: usize = 1000;

/// The PRM options of a problem.
pub(super) fn prm_options(problem: &ProblemSpec) -> Result<PrmOptions, SolveError> {
    let sampler = match problem.sampler.unwrap_or(SamplerKind::Uniform) {
        SamplerKind::Uniform => PrmSampler::Uniform { seed: problem.seed.unwrap_or(0) },
        SamplerKind::Halton => PrmSampler::Halton,
    };
    let connection = match (problem.k, problem.radius) {
        (Some(_), Some(_)) => return Err(DocumentError::KAndRadius.into()),
        (Some(k), None) => Connection::Nearest { k },
        (None, Some(radius)) => Connection::Radius { radius },
        (None, None) => Connection::PrmStar,
    };
    Ok(PrmOptions { sampler, connection, ..PrmOptions::default() })
}

/// `prm` grown by the problem's number of samples.
pub(super) fn grow<S: PlanarSpace>(
    problem: &ProblemSpec,
    mut prm: PolygonPrm<S>,
) -> Result<PolygonPrm<S>, SolveError> {
    prm.grow(problem.samples.unwrap_or(DEFAULT_SAMPLES))?;
    Ok(prm)
}

/// Searches a roadmap query and reports the roadmap's size and timings with the result.
pub(super) fn search_roadmap<R>(
    problem: &ProblemSpec,
    query: &RoadmapQuery<'_, R>,
    built: Duration,
    joined: Duration,
) -> Result<SolveResult, SolveError>
where
    R: Roadmap,
    R::Position: Coordinates,
{
    let waypoint = |node| Waypoint::Point(query.position(node).coordinates());
    let mut result = problem.planner.search(
        query,
        (query.start(), query.goal()),
        query.heuristic_between(),
        waypoint,
        None,
    )?;
    // A sampled roadmap without a path proves nothing: more samples may find one.
    let sampled =
        matches!(problem.graph, Some(GraphKind::Prm | GraphKind::DubinsPrm | GraphKind::ReedsSheppPrm));
    if sampled && result.status == Status::NoPath {
        result.status = Status::Stopped;
    }
    let roadmap = query.roadmap();
    result.stats.graph = Some(GraphStats {
        nodes: roadmap.node_count(),
        edges: roadmap.count_edges(),
        build_time_s: built.as_secs_f64(),
        query_time_s: joined.as_secs_f64(),
    });
    Ok(result)
}
