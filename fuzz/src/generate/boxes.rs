//! Box worlds, sometimes with touching boxes (a box cut in two, two meeting at a corner, a
//! wall of boxes).

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value, json};

use super::*;

/// A box world of 1 to 9 axes (9 is refused) with up to six boxes, its ends and its space.
/// Some worlds hold boxes that touch (closed boxes block as their union): a box cut in two
/// along an axis, two boxes meeting at a corner (the ends sometimes placed across that corner,
/// so that the straight motion between them runs through it), or a wall of boxes across the
/// region with the start and the goal on its two sides (`boxes::check_result` finds it).
pub(super) fn box_world(u: &mut Unstructured, doc: &mut Map<String, Value>) -> Result<()> {
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
