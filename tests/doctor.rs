//! `surfacelab doctor` finds the GPU adapter (lavapipe on a machine with none).

use std::process::Command;

#[test]
fn doctor_names_the_adapter_and_version() {
    let out = Command::new(env!("CARGO_BIN_EXE_surfacelab")).arg("doctor").output().expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "doctor found no GPU adapter. Install Mesa's software Vulkan driver: \
         `sudo apt-get install mesa-vulkan-drivers libvulkan1`.\nstdout: {stdout}\nstderr: {stderr}"
    );
    assert!(stdout.contains(env!("CARGO_PKG_VERSION")), "{stdout}");
    let adapter = stdout.lines().find_map(|l| l.strip_prefix("adapter: ")).expect("adapter line");
    assert!(!adapter.trim().is_empty());
    assert!(stdout.contains("device type:"), "{stdout}");
    if stdout.contains("device type: Cpu") {
        assert!(adapter.contains("llvmpipe"), "a CPU adapter here is Mesa lavapipe, got {adapter}");
    }
}

#[test]
fn help_lists_the_contract() {
    let out = Command::new(env!("CARGO_BIN_EXE_surfacelab")).arg("--help").output().expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    for cmd in ["demo", "run", "study", "screenshot", "contact", "tradeoff", "doctor"] {
        assert!(stdout.contains(cmd), "--help lists {cmd}:\n{stdout}");
    }
}

fn doctor_display(display: &str) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_surfacelab"))
        .arg("doctor")
        .env("DISPLAY", display)
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    stdout.lines().find(|l| l.starts_with("display: ")).expect("a display line").to_owned()
}

/// A `DISPLAY` with no server behind it is no display; one with a
/// live Xvfb is. (Xvfb comes from `.ci/setup`.)
#[test]
fn doctor_connects_to_the_display_instead_of_trusting_the_variable() {
    let line = doctor_display(":6553");
    assert!(line.starts_with("display: none (X11 :6553: nothing answers at /tmp/.X11-unix/X6553"), "{line}");

    let number = 6100 + std::process::id() % 400;
    let mut xvfb = Command::new("Xvfb")
        .args([format!(":{number}"), "-nolisten".into(), "tcp".into()])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("Xvfb is installed (bash .ci/setup)");
    let socket = format!("/tmp/.X11-unix/X{number}");
    let started = std::time::Instant::now();
    while !std::path::Path::new(&socket).exists() && started.elapsed().as_secs() < 20 {
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let line = doctor_display(&format!(":{number}"));
    // SIGTERM, not `kill()`'s SIGKILL: Xvfb then removes its lock file and
    // socket, which SIGKILL left behind in /tmp on every run.
    let _ = Command::new("kill").args(["-TERM", &xvfb.id().to_string()]).status();
    let _ = xvfb.wait();
    assert_eq!(line, format!("display: yes (X11 :{number})"));
}
