//! The desktop demo as a user gets it: the real binary in a real X window
//! (Xvfb, software Vulkan), driven by a scripted gesture, looked at through
//! two screenshots: the app's own read-back of its window, and the X
//! server's root window (`xwd`), which shows what was actually presented.
//!
//! Needs `xvfb-run` and `xwd` (packages xvfb and x11-apps; `bash .ci/setup`
//! installs them). Without them the tests fail and say so: they never skip.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_surfacelab");
const SCREEN: [u32; 2] = [1280, 800];
/// The panel's width in pixels (egui points at scale 1).
const PANEL_W: u32 = 320;
/// egui's dark panel fill.
const PANEL: [u8; 3] = [27, 27, 27];
/// The scenes' table, as rendered (sRGB).
const TABLE: [u8; 3] = [223, 226, 229];

/// A flat hand that sweeps from the middle to the left and stays down.
const SWEEP: &str = r#"format = "surfacelab-gesture"
version = 1

[[hands]]
id = 1
kind = "flat_hand"
keys = [{ t = 0.0, pos = [0.15, -0.05], angle_deg = 90.0 }, { t = 2.0, pos = [-0.15, -0.05] }, { t = 60.0, pos = [-0.15, -0.05] }]
"#;

fn work_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("test folder");
    dir
}

fn require(tool: &str, package: &str) {
    let found =
        Command::new("sh").args(["-c", &format!("command -v {tool}")]).output().is_ok_and(|o| o.status.success());
    assert!(
        found,
        "`{tool}` is not installed, and the demo's window test needs it. Install the test set-up with \
         `bash .ci/setup` (or `sudo apt-get install {package}`)."
    );
}

/// `xvfb-run -a` picks a free display number racily: one Xvfb at a time.
static XVFB: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Runs a shell script under a fresh Xvfb screen, with a private
/// `XDG_RUNTIME_DIR` (Vulkan's loader complains without one) and a time limit.
fn under_xvfb(dir: &Path, script: &str) -> Output {
    under_xvfb_for(dir, script, 180)
}

/// [`under_xvfb`] with a time limit of `limit_s` seconds.
fn under_xvfb_for(dir: &Path, script: &str, limit_s: u32) -> Output {
    require("xvfb-run", "xvfb");
    require("xwd", "x11-apps");
    let runtime = dir.join("xdg");
    std::fs::create_dir_all(&runtime).expect("runtime dir");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700)).expect("chmod");
    }
    let screen = format!("-screen 0 {}x{}x24", SCREEN[0], SCREEN[1]);
    // The script starts once the server answers: a fresh-clone CI run once
    // had the demo refused by its display ("Failed to open connection to X
    // server") although xvfb-run had started it.
    let script = format!(
        "i=0; until xwd -root -silent > /dev/null 2>&1 || [ $i -ge 100 ]; do sleep 0.1; i=$((i+1)); done\n{script}"
    );
    let _one_at_a_time = XVFB.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    Command::new("timeout")
        .arg(limit_s.to_string())
        .args(["xvfb-run", "-a", "-s", &screen, "sh", "-c", &script])
        .env("XDG_RUNTIME_DIR", &runtime)
        .env_remove("WAYLAND_DISPLAY")
        .current_dir(dir)
        .output()
        .expect("runs xvfb-run")
}

/// An RGB image as rows of pixels.
struct Image {
    width: u32,
    height: u32,
    pixels: Vec<[u8; 3]>,
}

impl Image {
    fn png(path: &Path) -> Image {
        let img = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).to_rgb8();
        Image { width: img.width(), height: img.height(), pixels: img.pixels().map(|p| p.0).collect() }
    }

    /// An XWD dump (what `xwd -root` writes) of a 24/32-bit `TrueColor` screen.
    fn xwd(path: &Path) -> Image {
        let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let field = |i: usize| u32::from_be_bytes(bytes[i * 4..i * 4 + 4].try_into().expect("4 bytes"));
        let (header, width, height, byte_order, bpp, line) =
            (field(0), field(4), field(5), field(7), field(11), field(12));
        let masks = [field(14), field(15), field(16)];
        let colors = field(19);
        assert_eq!(bpp, 32, "{}: expected a 32-bit XWD, got {bpp} bits per pixel", path.display());
        let data = &bytes[header as usize + colors as usize * 12..];
        let mut pixels = Vec::with_capacity((width * height) as usize);
        for y in 0..height as usize {
            for x in 0..width as usize {
                let at = y * line as usize + x * 4;
                let raw: [u8; 4] = data[at..at + 4].try_into().expect("4 bytes");
                let v = if byte_order == 0 { u32::from_le_bytes(raw) } else { u32::from_be_bytes(raw) };
                pixels.push(masks.map(|m| ((v & m) >> m.trailing_zeros()) as u8));
            }
        }
        Image { width, height, pixels }
    }

    fn at(&self, x: u32, y: u32) -> [u8; 3] {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Share of the pixels of a rectangle that satisfy `test`.
    fn share(&self, x: std::ops::Range<u32>, y: std::ops::Range<u32>, test: impl Fn([u8; 3]) -> bool) -> f64 {
        let total = (x.len() * y.len()) as f64;
        let hits = y.flat_map(|yy| x.clone().map(move |xx| (xx, yy))).filter(|&(xx, yy)| test(self.at(xx, yy))).count();
        hits as f64 / total
    }
}

fn near(a: [u8; 3], b: [u8; 3], tolerance: u8) -> bool {
    a.iter().zip(b).all(|(p, q)| p.abs_diff(q) <= tolerance)
}

/// What a researcher sees: the panel on the left, the table with its red
/// and blue objects and zones on the right, the scripted hand on it.
fn check_window(name: &str, img: &Image, report: &str) {
    assert_eq!([img.width, img.height], SCREEN, "{name}: screenshot size\n{report}");
    let panel = img.share(4..PANEL_W - 4, 0..SCREEN[1], |p| p == PANEL);
    assert!(
        panel > 0.45,
        "{name}: only {:.0}% of the panel is egui's dark panel colour {PANEL:?}\n{report}",
        panel * 100.0
    );
    let view = PANEL_W + 8..SCREEN[0] - 8;
    let table = img.share(view.clone(), 60..SCREEN[1] - 60, |p| near(p, TABLE, 3));
    assert!(table > 0.25, "{name}: only {:.0}% of the view shows the table colour {TABLE:?}\n{report}", table * 100.0);
    let red = img.share(view.clone(), 0..SCREEN[1], |[r, g, b]| r > 180 && g < 140 && b < 140);
    let blue = img.share(view.clone(), 0..SCREEN[1], |[r, g, b]| b > 180 && r < 140 && g < 190);
    assert!(
        red > 0.01 && blue > 0.01,
        "{name}: red {:.2}% and blue {:.2}% objects expected on the table\n{report}",
        red * 100.0,
        blue * 100.0
    );
    // The hand: the dark outline of the scripted flat hand, left of centre.
    let outline = img.share(PANEL_W + 150..PANEL_W + 500, 250..550, |p| p.iter().all(|&c| c < 90));
    assert!(
        outline > 0.002,
        "{name}: no hand outline where the script put the hand ({:.3}%)\n{report}",
        outline * 100.0
    );
    // No stray pixels from an uninitialized window around the view.
    let black = img.share(0..SCREEN[0], 0..SCREEN[1], |p| p == [0, 0, 0]);
    assert!(
        black < 0.01,
        "{name}: {:.1}% pure black pixels: part of the window was never drawn\n{report}",
        black * 100.0
    );
}

#[test]
fn the_demo_window_shows_the_panel_and_the_table_under_a_scripted_hand() {
    require("xwd", "x11-apps");
    let dir = work_dir("demo_window");
    std::fs::write(dir.join("sweep.toml"), SWEEP).expect("gesture file");
    // The app saves its own read-back at 3 s; as soon as that file exists
    // the X server's root window is dumped too, while the app still runs.
    let script = format!(
        "'{BIN}' demo --task sorting --technique particle --feedback --script sweep.toml \
            --screenshot-after 3 app.png --quit-after 8 --out out &
        pid=$!
        i=0; while [ ! -s app.png ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done
        sleep 0.3
        xwd -root -silent > root.xwd
        wait $pid"
    );
    let out = under_xvfb(&dir, &script);
    let report = format!(
        "exit: {:?}\nstdout: {}\nstderr: {}\nfiles in {}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
        dir.display()
    );
    assert!(out.status.success(), "the demo under Xvfb failed\n{report}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("window screenshot 1280x800"), "{report}");
    let steps: u64 = stderr
        .lines()
        .find_map(|l| {
            l.split(" physics steps").next().filter(|_| l.contains("frames,"))?.rsplit(' ').next()?.parse().ok()
        })
        .unwrap_or_else(|| panic!("no run summary\n{report}"));
    // 8 s of wall time; the physics keeps real time down to 10 frames per second.
    assert!(steps >= 60, "only {steps} physics steps in 8 s\n{report}");

    check_window("the app's read-back (app.png)", &Image::png(&dir.join("app.png")), &report);
    check_window("the X server's root window (root.xwd)", &Image::xwd(&dir.join("root.xwd")), &report);
}

#[test]
fn participant_mode_writes_study_rows_and_the_gestures_to_replay() {
    let dir = work_dir("demo_participant");
    std::fs::write(dir.join("sweep.toml"), SWEEP).expect("gesture file");
    // The box starts inside its region: each trial completes after the dwell.
    std::fs::write(dir.join("box.toml"), include_str!("scenes/box_in_region.toml")).expect("scene file");
    let script = format!(
        "'{BIN}' demo --participant 7 --condition proxy:on --task box.toml --reps 2 --trials-csv trials.csv \
         --script sweep.toml --out out --quit-after 60"
    );
    let out = under_xvfb(&dir, &script);
    let report = format!("exit: {:?}\nstderr: {}", out.status, String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{report}");
    let csv = std::fs::read_to_string(dir.join("trials.csv")).unwrap_or_else(|e| panic!("trials.csv: {e}\n{report}"));
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some(
            "participant,order_index,task,technique,feedback,repetition,practice,completion_time_s,completed,\
             restarts,objects_placed,steps,seed,version,strategy,hands_max,fingers_max,objects_moving_max,manners"
        ),
        "the study's header"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2, "two trials, two rows:\n{csv}");
    for (i, row) in rows.iter().enumerate() {
        // participant, order_index, task, technique, feedback, repetition, practice, time, completed, restarts, placed, steps, seed, version
        assert_eq!(
            &row[..7],
            ["7", &i.to_string(), "box.toml", "proxy", "true", &(i + 1).to_string(), "false"],
            "{csv}"
        );
        let time: f64 = row[7].parse().expect("a completion time");
        assert!((0.4..3.0).contains(&time), "completed after the 0.5 s dwell, not {time}\n{csv}");
        assert_eq!((row[8], row[12], row[13]), ("true", "0", env!("CARGO_PKG_VERSION")), "{csv}");
    }
    // Each trial's input was recorded where `study --replay` looks for it.
    for r in 1..=2 {
        let g = dir.join(format!("out/gestures/p7/box_proxy_on_r{r}.toml"));
        let gesture = surfacelab::input::Gesture::load(&g).unwrap_or_else(|e| panic!("{e}\n{report}"));
        assert_eq!(gesture.tracks().len(), 1, "the scripted flat hand");
    }
}

/// Ctrl-C (SIGINT) ends the demo as its close button does: exit status 0
/// and the summary line (the default action would kill it with neither).
#[test]
fn ctrl_c_ends_the_demo_with_its_summary() {
    let dir = work_dir("demo_ctrl_c");
    std::fs::write(dir.join("sweep.toml"), SWEEP).expect("gesture file");
    let script = format!(
        "'{BIN}' demo --task sorting --technique particle --script sweep.toml \
            --screenshot-after 1 up.png --quit-after 120 --out out &
        pid=$!
        i=0; while [ ! -s up.png ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done
        kill -INT $pid
        wait $pid"
    );
    let out = under_xvfb(&dir, &script);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let report = format!("exit: {:?}\nstderr: {stderr}", out.status);
    assert!(out.status.success(), "{report}");
    assert!(stderr.contains("frames, mean frame"), "no summary line\n{report}");
}

/// `calibrate` without `--points` opens the first frame in a window; four
/// real clicks (XTEST, through xdotool), one taken back with Backspace and
/// clicked again, and Enter write the calibration with exactly the clicked
/// camera pixels (the window shows the 640x480 frame one to one).
#[test]
fn calibrate_takes_four_clicks_on_the_first_frame() {
    require("xdotool", "xdotool");
    let dir = work_dir("calibrate_window");
    let frames = dir.join("frames");
    std::fs::create_dir_all(&frames).expect("frames folder");
    // A dim frame with a bright quadrilateral, as an infrared camera sees a lit table.
    let frame = image::GrayImage::from_fn(640, 480, |x, y| {
        image::Luma([if (60..580).contains(&x) && (50..440).contains(&y) { 90 } else { 20 }])
    });
    frame.save(frames.join("0000.png")).expect("frame");
    let clicks = [[100, 80], [540, 90], [600, 420], [40, 400]];
    let click = |p: [u32; 2]| format!("xdotool mousemove --window \"$wid\" {} {} click 1; sleep 0.4", p[0], p[1]);
    let script = format!(
        "'{BIN}' calibrate --images frames --out cal.toml --task sorting > calibrate.log 2>&1 &
        pid=$!
        wid=$(timeout 60 xdotool search --sync --onlyvisible --name 'surfacelab calibrate' | head -n 1)
        [ -n \"$wid\" ] || {{ echo 'no window'; kill $pid; exit 3; }}
        sleep 2
        xdotool windowfocus --sync \"$wid\"
        {}; {}; {}; {}
        xdotool key BackSpace; sleep 0.4
        {}
        xdotool key Return
        wait $pid; echo \"calibrate exit $?\"; cat calibrate.log",
        click(clicks[0]),
        click(clicks[1]),
        click(clicks[2]),
        click([300, 300]),
        click(clicks[3]),
    );
    let out = under_xvfb(&dir, &script);
    let report = format!(
        "exit: {:?}\nstdout: {}\nstderr: {}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("calibrate exit 0"), "{report}");
    let cal = std::fs::read_to_string(dir.join("cal.toml")).unwrap_or_else(|e| panic!("cal.toml: {e}\n{report}"));
    let expected = "image_points = [[100.0, 80.0], [540.0, 90.0], [600.0, 420.0], [40.0, 400.0]]";
    assert!(cal.contains(expected), "{cal}\n{report}");
    // The sorting table's corners, far-left first.
    assert!(cal.contains("table_points = [[-"), "{cal}");
}

/// The demo's mouse as a visitor uses it: real X pointer events (XTEST,
/// through xdotool) press a fingertip on the centre of `one_box`'s box,
/// move it 200 px right in 60 moves over 1.5 s, hold 0.5 s and release.
/// Under every technique the box follows the cursor most of the way, at
/// the demo's own frame rate and at `--max-fps 15`. The box's travel comes
/// from `--report` (its final pose), the cursor's from `--record` (the
/// first and last points the hand was at): no pixel is read.
#[test]
fn the_demo_mouse_drags_the_box_under_every_technique() {
    use common::thresholds::{DEMO_MOUSE_DRAG, DEMO_MOUSE_DRAG_JOINT};
    use std::fmt::Write;
    require("xdotool", "xdotool");
    let dir = work_dir("demo_mouse_drag");
    let task = concat!(env!("CARGO_MANIFEST_DIR"), "/tasks/cases/one_box.toml");
    // The box sits at the table's centre, which the 1280x800 window shows
    // at the centre of the view right of the 320 px panel: (800, 400).
    let mut moves = String::new();
    for i in 1..=60 {
        write!(moves, " sleep 0.025 mousemove --window \"$wid\" {} 400", 800 + (200 * i + 30) / 60).expect("writes");
    }
    let drag = format!("mousemove --window \"$wid\" 800 400 sleep 0.3 mousedown 1{moves} sleep 0.5 mouseup 1");
    let runs: Vec<(&str, &str)> =
        ["particle", "proxy", "hybrid", "joint"].into_iter().flat_map(|t| [(t, ""), (t, "--max-fps 15")]).collect();
    let mut script = String::new();
    for (i, (technique, fps)) in runs.iter().enumerate() {
        write!(
            script,
            "'{BIN}' demo --task '{task}' --technique {technique} {fps} --record rec{i}.toml --report rep{i}.json \
                --screenshot-after 1 ready{i}.png --quit-after 60 --out out > log{i}.txt 2>&1 &
            pid=$!
            i=0; while [ ! -s ready{i}.png ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done
            wid=$(xdotool search --onlyvisible --name 'surfacelab: ' | head -n 1)
            xdotool {drag}
            sleep 0.5
            kill -INT $pid; wait $pid; echo \"run {i} exit $?\"
            "
        )
        .expect("writes");
    }
    let out = under_xvfb(&dir, &script);
    let stdout = String::from_utf8_lossy(&out.stdout);
    for (i, (technique, fps)) in runs.iter().enumerate() {
        let log = std::fs::read_to_string(dir.join(format!("log{i}.txt"))).unwrap_or_default();
        let report = format!("{technique} {fps}\nstdout: {stdout}\nlog: {log}");
        assert!(stdout.contains(&format!("run {i} exit 0")), "{report}");
        let json =
            std::fs::read_to_string(dir.join(format!("rep{i}.json"))).unwrap_or_else(|e| panic!("{e}\n{report}"));
        let json: serde_json::Value = serde_json::from_str(&json).expect("a JSON report");
        let box_x = json["objects"][0]["position"][0].as_f64().expect("the box's x");
        let gesture = surfacelab::input::Gesture::load(dir.join(format!("rec{i}.toml")))
            .unwrap_or_else(|e| panic!("{e}\n{report}"));
        assert_eq!(gesture.tracks().len(), 1, "one fingertip\n{report}");
        let keys = gesture.tracks()[0].keys();
        let (first, last) = (keys[0].pos, keys[keys.len() - 1].pos);
        let travel = last[0] - first[0];
        // 200 px of a view about 930 px across a 1 m table.
        assert!((0.18..0.24).contains(&travel), "the cursor moved {travel} m\n{report}");
        let share = (box_x / travel) as f32;
        let threshold = if *technique == "joint" { DEMO_MOUSE_DRAG_JOINT } else { DEMO_MOUSE_DRAG };
        let rate = if fps.is_empty() { "its own frame rate" } else { fps };
        threshold.check(share, &format!("{technique} at {rate}: the box's travel over the cursor's"));
    }
}

/// `scripts/demo-fps.sh --tuio`, the frame-time measurement of
/// `docs/performance.md`, runs: the demo takes two TUIO hands from
/// `scripts/tuio-sweep.py`, and the script prints the demo's summary with
/// its frame and render times. Figures only, no timing is asserted.
#[test]
fn the_frame_time_script_drives_the_demo_with_two_tuio_hands() {
    require("Xvfb", "xvfb");
    require("python3", "python3");
    // The script starts its own Xvfb: not while xvfb-run picks a display.
    let _one_at_a_time = XVFB.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let dir = work_dir("demo_fps");
    let shot = dir.join("frame.png");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/demo-fps.sh");
    let out = Command::new("timeout")
        .args(["120", "bash"])
        .arg(&script)
        .args(["4", "--technique", "joint", "--tuio", "--", "--screenshot-after", "3"])
        .arg(&shot)
        .env("SURFACELAB", BIN)
        .output()
        .expect("bash runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let report = format!("stdout:\n{stdout}\nstderr:\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "exit {:?}\n{report}", out.status);
    println!("{stdout}");
    assert!(stdout.contains("sorting with joint on "), "{report}");
    let summary = stdout.lines().find(|l| l.contains("frames, mean frame")).unwrap_or_else(|| panic!("{report}"));
    assert!(summary.contains(" fps)") && summary.contains(", render "), "{summary}");
    assert!(shot.exists(), "no window screenshot\n{report}");
}

/// A TUIO 1.1 frame (`fseq` `f`) with two hand-sized blobs sweeping the
/// sorting table's pieces back and forth, 4 s a sweep, `t` seconds in.
fn sweeping_blobs(f: i32, t: f64) -> Vec<u8> {
    use rosc::{OscBundle, OscMessage, OscPacket, OscTime, OscType};
    let m = |args: Vec<OscType>| OscPacket::Message(OscMessage { addr: "/tuio/2Dblb".into(), args });
    let x = 0.5 + 0.3 * (std::f64::consts::TAU * t / 4.0).sin();
    let mut content = vec![m(vec!["alive".into(), OscType::Int(1), OscType::Int(2)])];
    for (id, y) in [(1, 0.35_f32), (2, 0.65)] {
        let args: Vec<OscType> = vec![
            "set".into(),
            OscType::Int(id),
            (x as f32).into(),
            y.into(),
            0.0f32.into(),
            0.12f32.into(),
            0.08f32.into(),
            0.0096f32.into(),
            0.0f32.into(),
            0.0f32.into(),
            0.0f32.into(),
            0.0f32.into(),
            0.0f32.into(),
        ];
        content.push(m(args));
    }
    content.push(m(vec!["fseq".into(), OscType::Int(f)]));
    rosc::encoder::encode(&OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content }))
        .expect("encodes")
}

/// `VmRSS` of process `pid` in MiB, `None` once it has gone.
fn resident_mib(pid: u32) -> Option<f64> {
    common::proc_status_kb(pid, "VmRSS").map(|kb| kb as f64 / 1024.0)
}

/// The demo over time: sorting under Particle with feedback, two TUIO blobs
/// sweeping its pieces at 60 packets/s for `SURFACELAB_SOAK_SECONDS`
/// (default 30). Resident memory, read from outside at a third of the run
/// and near its end, grows by at most 5%, and the summary names the worst
/// frame after the warm-up. `docs/performance.md` quotes the ten-minute run.
#[test]
fn a_demo_soak_under_tuio_keeps_its_memory() {
    let seconds: f64 = std::env::var("SURFACELAB_SOAK_SECONDS").ok().and_then(|v| v.parse().ok()).unwrap_or(30.0);
    let dir = work_dir("demo_soak");
    let port = 41_000 + (std::process::id() % 20_000) as u16;
    let script = format!(
        "'{BIN}' demo --task sorting --technique particle --feedback --tuio {port} --quit-after {seconds} --out out &
        echo $! > demo.pid
        wait $!"
    );
    let done = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let (flag, pid_file) = (done.clone(), dir.join("demo.pid"));
    let watcher = std::thread::spawn(move || {
        let socket = std::net::UdpSocket::bind("127.0.0.1:0").expect("a socket");
        let start = std::time::Instant::now();
        let mut samples = Vec::new();
        let mut pid = None;
        let mut f = 0;
        while !flag.load(std::sync::atomic::Ordering::Relaxed) {
            f += 1;
            let t = start.elapsed().as_secs_f64();
            let _ = socket.send_to(&sweeping_blobs(f, t), ("127.0.0.1", port));
            pid = pid.or_else(|| std::fs::read_to_string(&pid_file).ok().and_then(|p| p.trim().parse::<u32>().ok()));
            // Once a second: (seconds since the demo started, resident MiB).
            if f % 60 == 0
                && let Some(rss) = pid.and_then(resident_mib)
            {
                samples.push((t, rss));
            }
            std::thread::sleep(std::time::Duration::from_secs_f64(1.0 / 60.0));
        }
        samples
    });
    let limit = seconds as u32 + 120;
    let out = under_xvfb_for(&dir, &script, limit);
    done.store(true, std::sync::atomic::Ordering::Relaxed);
    let samples = watcher.join().expect("watcher");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let summary = stderr.lines().find(|l| l.contains("frames, mean frame")).unwrap_or_default().to_owned();
    println!("{summary}");
    assert!(out.status.success(), "exit {:?}\n{stderr}", out.status);
    assert!(summary.contains("worst frame "), "no worst frame in the summary: {stderr}");
    // The watcher's clock starts with Xvfb; the demo's window opens a few
    // seconds later, so the samples span a little less than the run.
    let at = |share: f64| {
        samples
            .iter()
            .find(|(t, _)| *t >= share * seconds)
            .copied()
            .unwrap_or_else(|| panic!("no sample at {share}: {samples:?}"))
    };
    // The last sample a second before the quit: at the quit the process
    // already frees its window and its GPU memory.
    let late = *samples.iter().rev().find(|(t, _)| *t <= seconds - 1.0).expect("samples");
    let early = at(1.0 / 3.0);
    println!("resident memory {:.1} MiB at {:.0} s, {:.1} MiB at {:.0} s", early.1, early.0, late.1, late.0);
    assert!(late.0 - early.0 >= seconds / 2.0, "samples too close: {samples:?}");
    assert!((late.1 - early.1).abs() <= 0.05 * early.1, "resident memory {early:?} -> {late:?}: {samples:?}");
}
