//! How a roadmap joins a new milestone to those it already has: the `k` nearest, every one within
//! a radius, or PRM*'s growing `k`. The sampling planners' roadmaps and the polygon roadmaps
//! share it.

use serde::{Deserialize, Serialize};

/// Which milestones a new one is joined to. Saved as `{"nearest": {"k": 10}}`,
/// `{"radius": {"radius": 2.5}}` or `"prm_star"`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Connection {
    /// The `k` nearest.
    Nearest {
        /// How many.
        k: usize,
    },
    /// Every milestone within this distance.
    Radius {
        /// The distance.
        radius: f64,
    },
    /// The `k = ⌈e (1 + 1/d) ln n⌉` nearest, `n` the milestones and `d` the dimension: PRM*.
    PrmStar,
}

impl Connection {
    /// The neighbours to ask for in a roadmap of `n` milestones in dimension `d` (`None`: by
    /// radius).
    pub fn neighbour_count(&self, n: usize, d: usize) -> Option<usize> {
        match *self {
            Connection::Nearest { k } => Some(k),
            Connection::Radius { .. } => None,
            Connection::PrmStar => {
                let k = std::f64::consts::E * (1.0 + 1.0 / d.max(1) as f64) * (n.max(1) as f64).ln();
                Some(k.ceil() as usize)
            }
        }
    }
}
