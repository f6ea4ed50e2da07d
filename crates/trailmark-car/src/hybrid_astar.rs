//! Hybrid A* (Dolgov, Thrun, Montemerlo and Diebel, "Path Planning for Autonomous Vehicles in
//! Unknown Semi-structured Environments", IJRR 2010): A* over cells and heading bins, where
//! each state keeps the continuous pose that reached it, expanded by the car's own motions, and
//! finished by a Reeds-Shepp (or Dubins) curve shot to the exact goal pose when one is free.
//!
//! As in Nav2's Smac Hybrid-A*: motions turn by whole heading bins, so states' headings lie on
//! bins; a state once expanded is not reopened (a cheaper way into its cell and bin later is
//! ignored), which keeps the search fast and makes its paths good rather than optimal.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::collections::hash_map::Entry;
use std::time::Instant;

use foldhash::HashMap;
use trailmark_core::dubins::{DubinsPath, Turn};
use trailmark_core::footprint::{Footprint, sweep_margin};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::reeds_shepp::{Gear, ReedsSheppPath};
use trailmark_core::termination::{Stop, Termination, Watch};

use crate::collision::FootprintChecker;
use crate::error::CarError;
use crate::heuristic::{HeuristicGrid, ObstacleHeuristic, curve_length};
use crate::map::CarMap;
use crate::motion::{Motion, Motions};
use crate::options::HybridOptions;
use crate::path::{CarPath, Stretch};
use crate::stats::HybridStats;

/// How near the goal, in turning radii, the estimate asks for the curve's length.
const CURVE_RADII: f64 = 10.0;

/// No parent: the start state.
const ROOT: u32 = u32::MAX;

/// The poses along a motion or a shot are checked this many to a cell.
const CHECKS_PER_CELL: f64 = 2.0;

/// The longest motion, in cells: a turn of one heading bin at the turning radius longer than
/// this (a radius of a million cells with four bins is a quarter circle of 1.6 million cells)
/// would hold millions of precomputed poses and leave any map a grid may be.
pub const MAX_MOTION_CELLS: f64 = 32_768.0;

/// Shots to the goal are tried within this many motions of it, whatever
/// [`HybridOptions::analytic_expansion_max_length`] says: a setting shorter than the map's
/// cells or the car's motions would leave the search no way to end.
const SHOT_MOTIONS: f64 = 4.0;

/// Hybrid A* for one car on one map: made once, asked for many queries.
///
/// ```
/// use trailmark_car::{CarMap, HybridAStar, HybridOptions};
/// use trailmark_core::footprint::Footprint;
/// use trailmark_core::geometry::Pose;
/// use trailmark_core::grid::Grid;
/// use trailmark_core::termination::Termination;
///
/// // A 12 m x 8 m yard of 0.1 m cells with a wall across its middle, open at the top.
/// let mut rows = vec![".".repeat(120); 80];
/// for row in rows.iter_mut().skip(30) {
///     row.replace_range(60..62, "@@");
/// }
/// let map = CarMap::from_grid(&Grid::from_rows(&rows)?, 0.1)?;
/// let settings = HybridOptions { turning_radius: 1.0, ..HybridOptions::default() };
/// let planner = HybridAStar::new(&map, &Footprint::Radius(0.3), settings)?;
/// let start = Pose::new(nalgebra::Vector2::new(2.0, 1.0), 0.0);
/// let goal = Pose::new(nalgebra::Vector2::new(10.0, 1.0), std::f64::consts::PI);
/// let plan = planner.plan(&start, &goal, &Termination::unlimited())?;
/// let end = plan.path.end().unwrap();
/// assert!((end.translation.vector - goal.translation.vector).norm() < 1e-6);
/// assert!(plan.path.length() > 8.0); // around the wall's top end
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct HybridAStar<'m> {
    map: &'m CarMap,
    settings: HybridOptions,
    motions: Motions,
    checker: FootprintChecker,
    /// The footprint as it is, without the margin: which poses the margin alone refuses.
    exact: FootprintChecker,
    /// How far the checked footprint is grown beyond the robot's own.
    margin: f64,
    /// The longest step between two checked poses.
    step: f64,
    /// The longest shot to the goal tried.
    shot_length: f64,
    /// The grid the estimate around the obstacles is computed on.
    heuristic: HeuristicGrid,
    /// The cheapest price of a metre on the map.
    least_price: f64,
}

/// A path and what the search did to find it.
#[derive(Debug, Clone, PartialEq)]
pub struct CarPlan {
    /// The path, in the world's frame.
    pub path: CarPath,
    /// Counters and times.
    pub stats: HybridStats,
}

/// A state of the search.
#[derive(Debug, Clone, Copy)]
struct Node {
    /// The continuous pose, in map coordinates; its heading is on bin `bin`.
    pose: Pose,
    bin: u32,
    g: f64,
    f: f64,
    parent: u32,
    /// The motion that reached it from its parent.
    motion: Option<Motion>,
    closed: bool,
}

impl<'m> HybridAStar<'m> {
    /// A planner for a car with `footprint` on `map`.
    ///
    /// Errors: a setting out of range ([`HybridOptions::check`]), too few heading bins for the
    /// turning radius (one bin's arc longer than [`MAX_MOTION_CELLS`] cells: the motions' poses
    /// are precomputed, two a cell), a footprint radius that is negative or not finite, a
    /// polygon of more than
    /// [`MAX_FOOTPRINT_VERTICES`](trailmark_core::footprint::MAX_FOOTPRINT_VERTICES) vertices.
    pub fn new(map: &'m CarMap, footprint: &Footprint, settings: HybridOptions) -> Result<Self, CarError> {
        settings.check(map.resolution())?;
        footprint.check()?;
        let bin_arc = std::f64::consts::TAU / f64::from(settings.heading_bins) * settings.turning_radius;
        if bin_arc > MAX_MOTION_CELLS * map.resolution() {
            return Err(CarError::Setting {
                setting: "heading_bins",
                expected: "enough bins that one bin's arc at the turning radius is at most 32,768 cells (2 pi turning_radius / heading_bins)",
                value: f64::from(settings.heading_bins),
            });
        }
        let reach = footprint.circumscribed_radius()?;
        let step = map.resolution() / CHECKS_PER_CELL;
        let margin = sweep_margin(step, reach, settings.turning_radius);
        let motions = Motions::new(
            settings.turning_radius,
            settings.heading_bins,
            map.resolution(),
            settings.reverse,
            step,
        );
        let shot_length = settings.analytic_expansion_max_length.max(SHOT_MOTIONS * motions.length);
        Ok(HybridAStar {
            map,
            settings,
            motions,
            checker: FootprintChecker::new(footprint, margin),
            exact: FootprintChecker::new(footprint, 0.0),
            margin,
            step,
            shot_length,
            heuristic: HeuristicGrid::new(map, footprint)?,
            least_price: map.least_price(),
        })
    }

    /// The settings.
    pub fn settings(&self) -> &HybridOptions {
        &self.settings
    }

    /// The cheapest price of a metre on the map.
    pub(crate) fn least_price(&self) -> f64 {
        self.least_price
    }

    /// Whether the footprint at `pose` (the world's frame) is clear of obstacles and on the map,
    /// as the planner checks it (with its margin).
    pub fn is_free(&self, pose: &Pose) -> bool {
        self.checker.is_free(self.map, &self.map.to_map(pose), &mut 0)
    }

    /// How far the footprint is grown where the planner checks it: half the farthest any point
    /// of the robot moves between two checked poses (a step of half a cell along the arc), so
    /// that the poses between them are covered too. A start or goal pose nearer an obstacle
    /// than this is refused ([`CarError::WithinMargin`]).
    pub fn margin(&self) -> f64 {
        self.margin
    }

    /// The longest shot to the goal the search tries: the larger of
    /// [`HybridOptions::analytic_expansion_max_length`] and four of the car's motions.
    pub fn shot_length(&self) -> f64 {
        self.shot_length
    }

    /// A path from `start` to `goal` (poses in the world's frame), within `termination`.
    ///
    /// Errors: a pose with a non-finite value; a start or goal whose footprint touches an
    /// obstacle or leaves the map ([`CarError::InCollision`]), or is free but nearer an
    /// obstacle than the [`margin`](Self::margin) ([`CarError::WithinMargin`]);
    /// [`CarError::NoPath`] without a path, its `stop` saying what is known:
    /// [`Stop::Unreachable`] when no pose of the car's reference point joins the start to the
    /// goal (proved on the map's cells, where they are the obstacles: [`CarMap::is_exact`]), [`Stop::LatticeExhausted`] when every state of the
    /// lattice the search reached was expanded without a free shot to the goal (nothing
    /// proved), or the termination's stop.
    pub fn plan(&self, start: &Pose, goal: &Pose, termination: &Termination) -> Result<CarPlan, CarError> {
        let clock = Instant::now();
        let mut stats = HybridStats::default();
        for (which, pose) in [("start", start), ("goal", goal)] {
            let v = [pose.translation.x, pose.translation.y, pose.rotation.re, pose.rotation.im];
            if !v.iter().all(|x| x.is_finite()) {
                return Err(CarError::Pose { which, pose: as_array(pose) });
            }
            if !self.is_free(pose) {
                if self.exact.is_free(self.map, &self.map.to_map(pose), &mut 0) {
                    return Err(CarError::WithinMargin { which, pose: as_array(pose), margin: self.margin });
                }
                return Err(CarError::InCollision { which, pose: as_array(pose) });
            }
        }
        let (start_m, goal_m) = (self.map.to_map(start), self.map.to_map(goal));
        let heuristic_clock = Instant::now();
        // The goal is on the map: its footprint was checked there.
        let goal_cell = self
            .map
            .cell_index(point(&goal_m))
            .ok_or(CarError::InCollision { which: "goal", pose: as_array(goal) })?;
        let obstacles = ObstacleHeuristic::new(&self.heuristic, goal_cell);
        stats.heuristic_time = heuristic_clock.elapsed();
        let mut search = Run {
            planner: self,
            obstacles,
            goal: goal_m,
            start_heading: start_m.rotation.angle(),
            nodes: Vec::new(),
            index: HashMap::default(),
            open: BinaryHeap::new(),
            stats,
        };
        let found = search.run(start_m, termination);
        let mut stats = search.stats;
        stats.time = clock.elapsed();
        match found {
            Ok((end, shot, cost)) => {
                let mut stretches = search.path(end, shot);
                let mut cost = cost;
                stats.search_cost = cost;
                if self.settings.smooth {
                    let smoothing = Instant::now();
                    (stretches, cost) = self.smooth(stretches, &mut stats);
                    stats.smoothing_time = smoothing.elapsed();
                    stats.time = clock.elapsed();
                }
                let stretches = stretches
                    .into_iter()
                    .map(|s| Stretch { start: self.map.to_world(&s.start), ..s })
                    .collect();
                let path = CarPath { stretches, turning_radius: self.settings.turning_radius, cost };
                Ok(CarPlan { path, stats })
            }
            Err(stop) => Err(CarError::NoPath { stop, stats }),
        }
    }

    /// Drives `stretch` (map coordinates), checking the footprint every step: the end pose and
    /// the mean price of a metre over the checked poses, or `None` on a collision.
    pub(crate) fn drive(&self, stretch: &Stretch, stats: &mut HybridStats) -> Option<(Pose, f64)> {
        let n = (stretch.length / self.step).ceil().max(1.0) as usize;
        let r = self.settings.turning_radius;
        self.check_poses((1..=n).map(|i| stretch.pose_at(stretch.length * i as f64 / n as f64, r)), stats)
    }

    /// Drives motion `k` from `start` (map coordinates) as [`drive`](Self::drive) does, its
    /// checked poses composed from the motion's precomputed ones.
    fn drive_motion(&self, start: &Pose, k: usize, stats: &mut HybridStats) -> Option<(Pose, f64)> {
        self.check_poses(self.motions.checks[k].iter().map(|offset| start * offset), stats)
    }

    /// Checks the footprint at each of `poses` in turn: the last pose and the mean price of a
    /// metre over them, or `None` on a collision (or no pose).
    #[inline]
    fn check_poses(&self, poses: impl Iterator<Item = Pose>, stats: &mut HybridStats) -> Option<(Pose, f64)> {
        let (mut price, mut count, mut end) = (0.0, 0usize, None);
        for pose in poses {
            stats.footprint_checks += 1;
            if !self.checker.is_free(self.map, &pose, &mut stats.footprint_rasters) {
                return None;
            }
            // A reference point outside the footprint may lie over an obstacle cell: priced as
            // the cheapest metre there.
            let here = self.map.price(self.map.cell_index(point(&pose))?);
            price += if here.is_finite() { here } else { self.least_price };
            count += 1;
            end = Some(pose);
        }
        end.map(|end| (end, price / count as f64))
    }

    /// The cost of driving `length` by `motion` at a mean `price` per metre, after a motion in
    /// gear `before` (`None` at the start).
    pub(crate) fn motion_cost(&self, before: Option<Gear>, motion: Motion, length: f64, price: f64) -> f64 {
        let s = &self.settings;
        let mut factor = price;
        if motion.turn != Turn::Straight {
            factor *= s.non_straight_penalty;
        }
        if motion.gear == Gear::Reverse {
            factor *= s.reverse_penalty;
        }
        let change = if before.is_some_and(|g| g != motion.gear) { s.gear_change_penalty } else { 0.0 };
        length * factor + change
    }

    /// The shortest curve the car can drive from `from` to `to` (map coordinates):
    /// Reeds-Shepp with reverse, Dubins without; its pieces, those of no length left out.
    pub(crate) fn curve(&self, from: &Pose, to: &Pose) -> Option<Shot> {
        let r = self.settings.turning_radius;
        let pieces: Shot = if self.settings.reverse {
            let path = ReedsSheppPath::shortest(from, to, r).ok()?;
            path.segments().map(|s| (s.turn, s.gear, s.length)).collect()
        } else {
            let path = DubinsPath::shortest(from, to, r).ok()?;
            path.word()
                .turns()
                .into_iter()
                .zip(path.segment_lengths())
                .map(|(t, l)| (t, Gear::Forward, l))
                .collect()
        };
        // Pieces of a billionth of the radius are rounding, not motions: kept, they would be
        // cusps of no length.
        Some(pieces.into_iter().filter(|&(_, _, length)| length > 1e-9 * r).collect())
    }

    /// The cost of driving `pieces` from `from` after a motion in gear `before`, if the
    /// footprint stays free along them.
    pub(crate) fn curve_cost(
        &self,
        from: &Pose,
        pieces: &Shot,
        mut before: Option<Gear>,
        stats: &mut HybridStats,
    ) -> Option<f64> {
        let mut at = *from;
        let mut cost = 0.0;
        for &(turn, gear, length) in pieces {
            let (end, price) = self.drive(&Stretch { start: at, turn, gear, length }, stats)?;
            cost += self.motion_cost(before, Motion { gear, turn, bins: 0 }, length, price);
            before = Some(gear);
            at = end;
        }
        Some(cost)
    }
}

/// The state of one query.
struct Run<'p, 'm> {
    planner: &'p HybridAStar<'m>,
    obstacles: ObstacleHeuristic,
    goal: Pose,
    start_heading: f64,
    nodes: Vec<Node>,
    /// The node of each (cell, bin).
    index: HashMap<u64, u32>,
    /// (the bits of f, which order as f does for costs not negative; the bits of g inverted,
    /// so that among equal f the deeper state comes first; node).
    open: BinaryHeap<Reverse<(u64, u64, u32)>>,
    stats: HybridStats,
}

/// A curve's pieces: turn, gear and length each (no start pose yet).
pub(crate) type Shot = Vec<(Turn, Gear, f64)>;

impl Run<'_, '_> {
    /// Searches from `start`: the node where a free shot to the goal was found, the shot and the
    /// path's cost; or why it stopped.
    ///
    /// The estimate around the obstacles is infinite only where no chain of cells, each with a
    /// point the reference point may occupy, joins a cell to the goal's: infinite at the start,
    /// the goal is proved unreachable, when the map's obstacle cells are the obstacles
    /// themselves ([`CarMap::is_exact`]). An open list that runs out proves nothing about the
    /// continuous problem, only about the lattice.
    fn run(&mut self, start: Pose, termination: &Termination) -> Result<(u32, Shot, f64), Stop> {
        let p = self.planner;
        let unreachable = if p.map.is_exact() { Stop::Unreachable } else { Stop::LatticeExhausted };
        // The start is on the map: its footprint was checked there.
        let start_cell = p.map.cell_index(point(&start)).ok_or(unreachable)?;
        let h = self.estimate(&start, start_cell);
        if !h.is_finite() {
            return Err(unreachable);
        }
        self.nodes.push(Node {
            pose: start,
            bin: 0,
            g: 0.0,
            f: h,
            parent: ROOT,
            motion: None,
            closed: false,
        });
        self.index.insert(self.key(start_cell, 0), 0);
        self.open.push(Reverse((h.to_bits(), !0.0f64.to_bits(), 0)));
        let mut watch = Watch::start(termination);
        let mut countdown = 0u64;
        let clock_every = if p.motions.checks[0].len() > 64 { 1 } else { 64 };
        while let Some(Reverse((f_bits, _, id))) = self.open.pop() {
            let node = self.nodes[id as usize];
            if node.closed || node.f.to_bits() != f_bits {
                continue; // expanded already, or reached more cheaply since this entry
            }
            // The expansion limit exactly; the clock and the caller every 64 expansions, or every
            // one where motions are long enough for one expansion to take long.
            if termination.expansions_spent(self.stats.expansions) {
                return Err(Stop::ExpansionLimit);
            }
            if self.stats.expansions.is_multiple_of(clock_every) {
                watch.set_expansions(self.stats.expansions);
                if let Some(stop) = watch.interrupted() {
                    return Err(stop);
                }
            }
            self.nodes[id as usize].closed = true;
            self.stats.expansions += 1;
            // Shots to the goal: every d / ratio expansions, d the straight distance to the goal
            // in cells, when close enough. Smac counts its estimate, in units of cost, instead:
            // where cells cost a million times the cheapest, the countdown never came.
            let distance = (point(&node.pose) - point(&self.goal)).norm();
            if countdown == 0 {
                if distance <= p.shot_length
                    && let Some((shot, cost)) = self.shot(&node)
                {
                    return Ok((id, shot, node.g + cost));
                }
                let cells = distance / p.map.resolution();
                countdown = (cells / p.settings.analytic_expansion_ratio).floor().max(0.0) as u64;
            } else {
                countdown -= 1;
            }
            self.expand(id, node);
        }
        Err(Stop::LatticeExhausted)
    }

    fn key(&self, cell: usize, bin: u32) -> u64 {
        cell as u64 * u64::from(self.planner.settings.heading_bins) + u64::from(bin)
    }

    /// The estimate from `pose` (in cell `cell`) to the goal. The curve's length is asked only
    /// within [`CURVE_RADII`] turning radii of the goal: farther away it exceeds the straight
    /// distance by less than the obstacle estimate does in all but open space, and it is the
    /// dearest part of an expansion.
    fn estimate(&self, pose: &Pose, cell: usize) -> f64 {
        let p = self.planner;
        let around = self.obstacles.at(cell);
        if !around.is_finite() {
            return around;
        }
        let r = p.settings.turning_radius;
        if (point(pose) - point(&self.goal)).norm() > CURVE_RADII * r {
            return around;
        }
        let turning = curve_length(pose, &self.goal, r, p.settings.reverse);
        around.max(turning * p.least_price)
    }

    /// Tries every motion from `node` (index `id`).
    fn expand(&mut self, id: u32, node: Node) {
        let p = self.planner;
        let bins = p.settings.heading_bins as i64;
        for k in 0..p.motions.all.len() {
            let motion = p.motions.all[k];
            self.stats.motions += 1;
            let Some((end, price)) = p.drive_motion(&node.pose, k, &mut self.stats) else { continue };
            let bin = (i64::from(node.bin) + i64::from(motion.bins)).rem_euclid(bins) as u32;
            let heading = self.start_heading + f64::from(bin) * p.motions.bin_angle;
            let end = Pose::new(end.translation.vector, heading);
            let Some(cell) = p.map.cell_index(point(&end)) else { continue };
            let g = node.g + p.motion_cost(node.motion.map(|m| m.gear), motion, p.motions.length, price);
            let key = self.key(cell, bin);
            let reached = match self.index.entry(key) {
                Entry::Occupied(e) => {
                    let other = &self.nodes[*e.get() as usize];
                    if other.closed || other.g <= g {
                        continue;
                    }
                    Some(*e.get())
                }
                Entry::Vacant(_) => None,
            };
            let h = match reached {
                Some(other) => self.nodes[other as usize].f - self.nodes[other as usize].g,
                None => self.estimate(&end, cell),
            };
            if !h.is_finite() {
                continue;
            }
            let fresh = Node { pose: end, bin, g, f: g + h, parent: id, motion: Some(motion), closed: false };
            let slot = match reached {
                Some(other) => {
                    self.nodes[other as usize] = fresh;
                    other
                }
                None => {
                    self.nodes.push(fresh);
                    let slot = (self.nodes.len() - 1) as u32;
                    self.index.insert(key, slot);
                    slot
                }
            };
            self.open.push(Reverse((fresh.f.to_bits(), !fresh.g.to_bits(), slot)));
        }
    }

    /// The shortest curve from `node` to the goal, if the footprint stays free along it: its
    /// stretches and cost.
    fn shot(&mut self, node: &Node) -> Option<(Shot, f64)> {
        let p = self.planner;
        self.stats.analytic_attempts += 1;
        let stretches = p.curve(&node.pose, &self.goal)?;
        let cost = p.curve_cost(&node.pose, &stretches, node.motion.map(|m| m.gear), &mut self.stats)?;
        Some((stretches, cost))
    }

    /// The stretches to node `end` followed by `shot` (map coordinates).
    fn path(&self, end: u32, shot: Shot) -> Vec<Stretch> {
        let p = self.planner;
        let r = p.settings.turning_radius;
        let mut chain = Vec::new();
        let mut id = end;
        while id != ROOT {
            let node = &self.nodes[id as usize];
            if let Some(motion) = node.motion {
                let from = self.nodes[node.parent as usize].pose;
                chain.push(Stretch {
                    start: from,
                    turn: motion.turn,
                    gear: motion.gear,
                    length: p.motions.length,
                });
            }
            id = node.parent;
        }
        chain.reverse();
        let mut at = self.nodes[end as usize].pose;
        for (turn, gear, length) in shot {
            let stretch = Stretch { start: at, turn, gear, length };
            at = stretch.pose_at(length, r);
            chain.push(stretch);
        }
        chain
    }
}

fn point(pose: &Pose) -> Point {
    Point::from(pose.translation.vector)
}

fn as_array(pose: &Pose) -> [f64; 3] {
    [pose.translation.x, pose.translation.y, pose.rotation.angle()]
}
