//! Which inputs are quick enough to run: the targets skip the others (they never edit an input
//! to make it quick, which would hide the value that mattered).
//!
//! The bounds keep one run well under libFuzzer's `-timeout` on a slow machine; they are far
//! above what the hostile values need (a 100-cell grid shows a bad weight as well as a
//! 10,000-cell one).

use trailmark::solve::{AnytimeSpec, GraphKind, PlannerSpec, ProblemSpec, SamplerSpec, SpaceKind, WorldSpec};
use trailmark_core::world::PolygonWorld;

/// The most cells of a grid world.
pub const MAX_GRID_CELLS: usize = 10_000;
/// The most vertices of all the obstacles of a polygon world.
pub const MAX_OBSTACLE_VERTICES: usize = 40;
/// The most obstacles of a polygon world.
pub const MAX_OBSTACLES: usize = 8;
/// The most boxes of a box world.
pub const MAX_BOXES: usize = 64;
/// The most samples of a straight-line PRM (the default, without `samples`, is 1000).
pub const MAX_PRM_SAMPLES: usize = 1000;
/// The most samples of a Dubins PRM.
pub const MAX_DUBINS_SAMPLES: usize = 150;
/// The most iterations of a sampling planner.
pub const MAX_SAMPLING_ITERATIONS: u64 = 3000;
/// The longest time limit of a planner that has no smaller limit of iterations, in seconds.
pub const MAX_TIME_LIMIT_S: f64 = 0.5;
/// The most tries of a bridge or Gaussian sampler per sample (the default is 100).
pub const MAX_SAMPLER_ATTEMPTS: u32 = 100;
/// The most expansions of a Hybrid A* run without a smaller time limit.
pub const MAX_CAR_EXPANSIONS: u64 = 20_000;
/// The most poses a Hybrid A* motion is checked at (twice its length in cells): the planner
/// lays out every motion's poses before it starts, and a turning radius of a million cells with
/// 4 heading bins makes motions millions of cells long.
pub const MAX_CAR_MOTION_POSES: f64 = 400.0;
/// The most vertices of a footprint that is run (a longer one, up to the documented 1024, is
/// checked at every pose, vertex by vertex: slow rather than hostile).
pub const MAX_CAR_FOOTPRINT_VERTICES: usize = 64;
/// The farthest, in cells, a footprint's vertex may lie from its reference point: each check
/// near an obstacle lays the footprint on the cells it covers.
pub const MAX_CAR_FOOTPRINT_CELLS: f64 = 64.0;
/// The most (cells x anytime iterations) of an ARA* or AD* run without a smaller limit.
pub const MAX_ANYTIME_WORK: u64 = 5_000_000;

/// Whether `problem` is small enough to solve in a fuzzing run, and names no file outside the
/// (nonexistent) base folder.
pub fn problem_is_quick(problem: &ProblemSpec) -> bool {
    let cells = match &problem.world {
        WorldSpec::Grid(world) => {
            if world.map.as_ref().is_some_and(|m| m.is_absolute() || m.has_root()) {
                return false; // Path::join would leave the base folder: never read a file.
            }
            let rows = world.rows.as_deref().unwrap_or_default();
            let width = rows.first().map_or(0, |r| r.chars().count());
            let cells = rows.len().saturating_mul(width);
            let text: usize = rows.iter().map(String::len).sum();
            if cells > MAX_GRID_CELLS || text > 4 * MAX_GRID_CELLS {
                return false;
            }
            cells
        }
        WorldSpec::Polygons(world) => {
            if !polygons_are_quick(world) {
                return false;
            }
            0
        }
        WorldSpec::Boxes(world) => {
            if world.bounds.len() > 8 || world.obstacles.len() > MAX_BOXES {
                return false;
            }
            0
        }
        WorldSpec::RosMap(world) => {
            if world.yaml.is_absolute() || world.yaml.has_root() {
                return false; // Path::join would leave the base folder: never read a file.
            }
            0
        }
        WorldSpec::Robot(world) => {
            let files = [Some(&world.robot.urdf), Some(&world.robot.srdf), world.scene.as_ref()];
            let files = files.into_iter().flatten().chain(problem.request.as_ref());
            if files.into_iter().any(|f| f.is_absolute() || f.has_root()) {
                return false; // Path::join would leave the base folder: never read a file.
            }
            0
        }
    };
    let time_ok = |t: Option<f64>| t.is_some_and(|t| t <= MAX_TIME_LIMIT_S);
    match &problem.planner {
        PlannerSpec::HybridAStar(spec) => {
            if !(spec.max_expansions.is_some_and(|e| e <= MAX_CAR_EXPANSIONS) || time_ok(spec.time_limit_s)) {
                return false;
            }
            let resolution = match &problem.world {
                WorldSpec::Polygons(_) => spec.resolution.unwrap_or(spec.turning_radius / 8.0),
                _ => spec.resolution.unwrap_or(1.0),
            };
            // A polygon world laid on cells: no more than a grid world's.
            let diagonal = if let WorldSpec::Polygons(world) = &problem.world {
                let size = world.bounds().max() - world.bounds().min();
                let cells = (size.x / resolution).ceil() * (size.y / resolution).ceil();
                if cells.is_nan() || cells > MAX_GRID_CELLS as f64 {
                    return false;
                }
                size.norm() + 2.0 * resolution
            } else if let WorldSpec::Grid(world) = &problem.world {
                let rows = world.rows.as_deref().unwrap_or_default();
                let width = rows.iter().map(|r| r.chars().count()).max().unwrap_or(0);
                (width as f64).hypot(rows.len() as f64) * resolution
            } else {
                f64::INFINITY
            };
            if !car_run_is_quick(spec, resolution, diagonal) {
                return false;
            }
        }
        PlannerSpec::AraStar(AnytimeSpec { epsilon, epsilon_step, time_limit_s, max_expansions, .. })
        | PlannerSpec::AdStar(AnytimeSpec { epsilon, epsilon_step, time_limit_s, max_expansions, .. }) => {
            let schedule =
                trailmark::search::EpsilonSchedule::new(epsilon.unwrap_or(3.0), epsilon_step.unwrap_or(0.5));
            let nodes = if cells > 0 { cells } else { roadmap_nodes(problem) };
            let work = (nodes as u64).saturating_mul(schedule.iterations() as u64);
            if !(work <= MAX_ANYTIME_WORK
                || max_expansions.is_some_and(|e| e <= MAX_ANYTIME_WORK)
                || time_ok(*time_limit_s))
            {
                return false;
            }
        }
        PlannerSpec::Rrt(spec)
        | PlannerSpec::RrtConnect(spec)
        | PlannerSpec::RrtStar(spec)
        | PlannerSpec::InformedRrtStar(spec)
        | PlannerSpec::BitStar(spec)
        | PlannerSpec::Prm(spec)
        | PlannerSpec::PrmStar(spec)
        | PlannerSpec::LazyPrm(spec)
        | PlannerSpec::LazyPrmStar(spec) => {
            let iterations_ok = match spec.max_iterations {
                Some(n) => n <= MAX_SAMPLING_ITERATIONS,
                None => {
                    spec.time_limit_s.is_none()
                        && trailmark::solve::DEFAULT_ITERATIONS <= MAX_SAMPLING_ITERATIONS
                }
            };
            if !(iterations_ok || time_ok(spec.time_limit_s)) {
                return false;
            }
            let attempts = match spec.sampler {
                Some(SamplerSpec::Bridge { attempts, .. } | SamplerSpec::Gaussian { attempts, .. }) => {
                    attempts
                }
                _ => None,
            };
            if attempts.is_some_and(|a| a > MAX_SAMPLER_ATTEMPTS) {
                return false;
            }
            // RRT* and PRM* over car curves are the slowest: fewer iterations.
            if matches!(problem.space, Some(SpaceKind::Dubins | SpaceKind::ReedsShepp))
                && matches!(problem.planner, PlannerSpec::RrtStar(_)
                        | PlannerSpec::InformedRrtStar(_)
                        | PlannerSpec::BitStar(_)
                        | PlannerSpec::PrmStar(_)
                        | PlannerSpec::LazyPrmStar(_)
                )
                && !(spec.max_iterations.is_some_and(|n| n <= MAX_SAMPLING_ITERATIONS / 3)
                    || time_ok(spec.time_limit_s))
            {
                return false;
            }
        }
        _ => {}
    }
    if matches!(problem.world, WorldSpec::Polygons(_)) {
        let samples = problem.samples.unwrap_or(trailmark::solve::DEFAULT_SAMPLES);
        match problem.graph {
            Some(GraphKind::Prm) if samples > MAX_PRM_SAMPLES => return false,
            Some(GraphKind::DubinsPrm | GraphKind::ReedsSheppPrm) if samples > MAX_DUBINS_SAMPLES => {
                return false;
            }
            _ => {}
        }
    }
    true
}

/// A rough count of the nodes of the roadmap a polygon-world problem searches.
fn roadmap_nodes(problem: &ProblemSpec) -> usize {
    match problem.graph {
        Some(GraphKind::Prm | GraphKind::DubinsPrm | GraphKind::ReedsSheppPrm) => {
            problem.samples.unwrap_or(trailmark::solve::DEFAULT_SAMPLES) + 2
        }
        _ => match &problem.world {
            // Grown corners are arcs of up to 16 vertices.
            WorldSpec::Polygons(w) => {
                16 * w.obstacles().iter().map(|o| o.vertices().len()).sum::<usize>() + 6
            }
            WorldSpec::Grid(_) | WorldSpec::Boxes(_) | WorldSpec::RosMap(_) | WorldSpec::Robot(_) => 0,
        },
    }
}

/// Whether a polygon world has few enough obstacles and vertices.
pub fn polygons_are_quick(world: &PolygonWorld) -> bool {
    let vertices: usize = world.obstacles().iter().map(|o| o.vertices().len()).sum();
    world.obstacles().len() <= MAX_OBSTACLES && vertices <= MAX_OBSTACLE_VERTICES
}

/// Whether a Hybrid A* run on cells `resolution` wide does bounded work per expansion: its
/// motions checked at few poses (the planner's rule: the fewest heading bins whose arc is 1.5
/// cells long, checked every half cell), a footprint of few vertices within a few cells. A
/// setting the planner refuses (a resolution or radius out of range, a footprint of more
/// vertices than documented) costs nothing, and so does a footprint reaching farther than the
/// map's `diagonal`: it leaves the map wherever it is, and the start is refused.
fn car_run_is_quick(spec: &trailmark::solve::HybridSpec, resolution: f64, diagonal: f64) -> bool {
    let (radius, bins) = (spec.turning_radius, spec.heading_bins.unwrap_or(72));
    let accepted = resolution.is_finite()
        && resolution > 0.0
        && radius.is_finite()
        && radius >= 0.5 * resolution
        && radius <= 1e6 * resolution
        && (4..=1440).contains(&bins);
    if !accepted {
        return true;
    }
    let bin_angle = std::f64::consts::TAU / f64::from(bins);
    let per_turn = (1.5 * resolution / (radius * bin_angle)).ceil().max(1.0);
    let poses = (per_turn * bin_angle * radius / (0.5 * resolution)).ceil();
    if poses.is_nan() || poses > MAX_CAR_MOTION_POSES {
        return false;
    }
    match &spec.footprint {
        Some(v) if v.len() > trailmark_core::footprint::MAX_FOOTPRINT_VERTICES => true,
        Some(v) => {
            let reach = v.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
            v.len() <= MAX_CAR_FOOTPRINT_VERTICES
                && (reach / resolution <= MAX_CAR_FOOTPRINT_CELLS || reach.is_nan() || reach > diagonal)
        }
        None => true,
    }
}
