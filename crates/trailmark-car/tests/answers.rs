//! What Hybrid A* answers is so: `Stop::Unreachable` only with a proof, and problems it can
//! solve solved whatever the scale of the map, the contrast of its costs or the shape of the
//! footprint.

use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark_car::{CarError, CarMap, HybridAStar, HybridOptions};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::Pose;
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::termination::{Stop, Termination};

fn pose(x: f64, y: f64, h: f64) -> Pose {
    Pose::new(nalgebra::Vector2::new(x, y), h)
}

fn scaled(p: &Pose, s: f64) -> Pose {
    Pose::new(p.translation.vector * s, p.rotation.angle())
}

/// A `w x h` grid with `count` random blocked rectangles of up to 6 x 6 cells.
fn blocks(w: u32, h: u32, count: usize, rng: &mut ChaCha8Rng) -> Grid {
    let mut grid = Grid::new(w as usize, h as usize).unwrap();
    for _ in 0..count {
        let (x0, y0) = (rng.random_range(0..w), rng.random_range(0..h));
        let (dx, dy) = (rng.random_range(1..7), rng.random_range(1..7));
        for y in y0..(y0 + dy).min(h) {
            for x in x0..(x0 + dx).min(w) {
                grid.set_blocked(Cell::new(x, y), true).unwrap();
            }
        }
    }
    grid
}

/// Plans on `grid` with cells `resolution` wide, a disc of `radius` and `settings`.
fn plan(
    grid: &Grid,
    resolution: f64,
    car: &Footprint,
    settings: HybridOptions,
    (start, goal): (&Pose, &Pose),
) -> Result<trailmark_car::CarPlan, CarError> {
    let map = CarMap::from_grid(grid, resolution).unwrap();
    let planner = HybridAStar::new(&map, car, settings).unwrap();
    planner.plan(start, goal, &Termination::expansions(200_000))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// A problem solved on cells of 0.1 is solved with every length scaled by 1e-2, 100 and
    /// 500 (cells of 50 m, a turning radius of 500 m): shots to the goal are tried within the
    /// car's own motions, not only within a fixed 3 m.
    #[test]
    fn a_problem_solved_at_one_scale_is_solved_at_every_scale(seed in any::<u64>()) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let grid = blocks(40, 30, 6, &mut rng);
        let map = CarMap::from_grid(&grid, 0.1).unwrap();
        let settings = HybridOptions { turning_radius: 1.0, heading_bins: 36, ..HybridOptions::default() };
        let car = Footprint::Radius(0.2);
        let planner = HybridAStar::new(&map, &car, settings).unwrap();
        let mut free = || loop {
            let p = pose(rng.random_range(0.3..3.7), rng.random_range(0.3..2.7), rng.random_range(-3.0..3.0));
            if planner.is_free(&p) {
                return p;
            }
        };
        let (start, goal) = (free(), free());
        let Ok(plan_1) = plan(&grid, 0.1, &car, settings, (&start, &goal)) else { return Ok(()) };
        for s in [1e-2, 100.0, 500.0] {
            let big = HybridOptions { turning_radius: settings.turning_radius * s, ..settings };
            let found = plan(&grid, 0.1 * s, &Footprint::Radius(0.2 * s), big, (&scaled(&start, s), &scaled(&goal, s)));
            match found {
                Ok(plan_s) => prop_assert!(plan_s.path.length() < 3.0 * s * plan_1.path.length() + 1e-9 * s),
                Err(e) => prop_assert!(false, "solved at scale 1, not at {s}: {e}"),
            }
        }
    }
}

/// Whether a point can go from cell `a` to cell `b` of `grid` (x, y from the top-left) through
/// open cells: side to side, or corner to corner past at least one open cell beside the corner
/// (the point cannot pass a corner both of whose other cells are blocked: blocked cells are
/// closed squares). A breadth-first search written here.
fn point_can_pass(grid: &Grid, a: Cell, b: Cell) -> bool {
    let (w, h) = (grid.width() as i64, grid.height() as i64);
    let open = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && grid.is_passable(Cell::new(x as u32, y as u32))
    };
    let mut seen = vec![false; (w * h) as usize];
    let mut queue = std::collections::VecDeque::from([(i64::from(a.x), i64::from(a.y))]);
    seen[(i64::from(a.y) * w + i64::from(a.x)) as usize] = true;
    while let Some((x, y)) = queue.pop_front() {
        if (x, y) == (i64::from(b.x), i64::from(b.y)) {
            return true;
        }
        for (dx, dy) in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)] {
            let (nx, ny) = (x + dx, y + dy);
            let diagonal_ok = dx == 0 || dy == 0 || open(x + dx, y) || open(x, y + dy);
            if open(nx, ny) && diagonal_ok && !seen[(ny * w + nx) as usize] {
                seen[(ny * w + nx) as usize] = true;
                queue.push_back((nx, ny));
            }
        }
    }
    false
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A point robot's `Stop::Unreachable` is a proof: no chain of open cells joins its ends.
    /// Any other end without a path is a stop, never a proof.
    #[test]
    fn unreachable_is_proved_by_the_cells(seed in any::<u64>()) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let grid = blocks(16, 12, 14, &mut rng);
        let map = CarMap::from_grid(&grid, 1.0).unwrap();
        let settings = HybridOptions { turning_radius: 1.0, heading_bins: 16, ..HybridOptions::default() };
        let planner = HybridAStar::new(&map, &Footprint::Radius(0.0), settings).unwrap();
        let cell_of = |p: &Pose| Cell::new(p.translation.x as u32, 11 - p.translation.y as u32);
        let mut free = || loop {
            let p = pose(rng.random_range(0.1..15.9), rng.random_range(0.1..11.9), rng.random_range(-3.0..3.0));
            if planner.is_free(&p) {
                return p;
            }
        };
        for _ in 0..4 {
            let (start, goal) = (free(), free());
            match planner.plan(&start, &goal, &Termination::expansions(20_000)) {
                Err(CarError::NoPath { stop: Stop::Unreachable, .. }) => {
                    prop_assert!(!point_can_pass(&grid, cell_of(&start), cell_of(&goal)), "{start:?} -> {goal:?}");
                }
                Ok(plan) => prop_assert!(point_can_pass(&grid, cell_of(&start), cell_of(&goal)), "{:?}", plan.path),
                Err(CarError::NoPath { .. }) => {}
                Err(e) => prop_assert!(false, "{e}"),
            }
        }
    }
}

#[test]
fn coarse_cells_and_a_wide_turn_are_solved() {
    // A 200 m x 40 m strip of 10 m cells, a turning radius of 50 m and four headings: every
    // motion is a 78.5 m straight (no turn fits), so no state comes within the shots' default
    // 3 m of the goal; a shot from within four motions does.
    let grid = Grid::new(20, 4).unwrap();
    let settings = HybridOptions { turning_radius: 50.0, heading_bins: 4, ..HybridOptions::default() };
    let (start, goal) = (pose(15.0, 20.0, 0.0), pose(100.0, 20.0, 0.0));
    let plan = plan(&grid, 10.0, &Footprint::Radius(5.0), settings, (&start, &goal)).unwrap();
    let end = plan.path.end().unwrap();
    assert!((end.translation.vector - goal.translation.vector).norm() < 1e-6);
    assert!((plan.path.length() - 85.0).abs() < 1e-6);
}

#[test]
fn a_gap_a_million_times_dearer_is_still_shot_through() {
    // A wall across the yard at x = 3 m whose only gap costs a million times a free cell.
    let mut grid = Grid::new(60, 40).unwrap();
    for y in 0..40 {
        let cell = Cell::new(30, y);
        if (15..25).contains(&y) {
            grid.set_cost(cell, 1e6).unwrap();
        } else {
            grid.set_blocked(cell, true).unwrap();
        }
    }
    let settings = HybridOptions { turning_radius: 0.5, ..HybridOptions::default() };
    let (start, goal) = (pose(1.0, 2.0, 0.0), pose(5.0, 2.0, 0.0));
    let plan = plan(&grid, 0.1, &Footprint::Radius(0.2), settings, (&start, &goal)).unwrap();
    // Through the gap: its tenth of a metre is priced at about 1e5 (the poses checked there).
    assert!(plan.path.cost > 5e4, "{}", plan.path.cost);
}

#[test]
fn a_lattice_that_runs_out_proves_nothing() {
    // A closed corridor 1 m wide; forward only with a 2 m turning radius, the car cannot turn
    // round, though its reference point can reach the goal's place.
    let mut grid = Grid::new(80, 12).unwrap();
    for x in 0..80 {
        for y in [0, 1, 10, 11] {
            grid.set_blocked(Cell::new(x, y), true).unwrap();
        }
    }
    let settings =
        HybridOptions { turning_radius: 2.0, reverse: false, heading_bins: 16, ..HybridOptions::default() };
    let (start, goal) = (pose(1.0, 0.6, 0.0), pose(1.0, 0.6, std::f64::consts::PI));
    match plan(&grid, 0.1, &Footprint::Radius(0.2), settings, (&start, &goal)) {
        Err(CarError::NoPath { stop: Stop::LatticeExhausted, stats }) => assert!(stats.expansions > 0),
        other => panic!("expected the lattice exhausted, got {other:?}"),
    }
}

#[test]
fn a_footprint_ahead_of_its_reference_point_plans() {
    // A 1 m square 0.5 m ahead of the point planned (a forklift planned by its mast), the goal's
    // point 0.3 m from a wall behind it: the nearest edge (0.5 m) is no circle inside the robot.
    let mut grid = Grid::new(60, 40).unwrap();
    for y in 0..40 {
        grid.set_blocked(Cell::new(0, y), true).unwrap();
    }
    let car = Footprint::polygon(vec![[0.5, -0.5], [1.5, -0.5], [1.5, 0.5], [0.5, 0.5]]).unwrap();
    let settings = HybridOptions { turning_radius: 1.0, ..HybridOptions::default() };
    let (start, goal) = (pose(2.0, 2.0, 0.0), pose(0.4, 2.0, 0.0));
    let plan = plan(&grid, 0.1, &car, settings, (&start, &goal)).unwrap();
    assert!(plan.stats.expansions > 0);
    let end = plan.path.end().unwrap();
    assert!((end.translation.vector - goal.translation.vector).norm() < 1e-6);
}

#[test]
fn sharp_footprints_are_grown_by_the_margin_not_their_mitre() {
    // A thin triangle 1 m long with a 0.2-degree tip, in an empty 20 x 20 m world: its mitre
    // grown by the margin reached 33 m.
    let map = CarMap::from_grid(&Grid::new(200, 200).unwrap(), 0.1).unwrap();
    let thin = Footprint::polygon(vec![[-0.5, -0.0017], [0.5, 0.0], [-0.5, 0.0017]]).unwrap();
    let planner = HybridAStar::new(&map, &thin, HybridOptions::default()).unwrap();
    assert!(planner.is_free(&pose(10.0, 10.0, 0.3)));
    // A 10-degree corner whose tip is 0.2 m from the wall it faces.
    let corner = Footprint::polygon(vec![[-0.5, -0.0875], [0.5, 0.0], [-0.5, 0.0875]]).unwrap();
    let planner = HybridAStar::new(&map, &corner, HybridOptions::default()).unwrap();
    assert!(planner.is_free(&pose(19.3, 10.0, 0.0)));
    assert!(planner.is_free(&pose(10.0, 10.0, 1.0)));
}

#[test]
fn a_pose_free_but_within_the_margin_is_refused_naming_it() {
    let mut grid = Grid::new(60, 40).unwrap();
    for y in 0..40 {
        grid.set_blocked(Cell::new(30, y), true).unwrap();
    }
    let map = CarMap::from_grid(&grid, 0.1).unwrap();
    let planner = HybridAStar::new(&map, &Footprint::Radius(0.2), HybridOptions::default()).unwrap();
    let margin = planner.margin();
    assert!(margin > 0.005 && margin < 0.05, "{margin}");
    // The wall's face is at x = 3.0: a disc of 0.2 m at 2.795 is 5 mm from it.
    let near = pose(3.0 - 0.2 - 0.5 * margin, 2.0, 0.0);
    match planner.plan(&near, &pose(1.0, 2.0, 0.0), &Termination::unlimited()) {
        Err(CarError::WithinMargin { which: "start", margin: m, .. }) => assert_eq!(m, margin),
        other => panic!("expected the margin named, got {other:?}"),
    }
    let touching = pose(2.9, 2.0, 0.0);
    assert!(matches!(
        planner.plan(&touching, &pose(1.0, 2.0, 0.0), &Termination::unlimited()),
        Err(CarError::InCollision { which: "start", .. })
    ));
}

#[test]
fn a_walled_off_goal_is_proved_unreachable_for_every_footprint() {
    let mut grid = Grid::new(60, 40).unwrap();
    for y in 0..40 {
        grid.set_blocked(Cell::new(30, y), true).unwrap();
    }
    let square = Footprint::polygon(vec![[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]]).unwrap();
    for car in [Footprint::Radius(0.0), Footprint::Radius(0.2), square] {
        let settings = HybridOptions { heading_bins: 16, ..HybridOptions::default() };
        let found = plan(&grid, 0.1, &car, settings, (&pose(1.0, 1.0, 0.0), &pose(5.0, 1.0, 0.0)));
        assert!(matches!(found, Err(CarError::NoPath { stop: Stop::Unreachable, .. })), "{car:?}: {found:?}");
    }
}

#[test]
fn a_polygon_world_laid_on_cells_proves_nothing_unreachable() {
    use trailmark_core::geometry::Point;
    use trailmark_core::world::{Bounds, PolygonWorld};
    // A wall across a 10 x 10 world with a gap from y = 4.05 to 4.25, 1.6 cells of 0.125 wide:
    // both cells it touches are marked, so the cells close a gap a point passes.
    let square = |x0: f64, y0: f64, x1: f64, y1: f64| {
        vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
    };
    let walls = vec![square(4.9, 0.0, 5.1, 4.05), square(4.9, 4.25, 5.1, 10.0)];
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap(), walls, 0.0).unwrap();
    let map = CarMap::from_world(&world, 0.125).unwrap();
    assert!(!map.is_exact());
    let planner = HybridAStar::new(&map, &Footprint::Radius(0.0), HybridOptions::default()).unwrap();
    match planner.plan(&pose(2.0, 4.15, 0.0), &pose(8.0, 4.15, 0.0), &Termination::expansions(50_000)) {
        Err(CarError::NoPath { stop, .. }) => assert_eq!(stop, Stop::LatticeExhausted),
        Ok(plan) => panic!("a point passed a gap the cells close: {:?}", plan.path),
        Err(e) => panic!("{e}"),
    }
    // On a grid the same wall of cells is the obstacle itself: a proof.
    assert!(CarMap::from_grid(&Grid::new(4, 4).unwrap(), 1.0).unwrap().is_exact());
}
