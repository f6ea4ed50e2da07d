//! Reeds-Shepp paths on random poses: each ends at the goal, no word that joins the poses is
//! shorter, the length is the same driven either way and under the mirror symmetries, never
//! longer than a Dubins path, cusps only where the gear changes, and bad input as typed errors.

use std::f64::consts::{PI, TAU};

use proptest::prelude::*;
use trailmark_core::dubins::{DubinsError, DubinsPath, Piece};
use trailmark_core::geometry::{Pose, Vector};
use trailmark_core::reeds_shepp::{Gear, ReedsSheppError, ReedsSheppPath};

fn pose() -> impl Strategy<Value = (f64, f64, f64)> {
    (-8.0..8.0f64, -8.0..8.0f64, -PI..PI)
}

fn to_pose((x, y, h): (f64, f64, f64)) -> Pose {
    Pose::new(Vector::new(x, y), h)
}

fn heading_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn the_shortest_path_ends_at_the_goal_and_no_word_is_shorter(
        a in pose(), b in pose(), radius in prop_oneof![Just(1.0), 0.2..5.0f64],
    ) {
        let (start, goal) = (to_pose(a), to_pose(b));
        let path = ReedsSheppPath::shortest(&start, &goal, radius).unwrap();
        let end = path.end();
        let scale = radius.max(1.0);
        prop_assert!((end.translation.vector - goal.translation.vector).norm() <= 1e-9 * scale * 16.0, "{path}: ends at {end:?}");
        prop_assert!(heading_gap(end.rotation.angle(), goal.rotation.angle()) <= 1e-9);
        for other in ReedsSheppPath::candidates(&start, &goal, radius).unwrap() {
            prop_assert!(path.length() <= other.length(), "{other} is shorter than {path}");
            // Every word the closed forms give ends at the goal too.
            let e = other.end();
            prop_assert!((e.translation.vector - goal.translation.vector).norm() <= 1e-8 * scale * 16.0, "{other} misses the goal");
        }
        // The length alone is the path's.
        prop_assert_eq!(ReedsSheppPath::shortest_length(&start, &goal, radius).unwrap(), path.length());
        // Saved and read back, the same path; cut anywhere, it ends where the path is there.
        // (The heading is saved as an angle, so the start's cosine and sine come back within
        // rounding; the pieces come back exactly.)
        let json = serde_json::to_string(&path).unwrap();
        let back: ReedsSheppPath = serde_json::from_str(&json).unwrap();
        prop_assert!(back.segments().eq(path.segments()));
        prop_assert_eq!(back.turning_radius(), path.turning_radius());
        prop_assert_eq!(back.start().translation, start.translation);
        prop_assert!(heading_gap(back.start().rotation.angle(), start.rotation.angle()) <= 1e-15);
        for fraction in [0.0, 0.3, 0.7, 1.0] {
            let s = fraction * path.length();
            let sub = path.subpath(s).unwrap();
            prop_assert!((sub.length() - s).abs() <= 1e-12 * scale * 16.0);
            let (e, at) = (sub.end(), path.pose_at(s).unwrap());
            prop_assert!((e.translation.vector - at.translation.vector).norm() <= 1e-9 * scale * 16.0);
        }
        // The pieces chain from the start to the goal, each ending where the path is after it.
        let mut driven = 0.0;
        let mut at = start.translation.vector;
        for (piece, segment) in path.pieces().into_iter().zip(path.segments()) {
            driven += segment.length;
            let expected = path.pose_at(driven.min(path.length())).unwrap().translation.vector;
            let (from, to) = match piece {
                Piece::Segment { from, to } => (from.coords, to.coords),
                Piece::Arc { center, radius: r, start_angle, sweep } => {
                    prop_assert!((r - radius).abs() < 1e-12 && (sweep.abs() * r - segment.length).abs() <= 1e-9 * scale);
                    let point = |a: f64| center.coords + Vector::new(a.cos(), a.sin()) * r;
                    (point(start_angle), point(start_angle + sweep))
                }
            };
            prop_assert!((from - at).norm() <= 1e-9 * scale * 16.0, "{path}: a piece starts at {from:?}, not {at:?}");
            prop_assert!((to - expected).norm() <= 1e-9 * scale * 16.0, "{path}: a piece ends at {to:?}, not {expected:?}");
            at = to;
        }
    }

    #[test]
    fn the_length_keeps_the_symmetries_and_never_exceeds_dubins(a in pose(), b in pose(), radius in 0.2..5.0f64) {
        let (start, goal) = (to_pose(a), to_pose(b));
        let length = ReedsSheppPath::shortest_length(&start, &goal, radius).unwrap();
        let tol = 1e-9 * (1.0 + length);
        // Driven the other way (from the goal to the start).
        let back = ReedsSheppPath::shortest_length(&goal, &start, radius).unwrap();
        prop_assert!((length - back).abs() <= tol, "{length} against {back} backwards");
        // Mirrored in the x axis (left and right turns swapped).
        let mirror = |(x, y, h): (f64, f64, f64)| to_pose((x, -y, -h));
        let mirrored = ReedsSheppPath::shortest_length(&mirror(a), &mirror(b), radius).unwrap();
        prop_assert!((length - mirrored).abs() <= tol, "{length} against {mirrored} mirrored");
        // Both headings turned around (every gear reversed).
        let flip = |(x, y, h): (f64, f64, f64)| to_pose((x, y, h + PI));
        let flipped = ReedsSheppPath::shortest_length(&flip(a), &flip(b), radius).unwrap();
        prop_assert!((length - flipped).abs() <= tol, "{length} against {flipped} with the headings turned around");
        // Never longer than driving forward only, nor shorter than the straight line.
        let dubins = DubinsPath::shortest(&start, &goal, radius).unwrap().length();
        prop_assert!(length <= dubins + tol, "{length} longer than Dubins' {dubins}");
        let line = (goal.translation.vector - start.translation.vector).norm();
        prop_assert!(length >= line - tol);
    }

    #[test]
    fn cusps_are_where_the_gear_changes(a in pose(), b in pose()) {
        let path = ReedsSheppPath::shortest(&to_pose(a), &to_pose(b), 1.0).unwrap();
        let mut expected = Vec::new();
        let (mut gear, mut driven) = (None, 0.0);
        for segment in path.segments() {
            if segment.length > 1e-12 {
                if gear.is_some_and(|g| g != segment.gear) {
                    expected.push(driven);
                }
                gear = Some(segment.gear);
            }
            driven += segment.length;
        }
        prop_assert_eq!(path.cusps(), expected);
        // Within each piece the car moves along its heading (forward) or against it (reverse).
        let step = 1e-5;
        let mut start = 0.0;
        for segment in path.segments() {
            if segment.length > 1e-3 {
                let s = start + 0.5 * segment.length;
                let (p, q) = (path.pose_at(s).unwrap(), path.pose_at(s + step).unwrap());
                let moved = q.translation.vector - p.translation.vector;
                let heading = Vector::new(p.rotation.re, p.rotation.im);
                let along = moved.dot(&heading) / step;
                let sign = if segment.gear == Gear::Forward { 1.0 } else { -1.0 };
                prop_assert!(along * sign > 0.9, "at {s} the car moves {along} along its heading in {:?}", segment.gear);
            }
            start += segment.length;
        }
    }
}

#[test]
fn parallel_parking_reverses_and_a_straight_line_does_not() {
    let start = to_pose((0.0, 0.0, 0.0));
    let parked = ReedsSheppPath::shortest(&start, &to_pose((0.0, 1.0, 0.0)), 1.0).unwrap();
    assert!(!parked.cusps().is_empty(), "{parked}");
    let ahead = ReedsSheppPath::shortest(&start, &to_pose((5.0, 0.0, 0.0)), 1.0).unwrap();
    assert!(ahead.cusps().is_empty());
    assert!((ahead.length() - 5.0).abs() < 1e-12, "{ahead}");
    let behind = ReedsSheppPath::shortest(&start, &to_pose((-5.0, 0.0, 0.0)), 1.0).unwrap();
    assert!((behind.length() - 5.0).abs() < 1e-12, "{behind}");
    assert!(behind.segments().filter(|s| s.length > 0.0).all(|s| s.gear == Gear::Reverse));
    // The same pose: a path of length 0.
    let stay = ReedsSheppPath::shortest(&start, &start, 1.0).unwrap();
    assert_eq!(stay.length(), 0.0);
    assert_eq!(stay.sample(0.1).unwrap().len(), 1);
}

#[test]
fn bad_input_is_a_typed_error() {
    let (a, b) = (to_pose((0.0, 0.0, 0.0)), to_pose((1.0, 2.0, 0.5)));
    for radius in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e301] {
        assert!(matches!(
            ReedsSheppPath::shortest(&a, &b, radius),
            Err(ReedsSheppError::Query(DubinsError::InvalidRadius(_)))
        ));
        assert!(ReedsSheppPath::shortest_length(&a, &b, radius).is_err());
    }
    let nan = Pose::new(Vector::new(f64::NAN, 0.0), 0.0);
    assert!(matches!(
        ReedsSheppPath::shortest(&nan, &b, 1.0),
        Err(ReedsSheppError::Query(DubinsError::NonFinitePose { which: "start", .. }))
    ));
    assert!(matches!(
        ReedsSheppPath::shortest(&a, &to_pose((1e20, 0.0, 0.0)), 1e-3),
        Err(ReedsSheppError::Query(DubinsError::OutOfScale { .. }))
    ));
    let path = ReedsSheppPath::shortest(&a, &b, 1.0).unwrap();
    for s in [-1e-9, path.length() + 1e-9, f64::NAN] {
        assert!(matches!(path.pose_at(s), Err(ReedsSheppError::Query(DubinsError::OutOfRange { .. }))));
    }
    for step in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(path.sample(step), Err(ReedsSheppError::Query(DubinsError::InvalidStep(_)))));
    }
    assert!(matches!(path.sample(1e-300), Err(ReedsSheppError::Query(DubinsError::TooManySamples { .. }))));
    assert!(matches!(
        path.subpath(path.length() * 2.0),
        Err(ReedsSheppError::Query(DubinsError::OutOfRange { .. }))
    ));
    // Saved paths that no query could give.
    let saved = serde_json::to_value(path).unwrap();
    for (field, value) in [
        ("turns", serde_json::json!("LXL")),
        ("turns", serde_json::json!("")),
        ("turns", serde_json::json!("LSLRLS")),
        ("params", serde_json::json!([1.0])),
        ("params", serde_json::json!([7.0, 0.5, 0.5])),
        ("turning_radius", serde_json::json!(-1.0)),
        ("start", serde_json::json!([1e301, 0.0, 0.0])),
    ] {
        let mut bad = saved.clone();
        bad[field] = value.clone();
        assert!(serde_json::from_value::<ReedsSheppPath>(bad).is_err(), "{field}: {value} accepted");
    }
}

/// The pose reached from `start` by one arc of `length` radii (radius 1), turning `left` or
/// right, driven forward or in reverse.
fn along_arc(start: &Pose, length: f64, left: bool, forward: bool) -> Pose {
    let (x, y, h) = (start.translation.x, start.translation.y, start.rotation.angle());
    let side = if left { 1.0 } else { -1.0 };
    let s = if forward { length } else { -length };
    // The circle's centre is one radius to the side; the heading turns by s on it.
    let (cx, cy) = (x - side * h.sin(), y + side * h.cos());
    let h2 = h + side * s;
    Pose::new(Vector::new(cx + side * h2.sin(), cy - side * h2.cos()), h2)
}

#[test]
fn a_short_arc_far_from_the_origin_is_that_arc() {
    // Two poses on one short arc: the solver's differences of nearly equal coordinates are then
    // rounding noise, and the arc must still be found (not a longer word).
    for far in [0.0, 20.0, 1e4, 1e7] {
        for (i, &arc) in [1e-3, 0.05, 0.3].iter().enumerate() {
            for (left, forward) in [(true, true), (false, true), (true, false), (false, false)] {
                let start = Pose::new(Vector::new(far + 0.37 * i as f64, far * 0.5), 1.3 * i as f64 + 0.2);
                let end = along_arc(&start, arc, left, forward);
                let length = ReedsSheppPath::shortest_length(&start, &end, 1.0).unwrap();
                let path = ReedsSheppPath::shortest(&start, &end, 1.0).unwrap();
                assert!(
                    (length - arc).abs() < 1e-6,
                    "{far} {arc} left {left} forward {forward}: {length} ({path})"
                );
                assert!(
                    (path.length() - length).abs() < 1e-9,
                    "{far} {arc}: {} against {length}",
                    path.length()
                );
            }
        }
    }
}
