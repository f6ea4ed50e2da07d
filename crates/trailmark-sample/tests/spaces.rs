//! State spaces and nearest neighbours on random data: the k-d tree answers exactly what brute
//! force answers, in both directions, for every space; the spaces' motions behave as documented.

use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use trailmark_core::world::Bounds;
use trailmark_sample::SVector;
use trailmark_sample::nearest::{BruteForce, Direction, KdNearest, NearestNeighbors};
use trailmark_sample::space::{Dubins, Joints, R2, ReedsShepp, Rn, Se2, SpaceError, StateSpace};

fn bounds() -> Bounds {
    Bounds::new(-5.0, 0.0, 15.0, 10.0).unwrap()
}

/// Fills a k-d tree and a brute-force set with the same `n` random states (a few repeated, to
/// exercise equal positions) and compares their answers for random queries.
fn agree<S: StateSpace, const D: usize>(
    space: &S,
    seed: u64,
    n: usize,
    k: usize,
    radius: f64,
) -> Result<(), TestCaseError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut tree = KdNearest::<S, D>::new(space).unwrap();
    let mut brute = BruteForce::<S>::new();
    let mut states: Vec<S::State> = Vec::new();
    for i in 0..n {
        let state = if i % 7 == 6 { states[i / 2 % states.len()].clone() } else { space.sample(&mut rng) };
        states.push(state.clone());
        prop_assert_eq!(tree.insert(space, state.clone()), brute.insert(space, state));
    }
    prop_assert_eq!(tree.len(), n);
    for _ in 0..20 {
        let q = space.sample(&mut rng);
        for direction in [Direction::ToQuery, Direction::FromQuery] {
            prop_assert_eq!(tree.nearest(space, &q, direction), brute.nearest(space, &q, direction));
            prop_assert_eq!(
                tree.k_nearest(space, &q, k, direction),
                brute.k_nearest(space, &q, k, direction)
            );
            prop_assert_eq!(
                tree.within(space, &q, radius, direction),
                brute.within(space, &q, radius, direction)
            );
        }
    }
    Ok(())
}

/// Steering moves at most the step toward the target, along the motion; interpolation ends
/// at the endpoints; the distance is at least the positions' straight-line distance (what
/// the k-d tree relies on).
fn check<S: StateSpace>(space: &S, seed: u64, step: f64) -> Result<(), TestCaseError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (a, b) = (space.sample(&mut rng), space.sample(&mut rng));
    let d = space.distance(&a, &b);
    prop_assert!(d >= 0.0 && d <= space.extent() + 1e-9, "{d} > extent {}", space.extent());
    let close = |x: &S::State, y: &S::State| space.distance(x, y).min(space.distance(y, x)) < 1e-6;
    prop_assert!(close(&space.interpolate(&a, &b, 0.0), &a));
    prop_assert!(close(&space.interpolate(&a, &b, 1.0), &b));
    let s = space.steer(&a, &b, step);
    let moved = space.distance(&a, &s);
    prop_assert!(moved <= step + 1e-9 && moved <= d + 1e-9, "moved {moved}, step {step}, distance {d}");
    // What is left to go plus what was gone is the whole way (up to rounding).
    prop_assert!((moved + space.distance(&s, &b) - d).abs() <= 1e-6 * (1.0 + d));
    let (pa, pb) = (space.position::<2>(&a), space.position::<2>(&b));
    if let (Some(pa), Some(pb)) = (pa, pb) {
        let line = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2)).sqrt();
        prop_assert!(d >= line - 1e-9);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn kd_tree_equals_brute_force_in_every_space(seed in any::<u64>(), n in 1usize..400, k in 1usize..20, radius in 0.0f64..6.0) {
        agree::<_, 2>(&R2::new(bounds()), seed, n, k, radius)?;
        agree::<_, 3>(&Rn::new([0.0, -1.0, 2.0], [1.0, 1.0, 5.0]).unwrap(), seed, n, k, radius / 4.0)?;
        // A wrapping joint: its cosine and sine, and a coordinate of padding.
        let joints = Joints::new([0.0, -1.0, 2.0], [1.0, 1.0, 5.0], [false, true, false]).unwrap();
        agree::<_, 5>(&joints, seed, n, k, radius / 4.0)?;
        agree::<_, 2>(&Se2::new(bounds()), seed, n, k, radius)?;
        agree::<_, 2>(&Dubins::new(bounds(), 0.4 + radius / 4.0).unwrap(), seed, n, k, radius + 1.0)?;
        agree::<_, 2>(&ReedsShepp::new(bounds(), 0.4 + radius / 4.0).unwrap(), seed, n, k, radius + 1.0)?;
    }

    /// Steering moves at most the step toward the target, along the motion; interpolation ends
    /// at the endpoints; the distance is at least the positions' straight-line distance (what
    /// the k-d tree relies on).
    #[test]
    fn motions_stay_on_their_way(seed in any::<u64>(), step in 0.01f64..8.0) {
        check(&R2::new(bounds()), seed, step)?;
        check(&Rn::new([0.0; 4], [1.0, 2.0, 3.0, 4.0]).unwrap(), seed, step)?;
        check(&Se2::new(bounds()), seed, step)?;
        check(&Joints::new([0.0; 2], [1.0, 2.0], [true, false]).unwrap(), seed, step)?;
    }

    /// A wrapping joint's difference is the short way round: never more than π, and the
    /// motion's states are those of turning by it; the positions' distance is a lower bound.
    #[test]
    fn wrapping_joints_turn_the_short_way(a in -3.2f64..3.2, b in -3.2f64..3.2, x in 0.0f64..1.0, y in 0.0f64..1.0, t in 0.0f64..1.0) {
        use std::f64::consts::{PI, TAU};
        let space = Joints::new([0.0, -PI], [1.0, PI], [false, true]).unwrap();
        let (mut p, mut q) = (SVector::from([x, a]), SVector::from([y, b]));
        space.enforce_bounds(&mut p);
        space.enforce_bounds(&mut q);
        prop_assert!(space.satisfies_bounds(&p) && space.satisfies_bounds(&q));
        let turn = space.difference(&p, &q)[1];
        prop_assert!(turn.abs() <= PI + 1e-12);
        // The same angle as q's, up to whole turns.
        let off = (p[1] + turn - q[1]) / TAU;
        prop_assert!((off - off.round()).abs() < 1e-12);
        prop_assert!((space.distance(&p, &q) - ((y - x).powi(2) + turn * turn).sqrt()).abs() < 1e-12);
        let m = space.interpolate(&p, &q, t);
        prop_assert!(space.satisfies_bounds(&m));
        prop_assert!((space.distance(&p, &m) - t * space.distance(&p, &q)).abs() < 1e-9);
        let (pp, pq) = (space.position::<3>(&p).unwrap(), space.position::<3>(&q).unwrap());
        let line = (0..3).map(|i| (pp[i] - pq[i]).powi(2)).sum::<f64>().sqrt();
        prop_assert!(line <= space.distance(&p, &q) + 1e-12);
        prop_assert!(space.position::<2>(&p).is_none());
    }

    /// The same for Dubins motions. A pose a short arc ahead (what steering along a first arc
    /// gives) once measured a full turn too long: the straight piece of length ~0 took its
    /// direction from rounding noise (seed 4826456373515848478, step 0.01).
    #[test]
    fn dubins_motions_stay_on_their_way(seed in any::<u64>(), step in 0.01f64..8.0) {
        check(&Dubins::new(bounds(), 1.0).unwrap(), seed, step)?;
    }

    /// The same for Reeds-Shepp motions, which may reverse.
    #[test]
    fn reeds_shepp_motions_stay_on_their_way(seed in any::<u64>(), step in 0.01f64..8.0) {
        check(&ReedsShepp::new(bounds(), 1.0).unwrap(), seed, step)?;
    }
}

#[test]
fn wrapped_angles_stay_within_their_bounds_at_the_seam() {
    use std::f64::consts::PI;
    let space = Joints::new([-PI], [PI], [true]).unwrap();
    for x in
        [f64::from_bits(PI.to_bits() - 1), PI, -PI, f64::from_bits((-PI).to_bits() - 1), 3.0 * PI, -5.0 * PI]
    {
        let mut s = SVector::from([x]);
        space.enforce_bounds(&mut s);
        assert!(space.satisfies_bounds(&s), "{x} -> {}", s[0]);
    }
    // ±π are one angle: distance 0, one position.
    let (a, b) = (SVector::from([PI]), SVector::from([-PI]));
    assert_eq!(space.distance(&a, &b), 0.0);
    assert_eq!(space.position::<2>(&a), space.position::<2>(&b));
}

#[test]
fn bad_spaces_are_typed_errors() {
    assert!(matches!(Rn::new([0.0, 1.0], [1.0, 1.0]), Err(SpaceError::InvalidBounds { axis: 1, .. })));
    assert!(matches!(Rn::new([f64::NAN], [1.0]), Err(SpaceError::InvalidBounds { axis: 0, .. })));
    assert!(matches!(Rn::new([-1e308], [1e308]), Err(SpaceError::InvalidBounds { axis: 0, .. }))); // infinite width
    assert!(matches!(Dubins::new(bounds(), 0.0), Err(SpaceError::NotPositive { .. })));
    assert!(matches!(ReedsShepp::new(bounds(), f64::NAN), Err(SpaceError::NotPositive { .. })));
    assert!(matches!(ReedsShepp::new(bounds(), 1e-20), Err(SpaceError::TurningRadiusOutOfScale(_))));
    assert!(matches!(Se2::with_heading_weight(bounds(), f64::INFINITY), Err(SpaceError::NotPositive { .. })));
    assert!(matches!(
        KdNearest::<R2, 3>::new(&R2::new(bounds())),
        Err(SpaceError::NoPosition { dimension: 3 })
    ));
    let space = Rn::new([0.0; 3], [1.0; 3]).unwrap();
    assert_eq!(space.measure(), 1.0);
    assert_eq!(R2::new(bounds()).measure(), 200.0);
}

#[test]
fn the_reeds_shepp_space_is_symmetric_and_reverses() {
    let space = ReedsShepp::new(bounds(), 1.0).unwrap();
    let a = nalgebra::Isometry2::new(nalgebra::Vector2::new(0.0, 5.0), 0.0);
    let b = nalgebra::Isometry2::new(nalgebra::Vector2::new(3.0, 5.0), 0.0);
    assert!((space.distance(&a, &b) - 3.0).abs() < 1e-12); // straight ahead
    assert!((space.distance(&b, &a) - 3.0).abs() < 1e-12); // straight back, in reverse
    const { assert!(<ReedsShepp as StateSpace>::SYMMETRIC) };
}

#[test]
fn the_dubins_space_is_asymmetric() {
    let space = Dubins::new(bounds(), 1.0).unwrap();
    let a = nalgebra::Isometry2::new(nalgebra::Vector2::new(0.0, 5.0), 0.0);
    let b = nalgebra::Isometry2::new(nalgebra::Vector2::new(3.0, 5.0), 0.0);
    assert!((space.distance(&a, &b) - 3.0).abs() < 1e-12); // straight ahead
    assert!(space.distance(&b, &a) > 3.0 + std::f64::consts::PI); // turn around and come back
}

/// Distances between distinct states are never 0, however close: squaring coordinates of
/// 1e-300 underflows, and a plan had ended at (0, 0) for a goal at (4e-300, 1e-300).
#[test]
fn tiny_distances_do_not_underflow_to_zero() {
    let bounds = trailmark_core::world::Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
    let r2 = R2::new(bounds);
    let (a, b) = (
        trailmark_core::geometry::Point::new(0.0, 0.0),
        trailmark_core::geometry::Point::new(4e-300, 1e-300),
    );
    let d = r2.distance(&a, &b);
    assert!(d > 0.0 && (d - 17f64.sqrt() * 1e-300).abs() < 1e-310, "{d}");
    assert_eq!(r2.distance(&a, &a), 0.0);
}

/// States go back from their coordinates, and spaces save and load, refusing bad settings.
#[test]
fn coordinates_and_saved_spaces_round_trip() {
    use trailmark_core::world::Bounds;
    use trailmark_sample::space::{Dubins, R2, Rn, Se2, StateSpace};
    let bounds = Bounds::new(0.0, 0.0, 10.0, 5.0).unwrap();
    let dubins = Dubins::new(bounds, 1.5).unwrap();
    let pose = trailmark_core::geometry::Pose::new(trailmark_core::geometry::Vector::new(2.0, 3.0), 1.25);
    let back = dubins.state_from_coordinates(&dubins.coordinates(&pose)).unwrap();
    assert!((back.rotation.angle() - 1.25).abs() < 1e-12 && back.translation == pose.translation);
    assert_eq!(dubins.state_from_coordinates(&[1.0, f64::NAN, 0.0]), None);
    assert_eq!(dubins.state_from_coordinates(&[1.0, 2.0]), None);
    let r2 = R2::new(bounds);
    assert_eq!(r2.state_from_coordinates(&[1.0, 2.0]), Some(trailmark_core::geometry::Point::new(1.0, 2.0)));
    let rn = Rn::<3>::new([0.0; 3], [1.0; 3]).unwrap();
    let q = rn.state_from_coordinates(&[0.1, 0.2, 0.3]).unwrap();
    assert_eq!(rn.coordinates(&q), [0.1, 0.2, 0.3]);

    let text = serde_json::to_string(&dubins).unwrap();
    assert_eq!(serde_json::from_str::<Dubins>(&text).unwrap(), dubins);
    let bad = text.replace("1.5", "-1.5");
    assert!(serde_json::from_str::<Dubins>(&bad).unwrap_err().to_string().contains("turning radius"));
    let se2 = Se2::with_heading_weight(bounds, 2.0).unwrap();
    assert_eq!(serde_json::from_str::<Se2>(&serde_json::to_string(&se2).unwrap()).unwrap(), se2);
    assert!(serde_json::from_str::<Se2>(r#"{"bounds": [0, 0, 1, 1], "heading_weight": 0}"#).is_err());
    assert_eq!(serde_json::from_str::<R2>(&serde_json::to_string(&r2).unwrap()).unwrap(), r2);
}
