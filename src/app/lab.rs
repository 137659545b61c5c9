//! The demo's state apart from the window: the running session and what
//! the panel changes, the merged input, the physics clock, recording,
//! participant trials and statistics. The window only feeds it events and
//! time, and draws what it holds; nothing here needs a display.

use super::DemoOptions;
use super::clock::Clock;
use super::participant_mode::{Phase, Trials};
use super::record::{Recording, timestamped};
use super::scene_view::{self, ViewOptions};
use super::stats::FrameStats;
use crate::harness::study::TrialResult;
use crate::input::tuio::TuioListener;
use crate::input::{CameraInput, Input, quantized};
use crate::pipeline::technique::{TechniqueConfig, TechniqueKind};
use crate::render::{self, DrawList, GpuContext};
use crate::scene::{self, Goal, Scene};
use crate::session::{Session, SessionOptions};
use anyhow::Context;
use std::path::PathBuf;

/// At most this many physics steps per frame (see [`Clock`]): real time
/// is kept down to 10 frames per second (software rendering manages 15-25).
const MAX_STEPS_PER_FRAME: u32 = 6;
/// Seconds the scene's hint stays over the view after a task opens.
const HINT_SECONDS: f64 = 10.0;
/// Seconds a participant sees a trial's result before the next one.
pub const BETWEEN_TRIALS_S: f64 = 3.0;
/// Seconds a status message stays in the panel.
const STATUS_SECONDS: f64 = 8.0;

/// Everything the demo shows and changes.
#[derive(Debug)]
pub struct Lab {
    pub session: Session,
    /// The task as given: a name under `tasks/` or a path.
    pub task: String,
    pub view: ViewOptions,
    pub paused: bool,
    step_requests: u32,
    clock: Clock,
    pub input: Input,
    /// Camera frames the session sees instead of the hands.
    camera: Option<CameraInput>,
    recording: Option<Recording>,
    /// Folder under which gestures/ and screenshots/ are written.
    pub out_dir: PathBuf,
    pub stats: FrameStats,
    status: Option<(String, f64)>,
    pub participant: Option<Trials>,
    /// Wall-clock seconds since the demo opened (set by the window).
    pub wall: f64,
    hint_until: f64,
}

impl Lab {
    /// The demo's state for `options`; `camera` is `options.camera`, taken
    /// out by the caller (it owns a capture thread and is not cloned).
    pub fn new(options: &DemoOptions, camera: Option<CameraInput>) -> anyhow::Result<Self> {
        let scene = scene::load(&options.task)?;
        let session = Session::new(&scene, options.technique, SessionOptions::default())?;
        let tuio = options
            .tuio
            .map(|addr| TuioListener::bind(addr).with_context(|| format!("--tuio: cannot listen on UDP {addr}")))
            .transpose()?;
        let participant = options.participant.clone().map(|p| Trials::open(p, &options.task)).transpose()?;
        Ok(Self {
            session,
            task: options.task.clone(),
            view: ViewOptions { feedback: options.feedback, contact_overlay: options.contact_overlay },
            paused: false,
            step_requests: 0,
            clock: Clock::new(f64::from(scene.physics.dt), MAX_STEPS_PER_FRAME),
            input: Input::new(options.script.clone(), tuio),
            camera,
            recording: None,
            out_dir: options.out_dir.clone(),
            stats: FrameStats::default(),
            status: None,
            participant,
            wall: 0.0,
            hint_until: HINT_SECONDS,
        })
    }

    pub fn scene(&self) -> &Scene {
        self.session.scene()
    }

    /// Table [width, depth] in metres.
    pub fn table(&self) -> [f32; 2] {
        let t = &self.scene().table;
        [t.width, t.depth]
    }

    pub fn technique(&self) -> TechniqueKind {
        self.session.technique_kind()
    }

    /// Opens another task with its own technique defaults.
    pub fn load_task(&mut self, task: &str) -> anyhow::Result<()> {
        let scene = scene::load(task)?;
        let session = Session::new(&scene, self.technique(), SessionOptions::default())?;
        self.stop_recording();
        self.session = session;
        task.clone_into(&mut self.task);
        self.clock = Clock::new(f64::from(scene.physics.dt), MAX_STEPS_PER_FRAME);
        self.hint_until = self.wall + HINT_SECONDS;
        self.say(format!("opened {}", scene.origin));
        Ok(())
    }

    /// Switches technique, keeping the tuned parameters; the scene restarts.
    pub fn set_technique(&mut self, kind: TechniqueKind) -> anyhow::Result<()> {
        let config = self.session.config_mut().clone();
        self.restart(kind, Some(config))
    }

    /// A fresh session of the same scene (time 0, objects back, a running
    /// script from its start); tuned parameters are kept. The hint shows
    /// again and the time the physics fell behind counts from zero, as for
    /// a task just opened.
    pub fn reset(&mut self) -> anyhow::Result<()> {
        self.set_technique(self.technique())?;
        self.clock = Clock::new(self.clock.dt(), MAX_STEPS_PER_FRAME);
        self.hint_until = self.wall + HINT_SECONDS;
        Ok(())
    }

    /// Technique parameters back to the scene's defaults; the scene restarts.
    pub fn default_parameters(&mut self) -> anyhow::Result<()> {
        self.restart(self.technique(), None)
    }

    fn restart(&mut self, kind: TechniqueKind, config: Option<TechniqueConfig>) -> anyhow::Result<()> {
        let scene = self.scene().clone();
        self.session = Session::new(&scene, kind, SessionOptions { config, ..SessionOptions::default() })?;
        self.clock.clear();
        // A recording restarts with the scene, so it replays from this state.
        if let Some(r) = self.recording.take() {
            self.recording = Some(Recording::new(r.path().to_path_buf()));
        }
        Ok(())
    }

    /// Steps once on the next frame (while paused).
    pub fn request_step(&mut self) {
        self.step_requests += 1;
    }

    pub fn toggle_pause(&mut self) {
        self.paused = !self.paused;
        self.clock.clear();
    }

    /// Runs the physics steps real time asks for, `elapsed_s` after the
    /// last frame, at wall time [`Lab::wall`]; returns how many ran.
    ///
    /// Each step takes its hands at the real time it stands for, on the
    /// clock's own grid ([`Clock::stood_for`]): the steps of successive
    /// frames lie exactly `dt` apart, so a steady drag moves the hand the
    /// same distance every step; steps anchored on each frame's own wall
    /// time would stand 0.5 to 20 ms apart, as frames and the step grid
    /// beat (`docs/design/demo-input-timing.md`).
    ///
    /// The window hears of input only between frames, so the events of a
    /// slow frame arrive together; they are first spread over the frame
    /// ([`Input::spread`]).
    ///
    /// The hands pass through [`quantized`], as a recording stores them, so
    /// that a recording replays this run exactly.
    pub fn advance(&mut self, elapsed_s: f64) -> u32 {
        let due = if self.paused {
            self.clock.clear();
            std::mem::take(&mut self.step_requests)
        } else {
            self.clock.advance(elapsed_s)
        };
        if !self.participant_gate() {
            self.input.apply_until(self.wall);
            return 0;
        }
        let table = self.table();
        if elapsed_s.is_finite() && elapsed_s > 0.0 {
            self.input.spread(self.wall - elapsed_s, self.wall);
        }
        let mut ran = 0;
        for k in 0..due {
            let t = self.session.time();
            let at = self.wall - self.clock.stood_for(k, due);
            let hands: Vec<_> = self.input.hands_at(at, t, table).iter().map(quantized).collect();
            let stepped = match &mut self.camera {
                Some(camera) => {
                    let sensor = *self.session.sensor();
                    let dt = self.clock.dt();
                    let instant = self.input.instant_at(at);
                    camera
                        .image_at(t, dt, instant, &sensor)
                        .map_err(anyhow::Error::new)
                        .and_then(|image| self.session.step_image(image).map_err(anyhow::Error::new))
                        .map(|_| ())
                }
                None => self.session.step(&hands).map(|_| ()).map_err(anyhow::Error::new),
            };
            if let Err(e) = stepped {
                self.paused = true;
                self.say(format!("physics stopped: {e:#}"));
                break;
            }
            ran += 1;
            self.stats.push_stages(&self.session.last_times());
            if let Some(r) = &mut self.recording {
                r.record(t, &hands);
            }
            if self.participant.is_some() && self.end_trial_if_over() {
                break;
            }
        }
        self.input.apply_until(self.wall);
        ran
    }

    /// Participant mode: whether the session may step now, moving through
    /// the trial phases. Always true otherwise.
    fn participant_gate(&mut self) -> bool {
        let table = self.table();
        let Some(trials) = &mut self.participant else {
            return true;
        };
        match trials.phase {
            Phase::Running => true,
            Phase::Ready => {
                self.input.apply_until(self.wall);
                if self.input.hands(self.session.time(), table).is_empty() {
                    return false;
                }
                trials.phase = Phase::Running;
                if let Some(path) = trials.gesture_path() {
                    self.recording = Some(Recording::new(path));
                }
                true
            }
            Phase::Finished { at, .. } => {
                if self.wall - at >= BETWEEN_TRIALS_S {
                    trials.next();
                    if trials.phase == Phase::Ready
                        && let Err(e) = self.restart(self.technique(), None)
                    {
                        self.say(format!("could not start the next trial: {e:#}"));
                    }
                }
                false
            }
            Phase::Done => false,
        }
    }

    /// Participant mode: after a step, ends the trial if the goal is met or
    /// the scene's time limit has passed (the study's rules).
    fn end_trial_if_over(&mut self) -> bool {
        let p = self.session.progress();
        let limit = f64::from(self.scene().time_limit_s);
        if !p.complete && self.session.time() < limit {
            return false;
        }
        // Failed at the limit, recorded at the limit (as the study's runners do).
        let result = TrialResult::from_progress(&p, self.session.frames(), limit);
        self.stop_recording();
        let wall = self.wall;
        if let Some(trials) = &mut self.participant
            && let Err(e) = trials.finish(&result, wall)
        {
            // The row could not be written: say so and stop, never lose it silently.
            self.say(format!("{e:#}"));
            self.paused = true;
        }
        true
    }

    /// True when participant mode has run all its trials.
    pub fn finished(&self) -> bool {
        self.participant.as_ref().is_some_and(|t| t.phase == Phase::Done)
    }

    /// What to draw into a view of `size` pixels: the whole table and
    /// everything on it, whatever the view's shape
    /// ([`scene_view::fitted_draw_list`]).
    pub fn draw_list(&self, size: [u32; 2]) -> DrawList {
        scene_view::fitted_draw_list(&self.session, self.view, size)
    }

    pub fn recording(&self) -> Option<&Recording> {
        self.recording.as_ref()
    }

    /// Starts recording to `path` (default `out/gestures/<task>_<time>.toml`)
    /// from a freshly reset scene.
    pub fn start_recording(&mut self, path: Option<PathBuf>) -> anyhow::Result<()> {
        self.stop_recording();
        self.reset()?;
        let path = path.unwrap_or_else(|| timestamped(&self.out_dir.join("gestures"), &self.task, "toml"));
        self.say(format!("recording to {} (the scene restarted)", path.display()));
        self.recording = Some(Recording::new(path));
        Ok(())
    }

    /// Saves the recording, if one is running.
    pub fn stop_recording(&mut self) {
        let Some(r) = self.recording.take() else {
            return;
        };
        let message = match r.save() {
            Ok((path, g)) => format!(
                "saved {:.1} s, {} touches to {}; replay: surfacelab run --task {} --technique {} --gesture {}",
                g.duration(),
                g.tracks().len(),
                path.display(),
                self.task,
                self.technique(),
                path.display()
            ),
            Err(e) => format!("recording not saved: {e:#}"),
        };
        tracing::info!("{message}");
        self.say(message);
    }

    /// Drops the recording, if one is running, without writing it.
    pub fn discard_recording(&mut self) {
        self.recording = None;
    }

    /// Renders the current draw list off-screen at `size` and writes
    /// `out/screenshots/<task>_<time>.png`.
    pub fn screenshot(&mut self, gpu: &GpuContext, size: [u32; 2]) {
        let path = timestamped(&self.out_dir.join("screenshots"), &self.task, "png");
        let result = render::render_to_image(gpu, &self.draw_list(size), size[0].max(16), size[1].max(16))
            .and_then(|image| render::save_png(&image, &path));
        self.say(match result {
            Ok(()) => format!("screenshot: {}", path.display()),
            Err(e) => format!("screenshot failed: {}", crate::error::chain(&e)),
        });
    }

    /// Shows a message in the panel (and the log) for a few seconds.
    pub fn say(&mut self, message: impl Into<String>) {
        let message = message.into();
        tracing::info!("{message}");
        self.status = Some((message, self.wall));
    }

    pub fn status(&self) -> Option<&str> {
        self.status.as_ref().filter(|(_, at)| self.wall - at < STATUS_SECONDS).map(|(m, _)| m.as_str())
    }

    /// The scene's hint while it should still be shown over the view.
    pub fn hint(&self) -> Option<&str> {
        (self.wall < self.hint_until && !self.scene().hint.is_empty()).then_some(self.scene().hint.as_str())
    }

    /// Waypoints of a steering goal (0 otherwise).
    pub fn waypoints(&self) -> usize {
        match &self.scene().goal {
            Goal::Steering(g) => g.waypoints.len(),
            _ => 0,
        }
    }

    /// Real seconds the physics has fallen behind since the start.
    pub fn behind_s(&self) -> f64 {
        self.clock.dropped()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{Button, Gesture, Modifiers, MouseEvent, SourceEvent};
    use crate::scene::ObjectId;

    /// A mouse path as a window delivers it: `(wall second, event)`.
    type Events = Vec<(f64, SourceEvent)>;

    /// Drives `lab` with frames `1/fps` apart until wall time `until`,
    /// delivering each event before the first frame at or after its stamp
    /// (as a window does: events queue while a frame renders).
    fn play(lab: &mut Lab, events: &Events, fps: f64, until: f64) {
        let mut next = 0;
        let frames = (until * fps).ceil() as usize;
        for f in 1..=frames {
            lab.wall = f as f64 / fps;
            while next < events.len() && events[next].0 <= lab.wall {
                lab.input.push(events[next].0, events[next].1);
                next += 1;
            }
            lab.advance(1.0 / fps);
        }
    }

    fn mouse(at: f64, e: MouseEvent) -> (f64, SourceEvent) {
        (at, SourceEvent::Mouse(e))
    }

    /// A drag from `from` by `by` metres over `seconds`, the cursor
    /// reporting at 125 Hz, starting at wall time `t0`.
    fn drag(events: &mut Events, t0: f64, from: [f32; 2], by: [f32; 2], seconds: f64) {
        events.push(mouse(t0, MouseEvent::Moved(from)));
        events.push(mouse(t0, MouseEvent::Pressed(Button::Left)));
        let n = (seconds * 125.0) as usize;
        for i in 1..=n {
            let s = i as f32 / n as f32;
            let at = t0 + seconds * i as f64 / n as f64;
            events.push(mouse(at, MouseEvent::Moved([from[0] + by[0] * s, from[1] + by[1] * s])));
        }
        events.push(mouse(t0 + seconds + 0.004, MouseEvent::Released(Button::Left)));
    }

    fn replay(lab: &Lab, path: &std::path::Path) -> Session {
        let gesture = Gesture::load(path).expect("a gesture file");
        let mut replay = Session::new(lab.scene(), lab.technique(), SessionOptions::default()).expect("session");
        while replay.frames() < lab.session.frames() {
            let hands = gesture.sample(replay.time());
            replay.step(&hands).expect("steps");
        }
        replay
    }

    /// What the record button writes replays, through `run`'s path, to
    /// the very state the demo showed: every object bit for bit, after
    /// 30 s of fingertip drags, flat-hand and hand-edge sweeps on the
    /// sorting task at a frame rate that never divides the step.
    #[test]
    fn a_recording_replays_the_live_run_bit_for_bit() {
        let dir = std::env::temp_dir().join(format!("surfacelab-lab-{}", std::process::id()));
        let path = dir.join("sort.toml");
        let mut lab = Lab::new(&DemoOptions::new("sorting", TechniqueKind::PARTICLE), None).expect("opens");
        lab.start_recording(Some(path.clone())).expect("starts");
        let mut events = Events::new();
        let shift = |on: bool| MouseEvent::Modifiers(Modifiers { shift: on, ..Modifiers::default() });
        let ctrl = |on: bool| MouseEvent::Modifiers(Modifiers { ctrl: on, ..Modifiers::default() });
        for round in 0..5 {
            let t0 = 6.0 * f64::from(round);
            let y = -0.2 + 0.1 * round as f32;
            drag(&mut events, t0 + 0.2, [-0.3, y], [0.35, 0.05], 1.4);
            events.push(mouse(t0 + 2.0, shift(true)));
            drag(&mut events, t0 + 2.1, [0.3, y + 0.1], [-0.4, -0.1], 1.6);
            events.push(mouse(t0 + 3.8, shift(false)));
            events.push(mouse(t0 + 3.9, ctrl(true)));
            drag(&mut events, t0 + 4.0, [0.0, -0.3], [0.1, 0.45], 1.5);
            events.push(mouse(t0 + 5.6, ctrl(false)));
        }
        play(&mut lab, &events, 23.0, 30.0);
        assert!(lab.session.time() > 25.0, "{} s simulated", lab.session.time());
        lab.stop_recording();
        assert!(lab.status().is_some_and(|s| s.contains("saved")), "{:?}", lab.status());
        let replayed = replay(&lab, &path);
        let mut moved = 0.0_f32;
        for id in lab.scene().object_ids() {
            let (live, again) = (lab.session.world().object_pose(id), replayed.world().object_pose(id));
            assert_eq!(live.position, again.position, "object {id:?}");
            assert_eq!(live.rotation, again.rotation, "object {id:?}");
            moved = moved.max((live.position - lab.scene().object(id).position).truncate().length());
        }
        assert!(moved > 0.05, "the sweeps moved something: {moved} m at most");
        let _ = std::fs::remove_dir_all(dir);
    }

    /// A slow frame rate must not weaken a drag: its catch-up steps see the
    /// hand move continuously. A fingertip drags the box 22 cm in 1.5 s at
    /// 8 and at 60 frames per second.
    #[test]
    fn a_drag_at_8_fps_moves_the_box_as_far_as_at_60() {
        for technique in [TechniqueKind::PARTICLE, TechniqueKind::PROXY] {
            let moved = |fps: f64| {
                let mut lab = Lab::new(&DemoOptions::new("tasks/cases/one_box.toml", technique), None).expect("opens");
                let mut events = Events::new();
                drag(&mut events, 0.3, [-0.05, 0.0], [0.22, 0.0], 1.5);
                play(&mut lab, &events, fps, 3.0);
                lab.session.world().object_pose(ObjectId::new(0)).position.x
            };
            let (slow, fast) = (moved(8.0), moved(60.0));
            eprintln!("{technique}: the box moved {slow:.4} m at 8 fps, {fast:.4} m at 60 fps");
            assert!(fast > 0.1, "{technique}: the drag moves the box at 60 fps ({fast} m)");
            assert!((slow - fast).abs() <= 0.1 * fast, "{technique}: {slow} m at 8 fps against {fast} m at 60 fps");
        }
    }

    /// Reset is a fresh start: the hint is back for its ten seconds and the
    /// lag of a stall before it is forgotten.
    #[test]
    fn reset_shows_the_hint_again_and_forgets_the_lag() {
        let mut lab = Lab::new(&DemoOptions::new("sorting", TechniqueKind::PARTICLE), None).expect("opens");
        assert!(lab.hint().is_some(), "a new task shows its hint");
        lab.wall = 20.0;
        lab.advance(2.0); // a two-second stall: most of it dropped
        assert!(lab.hint().is_none(), "gone after {HINT_SECONDS} s");
        assert!(lab.behind_s() > 1.5, "{} s behind", lab.behind_s());
        lab.reset().expect("resets");
        assert_eq!(lab.hint(), Some(lab.scene().hint.as_str()));
        assert_eq!(lab.behind_s(), 0.0);
        lab.wall = 20.0 + HINT_SECONDS + 0.1;
        assert!(lab.hint().is_none(), "and gone again {HINT_SECONDS} s later");
    }

    #[test]
    fn the_view_always_fits_the_whole_table() {
        let lab = Lab::new(&DemoOptions::new("positioning", TechniqueKind::JOINT), None).expect("opens");
        for size in [[960, 800], [1280, 800], [400, 900], [1600, 400]] {
            let list = lab.draw_list(size);
            let camera = crate::render::CameraMatrices::for_draw_list(&list, size);
            let [w, d] = lab.table();
            for corner in [[-w, -d], [w, d], [-w, d], [w, -d]] {
                let p = camera
                    .world_to_pixel(size, glam::Vec3::new(corner[0] / 2.0, corner[1] / 2.0, 0.0))
                    .expect("in front");
                assert!(
                    p.x >= 0.0 && p.y >= 0.0 && p.x <= size[0] as f32 && p.y <= size[1] as f32,
                    "{size:?}: corner at {p}"
                );
            }
        }
    }
}
