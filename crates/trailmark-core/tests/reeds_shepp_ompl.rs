//! Reeds-Shepp paths against OMPL's `ReedsSheppStateSpace` (see `data/reeds_shepp_ompl.txt` for
//! the source, the licence and how the file was made): for 1,200 seeded pose pairs at several
//! turning radii, the length of the shortest path, and the poses at a quarter, a half and three
//! quarters of it, within 1e-8.

use std::f64::consts::TAU;

use trailmark_core::geometry::{Pose, Vector};
use trailmark_core::reeds_shepp::ReedsSheppPath;

const TOLERANCE: f64 = 1e-8;

/// The difference of two headings, in `[0, pi]`.
fn heading_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

#[test]
fn lengths_and_poses_match_ompl() {
    let text = include_str!("data/reeds_shepp_ompl.txt");
    let (mut cases, mut ties) = (0, 0);
    for (i, line) in text.lines().enumerate() {
        if line.starts_with('#') || line.starts_with("r ") || line.trim().is_empty() {
            continue;
        }
        let f: Vec<f64> = line.split_whitespace().map(|v| v.parse().expect("a number")).collect();
        assert_eq!(f.len(), 17, "line {}", i + 1);
        let radius = f[0];
        let start = Pose::new(Vector::new(f[1], f[2]), f[3]);
        let goal = Pose::new(Vector::new(f[4], f[5]), f[6]);
        let path = ReedsSheppPath::shortest(&start, &goal, radius).unwrap();
        let length = path.length();
        assert!(
            (length - f[7]).abs() <= TOLERANCE,
            "line {}: length {length} against OMPL's {} ({path})",
            i + 1,
            f[7]
        );
        let short = ReedsSheppPath::shortest_length(&start, &goal, radius).unwrap();
        assert_eq!(short, length, "line {}", i + 1);
        // OMPL's poses along the way: the shortest path's, or where several words tie (the two
        // mirror images of a `C|C|C`), those of another path as short.
        let expected: Vec<[f64; 3]> = (0..3).map(|k| [f[8 + 3 * k], f[9 + 3 * k], f[10 + 3 * k]]).collect();
        let matches = |path: &ReedsSheppPath| {
            let length = path.length();
            [0.25, 0.5, 0.75].into_iter().zip(&expected).all(|(fraction, &[x, y, h])| {
                let pose = path.pose_at(fraction * length).unwrap();
                let v = pose.translation.vector;
                (v.x - x).abs() <= TOLERANCE
                    && (v.y - y).abs() <= TOLERANCE
                    && heading_gap(pose.rotation.angle(), h) <= TOLERANCE
            })
        };
        if !matches(&path) {
            let candidates = ReedsSheppPath::candidates(&start, &goal, radius).unwrap();
            let tie = candidates
                .iter()
                .find(|c| (c.length() - length).abs() <= 1e-12 * length.max(1.0) && matches(c));
            assert!(
                tie.is_some(),
                "line {}: no path of length {length} passes through OMPL's poses {expected:?} ({path})",
                i + 1
            );
            ties += 1;
        }
        cases += 1;
    }
    assert_eq!(cases, 1200);
    // Ties are few: a pair of mirror images, the same length to the last bits.
    assert!(ties <= 100, "{ties} cases matched only through a tie");
    eprintln!("{cases} cases, {ties} through a word of the same length");
}
