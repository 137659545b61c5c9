//! Why a finding is not reproduced: the strategies and what each paid.
//!
//! The paper explains its results by what the techniques invited people to
//! do: Joint "led users to predominately interact with a single finger",
//! while particles invited whole-hand manipulation. A simulated study that
//! disagrees with the paper can disagree in two ways, and this module tells
//! them apart from `strategies.csv`:
//!
//! - the *strategies*: the share of time the participants spent in each
//!   manner under each technique;
//! - the *physics*: what each manner paid under each technique, as net
//!   progress towards the goal per second of use (m/s; penalties for
//!   re-grips and drops included, see `participant::learner`).
//!
//! A technique's overall rate is its shares times its payoffs. Swapping the
//! shares of two techniques (one technique's physics with the other's mix of
//! manners) says how much of the difference the strategies make; the
//! manners whose payoff orders against the finding say where the physics
//! does.

use super::findings::{Finding, Rule};
use super::strategies::StrategyRow;
use crate::pipeline::technique::TechniqueKind;
use std::collections::BTreeMap;

/// Shares below this are left out of the orderings (too little use to read).
const MIN_SHARE: f64 = 0.05;

/// One condition's manners: time share and payoff (net m per second).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MannerMix {
    /// manner → (time s, net m), over participants (and feedback levels
    /// where pooled).
    pub by_manner: BTreeMap<String, (f64, f64)>,
}

impl MannerMix {
    fn total_time(&self) -> f64 {
        self.by_manner.values().map(|(t, _)| t).sum()
    }

    /// The share of time spent in `manner`.
    pub fn share(&self, manner: &str) -> f64 {
        let total = self.total_time();
        if total > 0.0 { self.by_manner.get(manner).map_or(0.0, |(t, _)| t / total) } else { 0.0 }
    }

    /// Net progress per second of use of `manner` (m/s), if it was used.
    pub fn payoff(&self, manner: &str) -> Option<f64> {
        self.by_manner.get(manner).filter(|(t, _)| *t > 0.0).map(|(t, n)| n / t)
    }

    /// The overall rate: net progress per second over every manner (m/s).
    pub fn rate(&self) -> Option<f64> {
        let total = self.total_time();
        (total > 0.0).then(|| self.by_manner.values().map(|(_, n)| n).sum::<f64>() / total)
    }

    /// The rate this condition's payoffs would give with `other`'s shares;
    /// manners `other` used that this one never did count at their payoff
    /// under `other` (nothing better is known).
    pub fn rate_with_shares_of(&self, other: &MannerMix) -> Option<f64> {
        let total = other.total_time();
        (total > 0.0).then(|| {
            other
                .by_manner
                .iter()
                .map(|(m, (t, n))| t / total * self.payoff(m).unwrap_or(if *t > 0.0 { n / t } else { 0.0 }))
                .sum()
        })
    }
}

/// The mix of one task's technique (feedback `Some(on)` or both pooled).
pub fn mix(rows: &[StrategyRow], task: &str, technique: TechniqueKind, feedback: Option<bool>) -> MannerMix {
    let mut out = MannerMix::default();
    for r in
        rows.iter().filter(|r| r.task == task && r.technique == technique && feedback.is_none_or(|f| r.feedback == f))
    {
        let e = out.by_manner.entry(r.manner.clone()).or_default();
        e.0 += r.time_s;
        e.1 += r.payoff * r.time_s;
    }
    out
}

/// A manner and, per condition, its share of the time and its payoff (m/s).
pub type MannerRow = (String, Vec<(f64, Option<f64>)>);

/// What the explanation of one finding says.
#[derive(Debug, Clone, PartialEq)]
pub struct Explanation {
    /// Column heads after "manner": one per technique (and feedback level).
    pub conditions: Vec<String>,
    /// Per manner: its name, then per condition (share, payoff).
    pub rows: Vec<MannerRow>,
    /// Overall rate per condition (m/s).
    pub rates: Vec<Option<f64>>,
    /// Sentences: the swap of strategies and the manners ordered against the finding.
    pub notes: Vec<String>,
}

/// Explains `finding` from the strategy rows; `None` when the rows hold
/// none of its conditions.
pub fn explain(finding: &Finding, rows: &[StrategyRow]) -> Option<Explanation> {
    let task = finding.task;
    let conditions: Vec<(String, MannerMix)> = match finding.rule {
        Rule::Faster { faster, than } => {
            faster.iter().chain(than).map(|&t| (t.label().to_owned(), mix(rows, task, t, None))).collect()
        }
        Rule::FeedbackSmall { technique } => [true, false]
            .map(|on| {
                (
                    format!("{} feedback {}", technique.label(), if on { "on" } else { "off" }),
                    mix(rows, task, technique, Some(on)),
                )
            })
            .to_vec(),
        Rule::FeedbackLarger { more, less } => [more, less]
            .into_iter()
            .flat_map(|t| {
                [true, false].map(|on| {
                    (format!("{} {}", t.label(), if on { "on" } else { "off" }), mix(rows, task, t, Some(on)))
                })
            })
            .collect(),
    };
    if conditions.iter().all(|(_, m)| m.by_manner.is_empty()) {
        return None;
    }
    let mut manners: Vec<String> = conditions.iter().flat_map(|(_, m)| m.by_manner.keys().cloned()).collect();
    manners.sort();
    manners.dedup();
    let rows_out = manners
        .iter()
        .map(|m| (m.clone(), conditions.iter().map(|(_, c)| (c.share(m), c.payoff(m))).collect()))
        .collect();
    let mut notes = Vec::new();
    if let Rule::Faster { faster, than } = finding.rule {
        // The conditions are `faster` then `than`, in order.
        let (fast, slow) = conditions.split_at(faster.len());
        for (&a, (_, ma)) in faster.iter().zip(fast) {
            for (&b, (_, mb)) in than.iter().zip(slow) {
                notes.extend(compare(a, ma, b, mb));
            }
        }
    }
    Some(Explanation {
        conditions: conditions.iter().map(|(n, _)| n.clone()).collect(),
        rows: rows_out,
        rates: conditions.iter().map(|(_, m)| m.rate()).collect(),
        notes,
    })
}

/// The paper's account of "`a` is faster than `b`" read against the mixes.
fn compare(a: TechniqueKind, ma: &MannerMix, b: TechniqueKind, mb: &MannerMix) -> Vec<String> {
    let (Some(ra), Some(rb)) = (ma.rate(), mb.rate()) else { return Vec::new() };
    let mut out = Vec::new();
    let (la, lb) = (a.label(), b.label());
    let swapped = ma.rate_with_shares_of(mb);
    out.push(format!(
        "{la} makes {ra:.4} m/s of net progress, {lb} {rb:.4} m/s; with {lb}'s mix of manners {la} would make {}: \
         the strategies account for {} of the difference.",
        swapped.map_or_else(|| "-".to_owned(), |s| format!("{s:.4} m/s")),
        swapped.map_or_else(
            || "-".to_owned(),
            |s| if (ra - rb).abs() > 1e-9 {
                format!("{:.0}%", (ra - s) / (ra - rb) * 100.0)
            } else {
                "none".to_owned()
            }
        ),
    ));
    let against: Vec<String> = ma
        .by_manner
        .keys()
        .chain(mb.by_manner.keys())
        .filter(|m| ma.share(m).max(mb.share(m)) >= MIN_SHARE)
        .filter_map(|m| match (ma.payoff(m), mb.payoff(m)) {
            (Some(pa), Some(pb)) if pb > pa => Some(format!("{m} ({la} {pa:.4}, {lb} {pb:.4} m/s)")),
            _ => None,
        })
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    out.push(if against.is_empty() {
        format!("Every manner used at least {:.0}% of the time pays at least as much under {la} as under {lb}, as the paper's account has it.", MIN_SHARE * 100.0)
    } else {
        format!("Manners that pay more under {lb} than under {la}, against the paper's account: {}.", against.join("; "))
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(technique: TechniqueKind, manner: &str, time_s: f64, payoff: f64) -> StrategyRow {
        StrategyRow {
            participant: 1,
            task: "sorting".into(),
            technique,
            feedback: true,
            manner: manner.into(),
            time_s,
            time_share: 0.0,
            payoff,
        }
    }

    #[test]
    fn the_swap_splits_a_difference_into_strategies_and_physics() {
        // Particle: 30 s of sweeps at 0.02 m/s and 10 s of drags at 0.01;
        // Joint: 40 s of drags at 0.012 m/s. By hand: Particle's rate is
        // (0.6 + 0.1) / 40 = 0.0175, Joint's 0.012; Particle with Joint's
        // mix (all drags) would make 0.01, so the strategies account for
        // (0.0175 - 0.01) / (0.0175 - 0.012) = 136% of the difference, and
        // drags pay more under Joint.
        let (p, j) = (TechniqueKind::PARTICLE, TechniqueKind::JOINT);
        let rows =
            [row(p, "edge_sweep", 30.0, 0.02), row(p, "fingertip_1", 10.0, 0.01), row(j, "fingertip_1", 40.0, 0.012)];
        let (mp, mj) = (mix(&rows, "sorting", p, None), mix(&rows, "sorting", j, None));
        assert!((mp.rate().expect("rate") - 0.0175).abs() < 1e-12);
        assert!((mp.rate_with_shares_of(&mj).expect("rate") - 0.01).abs() < 1e-12);
        assert!((mp.share("edge_sweep") - 0.75).abs() < 1e-12);
        let notes = compare(p, &mp, j, &mj);
        assert!(notes[0].contains("account for 136% of the difference"), "{notes:?}");
        assert!(notes[1].contains("fingertip_1 (Particle 0.0100, Joint 0.0120 m/s)"), "{notes:?}");
    }
}
