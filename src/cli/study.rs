//! `surfacelab study`: scripted or replayed participants → trials.csv,
//! summary.csv, anova.csv, pairwise.csv, strategies.csv, figure.png/svg,
//! report.md/html and
//! run.toml in one folder; with `--seeds N`, N such folders and findings.csv.

use super::Failure;
use super::{StudyAction, StudyArgs};
use crate::harness::participant::{ReplayRunner, ScriptedRunner};
use crate::harness::study::{self, RunFile, RunOptions, StudyDesign, Technique, TrialRunner};
use std::process::ExitCode;

pub fn run(args: &StudyArgs) -> super::Outcome {
    if let Some(StudyAction::Merge { out, dirs }) = &args.action {
        let m = study::merge(out, dirs)?;
        println!("surfacelab study merge: {m:?}");
        return Ok(ExitCode::SUCCESS);
    }
    let options = RunOptions {
        jobs: args.jobs,
        progress: !args.no_progress,
        shard: match &args.shard {
            Some(s) => Some(s.parse().map_err(|e| Failure::from(e).context(format!("--shard {s}")))?),
            None => None,
        },
        ..RunOptions::default()
    };
    if let Some(n) = args.seeds {
        return run_seeds(args, n, &options);
    }
    let cpu_before = process_cpu_s();
    let outcome = if let Some(dir) = &args.resume {
        let design = RunFile::load(&dir.join("run.toml"))
            .map_err(|e| Failure::from(e).context(format!("--resume {}", dir.display())))?
            .design;
        let runner = runner_for(args, design, dir)?;
        study::resume_study(dir, runner.as_ref(), &options)?
    } else {
        let design = design_from(args)?;
        design.validate()?;
        if let Some(note) = design.balance_note() {
            eprintln!("note: {note}");
        }
        let runner = runner_for(args, design.clone(), &args.out)?;
        study::run_study(&design, &args.out, runner.as_ref(), &options)?
    };
    print_outcome(&outcome, cpu_since(cpu_before));
    if outcome.reported {
        println!(
            "  trials.csv, summary.csv, anova.csv, pairwise.csv, strategies.csv, figure.png, figure.svg, report.md, report.html, run.toml"
        );
    } else {
        println!("  trials.csv, run.toml (the rest once every trial of an unsharded run has a row)");
    }
    Ok(ExitCode::SUCCESS)
}

/// The summary line: counts, wall time, and simulated time over wall time
/// and over CPU time ("per core": the speed goal is >= 100x per core).
/// `cpu_s` is the process's CPU seconds spent on the run; without it (no
/// `/proc`), wall time × workers stands in, which under load undercounts.
fn print_outcome(outcome: &study::RunOutcome, cpu_s: Option<f64>) {
    let wall = outcome.elapsed.as_secs_f64();
    let per = |s: f64| if s > 0.0 { outcome.simulated_s / s } else { 0.0 };
    let cpu = cpu_s.unwrap_or(wall * outcome.jobs.max(1) as f64);
    println!(
        "surfacelab study: {} trials ({} already done, {} run, {} failed: {} at the time limit, {} runner errors) in {:.1} s; \
         {:.0} s simulated, {:.0}x real time, {:.0}x per core ({:.1} s CPU, {} workers); files in {}",
        outcome.trials,
        outcome.already_done,
        outcome.ran,
        outcome.failed,
        outcome.failed.saturating_sub(outcome.errors),
        outcome.errors,
        wall,
        outcome.simulated_s,
        per(wall),
        per(cpu),
        cpu,
        outcome.jobs,
        outcome.dir.display()
    );
}

/// CPU seconds (user + system, all threads) this process has used so far,
/// from `/proc/self/stat` (fields 14 and 15, in ticks of `USER_HZ` = 100 on
/// Linux); `None` where there is no such file.
fn process_cpu_s() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which may hold spaces) start at field 3.
    let rest = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |i: usize| fields.get(i).and_then(|f| f.parse::<u64>().ok());
    Some((ticks(11)? + ticks(12)?) as f64 / 100.0)
}

/// CPU seconds used since `before` (a [`process_cpu_s`] reading).
fn cpu_since(before: Option<f64>) -> Option<f64> {
    Some(process_cpu_s()? - before?)
}

/// `--seeds N`: N whole studies, one folder each, then findings.csv.
fn run_seeds(args: &StudyArgs, n: u32, options: &RunOptions) -> super::Outcome {
    let base = design_from(args)?;
    base.validate()?;
    if let Some(note) = base.balance_note() {
        eprintln!("note: {note}");
    }
    let mut dirs = Vec::new();
    for k in 1..=n {
        let design = StudyDesign { seed: study::seeds::seed_for(base.seed, k), ..base.clone() };
        let dir = study::seeds::seed_dir(&args.out, k);
        let runner = runner_for(args, design.clone(), &dir)?;
        let cpu_before = process_cpu_s();
        let outcome = study::run_study(&design, &dir, runner.as_ref(), options)?;
        print!("seed {k}/{n} (study seed {}): ", design.seed);
        print_outcome(&outcome, cpu_since(cpu_before));
        dirs.push(dir);
    }
    let rows = study::seeds::summarize_seeds(&args.out, &dirs)?;
    println!("findings over {n} seeds (reproduced / seeds that could test it):");
    for r in &rows {
        println!("  {:32} {}/{}", r.finding, r.reproduced, r.seeds);
    }
    println!("  files in {}: findings.csv, seeds.png, seed-1 .. seed-{n}", args.out.display());
    Ok(ExitCode::SUCCESS)
}

fn runner_for(args: &StudyArgs, design: StudyDesign, out: &std::path::Path) -> Result<Box<dyn TrialRunner>, Failure> {
    let frames = design.settings.get("frames").and_then(toml::Value::as_bool).unwrap_or(false);
    let frames_dir = frames.then(|| out.join("frames"));
    let replay = args.replay.clone().or_else(|| design.settings.get("replay").and_then(|v| v.as_str()).map(Into::into));
    Ok(match replay {
        Some(dir) => {
            if !dir.is_dir() {
                return Err(Failure::bad_input(anyhow::anyhow!(
                    "--replay {}: not a folder of gesture files",
                    dir.display()
                )));
            }
            Box::new(ReplayRunner { dir, design })
        }
        None => Box::new(ScriptedRunner::new(design, frames_dir)),
    })
}

fn design_from(args: &StudyArgs) -> Result<StudyDesign, Failure> {
    let mut d = match &args.from {
        Some(path) => {
            RunFile::load(path).map_err(|e| Failure::from(e).context(format!("--from {}", path.display())))?.design
        }
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
            .map(|t| t.trim().parse::<Technique>().map_err(|e| Failure::bad_input(e).context("--techniques")))
            .collect::<Result<_, _>>()?;
    }
    if let Some(ts) = &args.tasks {
        d.tasks = ts.split(',').map(|t| t.trim().to_string()).collect();
        for t in &d.tasks {
            crate::scene::load(t).map_err(|e| Failure::from(e).context(format!("--tasks: task `{t}`")))?;
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
