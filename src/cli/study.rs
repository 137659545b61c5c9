//! `surfacelab study`: scripted or replayed participants → trials.csv,
//! summary.csv, figure.png/svg and run.toml in one folder.

use super::{StudyAction, StudyArgs};
use crate::participant::{ReplayRunner, ScriptedRunner};
use crate::study::{self, RunFile, RunOptions, StudyDesign, Technique, TrialRunner};
use anyhow::Context;
use std::process::ExitCode;

pub fn run(args: &StudyArgs) -> anyhow::Result<ExitCode> {
    if let Some(StudyAction::Merge { out, dirs }) = &args.action {
        let m = study::merge(out, dirs)?;
        println!("surfacelab study merge: {m:?}");
        return Ok(ExitCode::SUCCESS);
    }
    let options = RunOptions {
        jobs: args.jobs,
        progress: !args.no_progress,
        shard: match &args.shard {
            Some(s) => Some(s.parse().map_err(|e| anyhow::anyhow!("--shard {s}: {e}"))?),
            None => None,
        },
        ..RunOptions::default()
    };
    let outcome = if let Some(dir) = &args.resume {
        let design =
            RunFile::load(&dir.join("run.toml")).with_context(|| format!("--resume {}", dir.display()))?.design;
        let runner = runner_for(args, design, dir)?;
        study::resume_study(dir, runner.as_ref(), &options)?
    } else {
        let design = design_from(args)?;
        design.validate()?;
        let runner = runner_for(args, design.clone(), &args.out)?;
        study::run_study(&design, &args.out, runner.as_ref(), &options)?
    };
    println!(
        "surfacelab study: {} trials ({} already done, {} run, {} failed) in {:.1} s; files in {}",
        outcome.trials,
        outcome.already_done,
        outcome.ran,
        outcome.failed,
        outcome.elapsed.as_secs_f64(),
        outcome.dir.display()
    );
    println!("  trials.csv, summary.csv, figure.png, figure.svg, run.toml");
    Ok(ExitCode::SUCCESS)
}

fn runner_for(args: &StudyArgs, design: StudyDesign, out: &std::path::Path) -> anyhow::Result<Box<dyn TrialRunner>> {
    let frames = design.settings.get("frames").and_then(toml::Value::as_bool).unwrap_or(false);
    let frames_dir = frames.then(|| out.join("frames"));
    let replay = args.replay.clone().or_else(|| design.settings.get("replay").and_then(|v| v.as_str()).map(Into::into));
    Ok(match replay {
        Some(dir) => {
            anyhow::ensure!(dir.is_dir(), "--replay {}: not a folder of gesture files", dir.display());
            Box::new(ReplayRunner { dir, design })
        }
        None => Box::new(ScriptedRunner::new(design, frames_dir)),
    })
}

fn design_from(args: &StudyArgs) -> anyhow::Result<StudyDesign> {
    let mut d = match &args.from {
        Some(path) => RunFile::load(path).with_context(|| format!("--from {}", path.display()))?.design,
        None => StudyDesign::default(),
    };
    if let Some(n) = args.participants {
        d.participants = n;
    }
    if let Some(s) = args.seed {
        d.seed = s;
    }
    if let Some(r) = args.reps {
        d.repetitions = r;
    }
    if let Some(ts) = &args.techniques {
        d.techniques = ts
            .split(',')
            .map(|t| t.trim().parse::<Technique>().map_err(|e| anyhow::anyhow!("--techniques: {e}")))
            .collect::<anyhow::Result<_>>()?;
    }
    if let Some(ts) = &args.tasks {
        d.tasks = ts.split(',').map(|t| t.trim().to_string()).collect();
        for t in &d.tasks {
            crate::scene::load(t).with_context(|| format!("--tasks: task `{t}`"))?;
        }
    }
    if args.no_practice {
        d.practice = false;
    }
    if let Some(t) = args.time_limit {
        d.time_limit_override = Some(f64::from(t));
    }
    if let Some(dir) = &args.replay {
        d.settings.insert("replay".into(), toml::Value::String(dir.display().to_string()));
    }
    if args.frames {
        d.settings.insert("frames".into(), toml::Value::Boolean(true));
    }
    Ok(d)
}
