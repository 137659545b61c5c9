//! A study as a Slurm job array (`study --slurm N`): the run folders and the
//! two batch scripts, and their submission.
//!
//! Layout (one study; `--seeds S` puts this under `DIR/seed-<k>/`, k = 1..S):
//!
//! | path | written | contents |
//! |---|---|---|
//! | `DIR/run.toml` | first, by `--slurm` | the whole design, no shard: what `study merge` writes into |
//! | `DIR/shard-<i>/run.toml` | first, by `--slurm` | the design and shard `i/N` |
//! | `DIR/slurm/array.sbatch` | by `--slurm` | array task `i` runs `study --resume DIR/shard-<i> --shard i/N` |
//! | `DIR/slurm/merge.sbatch` | by `--slurm` | `study merge DIR DIR/shard-0 ...` (and `study findings` with seeds) |
//! | `DIR/slurm/*.out` | by Slurm | each task's and the merge's output |
//!
//! Writing every `run.toml` before anything runs fixes the design: an array
//! task only ever *resumes* its folder, so a task that failed, was cancelled
//! or ran out of time continues from its last written trial when it is
//! submitted again alone (`sbatch --array=K DIR/slurm/array.sbatch`), and a
//! task run twice adds nothing. Shards split by participant (participant `p`
//! is in shard `(p - 1) % N`, see `runner::in_shard`), so the merged
//! `trials.csv` is byte-identical to an unsharded run's.

use super::design::{Shard, StudyDesign};
use super::error::StudyError;
use super::output::{RUN_TOML, RunFile, TRIALS_CSV};
use super::seeds::{seed_dir, seed_for};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The scripts' folder inside the run folder.
pub const SLURM_DIR: &str = "slurm";
pub const ARRAY_SBATCH: &str = "array.sbatch";
pub const MERGE_SBATCH: &str = "merge.sbatch";

/// The folder of shard `i` (0-based) of the study in `dir`.
pub fn shard_dir(dir: &Path, i: u32) -> PathBuf {
    dir.join(format!("shard-{i}"))
}

/// A wall-clock limit for `#SBATCH --time`: `HH:MM:SS` or `D-HH:MM:SS`
/// (minutes and seconds below 60; hours below 24 when days are given).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SlurmTime {
    pub days: Option<u32>,
    pub hours: u32,
    pub minutes: u32,
    pub seconds: u32,
}

impl std::str::FromStr for SlurmTime {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad =
            |why: &str| format!("`{s}` is not a time limit: {why} (expected HH:MM:SS or D-HH:MM:SS, e.g. 02:00:00)");
        let number = |part: &str, what: &str| -> Result<u32, String> {
            if part.is_empty() || !part.bytes().all(|b| b.is_ascii_digit()) {
                return Err(bad(&format!("{what} `{part}` is not a number")));
            }
            part.parse().map_err(|_| bad(&format!("{what} `{part}` is too large")))
        };
        let (days, clock) = match s.split_once('-') {
            Some((d, rest)) => (Some(number(d, "days")?), rest),
            None => (None, s),
        };
        let parts: Vec<&str> = clock.split(':').collect();
        let [h, m, sec] = parts[..] else {
            return Err(bad("need three fields separated by `:`"));
        };
        let t = SlurmTime {
            days,
            hours: number(h, "hours")?,
            minutes: number(m, "minutes")?,
            seconds: number(sec, "seconds")?,
        };
        if m.len() != 2 || sec.len() != 2 {
            return Err(bad("minutes and seconds take two digits"));
        }
        if t.minutes >= 60 || t.seconds >= 60 {
            return Err(bad("minutes and seconds must be below 60"));
        }
        if t.days.is_some() && t.hours >= 24 {
            return Err(bad("hours must be below 24 when days are given"));
        }
        if t.total_seconds() == 0 {
            return Err(bad("it must be longer than zero"));
        }
        Ok(t)
    }
}

impl SlurmTime {
    pub fn total_seconds(self) -> u64 {
        ((u64::from(self.days.unwrap_or(0)) * 24 + u64::from(self.hours)) * 60 + u64::from(self.minutes)) * 60
            + u64::from(self.seconds)
    }
}

impl std::fmt::Display for SlurmTime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let Some(d) = self.days {
            write!(f, "{d}-")?;
        }
        write!(f, "{:02}:{:02}:{:02}", self.hours, self.minutes, self.seconds)
    }
}

/// A Slurm partition name (or a comma-separated list of them): letters,
/// digits and `_-.,` only, so it can go into a `#SBATCH` line unquoted.
pub fn parse_partition(s: &str) -> Result<String, String> {
    if !s.is_empty() && s.bytes().all(|b| b.is_ascii_alphanumeric() || b"_-.,".contains(&b)) {
        Ok(s.to_owned())
    } else {
        Err(format!("`{s}` is not a partition name (letters, digits, `_`, `-`, `.`; several joined by `,`)"))
    }
}

/// Everything the two scripts depend on.
#[derive(Debug, Clone, PartialEq)]
pub struct SlurmJob {
    /// The surfacelab binary the tasks run (absolute).
    pub exe: PathBuf,
    /// The run folder (absolute).
    pub dir: PathBuf,
    /// Shards per study (`N`).
    pub shards: u32,
    /// `Some(S)`: `S` studies under `DIR/seed-<k>`, each in `N` shards.
    pub seeds: Option<u32>,
    pub partition: Option<String>,
    pub time: Option<SlurmTime>,
    /// CPUs per array task (`--cpus-per-task`); the task runs that many workers.
    pub cpus: Option<u32>,
}

impl SlurmJob {
    /// Array tasks: `N`, or `S × N` with seeds (task `t` is seed `t / N + 1`, shard `t % N`).
    pub fn tasks(&self) -> u32 {
        self.shards * self.seeds.unwrap_or(1)
    }

    /// The study folders: `DIR`, or `DIR/seed-1 .. DIR/seed-S`.
    pub fn study_dirs(&self) -> Vec<PathBuf> {
        match self.seeds {
            None => vec![self.dir.clone()],
            Some(s) => (1..=s).map(|k| seed_dir(&self.dir, k)).collect(),
        }
    }

    pub fn slurm_dir(&self) -> PathBuf {
        self.dir.join(SLURM_DIR)
    }

    pub fn array_script_path(&self) -> PathBuf {
        self.slurm_dir().join(ARRAY_SBATCH)
    }

    pub fn merge_script_path(&self) -> PathBuf {
        self.slurm_dir().join(MERGE_SBATCH)
    }

    /// `DIR/slurm/array.sbatch`.
    pub fn array_script(&self) -> Result<String, StudyError> {
        let n = self.shards;
        let last = self.tasks() - 1;
        let about = format!(
            "# surfacelab study on Slurm: array task i runs its shard of the study in the run folder.\n\
             # Written by `surfacelab study --slurm {n}`. Every task only resumes its folder, so a task\n\
             # that failed, was cancelled or timed out continues where it stopped when resubmitted alone:\n\
             #   sbatch --array=K {}\n",
            shell_quote(&self.array_script_path())?
        );
        let head = self.script_head(
            &about,
            &format!("#SBATCH --job-name=surfacelab-study\n#SBATCH --array=0-{last}\n"),
            "array-%A_%a.out",
            true,
        )?;
        let study = match self.seeds {
            Some(_) => format!("seed=$((task / {n} + 1))\nshard=$((task % {n}))\nstudy=\"$dir/seed-$seed\"\n"),
            None => "shard=\"$task\"\nstudy=\"$dir\"\n".to_owned(),
        };
        Ok(format!(
            "{head}\
             task=\"${{SLURM_ARRAY_TASK_ID:?submit this script with sbatch (it is a job array)}}\"\n\
             {study}\
             echo \"surfacelab: task $task on $(hostname): shard $shard/{n} of $study\"\n\
             exec \"$exe\" study --resume \"$study/shard-$shard\" --shard \"$shard/{n}\" \
             --jobs \"${{SLURM_CPUS_PER_TASK:-1}}\" --no-progress\n"
        ))
    }

    /// `DIR/slurm/merge.sbatch`.
    pub fn merge_script(&self) -> Result<String, StudyError> {
        let array = shell_quote(&self.array_script_path())?;
        let merge = shell_quote(&self.merge_script_path())?;
        let about = format!(
            "# surfacelab study on Slurm: merges the shards once every array task succeeded. Submit with\n\
             #   array=$(sbatch --parsable {array})\n\
             #   sbatch --dependency=afterok:${{array%%;*}} {merge}\n"
        );
        let head = self.script_head(&about, "#SBATCH --job-name=surfacelab-merge\n", "merge-%j.out", false)?;
        let shard_args =
            |study: &str| (0..self.shards).map(|i| format!("\"{study}/shard-{i}\"")).collect::<Vec<_>>().join(" ");
        let body = match self.seeds {
            None => format!("\"$exe\" study merge \"$dir\" {}\n", shard_args("$dir")),
            Some(seeds) => format!(
                "for seed in $(seq 1 {seeds}); do\n  \
                 study=\"$dir/seed-$seed\"\n  \
                 \"$exe\" study merge \"$study\" {}\n\
                 done\n\
                 \"$exe\" study findings \"$dir\"\n",
                shard_args("$study")
            ),
        };
        Ok(head + &body)
    }

    /// What both scripts start with: the shebang, `about` (comment lines),
    /// the job's `directives`, its log file `log` in `DIR/slurm`, the
    /// resources, strict mode, and the binary and folder as `$exe`, `$dir`.
    fn script_head(&self, about: &str, directives: &str, log: &str, per_task_cpus: bool) -> Result<String, StudyError> {
        let output = directive_quote(&self.slurm_dir().join(log), true)?;
        let mut resources = String::new();
        if let Some(p) = &self.partition {
            let _ = writeln!(resources, "#SBATCH --partition={p}");
        }
        if let Some(t) = self.time {
            let _ = writeln!(resources, "#SBATCH --time={t}");
        }
        if per_task_cpus && let Some(c) = self.cpus {
            let _ = writeln!(resources, "#SBATCH --cpus-per-task={c}");
        }
        Ok(format!(
            "#!/bin/bash\n{about}{directives}#SBATCH --output={output}\n{resources}set -euo pipefail\nexe={}\ndir={}\n",
            shell_quote(&self.exe)?,
            shell_quote(&self.dir)?
        ))
    }

    /// The `sbatch` arguments that submit the merge after array job `array_id`.
    pub fn merge_submit_args(&self, array_id: &str) -> Vec<String> {
        vec![
            "--parsable".to_owned(),
            format!("--dependency=afterok:{array_id}"),
            self.merge_script_path().display().to_string(),
        ]
    }
}

/// Fixes a study before any task runs: validates the design, refuses a
/// folder that already holds a run, writes `run.toml` into every study
/// folder (whole, no shard) and into its `N` shard folders, then the two
/// scripts. With seeds, study `k` gets the seed `seeds::seed_for(seed, k)`,
/// as `study --seeds` gives it.
pub fn prepare(job: &SlurmJob, design: &StudyDesign) -> Result<(), StudyError> {
    design.validate()?;
    for (k, study) in job.study_dirs().iter().enumerate() {
        for d in std::iter::once(study.clone()).chain((0..job.shards).map(|i| shard_dir(study, i))) {
            if d.join(RUN_TOML).exists() || d.join(TRIALS_CSV).exists() {
                return Err(StudyError::AlreadyExists { path: d });
            }
        }
        let design = match job.seeds {
            None => design.clone(),
            Some(_) => StudyDesign { seed: seed_for(design.seed, k as u32 + 1), ..design.clone() },
        };
        std::fs::create_dir_all(study).map_err(StudyError::io(study))?;
        RunFile::new(design.clone(), None).save(&study.join(RUN_TOML))?;
        for i in 0..job.shards {
            let d = shard_dir(study, i);
            std::fs::create_dir_all(&d).map_err(StudyError::io(&d))?;
            RunFile::new(design.clone(), Some(Shard::new(i, job.shards)?)).save(&d.join(RUN_TOML))?;
        }
    }
    let slurm = job.slurm_dir();
    std::fs::create_dir_all(&slurm).map_err(StudyError::io(&slurm))?;
    for (path, text) in [(job.array_script_path(), job.array_script()?), (job.merge_script_path(), job.merge_script()?)]
    {
        super::output::write_atomically(&path, text.as_bytes())?;
    }
    Ok(())
}

/// `sbatch` could not submit.
#[derive(Debug, thiserror::Error)]
pub enum SubmitError {
    #[error("cannot run `sbatch` (is this a Slurm login node? Submit the scripts in {} yourself)", dir.display())]
    Spawn { dir: PathBuf, source: std::io::Error },
    #[error("`sbatch {args}` failed ({status}): {stderr}")]
    Failed { args: String, status: std::process::ExitStatus, stderr: String },
    #[error("`sbatch {args}` printed `{stdout}`, not a job id")]
    NoJobId { args: String, stdout: String },
}

impl crate::error::Kind for SubmitError {
    /// The scripts are written and right; the cluster refused or is absent.
    fn kind(&self) -> crate::error::ErrorKind {
        crate::error::ErrorKind::Runtime
    }
}

/// The job ids `--submit` got.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Submitted {
    pub array: String,
    pub merge: String,
}

/// Submits the array, then the merge with `--dependency=afterok:<array id>`.
pub fn submit(job: &SlurmJob) -> Result<Submitted, SubmitError> {
    let array = sbatch(job, &["--parsable".to_owned(), job.array_script_path().display().to_string()])?;
    let merge = sbatch(job, &job.merge_submit_args(&array))?;
    Ok(Submitted { array, merge })
}

/// Runs `sbatch ARGS` and returns the job id it prints (`--parsable`:
/// `id` or `id;cluster`).
fn sbatch(job: &SlurmJob, args: &[String]) -> Result<String, SubmitError> {
    let shown = args.join(" ");
    let out = Command::new("sbatch")
        .args(args)
        .output()
        .map_err(|source| SubmitError::Spawn { dir: job.slurm_dir(), source })?;
    let stdout = String::from_utf8_lossy(&out.stdout).trim().to_owned();
    if !out.status.success() {
        let stderr = String::from_utf8_lossy(&out.stderr).trim().to_owned();
        return Err(SubmitError::Failed { args: shown, status: out.status, stderr });
    }
    let id = stdout.split(';').next().unwrap_or_default().trim();
    if id.is_empty() || !id.bytes().all(|b| b.is_ascii_digit()) {
        return Err(SubmitError::NoJobId { args: shown, stdout });
    }
    Ok(id.to_owned())
}

/// A path as one word for bash: single-quoted, `'` written `'\''`. Paths
/// with control characters (a newline would end a `#SBATCH` line) or that
/// are not UTF-8 are refused.
pub fn shell_quote(path: &Path) -> Result<String, StudyError> {
    let s = plain_path(path)?;
    Ok(format!("'{}'", s.replace('\'', r"'\''")))
}

/// A path as the argument of a `#SBATCH` line: sbatch reads these with its
/// own rules (double quotes group, a backslash escapes the next character,
/// an unescaped `#` starts a comment). In a file-name pattern (`--output`)
/// `%` is a replacement symbol, so a literal `%` is doubled; the pattern's
/// own symbols (`%A`, `%a`, `%j`) are in the file name, added after quoting
/// the folder.
fn directive_quote(path: &Path, pattern: bool) -> Result<String, StudyError> {
    let (dir, name) = match (path.parent(), path.file_name()) {
        (Some(d), Some(n)) => (d, n.to_string_lossy().into_owned()),
        _ => (path, String::new()),
    };
    let mut s = plain_path(dir)?.to_owned();
    if pattern {
        s = s.replace('%', "%%");
    }
    let escaped = s.replace('\\', r"\\").replace('"', "\\\"");
    let sep = if name.is_empty() { "" } else { "/" };
    Ok(format!("\"{escaped}{sep}{name}\""))
}

fn plain_path(path: &Path) -> Result<&str, StudyError> {
    let s = path.to_str().ok_or_else(|| StudyError::Design(format!("{}: not a UTF-8 path", path.display())))?;
    if s.chars().any(char::is_control) {
        return Err(StudyError::Design(format!("{s:?}: a path with control characters cannot go into a batch script")));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job(seeds: Option<u32>) -> SlurmJob {
        SlurmJob {
            exe: PathBuf::from("/opt/surfacelab/bin/surfacelab"),
            dir: PathBuf::from("/scratch/it's a run"),
            shards: 3,
            seeds,
            partition: Some("short".into()),
            time: Some("0-02:30:00".parse().expect("time")),
            cpus: Some(4),
        }
    }

    fn lines(s: &str) -> Vec<&str> {
        s.lines().collect()
    }

    #[test]
    fn the_array_script_runs_one_resumable_shard_per_task() {
        let s = job(None).array_script().expect("script");
        let l = lines(&s);
        assert_eq!(l[0], "#!/bin/bash");
        assert!(l.contains(&"#SBATCH --array=0-2"), "{s}");
        assert!(l.contains(&"#SBATCH --partition=short"), "{s}");
        assert!(l.contains(&"#SBATCH --time=0-02:30:00"), "{s}");
        assert!(l.contains(&"#SBATCH --cpus-per-task=4"), "{s}");
        assert!(l.contains(&r#"#SBATCH --output="/scratch/it's a run/slurm/array-%A_%a.out""#), "{s}");
        assert!(l.contains(&r"exe='/opt/surfacelab/bin/surfacelab'"), "{s}");
        assert!(l.contains(&r"dir='/scratch/it'\''s a run'"), "{s}");
        assert!(l.contains(&r#"shard="$task""#), "{s}");
        assert!(
            l.contains(
                &r#"exec "$exe" study --resume "$study/shard-$shard" --shard "$shard/3" --jobs "${SLURM_CPUS_PER_TASK:-1}" --no-progress"#
            ),
            "{s}"
        );
        // Every #SBATCH line comes before the first command, or sbatch ignores it.
        let first_command = l.iter().position(|x| x.starts_with("set -")).expect("set line");
        assert!(l.iter().skip(first_command).all(|x| !x.starts_with("#SBATCH")), "{s}");
    }

    #[test]
    fn the_merge_script_merges_every_shard_into_the_run_folder() {
        let j = job(None);
        let s = j.merge_script().expect("script");
        let l = lines(&s);
        assert!(l.contains(&r#""$exe" study merge "$dir" "$dir/shard-0" "$dir/shard-1" "$dir/shard-2""#), "{s}");
        assert!(!s.contains("--cpus-per-task"), "the merge is one thread: {s}");
        assert!(l.contains(&"#SBATCH --time=0-02:30:00"), "{s}");
        assert_eq!(
            j.merge_submit_args("4711"),
            ["--parsable", "--dependency=afterok:4711", "/scratch/it's a run/slurm/merge.sbatch"]
        );
    }

    #[test]
    fn with_seeds_the_array_covers_every_seed_and_shard() {
        let j = job(Some(2));
        assert_eq!(j.tasks(), 6);
        let a = j.array_script().expect("script");
        assert!(a.lines().any(|x| x == "#SBATCH --array=0-5"), "{a}");
        assert!(a.lines().any(|x| x == "seed=$((task / 3 + 1))"), "{a}");
        assert!(a.lines().any(|x| x == "shard=$((task % 3))"), "{a}");
        assert!(a.lines().any(|x| x == r#"study="$dir/seed-$seed""#), "{a}");
        let m = j.merge_script().expect("script");
        assert!(m.lines().any(|x| x == "for seed in $(seq 1 2); do"), "{m}");
        assert!(
            m.lines()
                .any(|x| x == r#"  "$exe" study merge "$study" "$study/shard-0" "$study/shard-1" "$study/shard-2""#),
            "{m}"
        );
        assert!(m.lines().any(|x| x == r#""$exe" study findings "$dir""#), "{m}");
    }

    #[test]
    fn optional_resources_are_left_to_the_cluster() {
        let j = SlurmJob { partition: None, time: None, cpus: None, shards: 1, ..job(None) };
        let a = j.array_script().expect("script");
        assert!(a.lines().any(|x| x == "#SBATCH --array=0-0"), "{a}");
        for flag in ["--partition", "--time", "--cpus-per-task"] {
            assert!(!a.contains(flag), "{flag} in {a}");
        }
    }

    #[test]
    fn directive_paths_escape_what_sbatch_would_read_as_syntax() {
        let q = directive_quote(Path::new("/data/50% \"x\" #2/slurm/array-%A_%a.out"), true).expect("quote");
        assert_eq!(q, r#""/data/50%% \"x\" #2/slurm/array-%A_%a.out""#);
        assert!(shell_quote(Path::new("/a\nb")).is_err(), "a newline cannot go into a script");
    }

    #[test]
    fn time_limits_parse_in_both_slurm_forms() {
        let t: SlurmTime = "02:00:00".parse().expect("hh:mm:ss");
        assert_eq!((t.days, t.hours, t.minutes, t.seconds, t.total_seconds()), (None, 2, 0, 0, 7200));
        assert_eq!(t.to_string(), "02:00:00");
        let t: SlurmTime = "1-12:30:05".parse().expect("d-hh:mm:ss");
        assert_eq!(t.total_seconds(), 86_400 + 12 * 3600 + 30 * 60 + 5);
        assert_eq!(t.to_string(), "1-12:30:05");
        assert_eq!("48:00:00".parse::<SlurmTime>().expect("long").total_seconds(), 48 * 3600);
        for bad in
            ["", "2h", "02:00", "00:60:00", "00:00:60", "1-24:00:00", "00:00:00", "-01:00:00", "01:5:00", "a:00:00"]
        {
            let e = bad.parse::<SlurmTime>().expect_err(bad);
            assert!(e.contains("HH:MM:SS or D-HH:MM:SS"), "{bad}: {e}");
        }
    }

    #[test]
    fn partitions_are_plain_names() {
        assert_eq!(parse_partition("gpu-a100,short").as_deref(), Ok("gpu-a100,short"));
        for bad in ["", "a b", "x#y", "p\n"] {
            assert!(parse_partition(bad).is_err(), "{bad:?}");
        }
    }
}
