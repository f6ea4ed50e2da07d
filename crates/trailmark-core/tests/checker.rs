//! The exact collision checker against a plain reference written here: every obstacle, every
//! edge, the segment-to-segment distance from first principles (no hierarchy, no box tests, no
//! parry). Random points and segments on generated worlds, and segments placed just inside and
//! just outside the robot's radius from an obstacle's edge, where a wrong shortcut would show.

use proptest::prelude::*;
use trailmark_core::generate;
use trailmark_core::geometry::Point;
use trailmark_core::world::PolygonWorld;

fn point_segment(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let t = if len2 > 0.0 { ((p - a).dot(&ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + ab * t)).norm()
}

fn cross(o: Point, a: Point, b: Point) -> f64 {
    (a - o).perp(&(b - o))
}

/// The distance between segments `a-b` and `c-d`: 0 when they cross, otherwise the least
/// distance from an end of one to the other.
fn segment_segment(a: Point, b: Point, c: Point, d: Point) -> f64 {
    let (d1, d2) = (cross(c, d, a), cross(c, d, b));
    let (d3, d4) = (cross(a, b, c), cross(a, b, d));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0;
    }
    point_segment(a, c, d).min(point_segment(b, c, d)).min(point_segment(c, a, b)).min(point_segment(d, a, b))
}

fn edges(vertices: &[Point]) -> impl Iterator<Item = (Point, Point)> + '_ {
    vertices.iter().zip(vertices.iter().cycle().skip(1)).map(|(&p, &q)| (p, q))
}

/// The reference: both ends in the bounds, and for every obstacle, the start not inside and
/// every edge at least the robot's radius from the segment.
fn reference_segment_is_free(world: &PolygonWorld, a: Point, b: Point) -> bool {
    let r = world.robot_radius();
    world.bounds().contains(a)
        && world.bounds().contains(b)
        && world.obstacles().iter().all(|o| {
            !o.contains_strictly(a) && edges(o.vertices()).all(|(p, q)| segment_segment(a, b, p, q) >= r)
        })
}

fn worlds() -> Vec<PolygonWorld> {
    let mut out: Vec<PolygonWorld> =
        (0..3).map(|s| generate::convex_obstacles(40.0, 30, 6, 0.25, s).expect("a world")).collect();
    out.push(generate::bug_trap(40.0, 0.25).expect("a world").0);
    out.push(generate::narrow_passages(40.0, 3, 1.5, 0.25, 1).expect("a world"));
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random segments, short and long, on every world.
    #[test]
    fn segments_match_the_reference(
        w in 0usize..5, ax in 0.0..40.0f64, ay in 0.0..40.0f64, dx in -12.0..12.0f64, dy in -12.0..12.0f64,
    ) {
        let world = &worlds()[w];
        let checker = world.checker();
        let (a, b) = (Point::new(ax, ay), Point::new(ax + dx, ay + dy));
        prop_assert_eq!(checker.segment_is_free(a, b), reference_segment_is_free(world, a, b));
        prop_assert_eq!(checker.point_is_free(a), world.reference_is_clear(a, 0.0));
    }

    /// Segments parallel to an obstacle's edge, at the robot's radius plus or minus a hair
    /// outside it, slid along and clipped: free exactly when the reference says so.
    #[test]
    fn segments_grazing_an_edge_match_the_reference(
        w in 0usize..5, pick in 0usize..1000, edge in 0usize..64, along in -0.5..1.5f64,
        length in 0.0..3.0f64, hair in prop::sample::select(vec![-1e-6, 1e-6]),
    ) {
        let world = &worlds()[w];
        let checker = world.checker();
        let o = &world.obstacles()[pick % world.obstacles().len()];
        let v = o.vertices();
        let (p, q) = (v[edge % v.len()], v[(edge + 1) % v.len()]);
        // Counter-clockwise rings: the outward normal is on the right of each edge.
        let dir = (q - p).normalize();
        let out = nalgebra::Vector2::new(dir.y, -dir.x);
        let a = p + (q - p) * along + out * (world.robot_radius() + hair);
        let b = a + dir * length;
        prop_assert_eq!(checker.segment_is_free(a, b), reference_segment_is_free(world, a, b));
    }
}

/// A polygon robot: touching is allowed, overlapping is not, whichever way it overlaps (an edge
/// crossing, an obstacle wholly inside it, it wholly inside an obstacle, or lying exactly on an
/// obstacle with no edge crossing), and it must stay in the bounds.
#[test]
fn a_polygon_robot_is_free_only_apart_from_every_obstacle() {
    use trailmark_core::world::Bounds;
    let square = |x: f64, y: f64, s: f64| {
        vec![Point::new(x, y), Point::new(x + s, y), Point::new(x + s, y + s), Point::new(x, y + s)]
    };
    let bounds = Bounds::new(0.0, 0.0, 20.0, 20.0).unwrap();
    let world = PolygonWorld::new(bounds, vec![square(5.0, 5.0, 2.0)], 0.0).unwrap();
    let checker = world.checker();
    assert!(checker.polygon_is_free(&square(1.0, 1.0, 2.0)));
    assert!(checker.polygon_is_free(&square(3.0, 5.0, 2.0)), "touching along a side");
    assert!(!checker.polygon_is_free(&square(4.0, 4.0, 2.0)), "edges crossing");
    assert!(!checker.polygon_is_free(&square(4.0, 4.0, 4.0)), "the obstacle wholly inside");
    assert!(!checker.polygon_is_free(&square(5.5, 5.5, 1.0)), "wholly inside the obstacle");
    assert!(!checker.polygon_is_free(&square(5.0, 5.0, 2.0)), "exactly on the obstacle");
    assert!(!checker.polygon_is_free(&square(19.0, 1.0, 2.0)), "past the bounds");
    // Grown by the world's radius.
    let grown = PolygonWorld::new(bounds, vec![square(5.0, 5.0, 2.0)], 0.5).unwrap().checker();
    assert!(!grown.polygon_is_free(&square(2.7, 5.0, 2.0)));
    assert!(grown.polygon_is_free(&square(2.4, 5.0, 2.0)));
}
