//! Contingency terrains: build from a description, and for small terrains plan, drive the plan
//! in every world, and compare its expected cost with the driven costs and with the exhaustive
//! reference solver.

use std::path::Path as FsPath;

use trailmark_contingency::reference::Reference;
use trailmark_contingency::{PlannerOptions, TerrainSpec, plan};

use crate::{NO_DIR, close};

/// The most cells of a terrain that is planned over.
pub const MAX_PLAN_CELLS: usize = 2500;
/// The most choke points of a terrain that is planned over (64 worlds).
pub const MAX_PLAN_CHOKES: usize = 6;
/// The most choke points and cells of a terrain that is also solved by the reference solver.
pub const MAX_REFERENCE: (usize, usize) = (3, 400);
/// The states the planner may create.
pub const MAX_STATES: usize = 20_000;
/// The relative tolerance of expected costs.
pub const COST_TOLERANCE: f64 = 1e-9;

/// How far a terrain description got.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Reached {
    /// Not a terrain description.
    NotParsed,
    /// Parsed, but too large to build, or refused by `build`.
    Parsed,
    /// Built, but too large to plan over, or refused by `plan`.
    Built,
    /// ContingencyPlan and checked.
    ContingencyPlan,
    /// ContingencyPlan, checked, and compared with the reference solver.
    Referenced,
}

/// Parses `bytes` as a terrain description, builds it and, when small, plans over it.
pub fn terrain_bytes(bytes: &[u8]) -> Reached {
    let Ok(spec) = serde_json::from_slice::<TerrainSpec>(bytes) else { return Reached::NotParsed };
    check_spec(&spec)
}

/// Builds `spec` and, when small, plans over it and checks the plan.
pub fn check_spec(spec: &TerrainSpec) -> Reached {
    if spec.movingai.as_ref().is_some_and(|m| FsPath::new(m).has_root()) {
        return Reached::Parsed; // Path::join would leave the base folder: never read a file.
    }
    let rows = spec.rows.as_deref().unwrap_or_default();
    let width = rows.first().map_or(0, |r| r.chars().count());
    let text: usize = rows.iter().map(String::len).sum();
    if rows.len().saturating_mul(width) > 4 * MAX_PLAN_CELLS || text > 16 * MAX_PLAN_CELLS {
        return Reached::Parsed;
    }
    if spec.choke_points.len() > 64 || spec.choke_points.iter().map(|c| c.cells.len()).sum::<usize>() > 256 {
        return Reached::Parsed;
    }
    let Ok(terrain) = spec.build(FsPath::new(NO_DIR)) else { return Reached::Parsed };
    let chokes = terrain.choke_points().len();
    let cells = terrain.grid().len();
    if chokes > MAX_PLAN_CHOKES || cells > MAX_PLAN_CELLS {
        return Reached::Built;
    }
    let options = PlannerOptions { max_states: MAX_STATES, ..PlannerOptions::default() };
    let Ok(planned) = plan(&terrain, &options) else { return Reached::Built };
    let expected = planned.expected_cost;
    assert!(expected.is_finite() && expected >= 0.0, "expected cost {expected}");
    let stuck = planned.stuck_probability;
    assert!((-1e-12..=1.0 + 1e-9).contains(&stuck), "stuck probability {stuck}");
    let by_tree = planned.plan.tree_expected_cost();
    assert!(close(by_tree, expected, COST_TOLERANCE), "expected cost {expected}, tree says {by_tree}");
    let mut by_worlds = 0.0;
    for (blocked, p) in trailmark_contingency::plan::worlds(&terrain) {
        let run = planned
            .plan
            .execute(&terrain, blocked)
            .unwrap_or_else(|e| panic!("the plan cannot be driven in world {blocked:#b}: {e}"));
        assert!(run.cost.is_finite() && run.cost >= 0.0, "world {blocked:#b}: cost {}", run.cost);
        assert_eq!(
            run.route.first(),
            Some(&terrain.start()),
            "world {blocked:#b}: the drive starts elsewhere"
        );
        if run.arrived {
            assert_eq!(run.route.last(), Some(&terrain.goal()), "world {blocked:#b}: arrived elsewhere");
        }
        by_worlds += p * run.cost;
    }
    assert!(
        close(by_worlds, expected, COST_TOLERANCE),
        "expected cost {expected}, driven in every world {by_worlds}"
    );
    if chokes <= MAX_REFERENCE.0 && cells <= MAX_REFERENCE.1 && chokes <= options.max_blockages {
        let optimum = Reference::new(&terrain).expected_cost();
        assert!(
            close(optimum, expected, COST_TOLERANCE),
            "expected cost {expected}, reference optimum {optimum}"
        );
        return Reached::Referenced;
    }
    Reached::ContingencyPlan
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed seeds reach the stages they were written for.
    #[test]
    fn seeds_reach_the_planner() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/seeds/terrain_json");
        let reached = |name: &str| terrain_bytes(&std::fs::read(format!("{dir}/{name}")).unwrap());
        assert_eq!(reached("two-bridges.json"), Reached::Referenced);
        assert_eq!(reached("near-far.json"), Reached::Referenced);
        assert!(reached("detect-4.json") >= Reached::ContingencyPlan);
        assert_eq!(reached("invalid-touching.json"), Reached::Parsed);
        assert_eq!(reached("invalid-map-file.json"), Reached::Parsed);
    }
}
