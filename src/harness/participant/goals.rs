//! What the goal wants of each object, read from the scene and the tracker
//! (never from the technique): where an object should go, which zone that
//! is, how much work is left, and which objects share a destination.

use crate::scene::{Goal, ObjectId, Scene};
use crate::session::GoalTracker;
use glam::Vec2;

/// Where the goal wants one object now.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Want {
    /// The nearest point the object should reach.
    pub point: Vec2,
    /// Which destination that is (a zone, a target, a waypoint): objects with
    /// the same region may be swept there together; a new region means the
    /// old one was reached.
    pub region: u64,
}

/// Where the goal wants object `id` now, if anywhere.
pub fn want(scene: &Scene, tracker: &GoalTracker, id: ObjectId, observed: &[Vec2]) -> Option<Want> {
    let point_region = |p: Vec2| (u64::from(p.x.to_bits()) << 32) | u64::from(p.y.to_bits());
    match &scene.goal {
        // Soft-body goals concern no rigid object.
        Goal::None | Goal::SoftRegion { .. } | Goal::ClothFlat { .. } | Goal::Torn { .. } => None,
        Goal::Positioning { targets, .. } => targets
            .iter()
            .find(|t| t.object == id && !tracker.is_placed(id))
            .map(|t| Want { point: t.position, region: point_region(t.position) }),
        Goal::Sorting { zones, .. } => {
            let o = scene.object(id);
            let p = *observed.get(id.index())?;
            let mine = || zones.iter().enumerate().filter(|(_, z)| z.color == o.color);
            // A zone holds the whole object (see `session::goal`): the
            // participant, seeing its size, wants its centre that much
            // further in (however it has turned), and a centimetre more.
            let size = o.shape.footprint_radius();
            if mine().any(|(_, z)| {
                inset(z.min, z.max, size + 0.01).is_some_and(|(a, b)| p.cmpge(a).all() && p.cmple(b).all())
            }) {
                return None;
            }
            // The nearest point well inside the nearest zone of its colour:
            // 6 cm in beyond its size, or the zone's middle line where the
            // zone is narrower than that.
            mine()
                .filter_map(|(k, z)| {
                    let room = 0.5 * (z.max - z.min).min_element();
                    inset(z.min, z.max, (size + 0.06).min(room)).map(|(a, b)| (k, p.clamp(a, b)))
                })
                .min_by(|a, b| (a.1 - p).length().total_cmp(&(b.1 - p).length()))
                .map(|(k, point)| Want { point, region: k as u64 })
        }
        Goal::Steering(g) => (g.object == id)
            .then(|| tracker.next_waypoint())
            .flatten()
            .map(|p| Want { point: p, region: point_region(p) }),
        Goal::Gather { center, radius, .. } => {
            let p = *observed.get(id.index())?;
            ((p - *center).length() > radius * 0.7).then_some(Want { point: *center, region: 0 })
        }
        Goal::Region { object, min, max, .. } => {
            (*object == id).then(|| Want { point: (*min + *max) * 0.5, region: 0 })
        }
    }
}

/// How close to its goal point an object must get before the participant
/// lets go (half the goal's own tolerance: aiming for the middle).
pub fn settle_radius(scene: &Scene) -> f32 {
    match &scene.goal {
        Goal::Positioning { targets, .. } => targets.iter().map(|t| t.tolerance).fold(f32::MAX, f32::min) * 0.5,
        Goal::Steering(g) => g.waypoint_radius * 0.5,
        _ => 0.02,
    }
}

/// Objects that still need moving, with what the goal wants of each.
pub fn open_objects(scene: &Scene, tracker: &GoalTracker, active: &[bool], observed: &[Vec2]) -> Vec<(ObjectId, Want)> {
    let settle = settle_radius(scene);
    scene
        .object_ids()
        .take(observed.len())
        .filter(|&id| active.get(id.index()).copied().unwrap_or(false))
        .filter_map(|id| want(scene, tracker, id, observed).map(|w| (id, w)))
        .filter(|(i, w)| (w.point - observed[i.index()]).length() >= settle)
        .collect()
}

/// How far apart (m, centre to centre) two objects bound for the same region
/// may lie and still be moved as one cluster: about a hand's width.
pub const CLUSTER_REACH: f32 = 0.12;

/// The open objects bound for the same region as `seed` and lying within
/// [`CLUSTER_REACH`] of it or of another member (grown from the seed),
/// seed first.
pub fn cluster(open: &[(ObjectId, Want)], observed: &[Vec2], seed: ObjectId) -> Vec<ObjectId> {
    let Some(region) = open.iter().find(|(i, _)| *i == seed).map(|(_, w)| w.region) else {
        return vec![seed];
    };
    let mut members = vec![seed];
    let mut grew = true;
    while grew {
        grew = false;
        for (i, w) in open {
            if w.region == region
                && !members.contains(i)
                && members.iter().any(|&m| (observed[m.index()] - observed[i.index()]).length() <= CLUSTER_REACH)
            {
                members.push(*i);
                grew = true;
            }
        }
    }
    members
}

pub fn inset(min: Vec2, max: Vec2, m: f32) -> Option<(Vec2, Vec2)> {
    let a = min + Vec2::splat(m);
    let b = max - Vec2::splat(m);
    (a.x <= b.x && a.y <= b.y).then_some((a, b))
}

pub fn footprint(scene: &Scene, object: ObjectId) -> f32 {
    scene.object(object).shape.footprint_radius()
}
