//! A technique defined here, outside the crate, registered by name: the
//! behaviour suite gains its column, a study runs it and names it in
//! `trials.csv`, `summary.csv` and the report, resuming that study in a
//! binary without it exits 2 naming it, and the command line lists it.

use glam::Vec2;
use std::path::Path;
use std::process::Command;
use std::sync::OnceLock;
use surfacelab::harness::behaviour::{Expectation, Metric, cases, cells, markdown, run_case, suite_kinds};
use surfacelab::harness::participant::ScriptedRunner;
use surfacelab::harness::study::{RunOptions, StudyDesign, run_study};
use surfacelab::pipeline::surface::PixelPoint;
use surfacelab::pipeline::technique::{
    Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput, TechniqueKind, TechniqueSpec, register,
};
use surfacelab::pipeline::world::{TechniqueWorld, World, WorldError};

/// Sets the velocity of the object nearest each contact (within 8 cm) to
/// close the gap to the contact in a fifth of a second: a kinematic tether,
/// nothing like the built-in techniques.
#[derive(Debug)]
struct Tether {
    config: TechniqueConfig,
    contacts: usize,
}

impl Technique for Tether {
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        self.contacts = input.frame.contacts.len();
        for c in &input.frame.contacts {
            let hand = Vec2::from(input.sensor.to_table(PixelPoint::from(c.blob.centroid)));
            let nearest = world
                .object_ids()
                .map(|id| (id, world.object_pose(id)))
                .filter(|(_, p)| p.active && p.position.truncate().distance(hand) < 0.08)
                .min_by(|a, b| {
                    a.1.position.truncate().distance(hand).total_cmp(&b.1.position.truncate().distance(hand))
                });
            let Some((id, pose)) = nearest else { continue };
            if let Some(mut body) = world.push_object(id)
                && body.is_dynamic()
            {
                let v = (hand - pose.position.truncate()) / 0.2;
                body.set_linvel(v.extend(pose.linvel.z));
            }
        }
        Ok(())
    }

    fn feedback(&self, _world: &World) -> Feedback {
        Feedback::default()
    }

    fn counts(&self) -> TechniqueCounts {
        TechniqueCounts { contacts: self.contacts, ..TechniqueCounts::default() }
    }

    fn clear(&mut self, _world: &mut TechniqueWorld<'_>) {}

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}

const TWIST_LIMIT: &str = "a tether moves an object's centre and cannot turn it";

/// Registered once per test process (names are unique in a process).
fn tether() -> TechniqueKind {
    static KIND: OnceLock<TechniqueKind> = OnceLock::new();
    *KIND.get_or_init(|| {
        register(
            TechniqueSpec::new("tether", |config| Box::new(Tether { config, contacts: 0 }))
                .label("Tether")
                .limit("two_finger_twist", TWIST_LIMIT),
        )
        .expect("registers")
    })
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn a_registered_technique_joins_the_behaviour_suite() {
    let tether = tether();
    assert!(suite_kinds().contains(&tether));
    assert_eq!("Tether".parse::<TechniqueKind>(), Ok(tether));
    let all = cases();
    let twist = all.iter().find(|c| c.name == "two_finger_twist").expect("case");
    assert_eq!(twist.expectation(tether), Expectation::Shown { why: TWIST_LIMIT });
    let drag = all.iter().find(|c| c.name == "ball_light_touch").expect("case");
    assert_eq!(drag.expectation(tether), Expectation::Works);

    let measured = run_case(drag, tether, root()).expect("runs");
    assert_eq!(measured.nan_count, 0);
    // The case's own bound: a light touch moves the ball at least 4 cm.
    assert!(measured.get(Metric::Along) >= 0.04, "moved {:.3} m", measured.get(Metric::Along));
    assert!(cells(drag, &measured).iter().all(|c| !c.verdict.is_failure()));
    let twisted = run_case(twist, tether, root()).expect("runs");
    let table = markdown(
        &[drag.clone(), twist.clone()],
        &[TechniqueKind::JOINT, tether],
        &[
            run_case(drag, TechniqueKind::JOINT, root()).expect("runs"),
            measured,
            run_case(twist, TechniqueKind::JOINT, root()).expect("runs"),
            twisted,
        ],
    );
    assert!(table.starts_with("| behaviour | measure | works when | joint | tether |"), "{table}");
    assert!(table.contains(&format!("- two_finger_twist / tether: not asserted: {TWIST_LIMIT}")), "{table}");
}

#[test]
fn a_study_runs_and_names_a_registered_technique_and_resume_without_it_exits_2() {
    let tether = tether();
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("study");
    let design = StudyDesign {
        participants: 1,
        tasks: vec!["positioning".into()],
        techniques: vec![TechniqueKind::JOINT, tether],
        repetitions: 1,
        practice: false,
        ..StudyDesign::default()
    };
    let options = RunOptions { progress: false, ..RunOptions::default() };
    let outcome = run_study(&design, &out, &ScriptedRunner::new(design.clone(), None), &options).expect("runs");
    assert_eq!((outcome.ran, outcome.errors), (4, 0));

    let trials = std::fs::read_to_string(out.join("trials.csv")).expect("trials.csv");
    assert_eq!(trials.lines().filter(|l| l.contains(",tether,")).count(), 2, "{trials}");
    let summary = std::fs::read_to_string(out.join("summary.csv")).expect("summary.csv");
    assert_eq!(summary.lines().filter(|l| l.contains(",tether,")).count(), 2, "{summary}");
    let report = std::fs::read_to_string(out.join("report.md")).expect("report.md");
    assert!(report.contains("Tether"), "{report}");
    let run_toml = std::fs::read_to_string(out.join("run.toml")).expect("run.toml");
    assert!(run_toml.contains("\"tether\""), "{run_toml}");

    // The surfacelab binary has no tether: resuming must refuse, naming it.
    let resumed = Command::new(env!("CARGO_BIN_EXE_surfacelab"))
        .args(["study", "--no-progress", "--resume"])
        .arg(&out)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&resumed.stderr);
    assert_eq!(resumed.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("\"tether\" is not registered"), "{stderr}");
}

/// A technique that declares an effect gets it on a scene that does not
/// declare it; the world simulates only the effects a scene calls for.
#[test]
fn a_technique_that_needs_an_effect_gets_it() {
    use surfacelab::scene::{Effect, SceneBuilder, ShapeSpec};
    use surfacelab::session::{Session, SessionOptions};
    static KIND: OnceLock<TechniqueKind> = OnceLock::new();
    let jointed = *KIND.get_or_init(|| {
        register(
            TechniqueSpec::new("tether_jointed", |config| Box::new(Tether { config, contacts: 0 }))
                .needs(Effect::Joints),
        )
        .expect("registers")
    });
    let scene = SceneBuilder::new("plain")
        .effects(&[Effect::Gravity, Effect::Friction])
        .object("puck", ShapeSpec::Sphere { radius: 0.02 }, [0.0, 0.0], 0.05, "red")
        .build()
        .expect("scene");
    assert!(!scene.effects.contains(Effect::Joints));
    let with = Session::new(&scene, jointed, SessionOptions::default()).expect("session");
    assert!(with.world().effects().contains(Effect::Joints));
    let without = Session::new(&scene, tether(), SessionOptions::default()).expect("session");
    assert!(!without.world().effects().contains(Effect::Joints));
}

#[test]
fn the_command_line_lists_registered_techniques() {
    let tether = tether();
    let mut cli = surfacelab::cli::command();
    let study = cli.find_subcommand_mut("study").expect("study").render_help().to_string();
    assert!(study.contains("joint, proxy, particle, hybrid, tether"), "{study}");
    assert!(cli.render_help().to_string().contains(tether.name()));

    // The binary itself lists its own (built-in) ones, and refuses others by listing them.
    let help = Command::new(env!("CARGO_BIN_EXE_surfacelab")).args(["run", "--help"]).output().expect("runs");
    let text = String::from_utf8_lossy(&help.stdout);
    assert!(text.contains("Interaction technique: direct, joint, proxy, particle, hybrid"), "{text}");
    let bad = Command::new(env!("CARGO_BIN_EXE_surfacelab"))
        .args(["screenshot", "--technique", "tether", "--out", "/nonexistent/x.png"])
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("unknown technique \"tether\" (registered: direct, joint, proxy, particle, hybrid)"),
        "{stderr}"
    );
}
