//! Per-step timing and the health figures reports need.

/// Timing of the last step.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StepStats {
    pub step_us: f64,
}

/// Figures accumulated over a world's life.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct WorldStats {
    pub steps: u64,
    pub total_step_us: f64,
    /// Highest linear speed of any dynamic scene object seen after a step (m/s), before capping.
    pub max_speed_seen: f32,
    /// Deepest contact penetration seen (m, positive), when measured.
    pub max_penetration_seen: f32,
    /// Steps after which some body had a non-finite state (rapier quarantines it).
    pub nan_count: u64,
    /// Number of times a speed had to be capped.
    pub speed_caps: u64,
}

impl WorldStats {
    pub fn mean_step_us(&self) -> f64 {
        if self.steps == 0 { 0.0 } else { self.total_step_us / self.steps as f64 }
    }
}
