//! `surfacelab doctor`: what this machine offers the app.

use super::display::Display;
use std::process::ExitCode;

/// True when a window can be opened: a display server answers.
pub fn has_display() -> bool {
    super::display::probe().is_live()
}

pub fn run() -> super::CommandResult {
    outln!("surfacelab {}", env!("CARGO_PKG_VERSION"))?;
    let display = match super::display::probe() {
        Display::Live(what) => format!("yes ({what})"),
        Display::Dead(why) => format!("none ({why}): the demo needs one; run, study, screenshot and tradeoff do not"),
        Display::Unset => {
            "none (DISPLAY and WAYLAND_DISPLAY unset): the demo needs one; run, study, screenshot and tradeoff do not"
                .to_string()
        }
    };
    outln!("display: {display}")?;
    match crate::render::probe_adapter() {
        Ok(a) => {
            outln!("adapter: {}", a.name)?;
            outln!("backend: {:?}", a.backend)?;
            outln!("device type: {:?}", a.device_type)?;
            Ok(ExitCode::SUCCESS)
        }
        Err(e) => {
            eprintln!("adapter: none\nsurfacelab doctor: {e}");
            Ok(ExitCode::FAILURE)
        }
    }
}
