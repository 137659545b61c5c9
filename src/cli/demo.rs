//! `surfacelab demo`: the flags, checked once, turned into the app's
//! [`DemoOptions`]; the window itself is `crate::app`.

use super::{DemoArgs, EXIT_USAGE, Failure};
use crate::app::{self, DemoOptions, ParticipantOptions};
use crate::input::CameraInput;
use crate::input::Gesture;
use crate::input::camera::CameraFeed;
use crate::input::images::{Calibration, ImageSequence};
use crate::pipeline::technique::TechniqueKind;
use clap::Parser;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Default trials file of participant mode.
pub const TRIALS_CSV: &str = "out/participants/trials.csv";
/// Default trials per participant sitting: the paper's two per condition.
pub const REPETITIONS: u32 = 2;

impl Default for DemoArgs {
    /// What `surfacelab` with no arguments runs: the flags' own defaults,
    /// so the two cannot drift apart.
    fn default() -> Self {
        #[derive(Parser)]
        struct Wrapper {
            #[command(flatten)]
            args: DemoArgs,
        }
        Wrapper::parse_from(["surfacelab"]).args
    }
}

pub fn run(args: &DemoArgs) -> super::CommandResult {
    let mut options = match options(args) {
        Ok(o) => o,
        Err(message) => {
            eprintln!("surfacelab demo: {message}");
            return Ok(ExitCode::from(EXIT_USAGE));
        }
    };
    if let Some(device) = &args.camera {
        options.camera = Some(CameraInput::Live(open_camera(device, args.calibration.as_deref())?));
    }
    if !super::doctor::has_display() {
        // The headless job stands in for the window only when the demo was
        // asked for nothing a study cannot do: an input source or a
        // participant sitting needs the window.
        let wants_window = options.camera.is_some()
            || options.tuio.is_some()
            || options.script.is_some()
            || options.participant.is_some();
        if !wants_window {
            return super::headless_main();
        }
        return Err(Failure::from(anyhow::anyhow!(
            "no display answers (see `surfacelab doctor`), and a camera, TUIO, a script or a participant needs the \
             demo window; `surfacelab` with no arguments runs the headless job instead"
        )));
    }
    app::run(options)?;
    Ok(ExitCode::SUCCESS)
}

/// Checks the flags; an `Err` is a usage error (exit 2).
fn options(args: &DemoArgs) -> Result<DemoOptions, String> {
    let (technique, feedback) = args.condition.unwrap_or((args.technique, args.feedback));
    let mut o = DemoOptions::new(args.task.clone(), technique);
    o.feedback = feedback;
    o.contact_overlay = !args.no_contact_overlay;
    if let Some((w, h)) = args.window {
        o.window_size = [w, h];
    }
    o.out_dir.clone_from(&args.out);
    o.tuio = args.tuio.map(|port| SocketAddr::new(args.tuio_bind.unwrap_or(IpAddr::V4(Ipv4Addr::LOCALHOST)), port));
    if let Some(path) = &args.script {
        o.script = Some(Gesture::load(path).map_err(|e| format!("--script: {}", crate::error::chain(&e)))?);
    }
    if let (Some(dir), Some(calibration)) = (&args.images, &args.calibration) {
        let frames =
            ImageSequence::open(dir, calibration).map_err(|e| format!("--images: {}", crate::error::chain(&e)))?;
        o.camera = Some(CameraInput::Recorded(frames));
    } else if args.calibration.is_some() && args.camera.is_none() {
        return Err("--calibration is for --images or --camera".into());
    }
    o.screenshot_after.clone_from(&args.screenshot_after.0);
    o.quit_after = args.quit_after.map(f64::from);
    o.max_fps = args.max_fps;
    o.record.clone_from(&args.record);
    o.report.clone_from(&args.report);
    // clap enforces the pairs (`--participant` requires `--condition`;
    // `--trials-csv` and `--reps` require `--participant`).
    if let (Some(id), Some(_)) = (args.participant, &args.condition) {
        // The participant sees the table and their own hands, not the sensor's image.
        o.contact_overlay = false;
        o.participant = Some(ParticipantOptions {
            id,
            technique,
            feedback,
            repetitions: args.reps.unwrap_or(REPETITIONS).max(1),
            trials_csv: args.trials_csv.clone().unwrap_or_else(|| PathBuf::from(TRIALS_CSV)),
            gestures: Some(args.out.join("gestures")),
        });
    }
    Ok(o)
}

/// `--camera DEVICE [--calibration FILE]`: the calibration read, the
/// device opened and streaming before any window opens, so a wrong path or
/// an unreadable camera is said at once (a missing device or a format
/// surfacelab cannot read is bad input, exit 2; a driver failing, exit 1).
fn open_camera(device: &Path, calibration: Option<&Path>) -> Result<CameraFeed, Failure> {
    let calibration =
        calibration.map(|c| Calibration::load(c).map_err(|e| Failure::from(e).context("--calibration"))).transpose()?;
    CameraFeed::open(device, calibration).map_err(|e| Failure::from(e).context("--camera"))
}

/// `--condition TECHNIQUE:on|off`, e.g. `particle:on` (clap's value
/// parser: its errors name the flag).
pub fn parse_condition(s: &str) -> Result<(TechniqueKind, bool), String> {
    let (t, f) = s.split_once(':').ok_or_else(|| "expected TECHNIQUE:on|off, e.g. particle:on".to_owned())?;
    let technique: TechniqueKind =
        t.parse().map_err(|e: crate::pipeline::technique::UnknownTechnique| e.to_string())?;
    let feedback = match f.trim() {
        "on" => true,
        "off" => false,
        other => return Err(format!("feedback `{other}` must be on or off")),
    };
    Ok((technique, feedback))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::Screenshot;
    use crate::input::tuio::DEFAULT_PORT;

    fn parse(args: &[&str]) -> Result<DemoOptions, String> {
        let cli = super::super::Cli::try_parse_from(
            std::iter::once("surfacelab").chain(std::iter::once("demo")).chain(args.iter().copied()),
        )
        .map_err(|e| e.to_string())?;
        match cli.command {
            Some(super::super::Command::Demo(a)) => options(&a),
            _ => Err("not demo".into()),
        }
    }

    #[test]
    fn defaults_are_the_flags_defaults() {
        let d = DemoArgs::default();
        assert_eq!(d.task, "positioning");
        assert_eq!(d.technique, TechniqueKind::PARTICLE);
        assert!(d.tuio.is_none() && d.participant.is_none());
    }

    #[test]
    fn flags_become_options() {
        let o = parse(&["--tuio", "--task", "sorting"]).expect("valid");
        assert_eq!(o.tuio, Some(SocketAddr::new(IpAddr::V4(Ipv4Addr::LOCALHOST), DEFAULT_PORT)));
        let o = parse(&["--tuio", "4000", "--tuio-bind", "0.0.0.0"]).expect("valid");
        assert_eq!(o.tuio, Some("0.0.0.0:4000".parse().expect("address")));
        let o = parse(&["--screenshot-after", "2.5", "shot.png", "--quit-after", "4"]).expect("valid");
        assert_eq!(o.screenshot_after, Some(Screenshot { after_s: 2.5, path: "shot.png".into() }));
        assert_eq!(o.quit_after, Some(4.0));
        let o = parse(&["--max-fps", "15", "--record", "r.toml", "--report", "r.json"]).expect("valid");
        assert_eq!(o.max_fps, Some(15.0));
        assert_eq!((o.record, o.report), (Some("r.toml".into()), Some("r.json".into())));
        for bad in ["0", "0.5", "fast", "inf"] {
            let e = parse(&["--max-fps", bad]).expect_err("not a frame rate");
            assert!(e.contains("--max-fps"), "{e}");
        }
        assert!(parse(&["--record", "r.toml", "--participant", "1", "--condition", "joint:on"]).is_err());
        let late = parse(&["--screenshot-after", "soon", "shot.png"]).expect_err("not seconds");
        assert!(late.contains("--screenshot-after") && late.contains("`soon` is not a number of seconds"), "{late}");
        assert!(parse(&["--screenshot-after", "2"]).is_err(), "PATH is required");
        assert!(parse(&["--tuio-bind", "0.0.0.0"]).is_err());
        assert!(parse(&["--images", "x"]).is_err(), "--images needs --calibration");
        let missing = parse(&["--images", "no/such/dir", "--calibration", "no/such.toml"]).expect_err("missing");
        assert!(missing.starts_with("--images: no/such.toml: cannot read"), "{missing}");
    }

    #[test]
    fn participant_mode_takes_its_condition() {
        let o = parse(&["--participant", "4", "--condition", "joint:off", "--task", "steering"]).expect("valid");
        let p = o.participant.expect("participant mode");
        assert_eq!((p.id, p.technique, p.feedback, p.repetitions), (4, TechniqueKind::JOINT, false, REPETITIONS));
        assert_eq!(p.trials_csv, PathBuf::from(TRIALS_CSV));
        assert!(!o.contact_overlay);
        assert!(parse(&["--participant", "4"]).is_err());
        assert!(parse(&["--participant", "0", "--condition", "joint:on"]).is_err());
        assert!(parse(&["--reps", "3"]).is_err());
        assert_eq!(parse_condition("particle:on"), Ok((TechniqueKind::PARTICLE, true)));
        assert!(
            parse_condition("particle").is_err()
                && parse_condition("rope:on").is_err()
                && parse_condition("proxy:maybe").is_err()
        );
    }
}
