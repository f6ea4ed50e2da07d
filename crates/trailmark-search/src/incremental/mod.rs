//! Incremental searches: [`LpaStar`](crate::LpaStar) and [`DStarLite`](crate::DStarLite), which
//! repair their last search after edge costs change (and, for D* Lite, as the robot moves), and
//! the machinery they share with [`AdStar`](crate::AdStar).
//!
//! LPA* searches forward from its start: `rhs(v) = min over predecessors u of g(u) + c(u, v)`,
//! and an expanded node updates its successors. D* Lite searches backward from its goal:
//! `rhs(u) = min over successors v of c(u, v) + g(v)`, and an expanded node updates its
//! predecessors. Everything else, the keys, the queue and the loop (the optimized version of
//! Koenig and Likhachev's "D* Lite", AAAI 2002, figure 4), is the same, so it is written once
//! with a direction flag. The node whose `rhs` is fixed at 0 is the *source* (LPA*'s start, D*
//! Lite's goal); the node whose value the loop computes is the *target* (LPA*'s goal, D* Lite's
//! current start).
//!
//! The pieces, bottom up: the packed queue key (`packed_key`), the `g`/`rhs` store (`values`),
//! how expanded nodes are treated (`mode`: reopened at once, or closed per iteration as AD*
//! does), the repair engine (`engine`) and the path read out of its values (`walk`), and the
//! planner between a start and a goal that LPA*, D* Lite and AD* wrap (`planner`).
//!
//! Beside them, the replanners that search forward from the robot at every plan: A* from
//! scratch (`repeated_astar`), Adaptive A* (`adaptive_astar`, which learns its heuristic from
//! earlier plans) and MPGAA* (`mpgaa_star`, which also keeps their paths, `path_reuse`); and
//! the one interface of them all (`replanner`).

use serde::{Deserialize, Serialize};
use trailmark_core::cost::Cost;

pub use trailmark_core::graph::EdgeChange;

pub(crate) mod adaptive_astar;
pub(crate) mod all_pairs;
pub(crate) mod dstar_lite;
pub(crate) mod engine;
pub(crate) mod lifelong;
pub(crate) mod lpa_star;
pub(crate) mod mode;
pub(crate) mod mpgaa_star;
pub(crate) mod packed_key;
pub(crate) mod path_reuse;
pub(crate) mod planner;
pub(crate) mod repeated_astar;
pub(crate) mod replanner;
pub(crate) mod values;
pub(crate) mod walk;

/// The priority of a node in the queue of LPA* and D* Lite: `[min(g, rhs) + h (+ k_m);
/// min(g, rhs)]`, compared lexicographically (smaller first).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Serialize, Deserialize)]
pub struct Key {
    /// `min(g, rhs) + h`, plus the key modifier `k_m` in D* Lite.
    pub primary: Cost,
    /// `min(g, rhs)`, which breaks ties of the primary part.
    pub secondary: Cost,
}

impl Key {
    /// A key from its two parts.
    pub fn new(primary: Cost, secondary: Cost) -> Self {
        Key { primary, secondary }
    }
}

/// What an expansion did to a node's `g`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Consistency {
    /// `g > rhs`: `g` was lowered to `rhs` (the node is now consistent).
    Overconsistent,
    /// `g < rhs`: `g` was raised to infinity (the node will be expanded again if it can still be
    /// reached).
    Underconsistent,
}

/// One expansion of an incremental search, as reported to a trace callback.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expansion<N> {
    /// The node expanded.
    pub node: N,
    /// Its key when it left the queue.
    pub key: Key,
    /// Whether it was over- or underconsistent.
    pub kind: Consistency,
}
