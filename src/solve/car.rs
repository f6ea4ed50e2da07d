//! Problem documents for car-like robots: Hybrid A* on a ROS-map, grid or polygon world, poses
//! `[x, y, heading]` in metres and radians (on grids, x along the columns and y up from the
//! grid's bottom edge, as on a ROS map), the result a pose at every stretch's end (and the
//! cusps in the statistics), the picture the footprint along the path.

use std::path::Path;

use trailmark_car::{CarError, CarMap, CarPath, HybridAStar};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::reeds_shepp::Gear;
use trailmark_core::svg::WorldSvg;
use trailmark_core::termination::Stop;
use trailmark_core::world::PolygonWorld;
use trailmark_map::{Costmap, CostmapSvg, LETHAL, TravelCost};

use super::error::{DocumentError, SolveError};
use super::problem::{GridSpec, ProblemSpec, RosMapSpec, WorldSpec};
use super::result::{CarRecord, ResultStats, SolveResult, Status, Waypoint};
use super::settings::HybridSpec;
use super::world::grid::load_grid;
use super::world::ros_map::{DEFAULT_COST_FACTOR, DEFAULT_ROBOT_RADIUS, ros_costmap};

/// The footprint drawn every this many metres along the path in pictures.
const OUTLINE_EVERY: f64 = 0.5;

/// The pose `which` (`[x, y, heading]`), or why it is not one.
fn pose(which: &'static str, value: &[f64]) -> Result<Pose, DocumentError> {
    match *value {
        [x, y, heading] if x.is_finite() && y.is_finite() && heading.is_finite() => {
            Ok(Pose::new(Vector::new(x, y), heading))
        }
        _ => Err(DocumentError::NotAPose { which, value: value.to_vec(), planner: "hybrid_astar" }),
    }
}

/// The planner's polygon footprint, if it gives one.
fn given_footprint(spec: &HybridSpec) -> Result<Option<Footprint>, SolveError> {
    let Some(points) = &spec.footprint else { return Ok(None) };
    Ok(Some(Footprint::polygon(points.clone()).map_err(DocumentError::Footprint)?))
}

/// What a car plans on, and what its picture is drawn over.
enum Backdrop {
    /// A costmap (ROS maps, and grids drawn as one).
    Costmap(Costmap),
    /// A polygon world.
    World(PolygonWorld),
}

/// A ROS-map world: the costmap inflated around the car, the footprint the planner's polygon,
/// else the world's polygon, else a disc of the world's radius.
fn on_ros_map(
    world: &RosMapSpec,
    spec: &HybridSpec,
    base_dir: &Path,
) -> Result<(CarMap, Footprint, Backdrop), SolveError> {
    if spec.resolution.is_some() {
        return Err(DocumentError::NotForRosMaps { field: "resolution" }.into());
    }
    if spec.footprint.is_some() && world.robot_radius.is_some() {
        return Err(DocumentError::RadiusAndFootprint.into());
    }
    let car = match (given_footprint(spec)?, &world.footprint) {
        (Some(car), _) => car,
        (None, Some(points)) => Footprint::polygon(points.clone()).map_err(DocumentError::Footprint)?,
        (None, None) => Footprint::Radius(world.robot_radius.unwrap_or(DEFAULT_ROBOT_RADIUS)),
    };
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
    Ok((map, car, Backdrop::Costmap(costmap)))
}

/// A grid world: cells `resolution` metres wide (default 1), a metre costing the cell's cost,
/// the footprint the planner's polygon, else a point; drawn as a costmap of its blocked cells.
fn on_grid(
    world: &GridSpec,
    spec: &HybridSpec,
    base_dir: &Path,
) -> Result<(CarMap, Footprint, Backdrop), SolveError> {
    let grid = load_grid(world, base_dir)?;
    let map = CarMap::from_grid(&grid, spec.resolution.unwrap_or(1.0)).map_err(SolveError::Car)?;
    let car = given_footprint(spec)?.unwrap_or(Footprint::Radius(0.0));
    let blocked = grid.costs().iter().map(|c| if c.is_finite() { 0 } else { LETHAL }).collect();
    let costmap = Costmap::new(*map.frame(), blocked)?;
    Ok((map, car, Backdrop::Costmap(costmap)))
}

/// A polygon world laid on cells `resolution` wide (default an eighth of the turning
/// radius), the footprint the planner's polygon, else a disc of the world's radius.
fn on_polygons(world: &PolygonWorld, spec: &HybridSpec) -> Result<(CarMap, Footprint, Backdrop), SolveError> {
    if spec.footprint.is_some() && world.robot_radius() > 0.0 {
        return Err(DocumentError::RadiusAndFootprint.into());
    }
    let resolution = spec.resolution.unwrap_or(spec.turning_radius / 8.0);
    let map = CarMap::from_world(world, resolution).map_err(SolveError::Car)?;
    let car = given_footprint(spec)?.unwrap_or(Footprint::Radius(world.robot_radius()));
    Ok((map, car, Backdrop::World(world.clone())))
}

/// Solves a Hybrid A* problem on a ROS-map, grid or polygon world.
pub(super) fn solve_hybrid_astar(
    problem: &ProblemSpec,
    world: &WorldSpec,
    spec: &HybridSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForPlanner { field: name, planner: "hybrid_astar" }.into());
    }
    // Before the poses: a robot's joint values are not a pose, and that is not the fault.
    let robot = || DocumentError::RobotNeedsSampling { planner: "hybrid_astar" };
    if let WorldSpec::Robot(_) = world {
        return Err(robot().into());
    }
    let (start, goal) = (pose("start", &problem.start)?, pose("goal", &problem.goal)?);
    let (map, car, backdrop) = match world {
        WorldSpec::RosMap(w) => on_ros_map(w, spec, base_dir)?,
        WorldSpec::Grid(w) => on_grid(w, spec, base_dir)?,
        WorldSpec::Polygons(w) => on_polygons(w, spec)?,
        WorldSpec::Boxes(_) => {
            let why = "is not for hybrid_astar, which plans on ROS-map, grid and polygon worlds";
            return Err(DocumentError::InvalidBoxes(why.into()).into());
        }
        WorldSpec::Robot(_) => return Err(robot().into()),
    };
    let planner = HybridAStar::new(&map, &car, spec.settings()).map_err(SolveError::Car)?;
    let mut stopped = None;
    let (path, status, stats) = match planner.plan(&start, &goal, &spec.termination()) {
        Ok(plan) => (Some(plan.path), Status::Solved, plan.stats),
        Err(CarError::NoPath { stop: Stop::Unreachable, stats }) => (None, Status::NoPath, stats),
        Err(CarError::NoPath { stop, stats }) => {
            stopped = Some(stop);
            (None, Status::Stopped, stats)
        }
        Err(e) => return Err(SolveError::Car(e)),
    };
    if let Some(picture) = picture {
        let drawing = Drawing::of(&car, path.as_ref(), &goal, map.resolution() / 2.0);
        let title = "hybrid_astar: the footprint along the path, cusps in red";
        let (from, to) = (Point::from(start.translation.vector), Point::from(goal.translation.vector));
        *picture = match &backdrop {
            Backdrop::Costmap(costmap) => {
                let mut svg = CostmapSvg::new(costmap).start(from).goal(to).title(title);
                svg = drawing.outlines.iter().fold(svg, |svg, o| svg.outline(o));
                svg = drawing.marks.iter().fold(svg.path(&drawing.path), |svg, &m| svg.mark(m));
                svg.to_svg()?
            }
            Backdrop::World(world) => {
                let mut svg = WorldSvg::new(world).start(from).goal(to).title(title);
                svg = drawing.outlines.iter().fold(svg, |svg, o| svg.outline(o));
                svg = drawing.marks.iter().fold(svg.path(&drawing.path), |svg, &m| svg.mark(m));
                svg.to_svg()
            }
        };
    }
    let as_waypoint = |p: &Pose| Waypoint::Point(vec![p.translation.x, p.translation.y, p.rotation.angle()]);
    let (waypoints, record) = match &path {
        Some(path) => {
            // The start of every stretch and the end; the start alone when it is the goal.
            let mut poses: Vec<Pose> = path.stretches.iter().map(|s| s.start).collect();
            poses.push(path.end().unwrap_or(start));
            let reverse = 0.0
                + path.stretches.iter().filter(|s| s.gear == Gear::Reverse).map(|s| s.length).sum::<f64>();
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
            stop: stopped,
            ..ResultStats::default()
        },
    })
}

/// What a picture draws over its backdrop: the path (forward and reverse alike), the
/// footprint every [`OUTLINE_EVERY`] metres, at the goal and at the cusps, and the cusps.
struct Drawing {
    path: Vec<Point>,
    outlines: Vec<Vec<Point>>,
    marks: Vec<Point>,
}

impl Drawing {
    /// The drawing of `path` sampled every `step`.
    fn of(car: &Footprint, path: Option<&CarPath>, goal: &Pose, step: f64) -> Self {
        let mut drawing = Drawing { path: Vec::new(), outlines: Vec::new(), marks: Vec::new() };
        let Some(path) = path else { return drawing };
        let dense = path.sample(step);
        drawing.path = dense.iter().map(|(p, _)| Point::from(p.translation.vector)).collect();
        let mut travelled = f64::INFINITY;
        for pair in dense.windows(2) {
            if travelled >= OUTLINE_EVERY {
                drawing.outlines.push(outline(car, &pair[0].0));
                travelled = 0.0;
            }
            travelled += (pair[1].0.translation.vector - pair[0].0.translation.vector).norm();
        }
        drawing.outlines.push(outline(car, goal));
        for cusp in path.cusps() {
            drawing.outlines.push(outline(car, &cusp));
            drawing.marks.push(Point::from(cusp.translation.vector));
        }
        drawing
    }
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
