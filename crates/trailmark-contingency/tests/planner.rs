//! The planner against things it did not compute itself: the exhaustive reference solver on the
//! grid, every world driven one by one, Monte Carlo sampling, D* Lite replanning, and A* on the
//! grid for the abstraction.

use proptest::prelude::*;
use trailmark_contingency::detect::{DetectOptions, detect};
use trailmark_contingency::generate::{RiverOptions, river_terrain};
use trailmark_contingency::plan::worlds;
use trailmark_contingency::reference::Reference;
use trailmark_contingency::simulate::{monte_carlo, naive_expected_cost, naive_expected_cost_by_worlds};
use trailmark_contingency::{Abstraction, PlannerOptions, Terrain, plan};
use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark_search::astar;

const UNBOUNDED: PlannerOptions = PlannerOptions { max_blockages: usize::MAX, max_states: 2_000_000 };

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(1.0)
}

/// A small river terrain: two rivers of two bridges, a forest road, fords.
fn river(seed: u64) -> Terrain {
    let options = RiverOptions {
        width: 30,
        height: 14,
        river_width: 2,
        bridges: 2,
        forests: 2,
        ..RiverOptions::default()
    };
    river_terrain(seed, &options).expect("valid options")
}

/// A random grid with obstacles and the narrow passages found in it as choke points (at most
/// six, with random probabilities); `None` when the start cannot reach the goal.
fn random_terrain(seed: u64, cells: &[bool], probabilities: &[f64]) -> Option<Terrain> {
    let (w, h) = (12usize, 9usize);
    let mut grid = Grid::new(w, h).unwrap();
    for (i, &wall) in cells.iter().enumerate().take(w * h) {
        if wall {
            grid.set_blocked(Cell::new((i % w) as u32, (i / w) as u32), true).unwrap();
        }
    }
    let (start, goal) =
        (Cell::new(0, (seed % h as u64) as u32), Cell::new(w as u32 - 1, (seed / 7 % h as u64) as u32));
    grid.set_blocked(start, false).unwrap();
    grid.set_blocked(goal, false).unwrap();
    let mut chokes = detect(&grid, Connectivity::Eight, &DetectOptions::default(), &[start, goal]).unwrap();
    chokes.truncate(6);
    for (c, &p) in chokes.iter_mut().zip(probabilities) {
        c.probability = p;
    }
    Terrain::new(grid, Connectivity::Eight, start, goal, chokes).ok()
}

/// The planner's expected cost is the reference's, the plan's tree sums to it, and driving the
/// plan in every world gives it again.
fn check_against_reference(terrain: &Terrain) {
    let planned = plan(terrain, &UNBOUNDED).unwrap();
    let mut reference = Reference::new(terrain);
    let exact = reference.expected_cost();
    assert!(close(planned.expected_cost, exact), "planner {} reference {}", planned.expected_cost, exact);
    assert!(close(reference.expected_cost_by_worlds(), exact));
    assert!(close(planned.plan.tree_expected_cost(), exact));
    let by_worlds: f64 = worlds(terrain)
        .iter()
        .map(|&(blocked, p)| p * planned.plan.execute(terrain, blocked).unwrap().cost)
        .sum();
    assert!(close(by_worlds, exact), "worlds {by_worlds} reference {exact}");
    let stuck: f64 = worlds(terrain)
        .iter()
        .filter(|&&(blocked, _)| !planned.plan.execute(terrain, blocked).unwrap().arrived)
        .map(|&(_, p)| p)
        .sum();
    assert!(close(stuck, planned.stuck_probability));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn planner_equals_reference_on_river_terrains(seed in 0u64..10_000) {
        check_against_reference(&river(seed));
    }

    #[test]
    fn planner_equals_reference_on_random_grids(
        seed in 0u64..1_000,
        cells in proptest::collection::vec(proptest::bool::weighted(0.3), 108),
        probabilities in proptest::collection::vec(0.0f64..=1.0, 6),
    ) {
        if let Some(terrain) = random_terrain(seed, &cells, &probabilities) {
            check_against_reference(&terrain);
        }
    }

    /// Preparing for more blockages never costs more; preparing for none is naive replanning
    /// on the abstraction, and no plan is dearer than D* Lite replanning on the grid.
    #[test]
    fn deeper_plans_cost_no_more(seed in 0u64..10_000) {
        let terrain = river(seed);
        let mut last = f64::INFINITY;
        for depth in [0, 1, 2, usize::MAX] {
            let planned = plan(&terrain, &PlannerOptions { max_blockages: depth, ..UNBOUNDED }).unwrap();
            prop_assert!(planned.expected_cost <= last + 1e-9);
            if depth == 0 {
                prop_assert!(!planned_has_optimised_drive(&planned.plan));
            }
            let by_worlds: f64 = worlds(&terrain).iter()
                .map(|&(b, p)| p * planned.plan.execute(&terrain, b).unwrap().cost).sum();
            prop_assert!(close(by_worlds, planned.expected_cost));
            last = planned.expected_cost;
        }
        let naive = naive_expected_cost(&terrain).unwrap();
        let by_worlds = naive_expected_cost_by_worlds(&terrain).unwrap();
        prop_assert!(close(naive.expected_cost, by_worlds.expected_cost));
        prop_assert!(close(naive.stuck_probability, by_worlds.stuck_probability));
        prop_assert!(naive.drives <= by_worlds.drives);
        let naive = naive.expected_cost;
        prop_assert!(last <= naive + 1e-9, "plan {last} naive {naive}");
    }

    /// With every choke point open, the cheapest route through the abstraction costs what A*
    /// finds on the grid.
    #[test]
    fn abstraction_is_exact(seed in 0u64..10_000) {
        let terrain = river(seed);
        let mut abs = Abstraction::new(&terrain);
        let routes = abs.routes(abs.start(), terrain.choke_mask());
        let graph = terrain.graph();
        let goal = terrain.goal();
        let found = astar(graph, terrain.start(), goal, graph.heuristic(GridHeuristic::Octile, goal)).unwrap();
        prop_assert!(close(routes.cost[abs.goal() as usize], found.cost().unwrap()));
        let hops = routes.hops_to(abs.goal()).unwrap();
        let (cells, cost) = abs.route_cells(&hops);
        prop_assert!(close(terrain.route_cost(&cells, 0).unwrap(), cost));
        prop_assert!(close(cost, found.cost().unwrap()));
    }
}

/// Whether a drive of the plan was optimised (not naive replanning beyond the nesting depth).
fn planned_has_optimised_drive(node: &trailmark_contingency::PlanNode) -> bool {
    match &node.action {
        trailmark_contingency::Action::Drive(d) => {
            !d.replan || d.outcomes.iter().any(|o| planned_has_optimised_drive(&o.next))
        }
        _ => false,
    }
}

#[test]
fn monte_carlo_mean_matches_the_expected_cost() {
    let terrain = river(3);
    let planned = plan(&terrain, &PlannerOptions::default()).unwrap();
    let mc = monte_carlo(&terrain, &planned.plan, 10_000, 1).unwrap();
    let error = (mc.plan.mean - planned.expected_cost).abs() / planned.expected_cost;
    assert!(error < 0.02, "Monte Carlo {} expected {}", mc.plan.mean, planned.expected_cost);
    assert!(mc.plan.mean <= mc.naive.mean + 4.0 * (mc.plan.std_error + mc.naive.std_error));
}

#[test]
fn plans_serialize_and_read_back() {
    let terrain = river(5);
    let planned = plan(&terrain, &PlannerOptions::default()).unwrap();
    let text = serde_json::to_string(&planned.plan).unwrap();
    let back: trailmark_contingency::PlanNode = serde_json::from_str(&text).unwrap();
    assert_eq!(back, planned.plan);
    let readable = planned.plan.to_json(&terrain);
    assert!(readable["expected_cost"].as_f64().is_some());
}
