//! `strategies.csv`: how each participant moved objects in each condition,
//! from the `manners` column of the measured trials (practice left out, as
//! in the summary).
//!
//! One row per participant × task × technique × feedback × manner used:
//!
//! | column | meaning |
//! |---|---|
//! | `participant`, `task`, `technique`, `feedback` | the condition |
//! | `manner` | e.g. `fingertip_1`, `flat_hand`, `edge_sweep` |
//! | `time_s` | seconds spent in that manner over the condition's measured trials |
//! | `time_share` | `time_s` over the condition's time in all manners (0..=1) |
//! | `payoff` | net progress per second in that manner (m/s): the drop in the summed distance of open objects to their goals, less the re-grip and drop penalties, over `time_s` |
//!
//! Rows come in trial order of first use, so the file is deterministic.

use super::error::StudyError;
use super::output::TrialRow;
use crate::pipeline::technique::TechniqueKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// `strategies.csv` columns, in order.
pub const STRATEGY_COLUMNS: [&str; 8] =
    ["participant", "task", "technique", "feedback", "manner", "time_s", "time_share", "payoff"];

/// One line of `strategies.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StrategyRow {
    pub participant: u32,
    pub task: String,
    pub technique: TechniqueKind,
    pub feedback: bool,
    pub manner: String,
    pub time_s: f64,
    pub time_share: f64,
    pub payoff: f64,
}

/// One `name:time_s:net_m` item of a `manners` cell.
fn parse_item(item: &str) -> Option<(&str, f64, f64)> {
    let mut parts = item.split(':');
    let name = parts.next().filter(|n| !n.is_empty())?;
    let time = parts.next()?.parse().ok()?;
    let net = parts.next()?.parse().ok()?;
    parts.next().is_none().then_some((name, time, net))
}

/// The rows of `strategies.csv` from `trials.csv`'s rows; `path` names the
/// trials file in errors (a `manners` cell that does not parse).
pub fn strategies(rows: &[TrialRow], path: &Path) -> Result<Vec<StrategyRow>, StudyError> {
    type Key = (u32, String, TechniqueKind, bool);
    // Condition -> manner -> (first seen, time, net); conditions by first use.
    let mut order: Vec<Key> = Vec::new();
    let mut acc: BTreeMap<Key, Vec<(String, f64, f64)>> = BTreeMap::new();
    for row in rows.iter().filter(|r| !r.practice && !r.manners.is_empty()) {
        let key = (row.participant, row.task.clone(), row.technique, row.feedback);
        let entry = acc.entry(key.clone()).or_insert_with(|| {
            order.push(key);
            Vec::new()
        });
        for item in row.manners.split(';') {
            let (name, time, net) = parse_item(item).ok_or_else(|| {
                StudyError::mismatch(
                    path,
                    format!(
                        "row P{} #{}: manners item {item:?} is not name:time_s:net_m",
                        row.participant, row.order_index
                    ),
                )
            })?;
            match entry.iter_mut().find(|(n, _, _)| n == name) {
                Some(e) => {
                    e.1 += time;
                    e.2 += net;
                }
                None => entry.push((name.to_owned(), time, net)),
            }
        }
    }
    let mut out = Vec::new();
    for key in order {
        let manners = &acc[&key];
        let total: f64 = manners.iter().map(|m| m.1).sum();
        for (manner, time, net) in manners {
            out.push(StrategyRow {
                participant: key.0,
                task: key.1.clone(),
                technique: key.2,
                feedback: key.3,
                manner: manner.clone(),
                time_s: round(*time, 2),
                time_share: if total > 0.0 { round(time / total, 4) } else { 0.0 },
                payoff: if *time > 0.0 { round(net / time, 4) } else { 0.0 },
            });
        }
    }
    Ok(out)
}

fn round(x: f64, digits: i32) -> f64 {
    let k = 10f64.powi(digits);
    (x * k).round() / k
}

pub fn write_strategies(path: &Path, rows: &[StrategyRow]) -> Result<(), StudyError> {
    super::csv_rows::write_rows(path, Some(&STRATEGY_COLUMNS), rows)
}

pub fn read_strategies(path: &Path) -> Result<Vec<StrategyRow>, StudyError> {
    super::csv_rows::read_rows(path)
}
