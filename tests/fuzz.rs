//! The fuzz harness: every reader of user input is fed valid
//! files with numbers swapped for extremes, lines dropped and bytes
//! flipped, and must answer with a value or an error, never a panic or a
//! hang. Scenes that still load are also built into a world and stepped,
//! so a value that passes validation but makes rapier or parry panic is
//! caught too.
//!
//! Runs for `SURFACELAB_FUZZ_SECS` seconds in all (default 10, shared by
//! the six targets), so `cargo test` stays quick and CI runs the default:
//!
//! ```text
//! SURFACELAB_FUZZ_SECS=14400 cargo test --release --locked --test fuzz -- --test-threads 1
//! ```
//!
//! runs it for four hours. `SURFACELAB_FUZZ_SEED` picks the first seed
//! (default 0, so a run is reproducible); a failure prints proptest's
//! smallest failing input. Every crasher found is kept below as a named
//! regression test.

mod common;

use common::scratch;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::path::Path;
use std::time::{Duration, Instant};
use surfacelab::harness::study::RunFile;
use surfacelab::harness::study::recover_trials;
use surfacelab::input::Gesture;
use surfacelab::input::tuio::TuioState;
use surfacelab::pipeline::surface::{Hand, HandKind};
use surfacelab::pipeline::technique::TechniqueKind;
use surfacelab::scene;
use surfacelab::session::{Session, SessionOptions};

/// Values that break readers: not finite, huge, tiny, negative, zero,
/// past integer widths, not numbers.
const EXTREMES: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "1e30",
    "-1e30",
    "1e-30",
    "0",
    "-0.0",
    "-1",
    "1e9",
    "4294967296",
    "-9223372036854775808",
    "18446744073709551616",
    "3.4e38",
    "0.0000001",
    "\"x\"",
    "[]",
    "[1.0, 2.0, 3.0]",
    "{}",
    "true",
];

/// Each target's share of the budget.
fn budget() -> Duration {
    let total: f64 = std::env::var("SURFACELAB_FUZZ_SECS").ok().and_then(|s| s.parse().ok()).unwrap_or(10.0);
    Duration::from_secs_f64(total.max(0.0) / 6.0)
}

/// Runs `test` on values of `strategy` in rounds of 32 cases with fresh
/// seeds until this target's budget is spent (at least one round).
fn fuzz<S: Strategy>(name: &str, strategy: S, test: impl Fn(S::Value) -> Result<(), TestCaseError>)
where
    S::Value: std::fmt::Debug,
{
    let first: u64 = std::env::var("SURFACELAB_FUZZ_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(0);
    let end = Instant::now() + budget();
    let mut round = 0_u64;
    loop {
        let seed = first.wrapping_add(round);
        let mut bytes = [0_u8; 32];
        bytes[..8].copy_from_slice(&seed.to_le_bytes());
        bytes[8..16].copy_from_slice(&(name.len() as u64).to_le_bytes());
        let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &bytes);
        let config = Config { cases: 32, failure_persistence: None, ..Config::default() };
        let mut runner = TestRunner::new_with_rng(config, rng);
        if let Err(e) = runner.run(&strategy, &test) {
            panic!("{name}: seed {seed} (SURFACELAB_FUZZ_SEED={seed}): {e}");
        }
        round += 1;
        if Instant::now() >= end {
            break;
        }
    }
}

/// Byte ranges of the number literals in `text`.
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = (b[i].is_ascii_digit() || b[i] == b'-') && (i == 0 || !b[i - 1].is_ascii_alphanumeric());
        if starts && b.get(i + 1).is_some_and(|c| c.is_ascii_digit() || b[i].is_ascii_digit()) {
            let s = i;
            while i < b.len() && (b[i].is_ascii_digit() || matches!(b[i], b'.' | b'e' | b'E' | b'-' | b'+' | b'_')) {
                i += 1;
            }
            out.push((s, i));
        } else {
            i += 1;
        }
    }
    out
}

/// One edit of a text file.
#[derive(Debug, Clone)]
enum Edit {
    /// The k-th number (mod their count) becomes an extreme.
    Number(prop::sample::Index, &'static str),
    /// The k-th line (mod their count) is dropped.
    DropLine(prop::sample::Index),
    /// The k-th line is repeated.
    RepeatLine(prop::sample::Index),
    /// A byte (mod the length) becomes this one.
    Byte(prop::sample::Index, u8),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        6 => (any::<prop::sample::Index>(), prop::sample::select(EXTREMES)).prop_map(|(i, v)| Edit::Number(i, v)),
        1 => any::<prop::sample::Index>().prop_map(Edit::DropLine),
        1 => any::<prop::sample::Index>().prop_map(Edit::RepeatLine),
        1 => (any::<prop::sample::Index>(), any::<u8>()).prop_map(|(i, b)| Edit::Byte(i, b)),
    ]
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut text = text.to_owned();
    for e in edits {
        match e {
            Edit::Number(i, v) => {
                let spans = numbers(&text);
                if !spans.is_empty() {
                    let (s, t) = spans[i.index(spans.len())];
                    text.replace_range(s..t, v);
                }
            }
            Edit::DropLine(i) | Edit::RepeatLine(i) => {
                let mut lines: Vec<&str> = text.lines().collect();
                if !lines.is_empty() {
                    let k = i.index(lines.len());
                    if matches!(e, Edit::DropLine(_)) {
                        lines.remove(k);
                    } else {
                        lines.insert(k, lines[k]);
                    }
                }
                text = lines.join("\n") + "\n";
            }
            Edit::Byte(i, b) => {
                let mut bytes = text.into_bytes();
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] = *b;
                }
                text = String::from_utf8_lossy(&bytes).into_owned();
            }
        }
    }
    text
}

fn builtin(path: &str) -> &'static str {
    scene::builtin::file(Path::new(path)).unwrap_or_else(|| panic!("{path} is built in"))
}

fn scene_templates() -> Vec<&'static str> {
    scene::builtin::scene_names().map(|n| builtin(&format!("tasks/{n}.toml"))).collect()
}

/// A scene that loads is also built and stepped: validation must keep out
/// everything the physics cannot take.
fn check_scene(text: &str) {
    let Ok(scene) = scene::parse(text, "fuzz.toml") else { return };
    for kind in [TechniqueKind::JOINT, TechniqueKind::PARTICLE] {
        let Ok(mut session) = Session::new(&scene, kind, SessionOptions::default()) else { continue };
        for _ in 0..3 {
            let hand = Hand::new(1, HandKind::FlatHand, 0.0, 0.0).with_pressure(1.0);
            let _ = session.step(std::slice::from_ref(&hand));
        }
    }
}

#[test]
fn fuzz_scene_files() {
    let templates = scene_templates();
    let strategy = (prop::sample::select(templates), prop::collection::vec(edit(), 1..4));
    fuzz("scene", strategy, |(t, edits)| {
        check_scene(&apply(t, &edits));
        Ok(())
    });
}

/// A version-2 gesture with a contour hand: points, holes, a held outline.
const CONTOUR_GESTURE: &str = include_str!("gestures/contour_held.toml");

#[test]
fn fuzz_gesture_files() {
    let mut templates: Vec<&str> = ["flick", "fingertip_drag", "flat_hand_sweep", "edge_push", "grasp_pinch"]
        .iter()
        .map(|n| builtin(&format!("assets/gestures/{n}.toml")))
        .collect();
    templates.push(CONTOUR_GESTURE);
    let strategy = (prop::sample::select(templates), prop::collection::vec(edit(), 1..4));
    fuzz("gesture", strategy, |(t, edits)| {
        if let Ok(g) = Gesture::from_str(&apply(t, &edits), "fuzz.toml") {
            // A gesture that loads is bounded: sampling it ends.
            prop_assert!(g.duration() <= 600.0, "duration {}", g.duration());
            // What loads draws without a panic (contours included).
            draw(&g.sample(g.duration() / 2.0));
        }
        Ok(())
    });
}

/// Rasterizes `hands` on a small sensor; a panic fails the fuzz case.
fn draw(hands: &[surfacelab::pipeline::surface::Hand]) {
    let sensor = surfacelab::pipeline::surface::Sensor::new(160, 120, 1.0, 0.75);
    let _ = surfacelab::pipeline::surface::rasterize(
        hands,
        &sensor,
        &surfacelab::pipeline::surface::RasterParams::default(),
    );
}

#[test]
fn fuzz_contact_json() {
    let template = r#"{"a": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], "b": [[0.5, 0.5], [2.0, 0.5], [2.0, 2.0], [0.6, 1.8], [0.4, 1.2]]}"#;
    let strategy = (prop::collection::vec(edit(), 1..4), any::<bool>());
    fuzz("contact", strategy, |(edits, concave)| {
        let _ = surfacelab::contact::answer_json(&apply(template, &edits), concave);
        Ok(())
    });
}

/// A TUIO 2.0 frame in one bundle: a pointer with a contour and a hole.
fn tuio2_frame() -> Vec<u8> {
    use rosc::OscType::{Float, Int, String as Str, Time};
    let m =
        |addr: &str, args: Vec<rosc::OscType>| rosc::OscPacket::Message(rosc::OscMessage { addr: addr.into(), args });
    let content = vec![
        m("/tuio2/frm", vec![Int(3), Time(rosc::OscTime { seconds: 0, fractional: 1 }), Int(0), Str("f".into())]),
        m(
            "/tuio2/ptr",
            vec![Int(1), Int(0), Int(0), Float(0.5), Float(0.5), Float(0.0), Float(0.0), Float(0.0), Float(0.5)],
        ),
        m(
            "/tuio2/ocg",
            vec![
                Int(1),
                Float(0.3),
                Float(0.3),
                Float(0.7),
                Float(0.3),
                Float(0.7),
                Float(0.7),
                Float(0.3),
                Float(0.7),
            ],
        ),
        m("/tuio2/icg", vec![Int(1), Float(0.45), Float(0.45), Float(0.55), Float(0.45), Float(0.5), Float(0.55)]),
        m("/tuio2/alv", vec![Int(1)]),
    ];
    let bundle = rosc::OscBundle { timetag: rosc::OscTime { seconds: 0, fractional: 1 }, content };
    rosc::encoder::encode(&rosc::OscPacket::Bundle(bundle)).expect("encodes")
}

/// An OSC message: address, type tags and arguments, padded to 4 bytes.
fn osc(address: &str, args: &[rosc::OscType]) -> Vec<u8> {
    let m = rosc::OscMessage { addr: address.to_owned(), args: args.to_vec() };
    rosc::encoder::encode(&rosc::OscPacket::Message(m)).expect("encodes")
}

#[test]
fn fuzz_osc_packets() {
    use rosc::OscType::{Bool, Float, Int, String as Str, Time};
    let valid = vec![
        osc("/tuio/2Dcur", &[Str("alive".into()), Int(1), Int(2)]),
        osc("/tuio/2Dcur", &[Str("set".into()), Int(1), Float(0.5), Float(0.5), Float(0.0), Float(0.0), Float(0.0)]),
        osc("/tuio/2Dcur", &[Str("fseq".into()), Int(7)]),
        osc("/tuio/2Dblb", &[Str("set".into()), Int(3), Float(0.2), Float(0.3), Float(0.1), Float(0.1), Float(0.05)]),
        // TUIO 2.0: a whole frame in one bundle, and each message alone
        // (a frame may span packets).
        tuio2_frame(),
        osc(
            "/tuio2/frm",
            &[Int(9), Time(rosc::OscTime { seconds: 0, fractional: 1 }), Int(0x0280_01E0), Str("s".into())],
        ),
        osc(
            "/tuio2/ptr",
            &[Int(4), Int(0), Int(1), Float(0.5), Float(0.5), Float(0.0), Float(0.0), Float(0.01), Float(0.7)],
        ),
        osc("/tuio2/ocg", &[Int(4), Float(0.4), Float(0.4), Float(0.6), Float(0.4), Float(0.5), Float(0.6)]),
        osc(
            "/tuio2/icg",
            &[
                Int(4),
                Float(0.48),
                Float(0.45),
                Float(0.52),
                Float(0.45),
                Float(0.5),
                Float(0.5),
                Bool(true),
                Float(0.5),
                Float(0.5),
                Float(0.51),
                Float(0.5),
                Float(0.5),
                Float(0.51),
            ],
        ),
        osc("/tuio2/arg", &[Int(5), Float(0.1), Float(0.1), Float(0.05), Float(0.1), Float(0.102), Float(0.06)]),
        osc("/tuio2/bnd", &[Int(6), Float(0.3), Float(0.3), Float(0.2), Float(0.1), Float(0.05), Float(0.004)]),
        osc(
            "/tuio2/skg",
            &[
                Int(7),
                Float(0.3),
                Float(0.3),
                Float(0.3),
                Float(0.4),
                Float(0.35),
                Float(0.45),
                Int(1),
                Float(0.25),
                Float(0.45),
            ],
        ),
        osc("/tuio2/tok", &[Int(8), Int(0), Int(3), Float(0.7), Float(0.2), Float(1.0)]),
        osc("/tuio2/alv", &[Int(4), Int(5), Int(6), Int(7), Int(8)]),
    ];
    let strategy = (
        prop::collection::vec((prop::sample::select(valid), any::<prop::sample::Index>(), any::<u8>()), 1..6),
        prop::collection::vec(any::<u8>(), 0..64),
    );
    fuzz("osc", strategy, |(packets, noise)| {
        let mut state = TuioState::new();
        for (k, (mut p, i, b)) in packets.into_iter().enumerate() {
            let at = i.index(p.len());
            p[at] = b;
            let _ = state.receive(&p, k as f64 * 0.016);
        }
        let _ = state.receive(&noise, 1.0);
        let hands = state.hands([1.0, 0.75], 1.0);
        for h in &hands {
            prop_assert!(h.pose.x.is_finite() && h.pose.y.is_finite(), "a hand from TUIO is finite: {h:?}");
        }
        // Whatever arrived draws (contours included) without a panic.
        draw(&hands);
        Ok(())
    });
}

#[test]
fn fuzz_command_line() {
    use clap::Parser as _;
    let words: &[&str] = &[
        "run",
        "study",
        "screenshot",
        "contact",
        "demo",
        "merge",
        "--task",
        "--technique",
        "--gesture",
        "--tuio",
        "--tuio-bind",
        "--seconds",
        "--record",
        "--settle",
        "--at",
        "--participants",
        "--reps",
        "--seed",
        "--time-limit",
        "--shard",
        "--techniques",
        "--tasks",
        "--resume",
        "--from",
        "--seeds",
        "--slurm",
        "--size",
        "--window",
        "--out",
        "joint",
        "proxy",
        "positioning",
        "1e30",
        "nan",
        "-1",
        "0",
        "4294967296",
        "3/2",
        "0/0",
        "1x0",
        "99999x99999",
        "",
        "--",
        "-",
    ];
    let strategy = prop::collection::vec(prop::sample::select(words), 0..8);
    fuzz("cli", strategy, |args| {
        // Parsing alone: running would start windows and studies.
        let _ = surfacelab::cli::Cli::try_parse_from(std::iter::once("surfacelab").chain(args));
        Ok(())
    });
}

#[test]
fn fuzz_run_folders() {
    let dir = scratch("run");
    let design = surfacelab::harness::study::StudyDesign::default();
    let run_toml = RunFile::new(design, None).to_toml().expect("toml");
    let trials = "participant,order_index\n1,0\n";
    let strategy = (prop::collection::vec(edit(), 1..4), prop::collection::vec(any::<u8>(), 0..200), any::<bool>());
    fuzz("run folder", strategy, |(edits, bytes, prefix)| {
        let path = dir.join("run.toml");
        std::fs::write(&path, apply(&run_toml, &edits)).expect("write");
        let _ = RunFile::load(&path);
        let csv = dir.join("trials.csv");
        let mut content = if prefix { surfacelab::harness::study::COLUMNS.join(",").into_bytes() } else { Vec::new() };
        content.push(b'\n');
        content.extend(&bytes);
        content.extend(trials.as_bytes());
        std::fs::write(&csv, &content).expect("write");
        let _ = recover_trials(&csv);
        Ok(())
    });
    std::fs::remove_dir_all(&dir).ok();
}

// ---------------------------------------------------------------------------
// Crashers the fuzzer found, kept as regression tests.

/// A TUIO `set` whose session id is an OSC time tag before 1970: the
/// decoder's error message printed it with rosc's `Display`, which panicked
/// ("overflow when subtracting durations"). Found by `fuzz_osc_packets`.
#[test]
fn a_tuio_time_tag_argument_is_an_error_not_a_panic() {
    use rosc::OscType::{Float, String as Str};
    let tag = rosc::OscType::Time(rosc::OscTime { seconds: 0, fractional: 0 });
    let set = vec![Str("set".into()), tag.clone(), Float(0.5), Float(0.5), Float(0.0), Float(0.0), Float(0.0)];
    for args in [set, vec![tag.clone()]] {
        let mut state = TuioState::new();
        let packet = osc("/tuio/2Dcur", &args);
        let e = state.receive(&packet, 0.0).expect_err("a time tag is no session id");
        assert!(e.to_string().contains("time tag 0.0"), "{e}");
    }
    let mut state = TuioState::new();
    let e = state
        .receive(&osc("/tuio/2Dcur", &[rosc::OscType::String("fseq".into()), tag]), 0.0)
        .expect_err("a time tag is no frame id");
    assert!(e.to_string().contains("fseq: time tag 0.0 is not an int32 frame id"), "{e}");
}
