//! `surfacelab study`: scripted or replayed participants → trials.csv,
//! summary.csv, anova.csv, pairwise.csv, strategies.csv, figure.png/svg,
//! report.md/html and
//! run.toml in one folder; with `--seeds N`, N such folders and findings.csv;
//! with `--slurm N`, the folders and a Slurm job array that fills them.

use super::Failure;
use super::{StudyAction, StudyArgs};
use crate::harness::participant::{ReplayRunner, ScriptedRunner};
use crate::harness::study::slurm::{self, SlurmJob};
use crate::harness::study::{self, RunFile, RunOptions, Shard, StudyDesign, TrialRunner};
use anyhow::Context;
use std::process::ExitCode;

pub fn run(args: &StudyArgs) -> super::CommandResult {
    if let Some(StudyAction::Merge { out, dirs }) = &args.action {
        let m = study::merge(out, dirs)?;
        outln!("surfacelab study merge: {m:?}")?;
        return Ok(ExitCode::SUCCESS);
    }
    if let Some(StudyAction::Findings { dir }) = &args.action {
        return findings(dir);
    }
    if let Some(shards) = args.slurm {
        return run_slurm(args, shards);
    }
    let options =
        RunOptions { jobs: args.jobs, progress: !args.no_progress, shard: args.shard, ..RunOptions::default() };
    if !args.manners.is_empty() {
        return run_ablation(args, &options);
    }
    if let Some(n) = args.seeds {
        return run_seeds(args, n, &options);
    }
    let cpu_before = process_cpu_s();
    let outcome = if let Some(dir) = &args.resume {
        let run_toml = dir.join(study::RUN_TOML);
        if !run_toml.exists() && dir.join(study::TRIALS_CSV).exists() {
            return Err(Failure::bad_input(anyhow::anyhow!(
                "--resume {}: {} is missing{}",
                dir.display(),
                run_toml.display(),
                study::orphan_advice(dir)
            )));
        }
        let run =
            RunFile::load(&run_toml).map_err(|e| Failure::from(e).context(format!("--resume {}", dir.display())))?;
        refuse_conflicts(args, &run.design, &run_toml)?;
        if run.design_hash.is_none() {
            eprintln!(
                "note: {} was written before run.toml carried a design hash: resuming without checking that its design was not edited",
                run_toml.display()
            );
        }
        let runner = runner_for(args, run.design, dir)?;
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
    if outcome.dropped_bytes > 0 {
        eprintln!(
            "note: {}/trials.csv ended in a torn row ({} bytes, cut off when the run was interrupted): dropped, and its trial ran again",
            outcome.dir.display(),
            outcome.dropped_bytes
        );
    }
    print_outcome(&outcome, cpu_since(cpu_before))?;
    if outcome.reported {
        outln!(
            "  trials.csv, summary.csv, anova.csv, pairwise.csv, strategies.csv, figure.png, figure.svg, report.md, report.html, run.toml"
        )?;
    } else {
        outln!("  trials.csv, run.toml (the rest once every trial of an unsharded run has a row)")?;
    }
    Ok(ExitCode::SUCCESS)
}

/// The summary line: counts, wall time, and simulated time over wall time
/// and over CPU time ("per core": the speed goal is >= 100x per core).
/// `cpu_s` is the process's CPU seconds spent on the run; without it (no
/// `/proc`), wall time × workers stands in, which under load undercounts.
fn print_outcome(outcome: &study::RunOutcome, cpu_s: Option<f64>) -> Result<(), super::Failure> {
    let wall = outcome.elapsed.as_secs_f64();
    let per = |s: f64| if s > 0.0 { outcome.simulated_s / s } else { 0.0 };
    let cpu = cpu_s.unwrap_or(wall * outcome.jobs.max(1) as f64);
    outln!(
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
    )
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
fn run_seeds(args: &StudyArgs, n: u32, options: &RunOptions) -> super::CommandResult {
    let base = design_from(args)?;
    base.validate()?;
    if let Some(note) = base.balance_note() {
        eprintln!("note: {note}");
    }
    seeds_into(args, &base, &args.out, n, options)?;
    outln!("  files in {}: findings.csv, seeds.png, seed-1 .. seed-{n}", args.out.display())?;
    Ok(ExitCode::SUCCESS)
}

/// Runs `n` studies of `base` into `out/seed-1 ..`, writes `out/findings.csv`
/// and prints each finding's share of seeds.
fn seeds_into(
    args: &StudyArgs,
    base: &StudyDesign,
    out: &std::path::Path,
    n: u32,
    options: &RunOptions,
) -> Result<Vec<study::FindingsRow>, Failure> {
    let mut dirs = Vec::new();
    for k in 1..=n {
        let design = StudyDesign { seed: study::seed_for(base.seed, k), ..base.clone() };
        let dir = study::seed_dir(out, k);
        let runner = runner_for(args, design.clone(), &dir)?;
        let cpu_before = process_cpu_s();
        let outcome = study::run_study(&design, &dir, runner.as_ref(), options)?;
        out!("seed {k}/{n} (study seed {}): ", design.seed)?;
        print_outcome(&outcome, cpu_since(cpu_before))?;
        dirs.push(dir);
    }
    let rows = study::summarize_seeds(out, &dirs)?;
    outln!("findings over {n} seeds (reproduced / seeds that could test it, share, Wilson 95% interval):")?;
    for r in &rows {
        outln!("  {:32} {}", r.finding, share_text(r))?;
    }
    Ok(rows)
}

fn share_text(r: &study::FindingsRow) -> String {
    match (r.share, r.wilson_low, r.wilson_high) {
        (Some(p), Some(lo), Some(hi)) => {
            format!("{}/{} ({:.0}%, 95% CI {:.0}-{:.0}%)", r.reproduced, r.seeds, p * 100.0, lo * 100.0, hi * 100.0)
        }
        _ => format!("{}/{} (not tested)", r.reproduced, r.seeds),
    }
}

/// `--manners R ...`: the study under the full repertoire and under each
/// restriction (each `--seeds N` studies, default 1), then ablation.csv/md.
fn run_ablation(args: &StudyArgs, options: &RunOptions) -> super::CommandResult {
    use crate::harness::participant::Repertoire;
    let base = design_from(args)?;
    base.validate()?;
    let mut arms: Vec<(String, Option<String>)> = vec![("full".to_owned(), None)];
    for spec in &args.manners {
        let repertoire = Repertoire::parse(spec).map_err(|e| Failure::from(e).context("--manners"))?;
        let label = repertoire.label();
        if !repertoire.is_full() && !arms.iter().any(|(l, _)| *l == label) {
            arms.push((label, Some(spec.trim().to_owned())));
        }
    }
    let n = args.seeds.unwrap_or(1);
    let mut done = Vec::new();
    for (label, manners) in arms {
        let mut design = base.clone();
        design.settings.manners = manners;
        let out = args.out.join(&label);
        outln!("repertoire {label}:")?;
        let findings = seeds_into(args, &design, &out, n, options)?;
        done.push(study::Arm { repertoire: label, findings });
    }
    study::write_ablation(&args.out, &done)?;
    outln!(
        "  files in {}: ablation.csv, ablation.md, and a folder per repertoire ({})",
        args.out.display(),
        done.iter().map(|a| a.repertoire.as_str()).collect::<Vec<_>>().join(", ")
    )?;
    Ok(ExitCode::SUCCESS)
}

/// `--shard i/n`: checked by clap, so a bad value names the flag and exits 2.
pub fn parse_shard(s: &str) -> Result<Shard, String> {
    s.parse().map_err(|e: study::StudyError| e.to_string())
}

/// `study findings DIR`: findings.csv and seeds.png from `DIR/seed-1`,
/// `DIR/seed-2`, ... (every consecutive seed folder holding a run.toml).
fn findings(dir: &std::path::Path) -> super::CommandResult {
    let dirs: Vec<_> =
        (1..=u32::MAX).map(|k| study::seed_dir(dir, k)).take_while(|d| d.join(study::RUN_TOML).exists()).collect();
    if dirs.is_empty() {
        return Err(study::StudyError::mismatch(dir, "no seed-1/run.toml: not a `study --seeds` folder").into());
    }
    let rows = study::summarize_seeds(dir, &dirs)?;
    outln!("findings over {} seeds (reproduced / seeds that could test it):", dirs.len())?;
    for r in &rows {
        outln!("  {:32} {}/{}", r.finding, r.reproduced, r.seeds)?;
    }
    outln!("  files in {}: findings.csv, seeds.png", dir.display())?;
    Ok(ExitCode::SUCCESS)
}

/// `--slurm N`: the design fixed in run.toml files and the two batch scripts
/// (see `study::slurm`); with `--submit`, both submitted.
fn run_slurm(args: &StudyArgs, shards: u32) -> super::CommandResult {
    let design = design_from(args)?;
    design.validate()?;
    if let Some(note) = design.balance_note() {
        eprintln!("note: {note}");
    }
    if shards > design.participants {
        eprintln!(
            "note: {shards} shards for {} participants: shards split by participant, so {} of them have no trials",
            design.participants,
            shards - design.participants
        );
    }
    let dir = std::path::absolute(&args.out).with_context(|| format!("--out {}", args.out.display()))?;
    let exe = std::env::current_exe().context("cannot find the path of the running surfacelab binary")?;
    let job = SlurmJob {
        exe,
        dir,
        shards,
        seeds: args.seeds,
        partition: args.partition.clone(),
        time: args.time,
        cpus: args.cpus,
    };
    slurm::prepare(&job, &design).map_err(|e| Failure::from(e).context(format!("--out {}", args.out.display())))?;
    let (array, merge) = (job.array_script_path(), job.merge_script_path());
    outln!(
        "surfacelab study: {} array tasks ({} shard{} per study{}) and a merge job written:",
        job.tasks(),
        shards,
        if shards == 1 { "" } else { "s" },
        args.seeds.map_or_else(String::new, |s| format!(", {s} studies"))
    )?;
    outln!("  {}\n  {}", array.display(), merge.display())?;
    if args.submit {
        let ids = slurm::submit(&job)?;
        outln!(
            "submitted: array job {} ({} tasks), merge job {} (afterok:{})",
            ids.array,
            job.tasks(),
            ids.merge,
            ids.array
        )?;
        outln!(
            "  watch: squeue -j {},{}   failed tasks: sacct -X -j {} --format=JobID,State,ExitCode",
            ids.array,
            ids.merge,
            ids.array
        )?;
    } else {
        let q = |p: &std::path::Path| slurm::shell_quote(p).unwrap_or_else(|_| p.display().to_string());
        outln!("submit with:")?;
        outln!("  array=$(sbatch --parsable {})", q(&array))?;
        outln!("  sbatch --dependency=afterok:${{array%%;*}} {}", q(&merge))?;
    }
    Ok(ExitCode::SUCCESS)
}

fn runner_for(args: &StudyArgs, design: StudyDesign, out: &std::path::Path) -> Result<Box<dyn TrialRunner>, Failure> {
    let frames_dir = design.settings.frames.then(|| out.join("frames"));
    let replay = args.replay.clone().or_else(|| design.settings.replay.clone());
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
        d.techniques.clone_from(ts);
    }
    if let Some(ts) = &args.tasks {
        d.tasks.clone_from(ts);
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
        d.settings.replay = Some(dir.clone());
    }
    if args.frames {
        d.settings.frames = true;
    }
    if let Some(spec) = &d.settings.manners {
        crate::harness::participant::Repertoire::parse(spec)
            .map_err(|e| Failure::from(e).context("run.toml [design.settings] manners"))?;
    }
    Ok(d)
}

/// `--resume` runs the design in run.toml: a design flag given with it
/// that says otherwise is refused (exit 2, naming the flag), not ignored.
/// A flag that repeats the recorded value is fine.
fn refuse_conflicts(args: &StudyArgs, design: &StudyDesign, run_toml: &std::path::Path) -> Result<(), Failure> {
    let mut conflicts: Vec<(&str, String, String)> = Vec::new();
    if let Some(n) = args.participants.filter(|&n| n != design.participants) {
        conflicts.push(("--participants", n.to_string(), design.participants.to_string()));
    }
    if let Some(s) = args.seed.filter(|&s| s != design.seed) {
        conflicts.push(("--seed", s.to_string(), design.seed.to_string()));
    }
    if let Some(r) = args.reps.filter(|&r| r != design.repetitions) {
        conflicts.push(("--reps", r.to_string(), design.repetitions.to_string()));
    }
    if let Some(ts) = args.techniques.as_ref().filter(|ts| **ts != design.techniques) {
        let names = |v: &[crate::pipeline::technique::TechniqueKind]| {
            v.iter().map(ToString::to_string).collect::<Vec<_>>().join(",")
        };
        conflicts.push(("--techniques", names(ts), names(&design.techniques)));
    }
    if let Some(ts) = args.tasks.as_ref().filter(|ts| **ts != design.tasks) {
        conflicts.push(("--tasks", ts.join(","), design.tasks.join(",")));
    }
    if args.no_practice && design.practice {
        conflicts.push(("--no-practice", "given".into(), "practice = true".into()));
    }
    if let Some(t) = args.time_limit.filter(|&t| Some(f64::from(t)) != design.time_limit_override) {
        conflicts.push((
            "--time-limit",
            t.to_string(),
            design.time_limit_override.map_or("none".into(), |v| v.to_string()),
        ));
    }
    if let Some(r) = args.replay.as_ref().filter(|r| Some(*r) != design.settings.replay.as_ref()) {
        conflicts.push((
            "--replay",
            r.display().to_string(),
            design.settings.replay.as_ref().map_or("none (scripted participants)".into(), |p| p.display().to_string()),
        ));
    }
    if args.frames && !design.settings.frames {
        conflicts.push(("--frames", "given".into(), "frames = false".into()));
    }
    match conflicts.first() {
        None => Ok(()),
        Some((flag, given, recorded)) => Err(Failure::bad_input(anyhow::anyhow!(
            "{flag} {given} conflicts with the run being resumed ({} records {recorded}); --resume runs the recorded \
             design: drop {flag}, or start a new folder with --from {} --out NEW_FOLDER {flag} ...",
            run_toml.display(),
            run_toml.display()
        ))),
    }
}
