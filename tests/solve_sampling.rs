//! Sampling planners through problem documents: `rrt`, `rrt_connect`, `rrt_star`,
//! `informed_rrt_star`, `bit_star`, `prm`, `prm_star`, `lazy_prm` and `lazy_prm_star` in R² and
//! Dubins over a polygon world, and in Rⁿ over a box world (robot arms: `solve_robot.rs`).
//! Paths start and end where asked, every leg is re-checked (exactly and every 1e-3 against
//! plain distances), no path beats the visibility graph's optimum, the same seed gives the same document (timings aside), smoothed
//! curves are free, and every kind of bad input gives its typed error.

use trailmark::core::curve::Bezier;
use trailmark::core::dubins::{DubinsPath, Piece};
use trailmark::core::geometry::{Point, Pose};
use trailmark::core::reeds_shepp::ReedsSheppPath;
use trailmark::core::world::PolygonWorld;
use trailmark::sample::{PlanError, SamplerError};
use trailmark::solve::{DocumentError, SolveError, solve, solve_and_draw};
use trailmark::solve::{Family, PlannerName, ProblemSpec, Status, WorldSpec};

/// Every sampling planner of the registry, by its document name.
fn sampling_planners() -> Vec<&'static str> {
    PlannerName::ALL.iter().filter(|p| p.family() == Family::Sampling).map(|p| p.name()).collect()
}

#[path = "support/results.rs"]
mod results;
use results::{states, without_times};

/// The wall world of the examples (a wall and a triangle, robot radius 0.3) with `rest`.
fn document(rest: &str) -> ProblemSpec {
    let json = format!(
        r#"{{"world": {{"polygons": {{"bounds": [0, 0, 10, 10],
             "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]], [[1.5, 4], [3, 3.5], [2.5, 6]]],
             "robot_radius": 0.3}}}}, {rest}}}"#
    );
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

fn world(problem: &ProblemSpec) -> &PolygonWorld {
    match &problem.world {
        WorldSpec::Polygons(world) => world,
        _ => panic!("not a polygon world"),
    }
}

/// The visibility graph's shortest path cost in the same world.
fn optimum(start: &str, goal: &str) -> f64 {
    let problem = document(&format!(
        r#""graph": "visibility", "start": {start}, "goal": {goal}, "planner": {{"name": "astar"}}"#
    ));
    solve(&problem, ".").unwrap().cost.unwrap()
}

/// Every point every 1e-3 along the segment is clear by plain distances.
fn sampled_clear(world: &PolygonWorld, a: Point, b: Point) -> bool {
    let n = ((b - a).norm() / 1e-3).ceil().max(1.0) as usize;
    (0..=n).all(|i| world.reference_is_clear(a + (b - a) * (i as f64 / n as f64), 1e-9))
}

/// The document without its timings, for comparing runs.

#[test]
fn r2_planners_give_valid_paths_no_shorter_than_the_optimum() {
    let best = optimum("[1, 1]", "[9, 1]");
    for planner in sampling_planners() {
        for simplify in [false, true] {
            for seed in 0..4 {
                let problem = document(&format!(
                    r#""seed": {seed}, "start": [1, 1], "goal": [9, 1],
                       "planner": {{"name": "{planner}", "max_iterations": 1000, "simplify": {simplify}}}"#
                ));
                let result = solve(&problem, ".").unwrap();
                assert_eq!(result.status, Status::Solved, "{planner} seed {seed}");
                let path: Vec<Point> = states(&result).iter().map(|c| Point::new(c[0], c[1])).collect();
                assert_eq!((path[0], path[path.len() - 1]), (Point::new(1.0, 1.0), Point::new(9.0, 1.0)));
                let checker = world(&problem).checker();
                for leg in path.windows(2) {
                    assert!(checker.segment_is_free(leg[0], leg[1]), "{planner}: {leg:?}");
                    assert!(sampled_clear(world(&problem), leg[0], leg[1]), "{planner}: {leg:?}");
                }
                let cost = result.cost.unwrap();
                let length: f64 = path.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
                assert!((cost - length).abs() <= 1e-9 * length);
                // The visibility graph goes around chords outside the grown corners (steps of
                // π/8): the true optimum is at most 1 / cos(π/16) below it.
                assert!(
                    cost >= best * (std::f64::consts::PI / 16.0).cos(),
                    "{planner}: {cost} < the optimum {best}"
                );
                let stats = result.stats.sampling.unwrap();
                assert!(cost <= stats.planned_cost.unwrap() + 1e-9, "simplifying never costs more");
                assert!(stats.iterations <= 1000 && stats.collision_checks > 0);
                let last = stats.improvements.last().unwrap().cost;
                assert!((last - stats.planned_cost.unwrap()).abs() <= 1e-9 * last);
            }
        }
    }
}

#[test]
fn the_same_seed_gives_the_same_document() {
    for planner in sampling_planners() {
        let run = |seed: u64| {
            let problem = document(&format!(
                r#""seed": {seed}, "start": [1, 1], "goal": [9, 1],
                   "planner": {{"name": "{planner}", "max_iterations": 1500, "simplify": true, "smooth": "bezier"}}"#
            ));
            without_times(solve(&problem, ".").unwrap())
        };
        assert_eq!(run(5), run(5), "{planner}");
        assert_ne!(run(5).path, run(6).path, "{planner}");
    }
}

#[test]
fn samplers_give_valid_reproducible_paths() {
    let samplers = [
        r#"{"name": "uniform"}"#,
        r#"{"name": "bridge", "std_dev": 1.0}"#,
        r#"{"name": "bridge", "std_dev": 0.5, "share": 1.0, "attempts": 10}"#,
        r#"{"name": "gaussian", "std_dev": 0.5, "share": 0.25}"#,
    ];
    for planner in sampling_planners() {
        let mut checks = Vec::new();
        for sampler in samplers {
            let problem = document(&format!(
                r#""seed": 4, "start": [1, 1], "goal": [9, 1],
                   "planner": {{"name": "{planner}", "max_iterations": 1500, "sampler": {sampler}}}"#
            ));
            let result = solve(&problem, ".").unwrap();
            assert_eq!(result.status, Status::Solved, "{planner} {sampler}");
            assert_eq!(without_times(result.clone()), without_times(solve(&problem, ".").unwrap()));
            let path: Vec<Point> = states(&result).iter().map(|c| Point::new(c[0], c[1])).collect();
            assert_eq!((path[0], path[path.len() - 1]), (Point::new(1.0, 1.0), Point::new(9.0, 1.0)));
            let checker = world(&problem).checker();
            assert!(path.windows(2).all(|leg| checker.segment_is_free(leg[0], leg[1])));
            checks.push(result.stats.sampling.unwrap().collision_checks);
        }
        // Every sample of the share-1 bridge costs state checks (at least one per try).
        assert!(checks[2] > checks[0], "{planner}: {checks:?}");
    }
}

/// In the spaces of car poses, the path chains free shortest curves (Dubins, or Reeds-Shepp with
/// pieces in reverse) of the turning radius, and costs their lengths.
#[test]
fn car_paths_chain_shortest_curves_of_the_turning_radius() {
    let radius = 0.6;
    for space in ["dubins", "reeds_shepp"] {
        let trees = r#""range": 2.0, "max_iterations": 20000"#;
        let settings = [
            ("rrt", trees),
            ("rrt_connect", trees),
            ("rrt_star", r#""range": 2.0, "max_iterations": 2000"#),
            ("informed_rrt_star", r#""range": 2.0, "max_iterations": 2000"#),
            ("bit_star", r#""max_iterations": 1000"#),
            // A roadmap joins each state to its nearest without a range.
            ("prm", r#""max_iterations": 2000"#),
            ("prm_star", r#""max_iterations": 1000"#),
            // Dubins is asymmetric: a lazy roadmap keys and drops each direction apart.
            ("lazy_prm", r#""max_iterations": 2000"#),
            ("lazy_prm_star", r#""max_iterations": 1000"#),
        ];
        for (planner, settings) in settings {
            let problem = document(&format!(
                r#""space": "{space}", "turning_radius": {radius}, "seed": 2,
                   "start": [1, 1, 1.25], "goal": [9, 1, -1.25],
                   "planner": {{"name": "{planner}", {settings}, "simplify": true}}"#
            ));
            let (result, svg) = solve_and_draw(&problem, ".").unwrap();
            assert_eq!(result.status, Status::Solved, "{space} {planner}");
            assert!(svg.contains("polyline"), "{space} {planner}: the picture draws the curves");
            let poses: Vec<Pose> =
                states(&result).iter().map(|c| Pose::new(Point::new(c[0], c[1]).coords, c[2])).collect();
            assert_eq!(states(&result)[0], vec![1.0, 1.0, 1.25]);
            assert_eq!(states(&result).last().unwrap(), &vec![9.0, 1.0, -1.25]);
            let checker = world(&problem).checker();
            let mut length = 0.0;
            for pair in poses.windows(2) {
                let (free, pieces, samples, piece_length) = if space == "dubins" {
                    let curve = DubinsPath::shortest(&pair[0], &pair[1], radius).unwrap();
                    (
                        checker.dubins_is_free(&curve),
                        curve.pieces().to_vec(),
                        curve.sample(1e-3).unwrap(),
                        curve.length(),
                    )
                } else {
                    let curve = ReedsSheppPath::shortest(&pair[0], &pair[1], radius).unwrap();
                    (
                        checker.reeds_shepp_is_free(&curve),
                        curve.pieces(),
                        curve.sample(1e-3).unwrap(),
                        curve.length(),
                    )
                };
                assert!(free, "{space} {planner}");
                for piece in pieces {
                    if let Piece::Arc { radius: r, .. } = piece {
                        assert!((r - radius).abs() <= 1e-12, "an arc of radius {r}");
                    }
                }
                for p in samples {
                    assert!(world(&problem).reference_is_clear(Point::from(p.translation.vector), 1e-9));
                }
                length += piece_length;
            }
            assert!((result.cost.unwrap() - length).abs() <= 1e-9 * length);
            assert!(length >= optimum("[1, 1]", "[9, 1]") * (std::f64::consts::PI / 16.0).cos());
        }
    }
}

#[test]
fn smoothed_paths_are_free_and_reported() {
    for method in ["hermite", "bezier", "bspline"] {
        let problem = document(&format!(
            r#""seed": 3, "start": [1, 1], "goal": [9, 1],
               "planner": {{"name": "rrt_connect", "simplify": true, "smooth": "{method}"}}"#
        ));
        let (result, svg) = solve_and_draw(&problem, ".").unwrap();
        let smoothed = result.stats.sampling.unwrap().smoothed.unwrap();
        assert_eq!(smoothed.method.name(), method);
        let pieces: Vec<Bezier> = smoothed
            .pieces
            .iter()
            .map(|c| Bezier::new(c.iter().map(|p| Point::new(p[0], p[1])).collect()).unwrap())
            .collect();
        assert_eq!(pieces[0].start(), Point::new(1.0, 1.0));
        assert_eq!(pieces.last().unwrap().end(), Point::new(9.0, 1.0));
        assert!(pieces.windows(2).all(|w| w[0].end() == w[1].start()));
        let checker = world(&problem).checker();
        for piece in &pieces {
            assert!(checker.bezier_is_free(piece));
            let samples = piece.sample(1e-3).unwrap();
            assert!(samples.iter().all(|&p| world(&problem).reference_is_clear(p, 1e-9)));
        }
        let length: f64 = pieces.iter().map(Bezier::length).sum();
        assert!((smoothed.length - length).abs() <= 1e-9 * length);
        assert!(svg.contains("<polyline"));
    }
}

#[test]
fn no_path_within_the_limit_is_approximate() {
    // The goal inside a closed box.
    let json = r#"{"world": {"polygons": {"bounds": [0, 0, 30, 30], "robot_radius": 0.2,
        "obstacles": [[[10, 10], [20, 10], [20, 11], [10, 11]], [[10, 19], [20, 19], [20, 20], [10, 20]],
                      [[10, 11], [11, 11], [11, 19], [10, 19]], [[19, 11], [20, 11], [20, 19], [19, 19]]]}},
        "seed": 1, "start": [2, 2], "goal": [15, 15], "planner": {"name": "rrt_connect", "max_iterations": 500}}"#;
    let problem: ProblemSpec = serde_json::from_str(json).unwrap();
    let result = solve(&problem, ".").unwrap();
    assert_eq!(result.status, Status::Approximate);
    assert_eq!(states(&result)[0], vec![2.0, 2.0]);
    assert!(result.stats.sampling.unwrap().goal_distance >= 5.2 - 1e-9);
}

/// RRT-Connect's connect phase is bounded: with a range of 1e-7 across the world one
/// iteration had run for minutes, past its iteration and time limits. Such a range is now
/// refused (below 1e-4 of the extent); at the smallest range taken, the limits hold.
#[test]
fn rrt_connect_with_a_tiny_range_keeps_its_limits() {
    let tiny = r#""start": [1, 1], "goal": [9, 9], "planner": {"name": "rrt_connect", "range": 1e-7, "max_iterations": 10}"#;
    let error = solve(&document(tiny), ".").expect_err("a range of 1e-8 of the extent");
    assert!(error.to_string().contains("range"), "{error}");
    for limits in [r#""max_iterations": 1"#, r#""max_iterations": 10000000, "time_limit_s": 0.2"#] {
        let clock = std::time::Instant::now();
        let doc = format!(
            r#""start": [1, 1], "goal": [9, 9], "planner": {{"name": "rrt_connect", "range": 0.0015, {limits}}}"#
        );
        let result = solve(&document(&doc), ".").unwrap();
        assert_ne!(result.status, Status::NoPath, "{limits}");
        assert!(clock.elapsed().as_secs() < 30, "{limits}: {:?}", clock.elapsed());
    }
}

/// No iteration at all: the approximate path is the start alone, at cost +0 (an empty float
/// sum had reported -0).
#[test]
fn a_path_of_one_state_costs_plus_zero() {
    let result = solve(
        &document(r#""start": [1, 1], "goal": [9, 1], "planner": {"name": "rrt", "max_iterations": 0}"#),
        ".",
    )
    .unwrap();
    assert_eq!(result.status, Status::Approximate);
    assert_eq!(result.path.len(), 1);
    let cost = result.cost.unwrap();
    assert!(cost == 0.0 && cost.is_sign_positive(), "{cost}");
}

#[test]
fn bad_sampling_documents_give_typed_errors() {
    let err = |rest: &str| solve(&document(rest), ".").unwrap_err();
    let ends = r#""start": [1, 1], "goal": [9, 1]"#;
    type Expected = fn(&SolveError) -> bool;
    let cases: Vec<(String, Expected)> = vec![
        (format!(r#"{ends}, "graph": "prm", "planner": {{"name": "rrt"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "graph", planner: "rrt" }))
        }),
        (format!(r#"{ends}, "space": "r2", "planner": {{"name": "astar"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "space", .. }))
        }),
        (format!(r#"{ends}, "turning_radius": 1, "planner": {{"name": "rrt"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForSpace { field: "turning_radius", space: "r2" }))
        }),
        (r#""space": "dubins", "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NoTurningRadius))
        }),
        (
            r#""space": "dubins", "turning_radius": 1, "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt", "smooth": "bezier"}"#.into(),
            |e| matches!(e, SolveError::Document(DocumentError::NotForSpace { field: "smooth", space: "dubins" })),
        ),
        (
            r#""space": "dubins", "turning_radius": -1, "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt"}"#.into(),
            |e| matches!(e, SolveError::Space(_)),
        ),
        (r#""start": [1, 1, 0], "goal": [9, 1], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NotAState { which: "start", space: "r2", .. }))
        }),
        (r#""space": "dubins", "turning_radius": 1, "start": [1, 1, 0], "goal": [9, 1], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NotAState { which: "goal", space: "dubins", .. }))
        }),
        (r#""space": "reeds_shepp", "turning_radius": 1, "start": [1, 1], "goal": [9, 1, 0], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NotAState { which: "start", space: "reeds_shepp", .. }))
        }),
        (r#""space": "reeds_shepp", "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NoTurningRadius))
        }),
        (
            r#""space": "reeds_shepp", "turning_radius": 0, "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt"}"#.into(),
            |e| matches!(e, SolveError::Space(_)),
        ),
        (
            r#""space": "reeds_shepp", "turning_radius": 1, "start": [1, 1, 0], "goal": [9, 1, 0], "planner": {"name": "rrt", "smooth": "hermite"}"#.into(),
            |e| matches!(e, SolveError::Document(DocumentError::NotForSpace { field: "smooth", space: "reeds_shepp" })),
        ),
        (format!(r#"{ends}, "planner": {{"name": "rrt", "range": -1}}"#), |e| {
            matches!(e, SolveError::Plan(PlanError::InvalidOption { name: "range", .. }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "rrt_star", "goal_bias": 2}}"#), |e| {
            matches!(e, SolveError::Plan(PlanError::InvalidOption { name: "goal_bias", .. }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "prm", "range": 1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "range", planner: "prm" }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "bit_star", "range": 1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "range", planner: "bit_star" }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "prm_star", "goal_bias": 0.1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "goal_bias", planner: "prm_star" }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "lazy_prm", "range": 1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "range", planner: "lazy_prm" }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "lazy_prm_star", "goal_bias": 0.1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForPlanner { field: "goal_bias", planner: "lazy_prm_star" }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "prm_star", "time_limit_s": -1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::TimeLimit(_)))
        }),
        (format!(r#"{ends}, "planner": {{"name": "rrt_connect", "time_limit_s": -1}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::TimeLimit(_)))
        }),
        (format!(r#"{ends}, "planner": {{"name": "rrt_star", "time_limit_s": 1e20}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::TimeLimit(_)))
        }),
        // Limits that ran without end: a year of time, 1e15 iterations, u32::MAX attempts.
        (format!(r#"{ends}, "planner": {{"name": "rrt_star", "time_limit_s": 3.2e7}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::TimeLimit(_)))
        }),
        (format!(r#"{ends}, "planner": {{"name": "rrt", "max_iterations": 1000000000000000}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::TooManyIterations(_)))
        }),
        (
            format!(r#"{ends}, "planner": {{"name": "rrt_connect", "sampler": {{"name": "bridge", "std_dev": 1, "attempts": 4294967295}}}}"#),
            |e| matches!(e, SolveError::Sampler(SamplerError::TooManyAttempts(_))),
        ),
        (r#""start": [5, 1], "goal": [9, 1], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Plan(PlanError::InvalidStart { .. }))
        }),
        (format!(r#"{ends}, "planner": {{"name": "rrt", "sampler": {{"name": "bridge", "std_dev": 0}}}}"#), |e| {
            matches!(e, SolveError::Sampler(SamplerError::StdDev(_)))
        }),
        (
            format!(r#"{ends}, "planner": {{"name": "rrt", "sampler": {{"name": "gaussian", "std_dev": 1, "share": 1.5}}}}"#),
            |e| matches!(e, SolveError::Sampler(SamplerError::Share(_))),
        ),
        (
            format!(r#"{ends}, "planner": {{"name": "rrt_star", "sampler": {{"name": "bridge", "std_dev": 1, "attempts": 0}}}}"#),
            |e| matches!(e, SolveError::Sampler(SamplerError::NoAttempts)),
        ),
    ];
    for (rest, expected) in cases {
        let e = err(&rest);
        assert!(expected(&e), "{rest}: {e:?}");
        assert!(!e.to_string().is_empty());
    }
    let grid: ProblemSpec = serde_json::from_str(
        r#"{"world": {"grid": {"rows": [".."]}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "rrt"}}"#,
    )
    .unwrap();
    assert!(matches!(
        solve(&grid, "."),
        Err(SolveError::Document(DocumentError::NeedsPolygons { planner: "rrt" }))
    ));
    let unknown = format!(
        r#"{{"world": {{"polygons": {{"bounds": [0, 0, 1, 1], "obstacles": []}}}}, {ends}, "planner": {{"name": "rrt", "weight": 2}}}}"#
    );
    assert!(serde_json::from_str::<ProblemSpec>(&unknown).is_err(), "a setting the planner does not take");
}

/// Turning radii far beyond the world (found by the fuzzer): with a radius of 4e210 the Dubins
/// solver's offset overflowed and a planner panicked; with 3.5e30 (and already 1e10) it called
/// two poses 1 apart, one behind the other, the same, and RRT* "solved" with the start alone.
/// Beyond a thousand diagonals of the bounds the radius is refused, for the sampling planners
/// and the Dubins roadmap alike; a thousand diagonals still plans.
#[test]
fn turning_radii_far_beyond_the_world_are_refused() {
    let query = r#""start": [2.25, 2.25, 0], "goal": [1.25, 2.25, 0]"#;
    for radius in ["1e10", "3.529604902711434e30", "4.0201702141332154e210"] {
        for rest in [
            r#""space": "dubins", "planner": {"name": "rrt_star", "max_iterations": 200}"#,
            r#""graph": "dubins_prm", "samples": 50, "planner": {"name": "astar"}"#,
        ] {
            let problem = document(&format!(r#"{query}, "turning_radius": {radius}, {rest}"#));
            let error = solve(&problem, ".").expect_err(rest);
            assert!(error.to_string().contains("outside the supported range"), "{radius}, {rest}: {error}");
        }
    }
    let problem = document(&format!(
        r#"{query}, "turning_radius": 14000, "space": "dubins", "planner": {{"name": "rrt", "max_iterations": 10}}"#
    ));
    let result = solve(&problem, ".").unwrap();
    assert_ne!(result.status, Status::Solved, "a loop of 88,000 in a world of 10");
}

/// `"graph": "prm"` over a box world: a PRM* roadmap of the asked samples, searched by the
/// problem's graph planner; the path goes over the slab, and Dijkstra and A* agree on its cost.
#[test]
fn box_worlds_take_a_prm_roadmap_and_every_graph_search() {
    let mut costs = Vec::new();
    for (planner, sampler) in [("astar", "uniform"), ("dijkstra", "uniform"), ("astar", "halton")] {
        let problem = box_document(&format!(
            r#""graph": "prm", "samples": 1500, "sampler": "{sampler}", "seed": 3,
               "start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 0.1], "planner": {{"name": "{planner}"}}"#
        ));
        let result = solve(&problem, ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{planner}, {sampler}");
        let graph = result.stats.graph.as_ref().unwrap();
        assert_eq!(graph.nodes, 1500);
        let path = states(&result);
        for p in &path {
            assert!(!(p[0] > 0.4 && p[0] < 0.6 && p[2] < 0.8), "{p:?} in the slab");
        }
        let length: f64 =
            path.windows(2).map(|m| (0..3).map(|i| (m[1][i] - m[0][i]).powi(2)).sum::<f64>().sqrt()).sum();
        assert!((result.cost.unwrap() - length).abs() < 1e-9);
        assert!(length >= 0.3 + 2.0 * (0.1f64.powi(2) + 0.7f64.powi(2)).sqrt() - 1e-9, "{length}");
        costs.push(length);
    }
    assert!((costs[0] - costs[1]).abs() < 1e-9, "A* and Dijkstra on one roadmap: {costs:?}");
}

/// A 3-D box world: the unit cube with a slab across it, open above z = 0.8.
fn box_document(rest: &str) -> ProblemSpec {
    let json = format!(
        r#"{{"world": {{"boxes": {{"bounds": [[0, 1], [0, 1], [0, 1]],
             "obstacles": [[[0.4, 0, 0], [0.6, 1, 0.8]]]}}}}, {rest}}}"#
    );
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{e}: {json}"))
}

#[test]
fn box_worlds_in_rn_for_every_sampling_planner() {
    for planner in sampling_planners() {
        let problem = box_document(&format!(
            r#""space": "rn", "seed": 2, "start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 0.1],
               "planner": {{"name": "{planner}", "max_iterations": 3000, "simplify": true}}"#
        ));
        let result = solve(&problem, ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{planner}");
        let path = states(&result);
        assert_eq!(
            (path[0].as_slice(), path[path.len() - 1].as_slice()),
            ([0.1, 0.5, 0.1].as_slice(), [0.9, 0.5, 0.1].as_slice())
        );
        // Over the slab: every sample of every leg outside it, every 1e-3.
        let mut length = 0.0;
        for m in path.windows(2) {
            let d: f64 = (0..3).map(|i| (m[1][i] - m[0][i]).powi(2)).sum::<f64>().sqrt();
            let n = (d / 1e-3).ceil().max(1.0) as usize;
            for k in 0..=n {
                let q: Vec<f64> =
                    (0..3).map(|i| m[0][i] + (m[1][i] - m[0][i]) * k as f64 / n as f64).collect();
                assert!(!(q[0] > 0.4 && q[0] < 0.6 && q[2] < 0.8), "{planner}: {q:?} in the slab");
            }
            length += d;
        }
        assert!((result.cost.unwrap() - length).abs() < 1e-9);
        assert!(length >= 0.3 + 2.0 * (0.1f64.powi(2) + 0.7f64.powi(2)).sqrt() - 1e-9, "{planner}: {length}");
        // The same seed gives the same document.
        assert_eq!(without_times(result), without_times(solve(&problem, ".").unwrap()));
    }
}

#[test]
fn bad_box_documents_are_typed_errors() {
    let ends = r#""start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 0.1]"#;
    type Expected = fn(&SolveError) -> bool;
    let cases: Vec<(String, Expected)> = vec![
        (format!(r#"{ends}, "graph": "visibility", "planner": {{"name": "astar"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::InvalidBoxes(_)))
        }),
        (format!(r#"{ends}, "graph": "prm", "k": 5, "radius": 1, "planner": {{"name": "astar"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::KAndRadius))
        }),
        (format!(r#"{ends}, "turning_radius": 1, "planner": {{"name": "dijkstra"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForGraph { .. }))
        }),
        (r#""start": [0.5, 0.5, 0.5], "goal": [0.9, 0.5, 0.1], "graph": "prm", "planner": {"name": "astar"}"#.into(), |e| {
            matches!(e, SolveError::Plan(PlanError::InvalidStart { .. }))
        }),
        (format!(r#"{ends}, "space": "r2", "planner": {{"name": "rrt"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::InvalidBoxes(_)))
        }),
        (r#""start": [0.1, 0.5], "goal": [0.9, 0.5, 0.1], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Document(DocumentError::NotAState { which: "start", .. }))
        }),
        (r#""start": [0.5, 0.5, 0.5], "goal": [0.9, 0.5, 0.1], "planner": {"name": "rrt"}"#.into(), |e| {
            matches!(e, SolveError::Plan(PlanError::InvalidStart { .. }))
        }),
        (
            r#""start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 7], "planner": {"name": "rrt_connect"}"#.into(),
            |e| matches!(e, SolveError::Plan(PlanError::InvalidGoal(_))),
        ),
        (format!(r#"{ends}, "planner": {{"name": "rrt", "smooth": "bspline"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::NotForSpace { .. }))
        }),
        // A car's space with its turning radius: the space is at fault, not the radius.
        (format!(r#"{ends}, "space": "reeds_shepp", "turning_radius": 1, "planner": {{"name": "rrt"}}"#), |e| {
            matches!(e, SolveError::Document(DocumentError::InvalidBoxes(why)) if why.contains("reeds_shepp"))
        }),
    ];
    for (rest, expected) in cases {
        let error = solve(&box_document(&rest), ".").unwrap_err();
        assert!(expected(&error), "{rest}: {error}");
    }
    // Nine axes, a box of the wrong dimension, a box with low >= high.
    let nine = serde_json::from_str::<ProblemSpec>(
        r#"{"world": {"boxes": {"bounds": [[0,1],[0,1],[0,1],[0,1],[0,1],[0,1],[0,1],[0,1],[0,1]]}},
            "start": [0,0,0,0,0,0,0,0,0], "goal": [1,1,1,1,1,1,1,1,1], "planner": {"name": "rrt"}}"#,
    )
    .unwrap();
    assert!(matches!(solve(&nine, "."), Err(SolveError::Document(DocumentError::InvalidBoxes(_)))));
    for obstacles in [r#"[[[0.4, 0], [0.6, 1]]]"#, r#"[[[0.6, 0, 0], [0.4, 1, 1]]]"#] {
        let json = format!(
            r#"{{"world": {{"boxes": {{"bounds": [[0, 1], [0, 1], [0, 1]], "obstacles": {obstacles}}}}},
                "start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 0.1], "planner": {{"name": "rrt"}}}}"#
        );
        let problem: ProblemSpec = serde_json::from_str(&json).unwrap();
        assert!(solve(&problem, ".").is_err(), "{obstacles}");
    }
    // An inverted box is named as a box; bounds too large for a diagonal as bounds, not as the
    // planner's range.
    let named = |bounds: &str, obstacles: &str| {
        let json = format!(
            r#"{{"world": {{"boxes": {{"bounds": {bounds}, "obstacles": {obstacles}}}}},
                "start": [0.1, 0.5, 0.1], "goal": [0.9, 0.5, 0.1], "planner": {{"name": "rrt"}}}}"#
        );
        solve(&serde_json::from_str::<ProblemSpec>(&json).unwrap(), ".").unwrap_err().to_string()
    };
    let inverted = named("[[0, 1], [0, 1], [0, 1]]", r#"[[[0.6, 0, 0], [0.4, 1, 1]]]"#);
    assert!(inverted.contains("obstacle box 0, axis 0"), "{inverted}");
    let huge = named("[[-1e300, 1e300], [-1e300, 1e300], [-1e300, 1e300]]", "[]");
    assert!(huge.contains("bounds are too large") && !huge.contains("range"), "{huge}");
    // "space": "rn" over polygons, and no picture of a box world.
    let polygons = document(r#""space": "rn", "start": [1, 1], "goal": [9, 1], "planner": {"name": "rrt"}"#);
    assert!(matches!(solve(&polygons, "."), Err(SolveError::Document(DocumentError::RnNeedsBoxes))));
    let boxes = box_document(&format!(r#"{ends}, "planner": {{"name": "rrt"}}"#));
    assert!(matches!(
        solve_and_draw(&boxes, "."),
        Err(SolveError::Document(DocumentError::Undrawable("box")))
    ));
}
