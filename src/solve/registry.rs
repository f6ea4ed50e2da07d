//! The registry: one row per planner, its document name and its family. `solve` runs the
//! planners by these names ([`PlannerSpec`](super::PlannerSpec) holds each one's settings,
//! [`PlannerSpec::planner`](super::PlannerSpec::planner) says which row it is), `navigate`
//! drives the replanners among them, and the harness and the fuzzer take their lists from
//! [`PlannerName::ALL`], with tests that fail when a registered planner is missing from one.

use serde::{Deserialize, Serialize};

/// What kind of planner a row is: where it runs and what it returns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// One-shot searches over any graph of the core traits (grids, roadmaps): a path and its
    /// statistics.
    GraphSearch,
    /// One-shot searches that need a uniform-cost 8-connected grid (jump point search).
    GridSearch,
    /// Incremental searches that replan as costs change (`Replanner`); one search on a static
    /// world.
    Replanner,
    /// Anytime searches: a first path quickly, better ones until their limit.
    Anytime,
    /// Sampling planners over a configuration space (`trailmark_sample::Planner`).
    Sampling,
    /// Planners for car-like robots over poses.
    Car,
}

/// The table: each row a variant of [`PlannerName`], its document name, its family and whether
/// it replans. The
/// compiler then asks for the planner's arm in every exhaustive `match` over `PlannerName` and
/// `PlannerSpec`.
macro_rules! registry {
    ($($(#[$doc:meta])* $variant:ident => $name:literal, $family:ident, replans: $replans:literal;)*) => {
        /// A planner of the registry, by name: what a document's `"planner": {"name": ...}`
        /// selects.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum PlannerName {
            $($(#[$doc])* $variant,)*
        }

        impl PlannerName {
            /// Every registered planner, in the table's order.
            pub const ALL: &'static [PlannerName] = &[$(PlannerName::$variant,)*];

            /// Its name in problem documents (`"astar"`, `"dstar_lite"`, ...).
            pub const fn name(self) -> &'static str {
                match self {
                    $(PlannerName::$variant => $name,)*
                }
            }

            /// Its family.
            pub const fn family(self) -> Family {
                match self {
                    $(PlannerName::$variant => Family::$family,)*
                }
            }

            /// Whether it can drive a robot that replans as it senses (`navigate`): the
            /// replanners, A* from scratch at every plan, and AD*.
            pub const fn replans(self) -> bool {
                match self {
                    $(PlannerName::$variant => $replans,)*
                }
            }
        }
    };
}

registry! {
    /// Breadth-first search.
    Bfs => "bfs", GraphSearch, replans: false;
    /// Depth-first search.
    Dfs => "dfs", GraphSearch, replans: false;
    /// Dijkstra's algorithm.
    Dijkstra => "dijkstra", GraphSearch, replans: false;
    /// A*.
    AStar => "astar", GraphSearch, replans: true;
    /// Weighted A*.
    WeightedAStar => "weighted_astar", GraphSearch, replans: false;
    /// Theta*, any-angle.
    ThetaStar => "theta_star", GraphSearch, replans: false;
    /// Jump point search.
    Jps => "jps", GridSearch, replans: false;
    /// JPS+.
    JpsPlus => "jps_plus", GridSearch, replans: false;
    /// Lifelong Planning A*.
    LpaStar => "lpa_star", Replanner, replans: true;
    /// Adaptive A*.
    AdaptiveAStar => "adaptive_astar", Replanner, replans: true;
    /// MPGAA*.
    MpgaaStar => "mpgaa_star", Replanner, replans: true;
    /// D* Lite.
    DStarLite => "dstar_lite", Replanner, replans: true;
    /// ARA*.
    AraStar => "ara_star", Anytime, replans: false;
    /// AD*.
    AdStar => "ad_star", Anytime, replans: true;
    /// RRT.
    Rrt => "rrt", Sampling, replans: false;
    /// RRT-Connect.
    RrtConnect => "rrt_connect", Sampling, replans: false;
    /// RRT*.
    RrtStar => "rrt_star", Sampling, replans: false;
    /// Informed RRT*.
    InformedRrtStar => "informed_rrt_star", Sampling, replans: false;
    /// BIT*.
    BitStar => "bit_star", Sampling, replans: false;
    /// PRM.
    Prm => "prm", Sampling, replans: false;
    /// PRM*.
    PrmStar => "prm_star", Sampling, replans: false;
    /// Lazy PRM.
    LazyPrm => "lazy_prm", Sampling, replans: false;
    /// Lazy PRM*.
    LazyPrmStar => "lazy_prm_star", Sampling, replans: false;
    /// Hybrid A*.
    HybridAStar => "hybrid_astar", Car, replans: false;
}

impl PlannerName {
    /// The names of the planners that replan, for messages: `"astar, lpa_star, ..."`.
    pub fn replanner_names() -> String {
        let names: Vec<&str> = PlannerName::ALL.iter().filter(|p| p.replans()).map(|p| p.name()).collect();
        names.join(", ")
    }

    /// The planner of this document name, if one is registered.
    pub fn from_name(name: &str) -> Option<PlannerName> {
        PlannerName::ALL.iter().copied().find(|p| p.name() == name)
    }
}

impl std::fmt::Display for PlannerName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use super::{Family, PlannerName};
    use crate::solve::PlannerSpec;

    /// A document of each planner with its required settings.
    fn document(planner: PlannerName) -> serde_json::Value {
        let name = planner.name();
        match planner.family() {
            Family::Car => serde_json::json!({"name": name, "turning_radius": 1.0}),
            _ if planner == PlannerName::WeightedAStar => serde_json::json!({"name": name, "weight": 2.0}),
            _ => serde_json::json!({"name": name}),
        }
    }

    #[test]
    fn every_row_is_the_planner_its_document_names() {
        let names: BTreeSet<&str> = PlannerName::ALL.iter().map(|p| p.name()).collect();
        assert_eq!(names.len(), PlannerName::ALL.len(), "two rows share a name");
        for &planner in PlannerName::ALL {
            let spec: PlannerSpec =
                serde_json::from_value(document(planner)).unwrap_or_else(|e| panic!("{planner}: {e}"));
            assert_eq!(spec.planner(), planner);
            assert_eq!(spec.name(), planner.name());
            assert_eq!(PlannerName::from_name(planner.name()), Some(planner));
            // The family agrees with what the settings say.
            assert_eq!(spec.sampling().is_some(), planner.family() == Family::Sampling, "{planner}");
            if planner.family() == Family::Replanner {
                assert!(planner.replans(), "{planner} is a replanner");
            }
        }
        assert_eq!(PlannerName::from_name("a_star"), None);
    }

    #[test]
    fn the_planners_that_replan_are_made_replanners() {
        use trailmark_core::grid::{Cell, Connectivity, Grid};
        let grid = Grid::from_rows(&["...", "...", "..."]).expect("a grid");
        let graph = trailmark_graph::GridGraph::new(&grid, Connectivity::Eight);
        let (start, goal) = (Cell::new(0, 0), Cell::new(2, 2));
        for &planner in PlannerName::ALL {
            let spec: PlannerSpec = serde_json::from_value(document(planner)).expect("a document");
            let made = spec.replanner(&graph, start, goal, |_, _| 0.0);
            assert_eq!(made.is_some(), planner.replans(), "{planner}");
            if let Some(made) = made {
                let mut replanner = made.expect("made");
                replanner.plan(&graph).expect("a plan");
                assert_eq!(replanner.cost(), Some(2.0 * std::f64::consts::SQRT_2), "{planner}");
            }
        }
        let names = PlannerName::replanner_names();
        assert_eq!(names, "astar, lpa_star, adaptive_astar, mpgaa_star, dstar_lite, ad_star");
    }

    #[test]
    fn the_sampling_planners_are_made_planners() {
        use trailmark_sample::{KdNearest, R2, RrtOptions, Uniform};
        let bounds = trailmark_core::world::Bounds::new(0.0, 0.0, 10.0, 10.0).expect("bounds");
        let space = R2::new(bounds);
        for &planner in PlannerName::ALL {
            let spec: PlannerSpec = serde_json::from_value(document(planner)).expect("a document");
            let nearest = KdNearest::<R2, 2>::new(&space).expect("a tree");
            let made = spec.sampling_planner::<R2, trailmark_core::world::CollisionChecker, _, _>(
                nearest,
                Uniform,
                RrtOptions::default(),
                0,
            );
            assert_eq!(made.is_some(), planner.family() == Family::Sampling, "{planner}");
        }
    }
}
