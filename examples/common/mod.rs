//! What the timing examples share: a MovingAI map named on the command line and its queries.

use trailmark::movingai::{self, Scenario};
use trailmark::prelude::*;

/// A map's name, its grid, and queries on it.
pub type MapQueries = (String, Grid, Vec<Scenario>);

/// The map `SET NAME` of the command line (or the default), with 100 of its scenarios spread
/// over the file (every difficulty bucket); `None` after saying so when `../shared/movingai` is
/// not beside the project.
pub fn movingai_queries(
    default_set: &str,
    default_name: &str,
) -> Result<Option<MapQueries>, Box<dyn std::error::Error>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/movingai");
    if !dir.is_dir() {
        println!("skipped: {} not found", dir.display());
        return Ok(None);
    }
    let args: Vec<String> = std::env::args().collect();
    let set = args.get(1).map_or(default_set, String::as_str);
    let name = args.get(2).map_or(default_name, String::as_str);
    let grid = movingai::read_map(dir.join(format!("maps/{set}/{name}.map")))?;
    let scenarios = movingai::read_scenarios(dir.join(format!("scenarios/{set}/{name}.map.scen")))?;
    let step = (scenarios.len() / 100).max(1);
    let queries = scenarios.into_iter().step_by(step).take(100).collect();
    Ok(Some((name.to_string(), grid, queries)))
}
