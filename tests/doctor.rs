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
