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
}

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
        self.frames += 1;
        self.total_frame_ms += frame_ms;
        self.total_render_ms += render_ms;
        self.sim_steps += u64::from(steps);
    }

    /// One line about the whole run.
    pub fn summary(&self) -> String {
        let n = self.frames.max(1) as f64;
        format!(
            "{} frames, mean frame {:.1} ms ({:.0} fps), render {:.1} ms, {} physics steps ({:.2} per frame)",
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
}
