//! Paired t-tests, Holm's step-down correction and Cohen's dz, on plain
//! numbers.
//!
//! A paired test of `a` against `b` is a one-sample t-test of the
//! differences `a_i − b_i` against 0: `t = mean / (sd / √n)`, `df = n − 1`,
//! two-sided `p` from Student's t (`statrs`). Cohen's dz is `mean / sd` of
//! the differences (Cohen 1988; Lakens 2013, eq. 6). Holm (1979): with `m`
//! p-values sorted ascending, the `i`-th (0-based) is multiplied by `m − i`,
//! then made non-decreasing along the sorted order and capped at 1.

use statrs::distribution::{ContinuousCDF, StudentsT};

/// One paired comparison. `None` where the data cannot give it: fewer than
/// two pairs, or differences with no spread.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairedTest {
    pub n: usize,
    /// Mean of `a − b`.
    pub mean_diff: f64,
    pub t: Option<f64>,
    pub df: u32,
    /// Two-sided, uncorrected.
    pub p: Option<f64>,
    pub dz: Option<f64>,
}

/// Paired t-test of `a` against `b` (same subjects, same order). Returns
/// `None` when the lengths differ or there are no pairs.
pub fn paired_t(a: &[f64], b: &[f64]) -> Option<PairedTest> {
    if a.len() != b.len() || a.is_empty() {
        return None;
    }
    let diffs: Vec<f64> = a.iter().zip(b).map(|(x, y)| x - y).collect();
    Some(one_sample_t(&diffs))
}

/// One-sample t-test of `values` against 0.
pub fn one_sample_t(values: &[f64]) -> PairedTest {
    let n = values.len();
    let mean = values.iter().sum::<f64>() / n.max(1) as f64;
    let df = n.saturating_sub(1) as u32;
    let mut test = PairedTest { n, mean_diff: mean, t: None, df, p: None, dz: None };
    if n < 2 {
        return test;
    }
    let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
    if sd <= f64::EPSILON * mean.abs().max(f64::MIN_POSITIVE) {
        return test;
    }
    let t = mean / (sd / (n as f64).sqrt());
    test.t = Some(t);
    test.dz = Some(mean / sd);
    test.p = StudentsT::new(0.0, 1.0, f64::from(df)).ok().map(|dist| 2.0 * dist.sf(t.abs()));
    test
}

/// Holm-adjusted p-values, in the order given. `None`s (tests that could
/// not be run) stay `None` and do not count towards `m`.
pub fn holm(p: &[Option<f64>]) -> Vec<Option<f64>> {
    let mut order: Vec<usize> = (0..p.len()).filter(|&i| p[i].is_some()).collect();
    order.sort_by(|&i, &j| p[i].partial_cmp(&p[j]).unwrap_or(std::cmp::Ordering::Equal));
    let m = order.len();
    let mut out = vec![None; p.len()];
    let mut running = 0.0f64;
    for (rank, &i) in order.iter().enumerate() {
        let adjusted = (p[i].unwrap_or(1.0) * (m - rank) as f64).min(1.0);
        running = running.max(adjusted);
        out[i] = Some(running);
    }
    out
}
