//! Unit tests of polygon worlds and their collision checks.

use super::checker::{Arc, point_segment_distance};
use super::*;

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

fn square(x: f64, y: f64, s: f64) -> Vec<Point> {
    vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]
}

/// Far from the origin, a small ring's area is the same as at the origin (the shoelace on
/// raw coordinates cancelled it away and could flip its sign).
#[test]
fn areas_do_not_depend_on_where_the_ring_is() {
    for (x, y) in [(0.0, 0.0), (990000098.9042064, 990000098.9042064), (-1e9, 1e9)] {
        let ring = [p(x + 1.0958, y), p(x + 0.6019, y + 0.6019), p(x, y + 1.0958), p(x + 1.0958, y + 1.0958)];
        let area = signed_area(&ring);
        let reference = signed_area(&ring.map(|q| p(q.x - x, q.y - y)));
        // Clockwise: the pocket the trapezoid sweep met near 1e9.
        assert!(reference < -0.5, "{reference}");
        assert!((area - reference).abs() <= 1e-6, "at ({x}, {y}): {area} vs {reference}");
    }
}

#[test]
fn bad_polygons_are_typed_errors() {
    assert_eq!(Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0)]), Err(PolygonError::TooFewVertices { count: 2 }));
    assert_eq!(
        Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 0.0), p(0.0, 0.0)]),
        Err(PolygonError::TooFewVertices { count: 2 })
    );
    assert_eq!(Polygon::new(vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0)]), Err(PolygonError::ZeroArea));
    assert_eq!(
        Polygon::new(vec![p(0.0, 0.0), p(f64::NAN, 1.0), p(2.0, 2.0)]),
        Err(PolygonError::NonFinite { vertex: 1 })
    );
    // A bow tie.
    let bow = vec![p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)];
    assert!(matches!(Polygon::new(bow), Err(PolygonError::SelfIntersecting { .. })));
    // A spike folding back on itself.
    let spike = vec![p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)];
    assert!(matches!(Polygon::new(spike), Err(PolygonError::SelfIntersecting { .. })));
    // A vertex touching another edge.
    let touch = vec![p(0.0, 0.0), p(4.0, 0.0), p(4.0, 4.0), p(2.0, 0.0), p(0.0, 4.0)];
    assert!(matches!(Polygon::new(touch), Err(PolygonError::SelfIntersecting { .. })));
}

#[test]
fn clockwise_input_is_reversed() {
    let mut v = square(0.0, 0.0, 1.0);
    v.reverse();
    let poly = Polygon::new(v).unwrap();
    assert!(poly.area() > 0.0);
    assert!(poly.is_convex());
}

#[test]
fn bad_worlds_are_typed_errors() {
    assert!(matches!(Bounds::new(0.0, 0.0, 0.0, 1.0), Err(WorldError::InvalidBounds { .. })));
    let b = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
    assert_eq!(PolygonWorld::new(b, vec![], -1.0), Err(WorldError::InvalidRadius(-1.0)));
    assert_eq!(
        PolygonWorld::new(b, vec![], f64::NAN).unwrap_err().to_string(),
        "robot radius NaN must be finite and non-negative"
    );
    let e = PolygonWorld::new(b, vec![square(1.0, 1.0, 1.0), vec![p(0.0, 0.0)]], 0.0).unwrap_err();
    assert_eq!(e, WorldError::Obstacle { index: 1, error: PolygonError::TooFewVertices { count: 1 } });
}

#[test]
fn json_round_trip_and_checked_input() {
    let text =
        r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]], "robot_radius": 0.5}"#;
    let world: PolygonWorld = serde_json::from_str(text).unwrap();
    assert_eq!(world.obstacles().len(), 1);
    let again: PolygonWorld = serde_json::from_str(&serde_json::to_string(&world).unwrap()).unwrap();
    assert_eq!(again, world);
    let bad = r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[4, 4], [6, 4]]]}"#;
    let err = serde_json::from_str::<PolygonWorld>(bad).unwrap_err().to_string();
    assert!(err.contains("obstacle 0"), "{err}");
}

#[test]
fn point_robot_segments_touch_but_do_not_enter() {
    let b = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
    let world = PolygonWorld::new(b, vec![square(4.0, 4.0, 2.0)], 0.0).unwrap();
    let c = world.checker();
    assert!(c.segment_is_free(p(0.0, 4.0), p(10.0, 4.0))); // along the bottom side
    assert!(c.segment_is_free(p(2.0, 2.0), p(4.0, 4.0))); // to a corner
    assert!(c.segment_is_free(p(3.0, 5.0), p(5.0, 3.0))); // touching a corner
    assert!(!c.segment_is_free(p(3.0, 5.0), p(5.0, 4.5))); // cutting it
    assert!(!c.segment_is_free(p(0.0, 5.0), p(10.0, 5.0)));
    assert!(!c.segment_is_free(p(2.0, 2.0), p(8.0, 8.0))); // through two corners
    assert!(!c.segment_is_free(p(-1.0, 0.0), p(1.0, 1.0))); // leaves the bounds
}

#[test]
fn arcs_against_a_square() {
    let b = Bounds::new(-10.0, -10.0, 10.0, 10.0).unwrap();
    let world = PolygonWorld::new(b, vec![square(-1.0, 3.0, 2.0)], 0.5).unwrap();
    let c = world.checker();
    let half = std::f64::consts::PI;
    // The upper half of a circle of radius 3 around the origin runs through the square.
    assert!(!c.arc_is_free(p(0.0, 0.0), 3.0, 0.0, half));
    // The lower half does not.
    assert!(c.arc_is_free(p(0.0, 0.0), 3.0, 0.0, -half));
    // Radius 2.4: the top of the arc passes 0.6 below the square, more than the robot radius.
    assert!(c.arc_is_free(p(0.0, 0.0), 2.4, 0.0, half));
    assert!(!c.arc_is_free(p(0.0, 0.0), 2.6, 0.0, half));
    // A full turn leaving the bounds.
    assert!(!c.arc_is_free(p(0.0, -8.0), 3.0, 0.0, 2.0 * half));
}

/// For a point robot the free space keeps every obstacle vertex exactly, even two closer
/// together than the snapping tolerance (extent x 2^-20): each snapped vertex goes back to
/// its nearest original. (Restoring to the first one in range once merged them and cut a
/// sliver off the obstacle.)
#[test]
fn close_vertices_survive_the_union() {
    let b = Bounds::new(0.0, 0.0, 40.0, 40.0).unwrap();
    let v = vec![
        p(19.85748855920151, 21.500917134384114),
        p(19.49651392900802, 21.218310167815684),
        p(18.772466308939965, 19.203178962697976),
        p(20.357924526009626, 17.236321386233328),
        p(20.357959235248966, 17.236309328012158),
    ];
    let world = PolygonWorld::new(b, vec![v.clone()], 0.0).unwrap();
    let space = world.free_space();
    for q in &v {
        assert!(space.position_at(*q).is_some(), "{q} lost");
    }
    let from = p(35.78906048710447, 30.95817254821389);
    assert!(!world.checker().segment_is_free(from, v[3]));
    assert!(!space.segment_is_free(from, v[3]));
}

/// The arc-to-segment distance against dense sampling of the arc, on random arcs and
/// segments: never above the sampled distance, and within the sampling's resolution of
/// it. (A segment whose line foot lay outside it once hid a crossing.)
#[test]
fn arc_to_segment_distance_matches_sampling() {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
    let mut coordinate = || rng.random_range(-4.0..4.0);
    for _ in 0..3000 {
        let (a, b) = (p(coordinate(), coordinate()), p(coordinate(), coordinate()));
        let (cx, cy, radius, start, sweep) =
            (coordinate(), coordinate(), coordinate().abs() + 0.1, coordinate(), 1.6 * coordinate());
        let arc = Arc { center: p(cx, cy), radius, start, sweep };
        let steps = 4000;
        let sampled = (0..=steps)
            .map(|k| point_segment_distance(arc.point(start + sweep * f64::from(k) / f64::from(steps)), a, b))
            .fold(f64::INFINITY, f64::min);
        let computed = arc.distance_to_segment(a, b);
        // Between samples the arc strays at most radius * (step angle)^2 / 8 from a chord,
        // and the chord's points lie within half a step of a sample.
        let step = (sweep / f64::from(steps)).abs() * radius;
        assert!(computed <= sampled + 1e-12, "{computed} > sampled {sampled}");
        assert!(computed >= sampled - step, "{computed} < sampled {sampled} for {arc:?}, {a} {b}");
    }
}

#[test]
fn grown_polygons_are_conservative_and_merge() {
    let b = Bounds::new(0.0, 0.0, 20.0, 20.0).unwrap();
    // Two squares 0.8 apart, robot radius 0.5: grown, they overlap and merge.
    let world = PolygonWorld::new(b, vec![square(5.0, 5.0, 2.0), square(7.8, 5.0, 2.0)], 0.5).unwrap();
    let space = world.free_space();
    let checker = world.checker();
    // Outer ring plus one merged hole.
    let (lo, hi) = space.bounding_box();
    assert_eq!((lo, hi), (p(0.0, 0.0), p(20.0, 20.0)));
    let holes = space.positions().iter().filter(|v| v.x > 1.0 && v.x < 19.0).count();
    assert!(holes > 8);
    // Every edge of the grown polygons is outside the exact disc sum (checked at its ends and
    // middle), and no vertex is much farther out than the circumscribed polygon's corners
    // (where two grown outlines cross, a little farther).
    let limit = 1.001 * (0.5 / (DEFAULT_ARC_STEP / 2.0).cos() + world.resolution());
    for e in 0..space.edges().len() {
        let (a, z) = space.edge_points(e);
        if !(b.contains(a) && b.contains(z)) || a.x == 0.0 || a.x == 20.0 || a.y == 0.0 || a.y == 20.0 {
            continue; // the outer boundary
        }
        for q in [a, z, a + (z - a) * 0.5] {
            assert!(checker.point_is_free(q), "{q}");
        }
        let distance = world
            .obstacles()
            .iter()
            .flat_map(|o| o.edges())
            .map(|(s, t)| point_segment_distance(a, s, t))
            .fold(f64::INFINITY, f64::min);
        assert!(distance <= limit, "{a} is {distance} from the obstacles");
    }
    assert!(!space.segment_is_free(p(7.4, 0.0), p(7.4, 20.0)));
}
