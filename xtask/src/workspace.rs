//! Where the harness finds the workspace: the folder of `Cargo.lock`, `docs/` and `target/`.

use std::path::PathBuf;

/// The workspace root (the parent of this package's folder).
pub fn root() -> PathBuf {
    let here = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    here.parent().map(PathBuf::from).unwrap_or(here)
}
