//! Rⁿ among random boxes (the random worlds of the BIT* papers: axis-aligned boxes in the unit
//! hypercube), in 4 and 8 dimensions, with the exact box checker: RRT-Connect's success and
//! time over seeded queries, RRT*'s and PRM*'s cost after a fixed time, every path re-checked
//! by dense samples.

use std::time::{Duration, Instant};

use serde::Serialize;
use trailmark::core::termination::Termination;
use trailmark::sample::benchmark::benchmark;
use trailmark::sample::rand::{RngExt, SeedableRng};
use trailmark::sample::{
    BitStar, BoxWorld, ChaCha8Rng, InformedRrtStar, KdNearest, Planner, Prm, Problem, Rn, RrtConnect,
    RrtStar, StateSpace,
};

use crate::bench::ompl::{OmplBoxes, OmplDriver, OmplInput, OmplRun};
use crate::bench::stats::upper_median;

/// The name in `--only`.
pub const NAME: &str = "boxes";

/// RRT-Connect's iteration limit per query.
const CONNECT_ITERATIONS: u64 = 10_000;

/// The milestones of the PRM* roadmap built before its queries.
const ROADMAP_SIZE: usize = 2_000;

/// One planner in one world.
#[derive(Debug, Clone, Serialize)]
pub struct BoxRow {
    /// The world.
    pub world: String,
    /// `trailmark` or `OMPL`.
    pub library: String,
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

/// A row from re-checked paths and run times.
fn row<const N: usize>(
    (world, library, planner): (&str, &str, String),
    paths: &[(Option<Vec<<Rn<N> as StateSpace>::State>>, f64)],
    boxes: &BoxWorld<N>,
    ends: &[(<Rn<N> as StateSpace>::State, <Rn<N> as StateSpace>::State)],
) -> BoxRow {
    let (mut ratios, mut invalid) = (Vec::new(), 0);
    for (i, (path, _)) in paths.iter().enumerate() {
        let (a, b) = &ends[i.min(ends.len() - 1)];
        let (ratio, _, bad) = tally(boxes, path.as_deref().into_iter(), a, b);
        ratios.extend(ratio);
        invalid += bad;
    }
    BoxRow {
        world: world.into(),
        library: library.into(),
        planner,
        runs: paths.len(),
        solved: ratios.len(),
        median_ms: upper_median(paths.iter().map(|p| p.1).collect()),
        median_cost_ratio: upper_median(ratios),
        invalid,
    }
}

/// The driver's box world for `world`.
fn ompl_boxes<const N: usize>(world: &BoxWorld<N>) -> OmplBoxes {
    let space = world.space();
    OmplBoxes {
        low: space.low().iter().copied().collect(),
        high: space.high().iter().copied().collect(),
        obstacles: world.boxes().iter().map(|(lo, hi)| [lo.to_vec(), hi.to_vec()]).collect(),
    }
}

/// The runs of OMPL's `planner` on `ends`, as paths and times (ms).
#[allow(clippy::type_complexity)]
fn ompl_runs<const N: usize>(
    driver: &OmplDriver,
    world: &BoxWorld<N>,
    planner: &str,
    ends: &[(<Rn<N> as StateSpace>::State, <Rn<N> as StateSpace>::State)],
    (runs, max_iterations, limit): (usize, u64, Duration),
    seed: u64,
) -> Result<Vec<(Option<Vec<<Rn<N> as StateSpace>::State>>, f64)>, String> {
    let input = ompl_input(world, planner, ends, (runs, max_iterations, limit), seed, 0);
    Ok(paths_and_times(&driver.run(&input)?))
}

/// The driver's input for `planner` on `ends`; a roadmap of `roadmap_size` first if not 0.
fn ompl_input<'a, const N: usize>(
    world: &BoxWorld<N>,
    planner: &'a str,
    ends: &[(<Rn<N> as StateSpace>::State, <Rn<N> as StateSpace>::State)],
    (runs, max_iterations, limit): (usize, u64, Duration),
    seed: u64,
    roadmap_size: usize,
) -> OmplInput<'a> {
    OmplInput {
        space: None,
        turning_radius: None,
        world: None,
        boxes: Some(ompl_boxes(world)),
        planner,
        queries: ends.iter().map(|(a, b)| a.iter().chain(b.iter()).copied().collect()).collect(),
        runs,
        seed,
        max_iterations,
        time_limit_s: limit.as_secs_f64(),
        roadmap_size,
    }
}

/// The driver's runs as paths (exact ones) and times in ms.
#[allow(clippy::type_complexity)]
fn paths_and_times<const N: usize>(
    runs: &[OmplRun],
) -> Vec<(Option<Vec<<Rn<N> as StateSpace>::State>>, f64)> {
    runs.iter()
        .map(|r| {
            let path = r
                .exact()
                .then(|| r.path.iter().map(|p| <Rn<N> as StateSpace>::State::from_fn(|i, _| p[i])).collect());
            (path, r.time_s * 1e3)
        })
        .collect()
}

/// PRM* multi-query: a roadmap of [`ROADMAP_SIZE`] milestones, then every query on it (a query
/// adds its start and goal and searches, growing nothing), trailmark's and OMPL's. Two rows per
/// library: the build (one run) and the queries.
fn roadmap_rows<const N: usize>(
    (name, world): (&str, &BoxWorld<N>),
    kd: KdNearest<Rn<N>, N>,
    ends: &[(<Rn<N> as StateSpace>::State, <Rn<N> as StateSpace>::State)],
    seed: u64,
    ompl: Option<&OmplDriver>,
) -> Result<Vec<BoxRow>, String> {
    let err = |e: &dyn std::fmt::Display| format!("{name}: PRM* roadmap: {e}");
    let space = world.space();
    // The roadmap built, timed, then every query on it, timed: PRM*, and Lazy PRM* on the same
    // samples (no motion checked until a query's path asks).
    type Answers<const N: usize> = Vec<(Option<Vec<<Rn<N> as StateSpace>::State>>, f64)>;
    let build_and_ask = |mut prm: Prm<Rn<N>, KdNearest<Rn<N>, N>>| -> Result<(f64, Answers<N>), String> {
        let clock = Instant::now();
        let growth = prm
            .grow(&space, world, ROADMAP_SIZE, &Termination::time(Duration::from_secs(60)))
            .map_err(|e| err(&e))?;
        let build_ms = clock.elapsed().as_secs_f64() * 1e3;
        if growth.stop.is_some() {
            return Err(err(&format!("grew {} of {ROADMAP_SIZE} milestones in 60 s", prm.node_count())));
        }
        let mut answers = Vec::new();
        for (a, b) in ends {
            let clock = Instant::now();
            let plan = prm
                .solve(&Problem::new(&space, world, *a, *b), &Termination::iterations(0))
                .map_err(|e| err(&e))?;
            answers.push((plan.path().map(<[_]>::to_vec), clock.elapsed().as_secs_f64() * 1e3));
        }
        Ok((build_ms, answers))
    };
    let (build_ms, answers) = build_and_ask(Prm::star(kd.clone()).with_seed(seed))?;
    let (lazy_build_ms, lazy_answers) = build_and_ask(Prm::lazy_star(kd).with_seed(seed))?;
    let build = format!("PRM* build ({ROADMAP_SIZE} milestones)");
    let query = "PRM* query (on that roadmap)".to_string();
    let total = format!("PRM* build + {} queries (total)", ends.len());
    // A row of one timed figure: no cost.
    let figure = |library: &str, planner: String, ms: f64| BoxRow {
        world: name.into(),
        library: library.into(),
        planner,
        runs: 1,
        solved: 1,
        median_ms: ms,
        median_cost_ratio: f64::NAN,
        invalid: 0,
    };
    let sum = |answers: &[(Option<Vec<<Rn<N> as StateSpace>::State>>, f64)]| {
        answers.iter().map(|a| a.1).sum::<f64>()
    };
    let mut rows = vec![
        figure("trailmark", build.clone(), build_ms),
        row((name, "trailmark", query.clone()), &answers, world, ends),
        figure("trailmark", total.clone(), build_ms + sum(&answers)),
        figure(
            "trailmark",
            format!("Lazy PRM* build ({ROADMAP_SIZE} milestones, no motion checked)"),
            lazy_build_ms,
        ),
        row(
            (name, "trailmark", "Lazy PRM* query (checks its path's motions)".into()),
            &lazy_answers,
            world,
            ends,
        ),
        figure(
            "trailmark",
            format!("Lazy PRM* build + {} queries (total)", ends.len()),
            lazy_build_ms + sum(&lazy_answers),
        ),
    ];
    if let Some(driver) = ompl {
        let input = ompl_input(world, "prm_star", ends, (1, 0, Duration::from_secs(60)), seed, ROADMAP_SIZE);
        let (built, runs) = driver.run_roadmap(&input)?;
        if built.milestones < ROADMAP_SIZE as u64 {
            return Err(err(&format!(
                "OMPL's PRMstar grew {} of {ROADMAP_SIZE} milestones",
                built.milestones
            )));
        }
        let theirs = paths_and_times::<N>(&runs);
        rows.push(figure("OMPL", build, built.time_s * 1e3));
        rows.push(row((name, "OMPL", query), &theirs, world, ends));
        rows.push(figure("OMPL", total, built.time_s * 1e3 + sum(&theirs)));
    }
    Ok(rows)
}

/// The rows of one world.
fn world_rows<const N: usize>(
    name: &str,
    world: &BoxWorld<N>,
    (queries, runs, limit): (usize, usize, Duration),
    seed: u64,
    ompl: Option<&OmplDriver>,
) -> Result<Vec<BoxRow>, String> {
    let err = |e: &dyn std::fmt::Display| format!("{name}: {e}");
    let space = world.space();
    let kd = KdNearest::<Rn<N>, N>::new(&space).map_err(|e| err(&e))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let ends: Vec<_> =
        (0..queries).map(|_| (free_near(world, 0.1, &mut rng), free_near(world, 0.9, &mut rng))).collect();
    let mut rows = Vec::new();
    // RRT-Connect: one run per seeded query.
    let connect = format!("RRT-Connect (≤ {CONNECT_ITERATIONS} iterations)");
    let mut ours = Vec::new();
    for (i, (a, b)) in ends.iter().enumerate() {
        let problem = Problem::new(&space, world, *a, *b);
        let limit = Termination::iterations(CONNECT_ITERATIONS);
        let mut measured =
            benchmark(&mut RrtConnect::new(kd.clone()), &problem, &limit, 1, seed + i as u64, None)
                .map_err(|e| err(&e))?;
        let (plan, record) = (measured.plans.remove(0), measured.runs.remove(0));
        ours.push((plan.path().map(<[_]>::to_vec), record.time_s * 1e3));
    }
    rows.push(row((name, "trailmark", connect.clone()), &ours, world, &ends));
    if let Some(driver) = ompl {
        let theirs = ompl_runs(
            driver,
            world,
            "rrt_connect",
            &ends,
            (1, CONNECT_ITERATIONS, Duration::from_secs(60)),
            seed,
        )?;
        rows.push(row((name, "OMPL", connect), &theirs, world, &ends));
    }
    rows.extend(roadmap_rows((name, world), kd.clone(), &ends, seed, ompl)?);
    // The optimizing planners: seeded runs on one query, each for `limit`.
    let one = [ends[0]];
    let problem = Problem::new(&space, world, one[0].0, one[0].1);
    let planners: Vec<Box<dyn Planner<Rn<N>, BoxWorld<N>>>> = vec![
        Box::new(RrtStar::new(kd.clone())),
        Box::new(InformedRrtStar::new(kd.clone())),
        Box::new(BitStar::new(kd.clone())),
        Box::new(Prm::star(kd.clone())),
    ];
    for mut planner in planners {
        let measured = benchmark(planner.as_mut(), &problem, &Termination::time(limit), runs, seed, None)
            .map_err(|e| err(&e))?;
        let runs: Vec<_> = measured
            .plans
            .iter()
            .zip(&measured.runs)
            .map(|(p, r)| (p.path().map(<[_]>::to_vec), r.time_s * 1e3))
            .collect();
        let label = format!("{} ({} ms)", measured.planner, limit.as_millis());
        rows.push(row((name, "trailmark", label), &runs, world, &one));
    }
    if let Some(driver) = ompl {
        for (planner, label) in [
            ("rrt_star", "RRTstar"),
            ("prm_star", "PRMstar"),
            ("informed_rrt_star", "InformedRRTstar"),
            ("bit_star", "BITstar"),
        ] {
            let theirs = ompl_runs(driver, world, planner, &one, (runs, 0, limit), seed)?;
            rows.push(row(
                (name, "OMPL", format!("{label} ({} ms)", limit.as_millis())),
                &theirs,
                world,
                &one,
            ));
        }
    }
    Ok(rows)
}

/// Both worlds: R⁴ with 50 boxes of side 0.15 to 0.35, R⁸ with 100 of side 0.4 to 0.6.
pub fn bench_boxes(
    (queries, runs, limit): (usize, usize, Duration),
    seed: u64,
    ompl: Option<&OmplDriver>,
) -> Result<Vec<BoxRow>, String> {
    let r4 = BoxWorld::<4>::random(50, 0.15..0.35, seed).map_err(|e| e.to_string())?;
    let r8 = BoxWorld::<8>::random(100, 0.4..0.6, seed).map_err(|e| e.to_string())?;
    let mut rows = world_rows("R4, 50 boxes", &r4, (queries, runs, limit), seed, ompl)?;
    rows.extend(world_rows("R8, 100 boxes", &r8, (queries, runs, limit), seed, ompl)?);
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
         fixed time on one query; PRM* also multi-query, one roadmap built first and every query on it \
         (its build row's time is the build; its query rows' time is one query's, joining the ends and \
         searching). Costs over the straight line between the ends (a lower bound); every \
         path re-checked every 1e-3. With `--with-ompl`, OMPL's planners on the same queries, with the \
         same box tests written in C++ (its planners' time is `solve` alone).\n\n\
         | world | library | planner | runs | solved | median ms | median cost / straight line | invalid |\n\
         |---|---|---|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | {:.3} | {} | {} |\n",
            r.world,
            r.library,
            r.planner,
            r.runs,
            r.solved,
            r.median_ms,
            if r.median_cost_ratio.is_nan() {
                "–".to_string()
            } else {
                format!("{:.4}", r.median_cost_ratio)
            },
            r.invalid
        ));
    }
    s.push('\n');
    s
}
