//! The paper's findings, one table shared by the run report (`report.md`)
//! and the many-seeds summary (`findings.csv`), and the rule that decides
//! whether a run reproduces each.
//!
//! The paper states its findings qualitatively (Wilson et al. 2008, "User
//! study"); each is turned here into one test at α = .05 on the run's
//! statistics (`analysis`):
//! - "A faster than B": the Holm-corrected pairwise test of `pairwise.csv`
//!   is significant and the mean difference A − B is negative — for every
//!   pair the finding names;
//! - "feedback matters little for T": the paired t-test of T's feedback-off
//!   against feedback-on cell values is *not* significant (p ≥ .05; with 6
//!   participants that is weak evidence, and the report says the p-value);
//! - "feedback matters more for T than for U": the paired t-test of each
//!   participant's feedback benefit (off − on) of T minus that of U is
//!   significant and positive (an interaction contrast).
//!
//! A finding whose task, techniques or feedback levels the design lacks is
//! *not tested*, not "not reproduced".

use super::analysis::Analysis;
use super::pairwise::{PairedTest, one_sample_t, paired_t};
use crate::pipeline::technique::TechniqueKind;

/// The significance level of every decision.
pub const ALPHA: f64 = 0.05;

/// How a finding is decided.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// Every technique in `faster` is faster than every one in `than`.
    Faster { faster: &'static [TechniqueKind], than: &'static [TechniqueKind] },
    /// Feedback on vs off makes no significant difference for `technique`.
    FeedbackSmall { technique: TechniqueKind },
    /// Feedback's benefit (off − on) is larger for `more` than for `less`.
    FeedbackLarger { more: TechniqueKind, less: TechniqueKind },
}

/// One of the paper's findings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finding {
    /// The name in `findings.csv`.
    pub id: &'static str,
    /// The paper's claim, in words.
    pub claim: &'static str,
    pub task: &'static str,
    pub rule: Rule,
}

const JOINT: TechniqueKind = TechniqueKind::JOINT;
const PROXY: TechniqueKind = TechniqueKind::PROXY;
const PARTICLE: TechniqueKind = TechniqueKind::PARTICLE;

/// The paper's findings, in the paper's order.
pub const FINDINGS: [Finding; 5] = [
    Finding {
        id: "joint_fastest_positioning",
        claim: "Joint is fastest for positioning",
        task: "positioning",
        rule: Rule::Faster { faster: &[JOINT], than: &[PROXY, PARTICLE] },
    },
    Finding {
        id: "feedback_little_for_joint",
        claim: "feedback matters little for Joint (positioning)",
        task: "positioning",
        rule: Rule::FeedbackSmall { technique: JOINT },
    },
    Finding {
        id: "feedback_more_for_particle",
        claim: "feedback matters more for Particle than for Joint in positioning",
        task: "positioning",
        rule: Rule::FeedbackLarger { more: PARTICLE, less: JOINT },
    },
    Finding {
        id: "proxy_particle_faster_sorting",
        claim: "Proxy and Particle are faster than Joint for sorting",
        task: "sorting",
        rule: Rule::Faster { faster: &[PROXY, PARTICLE], than: &[JOINT] },
    },
    Finding {
        id: "particle_faster_steering",
        claim: "Particle is faster than Proxy for steering",
        task: "steering",
        rule: Rule::Faster { faster: &[PARTICLE], than: &[PROXY] },
    },
];

/// What a run says about a finding.
#[derive(Debug, Clone, PartialEq)]
pub enum FindingVerdict {
    Reproduced,
    NotReproduced,
    /// The design or the data cannot test it; why.
    NotTested(String),
}

impl FindingVerdict {
    pub fn label(&self) -> &'static str {
        match self {
            FindingVerdict::Reproduced => "reproduced",
            FindingVerdict::NotReproduced => "not reproduced",
            FindingVerdict::NotTested(_) => "not tested",
        }
    }
}

/// A verdict and the numbers behind it.
#[derive(Debug, Clone, PartialEq)]
pub struct Judgement {
    pub verdict: FindingVerdict,
    /// Which test decided, in words.
    pub test: String,
    /// The test's numbers (mean differences, p-values).
    pub evidence: String,
}

impl Finding {
    /// Decides this finding on a run's statistics.
    pub fn judge(&self, analysis: &Analysis) -> Judgement {
        let not_tested = |test: String, why: String| Judgement {
            verdict: FindingVerdict::NotTested(why.clone()),
            test,
            evidence: why,
        };
        let Some(cells) = analysis.task(self.task) else {
            return not_tested(self.test(), format!("the design has no {} task", self.task));
        };
        match self.rule {
            Rule::Faster { faster, than } => {
                let mut all = true;
                let mut evidence = Vec::new();
                for &a in faster {
                    for &b in than {
                        let Some((diff, row)) = analysis.pair(self.task, a, b) else {
                            let missing: Vec<&str> = [a, b]
                                .into_iter()
                                .filter(|&t| cells.technique_index(t).is_none())
                                .map(TechniqueKind::name)
                                .collect();
                            let why = if missing.is_empty() {
                                format!("no paired test of {a} and {b}")
                            } else {
                                format!("the design lacks {}", missing.join(" and "))
                            };
                            return not_tested(self.test(), why);
                        };
                        let (Some(diff), Some(p)) = (diff, row.p_holm) else {
                            return not_tested(self.test(), format!("{a} vs {b}: too few complete participants"));
                        };
                        all &= p < ALPHA && diff < 0.0;
                        evidence.push(format!(
                            "{} − {} = {diff:+.1} s, p_holm {}",
                            a.label(),
                            b.label(),
                            p_relation(p)
                        ));
                    }
                }
                decided(all, self.test(), evidence.join("; "))
            }
            Rule::FeedbackSmall { technique } => match feedback_effect(cells, technique) {
                Err(why) => not_tested(self.test(), why),
                Ok(test) => match test.p {
                    None => not_tested(self.test(), "no variance in the feedback effect".into()),
                    Some(p) => decided(
                        p >= ALPHA,
                        self.test(),
                        format!("{} off − on = {:+.1} s, p {}", technique.label(), test.mean_diff, p_relation(p)),
                    ),
                },
            },
            Rule::FeedbackLarger { more, less } => {
                let (a, b) = match (feedback_benefits(cells, more), feedback_benefits(cells, less)) {
                    (Ok(a), Ok(b)) => (a, b),
                    (Err(why), _) | (_, Err(why)) => return not_tested(self.test(), why),
                };
                let diffs: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x - y).collect();
                let test = one_sample_t(&diffs);
                match test.p {
                    None => not_tested(self.test(), "too few complete participants, or no variance".into()),
                    Some(p) => decided(
                        p < ALPHA && test.mean_diff > 0.0,
                        self.test(),
                        format!(
                            "benefit of feedback (off − on): {} {:+.1} s, {} {:+.1} s; difference {:+.1} s, p {}",
                            more.label(),
                            mean(&a),
                            less.label(),
                            mean(&b),
                            test.mean_diff,
                            p_relation(p)
                        ),
                    ),
                }
            }
        }
    }

    /// The deciding test, in words.
    pub fn test(&self) -> String {
        let names = |ts: &[TechniqueKind]| ts.iter().map(|t| t.label()).collect::<Vec<_>>().join(", ");
        match self.rule {
            Rule::Faster { faster, than } => format!(
                "{}: Holm-corrected pairwise t-test (pairwise.csv) of {} against {}, p_holm < {ALPHA} and the mean difference negative for every pair",
                self.task,
                names(faster),
                names(than)
            ),
            Rule::FeedbackSmall { technique } => format!(
                "{}: paired t-test of {} feedback off against on; reproduced when not significant (p ≥ {ALPHA})",
                self.task,
                technique.label()
            ),
            Rule::FeedbackLarger { more, less } => format!(
                "{}: paired t-test of each participant's feedback benefit (off − on) for {} minus that for {}, p < {ALPHA} and positive",
                self.task,
                more.label(),
                less.label()
            ),
        }
    }
}

fn decided(yes: bool, test: String, evidence: String) -> Judgement {
    Judgement { verdict: if yes { FindingVerdict::Reproduced } else { FindingVerdict::NotReproduced }, test, evidence }
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// A p-value after its name in a sentence: "= 0.034" or "< .001".
fn p_relation(p: f64) -> String {
    if p < 0.001 { "< .001".into() } else { format!("= {p:.3}") }
}

/// A p-value for a table cell: three decimals, or "< .001".
pub fn fmt_p(p: f64) -> String {
    if p < 0.001 { "< .001".into() } else { format!("{p:.3}") }
}

/// Per complete participant: the technique's feedback-off minus feedback-on value.
fn feedback_benefits(cells: &super::cells::TaskCells, technique: TechniqueKind) -> Result<Vec<f64>, String> {
    let t = cells.technique_index(technique).ok_or_else(|| format!("the design lacks {technique}"))?;
    let (Some(on), Some(off)) = (cells.feedback_index(true), cells.feedback_index(false)) else {
        return Err("the design lacks a feedback level".into());
    };
    Ok(cells.column(t, off).iter().zip(cells.column(t, on)).map(|(off, on)| off - on).collect())
}

fn feedback_effect(cells: &super::cells::TaskCells, technique: TechniqueKind) -> Result<PairedTest, String> {
    let t = cells.technique_index(technique).ok_or_else(|| format!("the design lacks {technique}"))?;
    let (Some(on), Some(off)) = (cells.feedback_index(true), cells.feedback_index(false)) else {
        return Err("the design lacks a feedback level".into());
    };
    paired_t(&cells.column(t, off), &cells.column(t, on)).ok_or_else(|| "no complete participants".into())
}
