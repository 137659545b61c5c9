//! `surfacelab run`: replay one gesture headless, run in real time from a
//! live TUIO stream, or play recorded camera frames (`run_images.rs`), and
//! write a JSON report.

use super::RunArgs;
use crate::app::Recording;
use crate::input::tuio::{DEFAULT_PORT, TuioListener};
use crate::input::{Gesture, quantized};
use crate::scene;
use crate::session::{RunReport, Session, SessionOptions};
use anyhow::Context;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::process::ExitCode;
use std::time::{Duration, Instant};

pub fn run(args: &RunArgs) -> super::CommandResult {
    if args.list {
        out!("{}", listing())?;
        return Ok(std::process::ExitCode::SUCCESS);
    }
    // clap requires both unless --list is given.
    let (Some(task), Some(technique)) = (args.task.as_deref(), args.technique) else {
        eprintln!("surfacelab run: --task and --technique are required");
        return Ok(std::process::ExitCode::from(super::EXIT_USAGE));
    };
    if let (Some(dir), Some(calibration)) = (&args.images, &args.calibration) {
        let report = super::run_images::play(args, task, technique, dir, calibration)?;
        return write_report(&report, args.report.as_deref());
    }
    let scene = scene::load(task)?;
    let options = SessionOptions { measure_penetration: true, ..SessionOptions::default() };
    let mut session = Session::new(&scene, technique, options)?;
    let t0 = Instant::now();
    let mut stopped_at = None;
    let source = match (&args.gesture, args.tuio) {
        (Some(path), _) => {
            let gesture = Gesture::load(path)?;
            // The whole gesture, then a short settle so released objects come to rest.
            let until = gesture.duration() + f64::from(args.settle);
            super::long_run::check_work(&scene, until)?;
            stopped_at = super::long_run::replay_showing_progress(
                &mut session,
                &gesture,
                super::long_run::Until::Gesture(until),
                "run",
                "writes the report",
            )?;
            path.display().to_string()
        }
        (None, port) => {
            super::long_run::check_work(&scene, f64::from(args.seconds.unwrap_or(0.0) + args.settle))?;
            let addr = SocketAddr::new(
                args.tuio_bind.unwrap_or(IpAddr::V4(Ipv4Addr::LOCALHOST)),
                port.unwrap_or(DEFAULT_PORT),
            );
            let listened = live(&mut session, addr, args)?;
            let settle_until = session.time() + f64::from(args.settle);
            session.replay_until(&Gesture::default(), settle_until)?;
            format!("tuio:{listened}")
        }
    };
    let mut report = RunReport::from_session(&session, args.feedback, &source, t0.elapsed().as_secs_f64());
    let Some((at, until)) = stopped_at else {
        return write_report(&report, args.report.as_deref());
    };
    if !report.completion.complete {
        report.completion.incomplete = Some(format!("stopped by Ctrl-C at {at:.2} s of {until:.2} s"));
    }
    write_report(&report, args.report.as_deref())?;
    Ok(ExitCode::from(super::long_run::EXIT_INTERRUPTED))
}

/// "packet to contact image: mean …, 99th percentile …, max … ms (one frame
/// is … ms)" over the packets' waits, `None` without packets. A packet
/// waits for the next step at or after it arrives (half a frame on
/// average at a steady rate), and longer when steps run late.
fn latency_line(waits: &mut [Duration], dt: f64) -> Option<String> {
    if waits.is_empty() {
        return None;
    }
    waits.sort_unstable();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let mean = waits.iter().map(|&d| ms(d)).sum::<f64>() / waits.len() as f64;
    let p99 = waits[(waits.len() * 99).div_ceil(100) - 1];
    Some(format!(
        "packet to contact image over {} packets: mean {mean:.1} ms, 99th percentile {:.1} ms, max {:.1} ms (one frame is {:.1} ms)",
        waits.len(),
        ms(p99),
        ms(waits[waits.len() - 1]),
        dt * 1e3
    ))
}

/// The report as JSON, to `path` (atomically) or standard output.
fn write_report(report: &RunReport, path: Option<&std::path::Path>) -> super::CommandResult {
    let Some(path) = path else {
        let json = serde_json::to_string_pretty(report).context("writing the JSON report")?;
        outln!("{json}")?;
        return Ok(ExitCode::SUCCESS);
    };
    report.save(path).with_context(|| format!("writing report {}", path.display()))?;
    let why = report.completion.incomplete.as_deref().map_or_else(String::new, |w| format!(" ({w})"));
    eprintln!(
        "surfacelab run: {} steps, complete: {}{why}, max speed {:.2} m/s, NaN {}; report in {}",
        report.steps,
        report.completion.complete,
        report.max_speed,
        report.nan_count,
        path.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Steps `session` in real time for `--seconds` from the TUIO stream on
/// `addr`, and saves `--record`; returns the address listened on.
///
/// Step k runs at wall time `k · dt` after the start and takes the hands
/// as the tracker had them at that instant (between the packets before
/// and after it, see [`crate::input::tuio::Timeline`]), so the session
/// keeps the scene's fixed rate against the wall clock; when a step runs
/// late the next ones catch up back to back, each still at its own time.
/// The hands pass through [`quantized`], as a recording stores them, so
/// replaying the recording steps the physics with the same hands.
fn live(session: &mut Session, addr: SocketAddr, args: &RunArgs) -> anyhow::Result<SocketAddr> {
    let listener = TuioListener::bind(addr).with_context(|| format!("--tuio: cannot listen on UDP {addr}"))?;
    let listened = listener.local_addr();
    let shown = args.seconds.unwrap_or(0.0);
    let seconds = f64::from(shown);
    // As given (0.2, not the f32's 0.20000000298023224).
    eprintln!("surfacelab run: listening for TUIO on {listened} for {shown} s");
    let table = [session.scene().table.width, session.scene().table.depth];
    let dt = f64::from(session.world().dt());
    let steps = (seconds / dt).round() as u64;
    let mut recording = args.record.clone().map(Recording::new);
    // How long each packet waited for the step that drew its contact image.
    let mut waits: Vec<Duration> = Vec::new();
    let start = Instant::now();
    for k in 0..steps {
        let due = start + Duration::from_secs_f64(k as f64 * dt);
        if let Some(wait) = due.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
        let hands: Vec<_> = listener.hands_at(table, due).iter().map(quantized).collect();
        let sampled = Instant::now();
        waits.extend(listener.take_arrivals(due).into_iter().map(|a| sampled.saturating_duration_since(a)));
        let t = session.time();
        session.step(&hands)?;
        if let Some(r) = &mut recording {
            r.record(t, &hands);
        }
    }
    let stats = listener.stats();
    eprintln!(
        "surfacelab run: {} TUIO packets ({} malformed, {} late frames, {} restarts)",
        stats.packets, stats.malformed, stats.late_frames, stats.restarts
    );
    if stats.packets == 0 {
        eprintln!("surfacelab run: no TUIO packet arrived on {listened}");
    }
    if let Some(line) = latency_line(&mut waits, dt) {
        eprintln!("surfacelab run: {line}");
    }
    if let Some(r) = recording {
        let (path, gesture) = r.save()?;
        eprintln!("surfacelab run: recorded {} hand entries in {}", gesture.tracks().len(), path.display());
    }
    Ok(listened)
}

/// What `run --list` prints: every name `--task`, `--gesture` and
/// `--technique` take without a path.
fn listing() -> String {
    use crate::pipeline::technique::TechniqueKind;
    use crate::scene::builtin;
    let scenes: Vec<&str> = builtin::scene_names().collect();
    let cases: Vec<&str> = builtin::FILES
        .iter()
        .filter_map(|(rel, _)| rel.strip_prefix("tasks/")?.strip_suffix(".toml"))
        .filter(|n| n.contains('/'))
        .collect();
    let gestures: Vec<&str> = builtin::gesture_names().filter(|n| !n.contains('/')).collect();
    let techniques: Vec<&str> = TechniqueKind::registered().iter().map(|k| k.name()).collect();
    format!(
        "scenes (--task): {}\nscenes for tests and behaviours (--task): {}\ngestures (--gesture): {}\n\
         behaviour gestures (--gesture): behaviours/NAME, {} of them\ntechniques (--technique): {}\n",
        scenes.join(", "),
        cases.join(", "),
        gestures.join(", "),
        builtin::gesture_names().filter(|n| n.contains('/')).count(),
        techniques.join(", "),
    )
}
