//! Lee's rotational sweep: around a centre, the boundary vertices sorted by angle and a ray
//! that sweeps them once while an ordered status keeps the boundary edges it crosses.

use std::cmp::Ordering;

use trailmark_core::freespace::FreeSpace;
use trailmark_core::geometry::Point;
use trailmark_core::predicates::{orient, wedge_holds};

use super::scope::Scope;

/// The boundary edges at each position of a free space, in compressed rows.
#[derive(Clone, Debug)]
pub(super) struct Incidence {
    /// `edges[start[p]..start[p + 1]]` are the edges at position `p`.
    start: Vec<u32>,
    edges: Vec<u32>,
}

impl Incidence {
    /// The edges at every position of `space`.
    pub(super) fn of(space: &FreeSpace) -> Self {
        let positions = space.positions().len();
        let mut start = vec![0u32; positions + 1];
        for &[a, b] in space.edges() {
            start[a as usize + 1] += 1;
            start[b as usize + 1] += 1;
        }
        for p in 0..positions {
            start[p + 1] += start[p];
        }
        let mut fill = start.clone();
        let mut edges = vec![0u32; space.edges().len() * 2];
        for (e, &[a, b]) in space.edges().iter().enumerate() {
            for v in [a, b] {
                edges[fill[v as usize] as usize] = e as u32;
                fill[v as usize] += 1;
            }
        }
        Incidence { start, edges }
    }

    /// The boundary edges at position `p`.
    pub(super) fn at(&self, p: usize) -> &[u32] {
        &self.edges[self.start[p] as usize..self.start[p + 1] as usize]
    }
}

/// What a sweep found visible.
pub(super) enum Sighting {
    /// A boundary vertex position.
    Position(usize),
    /// The extra point of the sweep.
    Extra,
}

/// An edge crossed by the sweep ray, ordered by its distance from the centre along the ray.
#[derive(Clone, Copy, Debug)]
struct Active {
    a: Point,
    b: Point,
    /// `orient(a, b, centre)`: which side of the edge's line the centre is on (never 0: edges
    /// in line with the centre never enter the status). Fixed for the whole sweep.
    side: f64,
    id: u32,
}

impl Active {
    pub(super) fn new(centre: Point, a: Point, b: Point, id: u32) -> Self {
        Active { a, b, side: orient(a, b, centre), id }
    }

    /// Nearer edges first. Two edges in the status never cross and both cross the current
    /// ray, so which is nearer does not depend on the ray: it is decided by which side of one
    /// edge's line the other edge and the centre lie. Ties (collinear edges) by id.
    pub(super) fn order(&self, other: &Self) -> Ordering {
        if self.id == other.id {
            return Ordering::Equal;
        }
        nearer(self, other).then(self.id.cmp(&other.id))
    }
}

/// `Less` when edge `e` is nearer to the centre than edge `f` along a ray from the centre that
/// crosses both (edges that do not cross each other).
fn nearer(e: &Active, f: &Active) -> Ordering {
    let same = |x: f64, y: f64| (x > 0.0) == (y > 0.0);
    let verdict = |e_is_nearer: bool| if e_is_nearer { Ordering::Less } else { Ordering::Greater };
    let (a, b) = (e.a, e.b);
    let (p, q) = (f.a, f.b);
    // A shared endpoint s: compare the other ends, from the line s -> (f's other end), whose
    // side of the centre is f's own, or its opposite when the line runs q -> p.
    let shared = if a == p {
        Some((a, b, q, f.side))
    } else if a == q {
        Some((a, b, p, -f.side))
    } else if b == p {
        Some((b, a, q, f.side))
    } else if b == q {
        Some((b, a, p, -f.side))
    } else {
        None
    };
    if let Some((s, e_other, f_other, centre_side)) = shared {
        let side = orient(s, f_other, e_other);
        if side == 0.0 {
            return Ordering::Equal;
        }
        return verdict(same(side, centre_side));
    }
    let (sa, sb) = (orient(p, q, a), orient(p, q, b));
    if sa * sb >= 0.0 {
        // e lies on one side of f's line: nearer when the centre is on that side.
        let side = if sa != 0.0 { sa } else { sb };
        if side == 0.0 {
            return Ordering::Equal;
        }
        verdict(same(side, f.side))
    } else {
        // e straddles f's line, so f lies on one side of e's line.
        let (sp, sq) = (orient(a, b, p), orient(a, b, q));
        let side = if sp != 0.0 { sp } else { sq };
        if side == 0.0 {
            return Ordering::Equal;
        }
        verdict(!same(side, e.side))
    }
}

/// The edges crossed by the sweep ray, nearest first: a sorted vector (it holds few edges, so
/// shifting beats a tree's allocations and pointer chasing).
#[derive(Default)]
struct Status {
    edges: Vec<Active>,
}

impl Status {
    pub(super) fn clear(&mut self) {
        self.edges.clear();
    }

    pub(super) fn insert(&mut self, edge: Active) {
        let at = self.edges.partition_point(|x| x.order(&edge) == Ordering::Less);
        self.edges.insert(at, edge);
    }

    /// Removes the edge `id`; returns where it was.
    pub(super) fn remove(&mut self, id: u32) -> Option<usize> {
        let at = self.edges.iter().position(|x| x.id == id)?;
        self.edges.remove(at);
        Some(at)
    }

    /// Inserts `edge` at `at`, where the edge it continues (ending at the vertex `edge` starts
    /// from) was: every other edge crossing the ray is nearer or farther than that vertex, so
    /// the order is unchanged. Where the neighbours say otherwise (boundary rings that cross
    /// after rounding), the edge is inserted by search instead.
    pub(super) fn replace_at(&mut self, at: usize, edge: Active) {
        let after_previous =
            at == 0 || self.edges.get(at - 1).is_some_and(|x| x.order(&edge) == Ordering::Less);
        let before_next = self.edges.get(at).is_none_or(|x| x.order(&edge) == Ordering::Greater);
        if after_previous && before_next {
            self.edges.insert(at, edge);
        } else {
            self.insert(edge);
        }
    }

    pub(super) fn first(&self) -> Option<&Active> {
        self.edges.first()
    }
}

/// The scratch space of Lee's rotational sweep, reused between sweeps.
#[derive(Default)]
pub(super) struct Sweep {
    ignored: Vec<u32>,
    keyed: Vec<((f64, f64), u32)>,
    events: Vec<u32>,
    status: Status,
}

/// A ray from a sweep's centre: toward `through`, or exactly away from it when `reversed`.
/// (Reversing by flipping signs keeps the tests exact, where a reflected point would round.)
#[derive(Clone, Copy, Debug)]
pub(super) struct Ray {
    through: Point,
    reversed: bool,
}

impl Ray {
    pub(super) fn toward(through: Point) -> Self {
        Ray { through, reversed: false }
    }

    pub(super) fn away_from(through: Point) -> Self {
        Ray { through, reversed: true }
    }

    pub(super) fn sign(&self) -> f64 {
        if self.reversed { -1.0 } else { 1.0 }
    }

    /// The orientation of `p` relative to the ray (positive on its left). Exact sign.
    pub(super) fn side(&self, centre: Point, p: Point) -> f64 {
        self.sign() * orient(centre, self.through, p)
    }

    /// Whether `p` lies on the ray (not behind the centre).
    pub(super) fn holds(&self, centre: Point, p: Point) -> bool {
        self.side(centre, p) == 0.0 && self.sign() * (p - centre).dot(&(self.through - centre)) > 0.0
    }

    /// An approximate point on the ray, for floating-point sort keys only.
    pub(super) fn approximate_point(&self, centre: Point) -> Point {
        if self.reversed { centre - (self.through - centre) } else { self.through }
    }
}

/// The part of the turn around a sweep's centre to look at: the closed wedge counter-clockwise
/// from ray `from` to ray `to` (the full turn when `to` is `None`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Wedge {
    pub(super) from: Ray,
    pub(super) to: Option<Ray>,
}

impl Wedge {
    pub(super) fn full(centre: Point) -> Self {
        Wedge { from: Ray::toward(Point::new(centre.x + 1.0, centre.y)), to: None }
    }

    /// The test of whether the direction toward a point lies in the wedge around `centre`,
    /// with what does not depend on the point computed once. Exact.
    pub(super) fn around(&self, centre: Point) -> impl Fn(Point) -> bool {
        let from = self.from;
        // The orientation of `to` relative to `from`, with the rays' signs, and whether the two
        // rays point the same way (for a turn of zero).
        let shape = self.to.map(|to| {
            let turn = -from.sign() * to.side(centre, from.through);
            let aligned = from.sign() * to.sign() * (from.through - centre).dot(&(to.through - centre)) > 0.0;
            (to, turn, aligned)
        });
        move |p| match shape {
            None => true,
            Some((to, turn, aligned)) => {
                wedge_holds(turn, || aligned, from.side(centre, p), to.side(centre, p))
            }
        }
    }
}

impl Sweep {
    /// Sweeps a ray around `centre` through `wedge`, calling `found` for every boundary vertex
    /// position (and the `extra` point, if any) in the wedge that the open segment from `centre`
    /// reaches through free space, leaving `centre` in a direction that `depart` accepts.
    /// Whether the segment may *end* there is the caller's test. `skip` is the position at
    /// `centre`, if it is a vertex. With a `scope`, only its edges and their ends are looked at:
    /// what is found is what the full sweep finds wherever the scope holds every edge that could
    /// block (the caller refuses what lies elsewhere).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn run(
        &mut self,
        space: &FreeSpace,
        incidence: &Incidence,
        (centre, skip): (Point, Option<usize>),
        wedge: Wedge,
        depart: &dyn Fn(Point) -> bool,
        extra: Option<Point>,
        scope: Option<&Scope>,
        mut found: impl FnMut(Sighting),
    ) {
        let positions = space.positions();
        let extra_id = positions.len() as u32;
        let point = |id: u32| if id == extra_id { extra.unwrap_or(centre) } else { positions[id as usize] };
        // Edges at the centre (a vertex, or a start on an edge) never block anything.
        self.ignored.clear();
        if let Some(p) = skip {
            self.ignored.extend_from_slice(incidence.at(p));
        } else {
            self.ignored.extend(space.edges_through(centre).map(|e| e as u32));
        }
        let ignored_edges = &self.ignored;
        let ignored = |e: usize| ignored_edges.contains(&(e as u32));

        // The events in the wedge, sorted by a floating-point pseudo-angle from the wedge's first
        // direction and by distance; an insertion pass with the exact order then repairs the few
        // near-ties that rounding got wrong.
        let origin = sweep_key(centre, wedge.from.approximate_point(centre)).0;
        self.keyed.clear();
        let all = 0..if scope.is_some() { 0 } else { positions.len() as u32 };
        let candidates = all
            .chain(scope.map_or(&[][..], |s| s.positions()).iter().copied())
            .filter(|&i| Some(i as usize) != skip)
            .chain(extra.filter(|&x| x != centre).map(|_| extra_id));
        let in_wedge = wedge.around(centre);
        for id in candidates {
            let p = point(id);
            if in_wedge(p) {
                let (angle, distance) = sweep_key(centre, p);
                let relative = if angle < origin { angle + 4.0 - origin } else { angle - origin };
                self.keyed.push(((relative, distance), id));
            }
        }
        self.keyed.sort_unstable_by(|a, b| a.0.0.total_cmp(&b.0.0).then(a.0.1.total_cmp(&b.0.1)));
        self.events.clear();
        self.events.extend(self.keyed.iter().map(|&(_, id)| id));
        let exact = |i: u32, j: u32| {
            let (p, q) = (point(i), point(j));
            angular_order_from(centre, wedge.from, p, q).then_with(|| {
                let d = |r: Point| ((r.x - centre.x).abs(), (r.y - centre.y).abs());
                d(p).partial_cmp(&d(q)).unwrap_or(Ordering::Equal)
            })
        };
        for k in 1..self.events.len() {
            let mut j = k;
            while j > 0 && exact(self.events[j - 1], self.events[j]) == Ordering::Greater {
                self.events.swap(j - 1, j);
                j -= 1;
            }
        }

        // The edges crossing the first ray of the wedge, just before it.
        self.status.clear();
        let first = wedge.from;
        let on_ray = |p: Point| first.holds(centre, p);
        let all = 0..if scope.is_some() { 0 } else { space.edges().len() as u32 };
        for e in all.chain(scope.map_or(&[][..], |s| s.edges()).iter().copied()) {
            let e = e as usize;
            if ignored(e) {
                continue;
            }
            let (a, b) = space.edge_points(e);
            let (sa, sb) = (first.side(centre, a), first.side(centre, b));
            let active = (sa < 0.0 && sb > 0.0 && orient(a, b, centre) > 0.0)
                || (sb < 0.0 && sa > 0.0 && orient(b, a, centre) > 0.0)
                || (sb < 0.0 && on_ray(a))
                || (sa < 0.0 && on_ray(b));
            if active {
                self.status.insert(Active::new(centre, a, b, e as u32));
            }
        }

        let mut start = 0;
        while start < self.events.len() {
            // The group of events on one ray, nearest first.
            let direction = point(self.events[start]);
            let mut end = start + 1;
            while end < self.events.len() && exact_same_ray(centre, direction, point(self.events[end])) {
                end += 1;
            }
            let group = start..end;
            start = end;

            // Edges ending on this ray leave the tree.
            let vacancy = update_status(
                &mut self.status,
                (space, incidence, scope),
                centre,
                &self.events[group.clone()],
                &self.ignored,
                None,
            );

            // Visibility along the ray: blocked by the nearest crossing edge, or at a vertex the
            // ray cannot pass through.
            let mut open = depart(direction);
            let mut previous: Option<u32> = None;
            for &id in &self.events[group.clone()] {
                if !open {
                    break;
                }
                let w = point(id);
                if let Some(p) = previous.filter(|&p| p != extra_id) {
                    open = space.passes_through(p as usize, centre, w);
                }
                if open && let Some(nearest) = self.status.first() {
                    let side = orient(nearest.a, nearest.b, centre);
                    open = side * orient(nearest.a, nearest.b, w) >= 0.0;
                }
                if open {
                    found(if id == extra_id { Sighting::Extra } else { Sighting::Position(id as usize) });
                }
                previous = Some(id);
            }

            // Edges starting on this ray enter the tree.
            update_status(
                &mut self.status,
                (space, incidence, scope),
                centre,
                &self.events[group],
                &self.ignored,
                Some(vacancy),
            );
        }
    }
}

/// Removes from the status the edges that end at the vertices `group` (on the current ray)
/// and lie clockwise of it (`entering` is `None`), or inserts those that start there and lie
/// counter-clockwise (`entering` holds what the removal returned). Edges in `ignored` or out of
/// the scope, and the extra point, are passed over.
///
/// The removal returns where its edge was when the group is one vertex with exactly one edge
/// ending there: the usual case of a ray passing a vertex of a boundary chain, whose one
/// entering edge then takes that place without a search.
fn update_status(
    status: &mut Status,
    (space, incidence, scope): (&FreeSpace, &Incidence, Option<&Scope>),
    centre: Point,
    group: &[u32],
    ignored: &[u32],
    entering: Option<Option<usize>>,
) -> Option<usize> {
    let positions = space.positions();
    let single = group.len() == 1;
    let (mut count, mut vacancy, mut entered) = (0, None, None);
    for &id in group.iter().filter(|&&id| (id as usize) < positions.len()) {
        let w = positions[id as usize];
        let looked_at = |e: &&u32| !ignored.contains(e) && scope.is_none_or(|s| s.holds(**e));
        for &e in incidence.at(id as usize).iter().filter(looked_at) {
            let (a, b) = space.edge_points(e as usize);
            let other = if a == w { b } else { a };
            let side = orient(centre, w, other);
            match entering {
                Some(place) if side > 0.0 => {
                    let edge = Active::new(centre, a, b, e);
                    count += 1;
                    match (place, count) {
                        // Hold the first edge back until it is known to be the only one.
                        (Some(_), 1) if single => entered = Some(edge),
                        _ => {
                            status.insert(edge);
                            if let Some(held) = entered.take() {
                                status.insert(held);
                            }
                        }
                    }
                }
                None if side < 0.0 => {
                    count += 1;
                    vacancy = status.remove(e);
                }
                _ => {}
            }
        }
    }
    if let (Some(edge), Some(Some(at))) = (entered, entering) {
        status.replace_at(at, edge);
    }
    if single && count == 1 { vacancy } else { None }
}

/// Whether `q` lies on the ray from `centre` through `p`. Exact.
fn exact_same_ray(centre: Point, p: Point, q: Point) -> bool {
    orient(centre, p, q) == 0.0 && (p - centre).dot(&(q - centre)) > 0.0
}

/// The order of the directions from `at` toward `p` and `q`, counter-clockwise starting from
/// ray `from`. Exact.
fn angular_order_from(at: Point, from: Ray, p: Point, q: Point) -> Ordering {
    let half = |r: Point| {
        let side = from.side(at, r);
        if side > 0.0 || (side == 0.0 && from.holds(at, r)) { 0 } else { 1 }
    };
    half(p).cmp(&half(q)).then_with(|| 0.0.partial_cmp(&orient(at, p, q)).unwrap_or(Ordering::Equal))
}

/// An approximate sort key for `p` around `centre`: a pseudo-angle in `[0, 4)` that increases
/// with the angle counter-clockwise from +x (the "diamond angle", no trigonometry), then the
/// distance in the L1 norm. Rounding may misorder near-ties; the sweep repairs them exactly.
fn sweep_key(centre: Point, p: Point) -> (f64, f64) {
    let (dx, dy) = (p.x - centre.x, p.y - centre.y);
    let l1 = dx.abs() + dy.abs();
    if l1 == 0.0 {
        return (0.0, 0.0);
    }
    let t = dy / l1;
    let angle = if dy > 0.0 || (dy == 0.0 && dx > 0.0) {
        if dx >= 0.0 { t } else { 2.0 - t }
    } else if dx < 0.0 {
        2.0 - t
    } else {
        4.0 + t
    };
    (angle, l1)
}
