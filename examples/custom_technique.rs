//! A technique that is not in surfacelab, registered by name and run through
//! the behaviour suite and a one-participant study.
//!
//! The "magnet" pulls the nearest object within reach of each contact
//! towards the contact, with a critically damped spring on the object's
//! centre: an object follows a hand that hovers near it without being
//! touched, which none of the paper's techniques does.
//!
//! `cargo run --release --example custom_technique` prints the behaviour
//! table (Joint beside Magnet) and the study's summary, and exits 1 if the
//! magnet fails the light-touch case or the study's files do not name it.

use glam::{Vec2, Vec3};
use std::path::Path;
use std::process::ExitCode;
use surfacelab::harness::behaviour::{Metric, cases, cells, markdown, run_suite};
use surfacelab::harness::participant::ScriptedRunner;
use surfacelab::harness::study::{RunOptions, StudyDesign, SummaryRow, run_study};
use surfacelab::pipeline::surface::PixelPoint;
use surfacelab::pipeline::technique::{
    Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput, TechniqueKind, TechniqueSpec, register,
};
use surfacelab::pipeline::world::{TechniqueWorld, World, WorldError};

/// How far from a contact the magnet reaches (m).
const REACH: f32 = 0.12;
/// Spring stiffness per kilogram (1/s²): a 0.3 m/s drag trails by about 4 cm.
const STIFFNESS: f32 = 400.0;
/// Critical damping for that stiffness (1/s): no overshoot at the hand.
const DAMPING: f32 = 40.0;

/// Pulls the nearest object under or near each contact towards it.
#[derive(Debug)]
struct Magnet {
    config: TechniqueConfig,
    /// Contact point and pulled object's centre, this frame (feedback lines).
    pulls: Vec<(Vec3, Vec3)>,
    contacts: usize,
}

impl Magnet {
    fn new(config: TechniqueConfig) -> Magnet {
        Magnet { config, pulls: Vec::new(), contacts: 0 }
    }
}

impl Technique for Magnet {
    fn apply(&mut self, input: &TechniqueInput<'_>, world: &mut TechniqueWorld<'_>) -> Result<(), WorldError> {
        self.pulls.clear();
        self.contacts = input.frame.contacts.len();
        for contact in &input.frame.contacts {
            let hand = Vec2::from(input.sensor.to_table(PixelPoint::from(contact.blob.centroid)));
            let nearest = world
                .object_ids()
                .map(|id| (id, world.object_pose(id)))
                .filter(|(_, pose)| pose.active)
                .map(|(id, pose)| (id, pose, pose.position.truncate().distance(hand)))
                .filter(|&(_, _, d)| d <= REACH)
                .min_by(|a, b| a.2.total_cmp(&b.2));
            let Some((id, pose, _)) = nearest else { continue };
            let Some(mut body) = world.push_object(id) else { continue };
            if !body.is_dynamic() {
                continue;
            }
            let pull = (hand - pose.position.truncate()) * STIFFNESS - pose.linvel.truncate() * DAMPING;
            let mass = body.mass();
            body.add_force((pull * mass).extend(0.0));
            self.pulls.push((hand.extend(pose.position.z), pose.position));
        }
        Ok(())
    }

    fn after_step(&mut self, world: &mut TechniqueWorld<'_>) {
        // Forces persist in the physics engine until cleared.
        for id in world.object_ids() {
            if let Some(mut body) = world.push_object(id) {
                body.reset_forces();
            }
        }
    }

    fn feedback(&self, _world: &World) -> Feedback {
        Feedback { lines: self.pulls.clone(), ..Feedback::default() }
    }

    fn counts(&self) -> TechniqueCounts {
        TechniqueCounts { contacts: self.contacts, bodies: 0, joints: 0 }
    }

    fn clear(&mut self, _world: &mut TechniqueWorld<'_>) {
        self.pulls.clear();
    }

    fn config_mut(&mut self) -> &mut TechniqueConfig {
        &mut self.config
    }
}

fn main() -> anyhow::Result<ExitCode> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let magnet = register(
        TechniqueSpec::new("magnet", |config| Box::new(Magnet::new(config)))
            .label("Magnet")
            .limit("two_finger_twist", "a magnet pulls an object's centre: it cannot turn it")
            .limit("two_finger_twist_slow", "a magnet pulls an object's centre: it cannot turn it"),
    )?;

    // Two behaviour cases, with Joint beside the magnet: a light touch on a
    // ball (expected to work), and a fingertip on a heavy box, which the
    // paper expects to stay put and a magnet, blind to weight, drags anyway.
    let chosen: Vec<_> =
        cases().into_iter().filter(|c| ["ball_light_touch", "heavy_fingertip"].contains(&c.name)).collect();
    let kinds = [TechniqueKind::JOINT, magnet];
    let outcomes = run_suite(&chosen, &kinds, root, 2)?;
    println!("{}", markdown(&chosen, &kinds, &outcomes));
    let light = outcomes.iter().find(|o| o.technique == magnet && o.case == "ball_light_touch");
    let carried = light.map_or(f32::NAN, |o| o.get(Metric::Along));
    let light_case = chosen.iter().find(|c| c.name == "ball_light_touch");
    let light_works =
        light.zip(light_case).is_some_and(|(o, case)| cells(case, o).iter().all(|cell| !cell.verdict.is_failure()));

    // A one-participant study of Joint against the magnet on the positioning task.
    let out = std::env::temp_dir().join(format!("surfacelab-magnet-{}", std::process::id()));
    let design = StudyDesign {
        participants: 1,
        tasks: vec!["positioning".into()],
        techniques: vec![TechniqueKind::JOINT, magnet],
        repetitions: 1,
        practice: false,
        ..StudyDesign::default()
    };
    let options = RunOptions { progress: false, ..RunOptions::default() };
    let outcome = run_study(&design, &out, &ScriptedRunner::new(design.clone(), None), &options)?;
    let mut summary = csv::Reader::from_path(out.join("summary.csv"))?;
    let rows: Vec<SummaryRow> = summary.deserialize().collect::<Result<_, _>>()?;
    println!("study: {} trials in {:.1} s, files in {}", outcome.ran, outcome.elapsed.as_secs_f64(), out.display());
    println!("task         technique  feedback  completed/trials  mean (s)");
    for r in &rows {
        let mean = r.mean_s.map_or_else(|| "-".to_owned(), |m| format!("{m:.1}"));
        println!("{:<12} {:<10} {:<9} {:>5}/{:<10} {mean}", r.task, r.technique, r.feedback, r.completed, r.trials);
    }
    let trials = std::fs::read_to_string(out.join("trials.csv"))?;
    let report = std::fs::read_to_string(out.join("report.md")).unwrap_or_default();

    let magnet_rows = rows.iter().filter(|r| r.technique == magnet).count();
    let ok = light_works && magnet_rows == 2 && trials.contains(",magnet,") && report.contains("Magnet");
    println!("magnet moved the lightly touched ball {:.1} cm; summary rows naming it: {magnet_rows}", carried * 100.0);
    Ok(if ok { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}
