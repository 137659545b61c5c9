//! Shape hit-testing: which movable objects a contact's outline overlaps
//! on the glass, how deeply, and where.
//!
//! Point hit-testing (a ray through the contact's centroid) "may fail ... if
//! the contact is not compact, as when the user places a large part of
//! their hand on the surface; the centre point may lie outside the target
//! object" (Wilson et al. 2008, "Interactive Surface Input"). A flat hand
//! whose centroid missed a ball grabbed nothing under Joint and put Proxy's
//! body on the table beside it.
//!
//! Both shapes are convex polygons on the table plane as the camera sees
//! it (the glass): the contact's convex hull, and each object's silhouette,
//! the hull of its shape's points projected through the eye
//! ([`World::screen_point`]). A ray through any point inside a silhouette
//! meets that object, so a point found here is one a technique can
//! ray-cast. The overlap depth and witness points come from the Contact
//! Theory entrance block ([`crate::contact::contact_report`]).

use super::surface_point::table_point;
use crate::contact::{ConvexPolygon, Vec2 as CVec2, contact_report};
use crate::pipeline::surface::Sensor;
use crate::pipeline::vision::Contact;
use crate::pipeline::world::{ObjectId, World};
use crate::scene::{Ring, solid_outline};
use glam::Vec2;

/// Points per ring when a round shape's silhouette is sampled: the hull of
/// 24 points on a circle lies within 0.9% of its radius.
const RING: usize = 24;

/// How far (m) inside the object's silhouette a found point is moved, so
/// that the ray through it meets the object rather than grazing its rim.
const INSET: f32 = 0.002;

/// One movable object a contact's outline overlaps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlap {
    pub object: ObjectId,
    /// Penetration depth of the two outlines on the glass (m).
    pub depth: f32,
    /// The point of the overlap nearest the contact's centroid, on the
    /// glass: where a ray meets the object.
    pub point: Vec2,
    /// The middle (area centroid) of the region both outlines cover, on
    /// the glass: the middle of the part of the hand lying over the object.
    pub middle: Vec2,
    /// The middle of the object's silhouette on the glass.
    pub centre: Vec2,
}

/// Every active, dynamic object whose silhouette the contact's `outline`
/// (a convex hull on the glass, metres) overlaps, deepest first.
pub fn overlaps(world: &World, outline: &[Vec2], centroid: Vec2) -> Vec<Overlap> {
    let Some(contact) = polygon(outline) else { return Vec::new() };
    let mut out: Vec<Overlap> = world
        .object_ids()
        .filter(|&id| world.is_movable(id))
        .filter_map(|id| {
            let object = polygon(&silhouette(world, id))?;
            let report = contact_report(&contact, &object);
            (report.distance < 0.0).then(|| Overlap {
                object: id,
                depth: -report.distance as f32,
                point: nearest_common_point(&contact, &object, centroid),
                middle: common_middle(&contact, &object),
                centre: centre(&object),
            })
        })
        .collect();
    out.sort_by(|a, b| b.depth.total_cmp(&a.depth).then(a.object.cmp(&b.object)));
    out
}

/// A contact's convex hull on the glass (metres).
pub fn outline(contact: &Contact, sensor: &Sensor) -> Vec<Vec2> {
    contact.blob.hull.iter().map(|q| table_point(sensor, [q[0] as f32, q[1] as f32])).collect()
}

/// The object's outline as the camera sees it, on the glass (metres).
pub fn silhouette(world: &World, id: ObjectId) -> Vec<Vec2> {
    let pose = world.object_pose(id);
    let shape = world.scene().object(id).shape;
    solid_outline(shape, pose.position, pose.rotation, Ring::on(RING))
        .into_iter()
        .map(|p| world.screen_point(p))
        .collect()
}

/// The convex polygon around `points` (any order); `None` for fewer than
/// three points not on one line: no area to overlap.
fn polygon(points: &[Vec2]) -> Option<ConvexPolygon> {
    use parry2d_f64::math::Vector;
    let pts: Vec<Vector> = points.iter().map(|p| Vector::new(f64::from(p.x), f64::from(p.y))).collect();
    let hull: Vec<CVec2> =
        parry2d_f64::transformation::convex_hull(&pts).into_iter().map(|v| CVec2::new(v.x, v.y)).collect();
    ConvexPolygon::new(&hull).ok()
}

/// The point of `a ∩ b` nearest `c` (approximately: `c` itself when it is
/// in `b`, else the point of `b` nearest `c` when that lies in `a`, else
/// the middle of the deepest penetration's witnesses), moved [`INSET`]
/// into `b`.
fn nearest_common_point(a: &ConvexPolygon, b: &ConvexPolygon, c: Vec2) -> Vec2 {
    let cc = CVec2::new(f64::from(c.x), f64::from(c.y));
    if b.contains(cc) {
        return c;
    }
    let nearest = nearest_on_boundary(b, cc);
    let point = if a.contains(nearest) {
        nearest
    } else {
        let w = contact_report(a, b).witness;
        CVec2::new(0.5 * (w[0].x + w[1].x), 0.5 * (w[0].y + w[1].y))
    };
    let p = Vec2::new(point.x as f32, point.y as f32);
    p + (centre(b) - p).clamp_length_max(INSET)
}

/// The area centroid of `a ∩ b` (both convex, counter-clockwise): `a`
/// clipped by each edge of `b` in turn (Sutherland–Hodgman). An overlap
/// too thin to have an area gives the mean of its clipped points, and one
/// that vanished in rounding the middle of `b`'s part of the penetration.
fn common_middle(a: &ConvexPolygon, b: &ConvexPolygon) -> Vec2 {
    let mut ring: Vec<CVec2> = a.vertices().to_vec();
    let bv = b.vertices();
    for i in 0..bv.len() {
        let (p, q) = (bv[i], bv[(i + 1) % bv.len()]);
        let e = CVec2::new(q.x - p.x, q.y - p.y);
        // Inside is to the left of a counter-clockwise edge.
        let side = |v: CVec2| e.cross(CVec2::new(v.x - p.x, v.y - p.y));
        let mut next = Vec::with_capacity(ring.len() + 1);
        for j in 0..ring.len() {
            let (u, w) = (ring[j], ring[(j + 1) % ring.len()]);
            let (su, sw) = (side(u), side(w));
            if su >= 0.0 {
                next.push(u);
            }
            if (su >= 0.0) != (sw >= 0.0) {
                next.push(u.lerp(w, su / (su - sw)));
            }
        }
        ring = next;
        if ring.is_empty() {
            let w = contact_report(a, b).witness;
            return Vec2::new((0.5 * (w[0].x + w[1].x)) as f32, (0.5 * (w[0].y + w[1].y)) as f32);
        }
    }
    let (mut area, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for j in 0..ring.len() {
        let (u, w) = (ring[j], ring[(j + 1) % ring.len()]);
        let k = u.cross(w);
        area += k;
        cx += (u.x + w.x) * k;
        cy += (u.y + w.y) * k;
    }
    if area.abs() < 1e-12 {
        let n = ring.len() as f64;
        let (sx, sy) = ring.iter().fold((0.0, 0.0), |(x, y), v| (x + v.x, y + v.y));
        return Vec2::new((sx / n) as f32, (sy / n) as f32);
    }
    Vec2::new((cx / (3.0 * area)) as f32, (cy / (3.0 * area)) as f32)
}

/// The mean of a polygon's vertices.
fn centre(p: &ConvexPolygon) -> Vec2 {
    p.vertices().iter().fold(Vec2::ZERO, |s, v| s + Vec2::new(v.x as f32, v.y as f32)) / p.len() as f32
}

/// The point of `p`'s boundary nearest `q`.
fn nearest_on_boundary(p: &ConvexPolygon, q: CVec2) -> CVec2 {
    let v = p.vertices();
    let mut best = (f64::INFINITY, v[0]);
    for i in 0..v.len() {
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len2 = dx * dx + dy * dy;
        let t = if len2 > 0.0 { (((q.x - a.x) * dx + (q.y - a.y) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
        let s = CVec2::new(a.x + t * dx, a.y + t * dy);
        let d = (s.x - q.x).powi(2) + (s.y - q.y).powi(2);
        if d < best.0 {
            best = (d, s);
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::test_scenes::fixture;

    /// A 6 cm ball at (0.1, 0) and a 6 cm box at (-0.2, 0) on an empty table.
    fn world() -> World {
        World::new(&fixture("ball_and_box"))
    }

    fn square(at: Vec2, half: f32) -> Vec<Vec2> {
        [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]
            .iter()
            .map(|[x, y]| at + Vec2::new(*x, *y) * half)
            .collect()
    }

    #[test]
    fn a_hand_whose_centre_misses_the_ball_still_overlaps_it() {
        let w = world();
        // An 8 cm square centred at x = 0.035: its centroid is 3.5 cm short
        // of the ball's near side (the ball spans 0.07..0.13 on the table,
        // a little more on the glass), its right edge, at 0.075, over it.
        let hand = square(Vec2::new(0.035, 0.0), 0.04);
        let found = overlaps(&w, &hand, Vec2::new(0.035, 0.0));
        assert_eq!(found.len(), 1, "{found:?}");
        let o = found[0];
        assert_eq!(o.object, ObjectId::new(0));
        // The ball's near side, 3 cm up, appears at 0.07 × 1.2 / 1.17 =
        // 0.0718 under the 1.2 m eye: the hand's edge reaches 3.2 mm past it.
        assert!((o.depth - 0.0032).abs() < 0.0005, "depth {}", o.depth);
        // The point is on the ball's near side, inside both outlines, and a
        // ray through it meets the ball.
        assert!(o.point.x > 0.06 && o.point.x < 0.075 && o.point.y.abs() < 1e-3, "{:?}", o.point);
        assert_eq!(w.cast_contact_ray(o.point).and_then(|h| h.object), Some(ObjectId::new(0)));
        // The middle of the overlap: the 3.2 mm sliver between the ball's
        // rim and the hand's edge, on the ball's axis.
        assert!(o.middle.x > 0.0718 && o.middle.x < 0.075 && o.middle.y.abs() < 1e-3, "{:?}", o.middle);
    }

    #[test]
    fn the_middle_of_an_overlap_under_a_hand_covering_a_ball_is_over_its_centre() {
        let w = world();
        // A 12 cm square from x = 0.03 to 0.15 covers the ball's silhouette.
        let found = overlaps(&w, &square(Vec2::new(0.09, 0.0), 0.06), Vec2::new(0.04, 0.0));
        assert_eq!(found.len(), 1, "{found:?}");
        let o = found[0];
        // The ball's centre, 3 cm up at x = 0.1, as the 1.2 m eye sees it:
        // 0.1 × 1.2 / 1.17 on the glass.
        let seen = Vec2::new(0.1 * 1.2 / 1.17, 0.0);
        assert!((o.middle - seen).length() < 5e-4, "middle {:?}", o.middle);
        // Its rim point nearest the hand's centroid is about 3 cm off it.
        assert!((o.point - o.centre).length() > 0.025, "{:?}", o.point);
    }

    #[test]
    fn a_centre_inside_an_outline_is_its_own_point_and_far_hands_overlap_nothing() {
        let w = world();
        let found = overlaps(&w, &square(Vec2::new(-0.2, 0.0), 0.01), Vec2::new(-0.2, 0.0));
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].object, found[0].point), (ObjectId::new(1), Vec2::new(-0.2, 0.0)));
        assert!(overlaps(&w, &square(Vec2::new(0.3, 0.3), 0.02), Vec2::new(0.3, 0.3)).is_empty());
        assert!(overlaps(&w, &[Vec2::ZERO, Vec2::X], Vec2::ZERO).is_empty(), "a degenerate outline overlaps nothing");
    }

    #[test]
    fn a_raised_object_is_hit_where_it_appears_not_where_it_stands() {
        // The box's top, 6 cm up and 20 cm from the centre under an eye
        // 1.2 m up, appears 5% further out: its silhouette reaches past
        // its footprint on the far side.
        let w = world();
        let s = silhouette(&w, ObjectId::new(1));
        let far = s.iter().map(|p| p.x).fold(f32::MAX, f32::min);
        assert!(far < -0.23 - 0.005, "the silhouette reaches {far}, past the footprint's -0.23");
    }
}
