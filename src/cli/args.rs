//! Every subcommand's arguments: parsed once by clap into a struct the
//! subcommand's module takes, the parsers of argument values beside them.

use super::{calibrate, demo, screenshot, study};
use crate::harness::scaling::Curve;
use crate::harness::study::Shard;
use crate::pipeline::technique::TechniqueKind;
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Tabletop physics on a (synthetic) vision-based surface, with a study harness.
#[derive(Debug, Parser)]
#[command(name = "surfacelab", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the desktop demo (the default with no subcommand).
    Demo(DemoArgs),
    /// Replay one gesture file, or run live from a TUIO tracker, headless and write a JSON report.
    Run(RunArgs),
    /// Run scripted or replayed study participants and write CSVs and plots.
    Study(StudyArgs),
    /// Render a scene off-screen (no display needed) and write a PNG.
    Screenshot(ScreenshotArgs),
    /// Answer a 2D contact query between two polygons given as JSON.
    Contact(ContactArgs),
    /// Measure what accuracy costs in time and write the trade-off report.
    Tradeoff(TradeoffArgs),
    /// Measure how cost grows with the work: scaling.csv, scaling.md and scaling.png.
    Bench(BenchArgs),
    /// Run the paper's manipulations (the behaviour suite) and print the behaviour × technique table.
    Behaviours(BehavioursArgs),
    /// Check the simulated participants against human data (`participants fitts`).
    Participants(ParticipantsArgs),
    /// Print the GPU adapter, the display and the version.
    Doctor,
    /// Write a camera calibration file for `--images` or `--camera` from four point pairs (clicked or given).
    Calibrate(CalibrateArgs),
    /// Write a gesture as the camera frames an infrared or depth camera would record.
    SynthImages(SynthImagesArgs),
}

#[derive(Debug, Args)]
pub struct DemoArgs {
    /// Scene name under tasks/ or a path to a scene file.
    #[arg(long, default_value = "positioning")]
    pub task: String,
    #[arg(long, value_parser = parse_technique, default_value_t = TechniqueKind::PARTICLE)]
    pub technique: TechniqueKind,
    /// Show the technique's feedback (joint lines, proxy cubes, particles).
    #[arg(long)]
    pub feedback: bool,
    /// Start with the contact-image overlay (the hand shadow) off.
    #[arg(long)]
    pub no_contact_overlay: bool,
    /// Listen for TUIO 1.1 and 2.0 over UDP on PORT (default 3333).
    #[arg(long, value_name = "PORT", num_args = 0..=1, default_missing_value = "3333")]
    pub tuio: Option<u16>,
    /// Address the TUIO socket binds to (default 127.0.0.1; 0.0.0.0 for a tracker on another machine).
    #[arg(long, value_name = "ADDR", requires = "tuio")]
    pub tuio_bind: Option<std::net::IpAddr>,
    /// Replay a gesture file as live input, from the start of the session.
    #[arg(long, value_name = "GESTURE_FILE")]
    pub script: Option<PathBuf>,
    /// Play recorded camera frames (8/16-bit grey PNGs) as what the table sees, from the start of the session.
    #[arg(long, value_name = "DIR", requires = "calibration", conflicts_with_all = ["script", "participant"])]
    pub images: Option<PathBuf>,
    /// Capture a live V4L2 camera (e.g. /dev/video0) as what the table sees; needs a build with
    /// `--features camera`. Without --calibration its whole picture spans the table.
    #[arg(long, value_name = "DEVICE", conflicts_with_all = ["images", "script", "participant"])]
    pub camera: Option<PathBuf>,
    /// The camera calibration (TOML) for --images or --camera.
    #[arg(long, value_name = "FILE")]
    pub calibration: Option<PathBuf>,
    #[command(flatten)]
    pub screenshot_after: ScreenshotAfter,
    /// Close the window after SECONDS.
    #[arg(long, value_name = "SECONDS", value_parser = parse_seconds)]
    pub quit_after: Option<f32>,
    /// Window size in logical pixels, width x height (default 1280x800).
    #[arg(long, value_name = "WxH", value_parser = screenshot::parse_size)]
    pub window: Option<(u32, u32)>,
    /// Folder for recordings (gestures/) and screenshots (screenshots/).
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Draw at most N frames per second (default: the display's refresh rate).
    #[arg(long, value_name = "N", value_parser = parse_max_fps)]
    pub max_fps: Option<f64>,
    /// Record every touch from the start to FILE, a gesture file that `run --gesture` replays.
    #[arg(long, value_name = "FILE", conflicts_with = "participant")]
    pub record: Option<PathBuf>,
    /// On close, write the run report (JSON, as `run --report` writes it): the objects' final poses.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Participant mode: no panel; the task runs as study trials of this participant (1-based ID).
    #[arg(long, value_name = "ID", value_parser = clap::value_parser!(u32).range(1..), requires = "condition")]
    pub participant: Option<u32>,
    /// Participant mode's condition, e.g. particle:on.
    #[arg(long, value_name = "TECHNIQUE:on|off", value_parser = demo::parse_condition, conflicts_with_all = ["technique", "feedback"])]
    pub condition: Option<(TechniqueKind, bool)>,
    /// Participant mode: trials.csv to append rows to (default out/participants/trials.csv).
    #[arg(long, value_name = "FILE", requires = "participant")]
    pub trials_csv: Option<PathBuf>,
    /// Participant mode: trials in this sitting (default 2).
    #[arg(long, value_name = "N", requires = "participant")]
    pub reps: Option<u32>,
}

/// Exactly one source of hands: a gesture file, a live TUIO stream or
/// recorded camera frames.
#[derive(Debug, Args)]
#[command(group(clap::ArgGroup::new("input").required(true).args(["gesture", "tuio", "images", "list"])))]
pub struct RunArgs {
    /// Scene name under tasks/ or a path to a scene file.
    #[arg(long, required_unless_present = "list")]
    pub task: Option<String>,
    #[arg(long, value_parser = parse_technique, required_unless_present = "list")]
    pub technique: Option<TechniqueKind>,
    /// List the built-in scenes and gestures (usable by name from any
    /// folder) and the registered techniques, then exit.
    #[arg(long, conflicts_with_all = ["task", "technique", "feedback", "report"])]
    pub list: bool,
    /// Record the run as one with the technique's feedback shown (the report's
    /// `feedback` field); the simulation is the same either way.
    #[arg(long)]
    pub feedback: bool,
    /// Gesture to replay: a built-in name (`fingertip_drag`) or a gesture file.
    #[arg(long, value_name = "NAME|FILE")]
    pub gesture: Option<PathBuf>,
    /// Run in real time from TUIO 1.1 or 2.0 over UDP on PORT (default 3333; 0 picks a free port, printed).
    #[arg(long, value_name = "PORT", num_args = 0..=1, default_missing_value = "3333", requires = "seconds")]
    pub tuio: Option<u16>,
    /// Address the TUIO socket binds to (default 127.0.0.1; 0.0.0.0 for a tracker on another machine).
    #[arg(long, value_name = "ADDR", conflicts_with_all = ["gesture", "images"])]
    pub tuio_bind: Option<std::net::IpAddr>,
    /// With --tuio: seconds of real time to run for.
    // Not `requires = "tuio"`: with `--tuio` requiring it back, clap 4
    // let `--gesture F --seconds S` through. One of the two sources is
    // required, so refusing `--gesture` is the same rule.
    #[arg(long, value_name = "S", value_parser = parse_seconds, conflicts_with_all = ["gesture", "images"])]
    pub seconds: Option<f32>,
    /// With --tuio: save what arrived as a gesture file that `run --gesture` replays.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["gesture", "images"])]
    pub record: Option<PathBuf>,
    /// A folder of recorded camera frames (8/16-bit grey PNGs) to play instead of a gesture.
    #[arg(long, value_name = "DIR", requires = "calibration")]
    pub images: Option<PathBuf>,
    /// The camera calibration (TOML) for --images.
    #[arg(long, value_name = "FILE", requires = "images")]
    pub calibration: Option<PathBuf>,
    /// Where to write the JSON report (default: standard output).
    #[arg(long)]
    pub report: Option<PathBuf>,
    /// Seconds simulated after the gesture (or the --tuio run) ends, so released objects settle.
    #[arg(long, default_value_t = 1.0, value_parser = parse_seconds)]
    pub settle: f32,
}

/// A technique name, as in files (`joint`); case and surrounding spaces
/// are ignored, so `--techniques "joint, Proxy"` reads as written.
fn parse_technique(s: &str) -> Result<TechniqueKind, String> {
    s.parse().map_err(|e: crate::pipeline::technique::UnknownTechnique| e.to_string())
}

/// A task name or path from a comma-separated list, spaces around it
/// dropped; whether the scene loads is checked where it is loaded.
fn parse_task_name(s: &str) -> Result<String, String> {
    let t = s.trim();
    if t.is_empty() { Err("empty task name".into()) } else { Ok(t.to_owned()) }
}

/// A finite number of seconds in `0..=scene::bounds::DURATION_S`: a
/// longer run would simulate for hours (`--settle 1e30` never ended).
/// `--screenshot-after SECONDS PATH`: two values of two types under one
/// flag, which clap's per-flag value parser cannot type, so this argument
/// reads its own matches (clap's `FromArgMatches`): a bad SECONDS is a clap
/// error at parse time (exit 2, naming the flag), like every other value.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ScreenshotAfter(pub Option<crate::app::Screenshot>);

const SCREENSHOT_AFTER: &str = "screenshot_after";

impl clap::FromArgMatches for ScreenshotAfter {
    fn from_arg_matches(matches: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let Some(mut values) = matches.get_raw(SCREENSHOT_AFTER) else { return Ok(Self(None)) };
        let invalid = |message: String| {
            clap::Error::raw(
                clap::error::ErrorKind::ValueValidation,
                format!("invalid value for '--screenshot-after <SECONDS> <PATH>': {message}\n"),
            )
        };
        let (Some(seconds), Some(path)) = (values.next(), values.next()) else {
            return Err(invalid("takes SECONDS PATH".into()));
        };
        let seconds = seconds.to_str().ok_or_else(|| invalid("SECONDS is not text".into()))?;
        let after_s = f64::from(parse_seconds(seconds).map_err(invalid)?);
        Ok(Self(Some(crate::app::Screenshot { after_s, path: PathBuf::from(path) })))
    }

    fn update_from_arg_matches(&mut self, matches: &clap::ArgMatches) -> Result<(), clap::Error> {
        if matches.contains_id(SCREENSHOT_AFTER) && matches.get_raw(SCREENSHOT_AFTER).is_some() {
            *self = Self::from_arg_matches(matches)?;
        }
        Ok(())
    }
}

impl clap::Args for ScreenshotAfter {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        cmd.arg(
            clap::Arg::new(SCREENSHOT_AFTER)
                .long("screenshot-after")
                .num_args(2)
                .value_names(["SECONDS", "PATH"])
                .value_parser(clap::value_parser!(std::ffi::OsString))
                .help("Save a PNG of the window once SECONDS have passed"),
        )
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

/// `--max-fps N`: a frame rate from 1 to 1000.
fn parse_max_fps(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("`{s}` is not a number of frames per second"))?;
    if v.is_finite() && (1.0..=1000.0).contains(&v) {
        Ok(v)
    } else {
        Err(format!("`{s}` is out of range (frames per second, 1..=1000)"))
    }
}

fn parse_seconds(s: &str) -> Result<f32, String> {
    let v: f32 = s.parse().map_err(|_| format!("`{s}` is not a number of seconds"))?;
    let max = crate::scene::bounds::DURATION_S;
    if v.is_finite() && (0.0..=max).contains(&v) {
        Ok(v)
    } else {
        Err(format!("`{s}` is out of range (a number of seconds, 0..={max})"))
    }
}

#[derive(Debug, Args)]
#[command(args_conflicts_with_subcommands = true)]
#[expect(clippy::struct_excessive_bools, reason = "each bool is an on/off command-line flag")]
pub struct StudyArgs {
    #[command(subcommand)]
    pub action: Option<StudyAction>,
    /// Output folder (must not already hold a run; use --resume for that).
    #[arg(long, default_value = "out/study")]
    pub out: PathBuf,
    /// Number of participants (default 6, as in the paper).
    #[arg(long)]
    pub participants: Option<u32>,
    /// Study seed: orders, skills and noise all derive from it.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Measured repetitions per condition (default 2).
    #[arg(long)]
    pub reps: Option<u32>,
    /// Comma-separated techniques (default joint,proxy,particle; direct is optional).
    #[arg(long, value_delimiter = ',', value_parser = parse_technique)]
    pub techniques: Option<Vec<TechniqueKind>>,
    /// Comma-separated tasks, in the fixed order they run (default positioning,sorting,steering).
    #[arg(long, value_delimiter = ',', value_parser = parse_task_name)]
    pub tasks: Option<Vec<String>>,
    /// Skip the unmeasured practice trial before each condition.
    #[arg(long)]
    pub no_practice: bool,
    /// Override every task's time limit (seconds); a trial past it counts as failed.
    #[arg(long, value_parser = parse_seconds)]
    pub time_limit: Option<f32>,
    /// Reproduce a run from its run.toml (flags given as well override it).
    #[arg(long)]
    pub from: Option<PathBuf>,
    /// Complete the missing trials of an interrupted run folder.
    #[arg(long, conflicts_with = "from")]
    pub resume: Option<PathBuf>,
    /// Run only shard i of n (0-based), e.g. for a Slurm job array; combine with `study merge`.
    #[arg(long, value_name = "i/n", value_parser = study::parse_shard)]
    pub shard: Option<Shard>,
    /// Worker threads (0 = one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0)]
    pub jobs: usize,
    /// Replay recorded gesture files from this folder instead of scripted participants.
    #[arg(long)]
    pub replay: Option<PathBuf>,
    /// No progress bar.
    #[arg(long)]
    pub no_progress: bool,
    /// Also write every frame of every scripted trial (contacts, technique
    /// bodies, object poses) to `frames/p<participant>_t<order>.csv`.
    #[arg(long)]
    pub frames: bool,
    /// Run N independent studies (study seeds derived from --seed) into
    /// OUT/seed-1 .. OUT/seed-N, then write OUT/findings.csv and OUT/seeds.png.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..), conflicts_with_all = ["resume", "shard"])]
    pub seeds: Option<u32>,
    /// Instead of running: fix run.toml, then write a Slurm job array of N
    /// shards (OUT/slurm/array.sbatch) and its merge job (OUT/slurm/merge.sbatch).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..), conflicts_with_all = ["resume", "shard"])]
    pub slurm: Option<u32>,
    /// With --slurm: submit both scripts with sbatch (the merge after the array, afterok) and print the job ids.
    #[arg(long, requires = "slurm")]
    pub submit: bool,
    /// With --slurm: the Slurm partition (#SBATCH --partition).
    #[arg(long, value_name = "P", requires = "slurm", value_parser = crate::harness::study::slurm::parse_partition)]
    pub partition: Option<String>,
    /// With --slurm: each job's wall-clock limit, HH:MM:SS or D-HH:MM:SS (#SBATCH --time).
    #[arg(long, value_name = "HH:MM:SS", requires = "slurm", value_parser = clap::value_parser!(crate::harness::study::slurm::SlurmTime))]
    pub time: Option<crate::harness::study::slurm::SlurmTime>,
    /// The participants' repertoire restricted, an ablation: a preset
    /// (single-finger, fingertips, one-hand) or comma-separated manners
    /// (`fingertip_1,pinch`). Repeat for several. The study then runs with
    /// the full repertoire and with each restriction, into OUT/full,
    /// `OUT/<restriction>`, ... (each as --seeds N, default 1), and writes
    /// OUT/ablation.csv and OUT/ablation.md: every finding under each.
    #[arg(long, value_name = "PRESET|MANNER,...", conflicts_with_all = ["resume", "shard", "slurm", "replay"])]
    pub manners: Vec<String>,
    /// With --slurm: CPUs per array task (#SBATCH --cpus-per-task); the task runs that many workers.
    #[arg(long, value_name = "C", requires = "slurm", value_parser = clap::value_parser!(u32).range(1..))]
    pub cpus: Option<u32>,
}

#[derive(Debug, Subcommand)]
pub enum StudyAction {
    /// Combine shard folders into one run (trials in order, summary, figure).
    Merge {
        /// Output folder.
        out: PathBuf,
        /// Shard folders.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
    },
    /// Write DIR/findings.csv and DIR/seeds.png from the studies DIR/seed-1, DIR/seed-2, ...
    /// (what `study --seeds N` writes last; the merge job of `--seeds N --slurm M` runs it).
    Findings {
        /// The folder holding seed-1, seed-2, ...
        dir: PathBuf,
    },
}

#[derive(Debug, Args)]
pub struct ScreenshotArgs {
    /// Scene name under tasks/ or a path to a scene file.
    #[arg(long, default_value = "positioning")]
    pub task: String,
    #[arg(long, value_parser = parse_technique, default_value_t = TechniqueKind::PARTICLE)]
    pub technique: TechniqueKind,
    /// Draw the technique's feedback (red joint lines, proxy cubes, particles).
    #[arg(long)]
    pub feedback: bool,
    /// Draw the sensed contact image as a translucent hand shadow over
    /// everything (the default; kept for scripts that ask for it).
    #[arg(long, overrides_with = "no_contact_overlay")]
    pub contact_overlay: bool,
    /// Leave the hands out of the picture.
    #[arg(long)]
    pub no_contact_overlay: bool,
    /// Gesture file to replay before capturing.
    #[arg(long)]
    pub gesture: Option<PathBuf>,
    /// Capture at this many seconds into the gesture (default: its end).
    #[arg(long, value_parser = parse_seconds, requires = "gesture")]
    pub at: Option<f32>,
    /// Image size, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "1024x768", value_parser = screenshot::parse_size)]
    pub size: (u32, u32),
    /// PNG file to write.
    #[arg(long)]
    pub out: PathBuf,
}

#[derive(Debug, Args)]
pub struct CalibrateArgs {
    /// The frames folder; its first frame (name order) gives the image size and bit depth.
    #[arg(long, value_name = "DIR")]
    pub images: PathBuf,
    /// The calibration file to write.
    #[arg(long, value_name = "FILE.toml")]
    pub out: PathBuf,
    /// Where the four table points appear in the image, pixels: "x,y x,y x,y x,y".
    /// Without it a window shows the first frame for four clicks.
    #[arg(long, value_name = "\"x,y x,y x,y x,y\"", value_parser = calibrate::parse_points)]
    pub points: Option<[[f64; 2]; 4]>,
    /// The four table points, metres, same order (default: the table's corners from --task,
    /// far-left, far-right, near-right, near-left).
    #[arg(long, value_name = "\"x,y x,y x,y x,y\"", value_parser = calibrate::parse_points)]
    pub table_points: Option<[[f64; 2]; 4]>,
    /// The scene whose table corners are the default --table-points.
    #[arg(long, default_value = "positioning")]
    pub task: String,
    /// ir or depth (default: depth for 16-bit frames, ir for 8-bit).
    #[arg(long, value_enum)]
    pub kind: Option<crate::input::images::CameraKind>,
    /// ir: a background image, as written into the file (relative to the file's folder).
    #[arg(long, value_name = "FILE")]
    pub background: Option<String>,
    /// ir: grey levels above the background that count as contact (default 40).
    #[arg(long)]
    pub threshold: Option<u8>,
    /// depth: the table's distance from the camera (default: the first frame's median reading).
    #[arg(long, value_name = "MM")]
    pub table_depth_mm: Option<f32>,
    /// depth: heights above the table that touch, "near,far" (default 4,30).
    #[arg(long, value_name = "NEAR,FAR", value_parser = calibrate::parse_band)]
    pub touch_band_mm: Option<[f32; 2]>,
}

#[derive(Debug, Args)]
pub struct SynthImagesArgs {
    /// Scene name under tasks/ or a path to a scene file (its table and frame rate).
    #[arg(long)]
    pub task: String,
    /// The gesture to film.
    #[arg(long)]
    pub gesture: PathBuf,
    /// ir (8-bit, from under the glass) or depth (16-bit millimetres, from above).
    #[arg(long, value_enum, default_value_t = crate::input::images::CameraKind::Ir)]
    pub kind: crate::input::images::CameraKind,
    /// Seed of the sensor noise.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Camera image size, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "640x480", value_parser = screenshot::parse_size)]
    pub size: (u32, u32),
    /// Folder to write frames, calibration.toml and background.png into (created).
    #[arg(long)]
    pub out: PathBuf,
}

#[derive(Debug, Args)]
pub struct ContactArgs {
    /// JSON file with `{"a": [[x,y],...], "b": [[x,y],...]}`, or - for standard input.
    #[arg(default_value = "-")]
    pub input: String,
    /// Accept concave (simple) polygons, by convex decomposition.
    #[arg(long)]
    pub concave: bool,
}

#[derive(Debug, Args)]
pub struct TradeoffArgs {
    #[arg(long, default_value = "out/tradeoff")]
    pub out: PathBuf,
    /// A smaller sweep that finishes in under two minutes.
    #[arg(long)]
    pub quick: bool,
}

#[derive(Debug, Args)]
pub struct BenchArgs {
    #[arg(long, default_value = "out/bench")]
    pub out: PathBuf,
    /// Fewer frames per point and no 10,000-object point (about a minute).
    #[arg(long)]
    pub quick: bool,
    /// Studies of these sizes for the participants curve, each in its own
    /// process on one worker with 5 s trials ("none" leaves the curve out).
    #[arg(long, value_name = "N,N,..", default_value = "6,60", value_parser = parse_participants)]
    pub participants: Participants,
    /// Measure one frame point alone (to run under a profiler), e.g.
    /// `objects=10000`; the curve is one of the four frame curves.
    #[arg(long, value_name = "CURVE=X", value_parser = parse_point)]
    pub point: Option<(Curve, f64)>,
}

fn parse_point(s: &str) -> Result<(Curve, f64), String> {
    let frame_curves = [Curve::Hands, Curve::Objects, Curve::RateHz, Curve::ImageSide];
    let names = frame_curves.map(Curve::name).join(", ");
    let (name, x) = s.split_once('=').ok_or_else(|| format!("`{s}` is not CURVE=X (curves: {names})"))?;
    let curve = frame_curves
        .into_iter()
        .find(|c| c.name() == name)
        .ok_or_else(|| format!("`{name}` is not a frame curve (curves: {names})"))?;
    let (lo, hi) = curve.point_range();
    match x.parse::<f64>() {
        Ok(x) if (lo..=hi).contains(&x) && x.fract() == 0.0 => Ok((curve, x)),
        _ => Err(format!("{name} = `{x}`: not a whole number from {lo} to {hi}")),
    }
}

/// The participants curve's study sizes.
#[derive(Debug, Clone, PartialEq)]
pub struct Participants(pub Vec<u32>);

fn parse_participants(s: &str) -> Result<Participants, String> {
    if s == "none" {
        return Ok(Participants(Vec::new()));
    }
    let max = crate::scene::bounds::MAX_PARTICIPANTS;
    s.split(',')
        .map(|n| match n.trim().parse::<u32>() {
            Ok(n) if (1..=max).contains(&n) => Ok(n),
            _ => Err(format!("`{n}` is not a participant count from 1 to {max}")),
        })
        .collect::<Result<Vec<u32>, String>>()
        .map(Participants)
}

#[derive(Debug, Args)]
pub struct ParticipantsArgs {
    #[command(subcommand)]
    pub action: ParticipantsAction,
}

#[derive(Debug, Subcommand)]
pub enum ParticipantsAction {
    /// Fitts' law: one-finger drags of one puck over a grid of distances and
    /// target widths; writes fitts.csv, fitts.json and fitts.png.
    Fitts(FittsArgs),
}

#[derive(Debug, Args)]
pub struct FittsArgs {
    #[arg(long, value_parser = parse_technique, default_value_t = TechniqueKind::JOINT)]
    pub technique: TechniqueKind,
    /// Output folder.
    #[arg(long, default_value = "out/fitts")]
    pub out: PathBuf,
    /// Simulated participants (default 6).
    #[arg(long, default_value_t = 6)]
    pub participants: u32,
    /// Trials per participant and condition, alternating direction (default 4).
    #[arg(long, default_value_t = 4)]
    pub reps: u32,
    /// Comma-separated distances, metres (default 0.05,0.1,0.2,0.4,0.6).
    #[arg(long, value_delimiter = ',', value_name = "M,M,...")]
    pub distances: Option<Vec<f64>>,
    /// Comma-separated target widths, metres (default 0.005,0.01,0.02,0.04).
    #[arg(long, value_delimiter = ',', value_name = "M,M,...")]
    pub widths: Option<Vec<f64>>,
    /// Skills and noise derive from it, as in a study.
    #[arg(long, default_value_t = 2008)]
    pub seed: u64,
    /// Worker threads (0 = one per core). Results do not depend on it.
    #[arg(long, default_value_t = 0)]
    pub jobs: usize,
}

#[derive(Debug, Args)]
pub struct BehavioursArgs {
    /// Comma-separated techniques (default: every technique but direct).
    #[arg(long, value_delimiter = ',', value_parser = parse_technique)]
    pub techniques: Option<Vec<TechniqueKind>>,
    /// Only the cases whose name contains this text.
    #[arg(long, value_name = "TEXT")]
    pub case: Option<String>,
    /// Runs at a time (0 = one per core).
    #[arg(long, default_value_t = 0)]
    pub jobs: usize,
    /// Exit 1 when a cell fails its expectation.
    #[arg(long)]
    pub check: bool,
}
