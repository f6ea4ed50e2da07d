//! The numbers of hostile documents: mostly ordinary, otherwise extreme, and the helpers that
//! put them in a document.

use std::f64::consts::PI;

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value};

/// Values at and beyond the edges of what the parameters take.
pub(super) const EXTREMES: &[f64] = &[
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
pub(super) fn float(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    if u.ratio(1u8, 4)? {
        return hostile_f64(u);
    }
    let steps = ((hi - lo) * 8.0).max(0.0) as u32;
    Ok(lo + f64::from(u.int_in_range(0..=steps)?) / 8.0)
}

/// A hostile unsigned integer (as JSON it must be an integer, not a float).
pub(super) fn hostile_u64(u: &mut Unstructured) -> Result<u64> {
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
pub(super) fn maybe<T>(
    u: &mut Unstructured,
    p: u8,
    f: impl FnOnce(&mut Unstructured) -> Result<T>,
) -> Result<Option<T>> {
    if u.arbitrary::<u8>()? < p { f(u).map(Some) } else { Ok(None) }
}

pub(super) fn num(v: f64) -> Value {
    serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
}

pub(super) fn insert(map: &mut Map<String, Value>, key: &str, value: Option<Value>) {
    if let Some(value) = value {
        map.insert(key.into(), value);
    }
}

/// A log-uniform float in `[lo, hi]` (65 steps).
pub(super) fn log_uniform(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    let t = f64::from(u.int_in_range(0u8..=64)?) / 64.0;
    Ok((lo.ln() + t * (hi.ln() - lo.ln())).exp().clamp(lo, hi))
}
