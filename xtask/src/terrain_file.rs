//! Terrain files (`TerrainSpec` documents) as the `contingency` command and the benchmark's
//! contingency section read them.

use std::path::Path;

use trailmark::contingency::TerrainSpec;
use trailmark::core::read::{MAX_DOCUMENT_BYTES, read_to_string_capped};

/// Reads a terrain file (see `TerrainSpec`) without building the terrain.
pub fn read_spec(path: &Path) -> Result<TerrainSpec, String> {
    let text = read_to_string_capped(path, MAX_DOCUMENT_BYTES).map_err(|e| e.to_string())?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}
