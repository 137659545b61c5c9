//! Soft bodies: cloth sheets, soft volumes and the pieces a tear leaves,
//! all simulated by rapier's `dynamics::soft_body` (no solver of our own).
//! This file builds them from the scene and reads them back from rapier's
//! physics; it knows nothing of [`super::World`], which owns a
//! [`SoftBodies`] and forwards to it (`soft_access.rs`).
//!
//! Soft bodies are an effect. A scene that declares none of `soft_bodies`,
//! `cloth` or `tearing` has an empty `SoftBodySet`, and [`SoftBodies::add`]
//! refuses to create one whose effect is off, returning that effect.
//!
//! Every piece of a body keeps the scene index of the body it came from in
//! `SoftBody::user_data` (rapier copies it to the pieces a tear splits off),
//! so "the sheet" is always the set of bodies carrying its index, however
//! often it tore. Their surface colliders carry [`SOFT_TAG`] and sit on
//! [`Layer::Soft`], which meets objects, proxies and particles alike, and
//! which scene ray casts see.

use super::config::WorldConfig;
use super::groups::Layer;
use crate::scene::SoftId;
use crate::scene::{Effect, SoftBodySpec, SoftKind};
use glam::{Vec2, Vec3};
use rapier3d::prelude::*;

/// Extra internal PGS iterations for soft bodies and what touches them.
const SOFT_PGS_ITERATIONS: usize = 12;

/// How fast (1/s) strain past a cloth's `crease` sets into its rest shape:
/// a crease forms within a few frames of a hand pressing it.
const CREASE_RATE: f32 = 20.0;

/// Largest set (fraction of an edge's rest length) a crease may take. Warp
/// and weft share the bend edges' plasticity in rapier, so two hands
/// pulling a cloth apart also stretch it for good; this caps that at 20%
/// (the flatten gesture leaves far less on average, see `tests/soft_bodies.rs`),
/// while the bend edges of the task's rumples need less than that to lie flat.
const CREASE_MAX: f32 = 0.2;

/// `user_data` of every soft-body surface collider (pieces copy it).
pub(super) const SOFT_TAG: u128 = u128::MAX - 1;

/// One declared soft body: its description and the body first inserted for
/// it (`None` while its effect is off).
#[derive(Debug, Clone)]
struct SoftSlot {
    spec: SoftBodySpec,
    root: Option<SoftBodyHandle>,
}

/// The declared soft bodies of a world, in declaration order.
#[derive(Debug, Clone, Default)]
pub(super) struct SoftBodies {
    slots: Vec<SoftSlot>,
}

/// A soft body's surface as the renderer wants it: world-space vertices and
/// outward triangles (a cloth's two sides share them).
#[derive(Debug, Clone, PartialEq)]
pub struct SoftSurface {
    /// Index of the declared soft body this piece belongs to.
    pub body: SoftId,
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
}

impl SoftBodies {
    /// Creates the declared soft bodies whose effects `config` simulates;
    /// the others get an empty slot (the world "with that effect off").
    pub(super) fn spawn(specs: &[SoftBodySpec], config: &WorldConfig, physics: &mut PhysicsWorld) -> Self {
        let mut soft = SoftBodies::default();
        for spec in specs {
            let index = soft.slots.len();
            soft.slots.push(SoftSlot { spec: spec.clone(), root: None });
            if missing_effect(spec, config).is_none() {
                soft.slots[index].root = Some(insert(spec, index, config, physics));
            }
        }
        soft
    }

    /// Adds a soft body (beyond the scene's own); returns its index, or the
    /// effect it needs that `config` leaves off.
    pub(super) fn add(
        &mut self,
        spec: &SoftBodySpec,
        config: &WorldConfig,
        physics: &mut PhysicsWorld,
    ) -> Result<usize, Effect> {
        if let Some(e) = missing_effect(spec, config) {
            return Err(e);
        }
        let index = self.slots.len();
        let root = insert(spec, index, config, physics);
        self.slots.push(SoftSlot { spec: spec.clone(), root: Some(root) });
        physics.detect_collisions(&(), &());
        Ok(index)
    }

    /// Puts every soft body back as declared: torn pieces go, the bodies
    /// return whole and at rest.
    pub(super) fn reset(&mut self, config: &WorldConfig, physics: &mut PhysicsWorld) {
        for (index, slot) in self.slots.iter_mut().enumerate() {
            if slot.root.is_none() {
                continue;
            }
            let family: Vec<SoftBodyHandle> = pieces(physics, index).map(|(h, _)| h).collect();
            for h in family {
                physics.remove_soft_body(h);
            }
            slot.root = Some(insert(&slot.spec, index, config, physics));
        }
    }

    /// Number of declared soft bodies (including those whose effect is off).
    pub(super) fn len(&self) -> usize {
        self.slots.len()
    }

    pub(super) fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    pub(super) fn spec(&self, index: usize) -> &SoftBodySpec {
        &self.slots[index].spec
    }

    /// Whether the declared soft body `index` exists (its effect is on).
    pub(super) fn exists(&self, index: usize) -> bool {
        self.slots[index].root.is_some()
    }
}

/// The first effect `spec` needs that `config` does not simulate.
fn missing_effect(spec: &SoftBodySpec, config: &WorldConfig) -> Option<Effect> {
    spec.required_effects().iter().find(|e| !config.effects.contains(*e))
}

fn insert(spec: &SoftBodySpec, index: usize, config: &WorldConfig, physics: &mut PhysicsWorld) -> SoftBodyHandle {
    let h = physics.insert_soft_body(soft_builder(spec, index, config.friction, config.sleeping));
    // The world refreshes its query structures (`detect_collisions`) before
    // the first step, which would file the new root body as untouched: ask
    // for a wake-up at the first step explicitly.
    physics.soft_bodies[h].wake_up();
    h
}

/// Wakes every sleeping soft body that a moving rigid body touches.
/// rapier keeps a soft body asleep under a finger sliding slowly over it
/// (its contacts are solved outside the rigid contact graph that wakes
/// islands): a proxy circling at 3 cm/s on a sleeping cloth would never
/// move it.
/// Called before every step; costs nothing when nothing sleeps.
pub(super) fn wake_touched(physics: &mut PhysicsWorld) {
    let mut wake = Vec::new();
    for (h, b) in physics.soft_bodies.iter().filter(|(_, b)| b.is_sleeping() && b.is_enabled()) {
        let touched = b.meshes().filter(|m| m.collision_enabled()).any(|m| {
            physics.narrow_phase.contact_pairs_with(m.collider()).any(|pair| {
                let other = if pair.collider1 == m.collider() { pair.collider2 } else { pair.collider1 };
                pair.has_any_active_contact()
                    && physics
                        .colliders
                        .get(other)
                        .and_then(Collider::parent)
                        .and_then(|p| physics.bodies.get(p))
                        .is_some_and(|rb| {
                            (rb.is_dynamic() || rb.is_kinematic())
                                && !rb.is_sleeping()
                                && !rb.is_soft_frame()
                                && rb.linvel().length() > 1e-3
                        })
            })
        });
        if touched {
            wake.push(h);
        }
    }
    for h in wake {
        physics.soft_bodies[h].wake_up();
    }
}

/// The rapier bodies soft body `index` is made of now: the body itself, or
/// after tears the pieces it came apart into.
pub(super) fn pieces(physics: &PhysicsWorld, index: usize) -> impl Iterator<Item = (SoftBodyHandle, &SoftBody)> {
    physics.soft_bodies.iter().filter(move |(_, b)| b.user_data == index as u128)
}

/// The mass of each piece of soft body `index`, largest first.
pub(super) fn piece_masses(physics: &PhysicsWorld, index: usize) -> Vec<f32> {
    let mut m: Vec<f32> = pieces(physics, index).map(|(_, b)| b.mass()).collect();
    m.sort_by(|a, b| b.total_cmp(a));
    m
}

/// Centre of mass of soft body `index` (all its pieces).
pub(super) fn center(physics: &PhysicsWorld, index: usize) -> Option<Vec3> {
    let (mut sum, mut mass) = (Vec3::ZERO, 0.0);
    for (_, b) in pieces(physics, index) {
        sum += b.center_of_mass() * b.mass();
        mass += b.mass();
    }
    (mass > 0.0).then(|| sum / mass)
}

/// Fastest particle of soft body `index` (m/s); infinite if any is not finite.
pub(super) fn max_speed(physics: &PhysicsWorld, index: usize) -> f32 {
    let mut top = 0.0f32;
    for (_, b) in pieces(physics, index) {
        for v in b.particle_velocities() {
            if !v.is_finite() {
                return f32::INFINITY;
            }
            top = top.max(v.length());
        }
    }
    top
}

/// Whether every particle of every soft body is finite.
pub(super) fn all_finite(physics: &PhysicsWorld) -> bool {
    physics
        .soft_bodies
        .iter()
        .all(|(_, b)| b.particle_positions().all(Vec3::is_finite) && b.particle_velocities().all(Vec3::is_finite))
}

/// Volume enclosed by soft body `index` now, and at rest (m³; 0 for a cloth).
pub(super) fn volume(physics: &PhysicsWorld, index: usize) -> (f32, f32) {
    pieces(physics, index).fold((0.0, 0.0), |(v, r), (_, b)| (v + b.volume(), r + b.rest_volume()))
}

/// Share of its rest area that soft body `index` covers on the table,
/// seen from above (a crumpled or folded cloth covers less; a fold
/// counts once). Rasterised on a 2 mm grid.
pub(super) fn coverage(physics: &PhysicsWorld, spec: &SoftBodySpec, index: usize) -> f32 {
    const CELL: f32 = 0.002;
    let mut tris: Vec<[Vec2; 3]> = Vec::new();
    let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
    for (_, b) in pieces(physics, index) {
        let p: Vec<Vec2> = b.particle_positions().map(Vec3::truncate).collect();
        for t in b.boundary() {
            let tri = [p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]];
            for q in tri {
                lo = lo.min(q);
                hi = hi.max(q);
            }
            tris.push(tri);
        }
    }
    if tris.is_empty() || !(lo.is_finite() && hi.is_finite()) {
        return 0.0;
    }
    let n = ((hi - lo) / CELL).ceil().as_uvec2() + 1;
    if n.x > 4096 || n.y > 4096 {
        return 0.0;
    }
    let mut covered = vec![false; (n.x * n.y) as usize];
    for [a, b, c] in tris {
        let (tlo, thi) = (a.min(b).min(c), a.max(b).max(c));
        let (i0, j0) = (((tlo.x - lo.x) / CELL).floor() as u32, ((tlo.y - lo.y) / CELL).floor() as u32);
        let (i1, j1) = (((thi.x - lo.x) / CELL).ceil() as u32, ((thi.y - lo.y) / CELL).ceil() as u32);
        let area = (b - a).perp_dot(c - a);
        if area.abs() < 1e-12 {
            continue;
        }
        for j in j0..=j1.min(n.y - 1) {
            for i in i0..=i1.min(n.x - 1) {
                let q = lo + (Vec2::new(i as f32, j as f32) + 0.5) * CELL;
                let (w0, w1, w2) = ((c - b).perp_dot(q - b), (a - c).perp_dot(q - c), (b - a).perp_dot(q - a));
                let inside =
                    if area > 0.0 { w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0 } else { w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0 };
                if inside {
                    covered[(j * n.x + i) as usize] = true;
                }
            }
        }
    }
    let cells = covered.iter().filter(|c| **c).count() as f32;
    cells * CELL * CELL / (spec.size.x * spec.size.y)
}

/// Every soft body's surface now, torn pieces included.
pub(super) fn surfaces(physics: &PhysicsWorld) -> Vec<SoftSurface> {
    physics
        .soft_bodies
        .iter()
        .filter(|(_, b)| b.is_enabled())
        .map(|(_, b)| SoftSurface {
            body: SoftId::new(b.user_data as usize),
            positions: b.particle_positions().collect(),
            triangles: b.boundary().to_vec(),
        })
        .collect()
}

/// The particle of soft body `h` nearest to `point`.
pub(super) fn nearest_particle(physics: &PhysicsWorld, h: SoftBodyHandle, point: Vec3) -> Option<u32> {
    let b = physics.soft_bodies.get(h)?;
    b.particle_positions()
        .enumerate()
        .min_by(|(_, a), (_, c)| (*a - point).length_squared().total_cmp(&(*c - point).length_squared()))
        .map(|(i, _)| i as u32)
}

/// The soft particle a ray hit on collider `c` lands on, if `c` is a soft surface.
pub(super) fn hit(physics: &PhysicsWorld, c: &Collider, point: Vec3) -> Option<(SoftBodyHandle, u32)> {
    let mesh = c.deformable_mesh_ref()?;
    Some((mesh.body, nearest_particle(physics, mesh.body, point)?))
}

/// The rapier builder for a declared soft body.
fn soft_builder(spec: &SoftBodySpec, index: usize, friction: bool, sleeping: bool) -> SoftBodyBuilder {
    let stretch = SpringCoefficients::new(spec.stiffness, 1.0);
    let [nx, ny, nz] = spec.resolution;
    let builder = match spec.kind {
        SoftKind::Cloth => {
            let origin = spec.position - Vec3::new(spec.size.x / 2.0, spec.size.y / 2.0, 0.0);
            let du = Vec3::X * spec.size.x / (nx - 1) as f32;
            let dv = Vec3::Y * spec.size.y / (ny - 1) as f32;
            let mut material = SoftBodyMaterial::uniform(stretch);
            material.bend_softness = SpringCoefficients::new(spec.bending.max(0.01), 1.0);
            // Creases: past `crease` strain an edge's rest length flows to
            // where the hand left it, so a cloth pressed flat stays flat and
            // one bunched up stays bunched (rapier's edge plasticity).
            material.edge_plastic_yield = spec.crease;
            material.edge_plastic_creep = CREASE_RATE;
            material.edge_plastic_max = CREASE_MAX;
            let mut cloth = SoftBodyBuilder::cloth(origin, du, dv, nx, ny).material(material);
            if spec.crumple > 0.0 {
                // Built in its rumpled shape: that is its rest shape (the
                // creases it came with). Warp and weft keep their lengths;
                // only shear and bending differ from the flat sheet.
                cloth.positions = crumpled(spec);
            }
            cloth
        }
        SoftKind::Volume => {
            // Tetrahedra that keep their volume, plus one constraint on the
            // whole: a squeezed block bulges instead of shrinking.
            let mut material = SoftBodyMaterial::uniform(stretch);
            // Volume held three times stiffer than shape: it changes shape
            // under a hand, not size.
            material.volume_softness = SpringCoefficients::new(spec.stiffness * 3.0, 1.0);
            SoftBodyBuilder::cuboid(spec.position, spec.size / 2.0, nx, ny, nz)
                .material(material)
                .cell_model(SoftBodyCellModel::Volume)
                .volume_preservation(true)
        }
    };
    let mut builder = builder
        .mass(spec.mass)
        .particle_radius(spec.thickness)
        .linear_damping(spec.damping)
        .user_data(index as u128)
        .surface_collider(
            ColliderBuilder::ball(spec.thickness)
                .friction(if friction { spec.friction } else { 0.0 })
                .collision_groups(Layer::Soft.groups())
                .user_data(SOFT_TAG),
        );
    builder.particle_settings.can_sleep = sleeping;
    // Fingers weigh far more than a cloth's particles: extra internal
    // iterations let the soft contacts hold them (with rapier's default 3 a
    // 0.2 kg box sinks through a 0.05 kg, 256-particle cloth; with 20 it
    // rests on it).
    builder.particle_settings.additional_pgs_iterations = SOFT_PGS_ITERATIONS;
    if let Some(t) = spec.tear_strain {
        builder = builder.tear_strain(t);
    }
    builder
}

/// A cloth's particles rumpled into `1 - crumple` of its width and depth:
/// waves `z = A(1 - cos kx)/2` along x plus waves along y, with the
/// particles spaced by arc length along each wave, so every warp and weft
/// edge keeps its flat length (the sheet is rumpled, not shrunk).
fn crumpled(spec: &SoftBodySpec) -> Vec<Vec3> {
    let [nu, nv, _] = spec.resolution;
    let along_x = Wave::new(spec.size.x, 1.0 - spec.crumple, 3.0);
    let along_y = Wave::new(spec.size.y, 1.0 - spec.crumple, 2.0);
    let mut out = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        let (x, zx) = along_x.at(i as f32 / (nu - 1) as f32);
        for j in 0..nv {
            let (y, zy) = along_y.at(j as f32 / (nv - 1) as f32);
            out.push(spec.position + Vec3::new(x, y, zx + zy));
        }
    }
    out
}

/// A cosine wave of a given arc length squeezed into a shorter span,
/// sampled by arc length.
struct Wave {
    /// `(x, z)` at evenly spaced arc lengths, `x` centred on 0.
    table: Vec<(f32, f32)>,
}

impl Wave {
    const SAMPLES: usize = 2048;

    /// A wave of arc length `len` spanning `len * squeeze` in `waves` periods.
    fn new(len: f32, squeeze: f32, waves: f32) -> Self {
        let span = len * squeeze;
        let k = std::f32::consts::TAU * waves / span;
        let curve = |a: f32| -> Vec<(f32, f32, f32)> {
            // (x, z, arc length so far) along the span.
            let mut out = Vec::with_capacity(Self::SAMPLES + 1);
            let mut arc = 0.0;
            let mut prev = (-span / 2.0, 0.0);
            for n in 0..=Self::SAMPLES {
                let x = span * (n as f32 / Self::SAMPLES as f32 - 0.5);
                let z = 0.5 * a * (1.0 - (k * (x + span / 2.0)).cos());
                arc += ((x - prev.0).powi(2) + (z - prev.1).powi(2)).sqrt();
                prev = (x, z);
                out.push((x, z, arc));
            }
            out
        };
        // The amplitude whose arc length is `len` (bisection: arc grows with it).
        let (mut lo, mut hi) = (0.0f32, len);
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if curve(mid).last().map_or(0.0, |c| c.2) < len {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let samples = curve(0.5 * (lo + hi));
        let total = samples.last().map_or(len, |c| c.2);
        let mut table = Vec::with_capacity(Self::SAMPLES + 1);
        let mut n = 0;
        for m in 0..=Self::SAMPLES {
            let s = total * m as f32 / Self::SAMPLES as f32;
            while n + 1 < samples.len() && samples[n + 1].2 < s {
                n += 1;
            }
            let (a, b) = (samples[n], samples[(n + 1).min(samples.len() - 1)]);
            let t = if b.2 > a.2 { ((s - a.2) / (b.2 - a.2)).clamp(0.0, 1.0) } else { 0.0 };
            table.push((a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t));
        }
        Self { table }
    }

    /// `(x, z)` at fraction `f` of the arc length.
    fn at(&self, f: f32) -> (f32, f32) {
        let m = (f.clamp(0.0, 1.0) * Self::SAMPLES as f32).round() as usize;
        self.table[m]
    }
}
