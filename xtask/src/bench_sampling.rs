//! The sampling section of `cargo xtask bench`: RRT-Connect's success rate and speed, and RRT*'s
//! convergence, on generated polygon worlds (random convex obstacles, a bug trap, walls with
//! narrow doors), each path checked against the visibility graph's shortest one.
//!
//! The reference optimum is the visibility graph of the obstacles grown by the robot radius
//! with round corners in steps of π/64 (chords outside the exact discs: at most 0.03% longer
//! than the true optimum around each corner). Every returned path is re-checked exactly (each
//! motion against the grown obstacles), must start and end where asked, and may not beat that
//! optimum by more than its approximation allows; a path that fails either is an error that
//! fails the run.

use std::time::Instant;

use plotters::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::Serialize;
use trailmark::core::freespace::Location;
use trailmark::core::generate;
use trailmark::core::geometry::Point;
use trailmark::core::world::{CollisionChecker, PolygonWorld};
use trailmark::graph::visibility::{Edges, VisibilityGraph};
use trailmark::prelude::*;
use trailmark::sample::{KdNearest, Plan, Query, R2, RrtOptions, Termination, rrt_connect, rrt_star};

use crate::bench::{Suite, median};

/// The side of the square worlds.
const SIZE: f64 = 40.0;
/// The robot's radius.
const ROBOT_RADIUS: f64 = 0.25;
/// The width of a door of the narrow-passage worlds (free width: 1.0, 2.5% of the side).
const DOOR: f64 = 1.5;
/// RRT-Connect's iteration limit per query (the figure).
const CONNECT_ITERATIONS: u64 = 10_000;
/// The least share of solvable queries RRT-Connect must solve.
const CONNECT_GOAL: f64 = 0.99;
/// RRT*'s iterations per run (the figure).
const STAR_ITERATIONS: u64 = 20_000;
/// The goal for RRT*'s median cost after its iterations, over the optimum.
const STAR_GOAL: f64 = 1.05;
/// Where RRT*'s best cost is read for the convergence plot.
const CHECKPOINTS: [u64; 8] = [250, 500, 1_000, 2_000, 5_000, 10_000, 15_000, 20_000];
/// The round corners of the reference free space, in radians per chord.
const ARC_STEP: f64 = std::f64::consts::PI / 64.0;

/// A generated world and how its queries are drawn.
struct World {
    name: String,
    world: PolygonWorld,
    /// The world's exact checker, built once.
    checker: CollisionChecker,
    ends: Ends,
    visibility: VisibilityGraph,
}

/// Where a world's queries start and end.
#[derive(Clone, Copy)]
enum Ends {
    /// Anywhere free.
    Anywhere,
    /// From this point inside the trap to anywhere free outside its square.
    OutOfTrap(Point),
    /// From left of the first wall to right of the last.
    Across { walls: usize },
}

impl World {
    fn new(name: String, world: PolygonWorld, ends: Ends) -> Result<Self, String> {
        let space = world.free_space_with_step(ARC_STEP).map_err(|e| format!("{name}: {e}"))?;
        let visibility = VisibilityGraph::with_edges(space, Edges::Tangent);
        Ok(World { name, checker: world.checker(), world, ends, visibility })
    }

    /// `n` seeded queries whose ends are free, with their shortest cost (`None`: no path).
    fn queries(&self, n: usize, seed: u64) -> Result<Vec<(Point, Point, Option<f64>)>, String> {
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
                Ends::Anywhere => (free(&|_| true), free(&|_| true)),
                Ends::OutOfTrap(inside) => {
                    let outside = |p: Point| (p.x - inside.x).abs().max((p.y - inside.y).abs()) > SIZE * 0.3;
                    (inside, free(&outside))
                }
                Ends::Across { walls } => {
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
    fn checks(&self, plan: &Plan<Point>, a: Point, b: Point, best: f64) -> bool {
        let checker = &self.checker;
        let Some(path) = plan.path.as_ref() else { return false };
        let cost = plan.cost.unwrap_or(0.0);
        path.first() == Some(&a)
            && path.last() == Some(&b)
            && path.windows(2).all(|m| checker.segment_is_free(m[0], m[1]))
            && cost >= best * (ARC_STEP / 2.0).cos()
    }
}

/// The worlds of the section.
fn worlds(seed: u64) -> Result<Vec<World>, String> {
    let e = |e: generate::GenerateError| e.to_string();
    let (trap, inside) = generate::bug_trap(SIZE, ROBOT_RADIUS).map_err(e)?;
    let convex =
        |count: usize, s: u64| generate::convex_obstacles(SIZE, count, 6, ROBOT_RADIUS, s).map_err(e);
    Ok(vec![
        World::new("convex-30".into(), convex(30, seed)?, Ends::Anywhere)?,
        World::new("convex-60".into(), convex(60, seed + 1)?, Ends::Anywhere)?,
        World::new("bug-trap".into(), trap, Ends::OutOfTrap(inside))?,
        World::new(
            "narrow-3".into(),
            generate::narrow_passages(SIZE, 3, DOOR, ROBOT_RADIUS, seed).map_err(e)?,
            Ends::Across { walls: 3 },
        )?,
        World::new(
            "narrow-6".into(),
            generate::narrow_passages(SIZE, 6, DOOR, ROBOT_RADIUS, seed + 1).map_err(e)?,
            Ends::Across { walls: 6 },
        )?,
    ])
}

/// RRT-Connect on one world.
#[derive(Debug, Clone, Serialize)]
pub struct ConnectRow {
    /// The world.
    pub world: String,
    /// Seeded queries run.
    pub queries: usize,
    /// Queries with a path (by the visibility graph).
    pub solvable: usize,
    /// Solvable queries RRT-Connect solved within its iterations.
    pub solved: usize,
    /// Median time per query, milliseconds.
    pub median_ms: f64,
    /// Median iterations per query.
    pub median_iterations: f64,
    /// Median collision checks per query.
    pub median_checks: f64,
    /// Median path cost over the optimum.
    pub median_cost_ratio: f64,
    /// Paths that failed the re-check, or solutions where the visibility graph has no path
    /// (must be 0).
    pub invalid: usize,
}

/// RRT* on one world.
#[derive(Debug, Clone, Serialize)]
pub struct StarRow {
    /// The world.
    pub world: String,
    /// The query.
    pub start: [f64; 2],
    /// The query.
    pub goal: [f64; 2],
    /// The shortest path's cost.
    pub optimum: f64,
    /// Seeded runs.
    pub runs: usize,
    /// Median final cost over the optimum.
    pub median_ratio: f64,
    /// Worst final cost over the optimum.
    pub worst_ratio: f64,
    /// Median run time, seconds.
    pub median_s: f64,
    /// Median time to the first solution, milliseconds.
    pub median_first_ms: f64,
    /// Median best cost over the optimum at each checkpoint (NaN before every run has one).
    pub convergence: Vec<(u64, f64)>,
    /// Paths that failed the re-check (must be 0).
    pub invalid: usize,
}

/// The sampling section's results.
#[derive(Debug, Clone, Serialize)]
pub struct SamplingReport {
    /// RRT-Connect per world.
    pub connect: Vec<ConnectRow>,
    /// RRT* per world.
    pub star: Vec<StarRow>,
    /// The cost-vs-iterations plot (SVG), not serialized.
    #[serde(skip)]
    pub convergence_svg: String,
}

impl SamplingReport {
    /// Paths that failed their re-check.
    pub fn errors(&self) -> usize {
        self.connect.iter().map(|r| r.invalid).sum::<usize>()
            + self.star.iter().map(|r| r.invalid).sum::<usize>()
    }
}

fn sorted(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v
}

/// Runs the section.
pub fn bench_sampling(suite: Suite, seed: u64) -> Result<SamplingReport, String> {
    let (queries, star_runs) = match suite {
        Suite::Quick => (200, 5),
        Suite::Full => (1000, 15),
    };
    let worlds = worlds(seed)?;
    let mut connect = Vec::new();
    let mut star = Vec::new();
    for (i, w) in worlds.iter().enumerate() {
        eprintln!("[sampling {}/{}] {}: RRT-Connect, {queries} queries", i + 1, worlds.len(), w.name);
        let qs = w.queries(queries, seed ^ 0x5a5a)?;
        connect.push(bench_connect(w, &qs, seed)?);
        eprintln!(
            "[sampling {}/{}] {}: RRT*, {star_runs} runs of {STAR_ITERATIONS}",
            i + 1,
            worlds.len(),
            w.name
        );
        // For RRT*: the longest of the first ten queries that have a path.
        let &(a, b, best) = qs
            .iter()
            .take(10)
            .filter(|q| q.2.is_some())
            .max_by(|x, y| x.2.unwrap_or(0.0).total_cmp(&y.2.unwrap_or(0.0)))
            .ok_or_else(|| format!("{}: no solvable query", w.name))?;
        star.push(bench_star(w, a, b, best.unwrap_or(f64::NAN), star_runs, seed)?);
    }
    let convergence_svg = convergence_svg(&star)?;
    Ok(SamplingReport { connect, star, convergence_svg })
}

fn bench_connect(
    w: &World,
    queries: &[(Point, Point, Option<f64>)],
    seed: u64,
) -> Result<ConnectRow, String> {
    let space = R2::new(w.world.bounds());
    let checker = &w.checker;
    let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
    let limit = Termination::iterations(CONNECT_ITERATIONS);
    let (mut times, mut iterations, mut checks, mut ratios) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut solvable, mut solved, mut invalid) = (0, 0, 0);
    for (i, &(a, b, best)) in queries.iter().enumerate() {
        let query = Query::new(&space, checker, a, b);
        let clock = Instant::now();
        let plan = rrt_connect(&query, nearest.clone(), &RrtOptions::default(), &limit, seed + i as u64)
            .map_err(|e| format!("{}: {e}", w.name))?;
        let ms = clock.elapsed().as_secs_f64() * 1e3;
        let Some(best) = best else {
            // No path by the visibility graph: a solution here would be an error of one of them.
            invalid += usize::from(!plan.approximate);
            continue;
        };
        solvable += 1;
        times.push(ms);
        iterations.push(plan.stats.iterations as f64);
        checks.push(plan.stats.collision_checks as f64);
        if plan.approximate {
            continue;
        }
        solved += 1;
        if w.checks(&plan, a, b, best) {
            ratios.push(plan.cost.unwrap_or(f64::NAN) / best);
        } else {
            invalid += 1;
        }
    }
    Ok(ConnectRow {
        world: w.name.clone(),
        queries: queries.len(),
        solvable,
        solved,
        median_ms: median(&sorted(times)),
        median_iterations: median(&sorted(iterations)),
        median_checks: median(&sorted(checks)),
        median_cost_ratio: median(&sorted(ratios)),
        invalid,
    })
}

fn bench_star(w: &World, a: Point, b: Point, best: f64, runs: usize, seed: u64) -> Result<StarRow, String> {
    let space = R2::new(w.world.bounds());
    let checker = &w.checker;
    let limit = Termination::iterations(STAR_ITERATIONS);
    let (mut finals, mut times, mut firsts, mut invalid) = (Vec::new(), Vec::new(), Vec::new(), 0);
    let mut at_checkpoints: Vec<Vec<f64>> = vec![Vec::new(); CHECKPOINTS.len()];
    for run in 0..runs {
        let nearest = KdNearest::<R2, 2>::new(&space).map_err(|e| e.to_string())?;
        let query = Query::new(&space, checker, a, b);
        let plan = rrt_star(&query, nearest, &RrtOptions::default(), &limit, seed + run as u64)
            .map_err(|e| format!("{}: {e}", w.name))?;
        times.push(plan.stats.elapsed.as_secs_f64());
        firsts.push(plan.stats.time_to_solution.map_or(f64::INFINITY, |t| t.as_secs_f64() * 1e3));
        if plan.approximate || !w.checks(&plan, a, b, best) {
            invalid += usize::from(!plan.approximate);
            finals.push(f64::INFINITY);
        } else {
            finals.push(plan.cost.unwrap_or(f64::INFINITY) / best);
        }
        for (k, &c) in CHECKPOINTS.iter().enumerate() {
            let cost = plan.history.iter().take_while(|h| h.iteration <= c).last().map(|h| h.cost);
            at_checkpoints[k].push(cost.map_or(f64::INFINITY, |c| c / best));
        }
    }
    let finals = sorted(finals);
    let convergence = CHECKPOINTS.iter().zip(at_checkpoints).map(|(&c, v)| (c, median(&sorted(v)))).collect();
    Ok(StarRow {
        world: w.name.clone(),
        start: [a.x, a.y],
        goal: [b.x, b.y],
        optimum: best,
        runs,
        median_ratio: median(&finals),
        worst_ratio: finals.last().copied().unwrap_or(f64::NAN),
        median_s: median(&sorted(times)),
        median_first_ms: median(&sorted(firsts)),
        convergence,
        invalid,
    })
}

/// Median RRT* cost over the optimum against iterations, one line per world (log x axis).
fn convergence_svg(rows: &[StarRow]) -> Result<String, String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let top = rows
        .iter()
        .flat_map(|r| r.convergence.iter().map(|c| c.1))
        .filter(|c| c.is_finite())
        .fold(1.1f64, f64::max)
        .min(2.0);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (720, 420)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| e(&x))?;
        let first = CHECKPOINTS[0] as f64;
        let last = CHECKPOINTS[CHECKPOINTS.len() - 1] as f64;
        let mut chart = ChartBuilder::on(&root)
            .caption("RRT*: median path cost over the optimum, by iterations", ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d((first..last).log_scale(), 0.99..top)
            .map_err(|x| e(&x))?;
        chart.configure_mesh().x_desc("iterations").y_desc("cost / optimum").draw().map_err(|x| e(&x))?;
        let goal = RGBColor(120, 120, 120);
        chart
            .draw_series(LineSeries::new([(first, STAR_GOAL), (last, STAR_GOAL)], goal.stroke_width(1)))
            .map_err(|x| e(&x))?
            .label("goal: 5% above the optimum")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], goal.stroke_width(1)));
        let colours = [
            RGBColor(225, 48, 108),
            RGBColor(22, 160, 133),
            RGBColor(41, 128, 185),
            RGBColor(243, 156, 18),
            RGBColor(142, 68, 173),
        ];
        for (row, &colour) in rows.iter().zip(colours.iter().cycle()) {
            let points: Vec<(f64, f64)> = row
                .convergence
                .iter()
                .filter(|c| c.1.is_finite())
                .map(|&(i, c)| (i as f64, c.min(top)))
                .collect();
            chart
                .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
                .map_err(|x| e(&x))?
                .label(row.world.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
            chart
                .draw_series(points.into_iter().map(|p| Circle::new(p, 3, colour.filled())))
                .map_err(|x| e(&x))?;
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .draw()
            .map_err(|x| e(&x))?;
        root.present().map_err(|x| e(&x))?;
    }
    Ok(svg)
}

/// The section of the report.
pub fn markdown(report: &SamplingReport) -> String {
    let mut s = String::from("## Sampling planners\n\n");
    s.push_str(&format!(
        "Generated {SIZE} x {SIZE} worlds, robot radius {ROBOT_RADIUS}: random convex hexagons, a bug \
         trap (queries from inside it), and walls with doors {DOOR} wide (free width {}). Reference \
         costs: the visibility graph with corners in steps of π/64. Every path is re-checked exactly.\n\n",
        DOOR - 2.0 * ROBOT_RADIUS
    ));
    s.push_str(&format!(
        "### RRT-Connect ({CONNECT_ITERATIONS} iterations at most, default range)\n\n\
         | world | queries | solvable | solved | median ms | median iterations | median checks | median cost / optimum | invalid |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
    ));
    for r in &report.connect {
        s.push_str(&format!(
            "| {} | {} | {} | {} ({:.1}%) | {:.3} | {:.0} | {:.0} | {:.3} | {} |\n",
            r.world,
            r.queries,
            r.solvable,
            r.solved,
            100.0 * r.solved as f64 / r.solvable.max(1) as f64,
            r.median_ms,
            r.median_iterations,
            r.median_checks,
            r.median_cost_ratio,
            r.invalid
        ));
    }
    let share = |r: &ConnectRow| r.solved as f64 / r.solvable.max(1) as f64;
    let missed: Vec<String> = report
        .connect
        .iter()
        .filter(|r| share(r) < CONNECT_GOAL)
        .map(|r| {
            format!("{} ({:.1}%, median {:.0} iterations)", r.world, share(r) * 100.0, r.median_iterations)
        })
        .collect();
    s.push_str(&format!(
        "\nGoal: RRT-Connect solves at least {:.0}% of the solvable queries of each world within \
         {CONNECT_ITERATIONS} iterations. Measured: met on {} of {} worlds{}.\n\n",
        CONNECT_GOAL * 100.0,
        report.connect.len() - missed.len(),
        report.connect.len(),
        if missed.is_empty() { String::new() } else { format!("; not met on {}", missed.join(", ")) }
    ));
    s.push_str(&format!(
        "### RRT* ({STAR_ITERATIONS} iterations, default range and k-nearest rewiring)\n\n\
         | world | query | optimum | runs | median cost / optimum | worst | median first solution (ms) | median run (s) | invalid |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|\n"
    ));
    for r in &report.star {
        s.push_str(&format!(
            "| {} | ({:.1}, {:.1}) → ({:.1}, {:.1}) | {:.3} | {} | {:.4} | {:.4} | {:.2} | {:.2} | {} |\n",
            r.world,
            r.start[0],
            r.start[1],
            r.goal[0],
            r.goal[1],
            r.optimum,
            r.runs,
            r.median_ratio,
            r.worst_ratio,
            r.median_first_ms,
            r.median_s,
            r.invalid
        ));
    }
    let worst = report.star.iter().map(|r| r.median_ratio).fold(0.0, f64::max);
    s.push_str(&format!(
        "\nGoal: RRT*'s median cost after {STAR_ITERATIONS} iterations within {:.0}% of the optimum on every \
         world. Measured: at most {:.2}% above: {}.\n\n![RRT* convergence](sampling-convergence.svg)\n",
        (STAR_GOAL - 1.0) * 100.0,
        (worst - 1.0) * 100.0,
        if worst <= STAR_GOAL { "met" } else { "not met" }
    ));
    s
}
