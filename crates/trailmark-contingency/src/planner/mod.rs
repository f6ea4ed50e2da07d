//! The contingency planner: best-first search (AO*) over partial plans.
//!
//! A *state* is where the vehicle is (a node of the [`Abstraction`]) and what it knows about the
//! choke points ([`Knowledge`]). In a state the vehicle either drives to the goal over choke
//! points known to be open, or drives to a node beside choke points it has not seen yet; on
//! arrival it sees them, and each combination of open and blocked leads to a new state with
//! its probability. A state where no route to the goal is left, even through the unseen choke
//! points, is *stuck*: the vehicle stops, and the outcome costs what was driven until then.
//! Knowledge only grows along a plan, so the states form a directed acyclic AND-OR graph.
//!
//! The expected cost of a state is the minimum over its actions of the route's cost plus the
//! probability-weighted expected costs of the states it leads to. AO* keeps the best partial
//! plan under the current estimates, expands its unexpanded states, and backs the new values up
//! to the root, until the best plan has nothing left to expand. Unexpanded states are valued by
//! an admissible estimate: the probability that the goal can still be reached (exact, by
//! enumerating the unseen choke points that matter, or a lower bound when there are many) times
//! a lower bound on the route to the goal with every unseen choke point open (cached segment
//! costs, lower bounds for the rest), plus the probability that it cannot times a lower bound on
//! the drive to the nearest choke point that matters (the vehicle finds out only there). So the
//! plan found is optimal.
//!
//! The nesting depth bounds how many blockages a plan prepares for: once a branch has seen
//! [`PlannerOptions::max_blockages`] blocked choke points, it follows the cheapest route as if
//! the unseen choke points were open and replans at each further blockage (the naive strategy,
//! whose expected cost is computed exactly, outcome by outcome).

use std::collections::{BinaryHeap, HashMap};

use std::time::Instant;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use trailmark_core::cost::Cost;
use trailmark_core::grid::Cell;

use crate::abstraction::{Abstraction, AbstractionStats, Hop, NodeId, Routes};
use crate::plan::{Action, Drive, Knowledge, Outcome, PlanNode, outcomes};
use crate::terrain::Terrain;

mod reach;

/// How the planner searches.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PlannerOptions {
    /// The nesting depth: how many blocked choke points one branch of the plan prepares for.
    /// Beyond it the branch replans naively. `usize::MAX` prepares for every combination.
    pub max_blockages: usize,
    /// The most states the search may create before giving up with
    /// [`ContingencyError::TooManyStates`].
    pub max_states: usize,
}

impl Default for PlannerOptions {
    fn default() -> Self {
        PlannerOptions { max_blockages: 3, max_states: 2_000_000 }
    }
}

/// Why no plan was returned.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContingencyError {
    /// The search created more states than [`PlannerOptions::max_states`].
    #[error("the search created more than {limit} states; lower max_blockages or raise max_states")]
    TooManyStates {
        /// The limit.
        limit: usize,
    },
}

/// What the planner did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct ContingencyStats {
    /// States created.
    pub states: usize,
    /// States expanded (their actions generated).
    pub expansions: usize,
    /// Rounds of expansion and backup.
    pub iterations: usize,
    /// States beyond the nesting depth, valued by naive replanning.
    pub replan_states: usize,
    /// Looks left out because a look on the way to them sees the same choke points.
    pub dominated: usize,
    /// What the abstraction computed.
    pub abstraction: AbstractionStats,
    /// Wall time in seconds.
    pub time_s: f64,
}

/// A plan with its expected cost and the planner's statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct ContingencyPlan {
    /// The expected cost of the plan over every outcome (stuck outcomes cost what was driven).
    pub expected_cost: Cost,
    /// The probability that the goal turns out unreachable.
    pub stuck_probability: f64,
    /// The plan, from the start.
    pub plan: PlanNode,
    /// What the planner did.
    pub stats: ContingencyStats,
}

/// Plans with contingencies for `terrain`, minimising the expected cost.
///
/// ```
/// use trailmark_core::{Cell, Connectivity};
/// use trailmark_contingency::{ChokePoint, PlannerOptions, Terrain, grid_from_rows, plan};
///
/// // A river with two bridges: the near one is often closed.
/// let grid = grid_from_rows(
///     &["....~....", "....=....", "....~....", "....~....", "....~....", "....=....", "....~...."],
///     Some(&[('.', Some(1.0)), ('=', Some(1.0)), ('~', None)].into_iter().collect()),
/// )?;
/// let bridge = |name: &str, y, p| ChokePoint { name: name.into(), cells: vec![Cell::new(4, y)], probability: p };
/// let terrain = Terrain::new(
///     grid,
///     Connectivity::Eight,
///     Cell::new(0, 1),
///     Cell::new(8, 1),
///     vec![bridge("near", 1, 0.5), bridge("far", 5, 0.0)],
/// )?;
/// let planned = plan(&terrain, &PlannerOptions::default())?;
/// // Try the near bridge (8 moves); when it is closed, drive down to the far one.
/// assert!(planned.expected_cost < 12.0);
/// assert_eq!(planned.stuck_probability, 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn plan(terrain: &Terrain, options: &PlannerOptions) -> Result<ContingencyPlan, ContingencyError> {
    let started = Instant::now();
    let mut search = AoStar::new(terrain, *options);
    search.run()?;
    let plan = search.extract(ROOT);
    let mut stats = search.stats;
    stats.abstraction = search.abs.stats();
    stats.time_s = started.elapsed().as_secs_f64();
    Ok(ContingencyPlan {
        expected_cost: search.states[ROOT].f,
        stuck_probability: plan.stuck_probability(),
        plan,
        stats,
    })
}

/// The root state: the vehicle at the start, before looking around. It is not interned, so it
/// never merges with the state after looking.
const ROOT: usize = 0;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Target {
    Goal,
    Look(NodeId),
}

#[derive(Debug, Clone)]
struct Choice {
    target: Target,
    transit: Cost,
    /// `(probability, blocked mask among those seen, state)`.
    children: Vec<(f64, u64, usize)>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    /// Valued by the estimate; not expanded yet.
    Tip,
    Expanded,
    /// At the goal.
    Goal,
    /// No route to the goal is left.
    Stuck,
    /// Beyond the nesting depth: valued exactly by naive replanning.
    Replan,
}

#[derive(Debug, Clone)]
struct State {
    node: NodeId,
    k: Knowledge,
    f: Cost,
    kind: Kind,
    solved: bool,
    best: usize,
    choices: Vec<Choice>,
    parents: Vec<usize>,
}

struct AoStar<'t> {
    terrain: &'t Terrain,
    abs: Abstraction<'t>,
    options: PlannerOptions,
    states: Vec<State>,
    index: HashMap<(NodeId, Knowledge), usize>,
    bounds: HashMap<u64, Routes>,
    reach: HashMap<(u32, Knowledge), (f64, u64)>,
    replan: HashMap<(NodeId, Knowledge), Cost>,
    stats: ContingencyStats,
}

impl<'t> AoStar<'t> {
    fn new(terrain: &'t Terrain, options: PlannerOptions) -> Self {
        let abs = Abstraction::new(terrain);
        let root = State {
            node: abs.start(),
            k: Knowledge::default(),
            f: 0.0,
            kind: Kind::Tip,
            solved: false,
            best: 0,
            choices: Vec::new(),
            parents: Vec::new(),
        };
        AoStar {
            terrain,
            abs,
            options,
            states: vec![root],
            index: HashMap::new(),
            bounds: HashMap::new(),
            reach: HashMap::new(),
            replan: HashMap::new(),
            stats: ContingencyStats { states: 1, ..ContingencyStats::default() },
        }
    }

    fn all(&self) -> u64 {
        self.terrain.choke_mask()
    }

    /// The children of arriving at `node` with knowledge `k`: one per combination of the unseen
    /// choke points beside it.
    fn arrive(
        &mut self,
        parent: usize,
        node: NodeId,
        k: Knowledge,
    ) -> Result<Vec<(f64, u64, usize)>, ContingencyError> {
        let seen = self.abs.nodes()[node as usize].beside & k.unknown(self.all());
        let mut children = Vec::new();
        for (blocked, p) in outcomes(seen, self.terrain) {
            let child = self.state(node, k.after(seen, blocked))?;
            self.states[child].parents.push(parent);
            children.push((p, blocked, child));
        }
        Ok(children)
    }

    /// The state `(node, k)`, created and valued if new.
    fn state(&mut self, node: NodeId, k: Knowledge) -> Result<usize, ContingencyError> {
        if let Some(&s) = self.index.get(&(node, k)) {
            return Ok(s);
        }
        if self.states.len() >= self.options.max_states {
            return Err(ContingencyError::TooManyStates { limit: self.options.max_states });
        }
        let (kind, f) = if node == self.abs.goal() {
            (Kind::Goal, 0.0)
        } else if !self.bound(node, k).is_finite() {
            (Kind::Stuck, 0.0)
        } else if (k.blocked.count_ones() as usize) >= self.options.max_blockages {
            self.stats.replan_states += 1;
            (Kind::Replan, self.replan_cost(node, k))
        } else {
            let (p, relevant) = self.reach_probability(node, k);
            let bound = self.bound(node, k);
            let h = if p < 1.0 { p * bound + (1.0 - p) * self.nearest_look(node, relevant) } else { bound };
            (Kind::Tip, h)
        };
        let s = self.states.len();
        self.states.push(State {
            node,
            k,
            f,
            kind,
            solved: kind != Kind::Tip,
            best: 0,
            choices: Vec::new(),
            parents: Vec::new(),
        });
        self.index.insert((node, k), s);
        self.stats.states += 1;
        Ok(s)
    }

    /// A lower bound on the route from `node` to the goal with every choke point not known to be
    /// blocked open.
    fn bound(&mut self, node: NodeId, k: Knowledge) -> Cost {
        let crossable = self.all() & !k.blocked;
        if !self.bounds.contains_key(&crossable) {
            let routes = self.abs.bounds_to_goal(crossable);
            self.bounds.insert(crossable, routes);
        }
        self.bounds[&crossable].cost[node as usize]
    }

    /// A lower bound on the cost of reaching a node beside one of the choke points `relevant`
    /// from `node`. When the goal turns out unreachable, the vehicle has seen one of them blocked
    /// (the others cannot cut it off), so it has driven at least this far.
    fn nearest_look(&self, node: NodeId, relevant: u64) -> Cost {
        let mut nearest = f64::INFINITY;
        for c in ids(relevant) {
            for &v in self.abs.nodes_beside(c) {
                nearest = nearest.min(self.abs.distance_bound(node, v));
            }
        }
        nearest
    }

    /// The exact expected cost of naive replanning from `(node, k)`: drive the cheapest route with
    /// every unseen choke point taken as open, stopping at each node beside unseen choke points
    /// to look, and plan again from there.
    fn replan_cost(&mut self, node: NodeId, k: Knowledge) -> Cost {
        if let Some(&c) = self.replan.get(&(node, k)) {
            return c;
        }
        let cost = match self.replan_step(node, k) {
            None => 0.0,
            Some((to, transit, 0)) => {
                debug_assert_eq!(to, self.abs.goal());
                transit
            }
            Some((to, transit, seen)) => {
                let mut total = transit;
                for (blocked, p) in outcomes(seen, self.terrain) {
                    total += p * self.replan_cost(to, k.after(seen, blocked));
                }
                total
            }
        };
        self.replan.insert((node, k), cost);
        cost
    }

    /// The next drive of naive replanning: `(to, cost, unseen choke points beside to)`, or `None`
    /// when stuck.
    fn replan_step(&mut self, node: NodeId, k: Knowledge) -> Option<(NodeId, Cost, u64)> {
        let routes = self.abs.routes(node, self.all() & !k.blocked);
        let goal = self.abs.goal();
        let hops = routes.hops_to(goal)?;
        let unknown = k.unknown(self.all());
        let stop = hops[1..hops.len().saturating_sub(1)]
            .iter()
            .map(|&(n, _)| n)
            .find(|&n| self.abs.nodes()[n as usize].beside & unknown != 0);
        Some(match stop {
            Some(n) => (n, routes.cost[n as usize], self.abs.nodes()[n as usize].beside & unknown),
            None => (goal, routes.cost[goal as usize], 0),
        })
    }

    /// Generates the choices of a tip.
    fn expand(&mut self, s: usize) -> Result<(), ContingencyError> {
        self.stats.expansions += 1;
        let mut choices = Vec::new();
        if s == ROOT {
            let start = self.abs.start();
            let children = self.arrive(s, start, Knowledge::default())?;
            choices.push(Choice { target: Target::Look(start), transit: 0.0, children });
        } else {
            let (node, k) = (self.states[s].node, self.states[s].k);
            let routes = self.abs.routes(node, k.open());
            let goal = self.abs.goal();
            if routes.cost[goal as usize].is_finite() {
                choices.push(Choice {
                    target: Target::Goal,
                    transit: routes.cost[goal as usize],
                    children: Vec::new(),
                });
            }
            let unknown = k.unknown(self.all());
            let blocked = k.blocked.count_ones() as usize;
            for v in 0..self.abs.nodes().len() as NodeId {
                let transit = routes.cost[v as usize];
                let seen = self.abs.nodes()[v as usize].beside & unknown;
                if v == goal || !transit.is_finite() || seen == 0 {
                    continue;
                }
                // Looking at `v` is dominated when the cheapest route to it passes a node that
                // sees the same choke points: whatever is seen, going on from there to `v` and
                // doing what would be done from `v` costs the same, so the earlier look is at least
                // as good. Beyond the nesting depth the states are valued by naive replanning,
                // for which that argument does not hold, so those looks are all kept.
                if blocked + (seen.count_ones() as usize) < self.options.max_blockages
                    && self.seen_on_the_way(&routes, v, seen, unknown)
                {
                    self.stats.dominated += 1;
                    continue;
                }
                let children = self.arrive(s, v, k)?;
                choices.push(Choice { target: Target::Look(v), transit, children });
            }
        }
        let state = &mut self.states[s];
        state.choices = choices;
        state.kind = Kind::Expanded;
        if state.choices.is_empty() {
            // Unreachable by construction (a finite bound leaves a choke point to look at), but a
            // state without choices is stuck, not an error.
            state.kind = Kind::Stuck;
            state.f = 0.0;
            state.solved = true;
        }
        Ok(())
    }

    /// Whether the cheapest route to `v` passes a node (other than the goal) that sees exactly the
    /// unknown choke points `seen` that `v` sees.
    fn seen_on_the_way(&self, routes: &Routes, v: NodeId, seen: u64, unknown: u64) -> bool {
        let goal = self.abs.goal();
        let mut at = v;
        while let Some((previous, _)) = routes.previous[at as usize] {
            if previous != goal && self.abs.nodes()[previous as usize].beside & unknown == seen {
                return true;
            }
            at = previous;
        }
        false
    }

    /// The value of a choice under the current estimates.
    fn q(&self, c: &Choice) -> Cost {
        c.transit + c.children.iter().map(|&(p, _, s)| p * self.states[s].f).sum::<Cost>()
    }

    /// Recomputes the value, best choice and solved label of the expanded states and of their
    /// ancestors, children before parents.
    fn backup(&mut self, expanded: &[usize]) {
        let depth = |st: &State, s: usize| if s == ROOT { -1 } else { st.k.known.count_ones() as i64 };
        let mut queue: BinaryHeap<(i64, usize)> =
            expanded.iter().map(|&s| (depth(&self.states[s], s), s)).collect();
        let mut queued: std::collections::HashSet<usize> = expanded.iter().copied().collect();
        while let Some((_, s)) = queue.pop() {
            queued.remove(&s);
            let state = &self.states[s];
            if state.kind != Kind::Expanded {
                continue;
            }
            let mut best = 0;
            let mut f = f64::INFINITY;
            for (i, c) in state.choices.iter().enumerate() {
                let q = self.q(c);
                if q < f {
                    f = q;
                    best = i;
                }
            }
            let solved = state.choices[best].children.iter().all(|&(_, _, c)| self.states[c].solved);
            let changed = f != state.f || solved != state.solved || best != state.best;
            let state = &mut self.states[s];
            (state.f, state.best, state.solved) = (f, best, solved);
            if changed {
                for &p in &self.states[s].parents {
                    if queued.insert(p) {
                        queue.push((depth(&self.states[p], p), p));
                    }
                }
            }
        }
    }

    /// The unexpanded states of the best partial plan.
    fn tips(&self) -> Vec<usize> {
        let mut tips = Vec::new();
        let mut seen = std::collections::HashSet::new();
        let mut stack = vec![ROOT];
        while let Some(s) = stack.pop() {
            if !seen.insert(s) || self.states[s].solved {
                continue;
            }
            match self.states[s].kind {
                Kind::Tip => tips.push(s),
                Kind::Expanded => {
                    let state = &self.states[s];
                    stack.extend(state.choices[state.best].children.iter().rev().map(|&(_, _, c)| c));
                }
                _ => {}
            }
        }
        tips
    }

    fn run(&mut self) -> Result<(), ContingencyError> {
        while !self.states[ROOT].solved {
            self.stats.iterations += 1;
            let tips = self.tips();
            for &s in &tips {
                self.expand(s)?;
            }
            self.backup(&tips);
        }
        Ok(())
    }

    /// The plan from state `s` (following naive replanning beyond the nesting depth).
    fn extract(&mut self, s: usize) -> PlanNode {
        let (node, k, kind) = (self.states[s].node, self.states[s].k, self.states[s].kind);
        let at = self.abs.nodes()[node as usize].cell;
        let f = self.states[s].f;
        match kind {
            Kind::Goal => PlanNode { at, expected_cost: 0.0, action: Action::Arrived },
            Kind::Stuck => PlanNode { at, expected_cost: 0.0, action: Action::Stuck },
            Kind::Replan => self.extract_replan(node, k),
            Kind::Tip => unreachable!("the plan is solved"),
            Kind::Expanded => {
                let choice = self.states[s].choices[self.states[s].best].clone();
                if s == ROOT && choice.children.len() == 1 && choice.children[0].1 == 0 {
                    // Nothing to see at the start: the plan begins with the first drive.
                    let first = self.extract(choice.children[0].2);
                    return first;
                }
                let (to, crossable) = match choice.target {
                    Target::Goal => (self.abs.goal(), k.open()),
                    Target::Look(v) => (v, k.open()),
                };
                let seen = self.abs.nodes()[to as usize].beside & k.unknown(self.all());
                let (route, crosses) =
                    if s == ROOT { (vec![at], Vec::new()) } else { self.route(node, to, crossable) };
                let outcomes = if choice.children.is_empty() {
                    vec![Outcome {
                        blocked: Vec::new(),
                        probability: 1.0,
                        next: PlanNode {
                            at: self.abs.nodes()[to as usize].cell,
                            expected_cost: 0.0,
                            action: Action::Arrived,
                        },
                    }]
                } else {
                    choice
                        .children
                        .iter()
                        .map(|&(p, blocked, c)| Outcome {
                            blocked: ids(blocked),
                            probability: p,
                            next: self.extract(c),
                        })
                        .collect()
                };
                PlanNode {
                    at,
                    expected_cost: f,
                    action: Action::Drive(Drive {
                        to: self.abs.nodes()[to as usize].cell,
                        cost: choice.transit,
                        crosses,
                        sees: if choice.children.is_empty() { Vec::new() } else { ids(seen) },
                        replan: false,
                        route,
                        outcomes,
                    }),
                }
            }
        }
    }

    /// The plan of naive replanning from `(node, k)`.
    fn extract_replan(&mut self, node: NodeId, k: Knowledge) -> PlanNode {
        let at = self.abs.nodes()[node as usize].cell;
        let expected_cost = self.replan_cost(node, k);
        let Some((to, cost, seen)) = self.replan_step(node, k) else {
            return PlanNode { at, expected_cost: 0.0, action: Action::Stuck };
        };
        let (route, crosses) = self.route(node, to, self.all() & !k.blocked);
        let to_cell = self.abs.nodes()[to as usize].cell;
        let outcomes = if seen == 0 {
            vec![Outcome {
                blocked: Vec::new(),
                probability: 1.0,
                next: PlanNode { at: to_cell, expected_cost: 0.0, action: Action::Arrived },
            }]
        } else {
            outcomes(seen, self.terrain)
                .into_iter()
                .map(|(blocked, p)| Outcome {
                    blocked: ids(blocked),
                    probability: p,
                    next: self.extract_replan(to, k.after(seen, blocked)),
                })
                .collect()
        };
        PlanNode {
            at,
            expected_cost,
            action: Action::Drive(Drive {
                to: to_cell,
                cost,
                crosses,
                sees: ids(seen),
                replan: true,
                route,
                outcomes,
            }),
        }
    }

    /// The cells of the cheapest route from `from` to `to` over the choke points of `crossable`,
    /// and the choke points it crosses.
    fn route(&mut self, from: NodeId, to: NodeId, crossable: u64) -> (Vec<Cell>, Vec<usize>) {
        let routes = self.abs.routes(from, crossable);
        let hops = routes.hops_to(to).expect("the target of a choice is reachable");
        let crosses = hops
            .iter()
            .filter_map(|&(_, h)| if let Hop::Crossing(c) = h { Some(c as usize) } else { None })
            .collect();
        let (cells, _) = self.abs.route_cells(&hops);
        (cells, crosses)
    }
}

/// The ids of the bits of a mask.
fn ids(mut mask: u64) -> Vec<usize> {
    let mut out = Vec::new();
    while mask != 0 {
        out.push(mask.trailing_zeros() as usize);
        mask &= mask - 1;
    }
    out
}
