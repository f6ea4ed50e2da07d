//! The k-d tree against measuring every point, on scattered, clustered, collinear and repeated
//! points, and its depth when points arrive in order.

use proptest::prelude::*;
use trailmark_space::nearest::KdTree;

/// Every point's item and squared distance, nearest first (ties by item).
fn brute<const D: usize>(points: &[[f64; D]], query: &[f64; D]) -> Vec<(u32, f64)> {
    let mut all: Vec<(u32, f64)> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (i as u32, (0..D).map(|d| (p[d] - query[d]) * (p[d] - query[d])).sum()))
        .filter(|(_, d): &(u32, f64)| !d.is_nan())
        .collect();
    all.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    all
}

/// The tree's answers equal measuring every point: the nearest (and those nearly as near), the
/// `k` nearest (the same distances, ties any of the tied items), all within a radius.
fn agree<const D: usize>(
    points: &[[f64; D]],
    queries: &[[f64; D]],
    k: usize,
    radius: f64,
) -> Result<(), TestCaseError> {
    let mut tree = KdTree::<D>::new();
    for (i, p) in points.iter().enumerate() {
        tree.insert(*p, i as u32);
    }
    prop_assert_eq!(tree.len(), points.len());
    for q in queries {
        let all = brute(points, q);
        let nearest = tree.nearest_one(q);
        prop_assert_eq!(nearest.map(|n| n.1), all.first().map(|n| n.1).filter(|d| d.is_finite()));
        if let Some((item, d)) = nearest {
            prop_assert!(all.contains(&(item, d)));
        }
        let (mut close, bound) = tree.nearest_within(q, 1.0 + 1e-6);
        close.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
        let least = all.first().map_or(f64::INFINITY, |n| n.1);
        let expected: Vec<(u32, f64)> = if least.is_finite() {
            all.iter().copied().filter(|n| n.1 <= least * (1.0 + 1e-6)).collect()
        } else {
            Vec::new()
        };
        prop_assert_eq!(close, expected);
        prop_assert_eq!(bound, least * (1.0 + 1e-6));
        let found = tree.nearest_n(q, k);
        let distances: Vec<f64> = found.iter().map(|n| n.1).collect();
        let expected: Vec<f64> = all.iter().take(k).map(|n| n.1).collect();
        prop_assert_eq!(distances, expected);
        for &(item, d) in &found {
            prop_assert_eq!(brute(&points[item as usize..=item as usize], q)[0].1, d);
        }
        let mut near = tree.within(q, radius * radius);
        near.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
        let expected: Vec<(u32, f64)> = all.iter().copied().filter(|n| n.1 <= radius * radius).collect();
        prop_assert_eq!(near, expected);
    }
    Ok(())
}

/// Points of one of five kinds from `raw` values in [0, 1): scattered, clustered in a corner,
/// on a line in order, repeated on a coarse lattice, or scattered with a few far away.
fn shaped<const D: usize>(kind: u8, raw: &[[f64; D]]) -> Vec<[f64; D]> {
    raw.iter()
        .enumerate()
        .map(|(i, r)| match kind {
            0 => r.map(|c| c * 100.0),
            1 => r.map(|c| 50.0 + c * 1e-6),
            2 => std::array::from_fn(|d| if d == 0 { i as f64 * 0.01 } else { 3.0 }),
            3 => r.map(|c| (c * 4.0).floor()),
            _ if i % 17 == 0 => r.map(|c| (c - 0.5) * 1e12),
            _ => r.map(|c| c * 100.0),
        })
        .collect()
}

fn raw_points<const D: usize>() -> impl Strategy<Value = Vec<[f64; D]>> {
    prop::collection::vec(prop::array::uniform::<_, D>(0.0f64..1.0), 0..300)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn answers_equal_every_point_measured_in_2d(
        kind in 0u8..5,
        raw in raw_points::<2>(),
        queries in prop::collection::vec(prop::array::uniform::<_, 2>(-10.0f64..110.0), 1..8),
        k in 1usize..40,
        radius in 0.0f64..30.0,
    ) {
        agree(&shaped(kind, &raw), &queries, k, radius)?;
    }

    #[test]
    fn answers_equal_every_point_measured_in_5d(
        kind in 0u8..5,
        raw in raw_points::<5>(),
        queries in prop::collection::vec(prop::array::uniform::<_, 5>(-10.0f64..110.0), 1..8),
        k in 1usize..40,
        radius in 0.0f64..60.0,
    ) {
        agree(&shaped(kind, &raw), &queries, k, radius)?;
    }
}

/// Points in order (rising along a slanted line, falling along it, or rising with every fifth
/// point scattered), enough for the tree to rebuild subtrees many times over.
fn ordered(order: u8, n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut state = seed | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.01;
            match order {
                0 => [t, 0.3 * t + next() * 1e-3],
                1 => [-t, 0.3 * t + next() * 1e-3],
                _ if i % 5 == 0 => [next() * n as f64 * 0.01, next() * 10.0],
                _ => [t, 0.3 * t],
            }
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn answers_hold_through_rebuilds(
        order in 0u8..3,
        n in 1_000usize..4_000,
        seed in any::<u64>(),
        raw in prop::collection::vec(prop::array::uniform::<_, 2>(-0.2f64..1.2), 1..6),
        k in 1usize..40,
        radius in 0.0f64..0.5,
    ) {
        let points = ordered(order, n, seed);
        let extent = n as f64 * 0.01;
        let queries: Vec<[f64; 2]> = raw.iter().map(|q| [q[0] * extent * if order == 1 { -1.0 } else { 1.0 }, q[1] * 0.3 * extent]).collect();
        agree(&points, &queries, k, radius)?;
    }
}

#[test]
fn points_beside_many_equal_ones_are_found() {
    // 2,000 equal points, then points coming ever closer to them: each parted off beside them.
    let mut points = vec![[5.0, 5.0]; 2_000];
    points.extend((0..1_000).map(|i| [6.0 - f64::from(i) * 1e-3, 5.0]));
    points.extend((0..100).map(|i| [5.0, 4.0 + f64::from(i) * 1e-3]));
    let queries = [[5.0, 5.0], [5.5, 5.0], [5.0004, 5.0], [5.0, 4.05], [0.0, 0.0]];
    agree(&points, &queries, 2_050, 0.01).expect("the same answers as measuring every point");
}

#[test]
fn points_that_are_not_finite_are_kept_and_never_nearer_than_a_number() {
    let mut points: Vec<[f64; 2]> = (0..100).map(|i| [f64::from(i), 1.0]).collect();
    points.push([f64::NAN, 0.0]);
    points.push([f64::INFINITY, 0.0]);
    points.push([f64::MAX, f64::MAX]);
    let queries = [[3.2, 0.0], [f64::MAX, f64::MAX], [f64::NAN, 1.0], [-1e300, 5.0], [f64::INFINITY, 0.0]];
    agree(&points, &queries, 110, 1e200).expect("the same answers as measuring every point");
    let mut tree = KdTree::<2>::new();
    for (i, p) in points.iter().enumerate() {
        tree.insert(*p, i as u32);
    }
    assert_eq!(tree.len(), 103);
    assert_eq!(tree.nearest_one(&[f64::NAN, 0.0]), None);
}

#[test]
fn many_equal_points_are_all_found() {
    let mut tree = KdTree::<3>::new();
    for i in 0..5_000u32 {
        tree.insert([1.0, 2.0, 3.0], i);
        if i % 100 == 0 {
            tree.insert([f64::from(i), 0.0, 0.0], 1_000_000 + i);
        }
    }
    assert_eq!(tree.len(), 5_050);
    assert_eq!(tree.within(&[1.0, 2.0, 3.0], 0.0).len(), 5_000);
    assert_eq!(tree.nearest_n(&[1.0, 2.0, 3.1], 5_001).len(), 5_001);
    assert_eq!(tree.nearest_one(&[4_900.0, 0.0, 0.0]).map(|n| n.0), Some(1_004_900));
}

#[test]
fn points_in_order_along_a_line_keep_the_tree_shallow() {
    // A connect phase's states: steps of 1e-4 of the extent, along an axis or a diagonal.
    let mut axis = KdTree::<2>::new();
    let mut diagonal = KdTree::<8>::new();
    let mut scattered = KdTree::<2>::new();
    let mut seed = 1u64;
    for i in 0..100_000u32 {
        let t = f64::from(i) * 4e-3;
        axis.insert([0.5 + t, 20.0], i);
        diagonal.insert([t; 8], i);
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        scattered.insert([(seed >> 11) as f64 / (1u64 << 53) as f64, (seed >> 13 & 0xffff) as f64], i);
    }
    // log2(100,000 / 16) is 13: splits go round the coordinates, so along an axis every other
    // split is across the line (parting nothing). A chain, one level per half bucket, would be
    // thousands deep.
    eprintln!(
        "depths: axis {}, diagonal {}, scattered {}",
        axis.depth(),
        diagonal.depth(),
        scattered.depth()
    );
    assert!(axis.depth() <= 64, "along an axis: depth {}", axis.depth());
    assert!(diagonal.depth() <= 64, "along a diagonal in 8-D: depth {}", diagonal.depth());
    assert!(scattered.depth() <= 40, "scattered: depth {}", scattered.depth());
    assert_eq!(axis.nearest_one(&[0.5 + 200.0, 19.0]).map(|n| n.0), Some(50_000));
    assert_eq!(diagonal.nearest_n(&[1.0; 8], 1)[0].0, 250);
}
