//! Valid-shaped problem documents with hostile values, for the `solve_document` target.
//!
//! [`ProblemDoc`] implements [`Arbitrary`]: from the fuzzer's bytes it builds the JSON of a
//! problem in the schema of trailmark-core's `problem.rs` — a small grid (inline rows, optional
//! costs) or a polygon world of a few polygons, any planner of the registry (`trailmark::solve::PlannerName::ALL`), any roadmap, space
//! and sampler — whose numbers are mostly ordinary and otherwise extreme: 0, -0, 1e308, 1e-300,
//! the smallest subnormal, `u32::MAX`, `u64::MAX`, values just beyond a documented limit. The
//! parameters that bound the work (samples, iterations, time limits, sampler attempts) stay
//! small; the bytes decide everything else. Most documents are valid, so the planners run;
//! a tenth or so put a field where it does not belong, to reach the errors.
//!
//! Hybrid A* documents (issue 47) plan on grids (cells 0.05 to 10 m wide and coarser, sometimes
//! a row or column a million or a trillion times dearer than the rest, or that row alone open)
//! and polygon worlds, with footprints about the reference point, ahead of it (not holding it),
//! sharp thin triangles, rings past the 1024 vertices documented, hostile coordinates, and
//! small expansion or time limits. Box worlds sometimes hold touching boxes: a box cut in two,
//! two boxes meeting at a corner, a wall of boxes with the ends on its two sides.

use std::f64::consts::PI;
use std::fmt;

use arbitrary::{Arbitrary, Result, Unstructured};
use serde_json::{Map, Value, json};
use trailmark::solve::{Family, PlannerName};

/// A problem document, as JSON. Its `Debug` form is the JSON text, so that a crash report
/// (`cargo fuzz fmt`) shows the document.
pub struct ProblemDoc(pub Value);

impl fmt::Debug for ProblemDoc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&serde_json::to_string(&self.0).unwrap_or_default())
    }
}

impl<'a> Arbitrary<'a> for ProblemDoc {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        problem(u).map(ProblemDoc)
    }
}

/// The roadmaps of polygon worlds (`None`: the default, visibility).
#[derive(Arbitrary, Debug, Clone, Copy, PartialEq, Eq)]
pub enum GraphName {
    Default,
    Visibility,
    Trapezoid,
    Prm,
    DubinsPrm,
    ReedsSheppPrm,
}

/// Values at and beyond the edges of what the parameters take.
const EXTREMES: &[f64] = &[
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    1e308,
    -1e308,
    f64::MAX,
    f64::MIN,
    1e-300,
    -1e-300,
    5e-324,
    f64::MIN_POSITIVE,
    f64::EPSILON,
    1.0 + f64::EPSILON,
    1.0 - f64::EPSILON / 2.0,
    1e-9,
    1e-15,
    1e6,
    1e6 + 1.0,
    1e9,
    1e12,
    1e12 * (1.0 + f64::EPSILON),
    1e15,
    1e18,
    1.8e19,
    1e20,
    4294967295.0,
    4294967296.0,
    18446744073709551615.0,
    PI,
    2.0 * PI,
    -PI,
    1e-7,
];

/// A hostile float: an extreme, a small fraction, an extreme times a small number, or any
/// finite bit pattern.
pub fn hostile_f64(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => *u.choose(EXTREMES)?,
        1 => f64::from(u.arbitrary::<i16>()?) / 16.0,
        2 => {
            let extreme = *u.choose(EXTREMES)?;
            let v = extreme * f64::from(u.int_in_range(-8i8..=8)?);
            if v.is_finite() { v } else { extreme }
        }
        _ => {
            let v = f64::from_bits(u.arbitrary()?);
            if v.is_finite() { v } else { 0.0 }
        }
    })
}

/// Usually a float in `[lo, hi]` on a grid of `1/8`, sometimes ([`hostile_f64`]) anything.
fn float(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    if u.ratio(1u8, 4)? {
        return hostile_f64(u);
    }
    let steps = ((hi - lo) * 8.0).max(0.0) as u32;
    Ok(lo + f64::from(u.int_in_range(0..=steps)?) / 8.0)
}

/// A hostile unsigned integer (as JSON it must be an integer, not a float).
fn hostile_u64(u: &mut Unstructured) -> Result<u64> {
    Ok(match u.int_in_range(0u8..=2)? {
        0 => *u.choose(&[
            0,
            1,
            2,
            u64::from(u32::MAX),
            u64::from(u32::MAX) + 1,
            u64::MAX,
            u64::MAX - 1,
            1 << 53,
        ])?,
        1 => u.int_in_range(0..=64)?,
        _ => u.arbitrary()?,
    })
}

/// `Some(value)` from `f` with probability `p` in 256.
fn maybe<T>(
    u: &mut Unstructured,
    p: u8,
    f: impl FnOnce(&mut Unstructured) -> Result<T>,
) -> Result<Option<T>> {
    if u.arbitrary::<u8>()? < p { f(u).map(Some) } else { Ok(None) }
}

fn num(v: f64) -> Value {
    serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
}

fn insert(map: &mut Map<String, Value>, key: &str, value: Option<Value>) {
    if let Some(value) = value {
        map.insert(key.into(), value);
    }
}

/// A whole problem document.
pub fn problem(u: &mut Unstructured) -> Result<Value> {
    let grid = u.ratio(1u8, 2)?;
    let misplaced = u.ratio(1u8, 10)?;
    // Every planner of the registry, drawn from its own list.
    let mut planner: PlannerName = *u.choose(PlannerName::ALL)?;
    // Sampling planners take polygon worlds; a few mismatched pairs reach the error.
    if grid && planner.family() == Family::Sampling && !misplaced {
        planner = PlannerName::AStar;
    }
    // Hybrid A* more often than one planner in eighteen: its documents have the most shapes.
    if u.ratio(1u8, 16)? {
        planner = PlannerName::HybridAStar;
    }
    let mut doc = Map::new();
    if planner == PlannerName::HybridAStar {
        hybrid_problem(u, &mut doc, grid)?;
    } else if !grid && planner.family() == Family::Sampling && u.ratio(1u8, 4)? {
        box_world(u, &mut doc)?;
    } else if grid {
        let (world, width, height) = grid_world(u)?;
        doc.insert("world".into(), world);
        doc.insert("start".into(), grid_end(u, width, height)?);
        doc.insert("goal".into(), grid_end(u, width, height)?);
    } else {
        let (world, frame) = polygon_world(u)?;
        let graph: GraphName = u.arbitrary()?;
        let space_dubins = planner.family() == Family::Sampling && u.ratio(1u8, 3)?;
        let car_roadmap = matches!(graph, GraphName::DubinsPrm | GraphName::ReedsSheppPrm);
        let dubins = space_dubins || (planner.family() != Family::Sampling && car_roadmap);
        doc.insert("world".into(), world);
        doc.insert("start".into(), polygon_end(u, &frame, dubins)?);
        doc.insert("goal".into(), polygon_end(u, &frame, dubins)?);
        if dubins || misplaced && u.ratio(1u8, 2)? {
            doc.insert("turning_radius".into(), num(float(u, 0.0, 3.0)? * frame.scale));
        }
        if planner.family() == Family::Sampling {
            if space_dubins || misplaced && u.ratio(1u8, 2)? {
                let car = if u.ratio(1u8, 2)? { "dubins" } else { "reeds_shepp" };
                doc.insert("space".into(), json!(if space_dubins { car } else { "r2" }));
            } else if u.ratio(1u8, 4)? {
                doc.insert("space".into(), json!("r2"));
            }
        } else {
            roadmap_fields(u, &mut doc, graph, &frame)?;
        }
    }
    if misplaced {
        // A field of the other kind of world or planner.
        match u.int_in_range(0u8..=4)? {
            0 => doc.insert("samples".into(), json!(u.int_in_range(0u32..=50)?)),
            1 => doc.insert("graph".into(), json!("prm")),
            2 => doc.insert("space".into(), json!("dubins")),
            3 => doc.insert("k".into(), json!(hostile_u64(u)?)),
            _ => doc.insert("sampler".into(), json!("halton")),
        };
    }
    if u.ratio(1u8, 2)? {
        doc.insert("seed".into(), json!(hostile_u64(u)?));
    }
    if planner != PlannerName::HybridAStar {
        doc.insert("planner".into(), planner_spec(u, planner, grid)?);
    }
    Ok(Value::Object(doc))
}

/// A box world of 1 to 9 axes (9 is refused) with up to six boxes, its ends and its space.
/// Some worlds hold boxes that touch (closed boxes block as their union): a box cut in two
/// along an axis, two boxes meeting at a corner (the ends sometimes placed across that corner,
/// so that the straight motion between them runs through it), or a wall of boxes across the
/// region with the start and the goal on its two sides (`boxes::check_result` finds it).
fn box_world(u: &mut Unstructured, doc: &mut Map<String, Value>) -> Result<()> {
    let axes = if u.ratio(1u8, 2)? { u.int_in_range(1usize..=3)? } else { u.int_in_range(1usize..=9)? };
    // A hostile world: any value may be extreme (float is a quarter hostile), so that most such
    // worlds are refused; the others are valid, so that the planners run.
    let hostile = u.ratio(1u8, 8)?;
    let value = |u: &mut Unstructured, lo: f64, hi: f64| -> Result<f64> {
        if !hostile {
            Ok(lo + (hi - lo) * f64::from(u.int_in_range(0u8..=8)?) / 8.0)
        } else if u.ratio(1u8, 32)? {
            hostile_f64(u)
        } else {
            float(u, lo, hi)
        }
    };
    let bounds: Vec<[f64; 2]> =
        (0..axes).map(|_| Ok([value(u, -1.0, 0.0)?, value(u, 1.0, 2.0)?])).collect::<Result<_>>()?;
    let mut obstacles: Vec<[Vec<f64>; 2]> = Vec::new();
    for _ in 0..u.int_in_range(0u8..=6)? {
        let lo: Vec<f64> = (0..axes).map(|_| value(u, -0.5, 1.0)).collect::<Result<_>>()?;
        let hi: Vec<f64> = if hostile {
            (0..axes).map(|_| value(u, 0.0, 1.5)).collect::<Result<_>>()?
        } else {
            lo.iter().map(|l| Ok(l + value(u, 0.125, 0.75)?)).collect::<Result<_>>()?
        };
        obstacles.push([lo, hi]);
    }
    // Eighths of a side: cuts and corners on exact binary fractions.
    let eighth = |u: &mut Unstructured, lo: u8, hi: u8| -> Result<f64> {
        Ok(f64::from(u.int_in_range(lo..=hi)?) / 8.0)
    };
    let mut ends: Option<[Vec<f64>; 2]> = None;
    match u.int_in_range(0u8..=7)? {
        0 => {
            // One box cut in two along an axis: the halves share a face.
            let lo: Vec<f64> = (0..axes).map(|_| eighth(u, 0, 6).map(|x| x - 0.25)).collect::<Result<_>>()?;
            let hi: Vec<f64> = lo.iter().map(|l| Ok(l + eighth(u, 1, 8)?)).collect::<Result<_>>()?;
            let axis = u.int_in_range(0..=axes - 1)?;
            let cut = lo[axis] + (hi[axis] - lo[axis]) * eighth(u, 1, 7)?;
            let (mut first_hi, mut second_lo) = (hi.clone(), lo.clone());
            first_hi[axis] = cut;
            second_lo[axis] = cut;
            obstacles.push([lo, first_hi]);
            obstacles.push([second_lo, hi]);
        }
        1 => {
            // Two boxes meeting at the corner m; the ends sometimes mirrored across it, off the
            // boxes' diagonal, so that the segment between them passes through m exactly.
            let m: Vec<f64> = (0..axes).map(|_| eighth(u, 0, 8)).collect::<Result<_>>()?;
            let below: Vec<f64> = m.iter().map(|x| Ok(x - eighth(u, 1, 6)?)).collect::<Result<_>>()?;
            let above: Vec<f64> = m.iter().map(|x| Ok(x + eighth(u, 1, 6)?)).collect::<Result<_>>()?;
            obstacles.push([below, m.clone()]);
            obstacles.push([m.clone(), above]);
            if axes >= 2 && u.ratio(1u8, 2)? {
                let d = eighth(u, 1, 4)?;
                // Signs not all alike: a direction out of both boxes' quadrants.
                let mut sign: Vec<f64> =
                    (0..axes).map(|_| Ok(if u.arbitrary()? { 1.0 } else { -1.0 })).collect::<Result<_>>()?;
                if sign.iter().all(|&s| s == sign[0]) {
                    sign[1] = -sign[0];
                }
                let at = |s: f64| m.iter().zip(&sign).map(|(x, g)| x + s * g * d).collect::<Vec<f64>>();
                ends = Some([at(1.0), at(-1.0)]);
            }
        }
        2 | 3 => {
            // A wall across the region at c0..c1 along `axis`, in pieces cut along another
            // axis (sharing faces), sometimes with a gap; the ends on its two sides.
            let axis = u.int_in_range(0..=axes - 1)?;
            let [b0, b1] = bounds[axis];
            let c0 = b0 + (b1 - b0) * eighth(u, 2, 4)?;
            let c1 = c0 + (b1 - b0) * eighth(u, 1, 2)? / 2.0;
            let over = if u.ratio(1u8, 2)? { 0.0 } else { 0.25 };
            let mut lo: Vec<f64> = bounds.iter().map(|[l, _]| l - over).collect();
            let mut hi: Vec<f64> = bounds.iter().map(|[_, h]| h + over).collect();
            (lo[axis], hi[axis]) = (c0, c1);
            let mut pieces = vec![[lo, hi]];
            if axes >= 2 {
                let other = (axis + u.int_in_range(1..=axes - 1)?) % axes;
                let [o0, o1] = bounds[other];
                for _ in 0..u.int_in_range(0u8..=2)? {
                    let cut = o0 + (o1 - o0) * eighth(u, 1, 7)?;
                    let k = pieces.iter().position(|[l, h]| l[other] < cut && cut < h[other]);
                    if let Some(k) = k {
                        let [l, h] = pieces.remove(k);
                        let (mut h1, mut l2) = (h.clone(), l.clone());
                        h1[other] = cut;
                        l2[other] = cut;
                        pieces.extend([[l, h1], [l2, h]]);
                    }
                }
                if u.ratio(1u8, 4)? {
                    // A gap: one piece shrunk off the others.
                    let k = u.int_in_range(0..=pieces.len() - 1)?;
                    let side = (pieces[k][1][other] - pieces[k][0][other]) / 8.0;
                    pieces[k][1][other] -= side;
                }
            }
            obstacles.extend(pieces);
            let near = |u: &mut Unstructured| -> Result<f64> { Ok(b0 + (c0 - b0) * eighth(u, 0, 7)?) };
            let far = |u: &mut Unstructured| -> Result<f64> { Ok(c1 + (b1 - c1) * eighth(u, 1, 8)?) };
            let at = |u: &mut Unstructured, x: f64| -> Result<Vec<f64>> {
                (0..axes)
                    .map(|i| {
                        if i == axis {
                            Ok(x)
                        } else {
                            Ok(bounds[i][0] + (bounds[i][1] - bounds[i][0]) * eighth(u, 0, 8)?)
                        }
                    })
                    .collect()
            };
            let (a, b) = (near(u)?, far(u)?);
            let (s, g) = (at(u, a)?, at(u, b)?);
            ends = Some(if u.arbitrary()? { [s, g] } else { [g, s] });
        }
        _ => {}
    }
    let obstacles: Vec<Value> = obstacles
        .iter()
        .map(|[lo, hi]| {
            json!([
                lo.iter().copied().map(num).collect::<Vec<_>>(),
                hi.iter().copied().map(num).collect::<Vec<_>>()
            ])
        })
        .collect();
    let bounds: Vec<Value> = bounds.iter().map(|[l, h]| json!([num(*l), num(*h)])).collect();
    doc.insert("world".into(), json!({"boxes": {"bounds": bounds, "obstacles": obstacles}}));
    for (k, end) in ["start", "goal"].into_iter().enumerate() {
        let n = if u.ratio(1u8, 16)? { axes + 1 } else { axes };
        let at: Vec<Value> = match &ends {
            Some(given) if n == axes => given[k].iter().copied().map(num).collect(),
            _ => (0..n).map(|_| value(u, -0.2, 1.2).map(num)).collect::<Result<_>>()?,
        };
        doc.insert(end.into(), Value::Array(at));
    }
    if u.ratio(1u8, 2)? {
        doc.insert("space".into(), json!(if u.ratio(1u8, 8)? { "r2" } else { "rn" }));
    }
    Ok(())
}

/// A small grid world: its JSON, width and height.
fn grid_world(u: &mut Unstructured) -> Result<(Value, usize, usize)> {
    let width = if u.ratio(1u8, 8)? { u.int_in_range(1..=40)? } else { u.int_in_range(1..=8)? };
    let height = if u.ratio(1u8, 8)? { u.int_in_range(1..=40)? } else { u.int_in_range(1..=8)? };
    let blocked_share = u.int_in_range(0u8..=5)?;
    let mut rows = Vec::with_capacity(height);
    for _ in 0..height {
        let mut row = String::with_capacity(width + 1);
        for _ in 0..width {
            let r = u.int_in_range(0u8..=15)?;
            row.push(match r {
                _ if r < blocked_share => *u.choose(&['@', '@', '@', 'O', 'T', 'W'])?,
                15 if u.ratio(1u8, 16)? => *u.choose(&['x', ' ', '\u{e9}', '\0'])?,
                _ => *u.choose(&['.', '.', '.', '.', 'G', 'S'])?,
            });
        }
        if u.ratio(1u8, 32)? {
            row.push('\r');
        }
        rows.push(row);
    }
    if u.ratio(1u8, 32)? {
        // A ragged row.
        let last = rows.len() - 1;
        rows[last].push('.');
    }
    let mut world = Map::new();
    world.insert("rows".into(), json!(rows));
    if u.ratio(1u8, 3)? {
        let (lo, hi): (f64, f64) = if u.ratio(1u8, 4)? { (1e-300, 1e12) } else { (0.125, 10.0) };
        let mut costs = Vec::with_capacity(height);
        for _ in 0..height {
            let row: Result<Vec<Value>> = (0..width)
                .map(|_| {
                    Ok(num(if u.ratio(1u8, 8)? {
                        hostile_f64(u)?
                    } else {
                        // Log-uniform between lo and hi.
                        let t = f64::from(u.int_in_range(0u8..=64)?) / 64.0;
                        (lo.ln() + t * (hi.ln() - lo.ln())).exp().clamp(lo, hi)
                    }))
                })
                .collect();
            costs.push(Value::Array(row?));
        }
        if u.ratio(1u8, 32)? {
            costs.pop();
        }
        world.insert("costs".into(), Value::Array(costs));
    }
    match u.int_in_range(0u8..=2)? {
        0 => {}
        1 => {
            world.insert("connectivity".into(), json!(4));
        }
        _ => {
            world.insert("connectivity".into(), json!(if u.ratio(1u8, 16)? { 6 } else { 8 }));
        }
    }
    if u.ratio(1u8, 2)? {
        world.insert("corner_cutting".into(), json!(u.arbitrary::<bool>()?));
    }
    Ok((json!({ "grid": Value::Object(world) }), width, height))
}

/// A grid start or goal: usually a cell inside the grid, sometimes anything.
fn grid_end(u: &mut Unstructured, width: usize, height: usize) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=15)? {
        0 => json!([num(hostile_f64(u)?), num(hostile_f64(u)?)]),
        1 => json!([u.int_in_range(0..=width)?, u.int_in_range(0..=height)?, 0]),
        2 => json!([u.arbitrary::<u32>()?, u.int_in_range(0..=height - 1)?]),
        _ => json!([u.int_in_range(0..=width - 1)?, u.int_in_range(0..=height - 1)?]),
    })
}

/// Where a polygon world's coordinates live: `offset + scale * c` for `c` in `[0, 10]`.
struct Frame {
    offset: [f64; 2],
    scale: f64,
    aspect: f64,
}

impl Frame {
    fn at(&self, x: f64, y: f64) -> [f64; 2] {
        [self.offset[0] + self.scale * x, self.offset[1] + self.scale * self.aspect * y]
    }
}

/// A polygon world of a few polygons in a frame that is usually `[0, 10]^2` and sometimes
/// tiny, huge, far from the origin or thin.
fn polygon_world(u: &mut Unstructured) -> Result<(Value, Frame)> {
    polygon_world_hostile(u, 3)
}

/// [`polygon_world`] with a hostile frame one time in `share`.
fn polygon_world_hostile(u: &mut Unstructured, share: u8) -> Result<(Value, Frame)> {
    let hostile_frame = u.ratio(1u8, share)?;
    let frame = if hostile_frame {
        // (scale, offset): the world is [offset, offset + 10 scale]. Most pairs are at the edges
        // of the supported range (coordinates up to 1e9, sides from 1e-6 and 1e-7 x the largest
        // coordinate); a few are beyond them.
        let (scale, offset) = *u.choose(&[
            (1e-7, 0.0),
            (1e-6, 0.0),
            (1e-6, -0.0),
            (1e-3, 1.0),
            (1e-2, 1e5),
            (1.0, 1e7),
            (10.0, 9.9e8),
            (10.0, -1e9),
            (1e3, 0.0),
            (1e6, 0.0),
            (1e8, 0.0),
            (1e8, -5e8),
            (1e-300, 0.0),
            (1e-8, 0.0),
            (1e12, 0.0),
            (1e-6, 1e9),
        ])?;
        let aspect = *u.choose(&[1.0, 1.0, 1e-3, 1e-7, 1e3])?;
        Frame { offset: [offset, if u.ratio(1u8, 2)? { offset } else { 0.0 }], scale, aspect }
    } else {
        Frame { offset: [0.0, 0.0], scale: 1.0, aspect: 1.0 }
    };
    let [xmin, ymin] = frame.at(0.0, 0.0);
    let [xmax, ymax] = frame.at(10.0, 10.0);
    let mut bounds = vec![xmin, ymin, xmax, ymax];
    if u.ratio(1u8, 16)? {
        let i = u.int_in_range(0..=3)?;
        bounds[i] = hostile_f64(u)?;
    }
    let count = u.int_in_range(0u8..=4)?;
    let mut obstacles = Vec::new();
    for _ in 0..count {
        let grid = |u: &mut Unstructured| -> Result<f64> { Ok(f64::from(u.int_in_range(0u8..=20)?) / 2.0) };
        let vertices: Vec<[f64; 2]> = match u.int_in_range(0u8..=3)? {
            0 | 1 => {
                // A box.
                let (x0, y0) = (grid(u)?, grid(u)?);
                let (w, h) =
                    (f64::from(u.int_in_range(1u8..=8)?) / 2.0, f64::from(u.int_in_range(1u8..=8)?) / 2.0);
                vec![frame.at(x0, y0), frame.at(x0 + w, y0), frame.at(x0 + w, y0 + h), frame.at(x0, y0 + h)]
            }
            2 => (0..3).map(|_| Ok(frame.at(grid(u)?, grid(u)?))).collect::<Result<_>>()?,
            _ => {
                // A star-shaped polygon around a centre (simple unless points coincide).
                let (cx, cy) = (grid(u)?, grid(u)?);
                let n = u.int_in_range(3u8..=8)?;
                (0..n)
                    .map(|i| {
                        let r = f64::from(u.int_in_range(1u8..=8)?) / 4.0;
                        let a = 2.0 * PI * f64::from(i) / f64::from(n);
                        Ok(frame.at(cx + r * a.cos(), cy + r * a.sin()))
                    })
                    .collect::<Result<_>>()?
            }
        };
        let mut vertices = vertices;
        if u.ratio(1u8, 16)? {
            let i = u.int_in_range(0..=vertices.len() - 1)?;
            vertices[i][u.int_in_range(0..=1)?] = hostile_f64(u)?;
        }
        if u.ratio(1u8, 16)? {
            vertices.reverse();
        }
        obstacles.push(vertices.into_iter().map(|[x, y]| json!([num(x), num(y)])).collect::<Vec<_>>());
    }
    let radius = if u.ratio(1u8, 10)? { hostile_f64(u)? } else { float(u, 0.0, 1.0)? * frame.scale };
    let mut world = Map::new();
    world.insert("bounds".into(), Value::Array(bounds.into_iter().map(num).collect()));
    if !obstacles.is_empty() || u.ratio(1u8, 2)? {
        world.insert("obstacles".into(), json!(obstacles));
    }
    if u.ratio(7u8, 8)? {
        world.insert("robot_radius".into(), num(radius));
    }
    Ok((json!({ "polygons": Value::Object(world) }), frame))
}

/// A polygon-world start or goal: a point (or pose) of the frame, sometimes anything.
fn polygon_end(u: &mut Unstructured, frame: &Frame, pose: bool) -> Result<Value> {
    let [x, y] = if u.ratio(1u8, 16)? {
        [hostile_f64(u)?, hostile_f64(u)?]
    } else {
        frame.at(f64::from(u.int_in_range(0u8..=40)?) / 4.0, f64::from(u.int_in_range(0u8..=40)?) / 4.0)
    };
    let mut v = vec![num(x), num(y)];
    if pose {
        let heading =
            if u.ratio(1u8, 8)? { hostile_f64(u)? } else { f64::from(u.int_in_range(-8i8..=8)?) * PI / 4.0 };
        v.push(num(heading));
    }
    if u.ratio(1u8, 32)? {
        if pose {
            v.pop();
        } else {
            v.push(json!(0));
        }
    }
    Ok(Value::Array(v))
}

/// The roadmap fields of a search over a polygon world.
fn roadmap_fields(
    u: &mut Unstructured,
    doc: &mut Map<String, Value>,
    graph: GraphName,
    frame: &Frame,
) -> Result<()> {
    let name = match graph {
        GraphName::Default => None,
        GraphName::Visibility => Some("visibility"),
        GraphName::Trapezoid => Some("trapezoid"),
        GraphName::Prm => Some("prm"),
        GraphName::DubinsPrm => Some("dubins_prm"),
        GraphName::ReedsSheppPrm => Some("reeds_shepp_prm"),
    };
    insert(doc, "graph", name.map(|n| json!(n)));
    if matches!(graph, GraphName::Prm | GraphName::DubinsPrm | GraphName::ReedsSheppPrm) {
        let most = if graph == GraphName::Prm { 300 } else { 100 };
        doc.insert("samples".into(), json!(u.int_in_range(0..=most)?));
        match u.int_in_range(0u8..=7)? {
            0 | 1 => {}
            2..=4 => {
                doc.insert(
                    "k".into(),
                    json!(if u.ratio(1u8, 3)? { hostile_u64(u)? } else { u.int_in_range(0..=20)? }),
                );
            }
            5 | 6 => {
                let r = if u.ratio(1u8, 3)? { hostile_f64(u)? } else { float(u, 0.0, 5.0)? * frame.scale };
                doc.insert("radius".into(), num(r));
            }
            _ => {
                // Both: an error.
                doc.insert("k".into(), json!(5));
                doc.insert("radius".into(), num(frame.scale));
            }
        }
        if u.ratio(1u8, 2)? {
            doc.insert("sampler".into(), json!(if u.ratio(1u8, 2)? { "halton" } else { "uniform" }));
        }
    }
    Ok(())
}

/// A log-uniform float in `[lo, hi]` (65 steps).
fn log_uniform(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    let t = f64::from(u.int_in_range(0u8..=64)?) / 64.0;
    Ok((lo.ln() + t * (hi.ln() - lo.ln())).exp().clamp(lo, hi))
}

/// A Hybrid A* problem: a grid world (cells of a chosen width, sometimes a row or column of
/// cells a million or a trillion times dearer than the rest, or such a corridor alone) or a
/// polygon world, start and goal poses, and the planner's spec ([`hybrid_spec`]).
fn hybrid_problem(u: &mut Unstructured, doc: &mut Map<String, Value>, grid: bool) -> Result<()> {
    // The spec before the world: a large grid may use up the fuzzer's bytes, and the planner's
    // fields matter more than the last cells.
    let spec = if grid {
        // Cells usually 0.05 to 10 m wide, sometimes coarser, the default 1, or anything.
        let resolution = match u.int_in_range(0u8..=15)? {
            0..=3 => None,
            4..=12 => Some(log_uniform(u, 0.05, 10.0)?),
            13 | 14 => Some(log_uniform(u, 10.0, 1000.0)?),
            _ => Some(if u.ratio(1u8, 2)? { hostile_f64(u)? } else { 1.0 }),
        };
        let cell = resolution.filter(|r| r.is_finite() && *r > 0.0).unwrap_or(1.0);
        // Radii from half a cell (coarse cells) to twenty cells.
        let spec = hybrid_spec(u, cell, (0.5, 20.0), cell, resolution)?;
        let (mut world, width, height) = car_grid(u)?;
        cost_contrast(u, &mut world, width, height)?;
        let open = open_cells(&world);
        doc.insert("world".into(), world);
        doc.insert("start".into(), grid_pose(u, &open, width, height, cell)?);
        doc.insert("goal".into(), grid_pose(u, &open, width, height, cell)?);
        spec
    } else {
        // Hostile frames are the other planners' to fuzz (a third of their worlds): fewer here.
        let (mut world, frame) = polygon_world_hostile(u, 8)?;
        // Cells usually a tenth of the frame's unit to two, sometimes the default (an eighth of
        // the turning radius), coarser, or anything.
        let resolution = match u.int_in_range(0u8..=15)? {
            0..=4 => None,
            5..=13 => Some(frame.scale * log_uniform(u, 0.1, 2.0)?),
            14 => Some(frame.scale * log_uniform(u, 2.0, 10.0)?),
            _ => Some(if u.ratio(1u8, 2)? { hostile_f64(u)? } else { frame.scale }),
        };
        let spec = hybrid_spec(u, frame.scale, (0.5, 4.0), frame.scale, resolution)?;
        // A footprint with a robot radius is an error: mostly the radius goes.
        if spec.get("footprint").is_some()
            && u.ratio(15u8, 16)?
            && let Some(w) = world.get_mut("polygons").and_then(Value::as_object_mut)
        {
            w.remove("robot_radius");
        }
        doc.insert("world".into(), world);
        doc.insert("start".into(), polygon_end(u, &frame, true)?);
        doc.insert("goal".into(), polygon_end(u, &frame, true)?);
        spec
    };
    doc.insert("planner".into(), Value::Object(spec));
    Ok(())
}

/// A grid world for a car: a quarter of the time any generated grid ([`grid_world`], hostile
/// cells and costs included), otherwise a valid one of a few blocked cells, sometimes with a
/// blocked column across it (with or without a gap: the ends may be cut apart), sometimes with
/// costs from 1 to 100.
fn car_grid(u: &mut Unstructured) -> Result<(Value, usize, usize)> {
    if u.ratio(1u8, 4)? {
        return grid_world(u);
    }
    let side = |u: &mut Unstructured| -> Result<usize> {
        if u.ratio(1u8, 4)? { u.int_in_range(1..=40) } else { u.int_in_range(3..=16) }
    };
    let (width, height) = (side(u)?, side(u)?);
    let share = u.int_in_range(0u8..=4)?;
    let mut rows: Vec<Vec<char>> = (0..height)
        .map(|_| (0..width).map(|_| Ok(if u.int_in_range(0u8..=15)? < share { '@' } else { '.' })).collect())
        .collect::<Result<_>>()?;
    if u.ratio(1u8, 4)? {
        let column = u.int_in_range(0..=width - 1)?;
        let gap = if u.ratio(1u8, 2)? { Some(u.int_in_range(0..=height - 1)?) } else { None };
        for (y, row) in rows.iter_mut().enumerate() {
            row[column] = if gap == Some(y) { '.' } else { '@' };
        }
    }
    let mut world = Map::new();
    world.insert("rows".into(), json!(rows.iter().map(|r| r.iter().collect::<String>()).collect::<Vec<_>>()));
    if u.ratio(1u8, 4)? {
        let costs: Vec<Vec<Value>> = (0..height)
            .map(|_| (0..width).map(|_| log_uniform(u, 1.0, 100.0).map(num)).collect())
            .collect::<Result<_>>()?;
        world.insert("costs".into(), json!(costs));
    }
    Ok((json!({ "grid": Value::Object(world) }), width, height))
}

/// Sometimes replaces a grid world's costs by extreme contrast: every cell 1 but a row or a
/// column of 1e6 or 1e12; or that row alone passable (a corridor), the others blocked.
fn cost_contrast(u: &mut Unstructured, world: &mut Value, width: usize, height: usize) -> Result<()> {
    let mode = u.int_in_range(0u8..=7)?;
    if mode > 1 {
        return Ok(());
    }
    let big = *u.choose(&[1e6, 1e12, 1e6, 1e12, 1e12 * (1.0 + f64::EPSILON)])?;
    let column = mode == 0 && u.ratio(1u8, 2)?;
    let k = u.int_in_range(0..=if column { width - 1 } else { height - 1 })?;
    let costs: Vec<Vec<Value>> = (0..height)
        .map(|y| {
            (0..width)
                .map(|x| num(if (column && x == k) || (!column && y == k) { big } else { 1.0 }))
                .collect()
        })
        .collect();
    world["grid"]["costs"] = json!(costs);
    if mode == 1 {
        let rows: Vec<String> =
            (0..height).map(|y| if y == k { ".".repeat(width) } else { "@".repeat(width) }).collect();
        world["grid"]["rows"] = json!(rows);
    }
    Ok(())
}

/// Cells `(column, row from the top)` of a grid world.
type Cells = Vec<(usize, usize)>;

/// The open cells `(column, row from the top)` of a generated grid world, and those of them off
/// its edges with every neighbour open (where a footprint of a cell or so usually fits).
fn open_cells(world: &Value) -> (Cells, Cells) {
    let rows: Vec<Vec<bool>> = world["grid"]["rows"]
        .as_array()
        .map(|rows| {
            rows.iter()
                .map(|r| {
                    r.as_str().unwrap_or_default().chars().map(|c| matches!(c, '.' | 'G' | 'S')).collect()
                })
                .collect()
        })
        .unwrap_or_default();
    let open = |x: usize, y: usize| rows.get(y).and_then(|r| r.get(x)).copied().unwrap_or(false);
    let mut all = Vec::new();
    let mut clear = Vec::new();
    for (y, row) in rows.iter().enumerate() {
        for x in (0..row.len()).filter(|&x| row[x]) {
            all.push((x, y));
            let inner = x > 0 && y > 0 && x + 1 < row.len() && y + 1 < rows.len();
            if inner && (0..9).all(|k| open(x + k % 3 - 1, y + k / 3 - 1)) {
                clear.push((x, y));
            }
        }
    }
    (all, clear)
}

/// A heading: usually a multiple of 45 or 5 degrees, sometimes anything.
fn heading(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=7)? {
        0 => hostile_f64(u)?,
        1 | 2 => f64::from(u.int_in_range(-36i8..=36)?) * PI / 18.0,
        _ => f64::from(u.int_in_range(-8i8..=8)?) * PI / 4.0,
    })
}

/// A grid pose `[x, y, heading]` in metres (y up from the grid's bottom edge, cells `cell`
/// wide): usually in an open cell with open neighbours, else any open cell, at its centre or
/// an eighth of it, sometimes anything.
fn grid_pose(
    u: &mut Unstructured,
    (open, clear): &(Cells, Cells),
    width: usize,
    height: usize,
    cell: f64,
) -> Result<Value> {
    if u.ratio(1u8, 32)? {
        return Ok(json!([num(hostile_f64(u)?), num(hostile_f64(u)?), num(hostile_f64(u)?)]));
    }
    let (x, row) = match u.int_in_range(0u8..=15)? {
        0 => (u.int_in_range(0..=width - 1)?, u.int_in_range(0..=height - 1)?),
        1..=4 if !open.is_empty() => *u.choose(open)?,
        _ if !clear.is_empty() => *u.choose(clear)?,
        _ if !open.is_empty() => *u.choose(open)?,
        _ => (u.int_in_range(0..=width - 1)?, u.int_in_range(0..=height - 1)?),
    };
    // Mostly clear of the cell's sides by more than the planner's margin (a quarter cell for a
    // point), sometimes on them.
    let frac = |u: &mut Unstructured| -> Result<f64> {
        Ok(match u.int_in_range(0u8..=7)? {
            0..=3 => 0.5,
            4 | 5 => *u.choose(&[0.375, 0.625])?,
            _ => f64::from(u.int_in_range(0u8..=8)?) / 8.0,
        })
    };
    let (fx, fy) = (frac(u)?, frac(u)?);
    let mut pose = vec![(x as f64 + fx) * cell, ((height - 1 - row) as f64 + fy) * cell, heading(u)?];
    if u.ratio(1u8, 64)? {
        pose.pop(); // not a pose
    }
    Ok(json!(pose.into_iter().map(num).collect::<Vec<_>>()))
}

/// The spec of a Hybrid A* planner: a turning radius of `unit` times a number in `radii`
/// (sometimes at or past its limits of half a cell and a million cells, or anything), the cell
/// width `resolution` when given, usually a few heading bins (4 to 72, sometimes a hostile
/// count), a gear, a small expansion limit or time limit (the budget skips runs without
/// either), and a footprint ([`footprint`]) sized by `size`.
fn hybrid_spec(
    u: &mut Unstructured,
    unit: f64,
    radii: (f64, f64),
    size: f64,
    resolution: Option<f64>,
) -> Result<Map<String, Value>> {
    let mut spec = Map::new();
    spec.insert("name".into(), json!("hybrid_astar"));
    let cell = resolution.filter(|r| r.is_finite() && *r > 0.0).unwrap_or(unit);
    let radius = match u.int_in_range(0u8..=31)? {
        0 => hostile_f64(u)?,
        1 => cell * *u.choose(&[0.25, 0.4999, 0.5, 1e6, 1e6 * (1.0 + f64::EPSILON)])?,
        2..=9 => cell * log_uniform(u, 0.5, 2.0)?,
        _ => (unit * log_uniform(u, radii.0, radii.1)?).max(0.5 * cell),
    };
    if !u.ratio(1u8, 64)? {
        spec.insert("turning_radius".into(), num(radius));
    }
    insert(&mut spec, "resolution", resolution.map(num));
    match u.int_in_range(0u8..=15)? {
        0..=3 => {}
        4..=14 => {
            spec.insert("heading_bins".into(), json!(u.int_in_range(4u32..=72)?));
        }
        _ => {
            let bins = *u.choose(&[0u64, 1, 3, 4, 5, 7, 1440, 1441, u64::from(u32::MAX), 1 << 32])?;
            spec.insert("heading_bins".into(), json!(bins));
        }
    }
    insert(&mut spec, "reverse", maybe(u, 192, |u| u.arbitrary::<bool>().map(|b| json!(b)))?);
    let expansions = match u.int_in_range(0u8..=7)? {
        0 => Some(*u.choose(&[0u64, 1])?),
        1..=4 => Some((1u64 << u.int_in_range(3u32..=12)?).min(5000)),
        5 | 6 => Some(u.int_in_range(0u64..=5000)?),
        _ => None,
    };
    insert(&mut spec, "max_expansions", expansions.map(|e| json!(e)));
    if expansions.is_none() || u.ratio(1u8, 4)? {
        let t = if u.ratio(1u8, 32)? {
            hostile_f64(u)?
        } else {
            *u.choose(&[0.0, 0.001, 0.002, 0.005, 0.01, 0.02])?
        };
        spec.insert("time_limit_s".into(), num(t));
    }
    insert(&mut spec, "footprint", footprint(u, size)?);
    insert(&mut spec, "smooth", maybe(u, 64, |u| u.arbitrary::<bool>().map(|b| json!(b)))?);
    // Penalties: rarely, and then usually in range (float is a quarter hostile).
    insert(&mut spec, "reverse_penalty", maybe(u, 16, |u| float(u, 1.0, 4.0).map(num))?);
    insert(&mut spec, "non_straight_penalty", maybe(u, 16, |u| float(u, 1.0, 4.0).map(num))?);
    insert(&mut spec, "gear_change_penalty", maybe(u, 16, |u| float(u, 0.0, 4.0).map(num))?);
    Ok(spec)
}

/// `points` turned by `angle` about the origin.
fn turned(points: Vec<[f64; 2]>, angle: f64) -> Vec<[f64; 2]> {
    let (s, c) = angle.sin_cos();
    points.into_iter().map(|[x, y]| [c * x - s * y, s * x + c * y]).collect()
}

/// A footprint polygon, lengths in eighths of `size`, or none (the world's): a rectangle about
/// the reference point (sometimes with it on the back edge); a square ahead of it, not holding
/// it; a sharp thin triangle (a tip of 0.2 to 10 degrees) holding it or not; a ring of more
/// vertices than the documented 1024 (an error); hostile coordinates; degenerate outlines.
fn footprint(u: &mut Unstructured, size: f64) -> Result<Option<Value>> {
    let len = |u: &mut Unstructured, lo: u8, hi: u8| -> Result<f64> {
        Ok(size * f64::from(u.int_in_range(lo..=hi)?) / 8.0)
    };
    let any_angle =
        |u: &mut Unstructured| -> Result<f64> { Ok(f64::from(u.int_in_range(0u8..=71)?) * PI / 36.0) };
    let points: Vec<[f64; 2]> = match u.int_in_range(0u8..=15)? {
        0..=4 => return Ok(None),
        5..=7 => {
            let (back, front, half) = (len(u, 0, 4)?, len(u, 1, 8)?, len(u, 1, 4)?);
            vec![[-back, -half], [front, -half], [front, half], [-back, half]]
        }
        8 | 9 => {
            // Ahead of the reference point, turned a quarter or any angle about it.
            let (gap, side) = (len(u, 1, 8)?, len(u, 1, 6)?);
            let square = vec![
                [gap, -side / 2.0],
                [gap + side, -side / 2.0],
                [gap + side, side / 2.0],
                [gap, side / 2.0],
            ];
            let angle =
                if u.ratio(1u8, 2)? { f64::from(u.int_in_range(0u8..=3)?) * PI / 2.0 } else { any_angle(u)? };
            turned(square, angle)
        }
        10 | 11 => {
            let tip = (0.2 + 9.8 * f64::from(u.int_in_range(0u8..=64)?) / 64.0).to_radians();
            let long = len(u, 4, 16)?;
            // Where the reference point is along it: on the base, inside, behind the base, past
            // the tip (the last two outside).
            let back = long * *u.choose(&[0.0, 1.0 / 3.0, -0.25, 1.2])?;
            let half = long * (tip / 2.0).tan();
            turned(vec![[-back, -half], [long - back, 0.0], [-back, half]], any_angle(u)?)
        }
        12 => {
            let n = *u.choose(&[1025usize, 1100])?;
            let (r, cx) = (len(u, 2, 12)?, len(u, 0, 8)?);
            (0..n)
                .map(|k| {
                    let a = 2.0 * PI * k as f64 / n as f64;
                    [cx + r * a.cos(), r * a.sin()]
                })
                .collect()
        }
        13 => {
            let mut v =
                vec![[-size, -size / 2.0], [size, -size / 2.0], [size, size / 2.0], [-size, size / 2.0]];
            for _ in 0..u.int_in_range(1u8..=3)? {
                let k = u.int_in_range(0..=3)?;
                v[k][u.int_in_range(0..=1)?] = hostile_f64(u)?;
            }
            v
        }
        14 => match u.int_in_range(0u8..=4)? {
            0 => Vec::new(),
            1 => vec![[0.0, 0.0], [size, 0.0]],
            2 => vec![[0.0, 0.0], [size, 0.0], [2.0 * size, 0.0]],
            3 => vec![[0.0, 0.0], [size, 0.0], [size, 0.0], [0.0, size]],
            _ => vec![[0.0, 0.0], [size, size], [size, 0.0], [0.0, size]], // crossing itself
        },
        _ => {
            let (back, front, half) = (len(u, 1, 4)?, len(u, 1, 8)?, len(u, 1, 4)?);
            turned(vec![[-back, -half], [front, -half], [front, half], [-back, half]], any_angle(u)?)
        }
    };
    let mut points = points;
    if u.ratio(1u8, 8)? {
        points.reverse(); // clockwise
    }
    Ok(Some(json!(points.into_iter().map(|[x, y]| json!([num(x), num(y)])).collect::<Vec<_>>())))
}

/// An optional heuristic, mostly admissible ones.
fn heuristic(u: &mut Unstructured, grid: bool) -> Result<Option<Value>> {
    maybe(u, 96, |u| {
        Ok(json!(if grid {
            *u.choose(&["zero", "octile", "euclidean", "manhattan"])?
        } else {
            *u.choose(&["euclidean", "euclidean", "euclidean", "octile"])?
        }))
    })
}

/// A planner object with its parameters.
fn planner_spec(u: &mut Unstructured, planner: PlannerName, grid: bool) -> Result<Value> {
    let mut spec = Map::new();
    spec.insert("name".into(), json!(planner.name()));
    match planner {
        PlannerName::Bfs
        | PlannerName::Dfs
        | PlannerName::Dijkstra
        | PlannerName::ThetaStar
        | PlannerName::Jps
        | PlannerName::JpsPlus => {}
        PlannerName::AStar
        | PlannerName::LpaStar
        | PlannerName::DStarLite
        | PlannerName::AdaptiveAStar
        | PlannerName::MpgaaStar => {
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
        }
        PlannerName::WeightedAStar => {
            spec.insert("weight".into(), num(float(u, 1.0, 6.0)?));
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
        }
        PlannerName::AraStar | PlannerName::AdStar => {
            insert(&mut spec, "epsilon", maybe(u, 192, |u| float(u, 1.0, 8.0).map(num))?);
            insert(&mut spec, "epsilon_step", maybe(u, 192, |u| float(u, 0.0, 2.0).map(num))?);
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
            insert(&mut spec, "time_limit_s", maybe(u, 64, |u| float(u, 0.0, 0.25).map(num))?);
            insert(
                &mut spec,
                "max_expansions",
                maybe(u, 96, |u| {
                    Ok(json!(if u.ratio(1u8, 3)? { hostile_u64(u)? } else { u.int_in_range(0..=200)? }))
                })?,
            );
        }
        PlannerName::HybridAStar => {
            // Built with its world by hybrid_problem; a plain one here.
            spec.insert("turning_radius".into(), json!(1.0));
            spec.insert("max_expansions".into(), json!(100));
        }
        PlannerName::Rrt | PlannerName::RrtConnect | PlannerName::RrtStar => {
            insert(&mut spec, "range", maybe(u, 128, |u| float(u, 0.0, 4.0).map(num))?);
            insert(&mut spec, "goal_bias", maybe(u, 128, |u| float(u, 0.0, 1.0).map(num))?);
            let iterations = if planner == PlannerName::RrtStar { 600 } else { 2000 };
            spec.insert("max_iterations".into(), json!(u.int_in_range(0..=iterations)?));
            insert(&mut spec, "time_limit_s", maybe(u, 48, |u| hostile_f64(u).map(num))?);
            insert(&mut spec, "simplify", maybe(u, 128, |u| u.arbitrary::<bool>().map(|b| json!(b)))?);
            insert(
                &mut spec,
                "smooth",
                maybe(u, 64, |u| Ok(json!(*u.choose(&["hermite", "bezier", "bspline"])?)))?,
            );
            insert(&mut spec, "sampler", maybe(u, 128, sampler)?);
        }
    }
    Ok(Value::Object(spec))
}

/// A sampler object of a sampling planner.
fn sampler(u: &mut Unstructured) -> Result<Value> {
    let name = *u.choose(&["uniform", "bridge", "gaussian"])?;
    let mut spec = Map::new();
    spec.insert("name".into(), json!(name));
    if name != "uniform" {
        spec.insert("std_dev".into(), num(float(u, 0.0, 2.0)?));
        insert(&mut spec, "share", maybe(u, 128, |u| float(u, 0.0, 1.0).map(num))?);
        insert(&mut spec, "attempts", maybe(u, 128, |u| Ok(json!(*u.choose(&[0u32, 1, 2, 10, 50, 100])?)))?);
    }
    Ok(Value::Object(spec))
}

#[cfg(test)]
mod tests {
    use super::*;
    use trailmark::solve::{ProblemSpec, Status};

    /// Most generated documents parse, and a fair share of them are solved: the generator
    /// reaches the planners rather than only the input checks. Prints the tally
    /// (`cargo test --release -- --nocapture` in fuzz/).
    #[test]
    fn documents_reach_the_planners() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut tally = std::collections::BTreeMap::<String, usize>::new();
        let n = 600;
        for _ in 0..n {
            let bytes = pseudo_random_bytes(&mut state, 512);
            let doc = problem(&mut Unstructured::new(&bytes)).unwrap();
            let outcome = match serde_json::from_value::<ProblemSpec>(doc) {
                Err(e) => format!("not a problem: {}", e.to_string().chars().take(60).collect::<String>()),
                Ok(p) if !crate::budget::problem_is_quick(&p) => "skipped".to_string(),
                Ok(p) => match trailmark::solve::solve(&p, crate::NO_DIR) {
                    Err(e) => format!("error: {}", e.to_string().chars().take(60).collect::<String>()),
                    Ok(r) => format!("{}: {:?}", p.planner.name(), r.status),
                },
            };
            *tally.entry(outcome).or_default() += 1;
        }
        for (outcome, count) in &tally {
            println!("{count:5} {outcome}");
        }
        let solved: usize =
            tally.iter().filter(|(k, _)| k.ends_with(&format!("{:?}", Status::Solved))).map(|(_, v)| v).sum();
        // A sixth: Hybrid A* documents, an eighth of all, are mostly refused or stopped by design
        // (footprints off the map or over obstacles, hostile settings, tiny limits).
        assert!(solved * 6 >= n, "only {solved} of {n} documents solved");
    }

    /// `len` bytes of a xorshift generator from `state`, which it advances.
    fn pseudo_random_bytes(state: &mut u64, len: usize) -> Vec<u8> {
        (0..len)
            .map(|_| {
                *state ^= *state << 13;
                *state ^= *state >> 7;
                *state ^= *state << 17;
                *state as u8
            })
            .collect()
    }

    /// `n` documents made by `make` from pseudo-random bytes.
    fn documents(
        n: usize,
        make: impl Fn(&mut Unstructured, &mut Map<String, Value>) -> Result<()>,
    ) -> Vec<Value> {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        (0..n)
            .map(|_| {
                let bytes = pseudo_random_bytes(&mut state, 1024);
                let mut doc = Map::new();
                make(&mut Unstructured::new(&bytes), &mut doc).unwrap();
                Value::Object(doc)
            })
            .collect()
    }

    /// Documents made by `make`, each run through the checks; the tally of their outcomes (a
    /// status and stop, an error's start, skipped).
    fn run_documents(
        n: usize,
        make: impl Fn(&mut Unstructured, &mut Map<String, Value>) -> Result<()>,
    ) -> std::collections::BTreeMap<String, usize> {
        let mut tally = std::collections::BTreeMap::<String, usize>::new();
        for doc in documents(n, make) {
            let outcome = match serde_json::from_value::<ProblemSpec>(doc.clone()) {
                Err(e) => format!("not a problem: {}", e.to_string().chars().take(50).collect::<String>()),
                Ok(p) if !crate::budget::problem_is_quick(&p) => "skipped".to_string(),
                Ok(p) => {
                    let outcome = match trailmark::solve::solve(&p, crate::NO_DIR) {
                        Err(e) => format!("error: {}", e.to_string().chars().take(80).collect::<String>()),
                        Ok(r) => format!("{:?} {:?}", r.status, r.stats.stop),
                    };
                    if std::panic::catch_unwind(|| crate::solve_and_check(&p)).is_err() {
                        panic!("a check failed on {doc}");
                    }
                    outcome
                }
            };
            *tally.entry(outcome).or_default() += 1;
        }
        for (outcome, count) in &tally {
            println!("{count:5} {outcome}");
        }
        tally
    }

    fn count(tally: &std::collections::BTreeMap<String, usize>, prefix: &str) -> usize {
        tally.iter().filter(|(k, _)| k.starts_with(prefix)).map(|(_, v)| v).sum()
    }

    /// Hybrid A* documents on grids and polygon worlds pass the checks, and enough of them are
    /// solved, stopped, proved unreachable and refused for too many footprint vertices.
    #[test]
    fn hybrid_documents_are_solved_and_checked() {
        for grid in [true, false] {
            println!("hybrid_astar on {} worlds:", if grid { "grid" } else { "polygon" });
            let tally = run_documents(300, |u, doc| hybrid_problem(u, doc, grid));
            let solved = count(&tally, "Solved");
            assert!(
                solved >= if grid { 25 } else { 12 },
                "{} world: only {solved} of 300 solved",
                if grid { "grid" } else { "polygon" }
            );
            assert!(count(&tally, "Stopped") >= 10);
            assert!(count(&tally, "error: the footprint: a footprint polygon has at most") >= 3);
            if grid {
                assert!(count(&tally, "NoPath") >= 3);
            }
        }
    }

    /// Box worlds, touching boxes and walls among them, pass the checks; walls between the
    /// ends are generated, found by the check, and never crossed.
    #[test]
    fn box_documents_are_checked() {
        let tally = run_documents(300, box_world_with_planner);
        assert!(count(&tally, "Solved") + count(&tally, "Approximate") >= 60);
        let mut parted = 0;
        for doc in documents(300, box_world_with_planner) {
            let Ok(p) = serde_json::from_value::<ProblemSpec>(doc) else { continue };
            let trailmark::solve::WorldSpec::Boxes(world) = &p.world else { unreachable!() };
            let Ok(result) = trailmark::solve::solve(&p, crate::NO_DIR) else { continue };
            let parts = |(axis, c0, c1): (usize, f64, f64)| {
                let (s, g) = (p.start[axis], p.goal[axis]);
                (s < c0 && g > c1) || (s > c1 && g < c0)
            };
            if crate::boxes::walls(world).into_iter().any(parts) {
                parted += 1;
                assert_ne!(result.status, Status::Solved, "solved across a wall");
            }
        }
        println!("{parted} documents with a wall between the ends");
        assert!(parted >= 15, "only {parted} documents with a wall between the ends");
    }

    /// A box world and an RRT-Connect planner with a small iteration limit.
    fn box_world_with_planner(u: &mut Unstructured, doc: &mut Map<String, Value>) -> Result<()> {
        box_world(u, doc)?;
        doc.insert("planner".into(), json!({"name": "rrt_connect", "max_iterations": 500}));
        Ok(())
    }
}
