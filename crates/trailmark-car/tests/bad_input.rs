//! Bad input gets a typed error naming what was wrong, and the planner stays usable.

use trailmark_car::{CarError, CarMap, HybridAStar, HybridOptions};
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::grid::Grid;
use trailmark_core::termination::{Stop, Termination};
use trailmark_core::world::{Polygon, PolygonError};

fn yard() -> CarMap {
    CarMap::from_grid(&Grid::new(60, 40).unwrap(), 0.1).unwrap()
}

fn pose(x: f64, y: f64, h: f64) -> Pose {
    Pose::new(nalgebra::Vector2::new(x, y), h)
}

fn setting_error(settings: HybridOptions) -> &'static str {
    let map = yard();
    match HybridAStar::new(&map, &Footprint::Radius(0.2), settings) {
        Err(CarError::Setting { setting, .. }) => setting,
        other => panic!("expected a setting error, got {other:?}"),
    }
}

#[test]
fn turning_radii_out_of_range_are_errors() {
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY, 0.01, 1e9] {
        let settings = HybridOptions { turning_radius: r, ..HybridOptions::default() };
        assert_eq!(setting_error(settings), "turning_radius", "radius {r}");
    }
}

#[test]
fn a_wide_turn_in_few_bins_is_refused_before_its_poses_are_laid_out() {
    // A turning radius of a million cells with four bins: a quarter circle of 1.6 million cells,
    // 3 million poses a motion (600 MB) had been laid out.
    let map = CarMap::from_grid(&Grid::new(4, 4).unwrap(), 1.0).unwrap();
    let wide = HybridOptions { turning_radius: 1e6, heading_bins: 4, ..HybridOptions::default() };
    match HybridAStar::new(&map, &Footprint::Radius(0.0), wide) {
        Err(CarError::Setting { setting: "heading_bins", value, .. }) => assert_eq!(value, 4.0),
        other => panic!("{other:?}"),
    }
    // Enough bins for the radius: 2 pi 1e6 / 32768 = 192.
    let enough = HybridOptions { heading_bins: 192, ..wide };
    assert!(HybridAStar::new(&map, &Footprint::Radius(0.0), enough).is_ok());
}

#[test]
fn heading_bins_out_of_range_are_errors() {
    for bins in [0, 1, 3, 1441, u32::MAX] {
        let settings = HybridOptions { heading_bins: bins, ..HybridOptions::default() };
        assert_eq!(setting_error(settings), "heading_bins", "bins {bins}");
    }
}

#[test]
fn penalties_out_of_range_are_errors() {
    let base = HybridOptions::default();
    assert_eq!(setting_error(HybridOptions { reverse_penalty: 0.5, ..base }), "reverse_penalty");
    assert_eq!(
        setting_error(HybridOptions { non_straight_penalty: f64::NAN, ..base }),
        "non_straight_penalty"
    );
    assert_eq!(setting_error(HybridOptions { gear_change_penalty: -1.0, ..base }), "gear_change_penalty");
    assert_eq!(
        setting_error(HybridOptions { analytic_expansion_ratio: 0.0, ..base }),
        "analytic_expansion_ratio"
    );
    let max = HybridOptions { analytic_expansion_max_length: f64::INFINITY, ..base };
    assert_eq!(setting_error(max), "analytic_expansion_max_length");
}

#[test]
fn footprints_that_are_not_simple_polygons_or_bad_discs_are_errors() {
    let bow = vec![Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0)];
    assert!(matches!(Polygon::new(bow), Err(PolygonError::SelfIntersecting { .. })));
    let line = vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(2.0, 0.0)];
    assert!(matches!(Polygon::new(line), Err(PolygonError::ZeroArea)));
    let map = yard();
    for r in [-0.1, f64::NAN] {
        let made = HybridAStar::new(&map, &Footprint::Radius(r), HybridOptions::default());
        assert!(matches!(made, Err(CarError::Footprint(_))), "radius {r}");
    }
    // In a document, a polygon footprint is checked as it is read.
    let doc = r#"{"polygon": [[0, 0], [1, 1], [1, 0], [0, 1]]}"#;
    assert!(serde_json::from_str::<Footprint>(doc).is_err());
}

#[test]
fn poses_with_non_finite_values_or_in_collision_are_errors_and_the_planner_goes_on() {
    let mut grid = Grid::new(60, 40).unwrap();
    grid.set_blocked(trailmark_core::grid::Cell::new(30, 20), true).unwrap();
    let map = CarMap::from_grid(&grid, 0.1).unwrap();
    let planner = HybridAStar::new(&map, &Footprint::Radius(0.2), HybridOptions::default()).unwrap();
    let ok = pose(1.0, 1.0, 0.0);
    let never = Termination::unlimited();
    for bad in [pose(f64::NAN, 1.0, 0.0), pose(1.0, f64::INFINITY, 0.0), pose(1.0, 1.0, f64::NAN)] {
        assert!(matches!(planner.plan(&bad, &ok, &never), Err(CarError::Pose { which: "start", .. })));
        assert!(matches!(planner.plan(&ok, &bad, &never), Err(CarError::Pose { which: "goal", .. })));
    }
    // The blocked cell's centre (3.05, 1.95 from the bottom... row 20 of 40 is y in 1.9..2.0).
    let on_wall = pose(3.05, 1.95, 0.0);
    assert!(matches!(planner.plan(&on_wall, &ok, &never), Err(CarError::InCollision { which: "start", .. })));
    let off_map = pose(-1.0, 1.0, 0.0);
    assert!(matches!(planner.plan(&ok, &off_map, &never), Err(CarError::InCollision { which: "goal", .. })));
    // Far off the map, where a cell index would overflow; a polygon footprint too.
    let car = Footprint::Polygon(
        Polygon::new(vec![
            Point::new(-0.1, -0.1),
            Point::new(0.3, -0.1),
            Point::new(0.3, 0.1),
            Point::new(-0.1, 0.1),
        ])
        .unwrap(),
    );
    let boxy = HybridAStar::new(&map, &car, HybridOptions::default()).unwrap();
    for far in [pose(1e308, -4.9e237, 3.9), pose(-1e300, 1e300, 0.0), pose(9e18, 9e18, 1.0)] {
        for p in [&planner, &boxy] {
            assert!(matches!(p.plan(&far, &ok, &never), Err(CarError::InCollision { which: "start", .. })));
            assert!(!p.is_free(&far));
        }
    }
    // Still usable.
    let plan = planner.plan(&ok, &pose(5.0, 3.0, 1.0), &never).unwrap();
    assert!(plan.path.length() > 4.0);
}

#[test]
fn a_goal_walled_off_is_reported_unreachable() {
    // A wall across the whole yard at x = 3 m.
    let mut grid = Grid::new(60, 40).unwrap();
    for y in 0..40 {
        grid.set_blocked(trailmark_core::grid::Cell::new(30, y), true).unwrap();
    }
    let map = CarMap::from_grid(&grid, 0.1).unwrap();
    let settings = HybridOptions { heading_bins: 16, ..HybridOptions::default() };
    let planner = HybridAStar::new(&map, &Footprint::Radius(0.2), settings).unwrap();
    let found = planner.plan(&pose(1.0, 1.0, 0.0), &pose(5.0, 1.0, 0.0), &Termination::unlimited());
    assert!(matches!(found, Err(CarError::NoPath { stop: Stop::Unreachable, .. })), "{found:?}");
}

#[test]
fn a_budget_stops_the_search_and_says_so() {
    let map = CarMap::from_grid(&Grid::new(200, 40).unwrap(), 0.1).unwrap();
    let planner = HybridAStar::new(&map, &Footprint::Radius(0.2), HybridOptions::default()).unwrap();
    let (start, goal) = (pose(1.0, 1.0, 0.0), pose(19.0, 3.0, std::f64::consts::PI));
    let found = planner.plan(&start, &goal, &Termination::expansions(10));
    assert!(matches!(found, Err(CarError::NoPath { stop: Stop::ExpansionLimit, .. })), "{found:?}");
    // The limit holds exactly, down to none.
    for limit in [0, 1, 10] {
        match planner.plan(&start, &goal, &Termination::expansions(limit)) {
            Err(CarError::NoPath { stop: Stop::ExpansionLimit, stats }) => {
                assert_eq!(stats.expansions, limit)
            }
            other => panic!("{limit}: {other:?}"),
        }
    }
    assert!(planner.plan(&start, &goal, &Termination::unlimited()).is_ok());
}
