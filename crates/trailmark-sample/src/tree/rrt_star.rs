//! RRT* (Karaman and Frazzoli 2011): RRT that keeps improving its path.
//!
//! Each sample is steered from its nearest state, as in RRT, and kept only when that motion is
//! valid (one check for a blocked sample). The new state is then joined to its cheapest valid
//! parent among its `k` nearest neighbours,
//! k = ⌈k_rrt ln n⌉ with k_rrt = 1.1 · 2^(d+1) · e · (1 + 1/d) (OMPL's choice), and then offers
//! itself as a cheaper parent to those neighbours (*rewiring*); a rewired node's new cost flows
//! down to all its descendants. The run goes on after the first solution until its
//! [`Termination`](trailmark_core::termination::Termination) (iterations, time, or a target cost), recording every improvement of the
//! best path. Distances are taken in the motion's direction both ways, so asymmetric spaces
//! (Dubins) work. The parent search and the rewiring ask the termination's time limit and
//! condition before each motion check: a run stops within one check of its limit.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Problem, R2, RrtStar};
//! use trailmark_core::termination::Termination;
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let problem = Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! let mut planner = RrtStar::new(KdNearest::<R2, 2>::new(&space)?).with_seed(1);
//! let plan = planner.solve(&problem, &Termination::iterations(3000))?;
//! let best = 2.0 * 58f64.sqrt() + 2.0; // up to the wall's corners, across, down
//! let cost = plan.cost().expect("solved");
//! assert!(cost >= best - 1e-9 && cost < 1.1 * best);
//! // Each improvement is cheaper than the one before.
//! assert!(plan.history.windows(2).all(|w| w[1].cost < w[0].cost));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::planner::{Grow, Grown, Job, TreePlanner};
use super::star::grow_star;
pub use super::star::neighbour_count;
use crate::nearest::NearestNeighbors;

use crate::sampler::StateSampler;
use crate::sampler::Uniform;
use crate::space::StateSpace;
use crate::validity::Validity;

/// RRT*: one tree from the start states, rewired toward lower costs until the termination;
/// see the [module](self) documentation.
pub type RrtStar<N, Q = Uniform> = TreePlanner<StarGrowth, N, Q>;

/// What makes a [`TreePlanner`] RRT*: how it grows its trees.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StarGrowth;

impl Grow for StarGrowth {
    const NAME: &'static str = "RRT*";
    const OPTIMIZES: bool = true;

    fn grow<S: StateSpace, V: Validity<S>, N: NearestNeighbors<S> + Clone, Q: StateSampler<S>>(
        job: Job<'_, S, V, Self, N, Q>,
    ) -> Grown<S> {
        grow_star(job, false)
    }
}
