//! Golden images of the renderer, drawn from the hand-made scenes in
//! `surfacelab::render::samples`, plus checks of what must be true of any
//! correct rendering (feedback is red and where it projects, the hand shadow
//! darkens the table where contact is, nothing is drawn differently twice).
//!
//! References: `tests/snapshots/NAME.png`. A failing run writes
//! `NAME.new.png` and `NAME.diff.png` beside them; `UPDATE_SNAPSHOTS=1`
//! accepts the new images. These tests need a GPU adapter and FAIL (never
//! skip) without one; on a machine without a GPU install Mesa's lavapipe:
//! `sudo apt-get install mesa-vulkan-drivers libvulkan1`.

use std::path::Path;
use std::sync::OnceLock;

use glam::{Vec2, Vec3};
use image::RgbaImage;
use surfacelab::render::{
    CameraMatrices, Capture, DOT_PER_LINE_WIDTH, DrawList, FeedbackDraw, GpuContext, RenderError, RendererOptions,
    render_to_image, samples,
};
use surfacelab::render::{SnapshotDir, Tolerance};

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;

/// Set on "llvmpipe (LLVM 15.0.6, 256 bits)" (Mesa lavapipe, Vulkan), where
/// renders are bit-identical from run to run and Vulkan and GL agree. The
/// slack is for other rasterisers: a channel may be off by 12/255 (shading
/// precision) and 0.5% of the pixels (silhouette and antialiasing
/// differences) may be off by more.
const TOLERANCE: Tolerance = Tolerance { per_pixel: 12, max_differing_share: 0.005 };

fn gpu() -> &'static GpuContext {
    static GPU: OnceLock<GpuContext> = OnceLock::new();
    GPU.get_or_init(|| {
        GpuContext::new_headless()
            .unwrap_or_else(|e| panic!("this test needs a GPU adapter: {}", surfacelab::error::chain(&e)))
    })
}

/// Golden images are rendered with 4x MSAA, as a GPU shows them (software
/// adapters default to no MSAA for speed; the other tests cover that path).
const GOLDEN_OPTIONS: RendererOptions =
    RendererOptions { sample_count: 4, shadow_map_size: 1024, feedback_line_px: 3.0 };

fn render(list: &DrawList) -> RgbaImage {
    Capture::with_options(gpu(), WIDTH, HEIGHT, GOLDEN_OPTIONS)
        .and_then(|mut capture| capture.render(list))
        .unwrap_or_else(|e| panic!("render failed: {e}"))
}

/// Beside this file, so it works wherever the test is built from.
fn snapshots() -> SnapshotDir {
    SnapshotDir::new(Path::new(file!()).parent().unwrap_or(Path::new("tests")).join("snapshots"))
}

fn check(name: &str, image: &RgbaImage) {
    if let Err(e) = snapshots().check(name, image, TOLERANCE) {
        panic!("{} (adapter: {})", surfacelab::error::chain(&e), gpu().summary());
    }
}

fn differs(a: image::Rgba<u8>, b: image::Rgba<u8>) -> bool {
    a.0.iter().zip(b.0).any(|(x, y)| x.abs_diff(y) > 2)
}

fn luminance(p: image::Rgba<u8>) -> f32 {
    0.2126 * f32::from(p[0]) + 0.7152 * f32::from(p[1]) + 0.0722 * f32::from(p[2])
}

#[test]
fn positioning_layout() {
    check("positioning", &render(&samples::positioning()));
}

#[test]
fn steering_layout() {
    check("steering", &render(&samples::steering()));
}

#[test]
fn every_shape_and_decal() {
    check("shapes", &render(&samples::shapes()));
}

/// Distance from `p` to the segment `a`–`b`.
fn distance_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let t = if ab.length_squared() > 0.0 { ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + ab * t)
}

/// Whether pixel centre `p` lies on (or within `margin` pixels of) the
/// screen projection of a feedback primitive.
fn on_feedback(camera: &CameraMatrices, feedback: &[FeedbackDraw], p: Vec2, line_px: f32, margin: f32) -> bool {
    let size = [WIDTH, HEIGHT];
    let project = |q: Vec3| camera.world_to_pixel(size, q).expect("feedback is in front of the camera");
    feedback.iter().any(|f| match *f {
        FeedbackDraw::Line { a, b, .. } => {
            // The line, or the square dot at either end (half its side times
            // sqrt 2 reaches the dot's corners).
            let dot = 0.5 * DOT_PER_LINE_WIDTH * line_px * std::f32::consts::SQRT_2;
            distance_to_segment(p, project(a), project(b)) <= 0.5 * line_px + margin
                || [a, b].iter().any(|&e| p.distance(project(e)) <= dot + margin)
        }
        FeedbackDraw::Cube { center, half, .. } => {
            let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
            for corner in [-1.0f32, 1.0]
                .into_iter()
                .flat_map(|x| [-1.0f32, 1.0].map(move |y| (x, y)))
                .flat_map(|(x, y)| [-1.0f32, 1.0].map(move |z| Vec3::new(x, y, z)))
            {
                let q = project(center + corner * half);
                lo = lo.min(q);
                hi = hi.max(q);
            }
            p.cmpge(lo - margin).all() && p.cmple(hi + margin).all()
        }
    })
}

#[test]
fn feedback_is_red_and_where_it_projects() {
    let off = samples::positioning();
    let on = samples::positioning_with_feedback();
    let (without, with) = (render(&off), render(&on));

    let camera = CameraMatrices::for_draw_list(&on, [WIDTH, HEIGHT]);
    let line_px = GOLDEN_OPTIONS.feedback_line_px;
    let (mut changed, mut red, mut outside) = (0, 0, Vec::new());
    for (x, y, p) in with.enumerate_pixels() {
        let q = without.get_pixel(x, y);
        if !differs(*p, *q) {
            continue;
        }
        changed += 1;
        if p[0] > p[1] && p[0] > p[2] {
            red += 1;
        }
        let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
        if !on_feedback(&camera, &on.feedback, centre, line_px, 2.0) {
            outside.push((x, y));
        }
    }
    // Three lines and nine cubes cover well over a thousand pixels at 640x480.
    assert!(changed > 1000, "feedback changed only {changed} pixels");
    assert!(red as f64 >= 0.95 * changed as f64, "only {red} of {changed} changed pixels are red-dominant");
    assert!(
        outside.is_empty(),
        "{} changed pixels lie off the feedback, e.g. {:?}",
        outside.len(),
        &outside[..outside.len().min(5)]
    );

    // And every primitive shows: the pixel at each cube's centre changed.
    let size = [WIDTH, HEIGHT];
    for f in &on.feedback {
        if let FeedbackDraw::Cube { center, .. } = *f {
            let p = camera.world_to_pixel(size, center).expect("in front");
            let (x, y) = (p.x as u32, p.y as u32);
            assert!(differs(*with.get_pixel(x, y), *without.get_pixel(x, y)), "cube at {center} is not visible");
        }
    }
    check("positioning_feedback", &with);
}

#[test]
fn contact_overlay_darkens_where_the_hand_touches() {
    let plain = samples::positioning();
    let touched = samples::positioning_with_contact();
    let (without, with) = (render(&plain), render(&touched));

    let overlay = touched.contact_overlay.as_ref().expect("sample has an overlay");
    let camera = CameraMatrices::for_draw_list(&touched, [WIDTH, HEIGHT]);
    let value = |c: u32, r: u32| overlay.pixels[(r * overlay.width + c) as usize];
    // Contact-image pixels whose 5x5 neighbourhood is uniformly bright or
    // uniformly empty (away from the blurred edges).
    let uniform = |c: u32, r: u32, test: &dyn Fn(u8) -> bool| {
        (c.saturating_sub(2)..=(c + 2).min(overlay.width - 1))
            .all(|cc| (r.saturating_sub(2)..=(r + 2).min(overlay.height - 1)).all(|rr| test(value(cc, rr))))
    };
    let (mut bright, mut darkened, mut occluded, mut empty, mut unchanged) = (0, 0, 0, 0, 0);
    for r in (0..overlay.height).step_by(3) {
        for c in (0..overlay.width).step_by(3) {
            let u = (c as f32 + 0.5) / overlay.width as f32;
            let v = (r as f32 + 0.5) / overlay.height as f32;
            let world = Vec3::new((u - 0.5) * touched.table.width, (0.5 - v) * touched.table.depth, 0.0);
            let p = camera.world_to_pixel([WIDTH, HEIGHT], world).expect("table is in front");
            let (x, y) = (p.x as u32, p.y as u32);
            if x >= WIDTH || y >= HEIGHT {
                continue;
            }
            let (a, b) = (*without.get_pixel(x, y), *with.get_pixel(x, y));
            if uniform(c, r, &|v| v >= 250) {
                bright += 1;
                if luminance(b) < 0.75 * luminance(a) {
                    darkened += 1;
                } else if !differs(a, b) {
                    occluded += 1; // An object stands over this point.
                }
            } else if uniform(c, r, &|v| v == 0) {
                empty += 1;
                if !differs(a, b) {
                    unchanged += 1;
                }
            }
        }
    }
    assert!(bright > 100, "the sample hand covers too little table ({bright} samples)");
    assert_eq!(darkened + occluded, bright, "{darkened} darkened + {occluded} occluded of {bright} bright samples");
    assert!(darkened as f64 > 0.8 * bright as f64, "only {darkened} of {bright} bright samples darkened");
    assert_eq!(unchanged, empty, "the overlay changed the table where there is no contact");
    check("positioning_contact", &with);
}

#[test]
fn rendering_is_deterministic_and_capture_is_reusable() {
    let list = samples::positioning_with_overlays();
    let mut capture = Capture::new(gpu(), WIDTH, HEIGHT).expect("capture");
    let first = capture.render(&list).expect("render");
    let other = capture.render(&samples::steering()).expect("render");
    let again = capture.render(&list).expect("render");
    assert!(first == again, "the same draw list rendered differently");
    assert!(first != other);
}

#[test]
fn capsule_meshes_are_cached_by_size() {
    let mut capture = Capture::new(gpu(), 64, 48).expect("capture");
    for _ in 0..3 {
        capture.render(&samples::shapes()).expect("render");
    }
    // shapes() has capsules of two sizes.
    assert_eq!(capture.renderer().cached_capsules(), 2);
}

/// An odd width exercises the 256-byte row padding of the readback.
#[test]
fn odd_sizes_read_back_unskewed() {
    let (w, h) = (333, 250);
    let image = render_to_image(gpu(), &samples::positioning(), w, h).expect("render");
    assert_eq!(image.dimensions(), (w, h));
    let background = *render_to_image(gpu(), &samples::positioning(), 64, 48).expect("render").get_pixel(0, 0);
    // The table does not reach the top corners: both show the background.
    assert_eq!(*image.get_pixel(0, 0), background);
    assert_eq!(*image.get_pixel(w - 1, 0), background);
    // The centre shows the table, not the background.
    assert!(differs(*image.get_pixel(w / 2, h / 2), background));
}

/// A window surface may be `Bgra8Unorm` (not sRGB): the shaders then encode
/// sRGB themselves, and the picture must match the sRGB capture.
#[test]
fn non_srgb_targets_look_the_same() {
    let list = samples::positioning_with_overlays();
    let reference = render(&list);
    for format in
        [wgpu::TextureFormat::Bgra8Unorm, wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureFormat::Bgra8UnormSrgb]
    {
        let mut capture = Capture::with_format(gpu(), WIDTH, HEIGHT, format, GOLDEN_OPTIONS).expect("capture");
        let image = capture.render(&list).expect("render");
        // In a non-sRGB target the MSAA resolve and the blending of
        // antialiased edges work on encoded values, so edge pixels of
        // saturated colours differ (on llvmpipe: 0.5% of the pixels by more
        // than 24, none by more than 43). A missing or doubled encoding
        // would shift every pixel.
        let c = surfacelab::render::compare(&reference, &image, 24);
        if format.is_srgb() {
            assert_eq!(c.max_channel_delta, 0, "{format:?} differs from {:?}", surfacelab::render::CAPTURE_FORMAT);
        }
        assert!(c.max_channel_delta <= 64, "{format:?}: a pixel is off by {}", c.max_channel_delta);
        assert!(c.differing_share() < 0.015, "{format:?}: {:.3}% of pixels differ", 100.0 * c.differing_share());
    }
}

#[test]
fn invalid_draw_lists_are_errors_not_panics() {
    let mut capture = Capture::new(gpu(), 64, 48).expect("capture");
    let mut list = samples::positioning_with_contact();
    if let Some(overlay) = &mut list.contact_overlay {
        overlay.pixels.pop();
    }
    assert!(matches!(capture.render(&list), Err(RenderError::InvalidDrawList(_))));
    let mut list = samples::shapes();
    list.deformables[0].triangles.push([0, 1, 100_000]);
    assert!(matches!(capture.render(&list), Err(RenderError::InvalidDrawList(_))));
    // The capture still works afterwards.
    capture.render(&samples::positioning()).expect("render after an error");
}

#[test]
fn adapter_is_reported() {
    let summary = surfacelab::render::probe_adapter().unwrap_or_else(|e| panic!("{}", surfacelab::error::chain(&e)));
    assert!(!summary.name.is_empty());
    assert!(summary.to_string().contains(&summary.name));
}
