//! The public paths that moved or were renamed in 0.2.0 keep naming the same items for one
//! release (CHANGELOG.md): each deprecated alias is checked to be the very type, constant or
//! function of its new path. (The search crate's own moved modules: its tests/old_paths.rs.)

#![allow(deprecated)]

use std::marker::PhantomData;

use trailmark::core::geometry::Point;

/// Compiles only when both are the same type.
fn same<T: ?Sized>(_: PhantomData<T>, _: PhantomData<T>) {}

#[test]
fn the_old_names_are_the_same_types() {
    use trailmark::{contingency, core, graph, navigate, problem, sample, solve};
    same(PhantomData::<problem::Problem>, PhantomData::<solve::ProblemSpec>);
    same(PhantomData::<problem::World>, PhantomData::<solve::WorldSpec>);
    same(PhantomData::<problem::GridWorld>, PhantomData::<solve::GridSpec>);
    same(PhantomData::<problem::BoxesWorld>, PhantomData::<solve::BoxesSpec>);
    same(PhantomData::<problem::PlannerSpec>, PhantomData::<solve::PlannerSpec>);
    same(PhantomData::<problem::SolveResult>, PhantomData::<solve::SolveResult>);
    same(PhantomData::<navigate::Outcome>, PhantomData::<navigate::NavigationOutcome>);
    same(PhantomData::<graph::Prm>, PhantomData::<graph::PolygonPrm>);
    same(PhantomData::<graph::Sampler>, PhantomData::<graph::PrmSampler>);
    same(PhantomData::<contingency::PlanError>, PhantomData::<contingency::ContingencyError>);
    same(PhantomData::<contingency::PlanStats>, PhantomData::<contingency::ContingencyStats>);
    same(PhantomData::<sample::Termination>, PhantomData::<core::termination::Termination>);
    same(PhantomData::<sample::Condition>, PhantomData::<core::termination::Condition>);
    same(PhantomData::<sample::Progress>, PhantomData::<core::termination::Progress>);
    same(PhantomData::<sample::Stop>, PhantomData::<core::termination::Stop>);
    same(PhantomData::<sample::plan::Stop>, PhantomData::<core::termination::Stop>);
    same(PhantomData::<trailmark::search::Stop>, PhantomData::<core::termination::Stop>);
    assert_eq!(graph::prm::MAX_NODES, graph::MAX_ROADMAP_NODES);
}

#[test]
fn the_old_predicate_paths_give_the_same_answers() {
    use trailmark::core::{freespace, predicates};
    let (a, b, c) = (Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(1.0, 1.0));
    assert_eq!(freespace::orient(a, b, c), predicates::orient(a, b, c));
    assert!(freespace::orient(a, b, c) > 0.0);
    assert_eq!(freespace::angular_order(a, b, c), predicates::angular_order(a, b, c));
    let q = Point::new(1.0, 0.5);
    assert_eq!(freespace::in_wedge(a, b, c, q), predicates::in_wedge(a, b, c, q));
}

#[test]
fn the_old_planner_choice_converts_into_the_registry() {
    use trailmark::navigate::PlannerChoice;
    use trailmark::solve::{AnytimeSpec, PlannerSpec};
    assert_eq!(PlannerSpec::from(PlannerChoice::DStarLite), PlannerSpec::DStarLite { heuristic: None });
    let ad_star = PlannerChoice::AdStar { epsilon: 2.0, epsilon_step: 0.25, expansions_per_step: Some(7) };
    assert_eq!(
        PlannerSpec::from(ad_star),
        PlannerSpec::AdStar(AnytimeSpec {
            epsilon: Some(2.0),
            epsilon_step: Some(0.25),
            max_expansions: Some(7),
            ..AnytimeSpec::default()
        })
    );
}
