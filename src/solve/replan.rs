//! The planners of the registry that replan: which they are, and each made a [`Replanner`] for
//! a graph (what navigation drives its robot with).

use trailmark_core::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_search::{
    AdStar, AdaptiveAStar, DStarLite, LpaStar, MpgaaStar, RepeatedAStar, Replanner, SearchError,
};

use super::planner::PlannerSpec;

/// A replanner of the registry, behind its trait.
type BoxedReplanner<'h, G> = Box<dyn Replanner<G> + 'h>;

impl PlannerSpec {
    /// Whether [`replanner`](Self::replanner) makes this planner a [`Replanner`]: the
    /// registry's [`PlannerName::replans`](super::PlannerName::replans).
    pub fn replans(&self) -> bool {
        self.planner().replans()
    }

    /// This planner as a [`Replanner`] from `start` to `goal` on `graph` with the heuristic
    /// `h(a, b)`, for the planners the registry says replan (`astar`, A* from scratch at every
    /// plan; `lpa_star`, `dstar_lite`, `adaptive_astar`, `mpgaa_star`; `ad_star`, whose limits
    /// apply to each plan); `None` for the others. [`navigate`](crate::navigate::navigate) drives the
    /// robot with it, and `solve` runs LPA* and D* Lite through it.
    pub fn replanner<'h, G, H>(
        &self,
        graph: &G,
        start: G::Node,
        goal: G::Node,
        h: H,
    ) -> Option<Result<BoxedReplanner<'h, G>, SearchError<G::Node>>>
    where
        G: Successors + Predecessors + IndexedGraph + 'h,
        H: Fn(G::Node, G::Node) -> Cost + Copy + 'h,
    {
        fn boxed<'h, G, R>(
            made: Result<R, SearchError<G::Node>>,
        ) -> Result<BoxedReplanner<'h, G>, SearchError<G::Node>>
        where
            G: Successors + Predecessors + IndexedGraph,
            R: Replanner<G> + 'h,
        {
            made.map(|planner| Box::new(planner) as BoxedReplanner<'h, G>)
        }
        Some(match self {
            PlannerSpec::AStar { .. } => boxed(RepeatedAStar::new(graph, start, goal, h)),
            PlannerSpec::LpaStar { .. } => boxed(LpaStar::new(graph, start, goal, h)),
            PlannerSpec::AdaptiveAStar { .. } => boxed(AdaptiveAStar::new(graph, start, goal, h)),
            PlannerSpec::MpgaaStar { .. } => boxed(MpgaaStar::new(graph, start, goal, h)),
            PlannerSpec::DStarLite { .. } => boxed(DStarLite::new(graph, start, goal, h)),
            PlannerSpec::AdStar(spec) => boxed(
                AdStar::new(graph, start, goal, h, spec.schedule())
                    .map(|planner| planner.with_termination_per_plan(spec.budget())),
            ),
            // The registry says which planners replan (`PlannerName::replans`); its test holds
            // that exactly those are made here.
            _ => return None,
        })
    }
}
