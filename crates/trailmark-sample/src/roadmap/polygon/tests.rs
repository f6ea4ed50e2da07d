//! Unit tests of the polygon roadmap.

use std::collections::BTreeSet;

use trailmark_core::generate::convex_obstacles;
use trailmark_core::geometry::Vector;
use trailmark_core::world::{Bounds, WorldError};
use trailmark_space::{Dubins, ReedsShepp};

use trailmark_core::graph::{Predecessors, Successors};

use super::*;

fn world(seed: u64, radius: f64) -> PolygonWorld {
    convex_obstacles(20.0, 12, 6, radius, seed).expect("a valid world")
}

fn nodes<S: PlanarSpace>(prm: &PolygonPrm<S>) -> Vec<S::State> {
    (0..prm.node_count() as u32).map(|u| prm.position(u)).collect()
}

fn options(connection: Connection) -> PrmOptions {
    PrmOptions { connection, ..PrmOptions::default() }
}

#[test]
fn prm_star_uses_karaman_and_frazzolis_k() {
    // The connection rule is trailmark-sample's, shared by both roadmaps.
    // e (1 + 1/2) ln 1000 = 28.17 and e (1 + 1/3) ln 1000 = 25.04.
    assert_eq!(Connection::PrmStar.neighbour_count(1000, 2), Some(29));
    assert_eq!(Connection::PrmStar.neighbour_count(1000, 3), Some(26));
    assert_eq!(Connection::Nearest { k: 7 }.neighbour_count(1000, 2), Some(7));
}

#[test]
fn bad_settings_are_typed_errors() {
    let w = world(1, 0.0);
    assert_eq!(
        PolygonPrm::new(w.clone(), options(Connection::Nearest { k: 0 })).err(),
        Some(PrmError::InvalidK)
    );
    for radius in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = PolygonPrm::new(w.clone(), options(Connection::Radius { radius })).err();
        assert!(matches!(e, Some(PrmError::InvalidRadius(_))), "{e:?}");
    }
    let none = PrmOptions { attempts_per_sample: 0, ..PrmOptions::default() };
    assert_eq!(PolygonPrm::new(w.clone(), none).err(), Some(PrmError::InvalidAttempts));
    let b = w.bounds();
    assert!(Dubins::new(b, 0.0).is_err() && Dubins::new(b, f64::NAN).is_err());
    let bad =
        PrmOptions { sampler: PrmSampler::Gaussian { seed: 0, std_dev: -1.0 }, ..PrmOptions::default() };
    assert!(matches!(PolygonPrm::new(w, bad).err(), Some(PrmError::PrmSampler(_))));
}

#[test]
fn sampling_a_blocked_world_gives_up_with_an_error() {
    let bounds = Bounds::new(0.0, 0.0, 1.0, 1.0).unwrap();
    let cover =
        vec![Point::new(-1.0, -1.0), Point::new(2.0, -1.0), Point::new(2.0, 2.0), Point::new(-1.0, 2.0)];
    let w = PolygonWorld::new(bounds, vec![cover], 0.0).unwrap();
    let mut prm =
        PolygonPrm::new(w, PrmOptions { attempts_per_sample: 10, ..PrmOptions::default() }).unwrap();
    assert_eq!(prm.grow(5), Err(PrmError::SamplingExhausted { requested: 5, added: 0, attempts: 50 }));
    assert!(matches!(prm.insert(Point::new(0.5, 0.5)), Err(PrmError::Blocked(_))));
}

/// The radius roadmap is the radius graph: every pair within the radius whose segment is
/// free, found by brute force over all pairs.
#[test]
fn radius_roadmap_equals_brute_force_radius_graph() {
    for (seed, r) in [(1, 0.0), (2, 0.4), (3, 1.0)] {
        let radius = 3.0;
        let mut prm = PolygonPrm::new(world(seed, r), options(Connection::Radius { radius })).unwrap();
        prm.grow(150).unwrap();
        let checker = prm.world().checker();
        let mut brute = BTreeSet::new();
        for u in 0..prm.node_count() as u32 {
            for v in u + 1..prm.node_count() as u32 {
                let (a, b) = (prm.position(u), prm.position(v));
                if (b - a).norm() <= radius && checker.segment_is_free(a, b) {
                    brute.insert((u, v));
                }
            }
        }
        let built: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a.min(b), a.max(b))).collect();
        assert_eq!(built, brute, "seed {seed}");
        assert_eq!(prm.edge_count(), brute.len());
    }
}

/// Components by union-find equal components by graph search.
#[test]
fn components_match_a_traversal() {
    let mut prm = PolygonPrm::new(world(4, 0.5), options(Connection::Nearest { k: 3 })).unwrap();
    prm.grow(120).unwrap();
    let n = prm.node_count();
    let mut label = vec![u32::MAX; n];
    let mut count = 0;
    for s in 0..n as u32 {
        if label[s as usize] != u32::MAX {
            continue;
        }
        count += 1;
        let mut stack = vec![s];
        label[s as usize] = s;
        while let Some(u) = stack.pop() {
            prm.for_each_successor(u, |v, _| {
                if label[v as usize] == u32::MAX {
                    label[v as usize] = s;
                    stack.push(v);
                }
            });
        }
    }
    assert_eq!(prm.component_count(), count);
    for u in 0..n as u32 {
        for v in 0..n as u32 {
            assert_eq!(prm.component(u) == prm.component(v), label[u as usize] == label[v as usize]);
        }
    }
}

#[test]
fn inserting_the_same_point_returns_the_same_node() {
    let mut prm = PolygonPrm::new(world(5, 0.0), PrmOptions::default()).unwrap();
    prm.grow(10).unwrap();
    let p = prm.position(3);
    // More repeats than a k-d tree bucket holds.
    for _ in 0..40 {
        assert_eq!(prm.insert(p), Ok(3));
    }
    assert_eq!(prm.node_count(), 10);
}

#[test]
fn growing_in_steps_equals_growing_at_once() {
    let bridge = PrmSampler::Bridge { seed: 4, std_dev: 0.5 };
    for sampler in [PrmSampler::Halton, PrmSampler::Uniform { seed: 9 }, bridge] {
        let o = PrmOptions { sampler, ..options(Connection::PrmStar) };
        let mut once = PolygonPrm::new(world(6, 0.3), o).unwrap();
        once.grow(90).unwrap();
        let mut steps = PolygonPrm::new(world(6, 0.3), o).unwrap();
        steps.grow(40).unwrap();
        steps.grow(50).unwrap();
        assert_eq!(nodes(&once), nodes(&steps));
        assert_eq!(once.edges().collect::<Vec<_>>(), steps.edges().collect::<Vec<_>>());
    }
}

#[test]
fn save_and_load_keep_the_roadmap_and_its_sample_stream() {
    let o = PrmOptions { sampler: PrmSampler::Uniform { seed: 11 }, ..options(Connection::Nearest { k: 5 }) };
    let mut prm = PolygonPrm::new(world(7, 0.4), o).unwrap();
    prm.grow(60).unwrap();
    let text = serde_json::to_string(&prm).unwrap();
    let mut loaded: PolygonPrm = serde_json::from_str(&text).unwrap();
    assert_eq!(nodes(&loaded), nodes(&prm));
    assert_eq!(loaded.edges().collect::<Vec<_>>(), prm.edges().collect::<Vec<_>>());
    assert_eq!(loaded.candidate_count(), prm.candidate_count());
    assert_eq!(loaded.component_count(), prm.component_count());
    prm.grow(20).unwrap();
    loaded.grow(20).unwrap();
    assert_eq!(nodes(&loaded), nodes(&prm));
    assert_eq!(loaded.attempts(), prm.attempts());

    // A flipped free flag, an edge to a missing node, a node moved into an obstacle.
    let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let flag = doc["edges"][0][2].as_u64().unwrap();
    doc["edges"][0][2] = serde_json::json!(1 - flag);
    assert!(serde_json::from_value::<PolygonPrm>(doc.clone()).unwrap_err().to_string().contains("edge 0"));
    doc["edges"][0] = serde_json::json!([0, 1000, 1]);
    assert!(serde_json::from_value::<PolygonPrm>(doc.clone()).unwrap_err().to_string().contains("edge 0"));
    let inside =
        prm.world().obstacles()[0].vertices().iter().fold(Vector::zeros(), |s, v| s + v.coords) / 6.0;
    doc["nodes"][2] = serde_json::json!([inside.x, inside.y]);
    assert!(serde_json::from_value::<PolygonPrm>(doc).unwrap_err().to_string().contains("node 2"));
}

/// After an obstacle is added and removed, the free edges are the candidates free in the
/// current world, and the reported changes are exactly the difference.
#[test]
fn obstacle_changes_report_exactly_the_changed_edges() {
    let mut prm = PolygonPrm::new(world(8, 0.3), options(Connection::Nearest { k: 6 })).unwrap();
    prm.grow(150).unwrap();
    let before: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
    let block =
        vec![Point::new(6.0, 6.0), Point::new(14.0, 6.0), Point::new(14.0, 14.0), Point::new(6.0, 14.0)];
    let changes = prm.add_obstacle(block).unwrap();
    let checker = prm.world().checker();
    let free_now = |prm: &PolygonPrm| -> BTreeSet<(u32, u32)> {
        prm.roadmap
            .tried
            .iter()
            .filter(|c| checker_free(&checker, prm, c.ends))
            .map(|c| (c.ends[0], c.ends[1]))
            .collect()
    };
    let after: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
    assert_eq!(after, free_now(&prm));
    let lost: BTreeSet<(u32, u32)> = before.difference(&after).copied().collect();
    assert!(!lost.is_empty());
    let reported: BTreeSet<(u32, u32)> =
        changes.iter().map(|c| (c.from, c.to)).filter(|(a, b)| a < b).collect();
    let lost_sorted: BTreeSet<(u32, u32)> = lost.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect();
    assert_eq!(reported, lost_sorted);
    assert_eq!(changes.len(), 2 * lost.len());

    let last = prm.world().obstacles().len() - 1;
    let changes = prm.remove_obstacle(last).unwrap();
    let restored: BTreeSet<(u32, u32)> = prm.edges().map(|(a, b, _)| (a, b)).collect();
    assert_eq!(restored, before);
    assert_eq!(changes.len(), 2 * lost.len());
    assert!(matches!(
        prm.remove_obstacle(99),
        Err(PrmError::World(WorldError::NoSuchObstacle { index: 99, .. }))
    ));
}

fn checker_free(checker: &CollisionChecker, prm: &PolygonPrm, [a, b]: [u32; 2]) -> bool {
    checker.segment_is_free(prm.position(a), prm.position(b))
}

/// Reeds-Shepp roadmaps: each edge's cost is its own shortest Reeds-Shepp path, free by the
/// exact checker, and the reverse edge, where both are free, costs the same.
#[test]
fn reeds_shepp_edges_are_free_and_cost_the_same_both_ways() {
    let w = world(9, 0.3);
    let space = ReedsShepp::new(w.bounds(), 1.5).unwrap();
    let o = PrmOptions { sampler: PrmSampler::Halton, ..options(Connection::Nearest { k: 8 }) };
    let mut prm: ReedsSheppPrm = PolygonPrm::with_space(w, space, o).unwrap();
    prm.grow(80).unwrap();
    let checker = prm.world().checker();
    let (mut edges, mut both_ways) = (0, 0);
    for (a, b, cost) in prm.edges() {
        edges += 1;
        let path = space.path(&prm.position(a), &prm.position(b));
        assert!(checker.reeds_shepp_is_free(&path));
        assert!((cost - path.length()).abs() <= 1e-12 * cost.max(1.0), "{cost} vs {}", path.length());
        prm.for_each_successor(b, |v, c| {
            if v == a {
                both_ways += 1;
                assert!((c - cost).abs() <= 1e-9 * cost.max(1.0), "{a} -> {b}: {cost}, back {c}");
            }
        });
    }
    assert!(edges > 0 && both_ways > 0, "{edges} edges, {both_ways} with their reverse");
}

/// Dubins roadmaps are directed: each edge's cost is its own shortest Dubins path, free by
/// the exact checker, and the reverse edge is checked on its own.
#[test]
fn dubins_edges_are_directed_and_free() {
    let w = world(9, 0.3);
    let space = Dubins::new(w.bounds(), 1.5).unwrap();
    let o = PrmOptions { sampler: PrmSampler::Halton, ..options(Connection::Nearest { k: 8 }) };
    let mut prm = PolygonPrm::with_space(w, space, o).unwrap();
    prm.grow(80).unwrap();
    let checker = prm.world().checker();
    let mut asymmetric = 0;
    for (a, b, cost) in prm.edges() {
        let path = space.path(&prm.position(a), &prm.position(b));
        assert!(checker.dubins_is_free(&path));
        // The space's distance is the length-only solver's, within rounding of the path's.
        assert!((cost - path.length()).abs() <= 1e-12 * cost, "{cost} vs {}", path.length());
        let mut back = None;
        prm.for_each_successor(b, |v, c| {
            if v == a {
                back = Some(c)
            }
        });
        asymmetric += usize::from(back != Some(cost));
    }
    assert!(asymmetric > 0, "Dubins edges differ by direction");
    let mut into = 0;
    for v in 0..prm.node_count() as u32 {
        prm.for_each_predecessor(v, |_, _| into += 1);
    }
    assert_eq!(into, prm.edge_count());
}
