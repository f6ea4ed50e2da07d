//! Shortest paths on a MovingAI map: A* against the published optimum, and a picture.
//!
//! ```text
//! cargo run --release --example grid_astar                      # ../shared/movingai/maps/dao/den312d.map
//! cargo run --release --example grid_astar -- path/to/map.map  # any MovingAI map (its .scen beside or in ../scenarios)
//! ```
//!
//! Without a map at hand it generates a maze. The picture goes to `target/grid_astar.svg`.

use std::path::PathBuf;

use trailmark::core::generate;
use trailmark::movingai;
use trailmark::prelude::*;
use trailmark::svg::GridSvg;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let map = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or(root.join("../shared/movingai/maps/dao/den312d.map"));
    let (grid, queries) = if map.is_file() {
        let grid = movingai::read_map(&map)?;
        // The scenarios: beside the map, or in the MovingAI layout's scenarios/ folder.
        let name = map.file_name().unwrap_or_default().to_string_lossy().into_owned();
        let set = map.parent().and_then(|p| p.file_name()).unwrap_or_default();
        let candidates = [
            map.with_file_name(format!("{name}.scen")),
            map.parent()
                .and_then(|p| p.parent())
                .unwrap_or(&root)
                .join("../scenarios")
                .join(set)
                .join(format!("{name}.scen")),
        ];
        let scen = candidates.iter().find(|p| p.is_file());
        let queries = match scen {
            Some(p) => movingai::read_scenarios(p)?
                .into_iter()
                .map(|s| (s.start, s.goal, Some(s.optimal_length)))
                .collect(),
            None => Vec::new(),
        };
        println!("{}: {} x {}, {} scenarios", map.display(), grid.width(), grid.height(), queries.len());
        (grid, queries)
    } else {
        println!("{} not found: using a generated 129 x 129 maze", map.display());
        (generate::maze(129, 129, 3, 7)?, vec![(Cell::new(1, 1), Cell::new(125, 125), None)])
    };

    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let mut search = Search::new();
    let (mut expansions, mut seconds, mut worst) = (0, 0.0, None::<f64>);
    for &(start, goal, optimal) in &queries {
        let found = search.astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
        expansions += found.stats.expansions;
        seconds += found.stats.elapsed.as_secs_f64();
        if let (Some(cost), Some(optimal)) = (found.cost(), optimal) {
            worst = Some(worst.unwrap_or(0.0).max((cost - optimal).abs()));
        }
    }
    println!(
        "A*: {} queries, {expansions} expansions in {:.1} ms ({:.1} million per second)",
        queries.len(),
        seconds * 1e3,
        expansions as f64 / seconds / 1e6
    );
    if let Some(gap) = worst {
        println!("largest gap to the published optima (rounded in the files): {gap:.2e}");
    }

    // The last query, drawn with the cells A* expanded.
    if let Some(&(start, goal, _)) = queries.last() {
        let found = search.astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?;
        let path = found.path.ok_or("the last query has no path")?;
        let svg =
            GridSvg::new(&grid).cell_size(4.0).explored(search.expanded(&graph)).path(&path.nodes).to_svg();
        let out = root.join("target/grid_astar.svg");
        std::fs::create_dir_all(root.join("target"))?;
        std::fs::write(&out, svg)?;
        println!("last query: cost {:.4}, {} moves; picture in {}", path.cost, path.moves(), out.display());
    }
    Ok(())
}
