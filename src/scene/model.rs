//! The validated scene: plain values every other module reads.

use super::effects::{Effect, EffectSet};
use super::{ObjectId, SoftId};
use glam::{Quat, Vec2, Vec3};

/// A validated scene. Units are metres, kilograms and seconds; z is up and the
/// table top is the plane z = 0 centred at the origin.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub name: String,
    /// Where it came from (a path, or a label for scenes built in code).
    pub origin: String,
    pub description: String,
    pub hint: String,
    pub effects: EffectSet,
    pub time_limit_s: f32,
    pub table: Table,
    pub camera: CameraSpec,
    pub physics: PhysicsSpec,
    pub objects: Vec<ObjectSpec>,
    /// Deformable bodies (`[[soft_bodies]]`); each needs its effect declared.
    pub soft_bodies: Vec<SoftBodySpec>,
    pub goal: Goal,
    /// Technique overrides (`[technique]`), checked by the technique config.
    pub technique: toml::Table,
    /// The 1-based line of each key of `technique`, for its errors.
    pub technique_lines: std::collections::BTreeMap<String, usize>,
}

impl Scene {
    /// The object with this name.
    pub fn object_id(&self, name: &str) -> Option<ObjectId> {
        self.objects.iter().position(|o| o.name == name).map(ObjectId::new)
    }

    /// Every declared object, in declaration order.
    pub fn object_ids(&self) -> impl Iterator<Item = ObjectId> + use<> {
        (0..self.objects.len()).map(ObjectId::new)
    }

    /// The declared object `id`.
    pub fn object(&self, id: ObjectId) -> &ObjectSpec {
        &self.objects[id.index()]
    }

    /// True when the table-plane point lies on the table.
    pub fn on_table(&self, p: Vec2) -> bool {
        p.x.abs() <= self.table.width / 2.0 && p.y.abs() <= self.table.depth / 2.0
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Table {
    pub width: f32,
    pub depth: f32,
    pub friction: f32,
    pub restitution: f32,
    pub color: Color,
    pub walls: bool,
}

/// A camera straight above the table centre. Looking straight down maps the
/// table plane affinely onto the screen, so a contact-image pixel, a screen
/// pixel and a table point are the same thing, and the ray for a contact is
/// the camera ray through that pixel (the paper's ray cast).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraSpec {
    pub height: f32,
}

impl CameraSpec {
    pub fn eye(&self) -> Vec3 {
        Vec3::new(0.0, 0.0, self.height)
    }

    /// Vertical field of view that makes the table's depth fill the view.
    pub fn fov_y_deg(&self, table: &Table) -> f32 {
        (2.0 * (table.depth / 2.0 / self.height).atan()).to_degrees()
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhysicsSpec {
    pub dt: f32,
    pub solver_iterations: usize,
    pub pgs_iterations: usize,
    pub length_unit: f32,
    /// CCD substeps, used only when the scene declares `ccd`.
    pub ccd_substeps: usize,
    /// Hard cap on any dynamic body's linear speed (m/s): no explosions.
    pub max_speed: f32,
    /// Natural frequency of rapier's soft contacts (Hz). Contact stiffness
    /// is the pair's effective mass × (2π·hz)², so a heavy object on a
    /// light one sinks unless this is raised (at 30 Hz, into a block a
    /// hundredth its mass, by centimetres).
    pub contact_hz: f32,
    /// Whether hands give way where they close on a pile of objects
    /// (`pipeline/world/give_way.rs`); off reproduces the paper's bodies
    /// that press with whatever impulse it takes.
    pub give_way: bool,
}

impl Default for PhysicsSpec {
    fn default() -> Self {
        PhysicsSpec {
            dt: 1.0 / 60.0,
            solver_iterations: 4,
            pgs_iterations: 1,
            // Centimetre objects on a metre table: 0.1 scales rapier's tolerances to them, which
            // also makes particles several times cheaper to simulate.
            length_unit: 0.1,
            ccd_substeps: 1,
            max_speed: 50.0,
            contact_hz: 30.0,
            give_way: true,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Color {
    pub rgba: [f32; 4],
}

impl Color {
    /// The named palette scene files may use.
    pub const NAMED: [(&'static str, [f32; 4]); 10] = [
        ("red", [0.85, 0.18, 0.16, 1.0]),
        ("blue", [0.16, 0.36, 0.86, 1.0]),
        ("green", [0.20, 0.66, 0.28, 1.0]),
        ("yellow", [0.95, 0.80, 0.15, 1.0]),
        ("orange", [0.95, 0.50, 0.12, 1.0]),
        ("purple", [0.55, 0.25, 0.75, 1.0]),
        ("white", [0.92, 0.92, 0.90, 1.0]),
        ("grey", [0.50, 0.50, 0.52, 1.0]),
        ("black", [0.10, 0.10, 0.11, 1.0]),
        ("wood", [0.55, 0.42, 0.30, 1.0]),
    ];

    /// Parses a palette name or `#rrggbb`.
    pub fn parse(s: &str) -> Option<Color> {
        if let Some(hex) = s.strip_prefix('#') {
            if hex.len() != 6 {
                return None;
            }
            let v = u32::from_str_radix(hex, 16).ok()?;
            let c = |shift: u32| ((v >> shift) & 0xff) as f32 / 255.0;
            return Some(Color { rgba: [c(16), c(8), c(0), 1.0] });
        }
        Self::NAMED.iter().find(|(n, _)| *n == s).map(|(_, rgba)| Color { rgba: *rgba })
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Box {
        half_extents: Vec3,
    },
    Sphere {
        radius: f32,
    },
    /// Axis along z (standing upright when unrotated).
    Cylinder {
        radius: f32,
        half_height: f32,
    },
    /// Axis along z; `half_height` is half the straight part.
    Capsule {
        radius: f32,
        half_height: f32,
    },
}

impl Shape {
    /// Half the height of the shape when unrotated: where its centre sits
    /// above a surface it rests on.
    pub fn half_z(&self) -> f32 {
        match *self {
            Shape::Box { half_extents } => half_extents.z,
            Shape::Sphere { radius } => radius,
            Shape::Cylinder { half_height, .. } => half_height,
            Shape::Capsule { radius, half_height } => half_height + radius,
        }
    }

    /// Radius of the smallest disc around the centre covering the footprint.
    pub fn footprint_radius(&self) -> f32 {
        match *self {
            Shape::Box { half_extents } => half_extents.truncate().length(),
            Shape::Sphere { radius } | Shape::Cylinder { radius, .. } | Shape::Capsule { radius, .. } => radius,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyKind {
    Dynamic,
    Fixed,
}

#[derive(Debug, Clone, PartialEq)]
pub struct ObjectSpec {
    pub name: String,
    pub shape: Shape,
    pub mass: f32,
    pub friction: f32,
    pub restitution: f32,
    /// The validated colour; sorting zones match objects on its value, so
    /// `#ff0000` and `#FF0000` are the same colour.
    pub color: Color,
    pub position: Vec3,
    pub rotation: Quat,
    pub body: BodyKind,
    /// Velocity damping (1/s); angular damping is a ball's rolling resistance.
    pub linear_damping: f32,
    pub angular_damping: f32,
}

/// What a soft body is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SoftKind {
    /// A sheet of particles with stretch, shear and bending springs (cloth,
    /// paper): needs the `cloth` effect.
    Cloth,
    /// A tetrahedralised block that keeps its volume (jelly, foam): needs the
    /// `soft_bodies` effect.
    Volume,
}

impl SoftKind {
    pub fn name(self) -> &'static str {
        match self {
            SoftKind::Cloth => "cloth",
            SoftKind::Volume => "volume",
        }
    }
}

/// One deformable body of a scene (`[[soft_bodies]]`).
#[derive(Debug, Clone, PartialEq)]
pub struct SoftBodySpec {
    pub name: String,
    pub kind: SoftKind,
    /// Full extents (m); a cloth's `z` is 0.
    pub size: Vec3,
    /// Particles along each side (a cloth's third entry is 1).
    pub resolution: [usize; 3],
    /// Centre of the body at rest (a cloth lies `thickness` above the table).
    pub position: Vec3,
    /// Total mass (kg).
    pub mass: f32,
    /// Natural frequency (Hz) of the stretch (and, for volumes, volume)
    /// constraints: higher is stiffer, up to what the solver resolves.
    pub stiffness: f32,
    /// Natural frequency (Hz) of a cloth's bending springs.
    pub bending: f32,
    /// Strain past which an edge tears (needs the `tearing` effect).
    pub tear_strain: Option<f32>,
    pub friction: f32,
    /// Contact thickness: the particles' radius (m).
    pub thickness: f32,
    /// Air drag on the particles (1/s).
    pub damping: f32,
    /// 0 = starts flat; up to 0.6 = starts rumpled into this much less area
    /// (creased that way: the rumpled shape is the sheet's rest shape).
    pub crumple: f32,
    /// Strain (and fold angle, in radians) past which a cloth's springs take
    /// a permanent set: 0 = perfectly elastic, springs back to its rest
    /// shape; 0.03 = cotton, keeps the creases a hand presses in or out.
    pub crease: f32,
    pub color: Color,
}

impl SoftBodySpec {
    /// The effects a scene must declare for this body to exist.
    pub fn required_effects(&self) -> EffectSet {
        let mut e = EffectSet::empty().with(match self.kind {
            SoftKind::Cloth => Effect::Cloth,
            SoftKind::Volume => Effect::SoftBodies,
        });
        if self.tear_strain.is_some() {
            e.insert(Effect::Tearing);
        }
        e
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    pub object: ObjectId,
    pub position: Vec2,
    pub tolerance: f32,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SortingZone {
    /// Objects of this colour (by value) belong in the zone.
    pub color: Color,
    pub min: Vec2,
    pub max: Vec2,
}

impl SortingZone {
    pub fn contains(&self, p: Vec2) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct SteeringGoal {
    pub object: ObjectId,
    /// The raised platform the object must stay on.
    pub platform: Option<ObjectId>,
    pub waypoints: Vec<Vec2>,
    pub waypoint_radius: f32,
    pub finish: Vec2,
    pub finish_radius: f32,
}

/// What a trial of this scene must achieve.
#[derive(Debug, Clone, PartialEq)]
pub enum Goal {
    /// Free play: never completes.
    None,
    /// Every target's object rests within tolerance for `dwell_s`; placed objects vanish.
    Positioning { targets: Vec<Target>, dwell_s: f32 },
    /// Every dynamic object with a zone colour rests in a zone of its colour.
    Sorting { zones: Vec<SortingZone>, dwell_s: f32 },
    /// Waypoints in order, then the finish, without falling off the platform.
    Steering(SteeringGoal),
    /// At least `fraction` of the dynamic objects rest inside the circle.
    Gather { center: Vec2, radius: f32, fraction: f32, dwell_s: f32 },
    /// The named object rests inside the rectangle (its centre no higher
    /// than `max_height` above the table).
    Region { object: ObjectId, min: Vec2, max: Vec2, max_height: f32, dwell_s: f32 },
    /// The named soft body's centre of mass rests inside the rectangle, no
    /// higher than `max_height` (`kind = "region"` naming a soft body).
    SoftRegion { body: SoftId, min: Vec2, max: Vec2, max_height: f32, dwell_s: f32 },
    /// The named cloth, at rest, covers at least `min_area_fraction` of its
    /// rest area on the table (crumpled cloth smoothed out).
    ClothFlat { body: SoftId, min_area_fraction: f32, dwell_s: f32 },
    /// The named soft body has come apart into at least `pieces` pieces,
    /// each holding at least `min_piece_fraction` of its mass.
    Torn { body: SoftId, pieces: usize, min_piece_fraction: f32 },
}
