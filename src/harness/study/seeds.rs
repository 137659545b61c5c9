//! Many independent studies of one design (`study --seeds N`): how often
//! does each of the paper's findings reproduce?
//!
//! Study `k` (1-based, `k = 1..=N`) runs into `DIR/seed-<k>/` as an ordinary
//! run folder, with study seed [`seed_for`]`(seed, k)`: study 1 uses `--seed`
//! itself (so it is the single run of that seed), the others seeds derived
//! from it with `SplitMix64`. Then `DIR/findings.csv` counts, per finding of
//! `findings::FINDINGS`, the seeds that could test it (`seeds`), those that
//! reproduced it (`reproduced`) and the share (`reproduced / seeds`, empty
//! for 0), and `DIR/seeds.png` draws every seed's cell means with their
//! mean over seeds.

use super::analysis::analyze;
use super::error::StudyError;
use super::findings::{FINDINGS, FindingVerdict};
use super::output::{RUN_TOML, RunFile, TRIALS_CSV, read_trials};
use super::seeds_figure::write_seeds_figure;
use super::summary::{SummaryRow, summarize};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

pub const FINDINGS_CSV: &str = "findings.csv";
pub const SEEDS_PNG: &str = "seeds.png";
/// `findings.csv` columns.
pub const FINDINGS_COLUMNS: [&str; 6] = ["finding", "seeds", "reproduced", "share", "wilson_low", "wilson_high"];

/// The study seed of study `k` (1-based) of a many-seeds run: `base` for
/// `k = 1`, else `SplitMix64` of `base` and `k`, kept within TOML's integers.
pub fn seed_for(base: u64, k: u32) -> u64 {
    if k <= 1 {
        return base;
    }
    // `trial_seed` with participant 0 is the same SplitMix64 chain, never
    // used for a trial (participants start at 1).
    super::design::trial_seed(base, 0, k) & (i64::MAX as u64)
}

/// The folder of study `k` (1-based).
pub fn seed_dir(dir: &Path, k: u32) -> PathBuf {
    dir.join(format!("seed-{k}"))
}

/// One line of `findings.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FindingsRow {
    pub finding: String,
    /// Seeds whose run could test the finding.
    pub seeds: u32,
    pub reproduced: u32,
    pub share: Option<f64>,
    /// Wilson's 95% score interval of the share (empty for 0 seeds).
    pub wilson_low: Option<f64>,
    pub wilson_high: Option<f64>,
}

/// Wilson's score interval for `k` successes in `n` trials at 95%
/// (Wilson 1927; recommended over the normal interval for small `n` and
/// shares near 0 or 1 by Brown, Cai & `DasGupta` 2001). `None` for `n = 0`.
pub fn wilson_95(k: u32, n: u32) -> Option<(f64, f64)> {
    // The 97.5th percentile of the standard normal.
    const Z: f64 = 1.959_963_984_540_054;
    if n == 0 {
        return None;
    }
    let (k, n) = (f64::from(k), f64::from(n));
    let p = k / n;
    let z2 = Z * Z;
    let denom = 1.0 + z2 / n;
    let centre = (p + z2 / (2.0 * n)) / denom;
    let half = Z * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt() / denom;
    Some(((centre - half).max(0.0), (centre + half).min(1.0)))
}

/// Reads the finished run folders, judges every finding in each, and writes
/// `findings.csv` and `seeds.png` into `dir`. Returns the rows written.
pub fn summarize_seeds(dir: &Path, runs: &[PathBuf]) -> Result<Vec<FindingsRow>, StudyError> {
    let mut rows: Vec<FindingsRow> = FINDINGS
        .iter()
        .map(|f| FindingsRow {
            finding: f.id.to_owned(),
            seeds: 0,
            reproduced: 0,
            share: None,
            wilson_low: None,
            wilson_high: None,
        })
        .collect();
    let mut summaries: Vec<Vec<SummaryRow>> = Vec::new();
    let mut design = None;
    for run in runs {
        let file = RunFile::load(&run.join(RUN_TOML))?;
        let trials = read_trials(&run.join(TRIALS_CSV))?;
        let analysis = analyze(&file.design, &trials);
        for (row, finding) in rows.iter_mut().zip(FINDINGS.iter()) {
            match finding.judge(&analysis).verdict {
                FindingVerdict::Reproduced => {
                    row.seeds += 1;
                    row.reproduced += 1;
                }
                FindingVerdict::NotReproduced => row.seeds += 1,
                FindingVerdict::NotTested(_) => {}
            }
        }
        summaries.push(summarize(&file.design, &trials));
        design.get_or_insert(file.design);
    }
    for row in &mut rows {
        row.share = (row.seeds > 0).then(|| f64::from(row.reproduced) / f64::from(row.seeds));
        let interval = wilson_95(row.reproduced, row.seeds);
        row.wilson_low = interval.map(|i| i.0);
        row.wilson_high = interval.map(|i| i.1);
    }
    super::csv_rows::write_rows(&dir.join(FINDINGS_CSV), Some(&FINDINGS_COLUMNS), &rows)?;
    if let Some(design) = design {
        write_seeds_figure(&design, &summaries, &dir.join(SEEDS_PNG))?;
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wilson_intervals_match_published_values() {
        // Brown, Cai & DasGupta (2001) and the usual tables: 5 of 10 gives
        // 0.2366 to 0.7634; 0 of 10 gives 0 to 0.2775; 20 of 20 gives
        // 0.8389 to 1.
        let close = |(a, b): (f64, f64), (c, d): (f64, f64)| (a - c).abs() < 5e-5 && (b - d).abs() < 5e-5;
        assert!(close(wilson_95(5, 10).expect("n > 0"), (0.2366, 0.7634)));
        assert!(close(wilson_95(0, 10).expect("n > 0"), (0.0, 0.2775)));
        assert!(close(wilson_95(20, 20).expect("n > 0"), (0.8389, 1.0)));
        assert_eq!(wilson_95(0, 0), None);
    }
}
