//! Unit tests of Dubins paths.

use super::*;
use proptest::prelude::*;
use std::f64::consts::PI;

fn pose(x: f64, y: f64, h: f64) -> Pose {
    Pose::new(Vector::new(x, y), h)
}

/// The angle between two headings, in `[0, π]`.
fn angle_between(a: f64, b: f64) -> f64 {
    let d = mod_tau(a - b);
    d.min(TAU - d)
}

fn close(a: &Pose, b: &Pose, tol: f64) -> bool {
    (a.translation.vector - b.translation.vector).norm() <= tol
        && angle_between(a.rotation.angle(), b.rotation.angle()) <= tol
}

/// Poses 1e200 apart with a radius of 1e199 are ten radii apart, in range: the plain norm
/// of their offset overflowed to infinity and called them out of range (a Dubins space with
/// a radius of 4e210 then panicked when its planner's steps went past 1e154).
#[test]
fn huge_offsets_are_measured_without_overflow() {
    let far = pose(1e200, 0.0, 0.0);
    let path = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &far, 1e199).unwrap();
    assert!((path.length() - 1e200).abs() <= 1e-9 * 1e200, "{}", path.length());
}

/// A left arc of angle φ from the origin, then a straight piece as long, for φ down to 1e-6:
/// the length is twice the arc's, to nine digits.
#[test]
fn short_curves_keep_their_length() {
    for radius in [1.0f64, 0.125, 1e6] {
        for phi in [1e-3f64, 1e-4, 1e-5, 1e-6] {
            // The arc, then as long a straight piece.
            let s = radius * phi;
            let goal =
                pose(radius * phi.sin() + s * phi.cos(), radius * (1.0 - phi.cos()) + s * phi.sin(), phi);
            let length = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &goal, radius).unwrap().length();
            let expected = 2.0 * radius * phi;
            assert!(
                (length - expected).abs() <= 1e-9 * expected,
                "radius {radius}, angle {phi}: {length} vs {expected}"
            );
        }
    }
}

#[test]
fn coincident_poses_give_an_empty_path() {
    let p = pose(3.0, -2.0, 1.0);
    let path = DubinsPath::shortest(&p, &p, 2.0).unwrap();
    assert_eq!(path.length(), 0.0);
    assert!(close(&path.end(), &p, 1e-12));
    assert_eq!(path.sample(0.5).unwrap().len(), 1);
}

/// A pose a short arc ahead (or one arc then its mirror) is reached along those arcs, not a
/// full turn later: the straight piece between them has length ~0 and no reliable
/// direction, and its square may round below 0.
#[test]
fn poses_on_one_or_two_touching_arcs_are_found_despite_rounding() {
    let mut worst: f64 = 0.0;
    for i in 0..3000 {
        let (x, y, h) = (f64::from(i % 37) * 0.37 - 5.0, f64::from(i % 23) * 0.51, f64::from(i) * 0.0137);
        let a = pose(x, y, h);
        let r = 0.3 + f64::from(i % 5) * 0.4;
        for (word, arcs) in [
            (DubinsWord::Lsl, [0.01, 0.0]),
            (DubinsWord::Rsr, [0.01, 0.0]),
            (DubinsWord::Lsl, [0.3, 0.0]),
            (DubinsWord::Lsl, [2.5, 0.0]),
            (DubinsWord::Lsr, [0.2, 0.1]),
            (DubinsWord::Rsl, [0.05, 0.4]),
        ] {
            let b =
                DubinsPath { start: Start::of(&a), turning_radius: r, word, params: [arcs[0], 0.0, arcs[1]] }
                    .end();
            let length = DubinsPath::shortest_length(&a, &b, r).unwrap();
            let shortest = DubinsPath::shortest(&a, &b, r).unwrap();
            // Such poses are ill-conditioned: a straight piece of length ~0 comes out of a
            // square root of rounding noise, about √ε of a radius.
            assert!(
                close(&shortest.end(), &b, 1e-7 * r),
                "{i} {word}: ends at {:?}, not {b:?}",
                shortest.end()
            );
            worst = worst.max(length - (arcs[0] + arcs[1]) * r);
        }
    }
    assert!(worst < 1e-6, "{worst}");
}

#[test]
fn straight_ahead_is_a_segment() {
    let path = DubinsPath::shortest(&pose(1.0, 1.0, PI / 2.0), &pose(1.0, 6.0, PI / 2.0), 1.0).unwrap();
    assert!((path.length() - 5.0).abs() < 1e-12);
    assert!(path.normalised_params()[0].abs() < 1e-12);
    assert!(matches!(path.pieces()[1], Piece::Segment { .. }));
}

#[test]
fn bad_input_is_an_error() {
    let (a, b) = (pose(0.0, 0.0, 0.0), pose(1.0, 0.0, 0.0));
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(DubinsPath::shortest(&a, &b, r), Err(DubinsError::InvalidRadius(_))));
    }
    let nan = pose(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        DubinsPath::shortest(&a, &nan, 1.0),
        Err(DubinsError::NonFinitePose { which: "goal", .. })
    ));
    let path = DubinsPath::shortest(&a, &b, 1.0).unwrap();
    for s in [-0.1, 1.5, f64::NAN] {
        assert!(matches!(path.pose_at(s), Err(DubinsError::OutOfRange { .. })));
        assert!(matches!(path.subpath(s), Err(DubinsError::OutOfRange { .. })));
    }
    for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(path.sample(step), Err(DubinsError::InvalidStep(_))));
    }
    // Far apart: no three-turn path.
    let far = pose(10.0, 0.0, 0.0);
    assert_eq!(
        DubinsPath::with_word(&a, &far, 1.0, DubinsWord::Rlr),
        Err(DubinsError::NoPath(DubinsWord::Rlr))
    );
}

#[test]
fn words_round_trip_through_json() {
    let path = DubinsPath::shortest(&pose(0.0, 0.0, 0.3), &pose(-2.0, 1.0, 2.0), 0.7).unwrap();
    let json = serde_json::to_string(&path).unwrap();
    assert!(json.contains(&format!("\"{}\"", path.word().name())));
    let back: DubinsPath = serde_json::from_str(&json).unwrap();
    // The heading is written as an angle, so the start comes back to within rounding.
    assert_eq!((back.word(), back.normalised_params()), (path.word(), path.normalised_params()));
    assert!(close(&back.start(), &path.start(), 1e-15));
    assert!(close(&back.end(), &path.end(), 1e-12));
    assert!(json.contains("\"start\":[0.0,0.0,0.3"), "{json}");
}

fn any_pose() -> impl Strategy<Value = Pose> {
    (-20.0..20.0f64, -20.0..20.0f64, -10.0..10.0f64).prop_map(|(x, y, h)| pose(x, y, h))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The shortest path joins the poses, is at least the straight-line distance, and is no
    /// longer than any word that joins them (each of which joins them too).
    #[test]
    fn shortest_joins_the_poses_and_beats_every_word(
        a in any_pose(), b in any_pose(), r in 0.05..5.0f64,
    ) {
        let scale = 1.0 + a.translation.vector.norm() + b.translation.vector.norm();
        let tol = 1e-9 * scale / r.min(1.0);
        let best = DubinsPath::shortest(&a, &b, r).unwrap();
        prop_assert!(close(&best.start(), &a, 1e-12 * scale));
        prop_assert!(close(&best.end(), &b, tol), "{:?} ends at {:?}, not {:?}", best, best.end(), b);
        let euclid = (b.translation.vector - a.translation.vector).norm();
        prop_assert!(best.length() >= euclid - 1e-9 * scale);
        let length = DubinsPath::shortest_length(&a, &b, r).unwrap();
        prop_assert!((best.length() - length).abs() <= 1e-12 * length.max(1.0), "{} vs {}", best.length(), length);
        let mut joined = 0;
        for word in DubinsWord::ALL {
            if let Ok(path) = DubinsPath::with_word(&a, &b, r, word) {
                joined += 1;
                prop_assert!(close(&path.end(), &b, tol), "{} ends at {:?}", word, path.end());
                // Words of equal length may be ranked either way by rounding.
                prop_assert!(best.length() <= path.length() + 1e-12 * (1.0 + path.length()));
            }
        }
        prop_assert!(joined >= 1);
    }

    /// On poses with round coordinates and headings (collinear poses, equal headings, turns
    /// of exactly 0 or π: where the shortcut for `LSL` and `RSR` must defer to the full
    /// evaluation), the shortest length is the least over the six words.
    #[test]
    fn shortest_is_the_least_word_on_degenerate_poses(
        a in (-4i32..=4, -4i32..=4, 0i32..8), b in (-4i32..=4, -4i32..=4, 0i32..8), r in 1i32..=3,
    ) {
        let at = |(x, y, h): (i32, i32, i32)| pose(f64::from(x), f64::from(y), f64::from(h) * PI / 4.0);
        let (a, b, r) = (at(a), at(b), f64::from(r) / 2.0);
        let least = DubinsWord::ALL
            .into_iter()
            .filter_map(|w| DubinsPath::with_word(&a, &b, r, w).ok())
            .map(|p| p.length())
            .fold(f64::INFINITY, f64::min);
        let best = DubinsPath::shortest(&a, &b, r).unwrap();
        prop_assert!((best.length() - least).abs() <= 1e-9, "{} vs {least}", best.length());
    }

    /// Evaluating, cutting and sampling agree with one another.
    #[test]
    fn pose_at_subpath_and_sample_agree(a in any_pose(), b in any_pose(), r in 0.1..3.0f64, f in 0.0..=1.0f64) {
        let path = DubinsPath::shortest(&a, &b, r).unwrap();
        let s = f * path.length();
        let at = path.pose_at(s).unwrap();
        let cut = path.subpath(s).unwrap();
        prop_assert!((cut.length() - s).abs() <= 1e-9 * (1.0 + s));
        prop_assert!(close(&cut.end(), &at, 1e-9 * (1.0 + path.length())));
        prop_assert!(close(&path.pose_at(path.length()).unwrap(), &path.end(), 1e-9));
        let step = (path.length() / 7.3).max(0.01);
        let samples = path.sample(step).unwrap();
        prop_assert!(close(&samples[0], &a, 1e-9 * (1.0 + a.translation.vector.norm())));
        prop_assert!(close(samples.last().unwrap(), &path.end(), 0.0));
        for pair in samples.windows(2) {
            let gap = (pair[1].translation.vector - pair[0].translation.vector).norm();
            prop_assert!(gap <= step * (1.0 + 1e-9));
        }
    }

    /// The pieces chain: each ends where the next starts, arcs at the turning radius.
    #[test]
    fn pieces_chain(a in any_pose(), b in any_pose(), r in 0.1..3.0f64) {
        let path = DubinsPath::shortest(&a, &b, r).unwrap();
        let ends = path.pieces().map(|piece| match piece {
            Piece::Segment { from, to } => (from, to),
            Piece::Arc { center, radius, start_angle, sweep } => {
                let at = |angle: f64| center + radius * Vector::new(angle.cos(), angle.sin());
                (at(start_angle), at(start_angle + sweep))
            }
        });
        let tol = 1e-9 * (1.0 + path.length() + a.translation.vector.norm());
        prop_assert!((ends[0].0.coords - a.translation.vector).norm() <= tol);
        prop_assert!((ends[0].1 - ends[1].0).norm() <= tol);
        prop_assert!((ends[1].1 - ends[2].0).norm() <= tol);
        prop_assert!((ends[2].1.coords - path.end().translation.vector).norm() <= tol);
    }
}

/// Far from the origin: exact poses (one position, a quarter turn apart) are joined as at the
/// origin, not by a word whose circles overlap; poses on one short arc, computed along
/// it, by that arc, not a full turn later; and the two ways of measuring agree.
#[test]
fn far_from_the_origin_arcs_stay_arcs() {
    for far in [20.0, 1e4, 1e8] {
        let a = pose(far, 0.0, 0.0);
        let b = pose(far, 0.0, PI / 2.0);
        let path = DubinsPath::shortest(&a, &b, 1.0).unwrap();
        assert!(close(&path.end(), &b, 1e-9 * far), "{far}: ends at {:?}", path.end());
        // The same query at the origin: paths do not depend on where they are.
        let home = DubinsPath::shortest(&pose(0.0, 0.0, 0.0), &pose(0.0, 0.0, PI / 2.0), 1.0).unwrap();
        assert!(
            (path.length() - home.length()).abs() < 1e-6,
            "{far}: {} against {}",
            path.length(),
            home.length()
        );
        for (i, &arc) in [0.05, 0.3, 1e-3].iter().enumerate() {
            for word in [DubinsWord::Lsl, DubinsWord::Rsr] {
                let start = pose(far + 0.37 * i as f64, far * 0.5, 1.3 * i as f64 + 0.2);
                let end = DubinsPath {
                    start: Start::of(&start),
                    turning_radius: 1.0,
                    word,
                    params: [arc, 0.0, 0.0],
                }
                .end();
                let path = DubinsPath::shortest(&start, &end, 1.0).unwrap();
                let length = DubinsPath::shortest_length(&start, &end, 1.0).unwrap();
                assert!((path.length() - arc).abs() < 1e-6, "{far} {word} {arc}: {}", path.length());
                assert!((length - path.length()).abs() < 1e-9, "{far} {word} {arc}: {length}");
                assert!(close(&path.end(), &end, 1e-7 * (1.0 + far * 1e-6)), "{far} {word} {arc}");
            }
        }
    }
}
