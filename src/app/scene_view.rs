//! From a running session to a [`DrawList`]: the one place that knows how a
//! scene, its goal and a technique's feedback look. The demo, `screenshot`
//! and the golden-image tests all draw through it.

use crate::render::{
    Camera, ContactOverlay, Decal, DeformableDraw, DrawList, FeedbackDraw, MeshKind, ObjectDraw, Rgba, TableDraw,
};
use crate::scene::{Goal, Scene, Shape};
use crate::session::Session;
use glam::{Mat4, Vec2, Vec3};

pub use crate::render::palette::{FEEDBACK_RED, TARGET_RED, WAYPOINT_BLUE};

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
    let objects = (0..scene.objects.len())
        .filter(|&i| world.is_active(i))
        .map(|i| {
            let p = world.object_pose(i);
            let o = &scene.objects[i];
            object_draw(o.shape, Mat4::from_rotation_translation(p.rotation, p.position), o.color.rgba)
        })
        .collect();

    let mut feedback = Vec::new();
    if options.feedback {
        let f = session.feedback();
        feedback.extend(f.lines.iter().map(|(a, b)| FeedbackDraw::Line { a: *a, b: *b, color: FEEDBACK_RED }));
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

/// Soft bodies as the simulation has them now: every piece a tear left,
/// in its body's colour, straight from rapier's particles and surface.
fn deformables(session: &Session) -> Vec<DeformableDraw> {
    let world = session.world();
    world
        .soft_surfaces()
        .into_iter()
        .filter(|s| !s.triangles.is_empty() && s.positions.iter().all(|p| p.is_finite()))
        .map(|s| {
            let color = if s.body < world.soft_body_count() {
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
                let o = &scene.objects[t.object];
                let mut c = o.color.rgba;
                if tracker.is_placed(t.object) {
                    c[3] = 0.25;
                }
                match o.shape {
                    Shape::Box { half_extents } => {
                        let angle = o.rotation.to_euler(glam::EulerRot::ZYX).0;
                        out.push(Decal::Rect {
                            center: t.position,
                            z: lift,
                            half: half_extents.truncate() + Vec2::splat(t.tolerance * 0.5),
                            angle,
                            color: c,
                            outline: Some(0.004),
                        });
                    }
                    _ => out.push(Decal::Disc {
                        center: t.position,
                        z: lift,
                        radius: o.shape.footprint_radius() + t.tolerance * 0.5,
                        color: c,
                        ring: Some(0.004),
                    }),
                }
                out.push(Decal::Disc { center: t.position, z: lift, radius: 0.003, color: c, ring: None });
            }
        }
        Goal::Sorting { zones, .. } => {
            for z in zones {
                let mut c = crate::scene::Color::parse(&z.color_name).map_or([0.5; 4], |c| c.rgba);
                c[3] = 0.22;
                let center = (z.min + z.max) * 0.5;
                out.push(Decal::Rect {
                    center,
                    z: lift,
                    half: (z.max - z.min) * 0.5,
                    angle: 0.0,
                    color: c,
                    outline: None,
                });
                c[3] = 0.8;
                out.push(Decal::Rect {
                    center,
                    z: lift * 2.0,
                    half: (z.max - z.min) * 0.5 - Vec2::splat(0.003),
                    angle: 0.0,
                    color: c,
                    outline: Some(0.004),
                });
            }
        }
        Goal::Steering(g) => {
            let top = g.platform.map_or(0.0, |p| {
                let po = &scene.objects[p];
                po.position.z + po.shape.half_z()
            }) + lift;
            let passed = session.progress().waypoints_passed;
            for (i, w) in g.waypoints.iter().enumerate() {
                let mut c = WAYPOINT_BLUE;
                if i < passed {
                    c[3] = 0.3;
                }
                let ring = if i == passed { Some(0.006) } else { None };
                out.push(Decal::Disc { center: *w, z: top, radius: g.waypoint_radius, color: c, ring });
            }
            out.push(Decal::Disc { center: g.finish, z: top, radius: g.finish_radius, color: TARGET_RED, ring: None });
        }
        Goal::Gather { center, radius, .. } => {
            out.push(Decal::Disc { center: *center, z: lift, radius: *radius, color: TARGET_RED, ring: Some(0.005) });
        }
        Goal::Region { min, max, .. } | Goal::SoftRegion { min, max, .. } => {
            out.push(Decal::Rect {
                center: (*min + *max) * 0.5,
                z: lift,
                half: (*max - *min) * 0.5,
                angle: 0.0,
                color: TARGET_RED,
                outline: Some(0.005),
            });
        }
    }
    out
}
