//! The chance that the goal can still be reached from a state: the part of AO*'s estimate that
//! weighs the unseen choke points.

use std::collections::HashMap;

use trailmark_core::UnionFind;

use crate::abstraction::{Hop, NodeId};
use crate::plan::Knowledge;
use crate::simple_paths::on_simple_paths;

use super::{AoStar, ids};

/// How many unseen choke points the reach probability enumerates exactly.
const EXACT_REACH: usize = 12;

/// Joins every region of `regions` into one set.
fn join_all(uf: &mut UnionFind, regions: &[u32]) {
    if let Some((&first, rest)) = regions.split_first() {
        for &r in rest {
            uf.union(first, r);
        }
    }
}

impl AoStar<'_> {
    /// The probability that the goal can be reached from `node` given `k`, and the unseen choke
    /// points that matter to it (see [`AoStar::relevant`]). The probability is exact when at most
    /// [`EXACT_REACH`] choke points matter, otherwise the probability that every unseen choke
    /// point on the bounding route is open (a lower bound).
    pub(super) fn reach_probability(&mut self, node: NodeId, k: Knowledge) -> (f64, u64) {
        let region = self.abs.nodes()[node as usize].region;
        if let Some(&found) = self.reach.get(&(region, k)) {
            return found;
        }
        let goal_region = self.abs.nodes()[self.abs.goal() as usize].region;
        let regions = self.abs.region_count();
        let mut base = UnionFind::new(regions);
        for c in ids(k.open()) {
            join_all(&mut base, self.abs.regions_of_choke(c));
        }
        let relevant = self.relevant(&mut base, k.unknown(self.all()), [region, goal_region]);
        let p = if base.find(region) == base.find(goal_region) {
            1.0
        } else if relevant.len() <= EXACT_REACH {
            self.reach_exact(&mut base, &relevant, [region, goal_region], 1.0)
        } else {
            self.bound(node, k);
            let routes = &self.bounds[&(self.all() & !k.blocked)];
            let mut q = 1.0;
            let mut at = node;
            let unknown = k.unknown(self.all());
            while let Some((next, hop)) = routes.previous[at as usize] {
                if let Hop::Crossing(c) = hop
                    && unknown & (1 << c) != 0
                {
                    q *= 1.0 - self.terrain.choke_points()[c as usize].probability;
                }
                at = next;
            }
            q
        };
        let relevant = relevant.iter().fold(0u64, |mask, &c| mask | 1 << c);
        self.reach.insert((region, k), (p, relevant));
        (p, relevant)
    }

    /// The probability, times `q`, that the regions `ends` end up joined when each of `chokes`
    /// is open with its probability, given the regions already joined in `uf`: depth first over
    /// the choke points, open before blocked, adding a branch's whole weight as soon as the ends
    /// are joined and dropping it as soon as they cannot be.
    fn reach_exact(&self, uf: &mut UnionFind, chokes: &[usize], ends: [u32; 2], q: f64) -> f64 {
        if uf.find(ends[0]) == uf.find(ends[1]) {
            return q;
        }
        let Some((&c, rest)) = chokes.split_first() else {
            return 0.0;
        };
        let mut all_open = uf.clone();
        for &c in chokes {
            join_all(&mut all_open, self.abs.regions_of_choke(c));
        }
        if all_open.find(ends[0]) != all_open.find(ends[1]) {
            return 0.0;
        }
        let p = self.terrain.choke_points()[c].probability;
        let mut total = 0.0;
        if p < 1.0 {
            let mut open = uf.clone();
            join_all(&mut open, self.abs.regions_of_choke(c));
            total += self.reach_exact(&mut open, rest, ends, q * (1.0 - p));
        }
        if p > 0.0 {
            total += self.reach_exact(uf, rest, ends, q * p);
        }
        total
    }

    /// The unseen choke points `unknown` that can decide whether the two regions `ends` are
    /// joined, given the regions already joined in `base` (by choke points known to be open).
    ///
    /// Take the graph whose vertices are the groups of joined regions and the unseen choke
    /// points, each choke point linked to the groups it touches. Whether the ends get joined
    /// depends exactly on the choke points that lie on some simple path between them: those in
    /// the blocks (biconnected components) on the path between the ends in the block-cut tree.
    /// The others lead only into dead ends or loops off that path.
    fn relevant(&self, base: &mut UnionFind, unknown: u64, ends: [u32; 2]) -> Vec<usize> {
        let mut vertex: HashMap<u32, usize> = HashMap::new();
        let mut adjacency: Vec<Vec<usize>> = Vec::new();
        let mut group = |g: u32, adjacency: &mut Vec<Vec<usize>>| {
            *vertex.entry(g).or_insert_with(|| {
                adjacency.push(Vec::new());
                adjacency.len() - 1
            })
        };
        let ends = ends.map(|r| group(base.find(r), &mut adjacency));
        let mut chokes = Vec::new();
        for c in ids(unknown) {
            let mut groups: Vec<u32> = self.abs.regions_of_choke(c).iter().map(|&r| base.find(r)).collect();
            groups.sort_unstable();
            groups.dedup();
            if groups.len() < 2 {
                continue;
            }
            adjacency.push(Vec::new());
            let v = adjacency.len() - 1;
            chokes.push((v, c));
            for g in groups {
                let u = group(g, &mut adjacency);
                adjacency[u].push(v);
                adjacency[v].push(u);
            }
        }
        let on_path = on_simple_paths(&adjacency, ends[0], ends[1]);
        chokes.into_iter().filter(|&(v, _)| on_path[v]).map(|(_, c)| c).collect()
    }
}
