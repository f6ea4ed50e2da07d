//! Polygon worlds searched on a roadmap of car poses (`"graph": "dubins_prm"` or
//! `"reeds_shepp_prm"`): edges along the car's shortest curves, every path re-checked exactly.

use std::time::Instant;

use trailmark_core::geometry::{Point, Pose};
use trailmark_core::svg::WorldSvg;
use trailmark_core::world::{CollisionChecker, PolygonWorld};
use trailmark_sample::PolygonPrm;
use trailmark_sample::StateSpace;
use trailmark_sample::space::{Car, CarCurves};

use super::roadmap::{grow, prm_options, search_roadmap};
use crate::solve::curves::car_curve;
use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{GraphKind, ProblemSpec};
use crate::solve::result::{SolveResult, same_length, states_of};

/// [`solve_polygons`] on a roadmap of car poses (`kind`): edges along the shortest curves of
/// the family `C` (Dubins: directed; Reeds-Shepp: the same both ways).
pub(super) fn solve_car_roadmap<C: CarCurves>(
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
