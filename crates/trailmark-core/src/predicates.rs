//! Exact geometric predicates: orientation, wedges, segments and winding numbers.
//!
//! Orientation signs come from Shewchuk's adaptive predicates (the `robust` crate), so collinear
//! and touching configurations, which grid maps are full of, are decided without tolerance.

use crate::geometry::Point;

/// The exact orientation of `c` relative to the directed line `a -> b`: positive when `c` is on
/// the left, negative on the right, zero when the three points are collinear. The magnitude is
/// twice the signed triangle area, approximately; the **sign** is exact.
#[inline]
pub fn orient(a: Point, b: Point, c: Point) -> f64 {
    // The floating-point determinant and its error bound (the one `robust` uses, after Ozaki et
    // al.), inline; the adaptive exact computation only when the bound cannot certify the sign.
    const THETA: f64 = 3.330_669_062_177_372_2e-16;
    let left = (a.x - c.x) * (b.y - c.y);
    let right = (a.y - c.y) * (b.x - c.x);
    let det = left - right;
    if det.abs() >= THETA * (left + right).abs() && det != 0.0 {
        return det;
    }
    orient_exact(a, b, c)
}

#[cold]
#[inline(never)]
fn orient_exact(a: Point, b: Point, c: Point) -> f64 {
    robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    )
}

/// Whether the direction from `apex` toward `q` lies in the closed wedge swept
/// counter-clockwise from the direction toward `from` to the direction toward `to`.
///
/// A wedge whose two directions coincide is taken as the full turn. Exact.
#[inline]
pub fn in_wedge(apex: Point, from: Point, to: Point, q: Point) -> bool {
    wedge_holds(
        orient(apex, from, to),
        || same_direction(apex, from, to),
        orient(apex, from, q),
        orient(apex, to, q),
    )
}

/// The decision of [`in_wedge`] from its orientation signs, for callers that compute them in
/// another way (rays pointing away from a point, say): `turn` is the orientation of the wedge's
/// second direction relative to its first, `aligned` whether the two coincide (asked only when
/// `turn` is zero), `from_q` and `to_q` the orientations of the tested direction relative to
/// each.
#[inline]
pub fn wedge_holds(turn: f64, aligned: impl FnOnce() -> bool, from_q: f64, to_q: f64) -> bool {
    if turn > 0.0 {
        // Less than a half turn: q between the two directions.
        from_q >= 0.0 && to_q <= 0.0
    } else if turn < 0.0 {
        // More than a half turn: q not strictly inside the complement.
        !(to_q > 0.0 && from_q < 0.0)
    } else if aligned() {
        true
    } else {
        // Exactly a half turn: the closed half-plane left of `from`.
        from_q >= 0.0
    }
}

/// Whether `a` and `b` lie in the same direction from `apex` (given that the three are collinear).
#[inline]
fn same_direction(apex: Point, a: Point, b: Point) -> bool {
    (a.x - apex.x) * (b.x - apex.x) + (a.y - apex.y) * (b.y - apex.y) > 0.0
}

/// Whether `p` lies on the closed segment `a`-`b`. Exact.
#[inline]
pub(crate) fn on_segment(a: Point, b: Point, p: Point) -> bool {
    orient(a, b, p) == 0.0
        && p.x >= a.x.min(b.x)
        && p.x <= a.x.max(b.x)
        && p.y >= a.y.min(b.y)
        && p.y <= a.y.max(b.y)
}

/// The winding number around `p` of the closed rings whose edges are `edges` (only those that
/// cross the ray from `p` toward +x count, so the caller may pass just those), or `None` when
/// `p` lies on an edge. Exact.
pub(crate) fn winding_number(p: Point, edges: impl IntoIterator<Item = (Point, Point)>) -> Option<i64> {
    let mut winding = 0i64;
    for (a, b) in edges {
        // An edge wholly above or below `p` neither holds it nor crosses its ray.
        if (a.y > p.y && b.y > p.y) || (a.y < p.y && b.y < p.y) {
            continue;
        }
        let side = orient(a, b, p);
        if side == 0.0 && on_segment(a, b, p) {
            return None;
        }
        if a.y <= p.y {
            if b.y > p.y && side > 0.0 {
                winding += 1;
            }
        } else if b.y <= p.y && side < 0.0 {
            winding -= 1;
        }
    }
    Some(winding)
}

/// `ring` without vertices equal to the one before them, nor a closing repeat of the first.
pub(crate) fn dedup_ring(ring: impl IntoIterator<Item = Point>) -> Vec<Point> {
    let mut kept: Vec<Point> = Vec::new();
    for p in ring {
        if kept.last() != Some(&p) {
            kept.push(p);
        }
    }
    while kept.len() > 1 && kept.first() == kept.last() {
        kept.pop();
    }
    kept
}

/// Whether collinear point `p` lies strictly between `a` and `b`.
#[inline]
pub(crate) fn strictly_between(a: Point, b: Point, p: Point) -> bool {
    if a.x != b.x {
        (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x)
    } else {
        (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y)
    }
}

/// The order of the directions from `at` toward `p` and `q`, counter-clockwise from +x. Exact.
pub fn angular_order(at: Point, p: Point, q: Point) -> std::cmp::Ordering {
    let half = |r: Point| if r.y > at.y || (r.y == at.y && r.x > at.x) { 0 } else { 1 };
    half(p)
        .cmp(&half(q))
        .then_with(|| 0.0.partial_cmp(&orient(at, p, q)).unwrap_or(std::cmp::Ordering::Equal))
}
