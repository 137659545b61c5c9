//! The health figures reports need. (A step's time is measured by the
//! session, which times every stage of a frame alike.)

/// Figures accumulated over a world's life.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct WorldStats {
    pub steps: u64,
    /// Highest linear speed of any dynamic scene object seen after a step (m/s), before capping.
    pub max_speed_seen: f32,
    /// Deepest contact penetration seen (m, positive), when measured.
    pub max_penetration_seen: f32,
    /// Steps after which some body had a non-finite state (rapier quarantines it).
    pub nan_count: u64,
    /// Number of times a speed had to be capped.
    pub speed_caps: u64,
}
