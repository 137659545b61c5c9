//! Within-subject 95% confidence intervals (Cousineau 2005, with Morey's
//! 2008 correction), on plain numbers.
//!
//! Between-subject CIs include how fast each participant is overall, which a
//! within-subject design removes from every comparison; so they look wide
//! while the ANOVA finds differences. Cousineau normalises each subject's
//! values by removing the subject's mean and adding the grand mean; Morey
//! scales the resulting variance by `C / (C − 1)` for `C` conditions, because
//! normalising makes the values of one subject correlated. The half-width
//! of condition `c` is `t(0.975, n − 1) · sd_c · √(C / (C − 1)) / √n`.

use super::t_quantile::t_quantile_975;

/// Half-widths of the 95% CIs, one per condition, for `values[subject][condition]`
/// (every subject has every condition). `None` for every condition when
/// there are fewer than two subjects or two conditions, or the rows are ragged.
pub fn cousineau_morey_half_widths(values: &[Vec<f64>]) -> Vec<Option<f64>> {
    let n = values.len();
    let conditions = values.first().map_or(0, Vec::len);
    if n < 2 || conditions < 2 || values.iter().any(|row| row.len() != conditions) {
        return vec![None; conditions];
    }
    let grand = values.iter().flatten().sum::<f64>() / (n * conditions) as f64;
    let normalised: Vec<Vec<f64>> = values
        .iter()
        .map(|row| {
            let subject_mean = row.iter().sum::<f64>() / conditions as f64;
            row.iter().map(|v| v - subject_mean + grand).collect()
        })
        .collect();
    let c = conditions as f64;
    let morey = (c / (c - 1.0)).sqrt();
    let t = t_quantile_975((n - 1) as u32);
    (0..conditions)
        .map(|k| {
            let column: Vec<f64> = normalised.iter().map(|row| row[k]).collect();
            let mean = column.iter().sum::<f64>() / n as f64;
            let sd = (column.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
            Some(t * sd * morey / (n as f64).sqrt())
        })
        .collect()
}
