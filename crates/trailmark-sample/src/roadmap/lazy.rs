//! Lazy PRM and Lazy PRM* (Bohlin and Kavraki 2000): the roadmap joins milestones without
//! checking the motions; a query searches it, checks the motions of the path it found (each
//! motion once, remembered), drops the blocked ones and searches again, until a path is free or
//! none is left. A symmetric space's motion is checked in one direction for both, as the eager
//! roadmap does. The roadmap's build is then sampling and nearest neighbours alone, and
//! only the motions queries lead to are ever checked; it stays for the next query, with what
//! the last one learnt.
//!
//! The path found is the shortest through the roadmap's free motions: every search runs on the
//! free motions and the unchecked ones, a superset, and ends with a path of free motions only.
//! Components count unchecked motions, so they only say where a path may be: a run searches
//! again each time the roadmap has grown by a tenth while a start and a goal share one.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::termination::Termination;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_sample::{KdNearest, Planner, Prm, Problem, R2};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.25)?.checker();
//! let space = R2::new(bounds);
//! let mut prm = Prm::lazy_star(KdNearest::<R2, 2>::new(&space)?).with_seed(3);
//! prm.grow(&space, &checker, 1_000, &Termination::iterations(100_000))?; // no motion checked
//! let plan = prm.solve(&Problem::new(&space, &checker, Point::new(1.0, 1.0), Point::new(9.0, 1.0)),
//!                      &Termination::iterations(0))?;
//! assert!(plan.is_exact()); // over the wall, every motion of the path checked
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use trailmark_core::UnionFind;
use trailmark_core::cost::Cost;

use super::prm::Prm;
use crate::nearest::NearestNeighbors;
use crate::space::StateSpace;
use crate::validity::Validity;

impl<S: StateSpace, N: NearestNeighbors<S> + Clone> Prm<S, N> {
    /// Lazy PRM: PRM whose motions are checked only on the paths its searches find.
    pub fn lazy(nearest: N) -> Self {
        let mut prm = Prm::new(nearest);
        prm.lazy = true;
        prm
    }

    /// Lazy PRM*: PRM*'s connection and improvement, its motions checked as Lazy PRM's.
    pub fn lazy_star(nearest: N) -> Self {
        let mut prm = Prm::star(nearest);
        prm.lazy = true;
        prm
    }
}

impl<S: StateSpace, N: NearestNeighbors<S> + Clone, Q> Prm<S, N, Q> {
    /// Whether motions are checked only on found paths.
    pub fn is_lazy(&self) -> bool {
        self.lazy
    }

    /// The cheapest path from a start to a goal milestone whose every motion is free: a search,
    /// then every unchecked motion of the path checked; the blocked ones are dropped from the
    /// roadmap and the search runs again, until a path is free, none is left, or `interrupted`
    /// (between searches; each search drops a motion, so the loop ends without it too). The
    /// components are recomputed once, at the end (not past the limit): stale ones only join
    /// too much, and the search uses them only to skip pairs that cannot connect.
    pub(super) fn search_checked<V: Validity<S>>(
        &mut self,
        space: &S,
        validity: &V,
        (starts, goals): (&[u32], &[u32]),
        interrupted: impl Fn() -> bool,
    ) -> Option<(Vec<u32>, f64)> {
        let mut dropped = false;
        let found = loop {
            let Some(found) = self.search(space, starts, goals) else { break None };
            let mut blocked = Vec::new();
            for pair in found.0.windows(2) {
                let key = self.motion_key(pair[0], pair[1]);
                if self.verified.contains(&key) {
                    continue;
                }
                self.checks += 1;
                if validity.motion_is_valid(space, self.state(pair[0]), self.state(pair[1])) {
                    self.verified.insert(key);
                } else {
                    blocked.push((pair[0], pair[1]));
                }
            }
            if blocked.is_empty() {
                break Some(found);
            }
            for (a, b) in blocked {
                self.drop_motion(a, b);
            }
            dropped = true;
            if interrupted() {
                // Past the limit: the components stay as they were (they only join too much,
                // and the next query that drops a motion recomputes them).
                return None;
            }
        };
        if dropped {
            self.recompute_components();
        }
        found
    }

    /// The key of the motion `a -> b` in `verified`: its two ends in order where the space is
    /// symmetric (one motion both ways).
    fn motion_key(&self, a: u32, b: u32) -> (u32, u32) {
        if S::SYMMETRIC { (a.min(b), a.max(b)) } else { (a, b) }
    }

    /// Removes the blocked motion `a -> b` (both ways in a symmetric space).
    fn drop_motion(&mut self, a: u32, b: u32) {
        let remove = |list: &mut Vec<(u32, Cost)>, other: u32| {
            let before = list.len();
            list.retain(|&(v, _)| v != other);
            before - list.len()
        };
        let removed = remove(&mut self.out[a as usize], b);
        if S::SYMMETRIC {
            remove(&mut self.out[b as usize], a);
        } else {
            remove(&mut self.into[b as usize], a);
        }
        self.edge_count -= removed;
    }

    /// The components again, from the motions left.
    fn recompute_components(&mut self) {
        let mut components = UnionFind::new(self.out.len());
        for (v, list) in self.out.iter().enumerate() {
            for &(w, _) in list {
                components.union(v as u32, w);
            }
        }
        self.components = components;
    }
}
