//! The planners of a problem document and how [`solve`](super::solve) runs each one; their
//! names and families are the registry's (`registry.rs`), their families' settings in
//! `settings.rs`.

use std::time::Instant;

use serde::{Deserialize, Serialize};
use trailmark_core::Cost;
use trailmark_core::graph::{IndexedGraph, Lines, Predecessors, Successors};
use trailmark_core::grid::{Cell, Connectivity, CornerCutting, Grid, GridHeuristic};
use trailmark_sample::{
    BitStar, InformedRrtStar, NearestNeighbors, Planner, Prm, Rrt, RrtConnect, RrtOptions, RrtStar,
    StateSampler, StateSpace, Validity,
};
use trailmark_search::{
    AdStar, AdaptiveAStar, DStarLite, Jps, JpsPlus, LpaStar, MpgaaStar, Replanner, Search, SearchError,
    SearchResult, ara_star,
};

use super::error::{DocumentError, MAX_ITERATIONS, MAX_TIME_LIMIT_S, SolveError};
use super::registry::PlannerName;
use super::result::{SolveResult, Waypoint, anytime_result_of, result_of};
use super::settings::{AnytimeSpec, HybridSpec, SamplingSpec};

/// A planner and its parameters. In JSON, an object whose `"name"` selects the planner.
///
/// Each variant is a row of the [registry](PlannerName) with its settings: a new planner is a
/// row there and a variant here, and the compiler then asks for its arm in each `match` of
/// this file (which row it is, the heuristic it needs, and how it runs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "name", deny_unknown_fields)]
pub enum PlannerSpec {
    /// Breadth-first search: fewest moves, whatever their costs.
    #[serde(rename = "bfs")]
    Bfs {},
    /// Depth-first search: some path, quickly found, not short.
    #[serde(rename = "dfs")]
    Dfs {},
    /// Dijkstra's algorithm: least cost.
    #[serde(rename = "dijkstra")]
    Dijkstra {},
    /// A*: least cost, guided by an admissible heuristic.
    #[serde(rename = "astar")]
    AStar {
        /// The heuristic (default: octile for 8-connected grids, Manhattan for 4-connected).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// Weighted A*: A* with the heuristic inflated by `weight >= 1`; cost at most `weight` times
    /// the least cost.
    #[serde(rename = "weighted_astar")]
    WeightedAStar {
        /// The inflation factor, at least 1.
        weight: f64,
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// Theta*: any-angle paths on grids and ROS maps, straight lines between cell centres
    /// priced by the cells they cross; the Euclidean heuristic.
    #[serde(rename = "theta_star")]
    ThetaStar {},
    /// Jump point search: least cost on an 8-connected grid world whose passable cells all cost
    /// the same, putting on its open list only the cells where a path may turn.
    #[serde(rename = "jps")]
    Jps {},
    /// JPS+: jump point search reading its jumps from a table made for the map first (its time
    /// is part of the result's time); the same grid worlds and paths as `jps`.
    #[serde(rename = "jps_plus")]
    JpsPlus {},
    /// Lifelong Planning A*: the incremental forward search (on a static world, one search).
    #[serde(rename = "lpa_star")]
    LpaStar {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// Adaptive A*: A* from the robot at every plan with a heuristic learned from the plans
    /// before, kept consistent when costs fall (on a static world, one search).
    #[serde(rename = "adaptive_astar")]
    AdaptiveAStar {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// MPGAA*: Adaptive A* that also ends where it meets a path of an earlier plan that is
    /// still good (on a static world, one search).
    #[serde(rename = "mpgaa_star")]
    MpgaaStar {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// D* Lite: the incremental backward search (on a static world, one search).
    #[serde(rename = "dstar_lite")]
    DStarLite {
        /// The heuristic (default as for A*).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heuristic: Option<GridHeuristic>,
    },
    /// ARA*: anytime repairing A*, from `epsilon` down to 1 by `epsilon_step`, unless a limit
    /// stops it first.
    #[serde(rename = "ara_star")]
    AraStar(AnytimeSpec),
    /// AD*: anytime D*, as ARA* but searching backward from the goal.
    #[serde(rename = "ad_star")]
    AdStar(AnytimeSpec),
    /// RRT over a polygon world: one tree from the start, biased toward the goal.
    #[serde(rename = "rrt")]
    Rrt(SamplingSpec),
    /// RRT-Connect over a polygon world: a tree from each end, grown toward each other.
    #[serde(rename = "rrt_connect")]
    RrtConnect(SamplingSpec),
    /// RRT* over a polygon world: rewiring toward the least cost until its limit.
    #[serde(rename = "rrt_star")]
    RrtStar(SamplingSpec),
    /// Informed RRT*: RRT* that, once solved, draws only states through which a cheaper path
    /// can pass and prunes the others from its tree.
    #[serde(rename = "informed_rrt_star")]
    InformedRrtStar(SamplingSpec),
    /// BIT*: batches of 100 samples searched in order of the solution each edge could give,
    /// edges checked only when processed, improving until its limit. It takes no `range` or
    /// `goal_bias`; `max_iterations` counts samples.
    #[serde(rename = "bit_star")]
    BitStar(SamplingSpec),
    /// PRM: a roadmap of valid states, each joined to its 10 nearest, grown until the start
    /// and the goal connect; the shortest path through it. It takes no `range` or
    /// `goal_bias`; `max_iterations` counts samples.
    #[serde(rename = "prm")]
    Prm(SamplingSpec),
    /// PRM*: PRM with PRM*'s number of neighbours, growing and searching again until its limit.
    #[serde(rename = "prm_star")]
    PrmStar(SamplingSpec),
    /// Lazy PRM: PRM's roadmap with no motion checked as it grows; a found path's motions are
    /// checked, the blocked ones dropped and the search repeated. It takes no `range` or
    /// `goal_bias`; `max_iterations` counts samples.
    #[serde(rename = "lazy_prm")]
    LazyPrm(SamplingSpec),
    /// Lazy PRM*: Lazy PRM with PRM*'s number of neighbours, growing and searching again until
    /// its limit.
    #[serde(rename = "lazy_prm_star")]
    LazyPrmStar(SamplingSpec),
    /// Hybrid A* for a car-like robot on a ROS map: poses `[x, y, heading]`, forward and
    /// reverse arcs, the footprint checked at every pose.
    #[serde(rename = "hybrid_astar")]
    HybridAStar(HybridSpec),
}

impl PlannerSpec {
    /// The settings of a sampling planner, `None` for a graph search.
    pub fn sampling(&self) -> Option<&SamplingSpec> {
        match self {
            PlannerSpec::Rrt(spec)
            | PlannerSpec::RrtConnect(spec)
            | PlannerSpec::RrtStar(spec)
            | PlannerSpec::InformedRrtStar(spec)
            | PlannerSpec::BitStar(spec)
            | PlannerSpec::Prm(spec)
            | PlannerSpec::PrmStar(spec)
            | PlannerSpec::LazyPrm(spec)
            | PlannerSpec::LazyPrmStar(spec) => Some(spec),
            PlannerSpec::Bfs {}
            | PlannerSpec::Dfs {}
            | PlannerSpec::Dijkstra {}
            | PlannerSpec::AStar { .. }
            | PlannerSpec::WeightedAStar { .. }
            | PlannerSpec::ThetaStar {}
            | PlannerSpec::Jps {}
            | PlannerSpec::JpsPlus {}
            | PlannerSpec::LpaStar { .. }
            | PlannerSpec::AdaptiveAStar { .. }
            | PlannerSpec::MpgaaStar { .. }
            | PlannerSpec::DStarLite { .. }
            | PlannerSpec::AraStar(_)
            | PlannerSpec::AdStar(_)
            | PlannerSpec::HybridAStar(_) => None,
        }
    }

    /// Which planner of the [registry](PlannerName) this is.
    pub fn planner(&self) -> PlannerName {
        match self {
            PlannerSpec::Bfs {} => PlannerName::Bfs,
            PlannerSpec::Dfs {} => PlannerName::Dfs,
            PlannerSpec::Dijkstra {} => PlannerName::Dijkstra,
            PlannerSpec::AStar { .. } => PlannerName::AStar,
            PlannerSpec::WeightedAStar { .. } => PlannerName::WeightedAStar,
            PlannerSpec::ThetaStar {} => PlannerName::ThetaStar,
            PlannerSpec::Jps {} => PlannerName::Jps,
            PlannerSpec::JpsPlus {} => PlannerName::JpsPlus,
            PlannerSpec::LpaStar { .. } => PlannerName::LpaStar,
            PlannerSpec::AdaptiveAStar { .. } => PlannerName::AdaptiveAStar,
            PlannerSpec::MpgaaStar { .. } => PlannerName::MpgaaStar,
            PlannerSpec::DStarLite { .. } => PlannerName::DStarLite,
            PlannerSpec::AraStar(_) => PlannerName::AraStar,
            PlannerSpec::AdStar(_) => PlannerName::AdStar,
            PlannerSpec::Rrt(_) => PlannerName::Rrt,
            PlannerSpec::RrtConnect(_) => PlannerName::RrtConnect,
            PlannerSpec::RrtStar(_) => PlannerName::RrtStar,
            PlannerSpec::InformedRrtStar(_) => PlannerName::InformedRrtStar,
            PlannerSpec::BitStar(_) => PlannerName::BitStar,
            PlannerSpec::Prm(_) => PlannerName::Prm,
            PlannerSpec::PrmStar(_) => PlannerName::PrmStar,
            PlannerSpec::LazyPrm(_) => PlannerName::LazyPrm,
            PlannerSpec::LazyPrmStar(_) => PlannerName::LazyPrmStar,
            PlannerSpec::HybridAStar(_) => PlannerName::HybridAStar,
        }
    }

    /// The name used in problem documents (`"astar"`, `"dstar_lite"`, ...): the registry's.
    pub fn name(&self) -> &'static str {
        self.planner().name()
    }

    /// The heuristic this planner searches a grid of `connectivity` with: the one it asks for,
    /// else the grid's own (octile or Manhattan); an error when the planner promises least cost
    /// and that heuristic may overestimate.
    pub fn grid_heuristic(&self, connectivity: Connectivity) -> Result<GridHeuristic, DocumentError> {
        let (asked, optimal) = self.heuristic();
        let kind = asked.unwrap_or(GridHeuristic::for_connectivity(connectivity));
        if optimal && !kind.is_admissible(connectivity) {
            return Err(DocumentError::Inadmissible { heuristic: kind });
        }
        Ok(kind)
    }

    /// The heuristic the planner asks for, and whether it promises least cost (so that the
    /// heuristic must be admissible).
    pub(crate) fn heuristic(&self) -> (Option<GridHeuristic>, bool) {
        match self {
            PlannerSpec::Bfs {}
            | PlannerSpec::Dfs {}
            | PlannerSpec::Dijkstra {}
            | PlannerSpec::Jps {}
            | PlannerSpec::JpsPlus {} => (None, true),
            PlannerSpec::Rrt(_)
            | PlannerSpec::RrtConnect(_)
            | PlannerSpec::RrtStar(_)
            | PlannerSpec::InformedRrtStar(_)
            | PlannerSpec::BitStar(_)
            | PlannerSpec::Prm(_)
            | PlannerSpec::PrmStar(_)
            | PlannerSpec::LazyPrm(_)
            | PlannerSpec::LazyPrmStar(_)
            | PlannerSpec::HybridAStar(_) => (None, false),
            PlannerSpec::WeightedAStar { heuristic, .. } => (*heuristic, false),
            // Lines may be shorter than any path of the grid: only the straight line is a
            // lower bound.
            PlannerSpec::ThetaStar {} => (Some(GridHeuristic::Euclidean), false),
            PlannerSpec::AStar { heuristic }
            | PlannerSpec::LpaStar { heuristic }
            | PlannerSpec::AdaptiveAStar { heuristic }
            | PlannerSpec::MpgaaStar { heuristic }
            | PlannerSpec::DStarLite { heuristic }
            | PlannerSpec::AraStar(AnytimeSpec { heuristic, .. })
            | PlannerSpec::AdStar(AnytimeSpec { heuristic, .. }) => (*heuristic, true),
        }
    }

    /// Errors when a limit of the planner's settings is out of range: a time limit that is
    /// negative, not a number or above [`MAX_TIME_LIMIT_S`], an iteration limit above
    /// [`MAX_ITERATIONS`]; or a setting this planner does not take (PRM's `range`).
    pub fn check_limits(&self) -> Result<(), DocumentError> {
        if let Some(t) = self.time_limit_s()
            && !(0.0..=MAX_TIME_LIMIT_S).contains(&t)
        {
            return Err(DocumentError::TimeLimit(t));
        }
        if let Some(n) = self.sampling().and_then(|spec| spec.max_iterations)
            && n > MAX_ITERATIONS
        {
            return Err(DocumentError::TooManyIterations(n));
        }
        // A roadmap or a batch of samples neither steers by a range nor aims at the goal.
        if let PlannerSpec::Prm(spec)
        | PlannerSpec::PrmStar(spec)
        | PlannerSpec::LazyPrm(spec)
        | PlannerSpec::LazyPrmStar(spec)
        | PlannerSpec::BitStar(spec) = self
        {
            let given = [("range", spec.range.is_some()), ("goal_bias", spec.goal_bias.is_some())];
            if let Some(&(field, _)) = given.iter().find(|(_, given)| *given) {
                return Err(DocumentError::NotForPlanner { field, planner: self.name() });
            }
        }
        Ok(())
    }

    /// The planner's time limit in seconds, if it takes one and the document gives it.
    fn time_limit_s(&self) -> Option<f64> {
        match self {
            PlannerSpec::AraStar(spec) | PlannerSpec::AdStar(spec) => spec.time_limit_s,
            PlannerSpec::HybridAStar(spec) => spec.time_limit_s,
            planner => planner.sampling().and_then(|spec| spec.time_limit_s),
        }
    }

    /// Runs this graph search from `start` to `goal` on `graph` with the heuristic `h(a, b)`,
    /// writing each path node (and each node an error names) as `waypoint(node)`. `line_cost`
    /// prices straight lines between nodes for the any-angle searches (`None` where the graph
    /// has no lines: Theta* is then refused). Sampling
    /// planners draw their own states: they are run by [`PlannerSpec::sampling_planner`].
    pub(super) fn search<G, H>(
        &self,
        graph: &G,
        ends: (G::Node, G::Node),
        h: H,
        waypoint: impl Fn(G::Node) -> Waypoint,
        line_cost: Option<&LineCost<'_, G::Node>>,
    ) -> Result<SolveResult, SolveError>
    where
        G: Successors + Predecessors + IndexedGraph,
        H: Fn(G::Node, G::Node) -> Cost + Copy,
    {
        self.search_in(&mut Search::new(), graph, ends, h, waypoint, line_cost)
    }

    /// [`search`](Self::search) in the workspace `search`, kept from query to query by callers
    /// that search one graph many times (its arrays are then not allocated again).
    pub(super) fn search_in<G, H>(
        &self,
        search: &mut Search,
        graph: &G,
        (start, goal): (G::Node, G::Node),
        h: H,
        waypoint: impl Fn(G::Node) -> Waypoint,
        line_cost: Option<&LineCost<'_, G::Node>>,
    ) -> Result<SolveResult, SolveError>
    where
        G: Successors + Predecessors + IndexedGraph,
        H: Fn(G::Node, G::Node) -> Cost + Copy,
    {
        let to_goal = |n| h(n, goal);
        let searched = |error: SearchError<G::Node>| SolveError::Search(error.map_node(&waypoint));
        let found = match self {
            PlannerSpec::Bfs {} => search.bfs(graph, start, goal),
            PlannerSpec::Dfs {} => search.dfs(graph, start, goal),
            PlannerSpec::Dijkstra {} => search.dijkstra(graph, start, goal),
            PlannerSpec::AStar { .. } => search.astar(graph, start, goal, to_goal),
            PlannerSpec::WeightedAStar { weight, .. } => {
                search.weighted_astar(graph, start, goal, to_goal, *weight)
            }
            PlannerSpec::ThetaStar {} => match line_cost {
                Some(line_cost) => search.theta_star(graph, start, goal, to_goal, line_cost),
                None => return Err(DocumentError::NeedsLines { planner: self.name() }.into()),
            },
            PlannerSpec::LpaStar { .. } => plan_once(graph, LpaStar::new(graph, start, goal, h)),
            PlannerSpec::AdaptiveAStar { .. } => plan_once(graph, AdaptiveAStar::new(graph, start, goal, h)),
            PlannerSpec::MpgaaStar { .. } => plan_once(graph, MpgaaStar::new(graph, start, goal, h)),
            PlannerSpec::DStarLite { .. } => plan_once(graph, DStarLite::new(graph, start, goal, h)),
            PlannerSpec::AraStar(spec) => {
                let found = ara_star(graph, start, goal, to_goal, spec.schedule(), spec.budget());
                return Ok(anytime_result_of(&found.map_err(searched)?, waypoint));
            }
            PlannerSpec::AdStar(spec) => {
                let found = AdStar::new(graph, start, goal, h, spec.schedule())
                    .and_then(|mut planner| planner.improve(graph, spec.budget()));
                return Ok(anytime_result_of(&found.map_err(searched)?, waypoint));
            }
            PlannerSpec::Jps {} | PlannerSpec::JpsPlus {} => {
                return Err(DocumentError::NeedsGridWorld { planner: self.name() }.into());
            }
            PlannerSpec::Rrt(_)
            | PlannerSpec::RrtConnect(_)
            | PlannerSpec::RrtStar(_)
            | PlannerSpec::InformedRrtStar(_)
            | PlannerSpec::BitStar(_)
            | PlannerSpec::Prm(_)
            | PlannerSpec::PrmStar(_)
            | PlannerSpec::LazyPrm(_)
            | PlannerSpec::LazyPrmStar(_)
            | PlannerSpec::HybridAStar(_) => {
                return Err(DocumentError::NotAGraphSearch { planner: self.name() }.into());
            }
        };
        Ok(result_of(&found.map_err(searched)?, waypoint))
    }

    /// Runs this planner on the grid itself where it is made for grids (jump point search: on
    /// `grid` with `connectivity` and diagonal moves by `rule`, from `start` to `goal`); `None`
    /// for the planners that search the grid's graph through [`PlannerSpec::search`].
    pub(super) fn grid_search(
        &self,
        grid: &Grid,
        connectivity: Connectivity,
        rule: CornerCutting,
        (start, goal): (Cell, Cell),
    ) -> Option<Result<SolveResult, SolveError>> {
        let found = match self {
            PlannerSpec::Jps {} | PlannerSpec::JpsPlus {} if connectivity != Connectivity::Eight => {
                return Some(Err(DocumentError::NeedsEightConnectedGrid { planner: self.name() }.into()));
            }
            PlannerSpec::Jps {} => Jps::new(grid, rule).and_then(|mut jps| jps.search(start, goal)),
            PlannerSpec::JpsPlus {} => {
                let clock = Instant::now();
                JpsPlus::new(grid, rule).and_then(|mut plus| plus.search(start, goal)).map(|mut found| {
                    found.stats.elapsed = clock.elapsed();
                    found
                })
            }
            PlannerSpec::Bfs {}
            | PlannerSpec::Dfs {}
            | PlannerSpec::Dijkstra {}
            | PlannerSpec::AStar { .. }
            | PlannerSpec::WeightedAStar { .. }
            | PlannerSpec::ThetaStar {}
            | PlannerSpec::LpaStar { .. }
            | PlannerSpec::AdaptiveAStar { .. }
            | PlannerSpec::MpgaaStar { .. }
            | PlannerSpec::DStarLite { .. }
            | PlannerSpec::AraStar(_)
            | PlannerSpec::AdStar(_)
            | PlannerSpec::Rrt(_)
            | PlannerSpec::RrtConnect(_)
            | PlannerSpec::RrtStar(_)
            | PlannerSpec::InformedRrtStar(_)
            | PlannerSpec::BitStar(_)
            | PlannerSpec::Prm(_)
            | PlannerSpec::PrmStar(_)
            | PlannerSpec::LazyPrm(_)
            | PlannerSpec::LazyPrmStar(_)
            | PlannerSpec::HybridAStar(_) => return None,
        };
        Some(match found {
            Ok(found) => Ok(result_of(&found, Waypoint::Cell)),
            Err(error) => Err(SolveError::Search(error.map_node(Waypoint::Cell))),
        })
    }

    /// This sampling planner over the space `S` with the validity `V`, with its nearest
    /// neighbours, sampler, options and seed; `None` for a graph search.
    pub(super) fn sampling_planner<'a, S, V, N, Q>(
        &self,
        nearest: N,
        sampler: Q,
        options: RrtOptions,
        seed: u64,
    ) -> Option<Box<dyn Planner<S, V> + 'a>>
    where
        S: StateSpace + 'a,
        V: Validity<S> + 'a,
        N: NearestNeighbors<S> + Clone + 'a,
        Q: StateSampler<S> + 'a,
    {
        Some(match self {
            PlannerSpec::Rrt(_) => {
                Box::new(Rrt::new(nearest).with_sampler(sampler).with_options(options).with_seed(seed))
            }
            PlannerSpec::RrtConnect(_) => {
                Box::new(RrtConnect::new(nearest).with_sampler(sampler).with_options(options).with_seed(seed))
            }
            PlannerSpec::RrtStar(_) => {
                Box::new(RrtStar::new(nearest).with_sampler(sampler).with_options(options).with_seed(seed))
            }
            PlannerSpec::InformedRrtStar(_) => Box::new(
                InformedRrtStar::new(nearest).with_sampler(sampler).with_options(options).with_seed(seed),
            ),
            PlannerSpec::BitStar(_) => Box::new(BitStar::new(nearest).with_sampler(sampler).with_seed(seed)),
            PlannerSpec::Prm(_) => Box::new(Prm::new(nearest).with_sampler(sampler).with_seed(seed)),
            PlannerSpec::PrmStar(_) => Box::new(Prm::star(nearest).with_sampler(sampler).with_seed(seed)),
            PlannerSpec::LazyPrm(_) => Box::new(Prm::lazy(nearest).with_sampler(sampler).with_seed(seed)),
            PlannerSpec::LazyPrmStar(_) => {
                Box::new(Prm::lazy_star(nearest).with_sampler(sampler).with_seed(seed))
            }
            // The graph searches, for which `sampling()` is `None`.
            _ => return None,
        })
    }
}

/// The price of a straight line between two nodes, `None` when it is blocked: what an
/// any-angle search draws its segments with.
pub(super) type LineCost<'a, N> = dyn Lines<N> + 'a;

/// One plan of a replanner just made: what `solve` asks of LPA* and D* Lite on a static world.
fn plan_once<G, R>(
    graph: &G,
    made: Result<R, SearchError<G::Node>>,
) -> Result<SearchResult<G::Node>, SearchError<G::Node>>
where
    G: Successors + Predecessors + IndexedGraph,
    R: Replanner<G>,
{
    let mut planner = made?;
    let stats = planner.plan(graph)?;
    Ok(SearchResult { path: planner.path(graph), stats })
}
