//! Rⁿ among random boxes (the random worlds of the BIT* papers: axis-aligned boxes in the unit
//! hypercube), in 4 and 8 dimensions, with the exact box checker: RRT-Connect's success and
//! time over seeded queries, RRT*'s and PRM*'s cost after a fixed time, every path re-checked
//! by dense samples.

use std::time::Duration;

use serde::Serialize;
use trailmark::sample::benchmark::benchmark;
use trailmark::sample::rand::{RngExt, SeedableRng};
use trailmark::sample::{
    BoxWorld, ChaCha8Rng, KdNearest, Planner, Prm, Problem, Rn, RrtConnect, RrtStar, StateSpace, Termination,
};

/// RRT-Connect's iteration limit per query.
const CONNECT_ITERATIONS: u64 = 10_000;

/// One planner in one world.
#[derive(Debug, Clone, Serialize)]
pub struct BoxRow {
    /// The world.
    pub world: String,
    /// The planner.
    pub planner: String,
    /// Runs.
    pub runs: usize,
    /// Runs with an exact path, re-checked.
    pub solved: usize,
    /// The median time of a run, ms.
    pub median_ms: f64,
    /// The median cost over the straight line's (the lower bound), over solved runs.
    pub median_cost_ratio: f64,
    /// Paths that failed the re-check.
    pub invalid: usize,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// A free state near `(c, c, ..., c)`.
fn free_near<const N: usize>(
    world: &BoxWorld<N>,
    c: f64,
    rng: &mut ChaCha8Rng,
) -> <Rn<N> as StateSpace>::State {
    loop {
        let q =
            <Rn<N> as StateSpace>::State::from_fn(|_, _| (c + rng.random_range(-0.1..0.1)).clamp(0.0, 1.0));
        if world.is_free(&q) {
            return q;
        }
    }
}

/// Whether `path` runs from `a` to `b` with every sample every 1e-3 free; its cost.
fn recheck<const N: usize>(
    world: &BoxWorld<N>,
    path: &[<Rn<N> as StateSpace>::State],
    a: &<Rn<N> as StateSpace>::State,
    b: &<Rn<N> as StateSpace>::State,
) -> Option<f64> {
    let ends = path.first() == Some(a) && path.last() == Some(b);
    let mut cost = 0.0;
    for m in path.windows(2) {
        let d = (m[1] - m[0]).norm();
        let n = (d / 1e-3).ceil().max(1.0) as usize;
        if !(0..=n).all(|i| world.is_free(&(m[0] + (m[1] - m[0]) * (i as f64 / n as f64)))) {
            return None;
        }
        cost += d;
    }
    ends.then_some(cost)
}

/// What the re-checks of `paths` from `a` to `b` found: the cost ratios of the valid ones, their
/// count, and the count of invalid ones.
fn tally<'p, const N: usize>(
    world: &BoxWorld<N>,
    paths: impl Iterator<Item = &'p [<Rn<N> as StateSpace>::State]>,
    a: &<Rn<N> as StateSpace>::State,
    b: &<Rn<N> as StateSpace>::State,
) -> (Vec<f64>, usize, usize) {
    let (mut ratios, mut invalid) = (Vec::new(), 0);
    for path in paths {
        match recheck(world, path, a, b) {
            Some(cost) => ratios.push(cost / (b - a).norm()),
            None => invalid += 1,
        }
    }
    let solved = ratios.len();
    (ratios, solved, invalid)
}

/// The rows of one world.
fn world_rows<const N: usize>(
    name: &str,
    world: &BoxWorld<N>,
    (queries, runs, limit): (usize, usize, Duration),
    seed: u64,
) -> Result<Vec<BoxRow>, String> {
    let err = |e: &dyn std::fmt::Display| format!("{name}: {e}");
    let space = world.space();
    let kd = KdNearest::<Rn<N>, N>::new(&space).map_err(|e| err(&e))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut rows = Vec::new();
    // RRT-Connect: one run per seeded query.
    let (mut times, mut ratios, mut solved, mut invalid) = (Vec::new(), Vec::new(), 0, 0);
    for i in 0..queries {
        let (a, b) = (free_near(world, 0.1, &mut rng), free_near(world, 0.9, &mut rng));
        let problem = Problem::new(&space, world, a, b);
        let limit = Termination::iterations(CONNECT_ITERATIONS);
        let mut runs =
            benchmark(&mut RrtConnect::new(kd.clone()), &problem, &limit, 1, seed + i as u64, None)
                .map_err(|e| err(&e))?;
        let (plan, record) = (runs.plans.remove(0), runs.runs.remove(0));
        times.push(record.time_s * 1e3);
        let (ratio, ok, bad) = tally(world, plan.path().into_iter(), &a, &b);
        ratios.extend(ratio);
        (solved, invalid) = (solved + ok, invalid + bad);
    }
    rows.push(BoxRow {
        world: name.into(),
        planner: format!("RRT-Connect (≤ {CONNECT_ITERATIONS} iterations)"),
        runs: queries,
        solved,
        median_ms: median(times),
        median_cost_ratio: median(ratios),
        invalid,
    });
    // RRT* and PRM*: seeded runs on one query, each for `limit`.
    let (a, b) = (free_near(world, 0.1, &mut rng), free_near(world, 0.9, &mut rng));
    let problem = Problem::new(&space, world, a, b);
    let planners: Vec<Box<dyn Planner<Rn<N>, BoxWorld<N>>>> =
        vec![Box::new(RrtStar::new(kd.clone())), Box::new(Prm::star(kd.clone()))];
    for mut planner in planners {
        let measured = benchmark(planner.as_mut(), &problem, &Termination::time(limit), runs, seed, None)
            .map_err(|e| err(&e))?;
        let (ratios, solved, invalid) = tally(world, measured.plans.iter().filter_map(|p| p.path()), &a, &b);
        rows.push(BoxRow {
            world: name.into(),
            planner: format!("{} ({} ms)", measured.planner, limit.as_millis()),
            runs,
            solved,
            median_ms: median(measured.runs.iter().map(|r| r.time_s * 1e3).collect()),
            median_cost_ratio: median(ratios),
            invalid,
        });
    }
    Ok(rows)
}

/// Both worlds: R⁴ with 50 boxes of side 0.15 to 0.35, R⁸ with 100 of side 0.4 to 0.6.
pub fn bench_boxes(queries: usize, runs: usize, limit: Duration, seed: u64) -> Result<Vec<BoxRow>, String> {
    let r4 = BoxWorld::<4>::random(50, 0.15..0.35, seed).map_err(|e| e.to_string())?;
    let r8 = BoxWorld::<8>::random(100, 0.4..0.6, seed).map_err(|e| e.to_string())?;
    let mut rows = world_rows("R4, 50 boxes", &r4, (queries, runs, limit), seed)?;
    rows.extend(world_rows("R8, 100 boxes", &r8, (queries, runs, limit), seed)?);
    Ok(rows)
}

/// The table.
pub fn markdown(rows: &[BoxRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = String::from(
        "### Rⁿ among random boxes (unit hypercube, exact box checks)\n\n\
         RRT-Connect over seeded queries from near one corner to near the other; RRT* and PRM* for a \
         fixed time on one query. Costs over the straight line between the ends (a lower bound); every \
         path re-checked every 1e-3. OMPL's side of these rows is not in the harness yet.\n\n\
         | world | planner | runs | solved | median ms | median cost / straight line | invalid |\n\
         |---|---|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {:.3} | {:.4} | {} |\n",
            r.world, r.planner, r.runs, r.solved, r.median_ms, r.median_cost_ratio, r.invalid
        ));
    }
    s.push('\n');
    s
}
