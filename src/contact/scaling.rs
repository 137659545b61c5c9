//! Empirical complexity: the slope of a log-log fit of time against size.
//! A slope of 1 is linear, 2 quadratic, about 0 logarithmic; used by the
//! contact benchmark and the accuracy-versus-time study.

/// Least-squares slope of `ln time` against `ln size` over `(size, time)`
/// samples. `None` with fewer than two usable (positive) samples or when
/// every size is the same.
pub fn log_log_slope(samples: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = samples
        .iter()
        .filter(|&&(n, t)| n > 0.0 && t > 0.0 && n.is_finite() && t.is_finite())
        .map(|&(n, t)| (n.ln(), t.ln()))
        .collect();
    if logs.len() < 2 {
        return None;
    }
    let count = logs.len() as f64;
    let mean_x = logs.iter().map(|p| p.0).sum::<f64>() / count;
    let mean_y = logs.iter().map(|p| p.1).sum::<f64>() / count;
    let sxx: f64 = logs.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

#[cfg(test)]
mod tests {
    use super::log_log_slope;

    #[test]
    fn power_laws_give_their_exponent() {
        let quadratic: Vec<(f64, f64)> = (1..8).map(|k| (f64::from(1 << k), 3.0 * f64::from(1 << (2 * k)))).collect();
        assert!((log_log_slope(&quadratic).expect("slope") - 2.0).abs() < 1e-12);
        assert_eq!(log_log_slope(&[(4.0, 1.0)]), None);
        assert_eq!(log_log_slope(&[(4.0, 1.0), (4.0, 2.0)]), None);
    }
}
