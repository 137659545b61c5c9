//! The JSON report of one headless run (`surfacelab run --report`).

use super::Session;
use crate::scene::{Goal, SoftKind};
use serde::Serialize;

/// Mean time per stage, µs.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct StageMeans {
    pub rasterize_us: f64,
    pub vision_us: f64,
    pub technique_us: f64,
    pub step_us: f64,
    pub total_us: f64,
}

#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct ObjectReport {
    pub name: String,
    pub position: [f32; 3],
    /// Quaternion x, y, z, w.
    pub rotation: [f32; 4],
    pub linvel: [f32; 3],
    /// Where it was when the run started: the displacement is
    /// `position - start_position` without reading the scene file.
    pub start_position: [f32; 3],
    /// Quaternion x, y, z, w at the start.
    pub start_rotation: [f32; 4],
    /// Largest angle (degrees) its up axis made with the vertical at any
    /// step: a cylinder that tipped over and was stood back up shows it.
    pub max_tilt_deg: f32,
    /// False once it vanished (placed on its positioning target).
    pub active: bool,
    /// How deep it lies inside where the goal wants it (m): its whole
    /// footprint in a zone, circle or region (negative: how far it sticks
    /// out), or a positioning target's tolerance less its centre's
    /// distance. Null where the goal has no area for it.
    pub goal_depth_m: Option<f32>,
}

/// The state of one declared soft body at the end of the run.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct SoftReport {
    pub name: String,
    /// `cloth` or `volume`.
    pub kind: &'static str,
    /// Whether it exists (its effect is declared).
    pub simulated: bool,
    /// Pieces it is in now (more than 1 after a tear).
    pub pieces: usize,
    /// Mass of each piece (kg), largest first.
    pub piece_masses: Vec<f32>,
    /// Centre of mass of all its pieces.
    pub center: Option<[f32; 3]>,
    /// Cloth: share of its rest area it covers seen from above (null for a volume).
    pub coverage: Option<f32>,
    /// Volume: its volume over its rest volume (null for a cloth).
    pub volume_ratio: Option<f32>,
    /// Fastest particle now (m/s).
    pub max_particle_speed: f32,
    /// Every particle position and velocity is finite.
    pub finite: bool,
}

#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Completion {
    /// The scene's goal was met.
    pub complete: bool,
    pub completed_at_s: Option<f64>,
    pub placed: usize,
    pub total: usize,
    pub waypoints_passed: usize,
    pub restarts: u32,
    /// Why the goal is not met when the run ends (absent when complete):
    /// the scene has no goal, the time limit passed, objects were still
    /// moving when the settle time ran out, or the goal is simply unmet.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub incomplete: Option<String>,
}

impl Completion {
    fn of(session: &Session) -> Completion {
        let p = session.progress();
        let scene = session.scene();
        let moving = session.objects_moving();
        let incomplete = (!p.complete).then(|| {
            if matches!(scene.goal, Goal::None) {
                "the scene has no goal (free play)".to_owned()
            } else if session.time() >= f64::from(scene.time_limit_s) {
                format!("time out: the scene's time limit of {} s passed", scene.time_limit_s)
            } else if moving > 0 {
                format!(
                    "{moving} object(s) still moving when the settle time ran out; the goal counts objects at rest, \
                     so a longer --settle may let it complete"
                )
            } else if p.total > 0 {
                format!("goal not met: {} of {} placed", p.placed, p.total)
            } else {
                "goal not met".to_owned()
            }
        });
        Completion {
            complete: p.complete,
            completed_at_s: p.completed_at,
            placed: p.placed,
            total: p.total,
            waypoints_passed: p.waypoints_passed,
            restarts: p.restarts,
            incomplete,
        }
    }
}

/// Everything `run` reports. Field names are a contract (docs/file-formats.md, "Run report").
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct RunReport {
    pub format: &'static str,
    pub version: String,
    pub scene: String,
    pub technique: String,
    pub feedback: bool,
    pub gesture: String,
    pub steps: u64,
    pub sim_time_s: f64,
    pub wall_time_s: f64,
    pub objects: Vec<ObjectReport>,
    /// Declared soft bodies (empty for a rigid scene).
    pub soft_bodies: Vec<SoftReport>,
    /// Highest speed of any scene object (m/s), before the speed cap.
    pub max_speed: f32,
    /// Deepest contact penetration between scene bodies (m).
    pub max_penetration: f32,
    /// Steps after which some body state was NaN/inf.
    pub nan_count: u64,
    /// Times a speed had to be capped.
    pub speed_caps: u64,
    pub completion: Completion,
    pub stage_means_us: StageMeans,
    pub max_contacts: usize,
    pub max_technique_bodies: usize,
}

impl RunReport {
    /// Writes the report as pretty JSON to `path`, atomically (a full disk
    /// leaves an earlier report whole, not truncated); `-` is standard
    /// output (see [`crate::files::write_output`]).
    pub fn save(&self, path: &std::path::Path) -> std::io::Result<()> {
        let json = serde_json::to_string_pretty(self).map_err(std::io::Error::other)?;
        crate::files::write_output(path, (json + "\n").as_bytes())
    }

    pub fn from_session(session: &Session, feedback: bool, gesture: &str, wall_time_s: f64) -> RunReport {
        let w = session.world();
        let scene = session.scene();
        let objects = scene
            .object_ids()
            .map(|id| {
                let (o, p) = (scene.object(id), w.object_pose(id));
                let track = session.object_tracks()[id.index()];
                ObjectReport {
                    name: o.name.clone(),
                    position: p.position.to_array(),
                    rotation: p.rotation.to_array(),
                    linvel: p.linvel.to_array(),
                    start_position: track.start_position.to_array(),
                    start_rotation: track.start_rotation.to_array(),
                    max_tilt_deg: track.max_tilt.to_degrees(),
                    active: p.active,
                    goal_depth_m: session.tracker().depth(id),
                }
            })
            .collect();
        let soft_bodies = w
            .soft_ids()
            .map(|i| {
                let spec = w.soft_spec(i);
                let simulated = w.soft_exists(i);
                let masses = w.soft_piece_masses(i);
                let (volume, rest) = w.soft_volume(i);
                SoftReport {
                    name: spec.name.clone(),
                    kind: spec.kind.name(),
                    simulated,
                    pieces: masses.len(),
                    piece_masses: masses,
                    center: w.soft_center(i).map(|c| c.to_array()),
                    coverage: (simulated && spec.kind == SoftKind::Cloth).then(|| w.soft_coverage(i)),
                    volume_ratio: (simulated && spec.kind == SoftKind::Volume && rest > 0.0).then(|| volume / rest),
                    max_particle_speed: w.soft_max_speed(i),
                    finite: w.soft_all_finite(),
                }
            })
            .collect();
        let m = session.mean_times();
        let stats = w.stats();
        RunReport {
            format: "surfacelab-run-report",
            version: env!("CARGO_PKG_VERSION").to_string(),
            scene: scene.name.clone(),
            technique: session.technique_kind().to_string(),
            feedback,
            gesture: gesture.to_string(),
            steps: session.frames(),
            sim_time_s: session.time(),
            wall_time_s,
            objects,
            soft_bodies,
            max_speed: stats.max_speed_seen,
            max_penetration: stats.max_penetration_seen,
            nan_count: stats.nan_count,
            speed_caps: stats.speed_caps,
            completion: Completion::of(session),
            stage_means_us: StageMeans {
                rasterize_us: m.rasterize_us,
                vision_us: m.vision_us,
                technique_us: m.technique_us,
                step_us: m.step_us,
                total_us: m.total_us(),
            },
            max_contacts: session.max_counts().contacts,
            max_technique_bodies: session.max_counts().bodies,
        }
    }
}
