//! The grid section: every one-shot grid planner on the suite's maps beside the `pathfinding`
//! and `grid_pathfinding` crates, each cost checked against the reference (the published optimum
//! on MovingAI maps, trailmark's Dijkstra on generated ones, trailmark's A* for the rule with
//! corners cut).
//!
//! Every planner solves the same queries on the same graph semantics (8-connected, costs 1 and
//! sqrt(2), no corner cutting but for the planners compared with `grid_pathfinding`, whose only
//! rule cuts them); a disagreement with the reference fails the run, a benchmark of wrong answers
//! measuring nothing, but for a peer's known flaw, which is counted and reported.

use std::time::Instant;

use grid_pathfinding::PathingGrid;
use grid_util::grid::ValueGrid;
use grid_util::point::Point;
use serde::Serialize;
use trailmark::prelude::*;
use trailmark::search::closures;

use crate::bench::peer::{neighbours, octile};
use crate::bench::progress::SectionProgress;
use crate::bench::stats::median;
use crate::bench::suite::{GridQuery, SuiteMap};
use crate::reference::tolerance;

mod report;

pub use report::{PeerRatio, goals, markdown, ratios, time_svg};

/// The weight of the benchmarked weighted A*.
pub const WEIGHT: f64 = 2.0;

/// What one query gave: the cost (`None`: no path, or a path that is not one of the grid's) and,
/// for trailmark, the expansions.
type Solved = (Option<f64>, Option<u64>);

/// How a planner solves a query.
#[derive(Clone, Copy)]
enum Kind {
    /// A search over the grid graph of the planner's rule, with a trailmark workspace.
    Graph(fn(&GridGraph, &mut Search, &GridQuery) -> Solved),
    /// trailmark's jump point search, made once per map.
    Jps,
    /// trailmark's JPS+, its table made once per map.
    JpsPlus,
    /// The `grid_pathfinding` crate's jump point search, its grid made once per map.
    GridPathfinding,
}

/// A planner of the section: everything the harness needs to know of it, in one entry of
/// [`PLANNERS`].
pub struct GridPlanner {
    /// The name in `--only` and the report.
    pub name: &'static str,
    /// The library it comes from.
    library: &'static str,
    /// The grid's rule for diagonal moves (the reference costs are of the same rule).
    rule: CornerCutting,
    /// The factor the cost may exceed the optimum by (`None`: no bound, BFS and DFS).
    bound: Option<f64>,
    /// Whether its paths above the bound are a known flaw of a peer, counted and reported but not
    /// failing the run.
    known_flaw: bool,
    /// Whether its paths are any-angle lines, which may be shorter than the grid's optimum
    /// (but never shorter than the straight line from start to goal).
    any_angle: bool,
    /// The planners this one is compared with in the report.
    peers: &'static [&'static str],
    /// Its colour in the time plot (`None`: not plotted).
    plot_colour: Option<usize>,
    /// How it solves a query.
    kind: Kind,
}

const NO_CUT: CornerCutting = CornerCutting::Forbidden;

/// The rule `grid_pathfinding` 0.3 follows: a diagonal move needs only its target free.
const SQUEEZE: CornerCutting = CornerCutting::Squeeze;

/// How far `grid_pathfinding`'s cost may exceed the optimum: it prices moves 70 and 99, so its
/// least-cost paths are least-cost for a diagonal of 99/70 = sqrt(2) (1 + 5.1e-5), and within
/// that factor of the optimum at sqrt(2).
const GRID_PATHFINDING_BOUND: f64 = 1.0 + 6e-5;

/// The registry's planners this section measures: its own planners that are registered (the
/// others are variants, as closure A*, or peers).
pub fn measured() -> impl Iterator<Item = trailmark::solve::PlannerName> {
    PLANNERS
        .iter()
        .filter(|p| p.library == TRAILMARK)
        .filter_map(|p| trailmark::solve::PlannerName::from_name(p.name))
}

/// An entry of [`PLANNERS`] in all it does not say otherwise: a trailmark planner held to the
/// optimum without corner cutting, compared with no peer, not plotted. Its name and kind only
/// hold places: every entry gives its own.
const DEFAULTS: GridPlanner = GridPlanner {
    name: "",
    library: TRAILMARK,
    rule: NO_CUT,
    bound: Some(1.0),
    known_flaw: false,
    any_angle: false,
    peers: &[],
    plot_colour: None,
    kind: Kind::Graph(|_, _, _| unreachable!("every planner says how it solves")),
};

/// The planners, in the order they run and are reported.
pub const PLANNERS: [GridPlanner; 14] = [
    GridPlanner {
        name: "astar",
        peers: &["pathfinding_astar"],
        plot_colour: Some(0),
        kind: Kind::Graph(|graph, search, q| {
            ours(search.astar(graph, q.start, q.goal, graph.heuristic(GridHeuristic::Octile, q.goal)))
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "jps",
        peers: &["pathfinding_astar", "astar"],
        plot_colour: Some(1),
        kind: Kind::Jps,
        ..DEFAULTS
    },
    GridPlanner {
        name: "jps_plus",
        peers: &["pathfinding_astar", "astar"],
        plot_colour: Some(4),
        kind: Kind::JpsPlus,
        ..DEFAULTS
    },
    GridPlanner {
        name: "closure_astar",
        peers: &["pathfinding_astar", "astar"],
        // The graph as `pathfinding` takes it: a successor closure over hashed cells.
        kind: Kind::Graph(|graph, _, q| {
            let h = graph.heuristic(GridHeuristic::Octile, q.goal);
            ours(closures::astar(&q.start, |&p| graph.neighbours(p), |&p| h(p), |&p| p == q.goal))
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "pathfinding_astar",
        library: PATHFINDING,
        plot_colour: Some(2),
        kind: Kind::Graph(|graph, _, q| {
            let h = |p: &Cell| octile(p, q.goal, 1.0);
            let r = pathfinding::prelude::astar(&q.start, |&p| neighbours(graph, p), h, |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "pathfinding_fringe",
        library: PATHFINDING,
        plot_colour: Some(3),
        // As `pathfinding_astar` but for the peer's function (generic, so not passed as a value).
        kind: Kind::Graph(|graph, _, q| {
            let h = |p: &Cell| octile(p, q.goal, 1.0);
            let r = pathfinding::prelude::fringe(&q.start, |&p| neighbours(graph, p), h, |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "jps_squeeze",
        rule: SQUEEZE,
        peers: &["grid_pathfinding_jps"],
        kind: Kind::Jps,
        ..DEFAULTS
    },
    GridPlanner {
        name: "grid_pathfinding_jps",
        library: GRID_PATHFINDING,
        rule: SQUEEZE,
        bound: Some(GRID_PATHFINDING_BOUND),
        // Its paths are drawn between jump points that need not lie on one line (the parent of a
        // jump point found past an unforced diagonal one is the cell before that one), and are
        // then longer than the optimum: on most queries of the random maps (docs/jump-points.md).
        known_flaw: true,
        kind: Kind::GridPathfinding,
        ..DEFAULTS
    },
    GridPlanner {
        name: "weighted_astar",
        bound: Some(WEIGHT),
        kind: Kind::Graph(|graph, search, q| {
            ours(search.weighted_astar(
                graph,
                q.start,
                q.goal,
                graph.heuristic(GridHeuristic::Octile, q.goal),
                WEIGHT,
            ))
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "dijkstra",
        peers: &["pathfinding_dijkstra"],
        kind: Kind::Graph(|graph, search, q| ours(search.dijkstra(graph, q.start, q.goal))),
        ..DEFAULTS
    },
    GridPlanner {
        name: "pathfinding_dijkstra",
        library: PATHFINDING,
        kind: Kind::Graph(|graph, _, q| {
            let r = pathfinding::prelude::dijkstra(&q.start, |&p| neighbours(graph, p), |&p| p == q.goal);
            (r.map(|(_, c)| c.0), None)
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "theta_star",
        any_angle: true,
        kind: Kind::Graph(|graph, search, q| {
            let h = graph.heuristic(GridHeuristic::Euclidean, q.goal);
            ours(search.theta_star(graph, q.start, q.goal, h, graph))
        }),
        ..DEFAULTS
    },
    GridPlanner {
        name: "bfs",
        bound: None,
        kind: Kind::Graph(|graph, search, q| ours(search.bfs(graph, q.start, q.goal))),
        ..DEFAULTS
    },
    GridPlanner {
        name: "dfs",
        bound: None,
        kind: Kind::Graph(|graph, search, q| ours(search.dfs(graph, q.start, q.goal))),
        ..DEFAULTS
    },
];

const TRAILMARK: &str = "trailmark";
const PATHFINDING: &str = "pathfinding 4";
const GRID_PATHFINDING: &str = "grid_pathfinding 0.3";

/// A trailmark search's cost and expansions.
fn ours(r: Result<SearchResult<Cell>, SearchError<Cell>>) -> Solved {
    let r = r.expect("benchmark queries are valid");
    (r.cost(), Some(r.stats.expansions))
}

/// A planner made for one map, holding what it keeps between queries.
enum Prepared<'a> {
    Graph(&'a GridGraph, Search, fn(&GridGraph, &mut Search, &GridQuery) -> Solved),
    Jps(Jps),
    JpsPlus(JpsPlus),
    GridPathfinding(&'a GridGraph, PathingGrid),
}

impl<'a> Prepared<'a> {
    /// `planner` made for `grid`, whose graph under the planner's rule is `graph`.
    fn new(planner: &GridPlanner, grid: &Grid, graph: &'a GridGraph) -> Self {
        let uniform = "the suite's maps have uniform costs";
        match planner.kind {
            Kind::Graph(solve) => Prepared::Graph(graph, Search::new(), solve),
            Kind::Jps => Prepared::Jps(Jps::new(grid, planner.rule).expect(uniform)),
            Kind::JpsPlus => Prepared::JpsPlus(JpsPlus::new(grid, planner.rule).expect(uniform)),
            Kind::GridPathfinding => {
                let mut pathing = PathingGrid::new(grid.width() as usize, grid.height() as usize, false);
                for cell in grid.cells().filter(|&c| !grid.is_passable(c)) {
                    pathing.set(cell.x as i32, cell.y as i32, true);
                }
                pathing.generate_components();
                Prepared::GridPathfinding(graph, pathing)
            }
        }
    }

    fn solve(&mut self, q: &GridQuery) -> Solved {
        match self {
            Prepared::Graph(graph, search, solve) => solve(graph, search, q),
            Prepared::Jps(jps) => ours(jps.search(q.start, q.goal)),
            Prepared::JpsPlus(plus) => ours(plus.search(q.start, q.goal)),
            Prepared::GridPathfinding(graph, pathing) => {
                let point = |c: Cell| Point::new(c.x as i32, c.y as i32);
                let path = pathing.get_path_single_goal(point(q.start), point(q.goal), false);
                (path.and_then(|p| peer_path_cost(graph, q, &p)), None)
            }
        }
    }

    /// Bytes held between queries (`None`: not known, a peer's).
    fn memory_bytes(&self) -> Option<usize> {
        match self {
            Prepared::Graph(_, search, _) => Some(search.memory_bytes()),
            Prepared::Jps(jps) => Some(jps.memory_bytes()),
            Prepared::JpsPlus(plus) => Some(plus.memory_bytes()),
            Prepared::GridPathfinding(..) => None,
        }
    }
}

/// The cost of a peer's path by the grid graph's moves (`None`: a step that is not a move, or a
/// path that does not join the query's cells).
fn peer_path_cost(graph: &GridGraph, q: &GridQuery, path: &[Point]) -> Option<f64> {
    let cells: Vec<Cell> = path
        .iter()
        .map(|p| Some(Cell::new(u32::try_from(p.x).ok()?, u32::try_from(p.y).ok()?)))
        .collect::<Option<_>>()?;
    if cells.first() != Some(&q.start) || cells.last() != Some(&q.goal) {
        return None;
    }
    cells.windows(2).map(|w| graph.edge_cost(w[0], w[1])).sum()
}

/// The planners `only` names (all of them when it names none).
pub fn chosen(only: &[String]) -> Vec<&'static GridPlanner> {
    PLANNERS.iter().filter(|p| only.is_empty() || only.iter().any(|o| o == p.name)).collect()
}

/// The results of one planner on one map.
#[derive(Debug, Clone, Serialize)]
pub struct GridRow {
    map: String,
    planner: &'static str,
    library: &'static str,
    queries: usize,
    solved: usize,
    /// Median over queries of the per-query time (itself a median over the rounds), µs.
    median_us: f64,
    mean_us: f64,
    p90_us: f64,
    /// Expansions summed over the queries (trailmark planners only).
    expansions: Option<u64>,
    /// Millions of expansions per second of search time.
    mexp_per_s: Option<f64>,
    /// Mean of cost / reference cost over solved queries.
    mean_cost_ratio: f64,
    /// Queries whose cost broke the planner's bound (must be 0 but for a peer's known flaw).
    pub cost_errors: usize,
    /// Whether those are a peer's known flaw, which does not fail the run.
    pub known_flaw: bool,
    /// Time to make the planner for the map (its tables, its copy of the grid), ms.
    prepare_ms: f64,
    /// Bytes held between queries after the map's queries (trailmark planners only).
    workspace_bytes: Option<usize>,
    /// Those bytes per cell of the map.
    bytes_per_cell: Option<f64>,
    /// Each query's time (its median over the rounds), µs, sorted (for the plots; not
    /// serialized).
    #[serde(skip)]
    times_us: Vec<f64>,
}

/// Runs `planners` on every map, `runs` rounds each.
pub fn bench_grid(maps: &[SuiteMap], planners: &[&GridPlanner], runs: u32) -> Vec<GridRow> {
    let mut rows = Vec::new();
    let mut progress = SectionProgress::new("grid", maps.len());
    for map in maps {
        progress.step(format!("{} ({} queries)", map.name, map.queries.len()));
        rows.extend(bench_map(map, planners, runs));
    }
    rows
}

/// Runs every planner on `map`: `runs` rounds, planners alternating within each round.
fn bench_map(map: &SuiteMap, planners: &[&GridPlanner], runs: u32) -> Vec<GridRow> {
    let graph = GridGraph::new(&map.grid, Connectivity::Eight);
    // The rule with corner cutting has its own graph, and its reference costs from trailmark's
    // A* on it (checked against `grid_pathfinding`'s paths within that peer's bound).
    let squeeze = planners
        .iter()
        .any(|p| p.rule == SQUEEZE)
        .then(|| GridGraph::new(&map.grid, Connectivity::Eight).with_corner_cutting(SQUEEZE));
    let squeeze_optimal: Vec<f64> = squeeze.as_ref().map_or(Vec::new(), |g| {
        let mut search = Search::new();
        map.queries
            .iter()
            .map(|q| {
                let found = search.astar(g, q.start, q.goal, g.heuristic(GridHeuristic::Octile, q.goal));
                found
                    .expect("benchmark queries are valid")
                    .cost()
                    .expect("a path without corner cutting is one with it")
            })
            .collect()
    });
    let graph_of =
        |rule: CornerCutting| if rule == SQUEEZE { squeeze.as_ref().expect("made above") } else { &graph };
    let n = map.queries.len();
    let mut prepare_s = Vec::with_capacity(planners.len());
    let mut prepared: Vec<Prepared> = planners
        .iter()
        .map(|p| {
            let clock = Instant::now();
            let made = Prepared::new(p, &map.grid, graph_of(p.rule));
            prepare_s.push(clock.elapsed().as_secs_f64());
            made
        })
        .collect();
    let mut times = vec![vec![Vec::with_capacity(runs as usize); n]; planners.len()];
    let mut outcomes = vec![vec![(None, None); n]; planners.len()];
    for _ in 0..runs {
        for (k, made) in prepared.iter_mut().enumerate() {
            for (i, q) in map.queries.iter().enumerate() {
                let clock = Instant::now();
                let outcome = made.solve(q);
                times[k][i].push(clock.elapsed().as_secs_f64());
                outcomes[k][i] = outcome;
            }
        }
    }
    let cells = map.grid.width() as f64 * map.grid.height() as f64;
    planners
        .iter()
        .enumerate()
        .map(|(k, planner)| {
            let mut per_query: Vec<f64> = times[k]
                .iter_mut()
                .map(|t| {
                    t.sort_by(f64::total_cmp);
                    median(t)
                })
                .collect();
            let total: f64 = per_query.iter().sum();
            per_query.sort_by(f64::total_cmp);
            let mut solved = 0;
            let mut ratio_sum = 0.0;
            let mut cost_errors = 0;
            let mut expansions = Some(0u64);
            for (i, (q, &(cost, exp))) in map.queries.iter().zip(&outcomes[k]).enumerate() {
                expansions = expansions.zip(exp).map(|(a, b)| a + b);
                let Some(cost) = cost else {
                    cost_errors += 1; // every query is solvable
                    continue;
                };
                solved += 1;
                let optimal = if planner.rule == SQUEEZE { squeeze_optimal[i] } else { q.optimal };
                ratio_sum += if optimal > 0.0 { cost / optimal } else { 1.0 };
                // No grid path beats the optimum (no any-angle path the straight line); bounded
                // planners stay within their bound.
                let tol = tolerance(optimal);
                let above_bound = planner.bound.is_some_and(|b| cost > b * optimal + tol);
                let floor = if planner.any_angle {
                    f64::from(q.start.x.abs_diff(q.goal.x)).hypot(f64::from(q.start.y.abs_diff(q.goal.y)))
                } else {
                    optimal
                };
                if cost < floor - tol || above_bound {
                    cost_errors += 1;
                }
            }
            let bytes = prepared[k].memory_bytes();
            GridRow {
                map: map.name.clone(),
                planner: planner.name,
                library: planner.library,
                queries: n,
                solved,
                median_us: median(&per_query) * 1e6,
                mean_us: total / n as f64 * 1e6,
                p90_us: per_query.get(n * 9 / 10).copied().unwrap_or(f64::NAN) * 1e6,
                mexp_per_s: expansions.map(|e| e as f64 / total / 1e6),
                expansions,
                mean_cost_ratio: ratio_sum / solved.max(1) as f64,
                cost_errors,
                known_flaw: planner.known_flaw,
                prepare_ms: prepare_s[k] * 1e3,
                workspace_bytes: bytes,
                bytes_per_cell: bytes.map(|b| b as f64 / cells),
                times_us: per_query.iter().map(|t| t * 1e6).collect(),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::PLANNERS;

    /// Every entry of the table names itself (over the placeholder of `DEFAULTS`), and no two
    /// share a name.
    #[test]
    fn planners_have_distinct_names() {
        let names: Vec<&str> = PLANNERS.iter().map(|p| p.name).collect();
        assert!(names.iter().all(|n| !n.is_empty()), "a planner without a name: {names:?}");
        let distinct: std::collections::BTreeSet<&str> = names.iter().copied().collect();
        assert_eq!(distinct.len(), names.len(), "two planners share a name: {names:?}");
    }
}
