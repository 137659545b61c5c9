//! Golden images of the real task scenes, drawn through the same
//! session → draw-list path as the demo and `surfacelab screenshot`.
//!
//! References live in `tests/snapshots/`; a failing run writes
//! `NAME.new.png` and `NAME.diff.png` beside them; `UPDATE_SNAPSHOTS=1`
//! refreshes them. A machine with no GPU adapter fails with the Mesa
//! install hint (it never skips).

mod common;

use common::{asset, gestures};
use image::RgbaImage;
use surfacelab::app::{ViewOptions, draw_list};
use surfacelab::input::Gesture;
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::render::{self, GpuContext};
use surfacelab::render::{SnapshotDir, Tolerance};
use surfacelab::scene;
use surfacelab::scene::ObjectId;
use surfacelab::session::{Session, SessionOptions};

/// Set on lavapipe, "llvmpipe (LLVM 15.0.6, 256 bits)": 12/255 per channel,
/// at most 0.5% of pixels (antialiased edges and shadow-map texels differ
/// slightly between drivers and LLVM versions).
const TOLERANCE: Tolerance = Tolerance { per_pixel: 12, max_differing_share: 0.005 };
const SIZE: (u32, u32) = (480, 360);

fn gpu() -> GpuContext {
    GpuContext::new_headless()
        .unwrap_or_else(|e| panic!("these tests need a GPU adapter: {}", surfacelab::error::chain(&e)))
}

/// `img` matches golden image `name` in `tests/snapshots/`.
fn assert_golden(name: &str, img: &RgbaImage) {
    SnapshotDir::new(asset("tests/snapshots"))
        .check(name, img, TOLERANCE)
        .unwrap_or_else(|e| panic!("{}", surfacelab::error::chain(&e)));
}

/// `s` drawn at [`SIZE`] with `view`.
fn rendered(gpu: &GpuContext, s: &Session, view: ViewOptions) -> RgbaImage {
    render::render_to_image(gpu, &draw_list(s, view), SIZE.0, SIZE.1).expect("render")
}

/// A fingertip landing on the sorting scene's big red box (5 cm tall, so
/// it appears 4% further out on screen) and dragging it left.
fn drag_red_box() -> String {
    gestures::text(&[gestures::fingertip(1, &[(0.0, [0.052, 0.167]), (1.0, [-0.1, 0.167])])])
}

fn session_at(task: &str, kind: TechniqueKind, gesture: Option<&str>, at: f64) -> Session {
    let scene = scene::load(&asset(task)).expect("scene");
    let mut s = Session::new(&scene, kind, SessionOptions::default()).expect("session");
    match gesture {
        Some(g) => {
            let g = if g.trim_start().starts_with("format") {
                Gesture::from_str(g, "inline")
            } else {
                Gesture::load(asset(g))
            }
            .expect("gesture");
            s.replay_until(&g, at).expect("replay");
        }
        None => {
            while s.time() < at {
                s.step(&[]).expect("step");
            }
        }
    }
    s
}

#[test]
fn each_task_scene_matches_its_golden_image() {
    let gpu = gpu();
    for task in ["positioning", "sorting", "steering"] {
        let s = session_at(&format!("tasks/{task}.toml"), TechniqueKind::PROXY, None, 0.25);
        let img = rendered(&gpu, &s, ViewOptions::default());
        assert_golden(&format!("task_{task}"), &img);
    }
}

#[test]
fn feedback_on_and_off_differ_exactly_by_red_feedback_for_every_technique() {
    let gpu = gpu();
    for kind in TechniqueKind::BUILT_IN {
        // Mid-gesture: a fingertip dragging a box.
        let s = session_at("tasks/sorting.toml", kind, Some(&drag_red_box()), 0.6);
        let off = rendered(&gpu, &s, ViewOptions { feedback: false, contact_overlay: false });
        let on_list = draw_list(&s, ViewOptions { feedback: true, contact_overlay: false });
        assert!(
            !on_list.feedback.is_empty() || kind == TechniqueKind::DIRECT,
            "{kind}: no feedback geometry mid-gesture"
        );
        let on = render::render_to_image(&gpu, &on_list, SIZE.0, SIZE.1).expect("render");
        let mut differing = 0;
        let mut red = 0;
        for (a, b) in off.pixels().zip(on.pixels()) {
            if a.0.iter().zip(b.0.iter()).any(|(x, y)| x.abs_diff(*y) > 12) {
                differing += 1;
                let [r, g, bl, _] = b.0;
                if u16::from(r) > u16::from(g) + 40 && u16::from(r) > u16::from(bl) + 40 {
                    red += 1;
                }
            }
        }
        if !on_list.feedback.is_empty() {
            assert!(differing > 20, "{kind}: feedback changed only {differing} pixels");
            assert!(red * 100 >= differing * 90, "{kind}: {red} of {differing} changed pixels are red");
        }
        assert_golden(&format!("feedback_{kind}"), &on);
    }
}

#[test]
fn the_contact_overlay_shadows_where_the_hands_are() {
    let gpu = gpu();
    let s =
        session_at("tasks/sorting.toml", TechniqueKind::PARTICLE, Some("assets/gestures/flat_hand_sweep.toml"), 0.5);
    let plain = rendered(&gpu, &s, ViewOptions::default());
    let shadow = rendered(&gpu, &s, ViewOptions { feedback: false, contact_overlay: true });
    // Darker where the surface senses a hand, unchanged elsewhere.
    let img = s.image();
    let mut darker = 0;
    let mut sensed = 0;
    for (x, y, p) in shadow.enumerate_pixels() {
        let c = (x as usize * img.width / SIZE.0 as usize, y as usize * img.height / SIZE.1 as usize);
        let q = plain.get_pixel(x, y);
        let lum = |v: &image::Rgba<u8>| u32::from(v.0[0]) + u32::from(v.0[1]) + u32::from(v.0[2]);
        if img.pixels[c.1 * img.width + c.0] > 200 {
            sensed += 1;
            if lum(p) + 30 < lum(q) {
                darker += 1;
            }
        } else if img.pixels[c.1 * img.width + c.0] == 0 {
            assert!(lum(p).abs_diff(lum(q)) < 40, "overlay changed an untouched pixel at ({x}, {y})");
        }
    }
    assert!(sensed > 100 && darker * 100 >= sensed * 60, "{darker} of {sensed} sensed pixels darker");
    assert_golden("contact_overlay", &shadow);
}

/// The hands are on the glass, so a fingertip pressing on a box is drawn
/// over the box, not hidden under the box's top.
#[test]
fn a_fingertip_on_a_box_is_drawn_over_the_box() {
    let gpu = gpu();
    let s =
        session_at("tasks/cases/one_box.toml", TechniqueKind::JOINT, Some("assets/gestures/fingertip_drag.toml"), 0.5);
    let draw = |overlay: bool| rendered(&gpu, &s, ViewOptions { feedback: false, contact_overlay: overlay });
    let (plain, shadow) = (draw(false), draw(true));
    let img = s.image();
    let lum = |v: &image::Rgba<u8>| u32::from(v.0[0]) + u32::from(v.0[1]) + u32::from(v.0[2]);
    let box_pose = s.world().object_pose(ObjectId::new(0)).position;
    let (mut sensed_on_box, mut darker) = (0, 0);
    for (x, y, p) in shadow.enumerate_pixels() {
        let c = (x as usize * img.width / SIZE.0 as usize, y as usize * img.height / SIZE.1 as usize);
        // Table point of this pixel (the view spans the 1 m x 0.75 m table, as the contact image does).
        let table = [(x as f32 + 0.5) / SIZE.0 as f32 - 0.5, 0.5 - (y as f32 + 0.5) / SIZE.1 as f32];
        let on_box = (table[0] - box_pose.x).abs() < 0.065 && (table[1] * 0.75 - box_pose.y).abs() < 0.065;
        if img.pixels[c.1 * img.width + c.0] > 200 && on_box {
            sensed_on_box += 1;
            if lum(p) + 30 < lum(plain.get_pixel(x, y)) {
                darker += 1;
            }
        }
    }
    assert!(sensed_on_box > 20, "the fingertip is on the box: {sensed_on_box} pixels");
    assert!(darker * 100 >= sensed_on_box * 80, "{darker} of {sensed_on_box} fingertip pixels over the box darker");
}
