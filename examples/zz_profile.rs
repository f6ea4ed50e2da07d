use ordered_float::OrderedFloat;
use std::time::Instant;
use trailmark::movingai;
use trailmark::prelude::*;
fn neighbours(graph: &GridGraph, c: Cell) -> impl Iterator<Item = (Cell, OrderedFloat<f64>)> {
    let mut buf = [(Cell::default(), OrderedFloat(0.0)); 8];
    let mut n = 0;
    graph.for_each_successor(c, |next, cost| {
        buf[n] = (next, OrderedFloat(cost));
        n += 1;
    });
    buf.into_iter().take(n)
}
fn main() {
    let dir = std::path::PathBuf::from("../shared/movingai");
    let args: Vec<String> = std::env::args().collect();
    let (set, name) = (args.get(1).map(|s| s.as_str()).unwrap_or("mazes"), args.get(2).map(|s| s.as_str()).unwrap_or("maze512-4-0"));
    let grid = movingai::read_map(dir.join(format!("maps/{set}/{name}.map"))).unwrap();
    let scen = movingai::read_scenarios(dir.join(format!("scenarios/{set}/{name}.map.scen"))).unwrap();
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut search = Search::new();
    let qs: Vec<_> = scen.iter().step_by(scen.len() / 100).take(100).collect();
    let (mut ours, mut theirs, mut exp) = (vec![], vec![], 0u64);
    for _ in 0..7 {
        let t = Instant::now();
        exp = 0;
        for q in &qs {
            let r = search.astar(&graph, q.start, q.goal, graph.heuristic(GridHeuristic::Octile, q.goal)).unwrap();
            exp += r.stats.expansions;
        }
        ours.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        for q in qs.iter().filter(|_| std::env::var("TM_ONLY").is_err()) {
            let p = pathfinding::prelude::astar(&q.start, |&p| neighbours(&graph, p), |&p| OrderedFloat(trailmark::core::cost::octile(p.x.abs_diff(q.goal.x), p.y.abs_diff(q.goal.y))), |&p| p == q.goal);
            std::hint::black_box(p);
        }
        theirs.push(t.elapsed().as_secs_f64());
    }
    ours.sort_by(f64::total_cmp); theirs.sort_by(f64::total_cmp);
    let (ours, theirs) = (ours[3], theirs[3]);
    println!("{name}: {:.1} ns/exp, ratio {:.2}", ours * 1e9 / exp as f64, theirs / ours);
}
