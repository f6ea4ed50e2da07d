//! Dubins paths against the 216 test vectors Andrew Walker published with his Dubins-Curves
//! library (see `data/dubins_walker.txt` for the source and licence): for every word and every
//! case, whether the word joins the poses, and if so its three normalised segment lengths and
//! its total length, within Walker's tolerance of 1e-8.

use trailmark_core::dubins::{DubinsError, DubinsPath, DubinsWord};
use trailmark_core::geometry::{Pose, Vector};

const TOLERANCE: f64 = 1e-8;

struct Case {
    line: usize,
    word: DubinsWord,
    a: f64,
    b: f64,
    d: f64,
    exists: bool,
    params: [f64; 3],
    length: f64,
}

fn cases() -> Vec<Case> {
    let text = include_str!("data/dubins_walker.txt");
    let mut cases = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.starts_with('#') || line.starts_with("word") || line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(fields.len(), 9, "line {}: {line}", i + 1);
        let word = DubinsWord::ALL
            .into_iter()
            .find(|w| w.name() == fields[0])
            .unwrap_or_else(|| panic!("line {}: unknown word {}", i + 1, fields[0]));
        let num: Vec<f64> = fields[1..].iter().map(|f| f.parse().expect("a number")).collect();
        cases.push(Case {
            line: i + 1,
            word,
            a: num[0],
            b: num[1],
            d: num[2],
            exists: num[3] == 0.0,
            params: [num[4], num[5], num[6]],
            length: num[7],
        });
    }
    cases
}

#[test]
fn walker_test_vectors() {
    let cases = cases();
    assert_eq!(cases.len(), 216);
    let mut checked = 0;
    for c in &cases {
        let start = Pose::new(Vector::new(0.0, 0.0), c.a);
        let goal = Pose::new(Vector::new(c.d, 0.0), c.b);
        match DubinsPath::with_word(&start, &goal, 1.0, c.word) {
            Ok(path) => {
                assert!(c.exists, "line {}: {} should not join the poses, got {:?}", c.line, c.word, path);
                let got = path.normalised_params();
                for (k, (got, published)) in got.iter().zip(c.params).enumerate() {
                    assert!(
                        (got - published).abs() <= TOLERANCE,
                        "line {}: {} parameter {k} is {got}, published {published}",
                        c.line,
                        c.word,
                    );
                }
                assert!((path.length() - c.length).abs() <= TOLERANCE, "line {}: length", c.line);
                checked += 1;
            }
            Err(DubinsError::NoPath(w)) => {
                assert_eq!(w, c.word);
                assert!(!c.exists, "line {}: {} should join the poses", c.line, c.word);
            }
            Err(e) => panic!("line {}: {e}", c.line),
        }
    }
    assert_eq!(checked, 160);
}

/// The shortest path of each case is the least of the published lengths of its six words.
#[test]
fn shortest_is_the_least_published_word() {
    let cases = cases();
    for group in cases.chunks(6) {
        let c = &group[0];
        assert!(group.iter().all(|g| (g.a, g.b, g.d) == (c.a, c.b, c.d)), "line {}: a group of six", c.line);
        let least = group.iter().filter(|g| g.exists).map(|g| g.length).fold(f64::INFINITY, f64::min);
        let start = Pose::new(Vector::new(0.0, 0.0), c.a);
        let goal = Pose::new(Vector::new(c.d, 0.0), c.b);
        let path = DubinsPath::shortest(&start, &goal, 1.0).unwrap();
        assert!((path.length() - least).abs() <= TOLERANCE, "line {}: {} vs {least}", c.line, path.length());
    }
}

/// Two poses 0.05 apart on one right-turn circle (the second the first's pose along the arc,
/// computed along a longer curve): the shortest path is the rest of the arc, not the near-full
/// loop that rounding of the coinciding circles' centres had put into RSR. Both RSR and RSL
/// hold the arc with pieces of length 0 after it; which one is rounding's choice.
#[test]
fn poses_on_one_circle_are_joined_by_the_arc() {
    let heading = 0.43709077816917624f64.atan2(-0.8994173956731457);
    let near = Pose::new(Vector::new(9.606196055773557, 4.604466443835626), heading);
    let end = Pose::new(Vector::new(9.561902456278117, 4.627374238340356), 2.6393592039599465);
    let path = DubinsPath::shortest(&near, &end, 1.0).unwrap();
    // The arc alone: RSR, or RSL (whose circles touch where the arc ends), with nothing after it.
    assert!(matches!(path.word(), DubinsWord::Rsr | DubinsWord::Rsl), "{}", path.word());
    assert!(path.segment_lengths()[1..].iter().all(|&l| l < 1e-9), "{:?}", path.segment_lengths());
    assert!((path.length() - 0.049871890665).abs() < 1e-9, "{}", path.length());
    assert!((DubinsPath::shortest_length(&near, &end, 1.0).unwrap() - path.length()).abs() < 1e-12);
    let reached = path.end();
    assert!((reached.translation.vector - end.translation.vector).norm() < 1e-9);
}
