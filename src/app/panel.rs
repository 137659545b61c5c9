//! The side panel: task, technique, view and hand choices, technique
//! parameters, run controls, recording, and live statistics. It changes
//! simple settings in place and returns [`Action`]s for the rest, which the
//! window applies after the frame's UI pass.

use super::lab::Lab;
use super::view::progress_line;
use crate::input::{DEGREES_PER_NOTCH, MouseEvent, SPREAD_PER_NOTCH};
use crate::pipeline::surface::HandKind;
use crate::pipeline::technique::TechniqueKind;
use egui::{Color32, RichText, Slider};
use std::path::{Path, PathBuf};

/// Width of the panel in points.
pub const WIDTH: f32 = 320.0;

/// The hand modes a plain left drag can put down, with their keys 1..9.
pub const HAND_MODES: [(HandKind, &str); 9] = [
    (HandKind::Fingertips(1), "fingertip"),
    (HandKind::Fingertips(2), "two fingers"),
    (HandKind::FlatHand, "flat hand"),
    (HandKind::Edge, "edge of hand"),
    (HandKind::Fist, "fist"),
    (HandKind::Forearm, "forearm"),
    (HandKind::Ruler, "ruler"),
    (HandKind::Cup, "cup"),
    (HandKind::Card, "card"),
];

/// What the panel asks the window to do.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    LoadTask(String),
    Technique(TechniqueKind),
    /// A parameter that only takes effect in a new session changed.
    Restart,
    DefaultParameters,
    Reset,
    Screenshot,
    StartRecording(Option<PathBuf>),
    StopRecording,
}

/// Seconds between refreshes of the numbers in the panel (timings, counts,
/// task time). Numbers that changed every frame would make the whole panel
/// redraw every frame, which on a software rasteriser cost as much as the
/// 3D table ([`super::ui_cache`]); twice a second is as fast as they are read.
pub const NUMBERS_REFRESH_S: f64 = 0.5;

/// One `name: value` line of the statistics.
type Row = (String, String);

/// Panel state that is not the lab's.
#[derive(Debug, Clone, Default)]
pub struct PanelState {
    tasks: Vec<String>,
    path: String,
    record_path: String,
    /// The numbers as last refreshed, and the wall time they were taken.
    numbers: Option<(f64, Numbers)>,
}

/// The panel's changing numbers, refreshed every [`NUMBERS_REFRESH_S`].
#[derive(Debug, Clone, Default)]
struct Numbers {
    tuio: Vec<Row>,
    stats: Vec<Row>,
}

impl PanelState {
    pub fn new() -> Self {
        Self { tasks: task_choices(), ..Self::default() }
    }
}

/// positioning, sorting, steering, then every other `tasks/*.toml` and
/// `tasks/cases/*.toml`, as names `scene::load` resolves.
pub fn task_choices() -> Vec<String> {
    let mut names: Vec<String> = ["positioning", "sorting", "steering"].map(String::from).to_vec();
    let mut found = Vec::new();
    for root in [PathBuf::from("tasks"), Path::new(env!("CARGO_MANIFEST_DIR")).join("tasks")] {
        for (sub, prefix) in [(root.clone(), ""), (root.join("cases"), "cases/")] {
            let Ok(dir) = std::fs::read_dir(&sub) else {
                continue;
            };
            for entry in dir.flatten() {
                let p = entry.path();
                if p.extension().is_some_and(|e| e == "toml")
                    && let Some(stem) = p.file_stem()
                {
                    found.push(format!("{prefix}{}", stem.to_string_lossy()));
                }
            }
        }
    }
    found.sort();
    for f in found {
        if !names.contains(&f) {
            names.push(f);
        }
    }
    names
}

/// Draws the panel; returns what must happen after this frame.
pub fn show(ui: &mut egui::Ui, lab: &mut Lab, state: &mut PanelState) -> Vec<Action> {
    let mut actions = Vec::new();
    egui::ScrollArea::vertical().auto_shrink([false, false]).show(ui, |ui| {
        ui.heading("surfacelab");
        ui.label(RichText::new(&lab.scene().description).small());
        if !lab.scene().hint.is_empty() {
            ui.label(RichText::new(&lab.scene().hint).color(Color32::from_rgb(255, 210, 120)));
        }
        ui.separator();
        task_section(ui, lab, state, &mut actions);
        let numbers = match state.numbers.take() {
            Some((at, n)) if (0.0..NUMBERS_REFRESH_S).contains(&(lab.wall - at)) => (at, n),
            _ => (lab.wall, Numbers { tuio: tuio_rows(lab), stats: stat_rows(lab) }),
        };
        // TUIO first: someone testing a tracker reads its counters without scrolling.
        if !numbers.1.tuio.is_empty() {
            ui.separator();
            grid(ui, "tuio", &numbers.1.tuio);
        }
        ui.separator();
        view_section(ui, lab);
        ui.separator();
        parameters(ui, lab, &mut actions);
        ui.separator();
        controls(ui, lab, state, &mut actions);
        if let Some(status) = lab.status() {
            ui.label(RichText::new(status).color(Color32::from_rgb(140, 200, 255)));
        }
        ui.separator();
        grid(ui, "stats", &numbers.1.stats);
        ui.separator();
        help(ui);
        state.numbers = Some(numbers);
    });
    actions
}

/// The panel at the window's left edge, as the demo shows it.
pub fn show_side(ui: &mut egui::Ui, lab: &mut Lab, state: &mut PanelState) -> Vec<Action> {
    let mut actions = Vec::new();
    egui::Panel::left("panel").exact_size(WIDTH).resizable(false).show(ui, |ui| actions = show(ui, lab, state));
    actions
}

fn grid(ui: &mut egui::Ui, id: &str, rows: &[Row]) {
    egui::Grid::new(id).num_columns(2).striped(true).show(ui, |ui| {
        for (name, value) in rows {
            ui.label(name);
            ui.monospace(value);
            ui.end_row();
        }
    });
}

fn task_section(ui: &mut egui::Ui, lab: &Lab, state: &mut PanelState, actions: &mut Vec<Action>) {
    egui::Grid::new("task grid").num_columns(2).show(ui, |ui| {
        ui.label("Task");
        let mut chosen = lab.task.clone();
        egui::ComboBox::from_id_salt("task").width(190.0).selected_text(&lab.task).show_ui(ui, |ui| {
            for t in &state.tasks {
                ui.selectable_value(&mut chosen, t.clone(), t);
            }
        });
        if chosen != lab.task {
            actions.push(Action::LoadTask(chosen));
        }
        ui.end_row();
        ui.label("File");
        ui.horizontal(|ui| {
            let edit = ui
                .add(egui::TextEdit::singleline(&mut state.path).hint_text("path/to/scene.toml").desired_width(140.0));
            let enter = edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if (ui.button("Open").clicked() || enter) && !state.path.trim().is_empty() {
                actions.push(Action::LoadTask(state.path.trim().to_owned()));
            }
        });
        ui.end_row();
        ui.label("Technique");
        let mut kind = lab.technique();
        ui.horizontal_wrapped(|ui| {
            for k in TechniqueKind::registered() {
                ui.radio_value(&mut kind, k, k.name());
            }
        });
        if kind != lab.technique() {
            actions.push(Action::Technique(kind));
        }
        ui.end_row();
    });
}

fn view_section(ui: &mut egui::Ui, lab: &mut Lab) {
    // In participant mode the condition fixes what is shown.
    ui.add_enabled_ui(lab.participant.is_none(), |ui| {
        ui.horizontal(|ui| {
            ui.checkbox(&mut lab.view.feedback, "feedback (F)");
            ui.checkbox(&mut lab.view.contact_overlay, "contact image (O)");
        });
    });
    ui.horizontal(|ui| {
        ui.label("Left drag puts down");
        let mut mode = lab.input.mouse.mode();
        let name = HAND_MODES.iter().find(|m| m.0 == mode).map_or("?", |m| m.1);
        egui::ComboBox::from_id_salt("hand mode").selected_text(name).show_ui(ui, |ui| {
            for (i, (kind, label)) in HAND_MODES.iter().enumerate() {
                ui.selectable_value(&mut mode, *kind, format!("{} {label}", i + 1));
            }
        });
        if mode != lab.input.mouse.mode() {
            lab.input.mouse.handle(MouseEvent::Mode(mode));
        }
    });
    ui.label(
        RichText::new(
            "Shift flat hand, Ctrl edge, Alt two fingers; wheel turns; right click pins a hand (more below).",
        )
        .small()
        .weak(),
    );
}

fn parameters(ui: &mut egui::Ui, lab: &mut Lab, actions: &mut Vec<Action>) {
    egui::CollapsingHeader::new("Technique parameters").default_open(true).show(ui, |ui| {
        let kind = lab.technique();
        let c = lab.session.config_mut();
        let stride = c.particle_stride;
        let proxy = kind == TechniqueKind::PROXY;
        let fingers = matches!(
            kind,
            TechniqueKind::PROXY | TechniqueKind::PARTICLE | TechniqueKind::HYBRID | TechniqueKind::JOINT
        );
        let particles = matches!(kind, TechniqueKind::PARTICLE | TechniqueKind::HYBRID);
        ui.add(parameter(&mut c.proxy_mass, 0.05..=5.0, "proxy mass", proxy).logarithmic(true).suffix(" kg"));
        ui.add(parameter(&mut c.proxy_weight, 0.1..=10.0, "proxy weight", proxy).logarithmic(true).suffix(" N"));
        ui.add(parameter(&mut c.friction, 0.0..=3.0, "finger friction", fingers));
        ui.add(
            parameter(&mut c.joint_stiffness, 5.0..=1000.0, "joint stiffness", kind == TechniqueKind::JOINT)
                .logarithmic(true)
                .suffix(" N/m"),
        );
        ui.add(parameter(&mut c.particle_stride, 1..=8, "particle stride", particles).suffix(" px"));
        let stride_changed = c.particle_stride != stride;
        ui.label(
            RichText::new("Mass, weight and friction apply to new touches; the stride restarts the scene.")
                .small()
                .weak(),
        );
        if stride_changed {
            actions.push(Action::Restart);
        }
        if ui.button("Scene defaults").clicked() {
            actions.push(Action::DefaultParameters);
        }
    });
}

/// A technique parameter's slider, labelled strongly where the current
/// technique reads the parameter (`used`) and weakly where it does not.
fn parameter<'a, N: egui::emath::Numeric>(
    value: &'a mut N,
    range: std::ops::RangeInclusive<N>,
    label: &str,
    used: bool,
) -> Slider<'a> {
    let text = if used { RichText::new(label).strong() } else { RichText::new(label).weak() };
    Slider::new(value, range).text(text)
}

fn controls(ui: &mut egui::Ui, lab: &mut Lab, state: &mut PanelState, actions: &mut Vec<Action>) {
    ui.horizontal_wrapped(|ui| {
        if ui.button("Reset (R)").clicked() {
            actions.push(Action::Reset);
        }
        if ui.button(if lab.paused { "Resume (space)" } else { "Pause (space)" }).clicked() {
            lab.toggle_pause();
        }
        if ui.add_enabled(lab.paused, egui::Button::new("Step (N)")).clicked() {
            lab.request_step();
        }
        if ui.button("Screenshot (S)").clicked() {
            actions.push(Action::Screenshot);
        }
    });
    ui.horizontal(|ui| {
        if let Some(r) = lab.recording() {
            let text =
                RichText::new(format!("Stop recording ({:.1} s)", r.duration())).color(Color32::from_rgb(255, 90, 90));
            if ui.button(text).clicked() {
                actions.push(Action::StopRecording);
            }
        } else {
            if ui.button("Record").clicked() {
                let path = state.record_path.trim();
                actions.push(Action::StartRecording((!path.is_empty()).then(|| PathBuf::from(path))));
            }
            ui.add(
                egui::TextEdit::singleline(&mut state.record_path)
                    .hint_text("out/gestures/<task>_<time>.toml")
                    .desired_width(200.0),
            );
        }
    });
}

fn stat_rows(lab: &Lab) -> Vec<Row> {
    let s = &lab.stats;
    let counts = lab.session.counts();
    let mut rows = Vec::new();
    let mut row = |name: &str, value: String| rows.push((name.to_owned(), value));
    row("frame", format!("{:5.1} ms  {:4.0} fps", s.frame_ms.mean(), s.fps()));
    row("render", format!("{:5.1} ms", s.render_ms.mean()));
    row("physics steps", format!("{:4.2} / frame", s.steps.mean()));
    row("  rasterize", format!("{:5.2} ms", s.rasterize_ms.mean()));
    row("  vision", format!("{:5.2} ms", s.vision_ms.mean()));
    row("  technique", format!("{:5.2} ms", s.technique_ms.mean()));
    row("  step", format!("{:5.2} ms", s.step_ms.mean()));
    row("contacts", counts.contacts.to_string());
    row(
        match lab.technique() {
            TechniqueKind::PARTICLE | TechniqueKind::HYBRID => "particles",
            TechniqueKind::PROXY => "proxies",
            TechniqueKind::JOINT => "anchors",
            _ => "bodies",
        },
        counts.bodies.to_string(),
    );
    if counts.joints > 0 || lab.technique() == TechniqueKind::JOINT {
        row("joints", counts.joints.to_string());
    }
    let limit = lab.scene().time_limit_s;
    row("task time", format!("{:5.1} s of {limit:.0}", lab.session.time()));
    let progress = progress_line(lab);
    row("progress", if progress.is_empty() { "-".into() } else { progress });
    if lab.behind_s() > 0.05 {
        row("behind real time", format!("{:.1} s", lab.behind_s()));
    }
    rows
}

/// The TUIO listener's address and counters (none without `--tuio`).
fn tuio_rows(lab: &Lab) -> Vec<Row> {
    let Some(tuio) = &lab.input.tuio else {
        return Vec::new();
    };
    let t = tuio.stats();
    let (cursors, blobs) = tuio.live_counts();
    vec![
        ("TUIO".into(), format!("{}", tuio.local_addr())),
        ("  live".into(), format!("{cursors} cursors, {blobs} blobs")),
        (
            "  packets".into(),
            format!("{} ({} malformed, {} other profiles)", t.packets, t.malformed, t.unknown_profile),
        ),
        ("  frames".into(), format!("{} late, {} restarts", t.late_frames, t.restarts)),
    ]
}

fn help(ui: &mut egui::Ui) {
    egui::CollapsingHeader::new("Mouse and keys").default_open(false).show(ui, |ui| {
        for line in [
            "left drag: a hand of the chosen kind follows the cursor".to_owned(),
            "Shift / Ctrl / Alt + drag: flat hand / edge / two fingers".to_owned(),
            format!("wheel: turn the hand {DEGREES_PER_NOTCH:.0}° per notch"),
            format!("Shift + wheel: spread the fingers ({SPREAD_PER_NOTCH} per notch)"),
            "right click while dragging: pin that hand, drag another".to_owned(),
            "right click: lift pinned hands (or pin one at the cursor)".to_owned(),
            "keys: 1-9 hand kind, space pause, N step, R reset, F feedback, O contact image, S screenshot".to_owned(),
        ] {
            ui.label(RichText::new(line).small());
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::DemoOptions;

    /// The panel's texts that a window of 1280x800 points shows, each with
    /// the bottom of its line: `(text, bottom)`, laid out as the demo does.
    fn visible_texts(ctx: &egui::Context, lab: &mut Lab, state: &mut PanelState) -> Vec<(String, f32)> {
        let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1280.0, 800.0));
        let input = || egui::RawInput { screen_rect: Some(screen), ..Default::default() };
        // The first pass only measures; the second is what a frame shows.
        drop(ctx.run_ui(input(), |ui| drop(show_side(ui, lab, state))));
        let output = ctx.run_ui(input(), |ui| drop(show_side(ui, lab, state)));
        let mut texts = Vec::new();
        let mut stack: Vec<(egui::Shape, egui::Rect)> =
            output.shapes.into_iter().map(|c| (c.shape, c.clip_rect.intersect(screen))).collect();
        while let Some((shape, clip)) = stack.pop() {
            match shape {
                egui::Shape::Vec(v) => stack.extend(v.into_iter().map(|s| (s, clip))),
                egui::Shape::Text(t) => {
                    let bottom = t.pos.y + t.galley.size().y;
                    if bottom <= clip.max.y && t.pos.y >= clip.min.y {
                        texts.push((t.galley.text().to_owned(), bottom));
                    }
                }
                _ => {}
            }
        }
        texts
    }

    /// The TUIO counters are on screen at 1280x800 without scrolling.
    #[test]
    fn tuio_counters_show_without_scrolling() {
        let mut options = DemoOptions::new("sorting", TechniqueKind::PARTICLE);
        options.tuio = Some("127.0.0.1:0".parse().expect("an address"));
        let mut lab = Lab::new(&options, None).expect("opens with a TUIO listener");
        let texts = visible_texts(&egui::Context::default(), &mut lab, &mut PanelState::new());
        for wanted in ["0 cursors, 0 blobs", "0 (0 malformed, 0 other profiles)", "0 late, 0 restarts"] {
            assert!(texts.iter().any(|(t, _)| t == wanted), "`{wanted}` not on screen; visible: {texts:?}");
        }
    }

    /// Numbers that change every frame change on screen only every
    /// [`NUMBERS_REFRESH_S`], so the panel's pixels stay the same between.
    #[test]
    fn numbers_refresh_twice_a_second() {
        let mut lab = Lab::new(&DemoOptions::new("sorting", TechniqueKind::PARTICLE), None).expect("opens");
        let (ctx, mut state) = (egui::Context::default(), PanelState::new());
        let frame_line = |texts: &[(String, f32)]| {
            texts.iter().find(|(t, _)| t.ends_with("fps")).map(|(t, _)| t.clone()).expect("the frame line")
        };
        lab.stats.push_frame(20.0, 10.0, 1);
        let first = frame_line(&visible_texts(&ctx, &mut lab, &mut state));
        assert!(first.contains("20.0 ms"), "{first}");
        lab.wall += 0.2;
        lab.stats.push_frame(80.0, 70.0, 5);
        assert_eq!(frame_line(&visible_texts(&ctx, &mut lab, &mut state)), first);
        lab.wall += NUMBERS_REFRESH_S;
        let later = frame_line(&visible_texts(&ctx, &mut lab, &mut state));
        assert!(later.contains("50.0 ms"), "the mean of 20 and 80 ms: {later}");
    }
}
