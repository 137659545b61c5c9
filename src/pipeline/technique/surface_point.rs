//! From contact-image pixels to points on touched surfaces (paper, Figure 6).

use crate::pipeline::surface::{PixelPoint, PixelVector, Sensor};
use crate::pipeline::world::{RayHit, World};
use glam::{Vec2, Vec3};

/// Table-plane point (m) of a contact-image pixel position.
pub fn table_point(sensor: &Sensor, px: [f32; 2]) -> Vec2 {
    Vec2::from(sensor.to_table(PixelPoint::from(px)))
}

/// A table-plane velocity (m/s) from a per-frame pixel displacement.
pub fn table_velocity(sensor: &Sensor, px_per_frame: [f32; 2], dt: f32) -> Vec2 {
    Vec2::from(sensor.vector_to_table(PixelVector::from(px_per_frame))) / dt
}

/// The least-squares turn (rad per unit of time) of points moving about
/// their centroid: each point's offset from the centroid and its velocity
/// less the mean velocity. A turn `w` moves the offset `(x, y)` at
/// `w * (-y, x)`. `None` when the points have no spread.
pub fn least_squares_turn(points: impl IntoIterator<Item = (Vec2, Vec2)>) -> Option<f32> {
    let (mut num, mut den) = (0.0f32, 0.0f32);
    for (d, dv) in points {
        num += -d.y * dv.x + d.x * dv.y;
        den += d.x * d.x + d.y * d.y;
    }
    (den > 0.0).then(|| num / den)
}

/// Clamps a vector's length.
pub fn clamp_len(v: Vec2, max: f32) -> Vec2 {
    let l = v.length();
    if l > max && l > 0.0 { v * (max / l) } else { v }
}

/// The paper's Figure 6: the image point `x_t` ray-cast to `p_t` with normal
/// `n`; the matched point `x_{t+1}` cast along its own camera ray onto the
/// plane through `p_t` with normal `n` gives `p_{t+1}`. Returns `p_{t+1}`.
pub fn project_flow(world: &World, hit: &RayHit, next: Vec2) -> Vec3 {
    let (o, d) = world.camera_ray(next);
    let denom = d.dot(hit.normal);
    if denom.abs() < 1e-4 {
        // Grazing: fall back to moving within the plane by the table displacement.
        return hit.point + next.extend(0.0) - hit.point.truncate().extend(0.0);
    }
    let t = (hit.point - o).dot(hit.normal) / denom;
    o + d * t
}

/// How far a point at height `z` under a hand moves for each metre the hand
/// moves over the glass: less the nearer the point is to the eye, since
/// both stay on the same camera ray.
pub fn move_at_height(world: &World, z: f32) -> f32 {
    let eye = world.eye().z;
    (eye - z) / eye
}

/// Where a contact's camera ray crosses the horizontal plane at height `z`:
/// the world x/y a body at that height must go to so that it appears under
/// the finger (perspective moves raised things outward on screen).
pub fn at_height(world: &World, table_point: Vec2, z: f32) -> Vec2 {
    let (o, d) = world.camera_ray(table_point);
    if d.z.abs() < 1e-4 {
        return table_point;
    }
    let t = (z - o.z) / d.z;
    (o + d * t).truncate()
}

/// The upward-facing surface a contact stands on: the ray's hit if it faces
/// up, else (a side face of an object) the surface just outside that face,
/// straight below — a finger beside a cylinder stands on the platform.
pub fn support_below(world: &World, table_point: Vec2) -> Option<RayHit> {
    let hit = world.cast_contact_ray(table_point)?;
    if hit.normal.z >= 0.7 {
        return Some(hit);
    }
    let side = Vec3::new(hit.normal.x, hit.normal.y, 0.0).normalize_or_zero();
    let from = hit.point + side * 0.002 + Vec3::Z * 0.001;
    world.cast_ray(from, Vec3::NEG_Z, 100.0).or(Some(hit))
}
