//! Running one case under one technique and measuring what happened.

use super::case::{Axis, Case, Metric};
use super::cases::GATHER_RADIUS;
use crate::input::{Gesture, GestureError};
use crate::pipeline::technique::TechniqueKind;
use crate::scene::{self, BodyKind, SceneError};
use crate::session::{Session, SessionError, SessionOptions};
use glam::Vec2;
use std::collections::BTreeMap;
use std::path::Path;

#[derive(Debug, thiserror::Error)]
pub enum BehaviourError {
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Gesture(#[from] GestureError),
    #[error(transparent)]
    Session(#[from] SessionError),
    #[error("behaviour `{case}`: scene {scene} has no object `{object}`")]
    NoObject { case: String, scene: String, object: String },
    #[error("behaviour `{case}`: gesture {gesture} has no hands")]
    NoHands { case: String, gesture: String },
}

impl crate::error::Kind for BehaviourError {
    /// Cases are data (scene and gesture files): a case that does not fit
    /// them is bad input, as is any error of the files themselves.
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            BehaviourError::Scene(e) => e.kind(),
            BehaviourError::Gesture(e) => e.kind(),
            BehaviourError::Session(e) => e.kind(),
            BehaviourError::NoObject { .. } | BehaviourError::NoHands { .. } => crate::error::ErrorKind::BadInput,
        }
    }
}

/// What one run measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    pub case: &'static str,
    pub technique: TechniqueKind,
    pub values: BTreeMap<Metric, f32>,
    /// NaN seen in the world (always a failure).
    pub nan_count: u64,
}

impl Measurement {
    /// The value of `m` (NaN when it was not measured).
    pub fn get(&self, m: Metric) -> f32 {
        self.values.get(&m).copied().unwrap_or(f32::NAN)
    }
}

/// Yaw rate integration and per-frame extremes of the measured object.
#[derive(Debug, Default)]
struct Track {
    yaw_rad: f32,
    max_lift: f32,
    max_drop: f32,
    max_along: f32,
    max_overlap: f32,
    end_speed: f32,
    back_speed: f32,
}

/// Runs `case` under `kind` (files relative to `root`) and measures it.
pub fn run_case(case: &Case, kind: TechniqueKind, root: &Path) -> Result<Measurement, BehaviourError> {
    let scene_path = root.join(case.scene);
    let scene = scene::load(&scene_path.to_string_lossy())?;
    let gesture = Gesture::load(root.join(case.gesture))?;
    let object = scene.object_id(case.object).ok_or_else(|| BehaviourError::NoObject {
        case: case.name.to_string(),
        scene: case.scene.to_string(),
        object: case.object.to_string(),
    })?;
    let lead = gesture
        .tracks()
        .first()
        .ok_or_else(|| BehaviourError::NoHands { case: case.name.to_string(), gesture: case.gesture.to_string() })?;
    let at = |k: &crate::input::Key| Vec2::new(k.pos[0] as f32, k.pos[1] as f32);
    let (Some(first_key), Some(last_key)) = (lead.keys().first(), lead.keys().last()) else {
        return Err(BehaviourError::NoHands { case: case.name.to_string(), gesture: case.gesture.to_string() });
    };
    let hand_start = at(first_key);
    let hand_move = at(last_key) - hand_start;
    let axis = match case.axis {
        Axis::Hand => hand_move.normalize_or_zero(),
        Axis::Fixed(d) => Vec2::from(d).normalize_or_zero(),
    };
    let wants_overlap = case.metrics().contains(&Metric::MaxOverlap);

    let mut s = Session::new(&scene, kind, SessionOptions::default())?;
    let start = s.world().object_pose(object);
    // The object point the first hand first touches (its ray hit), in the object's frame.
    let pinned = s
        .world()
        .cast_contact_ray(hand_start)
        .filter(|h| h.object == Some(object))
        .map(|h| (h.point, start.rotation.inverse() * (h.point - start.position)));
    let dt = f64::from(s.world().dt());
    let mut t = Track { max_along: f32::MIN, ..Track::default() };
    let mut prev_rotation = start.rotation;
    let end = gesture.duration() + case.settle_s;
    while s.time() + 0.5 * dt < end {
        let hands = gesture.sample(s.time());
        s.step(&hands)?;
        let p = s.world().object_pose(object);
        t.yaw_rad += turn_about_vertical(prev_rotation, p.rotation);
        prev_rotation = p.rotation;
        t.max_lift = t.max_lift.max(p.position.z - start.position.z);
        t.max_drop = t.max_drop.max(start.position.z - p.position.z);
        t.max_along = t.max_along.max((p.position - start.position).truncate().dot(axis));
        t.back_speed = t.back_speed.max(-p.linvel.truncate().dot(axis));
        if wants_overlap {
            t.max_overlap = t.max_overlap.max(s.world().max_object_overlap());
        }
        if s.time() <= gesture.duration() + 0.5 * dt {
            t.end_speed = p.linvel.truncate().length();
        }
    }
    let last = s.world().object_pose(object);
    let moved = (last.position - start.position).truncate();
    let along = moved.dot(axis);
    let hand_along = hand_move.dot(axis);
    let mut values = BTreeMap::new();
    values.insert(Metric::Along, along);
    values.insert(Metric::Carry, if hand_along.abs() > 1e-6 { along / hand_along } else { f32::NAN });
    values.insert(Metric::FollowError, (moved - hand_move).length());
    let across = (moved - axis * along).length();
    values.insert(Metric::Across, across);
    // Under a millimetre forward, any sideways motion is all veer.
    let veer = if along > 1e-3 {
        across / along
    } else if across > 1e-3 {
        f32::INFINITY
    } else {
        f32::NAN
    };
    values.insert(Metric::Veer, veer);
    values.insert(Metric::Yaw, t.yaw_rad.to_degrees());
    // The session tracks every object's largest tilt (the run report's
    // `max_tilt_deg`); read, not tracked a second time.
    values.insert(Metric::MaxTilt, s.object_tracks()[object.index()].max_tilt.to_degrees());
    values.insert(Metric::MaxLift, t.max_lift);
    values.insert(Metric::MaxDrop, t.max_drop);
    values.insert(Metric::MaxAlong, t.max_along);
    values.insert(Metric::Bounce, t.back_speed);
    values.insert(Metric::EndSpeed, t.end_speed);
    let drift = pinned.map_or(f32::NAN, |(at, local)| {
        let now = last.position + last.rotation * local;
        (now - at).truncate().length()
    });
    values.insert(Metric::PinDrift, drift);
    if wants_overlap {
        values.insert(Metric::MaxOverlap, t.max_overlap);
    }
    values.insert(Metric::Gathered, gathered(&s, &scene));
    Ok(Measurement { case: case.name, technique: kind, values, nan_count: s.world().stats().nan_count })
}

/// The turn (rad, counter-clockwise) about the vertical from `from` to
/// `to`: the twist about z of the step's rotation `to · from⁻¹`, in
/// (−π, π]. Summed step by step it counts whole turns and a ball's spin.
///
/// Taken from the poses, not from the angular velocity: rapier moves a
/// body by its solver velocities including the stabilisation's bias and
/// stores the velocity without it, so `angvel · dt` summed is not the turn
/// the body made. The box of the slow two-finger twist under Proxy turns
/// 81.6° by its poses while its angular velocity sums to 38.7°; under
/// Joint 85.3° against 98.8° (`docs/design/world-and-effects.md`).
fn turn_about_vertical(from: glam::Quat, to: glam::Quat) -> f32 {
    let d = to * from.inverse();
    let twist = 2.0 * d.z.atan2(d.w);
    // q and −q are the same rotation: bring the twist into (−π, π].
    if twist > std::f32::consts::PI {
        twist - std::f32::consts::TAU
    } else if twist <= -std::f32::consts::PI {
        twist + std::f32::consts::TAU
    } else {
        twist
    }
}

/// Share of the dynamic scene objects whose centre lies within
/// [`GATHER_RADIUS`] of the table centre.
fn gathered(s: &Session, scene: &crate::scene::Scene) -> f32 {
    let dynamic: Vec<_> = scene.object_ids().filter(|&id| scene.object(id).body == BodyKind::Dynamic).collect();
    if dynamic.is_empty() {
        return f32::NAN;
    }
    let inside =
        dynamic.iter().filter(|&&id| s.world().object_pose(id).position.truncate().length() <= GATHER_RADIUS).count();
    inside as f32 / dynamic.len() as f32
}

/// Runs every case under every technique, `jobs` runs at a time (each run is
/// deterministic and independent, so the order of work changes nothing);
/// outcomes come back in case-major order.
pub fn run_suite(
    cases: &[Case],
    kinds: &[TechniqueKind],
    root: &Path,
    jobs: usize,
) -> Result<Vec<Measurement>, BehaviourError> {
    let work: Vec<(&Case, TechniqueKind)> = cases.iter().flat_map(|c| kinds.iter().map(move |k| (c, *k))).collect();
    crate::harness::pool::map_in_order(&work, jobs, |&(case, kind)| run_case(case, kind, root)).into_iter().collect()
}

#[cfg(test)]
mod tests {
    use super::turn_about_vertical;
    use glam::{Quat, Vec3};

    fn deg(q0: Quat, q1: Quat) -> f32 {
        turn_about_vertical(q0, q1).to_degrees()
    }

    #[test]
    fn a_turn_is_the_twist_about_the_vertical_between_two_poses() {
        let yaw = |d: f32| Quat::from_rotation_z(d.to_radians());
        assert!((deg(yaw(10.0), yaw(40.0)) - 30.0).abs() < 1e-3);
        assert!((deg(yaw(40.0), yaw(10.0)) + 30.0).abs() < 1e-3);
        // Across ±180°, and with the sign of the quaternion flipped: the short way.
        assert!((deg(yaw(170.0), yaw(-170.0)) - 20.0).abs() < 1e-3);
        assert!((deg(yaw(5.0), -yaw(8.0)) - 3.0).abs() < 1e-3);
        // A roll about a horizontal axis is no turn; one on top of a turn leaves it.
        let roll = Quat::from_axis_angle(Vec3::X, 0.3);
        assert!(deg(Quat::IDENTITY, roll).abs() < 1e-3);
        assert!((deg(yaw(20.0), roll * yaw(20.0) * Quat::from_rotation_z(0.01)) - 0.573).abs() < 0.01);
    }
}
