//! Hand-made draw lists, defined once and shared by the golden-image tests
//! and the render benchmark: one scene, two uses. Layouts mimic the study's
//! tasks; they are not the
//! tasks themselves (those are data under `tasks/`).

use std::f32::consts::{FRAC_PI_2, PI};

use glam::{Mat4, Quat, Vec2, Vec3};

use crate::render::draw_list::{
    Camera, ContactOverlay, Decal, DeformableDraw, DrawList, FeedbackDraw, MeshKind, ObjectDraw, Rgba, TableDraw,
};

/// Linear-RGB colours of the sample scenes.
pub mod colors {
    use super::Rgba;
    pub const TABLE: Rgba = [0.56, 0.55, 0.52, 1.0];
    pub const BACKGROUND: Rgba = [0.018, 0.02, 0.026, 1.0];
    /// Targets, waypoints and feedback as the demo draws them.
    pub use crate::render::palette::{FEEDBACK_RED, TARGET_RED, WAYPOINT_BLUE};
    pub const PLATFORM: Rgba = [0.30, 0.31, 0.34, 1.0];
    pub const OBJECTS: [Rgba; 8] = [
        [0.85, 0.40, 0.05, 1.0], // orange
        [0.05, 0.45, 0.40, 1.0], // teal
        [0.80, 0.65, 0.08, 1.0], // yellow
        [0.35, 0.12, 0.55, 1.0], // purple
        [0.12, 0.30, 0.65, 1.0], // blue
        [0.20, 0.50, 0.12, 1.0], // green
        [0.60, 0.22, 0.30, 1.0], // rose
        [0.75, 0.74, 0.70, 1.0], // ivory
    ];
}

/// A 30-inch 4:3 display surface, as on the paper's Microsoft Surface.
pub fn table() -> TableDraw {
    TableDraw { width: 0.61, depth: 0.4575, color: colors::TABLE }
}

/// Seated in front of the table, looking down at ~55°; the table fills the
/// width of a 4:3 frame.
pub fn camera() -> Camera {
    Camera { eye: Vec3::new(0.0, -0.46, 0.66), target: Vec3::new(0.0, -0.012, 0.0), up: Vec3::Z, fov_y_deg: 40.0 }
}

fn empty_list() -> DrawList {
    DrawList {
        camera: camera(),
        clear_color: colors::BACKGROUND,
        table: table(),
        objects: Vec::new(),
        deformables: Vec::new(),
        decals: Vec::new(),
        feedback: Vec::new(),
        contact_overlay: None,
    }
}

/// A sphere of `radius` resting on the plane at height `z`.
pub fn sphere_on(center: Vec2, z: f32, radius: f32, color: Rgba) -> ObjectDraw {
    ObjectDraw {
        mesh: MeshKind::Sphere,
        transform: Mat4::from_scale_rotation_translation(
            Vec3::splat(radius),
            Quat::IDENTITY,
            center.extend(z + radius),
        ),
        color,
    }
}

/// A box of `size` resting on the plane at height `z`, turned by `yaw`.
pub fn box_on(center: Vec2, z: f32, size: Vec3, yaw: f32, color: Rgba) -> ObjectDraw {
    ObjectDraw {
        mesh: MeshKind::Box,
        transform: Mat4::from_scale_rotation_translation(
            size,
            Quat::from_rotation_z(yaw),
            center.extend(z + 0.5 * size.z),
        ),
        color,
    }
}

/// An upright cylinder resting on the plane at height `z`.
pub fn cylinder_on(center: Vec2, z: f32, radius: f32, height: f32, color: Rgba) -> ObjectDraw {
    ObjectDraw {
        mesh: MeshKind::Cylinder,
        transform: Mat4::from_scale_rotation_translation(
            Vec3::new(radius, radius, height),
            Quat::IDENTITY,
            center.extend(z + 0.5 * height),
        ),
        color,
    }
}

/// Positioning-like: four spheres and four boxes scattered on the table,
/// four red target rings to move them into.
pub fn positioning() -> DrawList {
    let mut list = empty_list();
    let spheres = [(-0.20, 0.12), (0.05, 0.15), (0.21, -0.02), (-0.08, -0.12)];
    for (i, (x, y)) in spheres.into_iter().enumerate() {
        list.objects.push(sphere_on(Vec2::new(x, y), 0.0, 0.025, colors::OBJECTS[i]));
    }
    let boxes = [(-0.05, 0.03, 0.3), (0.17, 0.13, -0.5), (-0.22, -0.08, 0.9), (0.12, -0.14, 0.15)];
    for (i, (x, y, yaw)) in boxes.into_iter().enumerate() {
        list.objects.push(box_on(Vec2::new(x, y), 0.0, Vec3::splat(0.05), yaw, colors::OBJECTS[4 + i]));
    }
    for (x, y) in [(-0.24, 0.16), (0.24, 0.16), (-0.24, -0.17), (0.24, -0.17)] {
        list.decals.push(Decal::disc(Vec2::new(x, y), 0.042, colors::TARGET_RED).outlined(0.005));
    }
    list
}

/// Height of the steering platform's top.
pub const PLATFORM_HEIGHT: f32 = 0.04;

/// Steering-like: a raised platform with blue waypoint discs on its top, a
/// red finish zone, and a cylinder to steer along the waypoints.
pub fn steering() -> DrawList {
    let mut list = empty_list();
    let platform = Vec3::new(0.46, 0.30, PLATFORM_HEIGHT);
    list.objects.push(box_on(Vec2::ZERO, 0.0, platform, 0.0, colors::PLATFORM));
    let z = PLATFORM_HEIGHT;
    let waypoints = [(-0.17, -0.09), (-0.08, 0.02), (0.02, -0.05), (0.10, 0.06)];
    for (x, y) in waypoints {
        list.decals.push(Decal::disc(Vec2::new(x, y), 0.022, colors::WAYPOINT_BLUE).at(z));
    }
    list.decals.push(Decal::rect(Vec2::new(0.185, 0.095), Vec2::new(0.03, 0.03), colors::TARGET_RED).at(z));
    // The start, outlined.
    let start = Decal::rect(Vec2::new(-0.185, -0.11), Vec2::new(0.028, 0.028), [0.9, 0.9, 0.88, 1.0]);
    list.decals.push(start.at(z).outlined(0.003));
    list.objects.push(cylinder_on(Vec2::new(-0.17, -0.09), z, 0.018, 0.03, colors::OBJECTS[0]));
    list
}

/// Technique feedback for [`positioning`]: joint lines from two contact
/// points to the objects they hold, and proxy cubes at the contacts.
pub fn positioning_feedback() -> Vec<FeedbackDraw> {
    let red = colors::FEEDBACK_RED;
    let mut feedback = vec![
        FeedbackDraw::Line { a: Vec3::new(-0.14, 0.04, 0.0), b: Vec3::new(-0.05, 0.03, 0.025), color: red },
        FeedbackDraw::Line { a: Vec3::new(0.13, 0.02, 0.0), b: Vec3::new(0.21, -0.02, 0.025), color: red },
        FeedbackDraw::Line { a: Vec3::new(0.0, -0.06, 0.0), b: Vec3::new(0.12, -0.14, 0.025), color: red },
    ];
    for i in 0..7 {
        let t = i as f32 / 6.0;
        let center = Vec3::new(-0.06 + 0.12 * t, -0.06 + 0.02 * (t * PI).sin(), 0.004);
        feedback.push(FeedbackDraw::Cube { center, half: 0.004, color: red });
    }
    feedback.push(FeedbackDraw::Cube { center: Vec3::new(-0.14, 0.04, 0.004), half: 0.005, color: red });
    feedback.push(FeedbackDraw::Cube { center: Vec3::new(0.13, 0.02, 0.004), half: 0.005, color: red });
    feedback
}

/// A synthetic contact image of a right hand lying flat on the table (row 0
/// = far edge): palm, four fingers and a thumb, as round-ended strokes, with
/// edges fading over ~4 mm as in a smoothed, thresholded IR image.
pub fn hand_contact(width: u32, height: u32) -> ContactOverlay {
    let table = table();
    // Segments in table metres (x right, y away from the viewer), radius.
    let wrist = Vec2::new(-0.02, -0.13);
    let finger = |base: Vec2, angle_deg: f32, length: f32, radius: f32| {
        let dir = Vec2::from_angle(angle_deg.to_radians());
        (base, base + dir * length, radius)
    };
    let strokes = [
        (wrist, wrist + Vec2::new(0.005, 0.045), 0.042),        // palm
        finger(Vec2::new(-0.045, -0.095), 150.0, 0.055, 0.011), // thumb
        finger(Vec2::new(-0.04, -0.05), 102.0, 0.065, 0.0095),
        finger(Vec2::new(-0.017, -0.045), 91.0, 0.075, 0.0095),
        finger(Vec2::new(0.007, -0.048), 80.0, 0.07, 0.009),
        finger(Vec2::new(0.027, -0.06), 66.0, 0.055, 0.008), // little finger
    ];
    let fade = 0.004;
    let mut pixels = vec![0u8; (width * height) as usize];
    for row in 0..height {
        for col in 0..width {
            let p = Vec2::new(
                ((col as f32 + 0.5) / width as f32 - 0.5) * table.width,
                (0.5 - (row as f32 + 0.5) / height as f32) * table.depth,
            );
            let outside = strokes
                .iter()
                .map(|&(a, b, r)| {
                    let ab = b - a;
                    let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
                    p.distance(a + ab * t) - r
                })
                .fold(f32::INFINITY, f32::min);
            let value = (0.5 - outside / fade).clamp(0.0, 1.0);
            pixels[(row * width + col) as usize] = (value * 255.0).round() as u8;
        }
    }
    ContactOverlay { width, height, pixels }
}

/// Every mesh kind and decal kind, a floating sphere (its shadow detached),
/// and a draped deformable sheet: a visual check of the whole renderer.
pub fn shapes() -> DrawList {
    let mut list = empty_list();
    let c = colors::OBJECTS;
    list.objects.push(box_on(Vec2::new(-0.21, 0.11), 0.0, Vec3::new(0.08, 0.05, 0.03), 0.4, c[4]));
    list.objects.push(sphere_on(Vec2::new(-0.07, 0.13), 0.0, 0.03, c[0]));
    // Floating 4 cm above the table: the shadow shows the gap.
    list.objects.push(sphere_on(Vec2::new(0.06, 0.12), 0.04, 0.025, c[2]));
    list.objects.push(cylinder_on(Vec2::new(0.20, 0.11), 0.0, 0.03, 0.06, c[1]));
    // Capsules: one standing, one lying along x, one lying along y.
    let (r, h) = (0.015, 0.025);
    list.objects.push(ObjectDraw {
        mesh: MeshKind::Capsule { radius: r, half_height: h },
        transform: Mat4::from_translation(Vec3::new(-0.22, -0.06, r + h)),
        color: c[3],
    });
    list.objects.push(ObjectDraw {
        mesh: MeshKind::Capsule { radius: r, half_height: h },
        transform: Mat4::from_rotation_translation(Quat::from_rotation_y(FRAC_PI_2), Vec3::new(-0.12, -0.05, r)),
        color: c[6],
    });
    list.objects.push(ObjectDraw {
        mesh: MeshKind::Capsule { radius: 0.01, half_height: 0.04 },
        transform: Mat4::from_rotation_translation(Quat::from_rotation_x(FRAC_PI_2), Vec3::new(-0.05, -0.12, 0.01)),
        color: c[7],
    });
    list.deformables.push(draped_sheet(Vec2::new(0.13, -0.07), Vec2::new(0.09, 0.07), 16, c[5]));
    list.decals.push(Decal::rect(Vec2::new(0.0, -0.03), Vec2::new(0.05, 0.025), colors::WAYPOINT_BLUE).turned(0.3));
    list.decals.push(Decal::rect(Vec2::new(-0.17, -0.06), Vec2::new(0.09, 0.05), colors::TARGET_RED).outlined(0.003));
    list.decals.push(Decal::disc(Vec2::new(0.06, 0.12), 0.035, colors::TARGET_RED).outlined(0.004));
    list
}

/// A cloth-like sheet of `n`×`n` quads draped over an invisible bump.
pub fn draped_sheet(center: Vec2, half: Vec2, n: u32, color: Rgba) -> DeformableDraw {
    let mut positions = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let s = Vec2::new(i as f32 / n as f32 * 2.0 - 1.0, j as f32 / n as f32 * 2.0 - 1.0);
            let bump = 0.045 * (-(s.length_squared()) * 2.2).exp();
            let ripple = 0.004 * (s.x * 7.0).sin() * (1.0 - s.length_squared() * 0.5).max(0.0);
            positions.push((center + s * half).extend(0.002 + bump + ripple));
        }
    }
    let mut triangles = Vec::new();
    let row = n + 1;
    for j in 0..n {
        for i in 0..n {
            let a = j * row + i;
            triangles.push([a, a + 1, a + row + 1]);
            triangles.push([a, a + row + 1, a + row]);
        }
    }
    DeformableDraw { positions, triangles, color }
}

/// [`positioning`] with feedback on.
pub fn positioning_with_feedback() -> DrawList {
    let mut list = positioning();
    list.feedback = positioning_feedback();
    list
}

/// [`positioning`] with the hand's contact image shown.
pub fn positioning_with_contact() -> DrawList {
    let mut list = positioning();
    list.contact_overlay = Some(hand_contact(256, 192));
    list
}

/// Everything at once: the heaviest frame of the samples.
pub fn positioning_with_overlays() -> DrawList {
    let mut list = positioning_with_feedback();
    list.contact_overlay = Some(hand_contact(256, 192));
    list
}
