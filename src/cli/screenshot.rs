//! `surfacelab screenshot`: run a scene (replaying a gesture up to a time),
//! then render it off-screen and write a PNG. Needs no display.

use super::ScreenshotArgs;
use super::long_run::Until;
use crate::app::{ViewOptions, fitted_draw_list};
use crate::input::Gesture;
use crate::render::{self, GpuContext};
use crate::scene;
use crate::session::{Session, SessionOptions};
use anyhow::Context;
use std::process::ExitCode;

pub fn run(args: &ScreenshotArgs) -> super::CommandResult {
    let (w, h) = args.size;
    let scene = scene::load(&args.task)?;
    let gesture = args.gesture.as_ref().map(Gesture::load).transpose()?;
    let mut session = Session::new(&scene, args.technique, SessionOptions::default())?;
    // Without a gesture, let the scene settle for a moment; with one, stop
    // at --at (default: its end), the hands still down.
    let at = args.at.map_or_else(|| gesture.as_ref().map_or(0.25, Gesture::duration), f64::from);
    super::long_run::check_work(&scene, at)?;
    let (hands, until) = match &gesture {
        Some(g) => (g, Until::Gesture(at)),
        // No hands: an empty gesture gives none at every step.
        None => (&Gesture::default(), Until::Before(at)),
    };
    let stopped =
        super::long_run::replay_showing_progress(&mut session, hands, until, "screenshot", "draws the picture")?;
    let list = fitted_draw_list(
        &session,
        ViewOptions { feedback: args.feedback, contact_overlay: !args.no_contact_overlay },
        [w, h],
    );
    let gpu = GpuContext::new_headless()?;
    let image = render::render_to_image(&gpu, &list, w, h)?;
    if let Some(dir) = args.out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    render::save_png(&image, &args.out)?;
    eprintln!(
        "surfacelab screenshot: {w}x{h} of {} ({}) at t = {:.2} s on {} -> {}",
        scene.name,
        args.technique,
        session.time(),
        gpu.summary().name,
        args.out.display()
    );
    Ok(if stopped.is_some() { ExitCode::from(super::long_run::EXIT_INTERRUPTED) } else { ExitCode::SUCCESS })
}

/// Parses `WxH` (e.g. 1024x768).
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("`{s}` is not WIDTHxHEIGHT (e.g. 1024x768)"))?;
    let w: u32 = w.trim().parse().map_err(|_| format!("`{s}`: width `{w}` is not a whole number"))?;
    let h: u32 = h.trim().parse().map_err(|_| format!("`{s}`: height `{h}` is not a whole number"))?;
    if !(16..=8192).contains(&w) || !(16..=8192).contains(&h) {
        return Err(format!("`{s}`: each side must be 16..=8192 pixels"));
    }
    Ok((w, h))
}
