//! trailmark A* against `pathfinding::prelude::astar` on the same queries of one MovingAI map,
//! in interleaved rounds (trailmark, then pathfinding, seven times), so that a slow drift of the
//! machine affects both alike: the ratio it prints moves less between runs than the one of two
//! separate criterion groups. Also a convenient target for `perf record`.
//!
//! `cargo run --release --example astar_interleaved -- [SET NAME]` (default: mazes maze512-4-0);
//! needs `../shared/movingai`. `TM_ONLY=1` times trailmark alone.

use std::time::Instant;

use ordered_float::OrderedFloat;
use trailmark::prelude::*;

mod common;

/// The grid's moves as `pathfinding` wants them, through a fixed array (no allocation).
fn neighbours(graph: &GridGraph, c: Cell) -> impl Iterator<Item = (Cell, OrderedFloat<f64>)> {
    let mut buf = [(Cell::default(), OrderedFloat(0.0)); 8];
    let mut n = 0;
    graph.for_each_successor(c, |next, cost| {
        buf[n] = (next, OrderedFloat(cost));
        n += 1;
    });
    buf.into_iter().take(n)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let Some((name, grid, queries)) = common::movingai_queries("mazes", "maze512-4-0")? else {
        return Ok(());
    };
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let only_ours = std::env::var("TM_ONLY").is_ok();
    let mut search = Search::new();
    let (mut ours, mut theirs, mut expansions) = (Vec::new(), Vec::new(), 0);
    for _ in 0..7 {
        let clock = Instant::now();
        expansions = 0;
        for q in &queries {
            let found =
                search.astar(&graph, q.start, q.goal, graph.heuristic(GridHeuristic::Octile, q.goal))?;
            expansions += found.stats.expansions;
        }
        ours.push(clock.elapsed().as_secs_f64());
        let clock = Instant::now();
        for q in queries.iter().filter(|_| !only_ours) {
            let found = pathfinding::prelude::astar(
                &q.start,
                |&c| neighbours(&graph, c),
                |&c| {
                    OrderedFloat(trailmark::core::cost::octile(
                        c.x.abs_diff(q.goal.x),
                        c.y.abs_diff(q.goal.y),
                    ))
                },
                |&c| c == q.goal,
            );
            std::hint::black_box(found);
        }
        theirs.push(clock.elapsed().as_secs_f64());
    }
    ours.sort_by(f64::total_cmp);
    theirs.sort_by(f64::total_cmp);
    let (ours, theirs) = (ours[3], theirs[3]);
    println!(
        "{name}: {} queries, trailmark {:.1} ns per expansion, {:.2} ms per query; pathfinding / trailmark {:.2}x",
        queries.len(),
        ours * 1e9 / expansions as f64,
        ours * 1e3 / queries.len() as f64,
        theirs / ours
    );
    Ok(())
}
