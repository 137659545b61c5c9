//! The ablation of the participants' repertoire (`study --manners`): each
//! finding under the full repertoire and under each restriction, as the
//! share of seeds that reproduce it with its Wilson 95% interval.
//!
//! The layout: `DIR/<repertoire>/seed-<k>/` run folders and
//! `DIR/<repertoire>/findings.csv` (as `study --seeds`), then
//! `DIR/ablation.csv` and `DIR/ablation.md` over every repertoire.

use super::error::StudyError;
use super::findings::FINDINGS;
use super::output::write_atomically;
use super::seeds::FindingsRow;
use std::fmt::Write as _;
use std::path::Path;

pub const ABLATION_CSV: &str = "ablation.csv";
pub const ABLATION_MD: &str = "ablation.md";
/// `ablation.csv` columns.
pub const ABLATION_COLUMNS: [&str; 7] =
    ["repertoire", "finding", "seeds", "reproduced", "share", "wilson_low", "wilson_high"];

/// One repertoire's findings over its seeds.
#[derive(Debug, Clone, PartialEq)]
pub struct Arm {
    /// The repertoire's label: `full`, a preset, or manners joined by `+`.
    pub repertoire: String,
    pub findings: Vec<FindingsRow>,
}

/// Writes `ablation.csv` and `ablation.md` into `dir`.
pub fn write_ablation(dir: &Path, arms: &[Arm]) -> Result<(), StudyError> {
    let path = dir.join(ABLATION_CSV);
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    w.write_record(ABLATION_COLUMNS).map_err(StudyError::csv(&path))?;
    let cell = |v: Option<f64>| v.map_or_else(String::new, |v| format!("{v:.4}"));
    for arm in arms {
        for r in &arm.findings {
            w.write_record([
                arm.repertoire.clone(),
                r.finding.clone(),
                r.seeds.to_string(),
                r.reproduced.to_string(),
                cell(r.share),
                cell(r.wilson_low),
                cell(r.wilson_high),
            ])
            .map_err(StudyError::csv(&path))?;
        }
    }
    let bytes = w.into_inner().map_err(|e| StudyError::io(&path)(e.into_error()))?;
    write_atomically(&path, &bytes)?;
    write_atomically(&dir.join(ABLATION_MD), markdown(arms).as_bytes())
}

/// The table: a row per finding, a column per repertoire, each cell
/// `reproduced/seeds (share, 95% CI low–high)`.
pub fn markdown(arms: &[Arm]) -> String {
    let mut s = String::from("# Findings by repertoire\n\n");
    s.push_str(
        "Each cell: seeds that reproduce the finding / seeds that could test it, the share, and its Wilson 95% \
         interval. Every technique runs with the same repertoire in a column: a finding that holds with the full \
         repertoire and goes under a restriction depends on the manners the restriction removes.\n\n",
    );
    s.push_str("| finding |");
    for a in arms {
        let _ = write!(s, " {} |", a.repertoire);
    }
    s.push_str("\n|---|");
    for _ in arms {
        s.push_str("---|");
    }
    s.push('\n');
    for f in &FINDINGS {
        let _ = write!(s, "| {} |", f.claim);
        for a in arms {
            match a.findings.iter().find(|r| r.finding == f.id) {
                Some(r) if r.seeds > 0 => {
                    let _ = write!(
                        s,
                        " {}/{} ({:.0}%, {:.0}–{:.0}%) |",
                        r.reproduced,
                        r.seeds,
                        r.share.unwrap_or(0.0) * 100.0,
                        r.wilson_low.unwrap_or(0.0) * 100.0,
                        r.wilson_high.unwrap_or(0.0) * 100.0
                    );
                }
                _ => s.push_str(" not tested |"),
            }
        }
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_has_a_column_per_repertoire() {
        let row = |finding: &str, seeds, reproduced| {
            let w = super::super::seeds::wilson_95(reproduced, seeds);
            FindingsRow {
                finding: finding.into(),
                seeds,
                reproduced,
                share: (seeds > 0).then(|| f64::from(reproduced) / f64::from(seeds)),
                wilson_low: w.map(|w| w.0),
                wilson_high: w.map(|w| w.1),
            }
        };
        let arms = [
            Arm { repertoire: "full".into(), findings: vec![row("particle_faster_steering", 10, 5)] },
            Arm { repertoire: "single-finger".into(), findings: vec![row("particle_faster_steering", 10, 0)] },
        ];
        let md = markdown(&arms);
        assert!(md.contains("| finding | full | single-finger |"), "{md}");
        assert!(
            md.contains("| Particle is faster than Proxy for steering | 5/10 (50%, 24–76%) | 0/10 (0%, 0–28%) |"),
            "{md}"
        );
        assert!(md.contains("| Joint is fastest for positioning | not tested | not tested |"), "{md}");
    }
}
