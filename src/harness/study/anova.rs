//! Two-way repeated-measures ANOVA (both factors within subjects) with the
//! Greenhouse–Geisser correction and partial η², on plain numbers.
//!
//! Each effect is tested through its orthonormal contrasts: for subject `s`
//! with cell values `y_s` (A-major: index `a·levels_b + b`), the effect's
//! contrast scores are `z_s = Mᵀ y_s`, where `M` is `C_a ⊗ 1_b/√b` (A),
//! `1_a/√a ⊗ C_b` (B) or `C_a ⊗ C_b` (A×B) and `C_k` is the normalised
//! Helmert basis of the `k - 1` contrasts of `k` levels. Then
//! `SS_effect = n·|z̄|²`, `SS_error = Σ_s |z_s − z̄|²` (the effect × subject
//! interaction), `df = (d, d·(n − 1))` for `d` contrasts — the textbook
//! decomposition (Maxwell & Delaney 2004, ch. 12), written once for all
//! three effects. The Greenhouse–Geisser ε̂ is `tr(S)² / (d·tr(S²))` for the
//! covariance `S` of the `z_s`; the corrected test uses `ε̂·df` for both
//! degrees of freedom. Partial η² = `SS / (SS + SS_error)`.
//!
//! Distributions come from `statrs` (F's survival function).

use statrs::distribution::{ContinuousCDF, FisherSnedecor};

/// Cell values of a two-factor within-subject design: one row per subject,
/// `levels_a · levels_b` values each, A-major (`a·levels_b + b`). Every
/// subject has every cell (drop incomplete subjects before).
#[derive(Debug, Clone, PartialEq)]
pub struct TwoWayData {
    pub levels_a: usize,
    pub levels_b: usize,
    pub subjects: Vec<Vec<f64>>,
}

/// One effect's test. Statistics that the data cannot give (fewer than two
/// subjects, a factor with one level, no error variance) are `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EffectTest {
    /// Uncorrected degrees of freedom: `d` and `d·(n − 1)`.
    pub df1: u32,
    pub df2: u32,
    pub ss: f64,
    pub ss_error: f64,
    pub f: Option<f64>,
    pub p: Option<f64>,
    /// Greenhouse–Geisser ε̂, in `[1/d, 1]`; exactly 1 for a one-df effect.
    pub epsilon_gg: Option<f64>,
    /// `p` with both dfs scaled by ε̂.
    pub p_gg: Option<f64>,
    pub eta_p2: Option<f64>,
}

/// The three effects of a two-way design.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RmAnova {
    pub a: EffectTest,
    pub b: EffectTest,
    pub ab: EffectTest,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnovaError {
    #[error("subject {subject} has {got} cell values, the design has {expected}")]
    Ragged { subject: usize, got: usize, expected: usize },
    #[error("subject {subject} has a value that is not a finite number")]
    NotFinite { subject: usize },
}

/// Runs the ANOVA. A design with zero subjects or one level everywhere gives
/// effects without statistics, not an error.
pub fn rm_anova(data: &TwoWayData) -> Result<RmAnova, AnovaError> {
    let (la, lb) = (data.levels_a, data.levels_b);
    let cells = la * lb;
    for (subject, row) in data.subjects.iter().enumerate() {
        if row.len() != cells {
            return Err(AnovaError::Ragged { subject, got: row.len(), expected: cells });
        }
        if row.iter().any(|v| !v.is_finite()) {
            return Err(AnovaError::NotFinite { subject });
        }
    }
    let (ca, cb) = (helmert(la), helmert(lb));
    let (ma, mb) = (mean_vector(la), mean_vector(lb));
    Ok(RmAnova {
        a: effect(&data.subjects, &kronecker(&ca, &mb)),
        b: effect(&data.subjects, &kronecker(&ma, &cb)),
        ab: effect(&data.subjects, &kronecker(&ca, &cb)),
    })
}

/// A matrix as its columns.
type Columns = Vec<Vec<f64>>;

/// Normalised Helmert contrasts of `k` levels: `k − 1` orthonormal columns,
/// each orthogonal to the constant.
fn helmert(k: usize) -> Columns {
    (1..k)
        .map(|j| {
            let norm = ((j * (j + 1)) as f64).sqrt();
            (0..k)
                .map(|i| match i.cmp(&j) {
                    std::cmp::Ordering::Less => 1.0 / norm,
                    std::cmp::Ordering::Equal => -(j as f64) / norm,
                    std::cmp::Ordering::Greater => 0.0,
                })
                .collect()
        })
        .collect()
}

/// The unit vector averaging `k` levels (one column).
fn mean_vector(k: usize) -> Columns {
    vec![vec![1.0 / (k as f64).sqrt(); k]]
}

/// Columns of `A ⊗ B` (A-major rows, matching the cell layout).
fn kronecker(a: &Columns, b: &Columns) -> Columns {
    let mut out = Vec::with_capacity(a.len() * b.len());
    for ca in a {
        for cb in b {
            out.push(ca.iter().flat_map(|x| cb.iter().map(move |y| x * y)).collect());
        }
    }
    out
}

fn effect(subjects: &[Vec<f64>], contrasts: &Columns) -> EffectTest {
    let d = contrasts.len();
    let n = subjects.len();
    let df1 = d as u32;
    let df2 = (d * n.saturating_sub(1)) as u32;
    let z: Vec<Vec<f64>> = subjects
        .iter()
        .map(|y| contrasts.iter().map(|c| c.iter().zip(y).map(|(c, y)| c * y).sum()).collect())
        .collect();
    let mut test =
        EffectTest { df1, df2, ss: 0.0, ss_error: 0.0, f: None, p: None, epsilon_gg: None, p_gg: None, eta_p2: None };
    if d == 0 || n < 2 {
        return test;
    }
    let mean: Vec<f64> = (0..d).map(|j| z.iter().map(|zs| zs[j]).sum::<f64>() / n as f64).collect();
    test.ss = n as f64 * mean.iter().map(|m| m * m).sum::<f64>();
    // Covariance of the contrast scores (n − 1 denominator).
    let mut cov = vec![vec![0.0; d]; d];
    for zs in &z {
        for i in 0..d {
            for j in 0..d {
                cov[i][j] += (zs[i] - mean[i]) * (zs[j] - mean[j]);
            }
        }
    }
    let trace: f64 = (0..d).map(|i| cov[i][i]).sum();
    test.ss_error = trace;
    for row in &mut cov {
        for v in row.iter_mut() {
            *v /= (n - 1) as f64;
        }
    }
    let total = test.ss + test.ss_error;
    test.eta_p2 = (total > 0.0).then(|| test.ss / total);
    // No error variance: F is undefined (infinite or 0/0), so no test.
    if test.ss_error <= f64::EPSILON * total.max(f64::MIN_POSITIVE) {
        return test;
    }
    let f = (test.ss / f64::from(df1)) / (test.ss_error / f64::from(df2));
    test.f = Some(f);
    test.p = f_survival(f, f64::from(df1), f64::from(df2));
    let s_trace: f64 = (0..d).map(|i| cov[i][i]).sum();
    let s2_trace: f64 = cov.iter().flatten().map(|v| v * v).sum();
    let eps = if d == 1 { 1.0 } else { (s_trace * s_trace / (d as f64 * s2_trace)).clamp(1.0 / d as f64, 1.0) };
    test.epsilon_gg = Some(eps);
    test.p_gg = f_survival(f, eps * f64::from(df1), eps * f64::from(df2));
    test
}

/// `P(F(df1, df2) > f)`.
fn f_survival(f: f64, df1: f64, df2: f64) -> Option<f64> {
    FisherSnedecor::new(df1, df2).ok().map(|dist| dist.sf(f))
}
