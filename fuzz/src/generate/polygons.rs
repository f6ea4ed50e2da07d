//! Polygon worlds of a few polygons (hostile coordinates among them), points and poses in them,
//! and the roadmap fields of their documents.

use std::f64::consts::PI;

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value, json};

use super::*;

/// Where a polygon world's coordinates live: `offset + scale * c` for `c` in `[0, 10]`.
pub(super) struct Frame {
    pub(super) offset: [f64; 2],
    pub(super) scale: f64,
    pub(super) aspect: f64,
}

impl Frame {
    fn at(&self, x: f64, y: f64) -> [f64; 2] {
        [self.offset[0] + self.scale * x, self.offset[1] + self.scale * self.aspect * y]
    }
}

/// A polygon world of a few polygons in a frame that is usually `[0, 10]^2` and sometimes
/// tiny, huge, far from the origin or thin.
pub(super) fn polygon_world(u: &mut Unstructured) -> Result<(Value, Frame)> {
    polygon_world_hostile(u, 3)
}

/// [`polygon_world`] with a hostile frame one time in `share`.
pub(super) fn polygon_world_hostile(u: &mut Unstructured, share: u8) -> Result<(Value, Frame)> {
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
pub(super) fn polygon_end(u: &mut Unstructured, frame: &Frame, pose: bool) -> Result<Value> {
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
pub(super) fn roadmap_fields(
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
