//! ROS-map worlds: a map_server map made into a Nav2-style costmap around the robot, searched
//! cell to cell (or by straight lines, Theta*) with start, goal and path in metres.

use std::path::Path;

use trailmark_core::geometry::Point;
use trailmark_core::grid::{Cell, Connectivity};
use trailmark_graph::GridGraph;

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::problem::{ProblemSpec, RosMapSpec};
use crate::solve::result::{SolveResult, Waypoint};
use crate::solve::world::ros_map::{cell_at, ros_costmap, ros_travel_cost};

/// Solves a ROS-map problem.
pub(in crate::solve) fn solve_ros_map(
    problem: &ProblemSpec,
    world: &RosMapSpec,
    base_dir: &Path,
    picture: Option<&mut String>,
) -> Result<SolveResult, SolveError> {
    if let Some(name) = problem.roadmap_fields().first() {
        return Err(DocumentError::NotForGrids { field: name }.into());
    }
    let costmap = ros_costmap(world, base_dir)?;
    let frame = *costmap.frame();
    let grid = costmap.to_grid(&ros_travel_cost(world, frame.resolution()))?;
    let start = cell_at("start", &problem.start, &costmap)?;
    let goal = cell_at("goal", &problem.goal, &costmap)?;
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let h = graph.heuristic_between(problem.planner.grid_heuristic(Connectivity::Eight)?);
    let waypoint = |cell: Cell| {
        let p = frame.centre(cell);
        Waypoint::Point(vec![p.x, p.y])
    };
    let result = problem.planner.search(&graph, (start, goal), h, waypoint, Some(&graph))?;
    if let Some(picture) = picture {
        let path: Vec<Point> = result
            .path
            .iter()
            .filter_map(|w| match w {
                Waypoint::Point(p) => Some(Point::new(p[0], p[1])),
                Waypoint::Cell(_) => None,
            })
            .collect();
        let title = format!("{} on {}", problem.planner.name(), world.yaml.display());
        *picture = trailmark_map::CostmapSvg::new(&costmap)
            .path(&path)
            .start(frame.centre(start))
            .goal(frame.centre(goal))
            .title(title)
            .to_svg()?;
    }
    Ok(result)
}
