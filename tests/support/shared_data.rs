//! The reference data beside the project (`../shared/NAME`: MovingAI maps, Nav2's ROS maps),
//! for tests that use it and skip with a message without it. Included by path
//! (`#[path = ...] mod shared_data;`) by the tests of the facade and of the crates.

use std::path::{Path, PathBuf};

/// `../shared/NAME` beside the workspace, or `None` (saying what is skipped) when it is absent.
pub fn shared_data(name: &str, what: &str) -> Option<PathBuf> {
    // The workspace's root is the first folder above this crate that holds the lock file.
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let root = manifest.ancestors().find(|dir| dir.join("Cargo.lock").is_file()).unwrap_or(manifest);
    let dir = root.join("../shared").join(name);
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!("skipped: {} not found ({what})", dir.display());
        None
    }
}
