//! Valid-shaped problem documents with hostile values, for the `solve_document` target.
//!
//! [`ProblemDoc`] implements [`Arbitrary`]: from the fuzzer's bytes it builds the JSON of a
//! problem in the schema of trailmark-core's `problem.rs` — a small grid (inline rows, optional
//! costs) or a polygon world of a few polygons, any of the twelve planners, any roadmap, space
//! and sampler — whose numbers are mostly ordinary and otherwise extreme: 0, -0, 1e308, 1e-300,
//! the smallest subnormal, `u32::MAX`, `u64::MAX`, values just beyond a documented limit. The
//! parameters that bound the work (samples, iterations, time limits, sampler attempts) stay
//! small; the bytes decide everything else. Most documents are valid, so the planners run;
//! a tenth or so put a field where it does not belong, to reach the errors.

use std::f64::consts::PI;
use std::fmt;

use arbitrary::{Arbitrary, Result, Unstructured};
use serde_json::{Map, Value, json};

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

/// The planners of problem documents.
#[derive(Arbitrary, Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlannerName {
    Bfs,
    Dfs,
    Dijkstra,
    Astar,
    WeightedAstar,
    LpaStar,
    DstarLite,
    AraStar,
    AdStar,
    Rrt,
    RrtConnect,
    RrtStar,
    ThetaStar,
    AdaptiveAstar,
    MpgaaStar,
    Jps,
    JpsPlus,
}

impl PlannerName {
    fn name(self) -> &'static str {
        match self {
            PlannerName::Bfs => "bfs",
            PlannerName::Dfs => "dfs",
            PlannerName::Dijkstra => "dijkstra",
            PlannerName::Astar => "astar",
            PlannerName::WeightedAstar => "weighted_astar",
            PlannerName::LpaStar => "lpa_star",
            PlannerName::DstarLite => "dstar_lite",
            PlannerName::AraStar => "ara_star",
            PlannerName::AdStar => "ad_star",
            PlannerName::Rrt => "rrt",
            PlannerName::RrtConnect => "rrt_connect",
            PlannerName::RrtStar => "rrt_star",
            PlannerName::ThetaStar => "theta_star",
            PlannerName::AdaptiveAstar => "adaptive_astar",
            PlannerName::MpgaaStar => "mpgaa_star",
            PlannerName::Jps => "jps",
            PlannerName::JpsPlus => "jps_plus",
        }
    }

    fn is_sampling(self) -> bool {
        matches!(self, PlannerName::Rrt | PlannerName::RrtConnect | PlannerName::RrtStar)
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
    let mut planner: PlannerName = u.arbitrary()?;
    // Sampling planners take polygon worlds; a few mismatched pairs reach the error.
    if grid && planner.is_sampling() && !misplaced {
        planner = PlannerName::Astar;
    }
    let mut doc = Map::new();
    if !grid && planner.is_sampling() && u.ratio(1u8, 4)? {
        box_world(u, &mut doc)?;
    } else if grid {
        let (world, width, height) = grid_world(u)?;
        doc.insert("world".into(), world);
        doc.insert("start".into(), grid_end(u, width, height)?);
        doc.insert("goal".into(), grid_end(u, width, height)?);
    } else {
        let (world, frame) = polygon_world(u)?;
        let graph: GraphName = u.arbitrary()?;
        let space_dubins = planner.is_sampling() && u.ratio(1u8, 3)?;
        let car_roadmap = matches!(graph, GraphName::DubinsPrm | GraphName::ReedsSheppPrm);
        let dubins = space_dubins || (!planner.is_sampling() && car_roadmap);
        doc.insert("world".into(), world);
        doc.insert("start".into(), polygon_end(u, &frame, dubins)?);
        doc.insert("goal".into(), polygon_end(u, &frame, dubins)?);
        if dubins || misplaced && u.ratio(1u8, 2)? {
            doc.insert("turning_radius".into(), num(float(u, 0.0, 3.0)? * frame.scale));
        }
        if planner.is_sampling() {
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
    doc.insert("planner".into(), planner_spec(u, planner, grid)?);
    Ok(Value::Object(doc))
}

/// A box world of 1 to 9 axes (9 is refused) with up to six boxes, its ends and its space.
fn box_world(u: &mut Unstructured, doc: &mut Map<String, Value>) -> Result<()> {
    let axes = u.int_in_range(1usize..=9)?;
    let value = |u: &mut Unstructured, lo: f64, hi: f64| -> Result<f64> {
        if u.ratio(1u8, 32)? { hostile_f64(u) } else { float(u, lo, hi) }
    };
    let bounds: Vec<Value> = (0..axes)
        .map(|_| Ok(json!([num(value(u, -1.0, 0.0)?), num(value(u, 1.0, 2.0)?)])))
        .collect::<Result<_>>()?;
    let mut obstacles = Vec::new();
    for _ in 0..u.int_in_range(0u8..=6)? {
        let lo: Vec<Value> = (0..axes).map(|_| value(u, -0.5, 1.0).map(num)).collect::<Result<_>>()?;
        let hi: Vec<Value> = (0..axes).map(|_| value(u, 0.0, 1.5).map(num)).collect::<Result<_>>()?;
        obstacles.push(json!([lo, hi]));
    }
    doc.insert("world".into(), json!({"boxes": {"bounds": bounds, "obstacles": obstacles}}));
    for end in ["start", "goal"] {
        let n = if u.ratio(1u8, 16)? { axes + 1 } else { axes };
        let at: Vec<Value> = (0..n).map(|_| value(u, -0.2, 1.2).map(num)).collect::<Result<_>>()?;
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
    let hostile_frame = u.ratio(1u8, 3)?;
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
        PlannerName::Astar
        | PlannerName::LpaStar
        | PlannerName::DstarLite
        | PlannerName::AdaptiveAstar
        | PlannerName::MpgaaStar => {
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
        }
        PlannerName::WeightedAstar => {
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
            let bytes: Vec<u8> = (0..512)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    state as u8
                })
                .collect();
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
        assert!(solved * 5 >= n, "only {solved} of {n} documents solved");
    }
}
