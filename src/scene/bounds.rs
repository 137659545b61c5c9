//! The bounds every number a user gives must lie within, in one place, each
//! with why. A value outside its bound is bad input (exit 2) and the error
//! names the file, line and field (or the flag) and the bound; nothing
//! outside these ranges reaches rapier or parry (a 1e30 cylinder panics
//! inside parry's EPA) or a loop whose length a file decides. docs/scenes.md
//! ("Bounds") lists the same values.
//!
//! The ranges are far wider than any task needs (the built-in scenes use
//! tables of 1 m, objects of 1-30 cm and masses of 8 g-10 kg); they are
//! where the simulation is still known to behave: `tests/stability.rs` runs
//! a scene at each bound for 10,000 steps and checks it stays finite.

/// Table width and depth (m). The Surface is 1.0 × 0.75 m; a wall-sized
/// display is a few metres. 5 cm is the smallest table a hand fits on.
pub const TABLE_SIDE_M: (f32, f32) = (0.05, 10.0);

/// Any extent of an object or soft body: box side, radius, cylinder or
/// capsule height (m). 1 mm is a card's thickness; 10 m is the largest table.
/// Larger shapes (1e30) make parry's contact solver index out of bounds.
pub const OBJECT_SIZE_M: (f32, f32) = (0.001, 10.0);

/// Mass of an object or soft body (kg). The lightest built-in piece weighs
/// 8 g; 1 g keeps the ratio to a 1 kg proxy within what the solver handles
/// (1000:1); 1000 kg is a desk.
pub const MASS_KG: (f32, f32) = (0.001, 1000.0);

/// Any coordinate of a position, and of `step`/`row_step` (m): an object
/// farther than 100 m from the table centre is lost to the simulation.
pub const POSITION_M: f32 = 100.0;

/// Objects in one scene, `count` repeats included. The gather scene has 40;
/// 1000 boxes stay within a real-time step, vision included
/// (`tests/stability.rs`, `the_most_objects_a_scene_may_have_stay_finite`),
/// while ten times as many at one spot take gigabytes and minutes.
pub const MAX_OBJECTS: usize = 1000;

/// Soft-body density (kg/m² for cloth, kg/m³ for volumes): paper is
/// 0.08 kg/m², rubber 1100 kg/m³; the resulting mass must also lie in
/// [`MASS_KG`].
pub const DENSITY: (f32, f32) = (0.001, 20_000.0);

/// Camera eye height (m): the default is 1.2 m over a 1 m table.
pub const CAMERA_HEIGHT_M: (f32, f32) = (0.05, 50.0);

/// `physics.length_unit` (m): rapier's tolerances scale with it; the
/// scenes use the default 1 cm..1 m scale.
pub const LENGTH_UNIT_M: (f32, f32) = (0.001, 10.0);

/// `physics.max_speed` (m/s): the fastest flick tested is 40 m/s.
pub const MAX_SPEED_M_S: (f32, f32) = (0.01, 1000.0);

/// `physics.ccd_substeps`: each costs a full collision pass.
pub const CCD_SUBSTEPS: usize = 16;

/// Any duration in seconds: a scene's `time_limit_s`, a gesture key's `t`,
/// `run --settle`, `screenshot --at`, `study --time-limit`. Ten minutes is
/// five times the longest trial limit (120 s); at 60 Hz it is 36,000 steps,
/// which `run` simulates in well under a minute.
pub const DURATION_S: f32 = 600.0;

/// A goal's radius, tolerance or height (m): no larger than the largest table.
pub const GOAL_LENGTH_M: f32 = TABLE_SIDE_M.1;

/// Gesture values: `scale` (1 = adult hand; 10 is a hand as big as a
/// large table), `spread` (0 together .. 1 relaxed) and `angle_deg` (a
/// hundred turns).
pub const GESTURE_SCALE: f64 = 10.0;
pub const GESTURE_SPREAD: f64 = 10.0;
pub const GESTURE_ANGLE_DEG: f64 = 36_000.0;

/// Participants in one study: the paper had 6; a study of 1000 scripted
/// participants runs the default design in about an hour.
pub const MAX_PARTICIPANTS: u32 = 1000;
/// Measured repetitions per condition (the paper: 2).
pub const MAX_REPETITIONS: u32 = 100;
/// Trials in one study, all conditions, tasks and practice included: a
/// trial needs a few hundred bytes of plan, so the design is checked
/// against this before anything is allocated (1e9 participants asked for
/// 864 GB).
pub const MAX_TRIALS: u64 = 1_000_000;

/// Bytes read from any input file: defined where files are read
/// (`files` depends on nothing), listed here with the other bounds.
pub use crate::files::MAX_INPUT_BYTES;

/// Technique parameters in a scene's `[technique]` table. Sizes (m) as an
/// object's; particle and proxy sizes at most 10 cm (a fingertip is 1 cm,
/// the default particle 3 mm).
pub const TECHNIQUE_SIZE_M: (f32, f32) = (0.0005, 0.1);
/// Technique masses (kg) and weights (N): a proxy is 1 kg, a particle 0.4 kg.
pub const TECHNIQUE_MASS_KG: (f32, f32) = MASS_KG;
pub const TECHNIQUE_WEIGHT_N: (f32, f32) = (0.0001, 10_000.0);
/// Gains, stiffnesses, dampings, forces, thresholds and speeds: the
/// defaults are 2-150; a million leaves room without letting a value
/// overflow a step's force.
pub const TECHNIQUE_GAIN: f32 = 1.0e6;
/// The smallest `joint_break_force` (N): a joint that breaks under a
/// thousandth of a newton never holds anything.
pub const TECHNIQUE_MIN_FORCE_N: f32 = 0.001;
/// `particle_stride` (pixels): the default is 3.
pub const PARTICLE_STRIDE: usize = 64;
/// `particle_cap` (particles per frame): the default is 4000; the flood
/// test runs 20,000.
pub const PARTICLE_CAP: usize = 100_000;
