//! Polygon worlds searched on a roadmap: the visibility graph, the trapezoidal cells, a
//! probabilistic roadmap of points or of Dubins poses. Every path found is re-checked exactly.

use std::time::{Duration, Instant};

use trailmark_core::geometry::{Point, Pose};
use trailmark_core::grid::GridHeuristic;
use trailmark_core::svg::WorldSvg;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_graph::prm::{Connection, PlanarSpace, PolygonPrm, PrmOptions, PrmSampler};
use trailmark_graph::trapezoid::TrapezoidError;
use trailmark_graph::visibility::{Edges, VisibilityError};
use trailmark_graph::{Roadmap, RoadmapQuery, Trapezoids, VisibilityGraph};
use trailmark_sample::StateSpace;
use trailmark_sample::space::{Car, CarCurves, DubinsCurves, ReedsSheppCurves};

use super::error::{DocumentError, SolveError};
use super::problem::{GraphKind, ProblemSpec, SamplerKind};
use super::result::{Coordinates, GraphStats, SolveResult, Status, Waypoint, same_length, states_of};

/// Builds the roadmap a polygon-world problem names, joins its start and goal, and searches it;
/// draws the world, the roadmap and the path into `picture` when one is given.
pub(super) fn solve_polygons(
    problem: &ProblemSpec,
    world: &PolygonWorld,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let kind = problem.graph.unwrap_or(GraphKind::Visibility);
    let sampled = matches!(kind, GraphKind::Prm | GraphKind::DubinsPrm | GraphKind::ReedsSheppPrm);
    for field in problem.roadmap_fields() {
        let applies = match field {
            "graph" => true,
            "turning_radius" => matches!(kind, GraphKind::DubinsPrm | GraphKind::ReedsSheppPrm),
            _ => sampled,
        };
        if !applies {
            return Err(DocumentError::NotForGraph { field, graph: kind.name() }.into());
        }
    }
    let (asked, _) = problem.planner.heuristic();
    if let Some(heuristic) = asked.filter(|&h| h != GridHeuristic::Euclidean) {
        return Err(DocumentError::NotEuclidean { heuristic }.into());
    }
    match kind {
        GraphKind::DubinsPrm => return solve_car_roadmap::<DubinsCurves>(problem, world, kind, picture),
        GraphKind::ReedsSheppPrm => {
            return solve_car_roadmap::<ReedsSheppCurves>(problem, world, kind, picture);
        }
        _ => {}
    }
    let point = |which, value: &[f64]| match *value {
        [x, y] if x.is_finite() && y.is_finite() => Ok(Point::new(x, y)),
        _ => Err(DocumentError::NotAPoint { which, value: value.to_vec(), graph: kind.name() }),
    };
    let (start, goal) = (point("start", &problem.start)?, point("goal", &problem.goal)?);
    let checker = world.checker();
    // The free space of the exact roadmaps is conservative by its resolution: a free end
    // refused there is below that resolution, not blocked.
    let refused = |which, at: Point, blocked: SolveError| {
        if checker.point_is_free(at) {
            let (x, y, resolution) = (at.x, at.y, world.resolution());
            SolveError::BelowResolution { which, x, y, graph: kind.name(), resolution }
        } else {
            blocked
        }
    };
    let clock = Instant::now();
    let (result, svg) = match kind {
        GraphKind::Visibility => {
            let graph = VisibilityGraph::with_edges(world.free_space(), Edges::Tangent);
            let built = clock.elapsed();
            let query = graph.query(start, goal).map_err(|e| match e {
                VisibilityError::StartBlocked { .. } => refused("start", start, e.into()),
                VisibilityError::GoalBlocked { .. } => refused("goal", goal, e.into()),
            })?;
            let result = search_roadmap(problem, &query, built, clock.elapsed().saturating_sub(built))?;
            let svg = WorldSvg::new(world).free_space(graph.space()).edges(graph.edge_ends());
            (result, svg.title("Visibility graph (tangent edges) and the shortest path"))
        }
        GraphKind::Trapezoid => {
            let space = world.free_space();
            let graph = Trapezoids::new(&space);
            let built = clock.elapsed();
            let query = graph.query(start, goal).map_err(|e| match e {
                TrapezoidError::StartBlocked { .. } => refused("start", start, e.into()),
                TrapezoidError::GoalBlocked { .. } => refused("goal", goal, e.into()),
            })?;
            let result = search_roadmap(problem, &query, built, clock.elapsed().saturating_sub(built))?;
            let cells = (0..graph.cell_count()).map(|c| graph.cell(c).corners().to_vec());
            let svg = WorldSvg::new(world).free_space(&space).cells(cells).edges(graph.edge_ends());
            (result, svg.title("Trapezoidal cells, their centroids and portal midpoints, and a path"))
        }
        _ => {
            let prm = grow(problem, PolygonPrm::new(world.clone(), prm_options(problem)?)?)?;
            let built = clock.elapsed();
            let result = search_roadmap(
                problem,
                &prm.query(start, goal)?,
                built,
                clock.elapsed().saturating_sub(built),
            )?;
            let nodes = (0u32..).take(prm.node_count()).map(|u| prm.position(u));
            let space = world.free_space();
            let svg = WorldSvg::new(world).free_space(&space).edges(prm.edge_ends()).nodes(nodes);
            let title = format!("PRM: {} samples, {} edges, and a path", prm.node_count(), prm.edge_count());
            (result, svg.title(title))
        }
    };
    let path: Vec<Point> = result.path.iter().filter_map(waypoint_point).collect();
    if let Some(cost) = result.cost {
        let rejected = |segment, reason| SolveError::PathRejected { graph: kind.name(), segment, reason };
        if let Some(segment) = checker.first_blocked_segment(&path) {
            return Err(rejected(segment, "the robot collides"));
        }
        let length: f64 = path.windows(2).map(|p| (p[1] - p[0]).norm()).sum();
        if !same_length(cost, length) {
            return Err(rejected(0, "the cost is not the path's length"));
        }
    }
    if let Some(picture) = picture {
        *picture = svg.path(&path).start(start).goal(goal).to_svg();
    }
    Ok(result)
}

/// [`solve_polygons`] on a roadmap of car poses (`kind`): edges along the shortest curves of
/// the family `C` (Dubins: directed; Reeds-Shepp: the same both ways).
fn solve_car_roadmap<C: CarCurves>(
    problem: &ProblemSpec,
    world: &PolygonWorld,
    kind: GraphKind,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    let radius = problem.turning_radius.ok_or(DocumentError::NoTurningRadius)?;
    let space = Car::<C>::new(world.bounds(), radius)?;
    let pose = |which, value: &[f64]| {
        space.state_from_coordinates(value).ok_or_else(|| DocumentError::NotAPose {
            which,
            value: value.to_vec(),
            planner: "dubins_prm",
        })
    };
    let (start, goal) = (pose("start", &problem.start)?, pose("goal", &problem.goal)?);
    let clock = Instant::now();
    let prm = grow(problem, PolygonPrm::with_space(world.clone(), space, prm_options(problem)?)?)?;
    let built = clock.elapsed();
    let result =
        search_roadmap(problem, &prm.query(start, goal)?, built, clock.elapsed().saturating_sub(built))?;
    let poses: Vec<Pose> = states_of(&space, &result);
    if let Some(cost) = result.cost {
        check_car_path(&world.checker(), &space, kind, &poses, cost)?;
    }
    if let Some(picture) = picture {
        let curve = car_curve(&space, &poses);
        let title = format!(
            "{} roadmap: {} poses, turning radius {radius}, and a path",
            kind.name(),
            prm.node_count()
        );
        *picture = WorldSvg::new(world)
            .free_space(&world.free_space())
            .poses((0u32..).take(prm.node_count()).map(|u| prm.position(u)))
            .path(&curve)
            .start(Point::from(start.translation.vector))
            .goal(Point::from(goal.translation.vector))
            .title(title)
            .to_svg();
    }
    Ok(result)
}

/// The exact re-check of a car roadmap's path: each shortest curve between consecutive poses
/// collision-free, and their lengths adding up to `cost`.
fn check_car_path<C: CarCurves>(
    checker: &CollisionChecker,
    space: &Car<C>,
    kind: GraphKind,
    poses: &[Pose],
    cost: f64,
) -> Result<(), SolveError> {
    let rejected = |segment, reason| SolveError::PathRejected { graph: kind.name(), segment, reason };
    if let [pose] = poses
        && !checker.point_is_free(Point::from(pose.translation.vector))
    {
        return Err(rejected(0, "the robot collides"));
    }
    let mut length = 0.0;
    for (segment, pair) in poses.windows(2).enumerate() {
        let piece = C::path(&pair[0], &pair[1], space.turning_radius())
            .ok_or_else(|| rejected(segment, "no curve joins the poses"))?;
        if !C::is_free(checker, &piece) {
            return Err(rejected(segment, "the robot collides"));
        }
        length += C::path_length(&piece);
    }
    if !same_length(cost, length) {
        return Err(rejected(0, "the cost is not the path's length"));
    }
    Ok(())
}

/// The positions along the shortest curves of `space` joining `poses`, every turning radius / 8
/// (at most 10,000 points a curve), for a picture.
pub(super) fn car_curve<C: CarCurves>(space: &Car<C>, poses: &[Pose]) -> Vec<Point> {
    let radius = space.turning_radius();
    let mut curve = Vec::new();
    for pair in poses.windows(2) {
        let Some(piece) = C::path(&pair[0], &pair[1], radius) else { continue };
        let step = (radius / 8.0).max(C::path_length(&piece) / 1e4);
        let samples = C::sample(&piece, step).unwrap_or_default();
        curve.extend(samples.iter().map(|p| Point::from(p.translation.vector)));
    }
    curve
}

/// The point of a waypoint (the position of a pose).
fn waypoint_point(waypoint: &Waypoint) -> Option<Point> {
    match waypoint {
        Waypoint::Point(c) if c.len() >= 2 => Some(Point::new(c[0], c[1])),
        _ => None,
    }
}

/// The PRM options of a problem.
fn prm_options(problem: &ProblemSpec) -> Result<PrmOptions, SolveError> {
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
fn grow<S: PlanarSpace>(problem: &ProblemSpec, mut prm: PolygonPrm<S>) -> Result<PolygonPrm<S>, SolveError> {
    prm.grow(problem.samples.unwrap_or(DEFAULT_SAMPLES))?;
    Ok(prm)
}

/// The number of samples of a sampled roadmap when the problem gives none.
pub const DEFAULT_SAMPLES: usize = 1000;

/// Searches a roadmap query and reports the roadmap's size and timings with the result.
fn search_roadmap<R>(
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
