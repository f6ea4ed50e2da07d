//! The names renamed in this release still work, deprecated, for one release.
#![allow(deprecated)]

#[test]
fn the_renamed_options_and_plans_keep_their_old_names() {
    let hybrid: trailmark::car::HybridSettings = trailmark::car::HybridOptions::default();
    assert_eq!(hybrid, trailmark::car::HybridOptions::default());
    let costmap: trailmark::map::CostmapSettings = trailmark::map::CostmapOptions::default();
    assert_eq!(costmap, trailmark::map::CostmapOptions::default());
    fn plan_type(
        _: Option<trailmark::contingency::Planned>,
    ) -> Option<trailmark::contingency::ContingencyPlan> {
        None
    }
    assert!(plan_type(None).is_none());
}
