//! Live statistics for the panel: rolling means over the last second or so.

use crate::session::StageTimes;
use std::collections::VecDeque;

/// Samples kept per series (about one second at 60 Hz).
const WINDOW: usize = 60;

/// Mean and maximum of the last `WINDOW` samples.
#[derive(Debug, Clone, Default)]
pub struct Rolling {
    samples: VecDeque<f64>,
}

impl Rolling {
    pub fn push(&mut self, v: f64) {
        if self.samples.len() == WINDOW {
            self.samples.pop_front();
        }
        self.samples.push_back(v);
    }

    pub fn mean(&self) -> f64 {
        if self.samples.is_empty() { 0.0 } else { self.samples.iter().sum::<f64>() / self.samples.len() as f64 }
    }
}

/// What the panel shows about timing (milliseconds unless named otherwise).
#[derive(Debug, Clone, Default)]
pub struct FrameStats {
    /// Wall time between frames.
    pub frame_ms: Rolling,
    /// Draw list, 3D render, UI and present.
    pub render_ms: Rolling,
    /// Physics steps run per frame.
    pub steps: Rolling,
    pub rasterize_ms: Rolling,
    pub vision_ms: Rolling,
    pub technique_ms: Rolling,
    pub step_ms: Rolling,
    /// Whole-run totals for the summary printed at exit.
    frames: u64,
    total_frame_ms: f64,
    total_render_ms: f64,
    sim_steps: u64,
    /// The longest frame after [`WARM_UP_MS`], and when it ended (ms into the run).
    worst: Option<(f64, f64)>,
    /// Resident memory (MiB) once the run passed [`MEMORY_SAMPLE_MS`].
    resident_at_1_min: Option<f64>,
}

/// The first seconds of a run build shaders, caches and the panel's fonts;
/// frame times after them are what a user sees from then on.
pub const WARM_UP_MS: f64 = 5_000.0;

/// When the summary's first resident-memory sample is taken: a minute in,
/// once every cache has filled, so that its growth to the end of a long
/// run shows a leak and not the start-up.
pub const MEMORY_SAMPLE_MS: f64 = 60_000.0;

impl FrameStats {
    /// Adds one session step's stage times.
    pub fn push_stages(&mut self, t: &StageTimes) {
        self.rasterize_ms.push(t.rasterize_us / 1000.0);
        self.vision_ms.push(t.vision_us / 1000.0);
        self.technique_ms.push(t.technique_us / 1000.0);
        self.step_ms.push(t.step_us / 1000.0);
    }

    /// Adds one frame's wall time, render time and physics steps.
    pub fn push_frame(&mut self, frame_ms: f64, render_ms: f64, steps: u32) {
        self.frame_ms.push(frame_ms);
        self.render_ms.push(render_ms);
        self.steps.push(f64::from(steps));
        if self.total_frame_ms >= WARM_UP_MS && self.worst.is_none_or(|(worst, _)| frame_ms > worst) {
            self.worst = Some((frame_ms, self.total_frame_ms + frame_ms));
        }
        if self.resident_at_1_min.is_none() && self.total_frame_ms + frame_ms >= MEMORY_SAMPLE_MS {
            self.resident_at_1_min = resident_mib();
        }
        self.frames += 1;
        self.total_frame_ms += frame_ms;
        self.total_render_ms += render_ms;
        self.sim_steps += u64::from(steps);
    }

    /// One line about the whole run: frames and their mean, the worst
    /// frame after the warm-up, and resident memory a minute in and now.
    pub fn summary(&self) -> String {
        let n = self.frames.max(1) as f64;
        let worst = match self.worst {
            Some((ms, at)) => format!("worst frame {ms:.1} ms at {:.1} s", at / 1000.0),
            None => format!("no frame after the {:.0} s warm-up", WARM_UP_MS / 1000.0),
        };
        let memory = match (self.resident_at_1_min, resident_mib()) {
            (Some(then), Some(now)) => format!(
                "resident memory {then:.1} MiB at 1 min, {now:.1} MiB at the end ({:+.1}%)",
                100.0 * (now - then) / then
            ),
            (None, Some(now)) => format!("resident memory {now:.1} MiB at the end"),
            _ => "resident memory unknown".to_owned(),
        };
        format!(
            "{} frames, mean frame {:.1} ms ({:.0} fps), {worst}, render {:.1} ms, {} physics steps ({:.2} per frame), {memory}",
            self.frames,
            self.total_frame_ms / n,
            1000.0 * n / self.total_frame_ms.max(1e-9),
            self.total_render_ms / n,
            self.sim_steps,
            self.sim_steps as f64 / n
        )
    }

    /// Frames per second from the mean frame time.
    pub fn fps(&self) -> f64 {
        let ms = self.frame_ms.mean();
        if ms > 0.0 { 1000.0 / ms } else { 0.0 }
    }
}

/// This process's resident memory (MiB), from `/proc/self/status`
/// (`VmRSS`); `None` where there is no `/proc`.
fn resident_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let kib: f64 =
        status.lines().find_map(|l| l.strip_prefix("VmRSS:"))?.trim().trim_end_matches("kB").trim().parse().ok()?;
    Some(kib / 1024.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rolling_keeps_the_last_window() {
        let mut r = Rolling::default();
        assert_eq!(r.mean(), 0.0);
        for i in 0..100 {
            r.push(f64::from(i));
        }
        assert_eq!(r.mean(), (40..100).sum::<i32>() as f64 / 60.0);
    }

    #[test]
    fn the_summary_names_the_worst_frame_after_the_warm_up() {
        let mut stats = FrameStats::default();
        // A slow first frame (shaders) inside the warm-up does not count.
        stats.push_frame(900.0, 800.0, 1);
        for _ in 0..400 {
            stats.push_frame(20.0, 10.0, 1);
        }
        stats.push_frame(120.0, 100.0, 7);
        stats.push_frame(20.0, 10.0, 1);
        let line = stats.summary();
        // 900 + 400 × 20 + 120 ms: the 120 ms frame ended 9.02 s in.
        assert!(line.contains("403 frames, mean frame 22.4 ms"), "{line}"); // 9040 ms / 403
        assert!(line.contains("worst frame 120.0 ms at 9.0 s"), "{line}");
        assert!(line.contains("resident memory ") && line.contains(" MiB at the end"), "{line}");
        assert!(!line.contains("at 1 min"), "under a minute: {line}");
    }
}
