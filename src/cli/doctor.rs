//! `surfacelab doctor`: what this machine offers the app.

use std::process::ExitCode;

/// True when a window can be opened (an X11 or Wayland display is set).
pub fn has_display() -> bool {
    ["WAYLAND_DISPLAY", "DISPLAY"].iter().any(|v| std::env::var(v).is_ok_and(|s| !s.is_empty()))
}

pub fn run() -> ExitCode {
    println!("surfacelab {}", env!("CARGO_PKG_VERSION"));
    let display = match (std::env::var("WAYLAND_DISPLAY"), std::env::var("DISPLAY")) {
        (Ok(w), _) if !w.is_empty() => format!("yes (Wayland {w})"),
        (_, Ok(d)) if !d.is_empty() => format!("yes (X11 {d})"),
        _ => "none (DISPLAY and WAYLAND_DISPLAY unset): the demo needs one; run, study, screenshot and tradeoff do not"
            .to_string(),
    };
    println!("display: {display}");
    match crate::render::gpu::probe_adapter() {
        Ok(a) => {
            println!("adapter: {}", a.name);
            println!("backend: {:?}", a.backend);
            println!("device type: {:?}", a.device_type);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("adapter: none\nsurfacelab doctor: {e}");
            ExitCode::FAILURE
        }
    }
}
