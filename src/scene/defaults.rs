//! What a scene file's optional fields default to, each with why. The
//! validator (`validate.rs`) is the only reader; docs/scenes.md lists the
//! same values.

/// Table colour: a light grey display surface (sRGB 0.78, 0.80, 0.82).
pub const TABLE_COLOR: [f32; 4] = [0.78, 0.80, 0.82, 1.0];
/// Table friction: a matte surface, so objects pushed by a hand stop within
/// a few centimetres.
pub const TABLE_FRICTION: f32 = 0.6;
/// Table restitution: objects dropped on a table barely bounce.
pub const TABLE_RESTITUTION: f32 = 0.1;
/// Rim walls keep objects on the display unless a scene removes them.
pub const TABLE_WALLS: bool = true;
/// Camera eye height above the table centre (m): the surface's camera sees
/// a 1.0 × 0.75 m table whole at this height.
pub const CAMERA_HEIGHT: f32 = 1.2;
/// Seconds before a study trial counts as failed (two minutes, generous for
/// the paper's tasks, which participants finished in under a minute).
pub const TIME_LIMIT_S: f32 = 120.0;

/// Object friction: wood or plastic on a glossy display.
pub const OBJECT_FRICTION: f32 = 0.5;
/// Object restitution, as the table's.
pub const OBJECT_RESTITUTION: f32 = 0.1;
/// Objects keep their momentum unless a scene asks for damping.
pub const OBJECT_DAMPING: f32 = 0.0;
/// One object per `[[objects]]` entry unless `count` repeats it.
pub const OBJECT_COUNT: u32 = 1;
// The largest `count` is `bounds::MAX_OBJECTS`, all objects together.

/// Soft-body thickness (m): a sheet of paper or cloth is about 2 mm, the
/// skin around a volume 3 mm.
pub const CLOTH_THICKNESS: f32 = 0.002;
pub const VOLUME_THICKNESS: f32 = 0.003;
/// The thickest skin a soft body may have (m).
pub const MAX_SOFT_THICKNESS: f32 = 0.05;
/// Particle spacing when no `resolution` is given (m): one particle every
/// 2 cm on cloth and 1.5 cm in volumes.
pub const CLOTH_SPACING: f32 = 0.02;
pub const VOLUME_SPACING: f32 = 0.015;
/// Particles per side chosen from the spacing are kept in this range.
pub const AUTO_RESOLUTION: (usize, usize) = (2, 48);
/// Particles per side a scene may ask for.
pub const RESOLUTION_RANGE: (u32, u32) = (2, 128);
/// The most particles one soft body may have.
pub const MAX_SOFT_PARTICLES: usize = 8192;
/// Default stretch stiffness of soft bodies (Hz): stiff enough that a sheet
/// dragged by a hand stretches by a few percent, not by half.
pub const SOFT_STIFFNESS_HZ: f32 = 60.0;
/// Default bending stiffness of cloth (Hz): a sheet that drapes and folds.
pub const CLOTH_BENDING_HZ: f32 = 4.0;
/// Soft-body friction, as the table's.
pub const SOFT_FRICTION: f32 = 0.6;
/// Soft-body velocity damping (1/s): enough that a dropped sheet settles.
pub const SOFT_DAMPING: f32 = 0.5;

/// Seconds an object must rest in place before a goal counts it: long
/// enough that a ball rolling over a target does not count.
pub const DWELL_S: f32 = 0.5;
/// How close to its target an object's centre must rest (m): 1.5 cm, about
/// half a sphere's radius in the positioning task.
pub const TARGET_TOLERANCE: f32 = 0.015;
/// Steering: how close the object must pass each waypoint, and come to the
/// finish (m).
pub const WAYPOINT_RADIUS: f32 = 0.04;
pub const FINISH_RADIUS: f32 = 0.04;
/// Gather: the share of objects that must lie within the radius.
pub const GATHER_FRACTION: f32 = 0.8;
/// Flatten: the share of its rest area a cloth must cover.
pub const MIN_AREA_FRACTION: f32 = 0.9;
/// Tear: pieces the sheet must come apart into, and the share of the
/// particles the smallest counted piece must hold.
pub const TEAR_PIECES: u32 = 2;
pub const MIN_PIECE_FRACTION: f32 = 0.1;
