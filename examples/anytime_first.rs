//! The first solution of ARA* and of AD* (ε = 3) on the same queries of one MovingAI map, in
//! interleaved rounds, beside optimal A*: time per query and per expansion for each. AD* keeps
//! one planner for the map and resets it for each query, as a robot's planner would be kept.
//! Also a convenient target for `perf record` (`TM_ONLY=ad` runs AD* alone).
//!
//! `cargo run --release --example anytime_first -- [SET NAME]` (default: bg512 AR0011SR);
//! needs `../shared/movingai`.

use std::ops::ControlFlow;
use std::time::Instant;

use trailmark::core::termination::Termination;
use trailmark::prelude::*;
use trailmark::search::{AdStar, EpsilonSchedule};

mod common;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let Some((name, grid, queries)) = common::movingai_queries("bg512", "AR0011SR")? else {
        return Ok(());
    };
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let schedule = EpsilonSchedule::new(3.0, 0.5);
    let only_ad = std::env::var("TM_ONLY").is_ok_and(|v| v == "ad");
    let mut search = Search::new();
    let first = queries.first().ok_or("no scenarios")?;
    let mut ad = AdStar::new(
        &graph,
        first.start,
        first.goal,
        graph.heuristic_between(GridHeuristic::Octile),
        schedule,
    )?;
    // [A*, ARA*, AD*]: seconds per round, expansions per round.
    let mut times: [Vec<f64>; 3] = Default::default();
    let mut expansions = [0u64; 3];
    for _ in 0..7 {
        expansions = [0; 3];
        let clock = Instant::now();
        for q in queries.iter().filter(|_| !only_ad) {
            let h = graph.heuristic(GridHeuristic::Octile, q.goal);
            expansions[0] += search.astar(&graph, q.start, q.goal, h)?.stats.expansions;
        }
        times[0].push(clock.elapsed().as_secs_f64());
        let clock = Instant::now();
        for q in queries.iter().filter(|_| !only_ad) {
            let h = graph.heuristic(GridHeuristic::Octile, q.goal);
            let found =
                search.ara_star(&graph, q.start, q.goal, h, schedule, Termination::unlimited(), |_| {
                    ControlFlow::Break(())
                })?;
            expansions[1] += found.stats.expansions;
        }
        times[1].push(clock.elapsed().as_secs_f64());
        let clock = Instant::now();
        for q in &queries {
            ad.reset(&graph, q.start, q.goal)?;
            expansions[2] += ad.improve_once(&graph)?.stats.expansions;
        }
        times[2].push(clock.elapsed().as_secs_f64());
    }
    let median = |t: &mut Vec<f64>| {
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    };
    let [a, ara, adt] = times.each_mut().map(median);
    let per = |t: f64, e: u64| t * 1e9 / e.max(1) as f64;
    println!("{name}: {} queries (median of 7 rounds)", queries.len());
    for (label, t, e) in
        [("A*", a, expansions[0]), ("ARA* first", ara, expansions[1]), ("AD* first", adt, expansions[2])]
    {
        println!(
            "  {label:<11} {:>8.3} ms/query {:>9} expansions/query {:>6.1} ns/expansion",
            t * 1e3 / queries.len() as f64,
            e / queries.len() as u64,
            per(t, e)
        );
    }
    if !only_ad {
        println!("  speedup over A*: ARA* {:.1}x, AD* {:.1}x", a / ara, a / adt);
    }
    Ok(())
}
