//! What happened to each scene object over a run, beyond where it ends:
//! where it started and how far it tipped on the way. A report of the end
//! state alone cannot tell a cylinder that slid from one that fell over and
//! was stood back up, and someone replaying their own gestures should not
//! have to replay every prefix of a run to find the largest tilt.

use crate::pipeline::world::ObjectPose;
use glam::{Quat, Vec3};

/// One object's start and the extremes of its path so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectTrack {
    pub start_position: Vec3,
    pub start_rotation: Quat,
    /// Largest angle (rad) its body's up axis made with the vertical.
    pub max_tilt: f32,
}

impl ObjectTrack {
    /// A track starting at `pose`.
    pub fn new(pose: &ObjectPose) -> Self {
        ObjectTrack { start_position: pose.position, start_rotation: pose.rotation, max_tilt: tilt(pose.rotation) }
    }

    /// Takes in the pose after a step.
    pub fn update(&mut self, pose: &ObjectPose) {
        self.max_tilt = self.max_tilt.max(tilt(pose.rotation));
    }
}

/// Angle (rad) between a body's up axis, turned by `rotation`, and the
/// vertical.
fn tilt(rotation: Quat) -> f32 {
    (rotation * Vec3::Z).z.clamp(-1.0, 1.0).acos()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(rotation: Quat) -> ObjectPose {
        ObjectPose { position: Vec3::ZERO, rotation, linvel: Vec3::ZERO, angvel: Vec3::ZERO, active: true }
    }

    #[test]
    fn a_turn_about_the_vertical_is_no_tilt_and_the_largest_tilt_is_kept() {
        let mut t = ObjectTrack::new(&pose(Quat::from_rotation_z(1.0)));
        assert!(t.max_tilt.abs() < 1e-6, "{}", t.max_tilt);
        t.update(&pose(Quat::from_rotation_x(0.5)));
        t.update(&pose(Quat::from_rotation_y(-0.2)));
        assert!((t.max_tilt - 0.5).abs() < 1e-5, "{}", t.max_tilt);
        t.update(&pose(Quat::from_rotation_x(std::f32::consts::PI)));
        assert!((t.max_tilt - std::f32::consts::PI).abs() < 1e-3, "upside down: {}", t.max_tilt);
    }
}
