//! `surfacelab run --tuio`: the real binary fed real OSC packets over
//! 127.0.0.1 in real time, TUIO 2.0 contours and TUIO 1.1 cursors, its
//! report checked against what the hands did, and its `--record`ing
//! replayed with `run --gesture`.

mod common;

use common::{bin, text, tmp};
use rosc::{OscBundle, OscMessage, OscPacket, OscTime, OscType, encoder};
use std::io::{BufRead, BufReader};
use std::net::{SocketAddr, UdpSocket};
use std::path::Path;
use std::process::{Child, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The live runs keep time with the wall clock: one at a time, so that
/// they do not fight over this machine's two cores.
static REAL_TIME: Mutex<()> = Mutex::new(());

const TABLE: [f32; 2] = [1.0, 0.75];
/// The senders' frame rate (Hz).
const RATE: f64 = 60.0;

/// Table metres to TUIO's normalized coordinates (origin top left, y down).
fn normalized(p: [f32; 2]) -> [f32; 2] {
    [p[0] / TABLE[0] + 0.5, 0.5 - p[1] / TABLE[1]]
}

fn bundle(content: Vec<OscPacket>) -> Vec<u8> {
    encoder::encode(&OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content }))
        .expect("encodes")
}

fn msg(addr: &str, args: Vec<OscType>) -> OscPacket {
    OscPacket::Message(OscMessage { addr: addr.into(), args })
}

/// Starts `surfacelab run --tuio 0 ...` and returns it with the address
/// it printed it listens on.
fn start_live(args: &[&str]) -> (Child, SocketAddr, std::thread::JoinHandle<String>) {
    let mut child = bin()
        .args(["run", "--tuio", "0"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("starts");
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr"));
    let mut line = String::new();
    let addr = loop {
        line.clear();
        assert!(stderr.read_line(&mut line).expect("reads stderr") > 0, "exited before listening");
        if let Some(rest) = line.trim().strip_prefix("surfacelab run: listening for TUIO on ") {
            break rest.split_whitespace().next().expect("an address").parse().expect("a socket address");
        }
    };
    // Keep draining stderr so the child never blocks on a full pipe.
    let rest = std::thread::spawn(move || {
        let mut all = String::new();
        for l in stderr.lines().map_while(Result::ok) {
            all.push_str(&l);
            all.push('\n');
        }
        all
    });
    (child, addr, rest)
}

/// Sends `frames` (one datagram each) to `to` at [`RATE`].
fn send_at_rate(to: SocketAddr, frames: impl Iterator<Item = Vec<u8>>) {
    let socket = UdpSocket::bind("127.0.0.1:0").expect("a socket");
    let start = Instant::now();
    for (k, packet) in frames.enumerate() {
        let due = start + Duration::from_secs_f64(k as f64 / RATE);
        if let Some(wait) = due.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
        socket.send_to(&packet, to).expect("sends");
    }
}

fn finish(mut child: Child, stderr: std::thread::JoinHandle<String>) -> String {
    let status = child.wait().expect("waits");
    let log = stderr.join().expect("stderr reader");
    assert!(status.success(), "surfacelab run failed: {log}");
    log
}

fn report(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("report")).expect("json")
}

fn position(r: &serde_json::Value, i: usize) -> [f64; 2] {
    let p = &r["objects"][i]["position"];
    [p[0].as_f64().expect("x"), p[1].as_f64().expect("y")]
}

/// The outline of a flat right hand on the glass, fingers to +y, centred
/// on the palm: a 9 × 9 cm palm and four fingers 1.8 cm wide, table metres.
fn flat_hand(centre: [f32; 2]) -> Vec<[f32; 2]> {
    let mut outline = vec![[-0.045, -0.09], [0.045, -0.09], [0.045, 0.0]];
    // Little, ring, middle, index fingers from right to left: (left x, length).
    for (x, length) in [(0.024, 0.06), (0.002, 0.078), (-0.02, 0.082), (-0.042, 0.072)] {
        outline.extend([[x + 0.018, 0.004], [x + 0.018, length], [x, length], [x, 0.004]]);
    }
    outline.push([-0.045, 0.0]);
    outline.iter().map(|p| [p[0] + centre[0], p[1] + centre[1]]).collect()
}

/// One TUIO 2.0 frame: the hand's outer contour with its
/// pointer for pressure, or an empty alive list when `hand` is `None`.
fn tuio2_frame(frame: i32, hand: Option<[f32; 2]>) -> Vec<u8> {
    let mut content = vec![msg(
        "/tuio2/frm",
        vec![
            OscType::Int(frame),
            OscType::Time(OscTime { seconds: 0, fractional: 1 }),
            OscType::Int((640 << 16) | 0x1E0),
            OscType::String("test-sender:0@0x7F000001".into()),
        ],
    )];
    match hand {
        Some(centre) => {
            let c = normalized(centre);
            let mut ptr = vec![OscType::Int(12), OscType::Int(0), OscType::Int(0x16)];
            ptr.extend([c[0], c[1], 0.0, 0.0, 0.05, 0.9].map(OscType::Float));
            content.push(msg("/tuio2/ptr", ptr));
            let mut ocg = vec![OscType::Int(12)];
            for p in flat_hand(centre) {
                let n = normalized(p);
                ocg.extend([OscType::Float(n[0]), OscType::Float(n[1])]);
            }
            content.push(msg("/tuio2/ocg", ocg));
            content.push(msg("/tuio2/alv", vec![OscType::Int(12)]));
        }
        None => content.push(msg("/tuio2/alv", vec![])),
    }
    bundle(content)
}

/// The sweep: down left of the three boxes, 0.3 s still, across them in
/// +x 40 cm in 1.2 s, 0.3 s still, lifted, 0.3 s of empty frames.
fn sweep() -> impl Iterator<Item = Option<[f32; 2]>> {
    let (from, to) = (-0.25f32, 0.15f32);
    let still = (0.3 * RATE) as usize;
    let moving = (1.2 * RATE) as usize;
    std::iter::repeat_n(Some([from, 0.0]), still)
        .chain((1..=moving).map(move |k| Some([from + (to - from) * k as f32 / moving as f32, 0.0])))
        .chain(std::iter::repeat_n(Some([to, 0.0]), still))
        .chain(std::iter::repeat_n(None, still))
}

/// Boxes of `tasks/cases/three_boxes.toml`: x = 0, y = -3.5, 0, 3.5 cm.
const BOXES_Y: [f64; 3] = [-0.035, 0.0, 0.035];

/// A flat hand's TUIO 2.0 contour sweeps the three boxes under Particle:
/// each box on its path ends up pushed in the sweep's direction, ahead of
/// where the hand's leading edge stopped; the recording of the run,
/// replayed, puts them in the same places.
#[test]
fn a_tuio_2_contour_of_a_flat_hand_sweeps_boxes_under_particle_and_its_recording_replays() {
    let _one = REAL_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let scratch_dir = tmp("sweep");
    let dir = scratch_dir.path().to_path_buf();
    let (live, recorded) = (dir.join("live.json"), dir.join("sweep.toml"));
    let common = ["--task", "tasks/cases/three_boxes.toml", "--technique", "particle", "--settle", "0.5"];
    let (child, addr, stderr) = start_live(
        &[&common[..], &["--seconds", "2.6", "--report", path(&live), "--record", path(&recorded)]].concat(),
    );
    send_at_rate(addr, sweep().enumerate().map(|(k, hand)| tuio2_frame(k as i32 + 1, hand)));
    let log = finish(child, stderr);
    let sent = format!("{} TUIO packets (0 malformed", sweep().count());
    assert!(log.contains(&sent), "{log}");
    let r = report(&live);
    assert_eq!(r["nan_count"], 0, "{r}");
    // The hand's leading edge (palm side, x + 4.5 cm) stopped at x = 19.5 cm;
    // the boxes' centres started at x = 0, their faces 1.5 cm to the left.
    for (i, y0) in BOXES_Y.into_iter().enumerate() {
        let [x, y] = position(&r, i);
        assert!(x >= 0.15, "box {i} was pushed only to x = {x:.3} m: {r}");
        assert!((y - y0).abs() < 0.06, "box {i} went sideways from y = {y0} to {y:.3}");
    }

    // The recording is a version-2 gesture with the contour, and replays.
    let saved = std::fs::read_to_string(&recorded).expect("the recording");
    assert!(
        saved.contains("version = 2") && saved.contains("kind = \"contour\""),
        "{}",
        &saved[..300.min(saved.len())]
    );
    let replay = dir.join("replay.json");
    let o = bin()
        .args(["run", "--gesture", path(&recorded)])
        .args(common)
        .args(["--report", path(&replay)])
        .output()
        .expect("runs");
    assert!(o.status.success(), "{}", text(&o));
    let back = report(&replay);
    for i in 0..3 {
        let (a, b) = (position(&r, i), position(&back, i));
        let d = (a[0] - b[0]).hypot(a[1] - b[1]);
        eprintln!("box {i}: live at ({:.3}, {:.3}) m, replayed at ({:.3}, {:.3}) m", a[0], a[1], b[0], b[1]);
        assert!(d < 0.01, "box {i}: live {a:?}, replayed {b:?} ({d:.4} m apart)");
    }
}

/// A TUIO 1.1 frame (`fseq` `f`) with cursor 3 at table point `at`, or
/// with no cursor alive.
fn cursor(f: i32, at: Option<[f32; 2]>) -> Vec<u8> {
    let m = |args: Vec<OscType>| msg("/tuio/2Dcur", args);
    let mut content = vec![m(vec!["source".into(), "test@127.0.0.1".into()])];
    match at {
        Some(p) => {
            let n = normalized(p);
            content.push(m(vec!["alive".into(), OscType::Int(3)]));
            content.push(m(vec![
                "set".into(),
                OscType::Int(3),
                n[0].into(),
                n[1].into(),
                0.0f32.into(),
                0.0f32.into(),
                0.0f32.into(),
            ]));
        }
        None => content.push(m(vec!["alive".into()])),
    }
    content.push(m(vec!["fseq".into(), OscType::Int(f)]));
    bundle(content)
}

/// One frame per 1/60 s: the finger lands 5 cm left of the box's centre,
/// drags 15 cm to +x in 1 s, rests, and lifts (90 frames).
fn finger_path() -> impl Iterator<Item = Option<[f32; 2]>> {
    std::iter::repeat_n(Some([-0.05f32, 0.0]), 12)
        .chain((1..=60).map(|k| Some([-0.05 + 0.15 * k as f32 / 60.0, 0.0])))
        .chain(std::iter::repeat_n(Some([0.1, 0.0]), 12))
        .chain(std::iter::repeat_n(None, 6))
}

/// A live run of the one-box case under Proxy for `seconds`, its report
/// written to `report`.
fn one_box_under_proxy(seconds: &str, report: &Path) -> (Child, SocketAddr, std::thread::JoinHandle<String>) {
    let one_box = ["--task", "tasks/cases/one_box.toml", "--technique", "proxy"];
    start_live(&[&one_box[..], &["--seconds", seconds, "--report", path(report)]].concat())
}

/// TUIO 1.1 on the same option: a cursor drags the box under Proxy.
#[test]
fn a_tuio_1_1_cursor_drags_a_box_live() {
    let _one = REAL_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let scratch_dir = tmp("drag");
    let dir = scratch_dir.path().to_path_buf();
    let live = dir.join("live.json");
    let (child, addr, stderr) = one_box_under_proxy("2.0", &live);
    send_at_rate(addr, finger_path().enumerate().map(|(k, at)| cursor(k as i32 + 1, at)));
    finish(child, stderr);
    let r = report(&live);
    let [x, _] = position(&r, 0);
    assert!(x > 0.08, "the drag moved the box to x = {x:.3} m only: {r}");
    assert_eq!(r["gesture"].as_str().map(|s| s.starts_with("tuio:127.0.0.1:")), Some(true), "{r}");
}

/// `--gesture` and `--tuio` are one choice; `--tuio` needs `--seconds`;
/// `--seconds`, `--record` and `--tuio-bind` need `--tuio`: each misuse
/// exits 2 naming the flags, before anything runs.
#[test]
fn run_takes_exactly_one_source_of_hands() {
    let base = ["run", "--task", "tasks/cases/one_box.toml", "--technique", "particle"];
    let g = "assets/gestures/fingertip_drag.toml";
    let cases: [(&[&str], &str); 7] = [
        (&[], "--gesture"),
        (&["--gesture", g, "--tuio", "4000", "--seconds", "1"], "cannot be used with"),
        (&["--tuio", "4000"], "--seconds"),
        (&["--gesture", g, "--seconds", "1"], "'--gesture <NAME|FILE>' cannot be used with '--seconds <S>'"),
        (&["--gesture", g, "--record", "r.toml"], "'--gesture <NAME|FILE>' cannot be used with '--record <FILE>'"),
        (&["--seconds", "1", "--tuio-bind", "0.0.0.0"], "--gesture <NAME|FILE>|--tuio"),
        (&["--tuio", "4000", "--seconds", "1e9"], "out of range"),
    ];
    for (extra, says) in cases {
        let o = bin().args(base).args(extra).output().expect("runs");
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {}", text(&o));
        assert!(text(&o).contains(says), "{extra:?} should mention {says}: {}", text(&o));
    }
}

fn path(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 temp path")
}

/// The most memory the process `pid` has held (`VmHWM`, kB), read until it exits.
fn peak_rss_kb(pid: u32) -> std::thread::JoinHandle<u64> {
    std::thread::spawn(move || {
        let mut peak = 0;
        while let Some(kb) = common::proc_status_kb(pid, "VmHWM") {
            peak = std::cmp::max(peak, kb);
            std::thread::sleep(Duration::from_millis(50));
        }
        peak
    })
}

/// A flood far faster than any tracker sends: `SURFACELAB_FLOOD_PACKETS`
/// packets (default 20,000) spread evenly over `SURFACELAB_FLOOD_SECONDS`
/// (default 1.5 s), one in ten malformed, the drag's frames in order (the
/// last repeated once the drag is done). Every packet is counted, the box
/// is dragged as the 60-packet/s drag does, memory stays small, and the
/// run prints how long packets waited for their contact image
/// (`docs/performance.md` quotes the figures at 200,000 packets).
#[test]
fn a_flood_of_packets_is_all_counted_and_drags_the_box_as_a_steady_stream_does() {
    let _one = REAL_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let from_env = |name: &str| std::env::var(name).ok().and_then(|v| v.parse::<f64>().ok());
    let packets = from_env("SURFACELAB_FLOOD_PACKETS").unwrap_or(20_000.0) as usize;
    let seconds = from_env("SURFACELAB_FLOOD_SECONDS").unwrap_or(1.5);
    let scratch_dir = tmp("flood");
    let live = scratch_dir.path().join("flood.json");
    let run_for = format!("{:.1}", seconds + 1.0);
    let (child, addr, stderr) = one_box_under_proxy(&run_for, &live);
    let peak = peak_rss_kb(child.id());
    let frames: Vec<Option<[f32; 2]>> = finger_path().collect();
    // The drag's frames, the finger held at its end until the flood is over.
    let held = frames.len() - 7;
    let socket = UdpSocket::bind("127.0.0.1:0").expect("a socket");
    let start = Instant::now();
    let mut malformed = 0;
    for i in 0..packets {
        let t = seconds * i as f64 / packets as f64;
        let due = start + Duration::from_secs_f64(t);
        if let Some(wait) = due.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
        let packet = if i % 10 == 9 {
            malformed += 1;
            b"#bundle\0 but not really".to_vec()
        } else {
            let k = (t * RATE) as usize;
            let at = if k < frames.len() - 6 && t < seconds - 0.1 { frames[k.min(held)] } else { None };
            cursor(i32::try_from(i + 1).expect("fits"), at)
        };
        socket.send_to(&packet, addr).expect("sends");
    }
    let sent_in = start.elapsed().as_secs_f64();
    let log = finish(child, stderr);
    let peak_mb = peak.join().expect("poller") as f64 / 1024.0;
    println!("{packets} packets in {sent_in:.1} s ({:.0}/s); peak RSS {peak_mb:.1} MB", packets as f64 / sent_in);
    println!("{log}");
    assert!(log.contains(&format!("{packets} TUIO packets ({malformed} malformed")), "{log}");
    assert!(log.contains("packet to contact image over "), "{log}");
    let r = report(&live);
    let [x, _] = position(&r, 0);
    println!("the box ended at x = {x:.3} m");
    assert!(x > 0.08, "the flood's drag moved the box to x = {x:.3} m only: {r}");
    assert!(peak_mb < 100.0, "peak RSS {peak_mb:.1} MB");
}
