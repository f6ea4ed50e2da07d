//! Problem documents for car-like robots: Hybrid A* on a ROS-map world, poses `[x, y, heading]`
//! in metres and radians, the result a pose at every stretch's end (and the cusps in the
//! statistics), the picture the footprint along the path.

use std::path::Path;

use trailmark_car::{CarError, CarMap, CarPath, HybridAStar};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::reeds_shepp::Gear;
use trailmark_core::world::Polygon;
use trailmark_map::{Costmap, CostmapSvg, TravelCost};

use super::error::{DocumentError, SolveError};
use super::planner::HybridSpec;
use super::problem::{ProblemSpec, RosMapSpec};
use super::result::{CarRecord, ResultStats, SolveResult, Status, Waypoint};
use super::ros_map::{DEFAULT_COST_FACTOR, DEFAULT_ROBOT_RADIUS, ros_costmap};

/// The footprint drawn every this many metres along the path in pictures.
const OUTLINE_EVERY: f64 = 0.5;

/// The pose `which` (`[x, y, heading]`), or why it is not one.
fn pose(which: &'static str, value: &[f64]) -> Result<Pose, DocumentError> {
    match *value {
        [x, y, heading] if x.is_finite() && y.is_finite() && heading.is_finite() => {
            Ok(Pose::new(Vector::new(x, y), heading))
        }
        _ => Err(DocumentError::NotAPoint { which, value: value.to_vec(), graph: "hybrid_astar" }),
    }
}

/// The robot's footprint: the planner's polygon, else the world's polygon, else a disc of the
/// world's radius.
fn footprint(spec: &HybridSpec, world: &RosMapSpec) -> Result<Footprint, SolveError> {
    if spec.footprint.is_some() && world.robot_radius.is_some() {
        return Err(DocumentError::RadiusAndFootprint.into());
    }
    match spec.footprint.as_ref().or(world.footprint.as_ref()) {
        Some(points) => {
            Ok(Footprint::Polygon(Polygon::try_from(points.clone()).map_err(DocumentError::Footprint)?))
        }
        None => Ok(Footprint::Radius(world.robot_radius.unwrap_or(DEFAULT_ROBOT_RADIUS))),
    }
}

/// Solves a Hybrid A* problem on a ROS-map world.
pub(super) fn solve_car(
    problem: &ProblemSpec,
    world: &RosMapSpec,
    spec: &HybridSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForGrids { field: name }.into());
    }
    let (start, goal) = (pose("start", &problem.start)?, pose("goal", &problem.goal)?);
    let car = footprint(spec, world)?;
    // The costmap is inflated around the planner's footprint when it gives one.
    let world = RosMapSpec {
        footprint: spec.footprint.clone().or(world.footprint.clone()),
        robot_radius: if spec.footprint.is_some() { None } else { world.robot_radius },
        ..world.clone()
    };
    let costmap = ros_costmap(&world, base_dir)?;
    let travel = TravelCost {
        neutral: 1.0,
        factor: world.cost_factor.unwrap_or(DEFAULT_COST_FACTOR),
        ..TravelCost::default()
    };
    let map = CarMap::from_costmap(&costmap, &travel).map_err(SolveError::Car)?;
    let planner = HybridAStar::new(&map, &car, spec.settings()).map_err(SolveError::Car)?;
    let (path, status, stats) = match planner.plan(&start, &goal, &spec.termination()) {
        Ok(plan) => (Some(plan.path), Status::Solved, plan.stats),
        Err(CarError::NoPath { stop: None, stats }) => (None, Status::NoPath, stats),
        Err(CarError::NoPath { stop: Some(_), stats }) => (None, Status::Stopped, stats),
        Err(e) => return Err(SolveError::Car(e)),
    };
    if let Some(picture) = picture {
        *picture = draw(&costmap, &car, path.as_ref(), &start, &goal)?;
    }
    let as_waypoint = |p: &Pose| Waypoint::Point(vec![p.translation.x, p.translation.y, p.rotation.angle()]);
    let (waypoints, record) = match &path {
        Some(path) => {
            let mut poses: Vec<Pose> = path.stretches.iter().map(|s| s.start).collect();
            poses.extend(path.end());
            let reverse = path.stretches.iter().filter(|s| s.gear == Gear::Reverse).map(|s| s.length).sum();
            let cusps =
                path.cusps().iter().map(|p| [p.translation.x, p.translation.y, p.rotation.angle()]).collect();
            let record = CarRecord { length: path.length(), reverse_length: reverse, cusps };
            (poses.iter().map(as_waypoint).collect(), Some(record))
        }
        None => (Vec::new(), None),
    };
    Ok(SolveResult {
        status,
        cost: path.as_ref().map(|p| p.cost),
        path: waypoints,
        stats: ResultStats {
            expansions: Some(stats.expansions),
            time_s: stats.time.as_secs_f64(),
            car: record,
            ..ResultStats::default()
        },
    })
}

/// The costmap, the path (forward and reverse alike), the footprint every
/// [`OUTLINE_EVERY`] metres and at the cusps (marked), the start and the goal.
fn draw(
    costmap: &Costmap,
    car: &Footprint,
    path: Option<&CarPath>,
    start: &Pose,
    goal: &Pose,
) -> Result<String, SolveError> {
    let mut svg = CostmapSvg::new(costmap)
        .start(Point::from(start.translation.vector))
        .goal(Point::from(goal.translation.vector))
        .title("hybrid_astar: the footprint along the path, cusps in red");
    if let Some(path) = path {
        let step = costmap.frame().resolution() / 2.0;
        let dense = path.sample(step);
        svg = svg.path(&dense.iter().map(|(p, _)| Point::from(p.translation.vector)).collect::<Vec<_>>());
        let mut travelled = f64::INFINITY;
        for pair in dense.windows(2) {
            if travelled >= OUTLINE_EVERY {
                svg = svg.outline(&outline(car, &pair[0].0));
                travelled = 0.0;
            }
            travelled += (pair[1].0.translation.vector - pair[0].0.translation.vector).norm();
        }
        svg = svg.outline(&outline(car, goal));
        for cusp in path.cusps() {
            svg = svg.outline(&outline(car, &cusp)).mark(Point::from(cusp.translation.vector));
        }
    }
    Ok(svg.to_svg()?)
}

/// The footprint at `pose`: its corners, or for a disc a 16-gon around it.
fn outline(car: &Footprint, pose: &Pose) -> Vec<Point> {
    match car {
        Footprint::Radius(r) => (0..16)
            .map(|k| {
                let a = f64::from(k) * std::f64::consts::TAU / 16.0;
                pose * Point::new(r * a.cos(), r * a.sin())
            })
            .collect(),
        Footprint::Polygon(_) => car.corners_at(pose),
    }
}
