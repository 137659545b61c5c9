//! A small study designed in Rust, run, and its `summary.csv` read back
//! through the library's own row type.
//!
//! `cargo run --release --example study_from_code` runs two participants on
//! the positioning task under Joint and Particle, prints each condition's
//! mean time, and exits 1 unless every condition has both participants'
//! trials in the summary.

use std::process::ExitCode;
use surfacelab::harness::participant::ScriptedRunner;
use surfacelab::harness::study::{RunOptions, StudyDesign, SummaryRow, run_study};
use surfacelab::pipeline::technique::TechniqueKind;

fn main() -> anyhow::Result<ExitCode> {
    let design = StudyDesign {
        participants: 2,
        tasks: vec!["positioning".into()],
        techniques: vec![TechniqueKind::JOINT, TechniqueKind::PARTICLE],
        feedback: vec![true, false],
        repetitions: 1,
        practice: false,
        seed: 7,
        ..StudyDesign::default()
    };
    let out = std::env::temp_dir().join(format!("surfacelab-study-from-code-{}", std::process::id()));
    let runner = ScriptedRunner::new(design.clone(), None);
    let outcome = run_study(&design, &out, &runner, &RunOptions { progress: false, ..RunOptions::default() })?;
    println!(
        "{} trials ({} failed) in {:.1} s; files in {}",
        outcome.ran,
        outcome.failed,
        outcome.elapsed.as_secs_f64(),
        out.display()
    );

    let rows: Vec<SummaryRow> =
        csv::Reader::from_path(out.join("summary.csv"))?.deserialize().collect::<Result<_, _>>()?;
    for r in &rows {
        let mean = r.mean_s.map_or_else(|| "-".to_owned(), |m| format!("{m:.1} s"));
        println!(
            "{:<11} {:<9} feedback {:<5}  {}/{} completed, mean {mean}",
            r.task,
            r.technique.label(),
            r.feedback,
            r.completed,
            r.trials
        );
    }
    // Two techniques × two feedback levels, each with both participants' one trial.
    let whole = rows.len() == 4 && rows.iter().all(|r| r.trials == 2);
    Ok(if whole { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}
