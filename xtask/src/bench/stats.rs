//! The statistics of the report: medians, geometric means and fitted power laws.

/// The median of sorted values (the mean of the middle two for an even count), NaN when empty.
pub fn median(sorted: &[f64]) -> f64 {
    match sorted.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => sorted[n / 2],
        n => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

/// The value at fraction `p` of `sorted`, interpolated between neighbours (NaN when empty).
pub fn quantile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let at = p * (sorted.len() - 1) as f64;
    let (i, f) = (at.floor() as usize, at.fract());
    if i + 1 < sorted.len() { sorted[i] + (sorted[i + 1] - sorted[i]) * f } else { sorted[i] }
}

/// `values` in increasing order (NaN last).
pub fn sorted(mut values: Vec<f64>) -> Vec<f64> {
    values.sort_by(f64::total_cmp);
    values
}

/// The upper median of `values` in any order: the middle value, or the higher of the middle two
/// for an even count; NaN when empty.
pub fn upper_median(values: Vec<f64>) -> f64 {
    let values = sorted(values);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The geometric mean of `values` (1 when there are none).
pub fn geometric_mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0), |(s, n), v| (s + v.ln(), n + 1));
    (sum / n.max(1) as f64).exp()
}

/// The least-squares exponent k of `y ~ x^k`.
pub fn fitted_exponent(samples: &[(f64, f64)]) -> f64 {
    let n = samples.len() as f64;
    let (sx, sy) = samples.iter().fold((0.0, 0.0), |(a, b), &(x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / n, sy / n);
    let (num, den) = samples
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + (x.ln() - mx) * (y.ln() - my), b + (x.ln() - mx).powi(2)));
    num / den
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians_by_hand() {
        assert_eq!(median(&[1.0, 2.0, 7.0]), 2.0);
        assert_eq!(median(&[1.0, 2.0, 4.0, 7.0]), 3.0);
        assert!(median(&[]).is_nan());
        assert_eq!(quantile(&[1.0, 2.0, 4.0, 8.0, 16.0], 0.5), 4.0);
        assert_eq!(quantile(&[1.0, 2.0, 4.0, 8.0, 16.0], 0.875), 12.0);
        assert!(quantile(&[], 0.99).is_nan());
        assert_eq!(upper_median(vec![7.0, 1.0, 4.0, 2.0]), 4.0);
        assert!(upper_median(Vec::new()).is_nan());
    }

    #[test]
    fn means_and_exponents_by_hand() {
        assert!((geometric_mean([2.0, 8.0].into_iter()) - 4.0).abs() < 1e-12);
        let cubic: Vec<(f64, f64)> =
            [1.0, 2.0, 5.0, 10.0].iter().map(|&x: &f64| (x, 3.0 * x.powi(3))).collect();
        assert!((fitted_exponent(&cubic) - 3.0).abs() < 1e-9);
    }
}
