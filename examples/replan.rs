//! D* Lite guiding a robot toward a wall it does not know about: the robot sees the wall when it
//! comes within two cells, tells the planner which cells changed, and replans from where it
//! stands. `cargo run --release --example replan`

use trailmark::core::{Cell, Connectivity, Grid, GridHeuristic};
use trailmark::graph::GridGraph;
use trailmark::search::DStarLite;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut graph = GridGraph::new(&Grid::new(64, 64)?, Connectivity::Eight);
    let (start, goal) = (Cell::new(0, 0), Cell::new(63, 63));
    let mut planner = DStarLite::new(&graph, start, goal, graph.heuristic_between(GridHeuristic::Octile))?;
    let first = planner.compute_shortest_path(&graph)?;
    println!("first plan: cost {:?}, {} expansions", planner.cost(), first.expansions);

    // A wall across most of the map, unknown to the robot until it comes within 2 cells.
    let wall: Vec<Cell> = (0..60).map(|y| Cell::new(32, y)).collect();
    let mut steps = 0;
    while let Some(next) = planner.next_step(&graph) {
        planner.move_start(&graph, next)?;
        steps += 1;
        let mut seen = 0;
        for &cell in wall.iter().filter(|c| c.x.abs_diff(next.x) <= 2 && c.y.abs_diff(next.y) <= 2) {
            if graph.is_passable(cell) {
                graph.set_cost(cell, f64::INFINITY)?;
                planner.update_nodes(&graph, graph.cells_affected_by(cell))?;
                seen += 1;
            }
        }
        let repair = planner.compute_shortest_path(&graph)?;
        if seen > 0 {
            println!(
                "step {steps} at {next}: {seen} wall cells seen, cost to go {:?}, {} expansions",
                planner.cost(),
                repair.expansions
            );
        }
    }
    assert_eq!(planner.start(), goal);
    let totals = planner.totals();
    println!(
        "at the goal after {steps} steps: {} expansions in all, {:?} planning",
        totals.expansions, totals.elapsed
    );
    Ok(())
}
