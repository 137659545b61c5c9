//! From a running session to a [`DrawList`]: the one place that knows how a
//! scene, its goal and a technique's feedback look. The demo, `screenshot`
//! and the golden-image tests all draw through it.

use crate::render::{
    Camera, ContactOverlay, Decal, DeformableDraw, DrawList, FeedbackDraw, MeshKind, ObjectDraw, Rgba, TableDraw,
};
use crate::scene::{Goal, Scene, Shape};
use crate::session::Session;
use glam::{Mat4, Vec2, Vec3};

pub use crate::render::{FEEDBACK_RED, TARGET_RED, WAYPOINT_BLUE};

/// What to show besides the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ViewOptions {
    /// The technique's feedback geometry (joint lines, proxy cubes, particles).
    pub feedback: bool,
    /// The sensed contact image as a translucent hand shadow.
    pub contact_overlay: bool,
}

/// The camera a scene asks for: straight above the table centre, its
/// field of view fitting the table's depth.
pub fn scene_camera(scene: &Scene) -> Camera {
    Camera { eye: scene.camera.eye(), target: Vec3::ZERO, up: Vec3::Y, fov_y_deg: scene.camera.fov_y_deg(&scene.table) }
}

/// How one object of a scene is drawn at a pose.
pub fn object_draw(shape: Shape, pose: Mat4, color: Rgba) -> ObjectDraw {
    let (mesh, scale) = match shape {
        Shape::Box { half_extents } => (MeshKind::Box, half_extents * 2.0),
        Shape::Sphere { radius } => (MeshKind::Sphere, Vec3::splat(radius)),
        Shape::Cylinder { radius, half_height } => (MeshKind::Cylinder, Vec3::new(radius, radius, half_height * 2.0)),
        Shape::Capsule { radius, half_height } => (MeshKind::Capsule { radius, half_height }, Vec3::ONE),
    };
    ObjectDraw { mesh, transform: pose * Mat4::from_scale(scale), color }
}

/// Everything the session shows now.
pub fn draw_list(session: &Session, options: ViewOptions) -> DrawList {
    let scene = session.scene();
    let world = session.world();
    let objects = scene
        .object_ids()
        .filter(|&id| world.is_active(id))
        .map(|id| {
            let p = world.object_pose(id);
            let o = scene.object(id);
            object_draw(o.shape, Mat4::from_rotation_translation(p.rotation, p.position), o.color.rgba)
        })
        .collect();

    let mut feedback = Vec::new();
    if options.feedback {
        let f = session.feedback();
        // Joint lines and prism edges look alike; only the participant
        // model tells them apart.
        let segments = f.lines.iter().chain(&f.edges);
        feedback.extend(segments.map(|(a, b)| FeedbackDraw::Line { a: *a, b: *b, color: FEEDBACK_RED }));
        feedback.extend(f.cubes.iter().map(|(c, h)| FeedbackDraw::Cube { center: *c, half: *h, color: FEEDBACK_RED }));
    }

    let contact_overlay = options.contact_overlay.then(|| {
        let img = session.image();
        ContactOverlay { width: img.width as u32, height: img.height as u32, pixels: img.pixels.clone() }
    });

    DrawList {
        camera: scene_camera(scene),
        clear_color: [0.12, 0.12, 0.13, 1.0],
        table: TableDraw { width: scene.table.width, depth: scene.table.depth, color: scene.table.color.rgba },
        objects,
        deformables: deformables(session),
        decals: goal_decals(session),
        feedback,
        contact_overlay,
    }
}

/// Room around what must show, as a factor on the view's half size.
const VIEW_MARGIN: f32 = 1.03;

/// Everything the session shows now, seen by a view of `size` pixels: the
/// field of view is widened (letterboxed) until the whole table and every
/// object on it show at the view's aspect ratio. Tall objects near an edge
/// appear pushed outward in perspective, so each object counts by the top
/// of its bounding sphere: even an 800x800 view cuts off neither the sides
/// of the table nor a cylinder pushed against a wall.
pub fn fitted_draw_list(session: &Session, options: ViewOptions, size: [u32; 2]) -> DrawList {
    let mut list = draw_list(session, options);
    let scene = session.scene();
    let world = session.world();
    let height = list.camera.eye.z;
    if height <= 0.0 {
        return list;
    }
    let aspect = size[0].max(1) as f32 / size[1].max(1) as f32;
    // Half extents [x, y] on the table plane's projection that must show.
    let mut need = [0.5 * scene.table.width, 0.5 * scene.table.depth];
    for id in scene.object_ids().filter(|&id| world.is_active(id)) {
        let half = local_half_extents(scene.object(id).shape);
        let pose = world.object_pose(id);
        // The corners of the object's own bounding box, where it is now.
        for k in 0..8 {
            let sign = |bit: usize| if k & bit == 0 { -1.0 } else { 1.0 };
            let local = Vec3::new(sign(1) * half.x, sign(2) * half.y, sign(4) * half.z);
            let q = pose.position + pose.rotation * local;
            let outward = height / (height - q.z.min(0.9 * height));
            need[0] = need[0].max(q.x.abs() * outward);
            need[1] = need[1].max(q.y.abs() * outward);
        }
    }
    let half = need[1].max(need[0] / aspect) * VIEW_MARGIN;
    list.camera.fov_y_deg = (2.0 * (half / height).atan()).to_degrees();
    list
}

/// Half extents of the box around a shape in its own frame (a capsule's
/// axis is its z).
fn local_half_extents(shape: Shape) -> Vec3 {
    let r = shape.footprint_radius();
    match shape {
        Shape::Box { half_extents } => half_extents,
        Shape::Sphere { .. } | Shape::Cylinder { .. } | Shape::Capsule { .. } => Vec3::new(r, r, shape.half_z()),
    }
}

/// Soft bodies as the simulation has them now: every piece a tear left,
/// in its body's colour, straight from rapier's particles and surface.
fn deformables(session: &Session) -> Vec<DeformableDraw> {
    let world = session.world();
    world
        .soft_surfaces()
        .into_iter()
        .filter(|s| !s.triangles.is_empty() && s.positions.iter().all(|p| p.is_finite()))
        .map(|s| {
            let color = if s.body.index() < world.soft_body_count() {
                world.soft_spec(s.body).color.rgba
            } else {
                [0.8, 0.8, 0.8, 1.0]
            };
            DeformableDraw { positions: s.positions, triangles: s.triangles, color }
        })
        .collect()
}

/// Targets, zones, waypoints and the finish, as flat marks.
fn goal_decals(session: &Session) -> Vec<Decal> {
    let scene = session.scene();
    let tracker = session.tracker();
    let lift = 0.0005;
    let mut out = Vec::new();
    match &scene.goal {
        // A cloth to smooth or tear carries its own goal; nothing to mark.
        Goal::None | Goal::ClothFlat { .. } | Goal::Torn { .. } => {}
        Goal::Positioning { targets, .. } => {
            // Each target is the outline of its object, in its colour, so
            // the matching is visible; a placed object's target fades.
            for t in targets {
                let o = scene.object(t.object);
                let mut c = o.color.rgba;
                if tracker.is_placed(t.object) {
                    c[3] = 0.25;
                }
                // The object's footprint grown by half the tolerance.
                let footprint = if let Shape::Box { half_extents } = o.shape {
                    let angle = o.rotation.to_euler(glam::EulerRot::ZYX).0;
                    Decal::rect(t.position, half_extents.truncate() + Vec2::splat(t.tolerance * 0.5), c).turned(angle)
                } else {
                    Decal::disc(t.position, o.shape.footprint_radius() + t.tolerance * 0.5, c)
                };
                out.push(footprint.at(lift).outlined(0.004));
                out.push(Decal::disc(t.position, 0.003, c).at(lift));
            }
        }
        Goal::Sorting { zones, .. } => {
            for z in zones {
                let mut c = z.color.rgba;
                c[3] = 0.22;
                let center = (z.min + z.max) * 0.5;
                let half = (z.max - z.min) * 0.5;
                out.push(Decal::rect(center, half, c).at(lift));
                c[3] = 0.8;
                out.push(Decal::rect(center, half - Vec2::splat(0.003), c).at(lift * 2.0).outlined(0.004));
            }
        }
        Goal::Steering(g) => {
            let top = g.platform.map_or(0.0, |p| {
                let po = scene.object(p);
                po.position.z + po.shape.half_z()
            }) + lift;
            let passed = session.progress().waypoints_passed;
            for (i, w) in g.waypoints.iter().enumerate() {
                let mut c = WAYPOINT_BLUE;
                if i < passed {
                    c[3] = 0.3;
                }
                let disc = Decal::disc(*w, g.waypoint_radius, c).at(top);
                out.push(if i == passed { disc.outlined(0.006) } else { disc });
            }
            out.push(Decal::disc(g.finish, g.finish_radius, TARGET_RED).at(top));
        }
        Goal::Gather { center, radius, .. } => {
            out.push(Decal::disc(*center, *radius, TARGET_RED).at(lift).outlined(0.005));
        }
        Goal::Region { min, max, .. } | Goal::SoftRegion { min, max, .. } => {
            out.push(Decal::rect((*min + *max) * 0.5, (*max - *min) * 0.5, TARGET_RED).at(lift).outlined(0.005));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::technique::TechniqueKind;
    use crate::render::CameraMatrices;
    use crate::scene::test_scenes::fixture;
    use crate::session::SessionOptions;

    /// A 30 cm column in the table's far right corner, the table's corners,
    /// and the column's top all show in views of any shape.
    #[test]
    fn the_fitted_view_shows_the_table_and_a_tall_object_at_its_corner() {
        let scene = fixture("corner_column");
        let session = Session::new(&scene, TechniqueKind::JOINT, SessionOptions::default()).expect("session");
        for size in [[800, 800], [960, 800], [1280, 800], [400, 900], [1600, 400]] {
            let list = fitted_draw_list(&session, ViewOptions::default(), size);
            let camera = CameraMatrices::for_draw_list(&list, size);
            let inside = |p: Vec3| {
                let q = camera.world_to_pixel(size, p).expect("in front of the camera");
                q.x >= 0.0 && q.y >= 0.0 && q.x <= size[0] as f32 && q.y <= size[1] as f32
            };
            for corner in [[-0.5, -0.375], [0.5, 0.375], [-0.5, 0.375], [0.5, -0.375]] {
                assert!(inside(Vec3::new(corner[0], corner[1], 0.0)), "{size:?}: table corner {corner:?}");
            }
            for top in [Vec3::new(0.49, 0.36, 0.3), Vec3::new(0.49, 0.30, 0.3), Vec3::new(0.43, 0.36, 0.3)] {
                assert!(inside(top), "{size:?}: the column's top at {top}");
            }
            // Letterboxed, not a fixed wide margin: the table fills one axis.
            let table_corner = camera.world_to_pixel(size, Vec3::new(0.5, 0.375, 0.0)).expect("in front");
            let fill = (table_corner.x / size[0] as f32).max(1.0 - table_corner.y / size[1] as f32);
            assert!(fill > 0.85, "{size:?}: the table fills {fill} of the view");
        }
    }
}
