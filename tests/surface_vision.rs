//! Known-answer tests of the input pipeline: synthetic hands drawn by
//! `surface`, analysed by `vision`.

use std::path::{Path, PathBuf};

use surfacelab::pipeline::surface::{
    ContactImage, Footprint, Hand, HandKind, Patch, PixelPoint, PixelVector, RasterParams, Sensor, TablePoint,
    rasterize, rasterize_into, rasterize_patches, rasterize_rows,
};

use surfacelab::input::{Button, Gesture, GestureRecorder, Modifiers, Mouse, MouseEvent};
use surfacelab::pipeline::vision::{
    BlobTrackerParams, BlockMatcher, ContactId, FlowInterest, Pipeline, VisionFrame, VisionParams, find_blobs,
    signed_area, sobel_at, threshold,
};

fn sensor() -> Sensor {
    Sensor::default()
}

fn draw(hands: &[Hand]) -> ContactImage {
    rasterize(hands, &sensor(), &RasterParams::default())
}

fn median(mut v: Vec<f32>) -> f32 {
    assert!(!v.is_empty(), "no samples");
    v.sort_by(f32::total_cmp);
    v[v.len() / 2]
}

fn gestures_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets").join("gestures")
}

// --- surface: rasterization ------------------------------------------------

#[test]
fn rasterized_disc_has_the_right_area_and_centroid() {
    let s = sensor();
    let mpp = s.metres_per_pixel();
    for (centre, radius) in [([0.0f32, 0.0f32], 0.02f32), ([0.1234, -0.0567], 0.0111), ([-0.31, 0.2], 0.05)] {
        let disc = Patch { shape: Footprint::Ellipse { centre, radii: [radius, radius], angle: 0.0 }, level: 1.0 };
        let image = rasterize_patches(&[disc], &s, &RasterParams::default());
        // Half the touch level lies exactly on the outline.
        let blobs = find_blobs(&image, &threshold(&image, 128), 1);
        assert_eq!(blobs.len(), 1);
        let b = &blobs[0];
        let r_px = radius / mpp;
        let expected = std::f32::consts::PI * r_px * r_px;
        let area_error = (b.area as f32 - expected).abs() / expected;
        assert!(area_error < 0.02, "area {} vs {expected}", b.area);
        // The thresholded pixels quantise the outline by up to a tenth of
        // a pixel for a small disc.
        let c = s.to_pixel(TablePoint::from(centre)).to_array();
        for got in [b.centroid, b.weighted_centroid] {
            assert!((got[0] - c[0]).abs() < 0.1 && (got[1] - c[1]).abs() < 0.1, "{got:?} vs {c:?}");
        }
        // A disc's ellipse is a circle of the same radius.
        let [major, minor] = b.ellipse.semi_axes;
        assert!((major - r_px).abs() < 0.15 && (minor - r_px).abs() < 0.15, "{major} {minor} vs {r_px}");
        // The hull is counter-clockwise on screen (negative area in pixel
        // coordinates); through the centres of the boundary pixels, it is
        // about half a pixel smaller in radius than the disc.
        let hull_area = -signed_area(&b.hull) as f32;
        let inner = std::f32::consts::PI * (r_px - 1.0).powi(2);
        assert!(hull_area > inner && hull_area < expected, "{hull_area}");
    }
}

#[test]
fn fingertips_merge_when_closed_and_separate_when_spread() {
    let count = |spread: f32| {
        let image = draw(&[Hand::new(1, HandKind::Fingertips(2), 0.0, 0.0).with_spread(spread)]);
        find_blobs(&image, &threshold(&image, VisionParams::default().threshold), 6).len()
    };
    assert_eq!(count(0.0), 1);
    assert_eq!(count(1.0), 2);
    for n in 1..=5 {
        let image = draw(&[Hand::new(1, HandKind::Fingertips(n), 0.0, 0.0)]);
        assert_eq!(find_blobs(&image, &threshold(&image, 48), 6).len(), usize::from(n));
    }
}

#[test]
fn every_hand_kind_draws_one_contact_of_plausible_size() {
    let mpp2 = sensor().metres_per_pixel().powi(2);
    for kind in HandKind::ALL {
        let image = draw(&[Hand::new(1, kind, 0.1, -0.05).with_angle(0.3)]);
        let blobs = find_blobs(&image, &threshold(&image, 48), 6);
        assert_eq!(blobs.len(), 1, "{kind:?}");
        let area_m2 = blobs[0].area as f32 * mpp2;
        assert!(area_m2 > 1.5e-4 && area_m2 < 0.03, "{kind:?}: {area_m2} m^2");
    }
}

// --- vision: flow ------------------------------------------------------------

/// Flow of every outline point of a flat hand whose pose changes from `a`
/// to `b` in one frame, with the true motion of each point.
struct FlowCase {
    frame: VisionFrame,
    truth: Vec<[f32; 2]>,
    prev: ContactImage,
    cur: ContactImage,
}

fn flat_hand_motion(a: &Hand, b: &Hand) -> FlowCase {
    let s = sensor();
    let (prev, cur) = (draw(std::slice::from_ref(a)), draw(std::slice::from_ref(b)));
    let mut pipeline = Pipeline::default();
    pipeline.process(&prev);
    let frame = pipeline.process(&cur);
    // Where was each current point one frame ago? Undo b's pose, apply a's.
    let truth = frame
        .edges
        .iter()
        .map(|e| {
            let p = s.to_table(PixelPoint::from(e.px)).to_array();
            let (sb, cb) = b.pose.angle.sin_cos();
            let local = [p[0] - b.pose.x, p[1] - b.pose.y];
            let local = [cb * local[0] + sb * local[1], -sb * local[0] + cb * local[1]];
            let (sa, ca) = a.pose.angle.sin_cos();
            let was = [a.pose.x + ca * local[0] - sa * local[1], a.pose.y + sa * local[0] + ca * local[1]];
            let was_px = s.to_pixel(TablePoint::from(was)).to_array();
            [e.px[0] - was_px[0], e.px[1] - was_px[1]]
        })
        .collect();
    FlowCase { frame, truth, prev, cur }
}

impl FlowCase {
    fn median_error(&self) -> f32 {
        median(
            self.frame
                .edges
                .iter()
                .zip(&self.truth)
                .map(|(e, t)| (e.flow_px[0] - t[0]).hypot(e.flow_px[1] - t[1]))
                .collect(),
        )
    }

    /// Block matching alone (no guess from tracking): its error along the
    /// image gradient, the component the aperture problem leaves
    /// observable, and its full-vector error.
    fn unguided_errors(&self, radius: usize) -> (f32, f32) {
        let m = BlockMatcher::new(7, radius);
        let mut normal = Vec::new();
        let mut full = Vec::new();
        for (e, t) in self.frame.edges.iter().zip(&self.truth) {
            let [x, y] = [e.px[0] as u32, e.px[1] as u32];
            let f = m.flow_at(&self.prev, &self.cur, [x, y], [0.0, 0.0]).expect("same size");
            let g = sobel_at(&self.cur, x as usize, y as usize);
            let len = (g[0] as f32).hypot(g[1] as f32);
            let n = [g[0] as f32 / len, g[1] as f32 / len];
            normal.push(((f[0] - t[0]) * n[0] + (f[1] - t[1]) * n[1]).abs());
            full.push((f[0] - t[0]).hypot(f[1] - t[1]));
        }
        (median(normal), median(full))
    }

    /// The guided flow's median error, and that of block matching alone
    /// along the gradient, are at most half a pixel; `label` names the
    /// motion in the printed errors.
    fn assert_within_half_a_pixel(&self, label: &str) {
        let err = self.median_error();
        assert!(err <= 0.5, "median flow error {err} px");
        let (normal, full) = self.unguided_errors(4);
        eprintln!("{label}: guided median error {err:.3} px; unguided normal {normal:.3} px, full {full:.3} px");
        assert!(normal <= 0.5, "unguided normal-flow error {normal}");
    }
}

#[test]
fn flow_recovers_a_known_translation_of_a_flat_hand() {
    let s = sensor();
    let a = Hand::new(1, HandKind::FlatHand, 0.05, -0.02).with_angle(0.2);
    let shift = s.vector_to_table(PixelVector::new(3.3, -2.1)).to_array();
    let mut b = a.clone();
    b.pose.x += shift[0];
    b.pose.y += shift[1];
    let case = flat_hand_motion(&a, &b);
    assert!(case.frame.edges.len() > 250, "{} edges", case.frame.edges.len());
    for t in &case.truth {
        assert!((t[0] - 3.3).abs() < 1e-3 && (t[1] + 2.1).abs() < 1e-3);
    }
    case.assert_within_half_a_pixel("translation");
}

#[test]
fn flow_recovers_a_known_rotation_of_a_flat_hand() {
    let a = Hand::new(1, HandKind::FlatHand, -0.1, 0.05).with_angle(-0.1);
    let b = a.clone().with_angle(-0.1 + 3f32.to_radians());
    let case = flat_hand_motion(&a, &b);
    let c = &case.frame.contacts[0];
    // Counter-clockwise on the table is negative in image orientation.
    assert!((c.rotation_rad + 3f32.to_radians()).abs() < 0.5f32.to_radians(), "{}", c.rotation_rad);
    let longest = case.truth.iter().map(|t| t[0].hypot(t[1])).fold(0.0, f32::max);
    assert!(longest > 3.0, "the fingertips move {longest} px");
    case.assert_within_half_a_pixel("rotation");
}

/// Two fingertips turning a quarter turn in 1.5 s about the point between
/// them (the behaviour suite's `two_finger_twist`): 0.017 rad and about 0.2
/// px a frame. A fingertip patch is nearly round, so its outline barely
/// changes as it turns; the turn must come from the tracked axis, smoothed
/// over frames, and reach the flow along the outline. Without both, each
/// fingertip's flow is a pure translation (no turn about its centroid) and
/// particles brake the box they twist.
#[test]
fn flow_carries_the_turn_of_a_twisting_fingertip() {
    let frames = 90;
    let rate = std::f32::consts::FRAC_PI_2 / frames as f32;
    let pair = |k: usize| {
        let mut h = Hand::new(1, HandKind::Fingertips(2), 0.0, 0.0).with_angle(rate * k as f32);
        h.spread = 2.25;
        h
    };
    let mut p = Pipeline::default();
    let (mut tracked, mut flowed, mut n) = (0.0f32, 0.0f32, 0);
    for k in 0..frames {
        let frame = p.process(&draw(&[pair(k)]));
        assert_eq!(frame.contacts.len(), 2, "frame {k}: two fingertips");
        if k < 20 {
            continue; // the smoothed axis (12 frames) settles on the turn
        }
        for c in &frame.contacts {
            // Counter-clockwise on the table is negative in image orientation.
            tracked -= c.rotation_rad;
            let cen = c.blob.weighted_centroid;
            let spins: Vec<f32> = frame
                .edges
                .iter()
                .filter(|e| e.contact_id == c.id)
                .map(|e| {
                    let r = [e.px[0] - cen[0], e.px[1] - cen[1]];
                    -(r[0] * e.flow_px[1] - r[1] * e.flow_px[0]) / (r[0] * r[0] + r[1] * r[1])
                })
                .collect();
            flowed += spins.iter().sum::<f32>() / spins.len() as f32;
            n += 1;
        }
    }
    let (tracked, flowed) = (tracked / n as f32, flowed / n as f32);
    eprintln!("fingertip turn: true {rate:.4}, tracked {tracked:.4}, in the flow {flowed:.4} rad a frame");
    assert!((tracked - rate).abs() < 0.25 * rate, "tracked turn {tracked} rad a frame, true {rate}");
    assert!(flowed > 0.5 * rate && flowed < 1.5 * rate, "turn in the flow {flowed} rad a frame, true {rate}");
}

/// Which contacts have their turn measured frame by frame (elongation at
/// least `BlobTrackerParams::steady_elongation`, 1.3): a flat hand, an edge
/// and a forearm do; a fingertip does not.
#[test]
fn elongation_of_each_hand_kind() {
    let steady = BlobTrackerParams::default().steady_elongation;
    let mut p = Pipeline::default();
    for (kind, long) in [
        (HandKind::FlatHand, true),
        (HandKind::Edge, true),
        (HandKind::Forearm, true),
        (HandKind::Fingertips(1), false),
    ] {
        let frame = p.process(&draw(&[Hand::new(1, kind, 0.0, 0.0).with_angle(0.3)]));
        let e = frame.contacts[0].blob.ellipse.elongation();
        eprintln!("{kind:?}: elongation {e:.2}");
        assert_eq!(e >= steady, long, "{kind:?}: elongation {e}");
    }
}

// --- vision: tracking --------------------------------------------------------

fn ids_left_to_right(frame: &VisionFrame) -> Vec<ContactId> {
    let mut c: Vec<(f32, ContactId)> = frame.contacts.iter().map(|c| (c.blob.centroid[0], c.id)).collect();
    c.sort_by(|a, b| a.0.total_cmp(&b.0));
    c.into_iter().map(|(_, id)| id).collect()
}

#[test]
fn two_fingers_that_merge_and_split_keep_sensible_ids() {
    let mut p = Pipeline::default();
    let tip = |id, x: f32| Hand::new(id, HandKind::Fingertips(1), x, 0.0);
    // The left finger lands first, so it is the older contact.
    let first = p.process(&draw(&[tip(1, -0.04)]));
    let left = first.contacts[0].id;
    let mut right = ContactId::new(0);
    // Approach (each finger 2 mm per frame), touch, hold, part.
    let mut xs: Vec<f32> = (0..=16).map(|k| 0.04 - 0.002 * k as f32).collect();
    xs.extend([0.008; 5]);
    xs.extend((1..=12).map(|k| 0.008 + 0.003 * k as f32));
    let mut merged_frames = 0;
    for (k, x) in xs.into_iter().enumerate() {
        let f = p.process(&draw(&[tip(1, -x), tip(2, x)]));
        match f.contacts.len() {
            2 => {
                let ids = ids_left_to_right(&f);
                if k == 0 {
                    right = ids[1];
                    assert_ne!(left, right);
                }
                assert_eq!(ids, vec![left, right], "frame {k}, x = {x}");
            }
            1 => {
                merged_frames += 1;
                assert_eq!(f.contacts[0].id, left, "the merged blob keeps the older id");
            }
            n => panic!("{n} contacts"),
        }
    }
    assert!(merged_frames >= 5, "merged for {merged_frames} frames");
}

#[test]
fn closing_and_spreading_two_fingers_restores_both_ids() {
    let mut p = Pipeline::default();
    let hand = |spread: f32| [Hand::new(1, HandKind::Fingertips(2), 0.0, 0.0).with_angle(0.4).with_spread(spread)];
    let start = p.process(&draw(&hand(1.0)));
    let ids = ids_left_to_right(&start);
    assert_eq!(ids.len(), 2);
    let mut saw_merge = false;
    for k in (0..=10).rev().chain(0..=10) {
        let f = p.process(&draw(&hand(k as f32 / 10.0)));
        if f.contacts.len() == 1 {
            saw_merge = true;
            assert_eq!(f.contacts[0].id, ids[0].min(ids[1]));
        } else {
            assert_eq!(ids_left_to_right(&f), ids);
        }
    }
    assert!(saw_merge);
}

#[test]
fn a_flick_keeps_one_id_while_it_moves_fast() {
    let g = Gesture::load(gestures_dir().join("flick.toml")).expect("flick parses");
    let mut p = Pipeline::default();
    let mut ids = Vec::new();
    let mut fastest = 0.0f32;
    for k in 0..=(g.duration() * 60.0) as usize {
        let f = p.process(&draw(&g.sample(k as f64 / 60.0)));
        assert_eq!(f.contacts.len(), 1, "frame {k}");
        ids.push(f.contacts[0].id);
        let v = f.contacts[0].velocity_px;
        fastest = fastest.max(v[0].hypot(v[1]));
    }
    assert!(ids.iter().all(|&id| id == ids[0]), "{ids:?}");
    assert!(fastest > 15.0, "fastest {fastest} px/frame");
}

// --- degenerate inputs -------------------------------------------------------

#[test]
fn degenerate_images_do_not_panic() {
    let mut p = Pipeline::default();
    let empty = ContactImage::new(640, 480);
    let white = ContactImage::from_pixels(640, 480, vec![255; 640 * 480]).expect("sized");
    let f = p.process(&empty);
    assert!(f.contacts.is_empty() && f.edges.is_empty());
    let f = p.process(&white);
    assert_eq!(f.contacts.len(), 1);
    assert_eq!(f.contacts[0].blob.area, 640 * 480);
    // Border replication: a full frame has no outline.
    assert!(f.edges.is_empty());
    let f = p.process(&white);
    assert_eq!(f.contacts[0].age_frames, 1);
    for (w, h, v) in [(1, 1, 0u8), (1, 1, 255), (0, 0, 0), (2, 1, 255), (7, 3, 200)] {
        let img = ContactImage::from_pixels(w, h, vec![v; w * h]).expect("sized");
        p.process(&img);
        p.process(&img);
    }
    // Contacts running off every border and corner, moving.
    let s = sensor();
    let edges = [[-0.5, 0.0], [0.5, 0.0], [0.0, 0.375], [0.0, -0.375], [-0.5, 0.375], [0.5, -0.375]];
    for (k, &[x, y]) in edges.iter().enumerate() {
        let mut p = Pipeline::default();
        for step in 0..3 {
            let hand = Hand::new(1, HandKind::FlatHand, x + 0.01 * step as f32, y).with_angle(k as f32);
            let f = p.process(&rasterize(&[hand], &s, &RasterParams::default()));
            // Cut by the rim, a hand may fall apart into several blobs.
            assert!(!f.contacts.is_empty());
            assert!(f.contacts.iter().any(|c| {
                let b = c.blob.bbox;
                b.x0 == 0 || b.y0 == 0 || b.x1 == 639 || b.y1 == 479
            }));
            assert!(f.contacts.iter().all(|c| !c.blob.contour.is_empty() && c.blob.hull.len() >= 3));
            assert!(f.edges.iter().all(|e| e.flow_px.iter().all(|v| v.is_finite())));
        }
    }
    // A frame of another size in between: flow is skipped, nothing breaks.
    p.process(&draw(&[Hand::new(1, HandKind::Fist, 0.0, 0.0)]));
    p.process(&ContactImage::new(320, 240));
    p.process(&draw(&[Hand::new(1, HandKind::Fist, 0.0, 0.0)]));
}

#[test]
fn random_frames_do_not_panic() {
    // Worst cases for the labelling, contour and tracking: speckle at every
    // density, frame after frame.
    let mut p = Pipeline::default();
    for (k, density) in [0.05f32, 0.3, 0.45, 0.6, 0.95].into_iter().enumerate() {
        let params = RasterParams {
            noise: Some(surfacelab::pipeline::surface::Noise { seed: k as u64, amplitude: 255 }),
            ..RasterParams::default()
        };
        // Uniform noise in -255..=255 clamps to 0 about half the time; shift
        // the threshold to get the wanted density of lit pixels.
        // A quarter-resolution frame keeps this quick in debug builds.
        let image = rasterize(&[], &Sensor::new(160, 120, 1.0, 0.75), &params);
        let level = (255.0 * (1.0 - 2.0 * density.min(0.499))).max(1.0) as u8;
        let mut p2 = Pipeline::new(VisionParams { threshold: level, min_area: 1, ..VisionParams::default() });
        p2.process(&image);
        let f = p2.process(&image);
        assert!(f.contacts.iter().all(|c| !c.blob.contour.is_empty()));
        p.process(&image);
    }
}

#[test]
fn noisy_frames_give_no_phantom_contacts() {
    let params = RasterParams {
        noise: Some(surfacelab::pipeline::surface::Noise { seed: 42, amplitude: 20 }),
        ..RasterParams::default()
    };
    let image = rasterize(&[Hand::new(1, HandKind::FlatHand, 0.0, 0.0)], &sensor(), &params);
    let f = Pipeline::default().process(&image);
    assert_eq!(f.contacts.len(), 1);
}

// --- gestures ----------------------------------------------------------------

#[test]
fn a_recorded_gesture_round_trips_exactly() {
    // Drive the mouse model like the demo's record button would: a flat
    // hand pinned, a fingertip dragged and turned past it, then two fingers.
    let mut mouse = Mouse::new();
    let mut rec = GestureRecorder::new();
    let mut t = 12.5; // the app's clock, any origin
    let mut frame = |mouse: &mut Mouse, events: &[MouseEvent]| {
        for &e in events {
            mouse.handle(e);
        }
        t += 1.0 / 60.0;
        assert!(rec.record(t, &mouse.hands()));
    };
    let shift = Modifiers { shift: true, ..Modifiers::default() };
    frame(
        &mut mouse,
        &[MouseEvent::Moved([-0.2, 0.1]), MouseEvent::Modifiers(shift), MouseEvent::Pressed(Button::Left)],
    );
    frame(&mut mouse, &[MouseEvent::Pressed(Button::Right), MouseEvent::Released(Button::Left)]);
    frame(&mut mouse, &[MouseEvent::Modifiers(Modifiers::default()), MouseEvent::Moved([0.0, -0.1])]);
    frame(&mut mouse, &[MouseEvent::Pressed(Button::Left)]);
    for k in 0..40 {
        let x = 0.0 + 0.00731 * k as f32;
        frame(&mut mouse, &[MouseEvent::Moved([x, -0.1 + 0.0017 * k as f32]), MouseEvent::Wheel(0.1)]);
    }
    frame(&mut mouse, &[MouseEvent::Released(Button::Left), MouseEvent::Mode(HandKind::Fingertips(2))]);
    frame(&mut mouse, &[MouseEvent::Pressed(Button::Left)]);
    for _ in 0..10 {
        frame(&mut mouse, &[MouseEvent::Modifiers(shift), MouseEvent::Wheel(-0.37)]);
    }
    let recorded = rec.finish();
    assert_eq!(recorded.tracks().len(), 3);

    let text = recorded.to_string();
    let dir = std::env::temp_dir().join(format!("surfacelab-gesture-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("recorded.toml");
    recorded.save(&path).expect("writes");
    let back = Gesture::load(&path).expect("reads back");
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(back, recorded);
    assert_eq!(back.to_string(), text);
    let frames = (recorded.duration() * 60.0).ceil() as usize + 2;
    let mut lit = 0;
    for k in 0..frames {
        let at = k as f64 / 60.0;
        let (a, b) = (recorded.sample(at), back.sample(at));
        assert_eq!(a, b, "t = {at}");
        let (ia, ib) = (draw(&a), draw(&b));
        assert!(ia.pixels == ib.pixels, "images differ at t = {at}");
        lit += usize::from(!ia.is_blank());
    }
    assert!(lit > 50);
}

/// Parses `body` (with the standard header unless it has its own) and
/// returns the error message.
fn error_of(name: &str, text: &str) -> String {
    match Gesture::from_str(text, name) {
        Ok(_) => panic!("{name} should not parse"),
        Err(e) => e.to_string(),
    }
}

const HEADER: &str = "format = \"surfacelab-gesture\"\nversion = 1\n";

fn hand(kind: &str, extra: &str, keys: &str) -> String {
    format!("{HEADER}\n[[hands]]\nid = 1\nkind = \"{kind}\"\n{extra}\n{keys}")
}

const KEYS: &str = "[[hands.keys]]\nt = 0.0\npos = [0.0, 0.0]\n\n[[hands.keys]]\nt = 1.0\n";

/// A fist with `keys` (its `[[hands.keys]]` tables).
fn fist(keys: &str) -> String {
    hand("fist", "", keys)
}

/// A fist of one key at t = 0 at the origin, its last lines (line 10 on) `extra`.
fn fist_at_0(extra: &str) -> String {
    fist(&format!("[[hands.keys]]\nt = 0.0\npos = [0.0, 0.0]\n{extra}"))
}

/// One piece on purpose: a table of malformed files and what each error
/// must name.
#[test]
fn malformed_gestures_name_the_file_the_field_and_the_line() {
    let overlap = "[[hands]]\nid = 1\nkind = \"edge\"\n[[hands.keys]]\nt = 0.5\npos = [0.1, 0.0]\n";
    let version = |v: &str| format!("format = \"surfacelab-gesture\"\nversion = {v}\n");
    // (file, text, must contain...)
    let cases: &[(&str, String, &[&str])] = &[
        ("kind.toml", hand("tentacle", "", KEYS), &["kind.toml:6", "hands[0].kind", "unknown hand kind \"tentacle\""]),
        (
            "order.toml",
            fist("[[hands.keys]]\nt = 1.0\npos = [0.0, 0.0]\n[[hands.keys]]\nt = 0.5\n"),
            &["order.toml:12", "hands[0].keys[1].t", "out of time order"],
        ),
        (
            "same_time.toml",
            fist("[[hands.keys]]\nt = 1.0\npos = [0.0, 0.0]\n[[hands.keys]]\nt = 1.0\n"),
            &["same_time.toml", "hands[0].keys[1].t", "out of time order"],
        ),
        (
            "nan.toml",
            fist("[[hands.keys]]\nt = 0.0\npos = [nan, 0.0]\n"),
            &["nan.toml:10", "hands[0].keys[0].pos", "finite"],
        ),
        ("inf.toml", fist_at_0("angle_deg = -inf\n"), &["inf.toml:11", "hands[0].keys[0].angle_deg", "finite"]),
        ("inf_t.toml", fist("[[hands.keys]]\nt = inf\npos = [0.0, 0.0]\n"), &["inf_t.toml:9", "hands[0].keys[0].t"]),
        ("version.toml", version("3"), &["version.toml:2", "`version`", "unsupported version 3"]),
        ("version_text.toml", version("\"1\""), &["version_text.toml:2", "`version`"]),
        (
            "no_version.toml",
            "format = \"surfacelab-gesture\"\n".to_owned(),
            &["no_version.toml", "`version`", "missing"],
        ),
        ("no_format.toml", "version = 1\n".to_owned(), &["no_format.toml", "`format`", "missing"]),
        (
            "wrong_format.toml",
            "format = \"svg\"\nversion = 1\n".to_owned(),
            &["wrong_format.toml:1", "`format`", "svg"],
        ),
        ("fingers.toml", hand("fingertips", "fingers = 6", KEYS), &["fingers.toml:7", "hands[0].fingers", "1..=5"]),
        ("fingers0.toml", hand("fingertips", "fingers = 0", KEYS), &["fingers0.toml:7", "hands[0].fingers"]),
        (
            "fingers_fist.toml",
            hand("fist", "fingers = 2", KEYS),
            &["fingers_fist.toml:7", "hands[0].fingers", "only kind"],
        ),
        (
            "pressure.toml",
            fist_at_0("pressure = 1.5\n"),
            &["pressure.toml:11", "hands[0].keys[0].pressure", "out of range"],
        ),
        ("scale.toml", fist_at_0("scale = 0.0\n"), &["scale.toml:11", "hands[0].keys[0].scale"]),
        ("no_pos.toml", fist("[[hands.keys]]\nt = 0.0\n"), &["no_pos.toml:9", "hands[0].keys[0].pos", "missing"]),
        ("no_keys.toml", hand("fist", "keys = []", ""), &["no_keys.toml:7", "hands[0].keys"]),
        (
            "negative_t.toml",
            fist("[[hands.keys]]\nt = -1.0\npos = [0.0, 0.0]\n"),
            &["negative_t.toml:9", "hands[0].keys[0].t"],
        ),
        ("id.toml", format!("{HEADER}[[hands]]\nid = -1\nkind = \"fist\"\n{KEYS}"), &["id.toml:4", "hands[0].id"]),
        (
            "overlap.toml",
            format!("{HEADER}[[hands]]\nid = 1\nkind = \"fist\"\n{KEYS}\n{overlap}"),
            &["overlap.toml:17", "hands[1].keys[0].t", "still on the table"],
        ),
        ("unknown_field.toml", fist_at_0("speed = 3.0\n"), &["unknown_field.toml:11", "speed"]),
        ("missing_t.toml", fist("[[hands.keys]]\npos = [0.0, 0.0]\n"), &["missing_t.toml", "`t`"]),
        ("syntax.toml", format!("{HEADER}[[hands]\n"), &["syntax.toml:3"]),
        ("pos_type.toml", fist("[[hands.keys]]\nt = 0.0\npos = [0.0]\n"), &["pos_type.toml:10"]),
    ];
    for (name, text, wanted) in cases {
        let message = error_of(name, text);
        for w in *wanted {
            assert!(message.contains(w), "{name}: {message:?} lacks {w:?}");
        }
    }
    // A file that does not exist is named too.
    let missing = Gesture::load("/nonexistent/dir/gone.toml").expect_err("no such file");
    assert!(missing.to_string().contains("gone.toml"));
}

#[test]
fn example_gestures_parse_and_draw() {
    let mut names: Vec<PathBuf> = std::fs::read_dir(gestures_dir())
        .expect("assets/gestures exists")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    names.sort();
    let expected = [
        "edge_push.toml",
        "fingertip_drag.toml",
        "flat_hand_sweep.toml",
        "flick.toml",
        "two_finger_twist.toml",
        "two_hand_gather.toml",
    ];
    for e in expected {
        assert!(names.iter().any(|p| p.ends_with(e)), "{e} missing");
    }
    for path in names {
        let g = Gesture::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let d = g.duration();
        assert!((0.3..=4.0).contains(&d), "{}: {d} s", path.display());
        let mut pipeline = Pipeline::default();
        for k in 0..=(d * 60.0) as usize {
            let t = k as f64 / 60.0;
            let image = draw(&g.sample(t));
            assert!(!image.is_blank(), "{} is blank at t = {t}", path.display());
            let f = pipeline.process(&image);
            assert!(!f.contacts.is_empty() && !f.edges.is_empty(), "{} at t = {t}", path.display());
        }
        // Writing and reading back changes nothing.
        let back = Gesture::from_str(&g.to_string(), "rewritten").expect("reads back");
        assert_eq!(back, g);
    }
}

#[test]
fn the_twist_turns_the_contacts_and_the_drag_moves_ten_centimetres() {
    let s = sensor();
    let twist = Gesture::load(gestures_dir().join("two_finger_twist.toml")).expect("parses");
    let angle = |hands: &[Hand]| {
        let image = draw(hands);
        let blobs = find_blobs(&image, &threshold(&image, 48), 6);
        assert_eq!(blobs.len(), 2);
        let (a, b) =
            (s.to_table(PixelPoint::from(blobs[0].centroid)).0, s.to_table(PixelPoint::from(blobs[1].centroid)).0);
        (b[1] - a[1]).atan2(b[0] - a[0])
    };
    let turned = angle(&twist.sample(2.0)) - angle(&twist.sample(0.0));
    let turned = (turned.to_degrees() + 360.0) % 180.0;
    assert!((turned - 90.0).abs() < 1.0, "{turned}");

    let drag = Gesture::load(gestures_dir().join("fingertip_drag.toml")).expect("parses");
    let at = |t: f64| {
        let image = draw(&drag.sample(t));
        s.to_table(PixelPoint::from(find_blobs(&image, &threshold(&image, 48), 6)[0].weighted_centroid)).0
    };
    let (a, b) = (at(0.0), at(1.5));
    assert!((b[0] - a[0] - 0.1).abs() < 0.001 && (b[1] - a[1]).abs() < 0.001, "{a:?} -> {b:?}");
    assert!((a[0] + 0.05).abs() < 0.002 && a[1].abs() < 0.002);
}

// --- the row-restricted path the session takes --------------------------------

/// Rasterizing and analysing only the rows the hands light gives exactly
/// the image and the vision frame that whole-image passes give, frame after
/// frame, as hands appear, move across the table, change and lift.
#[test]
fn row_restricted_frames_equal_whole_image_frames() {
    let s = sensor();
    let params = RasterParams::default();
    let (mut full_img, mut rows_img) = (ContactImage::default(), ContactImage::default());
    let (mut full, mut rows) = (Pipeline::default(), Pipeline::default());
    let mut lit = 0..s.height_px as usize;
    for frame in 0..90 {
        let t = frame as f32 / 30.0;
        let mut hands = Vec::new();
        if frame < 60 {
            hands.push(Hand::new(1, HandKind::FlatHand, -0.3 + 0.02 * frame as f32, -0.25 + 0.008 * frame as f32));
        }
        if (20..80).contains(&frame) {
            let mut h = Hand::new(2, HandKind::Fingertips(2), 0.2, 0.3 - 0.01 * (frame - 20) as f32);
            h.pose.angle = t;
            hands.push(h);
        }
        rasterize_into(&hands, &s, &params, &mut full_img);
        lit = rasterize_rows(&hands, &s, &params, &mut rows_img, lit);
        assert_eq!(full_img, rows_img, "frame {frame}: images differ");
        assert!(
            (0..s.height_px as usize).filter(|y| !lit.contains(y)).all(|y| rows_img.row(y).iter().all(|&p| p == 0)),
            "frame {frame}: a lit pixel outside the rows reported"
        );
        let a = full.process_with(&full_img, &FlowInterest::All);
        let b = rows.process_rows(&rows_img, lit.clone(), &FlowInterest::All);
        assert_eq!((a.contacts, a.edges), (b.contacts, b.edges), "frame {frame}: vision differs");
    }
}
