//! The behaviour × technique table: verdicts and markdown.

use super::case::{Case, Check, Expectation, Metric};
use super::gaps::known_gap;
use super::measure::Measurement;
use crate::pipeline::technique::TechniqueKind;
use std::fmt::Write as _;

/// How a measured value stands against the expectation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellVerdict {
    /// Meets the check where the manipulation should work.
    Pass,
    /// Misses it.
    Fail,
    /// Meets the paper's stated limit of this technique.
    LimitHolds,
    /// Misses the check of the paper's stated limit.
    LimitBroken,
    /// Misses it, as listed in [`super::GAPS`].
    KnownGap,
    /// Not asserted.
    Shown,
}

impl CellVerdict {
    pub fn is_failure(self) -> bool {
        matches!(self, CellVerdict::Fail | CellVerdict::LimitBroken)
    }

    fn mark(self) -> &'static str {
        match self {
            CellVerdict::Pass => "ok",
            CellVerdict::Fail => "**FAIL**",
            CellVerdict::LimitHolds => "limit ok",
            CellVerdict::LimitBroken => "**FAIL** (limit)",
            CellVerdict::KnownGap => "**FAIL** (known gap)",
            CellVerdict::Shown => "shown",
        }
    }
}

/// One measured value of one case under one technique.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    pub case: &'static str,
    pub technique: TechniqueKind,
    pub metric: Metric,
    pub value: f32,
    /// The check applied to it, if any.
    pub check: Option<Check>,
    pub verdict: CellVerdict,
}

/// The cells of one outcome: one per metric the case shows.
pub fn cells(case: &Case, outcome: &Measurement) -> Vec<Cell> {
    let kind = outcome.technique;
    let expectation = case.expectation(kind);
    let applied = case.checks_for(kind);
    case.metrics()
        .into_iter()
        .map(|metric| {
            let value = outcome.get(metric);
            let check = applied.iter().find(|c| c.metric == metric).copied();
            let verdict = match (&expectation, check) {
                (_, None) | (Expectation::Shown { .. }, _) => CellVerdict::Shown,
                (Expectation::Works, Some(c)) if c.holds(value) && outcome.nan_count == 0 => CellVerdict::Pass,
                (Expectation::Works, Some(_)) => CellVerdict::Fail,
                (Expectation::Limit { .. }, Some(c)) if c.holds(value) => CellVerdict::LimitHolds,
                (Expectation::Limit { .. }, Some(_)) => CellVerdict::LimitBroken,
            };
            let verdict = match verdict {
                CellVerdict::Fail | CellVerdict::LimitBroken if known_gap(case.name, kind, metric).is_some() => {
                    CellVerdict::KnownGap
                }
                v => v,
            };
            Cell { case: case.name, technique: kind, metric, value, check, verdict }
        })
        .collect()
}

fn format_value(metric: Metric, value: f32) -> String {
    if value.is_nan() {
        return "n/a".to_string();
    }
    let v = value * metric.scale();
    match metric {
        Metric::Carry | Metric::Veer | Metric::Gathered | Metric::EndSpeed | Metric::Bounce => format!("{v:.2}"),
        _ => format!("{v:.1}"),
    }
}

/// The markdown table: one row per case and metric, one column per
/// technique, each cell the measured value and its verdict; then the
/// paper's limits quoted.
pub fn markdown(cases: &[Case], kinds: &[TechniqueKind], outcomes: &[Measurement]) -> String {
    let mut s = String::new();
    let _ = write!(s, "| behaviour | measure | works when |");
    for k in kinds {
        let _ = write!(s, " {k} |");
    }
    s.push('\n');
    s.push_str("|---|---|---|");
    for _ in kinds {
        s.push_str("---|");
    }
    s.push('\n');
    let mut limits: Vec<String> = Vec::new();
    for case in cases {
        for metric in case.metrics() {
            let works = case.checks.iter().find(|c| c.metric == metric).map_or("—".to_string(), ToString::to_string);
            let _ = write!(s, "| {} | {} | {} |", case.name, metric.label(), works);
            for k in kinds {
                let cell = outcomes
                    .iter()
                    .find(|o| o.case == case.name && o.technique == *k)
                    .and_then(|o| cells(case, o).into_iter().find(|c| c.metric == metric));
                match cell {
                    Some(c) => {
                        let bound = match (c.verdict, c.check) {
                            (CellVerdict::LimitHolds | CellVerdict::LimitBroken, Some(ch)) => format!(" ({ch})"),
                            _ => String::new(),
                        };
                        let _ = write!(s, " {} {}{} |", format_value(metric, c.value), c.verdict.mark(), bound);
                    }
                    None => s.push_str(" — |"),
                }
            }
            s.push('\n');
        }
        for (technique, e) in &case.others {
            if !kinds.iter().any(|k| k.name() == *technique) {
                continue;
            }
            match e {
                Expectation::Limit { quote, .. } => limits.push(format!("- {} / {technique}: \"{quote}\"", case.name)),
                Expectation::Shown { why } => {
                    limits.push(format!("- {} / {technique}: not asserted: {why}", case.name));
                }
                Expectation::Works => {}
            }
        }
        // Limits a registered technique declares for itself.
        for k in kinds {
            if let Some(why) = k.declared_limit(case.name)
                && !case.others.iter().any(|(n, _)| *n == k.name())
            {
                limits.push(format!("- {} / {k}: not asserted: {why}", case.name));
            }
        }
    }
    if !limits.is_empty() {
        s.push_str("\nThe paper's limits, asserted instead (\"limit ok\": the limit holds), and cells only shown:\n\n");
        for l in limits {
            s.push_str(&l);
            s.push('\n');
        }
    }
    s
}
