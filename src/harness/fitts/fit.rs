//! Fitts' law fitted to drag trials, and ISO 9241-9 throughput: pure
//! functions on the trial rows.
//!
//! - The model: `MT = a + b · ID` with the Shannon formulation `ID =
//!   log2(D / W + 1)` (`MacKenzie` 1992), fitted by least squares over the
//!   condition means of completed trials; R² over those means.
//! - Throughput: for each participant and condition, the effective width
//!   `We = 4.133 · SD` of the end points along the movement axis and the
//!   effective distance `De` (the mean distance actually moved) give `IDe
//!   = log2(De / We + 1)`, and `TP = IDe / MT`; a participant's throughput is
//!   the mean over conditions, and the study's the mean over participants
//!   (Soukoreff & `MacKenzie` 2004, "the mean of means").

use super::FittsRow;
use std::collections::BTreeMap;

/// `4.133 = √(2πe)`: the width of a normal end-point distribution that
/// holds 96% of the hits, the convention that makes `We` comparable with a
/// nominal target width.
pub const WE_FACTOR: f64 = 4.133;

/// The fitted model and the throughput.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FittsFit {
    /// Intercept (s).
    pub a_s: f64,
    /// Slope (s per bit).
    pub b_s_per_bit: f64,
    /// R² of the fit over the condition means.
    pub r2: f64,
    /// Mean of the participants' throughputs (bits/s), from effective widths.
    pub throughput_bits_s: f64,
    /// Conditions with at least one completed trial.
    pub conditions: usize,
    /// Completed trials over all trials.
    pub completed: usize,
    pub trials: usize,
}

/// The Shannon index of difficulty (bits).
pub fn index_of_difficulty(distance: f64, width: f64) -> f64 {
    (distance / width + 1.0).log2()
}

/// Least squares `y = a + b x`, with R²; `None` for fewer than two
/// distinct `x`.
pub fn linear_fit(points: &[(f64, f64)]) -> Option<(f64, f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = points.iter().map(|p| (p.1 - my).powi(2)).sum();
    if sxx <= 0.0 {
        return None;
    }
    let b = sxy / sxx;
    let a = my - b * mx;
    let r2 = if syy > 0.0 { sxy * sxy / (sxx * syy) } else { 1.0 };
    Some((a, b, r2))
}

/// The condition means `(ID, mean MT)` of completed trials, in condition order.
pub fn condition_means(rows: &[FittsRow]) -> Vec<(f64, f64, f64, f64)> {
    let mut by: BTreeMap<(u64, u64), Vec<f64>> = BTreeMap::new();
    for r in rows.iter().filter(|r| r.completed) {
        by.entry((r.distance_m.to_bits(), r.width_m.to_bits())).or_default().push(r.movement_s);
    }
    by.into_iter()
        .map(|((d, w), mts)| {
            let (d, w) = (f64::from_bits(d), f64::from_bits(w));
            (d, w, index_of_difficulty(d, w), mts.iter().sum::<f64>() / mts.len() as f64)
        })
        .collect()
}

fn sd(xs: &[f64]) -> Option<f64> {
    if xs.len() < 2 {
        return None;
    }
    let m = xs.iter().sum::<f64>() / xs.len() as f64;
    Some((xs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (xs.len() - 1) as f64).sqrt())
}

/// The mean-of-means throughput (bits/s) over participants; conditions
/// where a participant has fewer than two completed trials, or no scatter,
/// are left out of that participant's mean.
pub fn throughput(rows: &[FittsRow]) -> Option<f64> {
    let mut cells: BTreeMap<(u32, u64, u64), Vec<&FittsRow>> = BTreeMap::new();
    for r in rows.iter().filter(|r| r.completed) {
        cells.entry((r.participant, r.distance_m.to_bits(), r.width_m.to_bits())).or_default().push(r);
    }
    let mut per_participant: BTreeMap<u32, Vec<f64>> = BTreeMap::new();
    for ((p, _, _), trials) in cells {
        let ends: Vec<f64> = trials.iter().map(|r| r.end_error_m).collect();
        let Some(spread) = sd(&ends).filter(|s| *s > 0.0) else { continue };
        let we = WE_FACTOR * spread;
        let de = trials.iter().map(|r| r.distance_m + r.end_error_m).sum::<f64>() / trials.len() as f64;
        let mt = trials.iter().map(|r| r.movement_s).sum::<f64>() / trials.len() as f64;
        if mt > 0.0 && de > 0.0 {
            per_participant.entry(p).or_default().push(index_of_difficulty(de, we) / mt);
        }
    }
    let means: Vec<f64> = per_participant.values().map(|v| v.iter().sum::<f64>() / v.len() as f64).collect();
    (!means.is_empty()).then(|| means.iter().sum::<f64>() / means.len() as f64)
}

/// The fit and throughput of a set of trials.
pub fn fit(rows: &[FittsRow]) -> Option<FittsFit> {
    let means = condition_means(rows);
    let points: Vec<(f64, f64)> = means.iter().map(|&(_, _, id, mt)| (id, mt)).collect();
    let (a, b, r2) = linear_fit(&points)?;
    Some(FittsFit {
        a_s: a,
        b_s_per_bit: b,
        r2,
        throughput_bits_s: throughput(rows)?,
        conditions: means.len(),
        completed: rows.iter().filter(|r| r.completed).count(),
        trials: rows.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::technique::TechniqueKind;

    fn row(participant: u32, distance_m: f64, width_m: f64, movement_s: f64, end_error_m: f64) -> FittsRow {
        FittsRow {
            participant,
            technique: TechniqueKind::JOINT,
            distance_m,
            width_m,
            id_bits: index_of_difficulty(distance_m, width_m),
            movement_s,
            completed: true,
            end_error_m,
            repetition: 0,
        }
    }

    #[test]
    fn the_shannon_index_and_a_perfect_line() {
        assert!((index_of_difficulty(0.3, 0.01) - 31f64.log2()).abs() < 1e-12);
        assert!((index_of_difficulty(0.07, 0.01) - 3.0).abs() < 1e-12);
        let (a, b, r2) = linear_fit(&[(1.0, 0.5), (2.0, 0.75), (3.0, 1.0)]).expect("fit");
        assert!((a - 0.25).abs() < 1e-12 && (b - 0.25).abs() < 1e-12 && (r2 - 1.0).abs() < 1e-12);
        // y = x with one point off by 1: r² = sxy² / (sxx syy) = 2.25 / (2 · 3.5) by hand.
        let (_, _, r2) = linear_fit(&[(0.0, 0.0), (1.0, 2.0), (2.0, 2.0)]).expect("fit");
        assert!((r2 - 0.75).abs() < 1e-12, "{r2}");
        assert_eq!(linear_fit(&[(1.0, 1.0), (1.0, 2.0)]), None);
    }

    #[test]
    fn throughput_uses_the_effective_width_of_the_end_points() {
        // One participant, one condition, D = 0.3 m, end errors ±1 cm: SD
        // = √(2·0.01²/1)·… by hand: errors +0.01 and -0.01 have SD 0.014142,
        // We = 4.133 · 0.014142 = 0.058450, De = 0.3, IDe = log2(0.3 /
        // 0.058450 + 1) = 2.6168 bits; MT 1 s gives 2.6168 bits/s.
        let rows = [row(1, 0.3, 0.02, 1.0, 0.01), row(1, 0.3, 0.02, 1.0, -0.01)];
        let tp = throughput(&rows).expect("throughput");
        assert!((tp - 2.6168).abs() < 1e-3, "{tp}");
        // A second participant twice as fast doubles theirs: the mean of means.
        let mut both = rows.to_vec();
        both.extend([row(2, 0.3, 0.02, 0.5, 0.01), row(2, 0.3, 0.02, 0.5, -0.01)]);
        assert!((throughput(&both).expect("throughput") - 1.5 * 2.6168).abs() < 2e-3);
    }
}
