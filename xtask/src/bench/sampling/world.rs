//! The sampling section's polygon worlds (random convex obstacles, a bug trap, walls with narrow
//! doors), their seeded queries with the shortest cost of each, and the exact re-check of every
//! path planned in them.
//!
//! The reference optimum is the visibility graph of the obstacles grown by the robot radius
//! with round corners in steps of π/64 (chords outside the exact discs: at most 0.03% longer
//! than the true optimum around each corner). Every returned path is re-checked exactly (each
//! motion against the grown obstacles), must start and end where asked, and may not beat that
//! optimum by more than its approximation allows.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use trailmark::core::freespace::Location;
use trailmark::core::generate;
use trailmark::core::geometry::Point;
use trailmark::core::world::{CollisionChecker, PolygonWorld};
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::prelude::*;
use trailmark::sample::Plan;

/// The side of the square worlds.
pub const SIZE: f64 = 40.0;
/// The robot's radius.
pub const ROBOT_RADIUS: f64 = 0.25;
/// The width of a door of the narrow-passage worlds (free width: 1.0, 2.5% of the side).
pub const DOOR: f64 = 1.5;
/// The round corners of the reference free space, in radians per chord.
const ARC_STEP: f64 = std::f64::consts::PI / 64.0;

/// A query of the section: its start, its goal and its shortest cost (`None`: no path).
pub type PlaneQuery = (Point, Point, Option<f64>);

/// A generated world and how its queries are drawn.
pub struct SamplingWorld {
    /// The world's name in the report.
    pub name: String,
    /// The obstacles.
    pub world: PolygonWorld,
    /// The world's exact checker, built once.
    pub checker: CollisionChecker,
    ends: QueryEnds,
    visibility: VisibilityGraph,
}

/// Where a world's queries start and end.
#[derive(Clone, Copy)]
enum QueryEnds {
    /// Anywhere free.
    Anywhere,
    /// From this point inside the trap to anywhere free outside its square.
    OutOfTrap(Point),
    /// From left of the first wall to right of the last.
    Across { walls: usize },
}

impl SamplingWorld {
    fn new(name: String, world: PolygonWorld, ends: QueryEnds) -> Result<Self, String> {
        let space = world.free_space_with_step(ARC_STEP).map_err(|e| format!("{name}: {e}"))?;
        let visibility = VisibilityGraph::with_edges(space, Edges::Tangent);
        Ok(SamplingWorld { name, checker: world.checker(), world, ends, visibility })
    }

    /// `n` seeded queries whose ends are free, with their shortest cost (`None`: no path).
    pub fn queries(&self, n: usize, seed: u64) -> Result<Vec<PlaneQuery>, String> {
        let checker = &self.checker;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut free = |ok: &dyn Fn(Point) -> bool| loop {
            let p = Point::new(rng.random_range(0.0..SIZE), rng.random_range(0.0..SIZE));
            if ok(p) && checker.point_is_free(p) && self.visibility.space().locate(p) != Location::Blocked {
                return p;
            }
        };
        let mut out = Vec::with_capacity(n);
        for _ in 0..n {
            let (a, b) = match self.ends {
                QueryEnds::Anywhere => (free(&|_| true), free(&|_| true)),
                QueryEnds::OutOfTrap(inside) => {
                    let outside = |p: Point| (p.x - inside.x).abs().max((p.y - inside.y).abs()) > SIZE * 0.3;
                    (inside, free(&outside))
                }
                QueryEnds::Across { walls } => {
                    let gap = SIZE / (walls + 1) as f64 - SIZE / 50.0;
                    (free(&|p: Point| p.x < gap), free(&|p: Point| p.x > SIZE - gap))
                }
            };
            let query = self.visibility.query(a, b).map_err(|e| format!("{}: {e}", self.name))?;
            let found = astar(&query, query.start(), query.goal(), query.heuristic())
                .map_err(|e| format!("{}: {e}", self.name))?;
            out.push((a, b, found.cost()));
        }
        Ok(out)
    }

    /// Whether `plan` is a valid path from `a` to `b` no shorter than the reference allows.
    pub fn checks(&self, plan: &Plan<Point>, a: Point, b: Point, best: f64) -> bool {
        plan.path().is_some_and(|path| self.checks_path(path, a, b, best))
    }

    /// Whether `path` runs from `a` to `b`, every motion free, no shorter than the reference
    /// allows (its cost recomputed here).
    pub fn checks_path(&self, path: &[Point], a: Point, b: Point, best: f64) -> bool {
        self.checked_cost(path, a, b, best).is_some()
    }

    /// The length of `path`, recomputed here, when it passes [`SamplingWorld::checks_path`].
    pub fn checked_cost(&self, path: &[Point], a: Point, b: Point, best: f64) -> Option<f64> {
        let cost: f64 = path.windows(2).map(|m| (m[1] - m[0]).norm()).sum();
        let valid = path.first() == Some(&a)
            && path.last() == Some(&b)
            && path.windows(2).all(|m| self.checker.segment_is_free(m[0], m[1]))
            && cost >= best * (ARC_STEP / 2.0).cos();
        valid.then_some(cost)
    }
}

/// The worlds of the section.
pub fn worlds(seed: u64) -> Result<Vec<SamplingWorld>, String> {
    let e = |e: generate::GenerateError| e.to_string();
    let (trap, inside) = generate::bug_trap(SIZE, ROBOT_RADIUS).map_err(e)?;
    let convex =
        |count: usize, s: u64| generate::convex_obstacles(SIZE, count, 6, ROBOT_RADIUS, s).map_err(e);
    Ok(vec![
        SamplingWorld::new("convex-30".into(), convex(30, seed)?, QueryEnds::Anywhere)?,
        SamplingWorld::new("convex-60".into(), convex(60, seed + 1)?, QueryEnds::Anywhere)?,
        SamplingWorld::new("bug-trap".into(), trap, QueryEnds::OutOfTrap(inside))?,
        SamplingWorld::new(
            "narrow-3".into(),
            generate::narrow_passages(SIZE, 3, DOOR, ROBOT_RADIUS, seed).map_err(e)?,
            QueryEnds::Across { walls: 3 },
        )?,
        SamplingWorld::new(
            "narrow-6".into(),
            generate::narrow_passages(SIZE, 6, DOOR, ROBOT_RADIUS, seed + 1).map_err(e)?,
            QueryEnds::Across { walls: 6 },
        )?,
    ])
}

/// The points of a path as the OMPL driver prints it.
pub fn points(path: &[Vec<f64>]) -> Vec<Point> {
    path.iter().map(|p| Point::new(p[0], p[1])).collect()
}

/// The queries as the OMPL driver reads them: `[ax, ay, bx, by]` each.
pub fn ompl_queries(queries: &[PlaneQuery]) -> Vec<Vec<f64>> {
    queries.iter().map(|(a, b, _)| vec![a.x, a.y, b.x, b.y]).collect()
}
