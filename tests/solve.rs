//! Solving problem documents: every planner on a known grid, and every kind of bad input giving
//! its typed error; random documents never panic.

use proptest::prelude::*;
use trailmark::solve::{AnytimeSpec, GridSpec, PlannerSpec, ProblemSpec, Status, Waypoint, WorldSpec};
use trailmark::solve::{DocumentError, SolveError, solve};

fn problem(rows: &[&str], start: Vec<f64>, goal: Vec<f64>, planner: PlannerSpec) -> ProblemSpec {
    let world = WorldSpec::Grid(GridSpec {
        rows: Some(rows.iter().map(|r| r.to_string()).collect()),
        ..Default::default()
    });
    ProblemSpec::new(world, start, goal, planner)
}

const ROWS: [&str; 3] = ["....", ".@@.", "...."];

fn planners() -> Vec<PlannerSpec> {
    vec![
        PlannerSpec::Bfs {},
        PlannerSpec::Dfs {},
        PlannerSpec::Dijkstra {},
        PlannerSpec::AStar { heuristic: None },
        PlannerSpec::WeightedAStar { weight: 2.0, heuristic: None },
        PlannerSpec::LpaStar { heuristic: None },
        PlannerSpec::DStarLite { heuristic: None },
        PlannerSpec::AdaptiveAStar { heuristic: None },
        PlannerSpec::MpgaaStar { heuristic: None },
        PlannerSpec::Jps {},
        PlannerSpec::JpsPlus {},
        anytime(false, None, None),
        anytime(true, None, None),
    ]
}

/// ARA* (`backward` false) or AD* with a schedule and default limits.
fn anytime(backward: bool, epsilon: Option<f64>, epsilon_step: Option<f64>) -> PlannerSpec {
    let spec = AnytimeSpec { epsilon, epsilon_step, ..AnytimeSpec::default() };
    if backward { PlannerSpec::AdStar(spec) } else { PlannerSpec::AraStar(spec) }
}

/// On a static world the anytime planners end at epsilon = 1 with the optimal cost, and report
/// each iteration within its bound.
#[test]
fn anytime_planners_report_their_iterations() {
    let rows = ["..........", ".@@@@@@@@.", "........@.", ".@@@@@@.@.", "..........", "@@@@@@@@.@"];
    let optimum = solve(&problem(&rows, vec![3.0, 2.0], vec![8.0, 5.0], PlannerSpec::Dijkstra {}), ".")
        .unwrap()
        .cost
        .unwrap();
    for backward in [false, true] {
        let planner = anytime(backward, Some(2.5), Some(0.5));
        let result = solve(&problem(&rows, vec![3.0, 2.0], vec![8.0, 5.0], planner), ".").unwrap();
        assert_eq!(result.cost, Some(optimum));
        let iterations = result.stats.iterations.expect("anytime planners list their iterations");
        assert_eq!(iterations[0].epsilon, 2.5);
        assert_eq!(iterations.last().unwrap().bound, 1.0);
        assert_eq!(result.stats.bound, Some(1.0));
        for it in iterations {
            assert!(it.cost.unwrap() <= it.bound * optimum + 1e-9);
        }
    }
}

#[test]
fn every_planner_solves_the_wall() {
    for planner in planners() {
        let result = solve(&problem(&ROWS, vec![0.0, 0.0], vec![3.0, 2.0], planner.clone()), ".").unwrap();
        assert_eq!(result.status, Status::Solved, "{planner:?}");
        assert_eq!(result.path.first(), Some(&Waypoint::Cell([0, 0].into())));
        assert_eq!(result.path.last(), Some(&Waypoint::Cell([3, 2].into())));
        assert!(result.stats.expansions.is_some());
        if !matches!(planner, PlannerSpec::Dfs {}) {
            // Around the wall without clipping its corners: 5 moves of length 1.
            assert_eq!(result.cost, Some(5.0), "{planner:?}");
        }
    }
}

#[test]
fn no_path_is_a_result_not_an_error() {
    let rows = [".@.", ".@.", ".@."];
    for planner in planners() {
        let result = solve(&problem(&rows, vec![0.0, 0.0], vec![2.0, 2.0], planner), ".").unwrap();
        assert_eq!((result.status, result.cost, result.path.len()), (Status::NoPath, None, 0));
    }
}

#[test]
fn bad_input_gives_typed_errors() {
    let astar = PlannerSpec::AStar { heuristic: None };
    let err = |p: ProblemSpec| solve(&p, ".").unwrap_err();
    assert!(matches!(
        err(problem(&ROWS, vec![1.0, 1.0], vec![0.0, 0.0], astar.clone())),
        SolveError::Document(DocumentError::Blocked { which: "start", .. })
    ));
    assert!(matches!(
        err(problem(&ROWS, vec![0.0, 0.0], vec![9.0, 0.0], astar.clone())),
        SolveError::Document(DocumentError::Outside { which: "goal", .. })
    ));
    for bad in [vec![0.5, 0.0], vec![-1.0, 0.0], vec![0.0], vec![0.0, 0.0, 0.0], vec![f64::NAN, 0.0]] {
        assert!(matches!(
            err(problem(&ROWS, bad, vec![0.0, 0.0], astar.clone())),
            SolveError::Document(DocumentError::NotACell { .. })
        ));
    }
    let weight = PlannerSpec::WeightedAStar { weight: 0.5, heuristic: None };
    assert!(matches!(err(problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], weight)), SolveError::Search(_)));
    let manhattan = PlannerSpec::AStar { heuristic: Some(trailmark::prelude::GridHeuristic::Manhattan) };
    assert!(matches!(
        err(problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], manhattan)),
        SolveError::Document(DocumentError::Inadmissible { .. })
    ));
    assert!(matches!(
        err(problem(&["..", "."], vec![0.0, 0.0], vec![1.0, 0.0], astar.clone())),
        SolveError::Grid(_)
    ));

    let with = |edit: &dyn Fn(&mut GridSpec)| {
        let mut p = problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], PlannerSpec::AStar { heuristic: None });
        let WorldSpec::Grid(world) = &mut p.world else { unreachable!() };
        edit(world);
        p
    };
    let both = with(&|w| w.map = Some("missing.map".into()));
    assert!(matches!(err(both), SolveError::Document(DocumentError::GridSource)), "map and rows together");
    let missing = with(&|w| {
        w.map = Some("missing.map".into());
        w.rows = None;
    });
    let message = err(missing).to_string();
    assert!(message.contains("missing.map"), "{message}");
    let short = with(&|w| w.costs = Some(vec![vec![1.0; 4], vec![1.0; 4]]));
    assert!(matches!(err(short), SolveError::Document(DocumentError::CostsShape { row: 2, .. })));
    let negative = with(&|w| w.costs = Some(vec![vec![1.0; 4], vec![1.0; 4], vec![1.0, -2.0, 1.0, 1.0]]));
    assert!(matches!(err(negative), SolveError::Grid(_)));

    // Jump point search: 8-connected grids of uniform cost only.
    for jumps in [PlannerSpec::Jps {}, PlannerSpec::JpsPlus {}] {
        let mut four = problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], jumps.clone());
        let WorldSpec::Grid(world) = &mut four.world else { unreachable!() };
        world.connectivity = trailmark::prelude::Connectivity::Four;
        assert!(matches!(
            err(four),
            SolveError::Document(DocumentError::NeedsEightConnectedGrid { planner }) if planner == jumps.name()
        ));
        let mut costly = problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], jumps.clone());
        let WorldSpec::Grid(world) = &mut costly.world else { unreachable!() };
        world.costs = Some(vec![vec![1.0; 4], vec![1.0; 4], vec![1.0, 2.0, 1.0, 1.0]]);
        assert!(matches!(
            err(costly),
            SolveError::Search(trailmark::search::SearchError::NonUniformCost { cell: Waypoint::Cell(c), .. })
                if c == [1, 2].into()
        ));
    }

    for backward in [false, true] {
        let low = anytime(backward, Some(0.5), None);
        assert!(matches!(err(problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], low)), SolveError::Search(_)));
        let mut late = anytime(backward, None, None);
        match &mut late {
            PlannerSpec::AraStar(spec) | PlannerSpec::AdStar(spec) => spec.time_limit_s = Some(-1.0),
            _ => unreachable!(),
        }
        assert!(matches!(
            err(problem(&ROWS, vec![0.0, 0.0], vec![3.0, 0.0], late)),
            SolveError::Document(DocumentError::TimeLimit(_))
        ));
    }
}

/// A limit that stops an anytime planner before it finds a path proves nothing about the goal:
/// the status is "stopped", never "no_path" (which says the goal is unreachable), whether the
/// goal is reachable or not.
#[test]
fn anytime_planners_stopped_by_a_limit_say_stopped() {
    let walled = [".@.", ".@.", ".@."];
    for name in ["ara_star", "ad_star"] {
        for limit in [r#""time_limit_s": 0"#, r#""max_expansions": 0"#] {
            let json = format!(r#"{{"name": "{name}", {limit}}}"#);
            let planner: PlannerSpec = serde_json::from_str(&json).unwrap();
            for (rows, goal) in [(&ROWS[..], vec![3.0, 2.0]), (&walled[..], vec![2.0, 2.0])] {
                let result = solve(&problem(rows, vec![0.0, 0.0], goal, planner.clone()), ".").unwrap();
                let document = serde_json::to_value(&result).unwrap();
                assert_eq!(document["status"], "stopped", "{json}: {document}");
                assert_eq!((result.cost, result.path.len()), (None, 0), "{json}");
            }
        }
    }
}

/// Cell costs of 8e307: the goal, three moves away, is reachable, but the cost of the way there
/// exceeds what an `f64` holds. Every planner gives a typed error (the grid refuses such costs,
/// or the search reports the overflow) instead of answering "no_path" or an infinite cost.
#[test]
fn path_costs_past_f64_max_are_errors() {
    use trailmark::search::SearchError;
    for planner in planners() {
        let mut p = problem(&["...."], vec![0.0, 0.0], vec![3.0, 0.0], planner.clone());
        let WorldSpec::Grid(world) = &mut p.world else { unreachable!() };
        world.costs = Some(vec![vec![8e307; 4]]);
        let result = solve(&p, ".");
        assert!(
            matches!(result, Err(SolveError::Grid(_) | SolveError::Search(SearchError::CostOverflow { .. }))),
            "{planner:?}: {result:?}"
        );
    }
}

/// The new planners' names, as a user writes them.
#[test]
fn incremental_and_anytime_planners_parse_from_json() {
    for (json, name) in [
        (r#"{"name": "lpa_star"}"#, "LpaStar"),
        (r#"{"name": "dstar_lite"}"#, "DStarLite"),
        (r#"{"name": "adaptive_astar"}"#, "AdaptiveAStar"),
        (r#"{"name": "mpgaa_star"}"#, "MpgaaStar"),
        (r#"{"name": "ara_star", "epsilon": 3.0, "epsilon_step": 0.5}"#, "AraStar"),
        (r#"{"name": "ad_star", "epsilon": 2.0, "max_expansions": 100}"#, "AdStar"),
    ] {
        let planner: PlannerSpec = serde_json::from_str(json).unwrap();
        assert!(format!("{planner:?}").starts_with(name), "{json}");
    }
    assert!(serde_json::from_str::<PlannerSpec>(r#"{"name": "ara_star", "weight": 2}"#).is_err());
}

#[test]
fn costs_change_the_route() {
    // The bottom route is cheaper unless its cells cost 10.
    let rows = ["...", ".@.", "..."];
    let mut p = problem(&rows, vec![0.0, 1.0], vec![2.0, 1.0], PlannerSpec::Dijkstra {});
    let WorldSpec::Grid(world) = &mut p.world else { unreachable!() };
    world.costs = Some(vec![vec![1.0; 3], vec![1.0; 3], vec![10.0; 3]]);
    let result = solve(&p, ".").unwrap();
    assert!(result.path.contains(&Waypoint::Cell([1, 0].into())), "{:?}", result.path);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random rows, costs, endpoints and planners: a result or a typed error, never a panic.
    #[test]
    fn random_documents_never_panic(
        rows in prop::collection::vec("[.@GSTWOx]{0,6}", 0..6),
        costs in prop::option::of(prop::collection::vec(prop::collection::vec(
            prop_oneof![Just(f64::NAN), Just(-1.0), Just(0.0), 0.1f64..5.0], 0..6), 0..6)),
        start in prop::collection::vec(prop_oneof![Just(f64::NAN), -2.0f64..8.0, 0.0f64..8.0], 0..4),
        goal in prop::collection::vec(0u32..8, 2).prop_map(|v| v.iter().map(|&x| f64::from(x)).collect::<Vec<_>>()),
        which in 0usize..11,
        weight in prop_oneof![Just(f64::NAN), -1.0f64..4.0],
        eight in any::<bool>(),
        cut in any::<bool>(),
    ) {
        let planner = match which {
            0 => PlannerSpec::Bfs {},
            1 => PlannerSpec::Dfs {},
            2 => PlannerSpec::Dijkstra {},
            3 => PlannerSpec::AStar { heuristic: None },
            4 => PlannerSpec::WeightedAStar { weight, heuristic: None },
            5 => PlannerSpec::LpaStar { heuristic: None },
            6 => PlannerSpec::DStarLite { heuristic: None },
            7 => anytime(false, Some(weight), Some(0.5)),
            8 => PlannerSpec::Jps {},
            9 => PlannerSpec::JpsPlus {},
            _ => anytime(true, Some(weight), Some(0.5)),
        };
        let world = GridSpec {
            rows: Some(rows),
            costs,
            connectivity: if eight { trailmark::prelude::Connectivity::Eight } else { trailmark::prelude::Connectivity::Four },
            corner_cutting: cut,
            ..Default::default()
        };
        let p = ProblemSpec::new(WorldSpec::Grid(world), start, goal, planner);
        if let Ok(result) = solve(&p, ".") {
            prop_assert_eq!(result.cost.is_some(), result.status == Status::Solved);
        }
    }
}
