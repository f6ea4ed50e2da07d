//! The planner against the exhaustive reference, and the plans against every world.

use trailmark_contingency::generate::{RiverOptions, river_terrain};
use trailmark_contingency::plan::worlds;
use trailmark_contingency::reference::Reference;
use trailmark_contingency::{PlannerOptions, Terrain, plan};

fn small(seed: u64) -> Terrain {
    let options = RiverOptions {
        width: 30,
        height: 14,
        rivers: 2,
        river_width: 2,
        bridges: 2,
        forests: 2,
        roads: 1,
        ..RiverOptions::default()
    };
    river_terrain(seed, &options).expect("valid options")
}

#[test]
fn smoke() {
    for seed in 0..5 {
        let terrain = small(seed);
        let unbounded = PlannerOptions { max_blockages: usize::MAX, ..PlannerOptions::default() };
        let planned = plan(&terrain, &unbounded).unwrap();
        let mut reference = Reference::new(&terrain);
        let exact = reference.expected_cost();
        let by_worlds: f64 =
            worlds(&terrain).iter().map(|&(b, p)| p * planned.plan.execute(&terrain, b).unwrap().cost).sum();
        println!(
            "seed {seed}: chokes {} plan {:.6} tree {:.6} worlds {:.6} reference {:.6} ref-worlds {:.6} stats {:?}",
            terrain.choke_points().len(),
            planned.expected_cost,
            planned.plan.tree_expected_cost(),
            by_worlds,
            exact,
            reference.expected_cost_by_worlds(),
            planned.stats
        );
    }
}
