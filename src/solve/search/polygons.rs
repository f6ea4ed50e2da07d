//! Polygon worlds searched on a roadmap: the visibility graph, the trapezoidal cells, a
//! probabilistic roadmap of points or of Dubins poses. Every path found is re-checked exactly.

use std::time::Instant;

use trailmark_core::geometry::Point;
use trailmark_core::grid::GridHeuristic;
use trailmark_core::svg::WorldSvg;
use trailmark_core::world::PolygonWorld;
use trailmark_graph::VisibilityError;
use trailmark_graph::trapezoid::TrapezoidError;
use trailmark_graph::{LazyVisibilityGraph, Roadmap, Trapezoids};
use trailmark_sample::PolygonPrm;
use trailmark_sample::space::{DubinsCurves, ReedsSheppCurves};

use super::roadmap::{grow, prm_options, search_roadmap};
use super::visibility::search_visibility;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{GraphKind, ProblemSpec};
use crate::solve::result::{SolveResult, Waypoint, same_length};

/// Builds the roadmap a polygon-world problem names, joins its start and goal, and searches it;
/// draws the world, the roadmap and the path into `picture` when one is given.
pub(in crate::solve) fn solve_polygons(
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
        GraphKind::DubinsPrm => {
            return super::car_roadmap::solve_car_roadmap::<DubinsCurves>(problem, world, kind, picture);
        }
        GraphKind::ReedsSheppPrm => {
            return super::car_roadmap::solve_car_roadmap::<ReedsSheppCurves>(problem, world, kind, picture);
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
            let graph = LazyVisibilityGraph::new(world.free_space());
            let built = clock.elapsed();
            let blocked = |e: VisibilityError| match e {
                VisibilityError::StartBlocked { .. } => refused("start", start, e.into()),
                VisibilityError::GoalBlocked { .. } => refused("goal", goal, e.into()),
            };
            let (result, edges) = search_visibility(problem, &graph, (start, goal), built, blocked)?;
            let svg = WorldSvg::new(world).free_space(graph.space()).edges(edges);
            (result, svg.title("Visibility graph (the tangent edges the search swept) and the shortest path"))
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

/// The point of a waypoint (the position of a pose).
fn waypoint_point(waypoint: &Waypoint) -> Option<Point> {
    match waypoint {
        Waypoint::Point(c) if c.len() >= 2 => Some(Point::new(c[0], c[1])),
        _ => None,
    }
}
