//! Contingency route planning over choke points that may turn out blocked.
//!
//! A vehicle crossing terrain with bridges, passes and roads through forest does not know in
//! advance whether each choke point is open; it finds out on approach. A [`Terrain`] is a cost
//! grid with choke points, each blocked with some probability. [`plan()`] returns a plan with
//! contingencies: the preferred route, and for every choke point that may be blocked, where the
//! vehicle is when it finds out and the route it takes then, chosen to minimise the expected
//! cost over every outcome (best-first AO* search over an [`Abstraction`] of regions and choke
//! points, with admissible estimates; [`mod@reference`] solves the same problem by exhaustive
//! recursion on the grid, for tests).
//!
//! ```
//! use trailmark_core::{Cell, Connectivity};
//! use trailmark_contingency::{ChokePoint, PlannerOptions, Terrain, grid_from_rows, plan};
//!
//! // Two rivers (~), each with a bridge (=) that may be closed, and a ford far to the south (,)
//! // that costs three times as much per step.
//! let legend = [('.', Some(1.0)), ('=', Some(1.0)), (',', Some(3.0)), ('~', None)].into_iter().collect();
//! let grid = grid_from_rows(
//!     &[
//!         "...~.....~...",
//!         "...=.....=...",
//!         "...~.....~...",
//!         "...~.....~...",
//!         "...,.....,...",
//!     ],
//!     Some(&legend),
//! )?;
//! let bridge = |name: &str, x, p| ChokePoint { name: name.into(), cells: vec![Cell::new(x, 1)], probability: p };
//! let terrain = Terrain::new(
//!     grid,
//!     Connectivity::Eight,
//!     Cell::new(0, 1),
//!     Cell::new(12, 1),
//!     vec![bridge("west bridge", 3, 0.4), bridge("east bridge", 9, 0.2)],
//! )?;
//! let planned = plan(&terrain, &PlannerOptions::default())?;
//!
//! // The plan tries both bridges, falling back to the fords; its expected cost is exact:
//! // the mean over every combination of blockages of what driving the plan costs.
//! let by_worlds: f64 = trailmark_contingency::plan::worlds(&terrain)
//!     .iter()
//!     .map(|&(blocked, p)| p * planned.plan.execute(&terrain, blocked).unwrap().cost)
//!     .sum();
//! assert!((planned.expected_cost - by_worlds).abs() < 1e-9);
//! assert!(planned.expected_cost > 12.0); // the route with both bridges open
//! println!("{}", planned.plan.to_json(&terrain));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

// One documented path per item: the root, or for the families that read better under their
// names (the abstraction's parts, detection, generators, the reference solver, Monte Carlo,
// pictures) their module. The other modules stay public, hidden, for one release.
pub mod abstraction;
pub mod detect;
pub mod generate;
#[doc(hidden)]
pub mod plan;
#[doc(hidden)]
pub mod planner;
pub mod reference;
mod regions;
mod simple_paths;
pub mod simulate;
mod spec;
pub mod svg;
#[doc(hidden)]
pub mod terrain;
mod view;

#[doc(hidden)]
pub use abstraction::Abstraction;
pub use plan::{Action, Drive, Execution, ExecutionError, Knowledge, Outcome, PlanNode, outcomes, worlds};
pub use planner::{ContingencyError, ContingencyPlan, ContingencyStats, PlannerOptions, plan};
/// Old name of [`ContingencyPlan`], kept for one release.
#[deprecated(since = "0.3.0", note = "use trailmark_contingency::ContingencyPlan")]
pub type Planned = ContingencyPlan;
/// The random generator [`simulate::sample_world`] draws from (`rand_chacha` 0.10), and the trait
/// that seeds it (`rand_core` 0.10), so a caller needs no version-matched dependency.
///
/// ```
/// use trailmark_contingency::{ChaCha8Rng, SeedableRng};
///
/// let mut rng = ChaCha8Rng::seed_from_u64(7);
/// # let _ = &mut rng;
/// ```
pub use rand_chacha::{ChaCha8Rng, rand_core::SeedableRng};
/// JSON (`serde_json` 1), the form [`PlanNode::to_json`] gives a plan in, so a caller can read
/// or embed it without a dependency of their own.
pub use serde_json;
pub use spec::TerrainSpec;
pub use terrain::{ChokePoint, MAX_CHOKE_POINTS, Terrain, TerrainError, grid_from_rows};
