//! The participants curve: a whole study in a child process, for its wall
//! time and its peak resident memory, which only a process of its own
//! reports cleanly (the parent's high-water mark holds the frame curves').

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// Each trial's time limit (s): short trials keep the curve's large end
/// within an hour; the cost per trial, not the task, is what grows.
pub const TRIAL_LIMIT_S: u32 = 5;

/// Runs `exe study --participants n` on one worker into `dir` and returns
/// (wall s, peak resident MB), the peak read from `/proc` as the child runs.
pub fn measure_study(exe: &Path, n: u32, dir: &Path) -> anyhow::Result<(f64, f64)> {
    let out = dir.join(format!("study-{n}"));
    if out.exists() {
        std::fs::remove_dir_all(&out)?;
    }
    let t0 = Instant::now();
    let mut child = Command::new(exe)
        .args(["study", "--participants", &n.to_string(), "--time-limit", &TRIAL_LIMIT_S.to_string()])
        .args(["--jobs", "1", "--no-progress", "--out"])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()?;
    let status_file = format!("/proc/{}/status", child.id());
    let mut peak_kb = 0u64;
    let status = loop {
        // VmHWM is the high-water mark: the last reading before the child
        // exits holds every earlier peak.
        if let Ok(text) = std::fs::read_to_string(&status_file) {
            peak_kb = peak_kb.max(vm_hwm_kb(&text).unwrap_or(0));
        }
        if let Some(status) = child.try_wait()? {
            break status;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let wall = t0.elapsed().as_secs_f64();
    anyhow::ensure!(status.success(), "the {n}-participant study exited with {status}");
    std::fs::remove_dir_all(&out)?;
    Ok((wall, peak_kb as f64 / 1024.0))
}

/// `VmHWM` of a `/proc/PID/status` text, kB.
fn vm_hwm_kb(status: &str) -> Option<u64> {
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
}

#[cfg(test)]
mod tests {
    use super::vm_hwm_kb;

    #[test]
    fn the_high_water_mark_is_read_from_a_status_text() {
        let text = "Name:\tsurfacelab\nVmPeak:\t  300000 kB\nVmHWM:\t   28716 kB\nVmRSS:\t   27000 kB\n";
        assert_eq!(vm_hwm_kb(text), Some(28_716));
        assert_eq!(vm_hwm_kb("Name:\tx\n"), None);
    }
}
