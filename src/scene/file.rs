//! The raw TOML shape of a scene file, exactly as written. Validation turns it
//! into a [`super::Scene`]; nothing downstream reads these types.

use super::effects::Effect;
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    pub name: String,
    #[serde(default)]
    pub description: String,
    /// One line shown on screen when the scene opens.
    #[serde(default)]
    pub hint: String,
    pub effects: Vec<Effect>,
    /// Seconds before a study trial of this scene counts as failed.
    #[serde(default)]
    pub time_limit_s: Option<Spanned<f32>>,
    pub table: Spanned<TableFile>,
    #[serde(default)]
    pub camera: Option<Spanned<CameraFile>>,
    #[serde(default)]
    pub physics: Option<Spanned<PhysicsFile>>,
    #[serde(default)]
    pub objects: Vec<Spanned<ObjectFile>>,
    #[serde(default)]
    pub soft_bodies: Vec<Spanned<SoftBodyFile>>,
    #[serde(default)]
    pub goal: Option<Spanned<GoalFile>>,
    /// Technique parameter overrides, validated by the technique module.
    #[serde(default)]
    /// Each key with its place in the file, so errors name the line.
    pub technique: Option<std::collections::BTreeMap<String, Spanned<toml::Value>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableFile {
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub size: [f32; 2],
    #[serde(default)]
    pub friction: Option<f32>,
    #[serde(default)]
    pub restitution: Option<f32>,
    #[serde(default)]
    pub color: Option<String>,
    /// Invisible rim walls that keep objects on the display (default true).
    #[serde(default)]
    pub walls: Option<bool>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraFile {
    /// Height of the eye above the table centre, metres.
    pub height: f32,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhysicsFile {
    #[serde(default)]
    pub timestep_hz: Option<f32>,
    #[serde(default)]
    pub solver_iterations: Option<usize>,
    #[serde(default)]
    pub pgs_iterations: Option<usize>,
    #[serde(default)]
    pub length_unit: Option<f32>,
    #[serde(default)]
    pub ccd_substeps: Option<usize>,
    #[serde(default)]
    pub max_speed: Option<f32>,
    #[serde(default)]
    pub contact_hz: Option<f32>,
    #[serde(default)]
    pub give_way: Option<bool>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShapeKind {
    Box,
    Sphere,
    Cylinder,
    Capsule,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyKindFile {
    Dynamic,
    Fixed,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectFile {
    pub name: String,
    pub shape: ShapeKind,
    /// Box: full extents [x, y, z].
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub size: Option<[f32; 3]>,
    /// Sphere, cylinder, capsule.
    #[serde(default)]
    pub radius: Option<f32>,
    /// Cylinder: full height; capsule: length of the straight part.
    #[serde(default)]
    pub height: Option<f32>,
    #[serde(default)]
    pub mass: Option<f32>,
    #[serde(default)]
    pub friction: Option<f32>,
    #[serde(default)]
    pub restitution: Option<f32>,
    pub color: String,
    /// [x, y] (resting on the table) or [x, y, z] (centre).
    pub position: Vec<f32>,
    /// Euler angles XYZ in degrees.
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub rotation_deg: Option<[f32; 3]>,
    #[serde(default)]
    pub body: Option<BodyKindFile>,
    /// Linear and angular velocity damping (1/s): rolling resistance for balls.
    #[serde(default)]
    pub linear_damping: Option<f32>,
    #[serde(default)]
    pub angular_damping: Option<f32>,
    /// Repeat this object `count` times along `step` (for the gather scene's
    /// many small objects): object i sits at position + i·step.
    #[serde(default)]
    pub count: Option<u32>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub step: Option<[f32; 2]>,
    /// Wrap the row every `per_row` objects, moving by `row_step`.
    #[serde(default)]
    pub per_row: Option<u32>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub row_step: Option<[f32; 2]>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SoftKindFile {
    Cloth,
    Volume,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SoftBodyFile {
    pub name: String,
    pub kind: SoftKindFile,
    /// Cloth: [x, y]; volume: [x, y, z] full extents (m).
    pub size: Vec<f32>,
    /// Particles per side: cloth [nu, nv]; volume [nx, ny, nz].
    #[serde(default)]
    pub resolution: Option<Vec<u32>>,
    /// [x, y] (resting on the table) or [x, y, z] (centre).
    pub position: Vec<f32>,
    /// Total kg; or give `density` (kg/m² for cloth, kg/m³ for volumes).
    #[serde(default)]
    pub mass: Option<f32>,
    #[serde(default)]
    pub density: Option<f32>,
    #[serde(default)]
    pub stiffness: Option<f32>,
    #[serde(default)]
    pub bending: Option<f32>,
    #[serde(default)]
    pub tear_strain: Option<f32>,
    #[serde(default)]
    pub friction: Option<f32>,
    #[serde(default)]
    pub thickness: Option<f32>,
    #[serde(default)]
    pub damping: Option<f32>,
    #[serde(default)]
    pub crumple: Option<f32>,
    #[serde(default)]
    pub crease: Option<f32>,
    pub color: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetFile {
    pub object: String,
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub position: [f32; 2],
    #[serde(default)]
    pub tolerance: Option<f32>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ZoneFile {
    pub color: String,
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub min: [f32; 2],
    #[serde(deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub max: [f32; 2],
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GoalKind {
    None,
    Positioning,
    Sorting,
    Steering,
    Gather,
    Region,
    ClothFlat,
    Torn,
}

impl GoalKind {
    /// The name as written in a scene file.
    pub fn name(self) -> &'static str {
        match self {
            GoalKind::None => "none",
            GoalKind::Positioning => "positioning",
            GoalKind::Sorting => "sorting",
            GoalKind::Steering => "steering",
            GoalKind::Gather => "gather",
            GoalKind::Region => "region",
            GoalKind::ClothFlat => "cloth_flat",
            GoalKind::Torn => "torn",
        }
    }

    /// The keys a goal of this kind reads besides `kind`. One `[goal]`
    /// table serves every kind, so serde alone would take a steering key in
    /// a region goal and ignore it; the scene check refuses it by this list.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            GoalKind::None => &[],
            GoalKind::Positioning => &["dwell_s", "targets"],
            GoalKind::Sorting => &["dwell_s", "zones"],
            GoalKind::Steering => &["object", "platform", "waypoints", "waypoint_radius", "finish", "finish_radius"],
            GoalKind::Gather => &["dwell_s", "center", "radius", "fraction"],
            GoalKind::Region => &["dwell_s", "object", "min", "max", "max_height"],
            GoalKind::ClothFlat => &["dwell_s", "body", "min_area_fraction"],
            GoalKind::Torn => &["body", "pieces", "min_piece_fraction"],
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GoalFile {
    pub kind: GoalKind,
    /// Seconds an object must rest in place before it counts.
    #[serde(default)]
    pub dwell_s: Option<f32>,
    #[serde(default)]
    pub targets: Vec<Spanned<TargetFile>>,
    #[serde(default)]
    pub zones: Vec<Spanned<ZoneFile>>,
    // steering
    #[serde(default)]
    pub object: Option<String>,
    #[serde(default)]
    pub platform: Option<String>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub waypoints: Vec<[f32; 2]>,
    #[serde(default)]
    pub waypoint_radius: Option<f32>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub finish: Option<[f32; 2]>,
    #[serde(default)]
    pub finish_radius: Option<f32>,
    // gather / region
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub center: Option<[f32; 2]>,
    #[serde(default)]
    pub radius: Option<f32>,
    #[serde(default)]
    pub fraction: Option<f32>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub min: Option<[f32; 2]>,
    #[serde(default, deserialize_with = "crate::files::fixed_arrays::exactly")]
    pub max: Option<[f32; 2]>,
    /// region: the object's centre at most this high (m), so resting on top
    /// of the cavity does not count as inside it.
    #[serde(default)]
    pub max_height: Option<f32>,
    // cloth_flat / torn: the soft body
    #[serde(default)]
    pub body: Option<String>,
    #[serde(default)]
    pub min_area_fraction: Option<f32>,
    #[serde(default)]
    pub pieces: Option<u32>,
    #[serde(default)]
    pub min_piece_fraction: Option<f32>,
}

impl GoalFile {
    /// The keys written in this `[goal]` table besides `kind`, in the
    /// struct's order.
    pub fn given(&self) -> Vec<&'static str> {
        let set = [
            ("dwell_s", self.dwell_s.is_some()),
            ("targets", !self.targets.is_empty()),
            ("zones", !self.zones.is_empty()),
            ("object", self.object.is_some()),
            ("platform", self.platform.is_some()),
            ("waypoints", !self.waypoints.is_empty()),
            ("waypoint_radius", self.waypoint_radius.is_some()),
            ("finish", self.finish.is_some()),
            ("finish_radius", self.finish_radius.is_some()),
            ("center", self.center.is_some()),
            ("radius", self.radius.is_some()),
            ("fraction", self.fraction.is_some()),
            ("min", self.min.is_some()),
            ("max", self.max.is_some()),
            ("max_height", self.max_height.is_some()),
            ("body", self.body.is_some()),
            ("min_area_fraction", self.min_area_fraction.is_some()),
            ("pieces", self.pieces.is_some()),
            ("min_piece_fraction", self.min_piece_fraction.is_some()),
        ];
        set.into_iter().filter(|&(_, given)| given).map(|(k, _)| k).collect()
    }
}
