//! What the renderer draws: a plain value built fresh each frame.
//!
//! The renderer never reads the physics world; the caller flattens the world,
//! the goals and the technique's feedback into a [`DrawList`]. This keeps the
//! GPU code testable with hand-made lists and keeps data flowing one way.
//!
//! Coordinates: metres, right-handed, **z up**. The table top is the plane
//! z = 0, centred at the origin, x to the right, y away from the viewer
//! (towards the top of the screen).

use glam::{Mat4, Vec2, Vec3};

/// Linear RGBA colour, components in 0..=1.
pub type Rgba = [f32; 4];

/// A perspective camera looking at the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    pub fov_y_deg: f32,
}

/// The table top: a slab whose upper face is z = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableDraw {
    pub width: f32,
    pub depth: f32,
    pub color: Rgba,
}

/// The unit meshes objects are instanced from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MeshKind {
    /// A cube of side 1 centred at the origin; scale it with the transform.
    Box,
    /// A sphere of radius 1.
    Sphere,
    /// A cylinder of radius 1 and height 1 (z from -0.5 to 0.5), axis z.
    Cylinder,
    /// A capsule along z; not uniformly scalable, so it carries its size.
    Capsule { radius: f32, half_height: f32 },
}

/// One rigid object: a unit mesh, a full transform (scale included) and a colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectDraw {
    pub mesh: MeshKind,
    pub transform: Mat4,
    pub color: Rgba,
}

/// A deformable mesh (cloth, soft volume, torn pieces): world-space vertices
/// and triangles; the renderer recomputes normals every frame.
#[derive(Debug, Clone, PartialEq)]
pub struct DeformableDraw {
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
    pub color: Rgba,
}

/// Flat marks painted on a horizontal plane at height `z` (0 for the table,
/// the platform's top for steering): targets, zones, waypoints, the finish.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Decal {
    /// A filled disc, or a ring of the given line width when `ring` is set.
    Disc { center: Vec2, z: f32, radius: f32, color: Rgba, ring: Option<f32> },
    /// A filled rectangle, or its outline of the given line width.
    Rect { center: Vec2, z: f32, half: Vec2, angle: f32, color: Rgba, outline: Option<f32> },
}

impl Decal {
    /// A filled disc on the table top (`z` 0).
    pub fn disc(center: Vec2, radius: f32, color: Rgba) -> Decal {
        Decal::Disc { center, z: 0.0, radius, color, ring: None }
    }

    /// A filled rectangle on the table top (`z` 0), `half` either side of
    /// `center` along the table's axes.
    pub fn rect(center: Vec2, half: Vec2, color: Rgba) -> Decal {
        Decal::Rect { center, z: 0.0, half, angle: 0.0, color, outline: None }
    }

    /// The same decal at height `z` (on a platform, or lifted over another).
    pub fn at(self, z: f32) -> Decal {
        match self {
            Decal::Disc { center, radius, color, ring, .. } => Decal::Disc { center, z, radius, color, ring },
            Decal::Rect { center, half, angle, color, outline, .. } => {
                Decal::Rect { center, z, half, angle, color, outline }
            }
        }
    }

    /// Only its edge, a line `width` wide: a disc's ring, a rectangle's
    /// outline.
    pub fn outlined(self, width: f32) -> Decal {
        match self {
            Decal::Disc { center, z, radius, color, .. } => Decal::Disc { center, z, radius, color, ring: Some(width) },
            Decal::Rect { center, z, half, angle, color, .. } => {
                Decal::Rect { center, z, half, angle, color, outline: Some(width) }
            }
        }
    }

    /// A rectangle turned `angle` (rad) about z; a disc looks the same
    /// turned, and stays as it is.
    pub fn turned(self, angle: f32) -> Decal {
        match self {
            Decal::Rect { center, z, half, color, outline, .. } => {
                Decal::Rect { center, z, half, angle, color, outline }
            }
            disc @ Decal::Disc { .. } => disc,
        }
    }
}

/// The technique's feedback, drawn only when feedback is on (the caller
/// leaves this empty otherwise).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FeedbackDraw {
    /// A line in space, e.g. a joint from the contact to its anchor.
    Line { a: Vec3, b: Vec3, color: Rgba },
    /// An axis-aligned cube, e.g. a proxy or one particle.
    Cube { center: Vec3, half: f32, color: Rgba },
}

/// The sensed contact image, shown as a translucent "hand shadow" covering
/// the whole table. Row 0 is the far edge (+y), column 0 the left edge (-x).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactOverlay {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<u8>,
}

/// Everything one frame shows.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawList {
    pub camera: Camera,
    pub clear_color: Rgba,
    pub table: TableDraw,
    pub objects: Vec<ObjectDraw>,
    pub deformables: Vec<DeformableDraw>,
    pub decals: Vec<Decal>,
    pub feedback: Vec<FeedbackDraw>,
    pub contact_overlay: Option<ContactOverlay>,
}
