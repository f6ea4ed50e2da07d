//! Hybrid A* documents: grids of any cell size with dear rows, polygon worlds, poses, and
//! footprints (ahead of the reference point, thin, past the vertex limit).

use std::f64::consts::PI;

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value, json};

use super::*;

/// A Hybrid A* problem: a grid world (cells of a chosen width, sometimes a row or column of
/// cells a million or a trillion times dearer than the rest, or such a corridor alone) or a
/// polygon world, start and goal poses, and the planner's spec ([`hybrid_spec`]).
pub(super) fn hybrid_problem(u: &mut Unstructured, doc: &mut Map<String, Value>, grid: bool) -> Result<()> {
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
pub(super) fn car_grid(u: &mut Unstructured) -> Result<(Value, usize, usize)> {
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
pub(super) fn cost_contrast(
    u: &mut Unstructured,
    world: &mut Value,
    width: usize,
    height: usize,
) -> Result<()> {
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
pub(super) type Cells = Vec<(usize, usize)>;

/// The open cells `(column, row from the top)` of a generated grid world, and those of them off
/// its edges with every neighbour open (where a footprint of a cell or so usually fits).
pub(super) fn open_cells(world: &Value) -> (Cells, Cells) {
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
pub(super) fn heading(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=7)? {
        0 => hostile_f64(u)?,
        1 | 2 => f64::from(u.int_in_range(-36i8..=36)?) * PI / 18.0,
        _ => f64::from(u.int_in_range(-8i8..=8)?) * PI / 4.0,
    })
}

/// A grid pose `[x, y, heading]` in metres (y up from the grid's bottom edge, cells `cell`
/// wide): usually in an open cell with open neighbours, else any open cell, at its centre or
/// an eighth of it, sometimes anything.
pub(super) fn grid_pose(
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
pub(super) fn hybrid_spec(
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
pub(super) fn turned(points: Vec<[f64; 2]>, angle: f64) -> Vec<[f64; 2]> {
    let (s, c) = angle.sin_cos();
    points.into_iter().map(|[x, y]| [c * x - s * y, s * x + c * y]).collect()
}

/// A footprint polygon, lengths in eighths of `size`, or none (the world's): a rectangle about
/// the reference point (sometimes with it on the back edge); a square ahead of it, not holding
/// it; a sharp thin triangle (a tip of 0.2 to 10 degrees) holding it or not; a ring of more
/// vertices than the documented 1024 (an error); hostile coordinates; degenerate outlines.
pub(super) fn footprint(u: &mut Unstructured, size: f64) -> Result<Option<Value>> {
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
