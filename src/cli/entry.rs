//! The entry points: the binary's `main`, a researcher's own `main` with
//! their techniques added, the clap command for completions and docs, and
//! the dispatch from a parsed command to its subcommand.

use super::{
    Cli, Command, CommandResult, DemoArgs, StudyArgs, behaviours, bench, calibrate, contact, demo, doctor,
    participants, run, screenshot, study, synth_images, tradeoff,
};
use crate::pipeline::technique::{TechniqueKind, TechniqueRegistry};
use clap::{CommandFactory, FromArgMatches};
use std::path::PathBuf;
use std::process::ExitCode;

/// Parses the command line and runs it, with the built-in techniques.
pub fn main() -> ExitCode {
    main_with(TechniqueRegistry::new())
}

/// Parses the command line and runs it with `registry`'s techniques added
/// to the built-in ones: every subcommand (demo, run, study, screenshot,
/// behaviours) takes them by name. This is the whole `main` of a
/// researcher's own binary:
///
/// ```no_run
/// use surfacelab::pipeline::technique::{TechniqueRegistry, TechniqueSpec, JointTechnique};
///
/// fn main() -> std::process::ExitCode {
///     let mut registry = TechniqueRegistry::new();
///     registry.with(TechniqueSpec::new("soft_joint", |mut config| {
///         config.joint_stiffness *= 0.25;
///         Box::new(JointTechnique::new(config))
///     }).needs(surfacelab::scene::Effect::Joints));
///     surfacelab::cli::main_with(registry)
/// }
/// ```
pub fn main_with(registry: TechniqueRegistry) -> ExitCode {
    ensure_runtime_dir();
    init_tracing();
    if let Err(e) = registry.install() {
        eprintln!("surfacelab: error: {e}");
        return ExitCode::FAILURE;
    }
    let cli = match command().try_get_matches().and_then(|m| Cli::from_arg_matches(&m)) {
        Ok(cli) => cli,
        Err(e) => e.exit(),
    };
    let command = cli.command.unwrap_or_else(|| Command::Demo(DemoArgs::default()));
    match run(command) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("surfacelab: error: {e}");
            e.exit_code()
        }
    }
}

/// The command line's definition, with the techniques registered in this
/// program named in the help of every flag that takes one and at the foot
/// of `--help`.
pub fn command() -> clap::Command {
    let names: Vec<&str> = TechniqueKind::registered().iter().map(|k| k.name()).collect();
    let names = names.join(", ");
    let one = format!("Interaction technique: {names}");
    let many = format!("Comma-separated interaction techniques, from: {names}");
    let name_them = |cmd: clap::Command| -> clap::Command {
        let has = |id: &str| cmd.get_arguments().any(|a| a.get_id() == id);
        let (technique, techniques) = (has("technique"), has("techniques"));
        let mut cmd = cmd;
        if technique {
            cmd = cmd.mut_arg("technique", |a| a.help(one.clone()));
        }
        if techniques {
            let default = if cmd.get_name() == "study" {
                "default joint,proxy,particle"
            } else {
                "default: every technique the suite covers"
            };
            cmd = cmd.mut_arg("techniques", |a| a.help(format!("{many} ({default})")));
        }
        cmd
    };
    Cli::command().after_help(format!("Techniques: {names}")).mut_subcommands(name_them)
}

/// Gives the process a private `XDG_RUNTIME_DIR` when it has none (a
/// server, a container, CI), by running itself again with one set.
///
/// Mesa's Vulkan device-select layer connects to Wayland whenever the
/// instance has the Wayland surface extension, which wgpu always enables,
/// and libwayland prints `error: XDG_RUNTIME_DIR is invalid or not set` for
/// each instance: twice in a successful headless `screenshot`. The variable
/// has to be set before the first GPU call and the crate forbids `unsafe`,
/// which setting it in-process now needs, so the process replaces itself
/// (`exec`: same pid, same arguments, same standard streams). Nothing
/// happens where the variable names a folder, or when the folder cannot be
/// made (the message then shows, harmlessly).
fn ensure_runtime_dir() {
    const GUARD: &str = "SURFACELAB_RUNTIME_DIR_SET";
    let usable = std::env::var_os("XDG_RUNTIME_DIR").is_some_and(|d| std::path::Path::new(&d).is_dir());
    if usable || std::env::var_os(GUARD).is_some() {
        return;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::{DirBuilderExt, MetadataExt};
        use std::os::unix::process::CommandExt;
        let uid = std::fs::metadata("/proc/self").map_or(0, |m| m.uid());
        let dir = std::env::temp_dir().join(format!("surfacelab-xdg-{uid}"));
        let made = std::fs::DirBuilder::new().recursive(true).mode(0o700).create(&dir).is_ok();
        let Ok(exe) = std::env::current_exe() else { return };
        if made {
            // Returns only if the exec failed; then carry on as we are.
            let _ = std::process::Command::new(exe)
                .args(std::env::args_os().skip(1))
                .env("XDG_RUNTIME_DIR", &dir)
                .env(GUARD, "1")
                .exec();
        }
    }
}

fn init_tracing() {
    let filter = tracing_subscriber::EnvFilter::try_from_env("SURFACELAB_LOG")
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new("warn"));
    let _ = tracing_subscriber::fmt().with_env_filter(filter).with_writer(std::io::stderr).try_init();
}

fn run(command: Command) -> CommandResult {
    match command {
        Command::Doctor => doctor::run(),
        Command::Participants(args) => participants::run(&args),
        Command::Demo(args) => demo::run(&args),
        Command::Run(args) => run::run(&args),
        Command::Study(args) => study::run(&args),
        Command::Screenshot(args) => screenshot::run(&args),
        Command::Contact(args) => contact::run(&args),
        Command::Tradeoff(args) => tradeoff::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Behaviours(args) => behaviours::run(&args),
        Command::Calibrate(args) => calibrate::run(&args),
        Command::SynthImages(args) => synth_images::run(&args),
    }
}

/// What `surfacelab` does with no display: the headless job, so the
/// README's first command is useful on a server or in CI — a one-participant
/// scripted study (18 measured trials) with its CSVs and figure.
pub(crate) fn headless_main() -> CommandResult {
    eprintln!("surfacelab: no display, so no demo window; running a small scripted study headless instead");
    let _ = doctor::run();
    let stamp = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let out = PathBuf::from(format!("out/headless-study-{stamp}"));
    let args = StudyArgs {
        action: None,
        out,
        participants: Some(1),
        seed: None,
        reps: Some(1),
        techniques: None,
        tasks: None,
        no_practice: true,
        time_limit: None,
        from: None,
        resume: None,
        shard: None,
        jobs: 0,
        replay: None,
        no_progress: false,
        frames: false,
        seeds: None,
        manners: Vec::new(),
        slurm: None,
        submit: false,
        partition: None,
        time: None,
        cpus: None,
    };
    study::run(&args)
}
