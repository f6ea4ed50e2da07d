//! Nearest neighbours under a connect phase's order: from 1,000 scattered states in a 40 x 40
//! square, each further state is asked for its nearest and then stored, the states scattered
//! or in order along a line in steps of 1e-4 of the extent (diagonal, or along an axis), as
//! RRT-Connect's connect phase adds them. trailmark's `KdNearest` (what its planners use)
//! beside kiddo's growing k-d tree and, with `--with-ompl`, OMPL's default for tree planners
//! (GNAT), on the same states.

use std::time::Instant;

use serde::Serialize;
use trailmark::core::geometry::Point;
use trailmark::sample::rand::{RngExt, SeedableRng};
use trailmark::sample::{ChaCha8Rng, Direction, KdNearest, NearestNeighbors, R2};

use crate::bench::ompl::OmplDriver;
use crate::bench::report::GoalRow;

/// The name in `--only`.
pub const NAME: &str = "nearest";

/// The scattered states stored first.
const BASE: usize = 1_000;

/// The side of the square.
const SIDE: f64 = 40.0;

/// The states of each case after the first ones: a connect phase's length, and ten times it.
const LENGTHS: [usize; 2] = [10_000, 100_000];

/// One library on one case.
#[derive(Debug, Clone, Serialize)]
pub struct NearestRow {
    /// `scattered`, `diagonal` or `axis`.
    pub case: &'static str,
    /// The states asked and stored after the first ones.
    pub states: usize,
    /// `trailmark`, `kiddo` or `OMPL`.
    pub library: String,
    /// The fastest run's time, ms.
    pub ms: f64,
    /// Over the same library's time on scattered states of the same number.
    pub over_scattered: f64,
}

/// The cases' states: the first ones, then the case's.
fn cases(seed: u64, length: usize) -> [(&'static str, Vec<Point>); 3] {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut point = || Point::new(rng.random_range(0.0..SIDE), rng.random_range(0.0..SIDE));
    let first: Vec<Point> = (0..BASE).map(|_| point()).collect();
    let step = SIDE * 1e-4;
    let scattered = (0..length).map(|_| point()).collect::<Vec<_>>();
    let unit = std::f64::consts::FRAC_1_SQRT_2;
    // Lines long enough for 100,000 steps: across the square and past it (a line leaving the
    // first states' region is part of the case).
    let diagonal =
        (0..length).map(|i| Point::new(2.0 + unit * step * i as f64, 2.0 + unit * step * i as f64));
    let axis = (0..length).map(|i| Point::new(0.5 + step * i as f64, SIDE / 2.0));
    let with_first = |rest: Vec<Point>| first.iter().copied().chain(rest).collect::<Vec<_>>();
    [
        ("scattered", with_first(scattered)),
        ("diagonal", with_first(diagonal.collect())),
        ("axis", with_first(axis.collect())),
    ]
}

/// The fastest of `runs` runs of the connect-phase loop, ms, and the sum of the answers: each
/// run gives its loop's time (the first states' insertion not counted, as in the OMPL driver).
fn fastest(runs: usize, mut run: impl FnMut() -> (f64, u64)) -> (f64, u64) {
    let mut best = f64::INFINITY;
    let mut sum = 0;
    for _ in 0..runs {
        let (ms, answers) = run();
        best = best.min(ms);
        sum = answers;
    }
    (best, sum)
}

fn trailmark_loop(states: &[Point]) -> (f64, u64) {
    let space = R2::new(trailmark::core::world::Bounds::new(0.0, 0.0, SIDE, SIDE).expect("a square"));
    let mut set = KdNearest::<R2, 2>::new(&space).expect("R2 has positions");
    for p in &states[..BASE] {
        set.insert(&space, *p);
    }
    let start = Instant::now();
    let mut sum = 0u64;
    for p in &states[BASE..] {
        sum += u64::from(set.nearest(&space, p, Direction::ToQuery).map_or(0, |n| n.0));
        set.insert(&space, *p);
    }
    (start.elapsed().as_secs_f64() * 1e3, sum)
}

fn kiddo_loop(states: &[Point]) -> (f64, u64) {
    let mut tree = kiddo::KdTree::<f64, 2>::new();
    for (i, p) in states[..BASE].iter().enumerate() {
        tree.add(&[p.x, p.y], i as u64);
    }
    let start = Instant::now();
    let mut sum = 0u64;
    for (i, p) in states.iter().enumerate().skip(BASE) {
        sum += tree.nearest_one::<kiddo::SquaredEuclidean>(&[p.x, p.y]).item;
        tree.add(&[p.x, p.y], i as u64);
    }
    (start.elapsed().as_secs_f64() * 1e3, sum)
}

/// Every case at every length; OMPL's too when `ompl` is given. The peers run 100,000 states
/// along a line only when `peers_on_long_lines` (the full suite: they take seconds there). The
/// sums of the answers must agree between libraries (the states are in general position: no
/// ties).
pub fn bench_nearest(
    seed: u64,
    ompl: Option<&OmplDriver>,
    peers_on_long_lines: bool,
) -> Result<Vec<NearestRow>, String> {
    let mut rows = Vec::new();
    for length in LENGTHS {
        let mut scattered: Vec<(String, f64)> = Vec::new();
        for (case, states) in cases(seed, length) {
            let (ms, sum) = fastest(3, || trailmark_loop(&states));
            let mut measured = vec![("trailmark".to_string(), ms)];
            let long_line = length > LENGTHS[0] && case != "scattered";
            if long_line && !peers_on_long_lines {
                rows.push(NearestRow {
                    case,
                    states: length,
                    library: "trailmark".into(),
                    ms,
                    over_scattered: ms / scattered[0].1,
                });
                continue;
            }
            // The peers' long lines once: they take seconds there.
            let runs = if long_line { 1 } else { 3 };
            let (kiddo_ms, kiddo_sum) = fastest(runs, || kiddo_loop(&states));
            if kiddo_sum != sum {
                return Err(format!("nearest neighbours, {case}: kiddo's answers differ from trailmark's"));
            }
            measured.push(("kiddo".to_string(), kiddo_ms));
            if let Some(driver) = ompl {
                let flat: Vec<f64> = states.iter().flat_map(|p| [p.x, p.y]).collect();
                let (s, ompl_sum) = driver.nearest(2, &flat, BASE, runs)?;
                if ompl_sum != sum {
                    return Err(format!(
                        "nearest neighbours, {case}: OMPL's answers differ from trailmark's"
                    ));
                }
                measured.push(("OMPL".to_string(), s * 1e3));
            }
            if case == "scattered" {
                scattered = measured.clone();
            }
            for (library, ms) in measured {
                let base = scattered.iter().find(|(l, _)| *l == library).map_or(f64::NAN, |s| s.1);
                rows.push(NearestRow { case, states: length, library, ms, over_scattered: ms / base });
            }
        }
    }
    Ok(rows)
}

/// The goal: states in order along a line within twice scattered states' time, for a
/// connect phase of 10,000 states.
pub fn goal(rows: &[NearestRow]) -> GoalRow {
    let figures = rows
        .iter()
        .filter(|r| r.library == "trailmark" && r.case != "scattered" && r.states == LENGTHS[0])
        .map(|r| (format!("{} ({} states)", r.case, r.states), 2.0 / r.over_scattered))
        .collect();
    GoalRow {
        goal: "nearest neighbours of 10,000 states in order along a line within 2x of scattered ones (2 / ratio >= 1)",
        figures,
        target: 1.0,
        unit: "",
        missing: "run the sampling section",
    }
}

/// The table.
pub fn markdown(rows: &[NearestRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = String::from("### Nearest neighbours in a connect phase's order\n\n");
    s.push_str(&format!(
        "{BASE} scattered states in a {SIDE} x {SIDE} square, then each further state asked for its \
         nearest and stored: scattered, or in order along a line in steps of 1e-4 of the side \
         (diagonal, along an axis). trailmark: `KdNearest` (its planners' structure); kiddo: its \
         growing k-d tree; OMPL: GNAT, its default for tree planners (with `--with-ompl`). The \
         fastest of 3 runs (the peers' 100,000 states along a line: 1, and only in the full suite: \
         seconds each). Ratio: over the same library on scattered states.\n\n"
    ));
    s.push_str("| case | states | library | ms | over scattered |\n|---|---:|---|---:|---:|\n");
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {:.2} | {:.2} |\n",
            r.case, r.states, r.library, r.ms, r.over_scattered
        ));
    }
    s.push('\n');
    s
}
