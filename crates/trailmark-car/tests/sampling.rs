//! The sampling planners in the car spaces on a map's cells, through `MapFootprintValidity`:
//! RRT-Connect's paths in the Reeds-Shepp space keep a car's rectangle off every blocked cell,
//! checked here by points of the footprint laid on the grid by hand, every centimetre along
//! every motion.

use trailmark_car::{CarMap, MapFootprintValidity};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::reeds_shepp::ReedsSheppPath;
use trailmark_core::termination::Termination;
use trailmark_core::world::{Bounds, Polygon};
use trailmark_sample::{KdNearest, Planner, Problem, ReedsShepp, RrtConnect, Validity};

const RESOLUTION: f64 = 0.1;
const WIDTH: usize = 120;
const HEIGHT: usize = 60;

/// A 12 m x 6 m yard with two walls, each leaving a 2.4 m gap at alternate ends.
fn yard() -> Grid {
    let mut rows = vec![".".repeat(WIDTH); HEIGHT];
    for (y, row) in rows.iter_mut().enumerate() {
        if y >= 24 {
            row.replace_range(38..42, "@@@@");
        }
        if y < 36 {
            row.replace_range(78..82, "@@@@");
        }
    }
    Grid::from_rows(&rows).expect("a grid")
}

/// A 1.2 m x 0.6 m car about its rear axle.
fn car() -> (Footprint, Vec<Point>) {
    let corners: Vec<Point> =
        [(-0.2, -0.3), (1.0, -0.3), (1.0, 0.3), (-0.2, 0.3)].iter().map(|&(x, y)| Point::new(x, y)).collect();
    (Footprint::Polygon(Polygon::new(corners.clone()).expect("a rectangle")), corners)
}

/// Whether every point of the car at `pose`, on a 2 cm lattice over its rectangle and its
/// outline, lies on the grid in a free cell (cells counted from the top-left corner).
fn covers_only_free_cells(grid: &Grid, corners: &[Point], pose: &Pose) -> bool {
    let (x0, x1, y0, y1) = (corners[0].x, corners[2].x, corners[0].y, corners[2].y);
    let steps = |a: f64, b: f64| ((b - a) / 0.02).ceil() as usize;
    (0..=steps(x0, x1)).all(|i| {
        (0..=steps(y0, y1)).all(|j| {
            let local = Point::new((x0 + 0.02 * i as f64).min(x1), (y0 + 0.02 * j as f64).min(y1));
            let p = pose * local;
            let (gx, gy) = (p.x / RESOLUTION, (HEIGHT as f64 * RESOLUTION - p.y) / RESOLUTION);
            gx >= 0.0
                && gy >= 0.0
                && gx < WIDTH as f64
                && gy < HEIGHT as f64
                && grid.is_passable(Cell::new(gx as u32, gy as u32))
        })
    })
}

#[test]
fn rrt_connect_on_a_map_keeps_the_car_off_blocked_cells() {
    let grid = yard();
    let map = CarMap::from_grid(&grid, RESOLUTION).expect("a map");
    let (footprint, corners) = car();
    let bounds =
        Bounds::new(0.0, 0.0, WIDTH as f64 * RESOLUTION, HEIGHT as f64 * RESOLUTION).expect("bounds");
    let space = ReedsShepp::new(bounds, 1.0).expect("a space");
    let validity = MapFootprintValidity::new(&map, &footprint, &space, 0.05).expect("a validity");
    let start = Pose::new(Vector::new(1.0, 1.0), 0.0);
    let goal = Pose::new(Vector::new(10.5, 5.0), 0.0);
    assert!(
        covers_only_free_cells(&grid, &corners, &start) && covers_only_free_cells(&grid, &corners, &goal)
    );
    let mut solved = 0;
    for seed in 0..4 {
        let problem = Problem::new(&space, &validity, start, goal);
        let mut planner =
            RrtConnect::new(KdNearest::<ReedsShepp, 2>::new(&space).expect("a tree")).with_seed(seed);
        let plan = planner.solve(&problem, &Termination::iterations(20_000)).expect("a run");
        let Some(path) = plan.path().filter(|_| plan.is_exact()) else { continue };
        solved += 1;
        for pair in path.windows(2) {
            let curve = ReedsSheppPath::shortest(&pair[0], &pair[1], 1.0).expect("a curve");
            let poses = curve.sample(0.01).expect("poses");
            assert!(
                poses.iter().all(|p| covers_only_free_cells(&grid, &corners, p)),
                "seed {seed}: a motion from {:?} to {:?} crosses a blocked cell",
                pair[0],
                pair[1]
            );
        }
    }
    assert!(solved >= 3, "RRT-Connect threads both gaps: {solved} of 4 seeds");
}

#[test]
fn states_on_blocked_cells_or_off_the_map_are_invalid_and_bad_steps_are_errors() {
    let grid = yard();
    let map = CarMap::from_grid(&grid, RESOLUTION).expect("a map");
    let (footprint, corners) = car();
    let space = ReedsShepp::new(Bounds::new(0.0, 0.0, 12.0, 6.0).expect("bounds"), 1.0).expect("a space");
    let validity = MapFootprintValidity::new(&map, &footprint, &space, 0.05).expect("a validity");
    // Across the lattice of poses, the validity never calls a pose free that puts a point of
    // the car on a blocked cell or off the map.
    for i in 0..60 {
        for j in 0..30 {
            for k in 0..4 {
                let pose = Pose::new(Vector::new(0.2 * i as f64, 0.2 * j as f64), 1.6 * k as f64);
                if validity.state_is_valid(&space, &pose) {
                    assert!(covers_only_free_cells(&grid, &corners, &pose), "{pose:?}");
                }
            }
        }
    }
    for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(MapFootprintValidity::new(&map, &footprint, &space, step).is_err(), "step {step}");
    }
}
