//! Strategies shared by the integration tests.

#![allow(dead_code)]

use proptest::prelude::*;
use trailmark::prelude::*;

/// A random grid with about `density` of its cells blocked, as rows of `.` and `@`.
pub fn grid_strategy() -> impl Strategy<Value = Grid> {
    (2usize..14, 2usize..14, 0.0f64..0.45, any::<u64>()).prop_map(|(w, h, density, seed)| {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let rows: Vec<String> = (0..h)
            .map(|_| (0..w).map(|_| if rng.random_bool(density) { '@' } else { '.' }).collect())
            .collect();
        Grid::from_rows(&rows).expect("valid rows")
    })
}
