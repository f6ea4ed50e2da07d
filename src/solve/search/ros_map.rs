//! ROS-map worlds: a map_server map made into a Nav2-style costmap around the robot, searched
//! cell to cell (or by straight lines, Theta*) with start, goal and path in metres.

use std::path::Path;

use trailmark_core::geometry::Point;
use trailmark_core::grid::{Cell, Connectivity};
use trailmark_graph::GridGraph;

use crate::solve::error::{DocumentError, SolveError};
use crate::solve::planner::PlannerSpec;
use crate::solve::problem::{ProblemSpec, RosMapSpec};
use crate::solve::result::{SolveResult, Waypoint};
use crate::solve::world::ros_map::{RosMapWorld, cell_at};

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
    let ros = RosMapWorld::load(world, base_dir)?;
    let result = ros.search(&problem.planner, &problem.start, &problem.goal)?;
    let (costmap, frame) = (&ros.costmap, ros.costmap.frame());
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
        *picture = trailmark_map::CostmapSvg::new(costmap)
            .path(&path)
            .start(frame.centre(cell_at("start", &problem.start, costmap)?))
            .goal(frame.centre(cell_at("goal", &problem.goal, costmap)?))
            .title(title)
            .to_svg()?;
    }
    Ok(result)
}

impl RosMapWorld {
    /// Runs the graph search `planner` from `start` to `goal` (`[x, y]` in metres) on this
    /// map's 8-connected cells, or by straight lines for Theta*; the path in metres, at cell
    /// centres. The result is the one a ROS-map document with this world and planner gives.
    ///
    /// ```
    /// use trailmark::solve::{PlannerSpec, RosMapSpec, RosMapWorld, Status};
    ///
    /// let spec: RosMapSpec = serde_json::from_str(r#"{"yaml": "examples/maps/office.yaml"}"#)?;
    /// let office = RosMapWorld::load(&spec, env!("CARGO_MANIFEST_DIR"))?;
    /// let found = office.search(&PlannerSpec::ThetaStar {}, &[-4.2, -2.2], &[4.3, 2.3])?;
    /// assert_eq!(found.status, Status::Solved);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn search(
        &self,
        planner: &PlannerSpec,
        start: &[f64],
        goal: &[f64],
    ) -> Result<SolveResult, SolveError> {
        planner.check_limits()?;
        if planner.sampling().is_some() {
            return Err(DocumentError::NeedsPolygons { planner: planner.name() }.into());
        }
        let frame = *self.costmap.frame();
        let start = cell_at("start", start, &self.costmap)?;
        let goal = cell_at("goal", goal, &self.costmap)?;
        let graph = GridGraph::new(&self.grid, Connectivity::Eight);
        let h = graph.heuristic_between(planner.grid_heuristic(Connectivity::Eight)?);
        let waypoint = |cell: Cell| {
            let p = frame.centre(cell);
            Waypoint::Point(vec![p.x, p.y])
        };
        planner.search(&graph, (start, goal), h, waypoint, Some(&graph))
    }
}
