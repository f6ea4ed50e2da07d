//! Grid worlds: inline rows with optional costs, and cells in them.

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value, json};

use super::*;

/// A small grid world: its JSON, width and height.
pub(super) fn grid_world(u: &mut Unstructured) -> Result<(Value, usize, usize)> {
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
pub(super) fn grid_end(u: &mut Unstructured, width: usize, height: usize) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=15)? {
        0 => json!([num(hostile_f64(u)?), num(hostile_f64(u)?)]),
        1 => json!([u.int_in_range(0..=width)?, u.int_in_range(0..=height)?, 0]),
        2 => json!([u.arbitrary::<u32>()?, u.int_in_range(0..=height - 1)?]),
        _ => json!([u.int_in_range(0..=width - 1)?, u.int_in_range(0..=height - 1)?]),
    })
}
