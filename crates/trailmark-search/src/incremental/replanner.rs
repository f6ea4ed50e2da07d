//! One interface for the planners kept between plans, so a program picks its planner at run
//! time and compares them on the same sequence of problems.

use trailmark_core::cost::Cost;
use trailmark_core::graph::{IndexedGraph, Predecessors, Successors};
use trailmark_core::path::Path;

use crate::error::SearchError;
use crate::incremental::EdgeChange;
use crate::stats::SearchStats;

/// A planner kept between plans, on a graph that changes and from a start that moves: the loop
/// of a robot that senses, tells its planner what changed, plans and moves.
///
/// Each plan is made from the planner's current start to its goal on the graph as it is when
/// [`plan`](Replanner::plan) is called. Between two plans the planner must be told of every
/// change of the graph ([`update_edges`](Replanner::update_edges) or
/// [`update_nodes`](Replanner::update_nodes)) and of every move of its start
/// ([`move_start`](Replanner::move_start)); what it does with that is its own business: A* from
/// scratch ([`RepeatedAStar`](crate::RepeatedAStar)) ignores it, LPA* ([`LpaStar`](crate::LpaStar))
/// repairs after changes but restarts when its start moves, D* Lite
/// ([`DStarLite`](crate::DStarLite)) repairs after both, AD* ([`AdStar`](crate::AdStar)) repairs
/// and improves an inflated path within a budget per plan, Adaptive A*
/// ([`AdaptiveAStar`](crate::AdaptiveAStar)) searches afresh with what earlier plans learned, and
/// MPGAA* ([`MpgaaStar`](crate::MpgaaStar)) also stops where it meets an earlier path that is
/// still good.
///
/// The trait is object safe: a `Box<dyn Replanner<G>>` holds any planner for graphs of type `G`.
///
/// ```
/// use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
/// use trailmark_graph::GridGraph;
/// use trailmark_search::{AdStar, DStarLite, EpsilonSchedule, LpaStar, RepeatedAStar, Replanner};
///
/// let mut graph = GridGraph::new(&Grid::new(8, 5)?, Connectivity::Eight);
/// let (start, goal) = (Cell::new(0, 2), Cell::new(7, 2));
/// let h = graph.heuristic_between(GridHeuristic::Octile);
/// let mut planners: Vec<Box<dyn Replanner<GridGraph>>> = vec![
///     Box::new(RepeatedAStar::new(&graph, start, goal, h)?),
///     Box::new(LpaStar::new(&graph, start, goal, h)?),
///     Box::new(DStarLite::new(&graph, start, goal, h)?),
///     Box::new(AdStar::new(&graph, start, goal, h, EpsilonSchedule::default())?),
/// ];
/// for planner in &mut planners {
///     planner.plan(&graph)?;
///     assert_eq!(planner.cost(), Some(7.0));
/// }
///
/// // A wall rises in column 4, open in the top row only, and the robot takes a step.
/// let mut changed = Vec::new();
/// for y in 1..5 {
///     graph.set_cost(Cell::new(4, y), f64::INFINITY)?;
///     changed.extend(graph.cells_affected_by(Cell::new(4, y)));
/// }
/// for planner in &mut planners {
///     planner.update_nodes(&graph, &changed)?;
///     planner.move_start(&graph, Cell::new(1, 2))?;
///     let stats = planner.plan(&graph)?;
///     let cost = planner.cost().expect("the top row is open");
///     assert!((cost - (2.0 + 4.0 * std::f64::consts::SQRT_2)).abs() < 1e-9);
///     assert_eq!(planner.next_step(&graph), Some(Cell::new(2, 1)));
///     assert_eq!(planner.inflation(), 1.0); // AD* improved to the optimum: no limit per plan
///     assert!(planner.totals().expansions >= stats.expansions);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Replanner<G>
where
    G: Successors + Predecessors + IndexedGraph + ?Sized,
{
    /// Tells the planner that these edges changed cost since its last plan (the graph already
    /// has the new costs; the old ones are not needed). Errors, applying nothing, when a change
    /// names no node of the graph (and, for the incremental planners, when a new cost is negative
    /// or NaN).
    fn update_edges(
        &mut self,
        graph: &G,
        changes: &[EdgeChange<G::Node>],
    ) -> Result<(), SearchError<G::Node>>;

    /// Tells the planner that edges at these nodes changed, in whatever way: name every node
    /// whose in-edges changed (LPA*) or whose out-edges changed (D* Lite, AD*); on a grid, after
    /// `GridGraph::set_cost(cell, ..)`, the cells of `GridGraph::cells_affected_by(cell)` serve
    /// both. Errors, applying nothing, when a node names nothing.
    fn update_nodes(&mut self, graph: &G, nodes: &[G::Node]) -> Result<(), SearchError<G::Node>>;

    /// Moves the start to `to` (a robot's next step, or anywhere). Errors when `to` is not a
    /// node of the graph.
    fn move_start(&mut self, graph: &G, to: G::Node) -> Result<(), SearchError<G::Node>>;

    /// Plans from the current start to the goal on `graph` as it is now, and returns what this
    /// plan did. Afterwards [`path`](Replanner::path), [`cost`](Replanner::cost) and
    /// [`next_step`](Replanner::next_step) answer for this plan; no path means the goal is
    /// unreachable from the start.
    fn plan(&mut self, graph: &G) -> Result<SearchStats, SearchError<G::Node>>;

    /// The last plan's path from the start to the goal (`None` without one).
    fn path(&self, graph: &G) -> Option<Path<G::Node>>;

    /// The cost of the last plan's path (`None` without one).
    fn cost(&self) -> Option<Cost>;

    /// The node after the start on the last plan's path: where a robot moves next (`None` at
    /// the goal or without a path).
    fn next_step(&self, graph: &G) -> Option<G::Node>;

    /// Counters summed over every call since the planner was made.
    fn totals(&self) -> SearchStats;

    /// Bytes held by the planner's state.
    fn memory_bytes(&self) -> usize;

    /// The inflation the last plan was made with: its path costs at most this times the least
    /// cost. 1 for the exact planners.
    fn inflation(&self) -> f64 {
        1.0
    }
}

/// Implements [`Replanner`] for a planner type by its inherent methods of the same names, the
/// method `$plan` planning and `$inflation`, when named, giving the inflation:
/// [`LpaStar`](crate::LpaStar) and [`DStarLite`](crate::DStarLite) (`compute_shortest_path`
/// plans) and [`AdStar`](crate::AdStar), whose own methods say how each answers. The impl's
/// documentation, if any, goes first.
macro_rules! replanner_by_inherent_methods {
    ($(#[$attr:meta])* $planner:ident, plan: $plan:ident $(, inflation: $inflation:ident)?) => {
        $(#[$attr])*
        impl<G, H> $crate::incremental::replanner::Replanner<G> for $planner<G::Node, H>
        where
            G: Successors + Predecessors + IndexedGraph + ?Sized,
            H: $crate::Heuristic<G>,
        {
            fn update_edges(
                &mut self,
                graph: &G,
                changes: &[$crate::EdgeChange<G::Node>],
            ) -> Result<(), $crate::SearchError<G::Node>> {
                $planner::update_edges(self, graph, changes)
            }

            fn update_nodes(
                &mut self,
                graph: &G,
                nodes: &[G::Node],
            ) -> Result<(), $crate::SearchError<G::Node>> {
                $planner::update_nodes(self, graph, nodes.iter().copied())
            }

            fn move_start(&mut self, graph: &G, to: G::Node) -> Result<(), $crate::SearchError<G::Node>> {
                $planner::move_start(self, graph, to)
            }

            fn plan(&mut self, graph: &G) -> Result<$crate::SearchStats, $crate::SearchError<G::Node>> {
                $planner::$plan(self, graph)
            }

            fn path(&self, graph: &G) -> Option<Path<G::Node>> {
                $planner::path(self, graph)
            }

            fn cost(&self) -> Option<Cost> {
                $planner::cost(self)
            }

            fn next_step(&self, graph: &G) -> Option<G::Node> {
                $planner::next_step(self, graph)
            }

            fn totals(&self) -> $crate::SearchStats {
                $planner::totals(self)
            }

            fn memory_bytes(&self) -> usize {
                $planner::memory_bytes(self)
            }

            $(
                fn inflation(&self) -> f64 {
                    $planner::$inflation(self)
                }
            )?
        }
    };
}

pub(crate) use replanner_by_inherent_methods;

#[cfg(test)]
mod tests {
    use trailmark_core::{Cell, Connectivity, Grid, GridHeuristic};
    use trailmark_graph::GridGraph;

    use super::*;
    use crate::anytime::ad_star::AdStar;
    use trailmark_core::termination::Termination;

    use crate::anytime::EpsilonSchedule;
    use crate::incremental::adaptive_astar::AdaptiveAStar;
    use crate::incremental::dstar_lite::DStarLite;
    use crate::incremental::lpa_star::LpaStar;
    use crate::incremental::mpgaa_star::MpgaaStar;
    use crate::incremental::repeated_astar::RepeatedAStar;
    use crate::one_shot::astar::dijkstra;

    /// A small linear congruential generator: the same sequence of changes on every run.
    struct Lcg(u64);

    impl Lcg {
        fn below(&mut self, n: u32) -> u32 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((self.0 >> 33) % u64::from(n)) as u32
        }
    }

    fn same(a: Option<Cost>, b: Option<Cost>) -> bool {
        match (a, b) {
            (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * a.max(1.0),
            (a, b) => a.is_none() && b.is_none(),
        }
    }

    /// The exact planners, told the same changes and start moves through the trait, plan the
    /// same cost as Dijkstra from scratch; AD* with a small budget per plan stays within its
    /// inflation of it.
    #[test]
    fn every_replanner_plans_the_least_cost_after_the_same_changes_and_moves() {
        let (w, h) = (12, 8);
        let mut graph = GridGraph::new(&Grid::new(w, h).unwrap(), Connectivity::Eight);
        let (start, goal) = (Cell::new(0, 0), Cell::new(11, 7));
        let heuristic = graph.heuristic_between(GridHeuristic::Octile);
        let mut exact: Vec<Box<dyn Replanner<GridGraph>>> = vec![
            Box::new(RepeatedAStar::new(&graph, start, goal, heuristic).unwrap()),
            Box::new(LpaStar::new(&graph, start, goal, heuristic).unwrap()),
            Box::new(DStarLite::new(&graph, start, goal, heuristic).unwrap()),
            Box::new(AdStar::new(&graph, start, goal, heuristic, EpsilonSchedule::default()).unwrap()),
            Box::new(AdaptiveAStar::new(&graph, start, goal, heuristic).unwrap()),
            Box::new(MpgaaStar::new(&graph, start, goal, heuristic).unwrap()),
        ];
        let exact_count = exact.len();
        let schedule = EpsilonSchedule::new(2.5, 0.5);
        let limits = Termination::expansions(5);
        let mut bounded =
            AdStar::new(&graph, start, goal, heuristic, schedule).unwrap().with_termination_per_plan(limits);
        let mut rng = Lcg(7);
        let mut robot = start;
        let mut checked = 0;
        for step in 0..60 {
            let mut changed = Vec::new();
            for _ in 0..3 {
                let cell = Cell::new(rng.below(w as u32), rng.below(h as u32));
                if cell == robot || cell == goal {
                    continue;
                }
                let cost = if graph.cost(cell) == Some(f64::INFINITY) {
                    1.0 + f64::from(rng.below(3))
                } else {
                    f64::INFINITY
                };
                graph.set_cost(cell, cost).unwrap();
                changed.extend(graph.cells_affected_by(cell));
            }
            let best = dijkstra(&graph, robot, goal).unwrap().cost();
            let planners =
                exact.iter_mut().map(|p| p.as_mut()).chain([&mut bounded as &mut dyn Replanner<GridGraph>]);
            for (i, planner) in planners.enumerate() {
                planner.update_nodes(&graph, &changed).unwrap();
                planner.move_start(&graph, robot).unwrap();
                let stats = planner.plan(&graph).unwrap();
                assert!(planner.totals().expansions >= stats.expansions);
                let cost = planner.cost();
                if i < exact_count {
                    assert!(same(cost, best), "planner {i} at step {step}: {cost:?} vs {best:?}");
                    assert_eq!(planner.inflation(), 1.0);
                } else if let (Some(cost), Some(best)) = (cost, best) {
                    assert!(cost <= planner.inflation() * best + 1e-9, "bounded AD*: {cost} vs {best}");
                } else {
                    assert_eq!(cost.is_some(), best.is_some());
                }
                let path = planner.path(&graph);
                assert_eq!(path.as_ref().map(|p| p.nodes[0]), cost.map(|_| robot));
                assert_eq!(planner.next_step(&graph), path.and_then(|p| p.nodes.get(1).copied()));
                checked += 1;
            }
            // Half the time the robot follows a plan (D* Lite's or MPGAA*'s); otherwise it jumps
            // elsewhere.
            let next = match step % 4 {
                0 => exact[2].next_step(&graph),
                2 => exact[exact_count - 1].next_step(&graph),
                _ => None,
            };
            robot = next.unwrap_or_else(|| {
                let cells: Vec<Cell> = (0..h as u32)
                    .flat_map(|y| (0..w as u32).map(move |x| Cell::new(x, y)))
                    .filter(|&c| graph.is_passable(c) && c != goal)
                    .collect();
                cells[rng.below(cells.len() as u32) as usize]
            });
        }
        assert_eq!(checked, 60 * (exact_count + 1));
        for planner in &exact {
            assert!(planner.memory_bytes() > 0);
        }
    }
}
