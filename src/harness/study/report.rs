//! `report.md` and `report.html`: a run explained in one page — the design
//! table, the figure, the descriptive table, the ANOVA and pairwise tables,
//! the strategies the participants used, and the paper's findings one by
//! one with the test that decides each (`findings`).
//!
//! Both files come from one list of blocks, so they say the same. The HTML
//! embeds the figure as a base64 PNG and so stands alone; the Markdown links
//! `figure.png` beside it.

use super::analysis::Analysis;
use super::design::StudyDesign;
use super::error::StudyError;
use super::explain::explain;
use super::findings::{FINDINGS, FindingVerdict, fmt_p};
use super::output::{FIGURE_PNG, STRATEGIES_CSV, TRIALS_CSV, write_atomically};
use super::strategies::{StrategyRow, read_strategies};
use super::summary::SummaryRow;
use crate::pipeline::technique::TechniqueKind;
use base64::Engine;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

pub const REPORT_MD: &str = "report.md";
pub const REPORT_HTML: &str = "report.html";

/// A piece of the report.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    Heading(String),
    Paragraph(String),
    Table {
        head: Vec<String>,
        rows: Vec<Vec<String>>,
    },
    /// An image file in the run folder.
    Figure {
        file: String,
        alt: String,
    },
}

/// Measured trials per technique (name as in `trials.csv`) and manner.
pub type StrategyCounts = BTreeMap<String, BTreeMap<String, usize>>;

/// Strategy shares per technique from `trials.csv`'s `strategy` column:
/// technique → manner → measured trials. `None` when the column is absent
/// or empty in every measured row (replays and the demo record none).
pub fn strategy_counts(trials_csv: &Path) -> Result<Option<StrategyCounts>, StudyError> {
    let mut reader = csv::Reader::from_path(trials_csv).map_err(StudyError::csv(trials_csv))?;
    let headers = reader.headers().map_err(StudyError::csv(trials_csv))?.clone();
    let column = |name: &str| headers.iter().position(|h| h == name);
    let (Some(strategy), Some(technique), Some(practice)) =
        (column("strategy"), column("technique"), column("practice"))
    else {
        return Ok(None);
    };
    let mut out = StrategyCounts::new();
    for record in reader.records() {
        let record = record.map_err(StudyError::csv(trials_csv))?;
        if record.get(practice) == Some("true") {
            continue;
        }
        let (Some(t), Some(s)) = (record.get(technique), record.get(strategy)) else { continue };
        // Replayed and demo trials record no strategy.
        if !s.is_empty() {
            *out.entry(t.to_owned()).or_default().entry(s.to_owned()).or_default() += 1;
        }
    }
    Ok((!out.is_empty()).then_some(out))
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(String::new, |v| format!("{v:.digits$}"))
}

fn on_off(on: bool) -> &'static str {
    if on { "on" } else { "off" }
}

/// The report's blocks.
pub fn report_blocks(
    design: &StudyDesign,
    summary: &[SummaryRow],
    analysis: &Analysis,
    strategies: Option<&StrategyCounts>,
    strategy_rows: &[StrategyRow],
) -> Vec<Block> {
    let mut b = vec![Block::Heading(s("Study report"))];
    design_blocks(&mut b, design);
    time_blocks(&mut b, summary);
    anova_blocks(&mut b, analysis);
    pairwise_blocks(&mut b, analysis);
    strategy_blocks(&mut b, strategies);
    finding_blocks(&mut b, analysis);
    explanation_blocks(&mut b, analysis, strategy_rows);
    b
}

/// A section per finding this run does not reproduce: the strategies and
/// what each manner paid under each condition (`explain`).
fn explanation_blocks(b: &mut Vec<Block>, analysis: &Analysis, rows: &[StrategyRow]) {
    for f in FINDINGS.iter().filter(|f| f.judge(analysis).verdict == FindingVerdict::NotReproduced) {
        let Some(e) = explain(f, rows) else { continue };
        b.push(Block::Heading(format!("Why not reproduced: {}", f.claim)));
        b.push(Block::Paragraph(format!(
            "{} task, measured trials (strategies.csv). Per manner: the share of the time spent in it, and its \
             payoff, net progress towards the goal per second of use (m/s, re-grips and drops deducted).",
            f.task
        )));
        let mut head = vec![s("manner")];
        for c in &e.conditions {
            head.push(format!("{c}: share"));
            head.push(format!("{c}: m/s"));
        }
        let mut table: Vec<Vec<String>> = e
            .rows
            .iter()
            .map(|(m, cells)| {
                let mut row = vec![m.clone()];
                for (share, pay) in cells {
                    row.push(format!("{:.0}%", share * 100.0));
                    row.push(opt(*pay, 4));
                }
                row
            })
            .collect();
        let mut all = vec![s("all manners")];
        for r in &e.rates {
            all.push(s("100%"));
            all.push(opt(*r, 4));
        }
        table.push(all);
        b.push(Block::Table { head, rows: table });
        for note in &e.notes {
            b.push(Block::Paragraph(note.clone()));
        }
    }
}

impl Block {
    /// A table with a row per item, `cells` giving its columns: as many as
    /// `head` has, by their type.
    fn table<T, const N: usize>(
        head: [&str; N],
        items: impl IntoIterator<Item = T>,
        cells: impl FnMut(T) -> [String; N],
    ) -> Block {
        Block::Table { head: head.map(s).to_vec(), rows: items.into_iter().map(cells).map(Vec::from).collect() }
    }
}

/// Owned text: the blocks hold `String`s.
fn s(x: &str) -> String {
    x.to_owned()
}

/// What was run, and the design's balance and plan.
fn design_blocks(b: &mut Vec<Block>, design: &StudyDesign) {
    let techniques: Vec<&str> = design.techniques.iter().map(|t| t.label()).collect();
    b.push(Block::Paragraph(format!(
        "{} participants × tasks {} (fixed order) × techniques {} × feedback {}; measured repetitions per condition: {}{}; seed {}{}.",
        design.participants,
        design.tasks.join(", "),
        techniques.join(", "),
        design.feedback.iter().map(|&f| on_off(f)).collect::<Vec<_>>().join("/"),
        design.repetitions,
        if design.practice { " after one practice trial" } else { "" },
        design.seed,
        design.time_limit_override.map_or_else(String::new, |l| format!("; time limit {l} s"))
    )));
    if let Some(manners) = &design.settings.manners {
        b.push(Block::Paragraph(format!(
            "The scripted participants' repertoire is restricted to `{manners}` (study --manners), under every technique."
        )));
    }

    b.push(Block::Heading(s("Design")));
    b.push(Block::Paragraph(match design.balance_note() {
        None => s(
            "Balanced: within each feedback-order group every technique is in every position equally often, and every Williams row is used equally often.",
        ),
        Some(note) => format!("Not fully balanced: {note}."),
    }));
    b.push(Block::table(["participant", "feedback order", "technique order"], &design.plan(), |p| {
        [
            format!("P{}", p.participant),
            p.feedback_order.iter().map(|&f| on_off(f)).collect::<Vec<_>>().join(", "),
            p.technique_order.iter().map(|t| t.label()).collect::<Vec<_>>().join(", "),
        ]
    }));
}

/// The completion-time figure and its table.
fn time_blocks(b: &mut Vec<Block>, summary: &[SummaryRow]) {
    b.push(Block::Heading(s("Completion time")));
    b.push(Block::Figure { file: FIGURE_PNG.to_owned(), alt: s("Completion time per task, technique and feedback") });
    b.push(Block::Paragraph(s(
        "Mean over participants of each participant's mean of the measured repetitions. Whiskers: within-subject 95% CI (Cousineau–Morey). Failed trials (time limit reached, or the runner failed) are counted in red on the bars; a timed-out trial enters at the time limit, so a mean with failures is a lower bound.",
    )));
    b.push(Block::table(
        ["task", "technique", "feedback", "mean s", "within 95% CI", "completed", "failed"],
        summary,
        |r| {
            [
                r.task.clone(),
                r.technique.label().to_owned(),
                on_off(r.feedback).to_owned(),
                opt(r.mean_s, 1),
                match (r.ci95_within_low_s, r.ci95_within_high_s) {
                    (Some(lo), Some(hi)) => format!("{lo:.1}–{hi:.1}"),
                    _ => String::new(),
                },
                format!("{}/{}", r.completed, r.trials),
                r.failed.to_string(),
            ]
        },
    ));
}

/// The RM-ANOVA table, naming participants left out.
fn anova_blocks(b: &mut Vec<Block>, analysis: &Analysis) {
    b.push(Block::Heading(s("Repeated-measures ANOVA (anova.csv)")));
    let dropped: Vec<String> = analysis
        .cells
        .iter()
        .filter(|c| !c.incomplete.is_empty())
        .map(|c| format!("{}: P{}", c.task, c.incomplete.iter().map(u32::to_string).collect::<Vec<_>>().join(", P")))
        .collect();
    b.push(Block::Paragraph(format!(
        "Per task, technique × feedback within subjects; cell value = a participant's mean of the measured repetitions (timed-out trials at the time limit). Greenhouse–Geisser ε̂ and corrected p; partial η². {}",
        if dropped.is_empty() {
            s("Every participant has every cell.")
        } else {
            format!("Left out for a missing cell (runner failures): {}.", dropped.join("; "))
        }
    )));
    b.push(Block::table(["task", "effect", "df", "F", "p", "ε̂ (GG)", "p (GG)", "η²p"], &analysis.anova, |r| {
        [
            r.task.clone(),
            r.effect.clone(),
            format!("{}, {}", r.df1, r.df2),
            opt(r.f, 2),
            r.p.map_or_else(String::new, fmt_p),
            opt(r.epsilon_gg, 3),
            r.p_gg.map_or_else(String::new, fmt_p),
            opt(r.eta_p2, 3),
        ]
    }));
}

/// Holm-corrected pairwise comparisons of techniques.
fn pairwise_blocks(b: &mut Vec<Block>, analysis: &Analysis) {
    b.push(Block::Heading(s("Pairwise comparisons (pairwise.csv)")));
    b.push(Block::Paragraph(s(
        "Paired t-tests between techniques on each participant's mean over feedback levels, Holm-corrected over the technique pairs of a task; mean difference a − b (negative: a faster); Cohen's dz.",
    )));
    b.push(Block::table(["task", "a", "b", "a − b (s)", "t", "df", "p (Holm)", "dz"], &analysis.pairwise, |r| {
        [
            r.task.clone(),
            r.a.label().to_owned(),
            r.b.label().to_owned(),
            opt(r.mean_diff_s, 1),
            opt(r.t, 2),
            r.df.to_string(),
            r.p_holm.map_or_else(String::new, fmt_p),
            opt(r.dz, 2),
        ]
    }));
}

/// Which manners participants used, per technique.
fn strategy_blocks(b: &mut Vec<Block>, strategies: Option<&StrategyCounts>) {
    b.push(Block::Heading(s("Strategies")));
    match strategies {
        None => b.push(Block::Paragraph(s(
            "Strategy shares: not recorded (no measured trial in trials.csv names a strategy).",
        ))),
        Some(counts) => {
            b.push(Block::Paragraph(s(
                "Share of measured trials per technique by the manner used for the most time (trials.csv `strategy`).",
            )));
            let mut rows = Vec::new();
            for (technique, manners) in counts {
                let total: usize = manners.values().sum();
                let label = technique.parse::<TechniqueKind>().map_or(technique.as_str(), |t| t.label());
                for (manner, n) in manners {
                    rows.push(vec![
                        label.to_owned(),
                        manner.clone(),
                        n.to_string(),
                        format!("{:.0}%", 100.0 * *n as f64 / total.max(1) as f64),
                    ]);
                }
            }
            b.push(Block::Table { head: ["technique", "strategy", "trials", "share"].map(s).to_vec(), rows });
        }
    }
}

/// Each of the paper's findings judged on this run.
fn finding_blocks(b: &mut Vec<Block>, analysis: &Analysis) {
    b.push(Block::Heading(s("The paper's findings")));
    b.push(Block::Paragraph(s(
        "Each finding of Wilson et al. (2008) as one test at α = .05 on this run's statistics.",
    )));
    b.push(Block::table(["finding", "this run", "decided by", "numbers"], &FINDINGS, |f| {
        let j = f.judge(analysis);
        [f.claim.to_owned(), j.verdict.label().to_owned(), j.test, j.evidence]
    }));
}

/// The blocks as Markdown.
pub fn to_markdown(blocks: &[Block]) -> String {
    let cell = |s: &str| s.replace('|', "\\|").replace('\n', " ");
    let mut out = String::new();
    for block in blocks {
        match block {
            Block::Heading(h) if out.is_empty() => {
                let _ = writeln!(out, "# {h}\n");
            }
            Block::Heading(h) => {
                let _ = writeln!(out, "## {h}\n");
            }
            Block::Paragraph(p) => {
                let _ = writeln!(out, "{p}\n");
            }
            Block::Figure { file, alt } => {
                let _ = writeln!(out, "![{alt}]({file})\n");
            }
            Block::Table { head, rows } => {
                let line =
                    |cells: &[String]| format!("| {} |", cells.iter().map(|c| cell(c)).collect::<Vec<_>>().join(" | "));
                let _ = writeln!(out, "{}", line(head));
                let _ = writeln!(out, "|{}", "---|".repeat(head.len()));
                for row in rows {
                    let _ = writeln!(out, "{}", line(row));
                }
                out.push('\n');
            }
        }
    }
    out
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The blocks as a standalone HTML page; `figure` resolves a figure's file
/// name to its PNG bytes (embedded as base64), `None` leaves a note instead.
pub fn to_html(blocks: &[Block], figure: &dyn Fn(&str) -> Option<Vec<u8>>) -> String {
    let mut out = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Study report</title>\n<style>\
         body{font-family:sans-serif;max-width:1400px;margin:2em auto;padding:0 1em}\
         table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:.25em .6em;text-align:left}\
         th{background:#f3f3f3}img{max-width:100%}</style>\n</head>\n<body>\n",
    );
    let mut first = true;
    for block in blocks {
        match block {
            Block::Heading(h) => {
                let tag = if first { "h1" } else { "h2" };
                let _ = writeln!(out, "<{tag}>{}</{tag}>", escape(h));
            }
            Block::Paragraph(p) => {
                let _ = writeln!(out, "<p>{}</p>", escape(p));
            }
            Block::Figure { file, alt } => match figure(file) {
                Some(png) => {
                    let data = base64::engine::general_purpose::STANDARD.encode(png);
                    let _ = writeln!(out, "<p><img alt=\"{}\" src=\"data:image/png;base64,{data}\"></p>", escape(alt));
                }
                None => {
                    let _ = writeln!(out, "<p>({} missing)</p>", escape(file));
                }
            },
            Block::Table { head, rows } => {
                out.push_str("<table>\n<tr>");
                for h in head {
                    let _ = write!(out, "<th>{}</th>", escape(h));
                }
                out.push_str("</tr>\n");
                for row in rows {
                    out.push_str("<tr>");
                    for c in row {
                        let _ = write!(out, "<td>{}</td>", escape(c));
                    }
                    out.push_str("</tr>\n");
                }
                out.push_str("</table>\n");
            }
        }
        first = false;
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// Writes `report.md` and `report.html` into a run folder (after the figure).
pub fn write_run_report(
    dir: &Path,
    design: &StudyDesign,
    summary: &[SummaryRow],
    analysis: &Analysis,
) -> Result<(), StudyError> {
    let strategies = strategy_counts(&dir.join(TRIALS_CSV))?;
    let path = dir.join(STRATEGIES_CSV);
    let rows = if path.exists() { read_strategies(&path)? } else { Vec::new() };
    let blocks = report_blocks(design, summary, analysis, strategies.as_ref(), &rows);
    write_atomically(&dir.join(REPORT_MD), to_markdown(&blocks).as_bytes())?;
    let html = to_html(&blocks, &|file| std::fs::read(dir.join(file)).ok());
    write_atomically(&dir.join(REPORT_HTML), html.as_bytes())
}
