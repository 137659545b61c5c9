//! [`World`]: the scene's rigid bodies in rapier3d, stepped at a fixed rate.

use super::config::WorldConfig;
use super::error::WorldError;
use super::give_way::{self, Push, StepHooks};
use super::groups::Layer;
use super::magnified::MagnifiedDispatcher;
use super::pile_projection;
use super::ray::{RayHit, cylinder_hit};
use super::scene_index::{SceneColliders, SceneIndex};
use super::soft::{self, SOFT_TAG, SoftBodies};
use super::stats::WorldStats;
use crate::scene::{BodyKind, Effect, EffectSet, ObjectId, Scene, Shape};
use glam::{Quat, Vec2, Vec3};
use rapier3d::parry::bounding_volume::Aabb;
use rapier3d::parry::query::{RayCast, RayIntersection};
use rapier3d::prelude::*;

/// A rigid scene collider: its handle, its object index (`None` for the
/// table and its walls) and its cached world AABB.
type SceneCollider = (ColliderHandle, Option<usize>, Aabb);

/// `user_data` tag of environment colliders (table, walls).
const ENV_TAG: u128 = u128::MAX;

/// The pose of one scene object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectPose {
    pub position: Vec3,
    pub rotation: Quat,
    pub linvel: Vec3,
    pub angvel: Vec3,
    /// False once removed (a placed positioning object vanishes).
    pub active: bool,
}

#[derive(Debug, Clone, Copy)]
struct ObjectSlot {
    body: RigidBodyHandle,
    collider: ColliderHandle,
    active: bool,
}

/// The physics world of one scene.
pub struct World {
    physics: PhysicsWorld,
    config: WorldConfig,
    scene: Scene,
    objects: Vec<ObjectSlot>,
    /// Declared soft bodies (src/pipeline/world/soft.rs); empty slots when their effect is off.
    soft: SoftBodies,
    /// The table, its walls and every object's collider, with the object
    /// index (`None` for the environment) and a cached world AABB. Rigid
    /// scene ray casts test these directly: rapier's broad phase also holds
    /// the technique's particles, which sit exactly where contact rays go,
    /// and walking past hundreds of them per ray cost more than the physics
    /// (measured with `cargo bench --bench frame`).
    scene_colliders: Vec<SceneCollider>,
    /// Which of `scene_colliders` lie near a point of the table.
    scene_index: SceneIndex,
    /// By object index: whether it is in a jammed pile this step, where
    /// hands give way (`give_way`).
    jammed: Vec<bool>,
    /// Which way hands pressed each object in the last step, in object order
    /// (see `give_way::pushes`).
    pushes: Vec<Push>,
    time: f64,
    stats: WorldStats,
}

impl std::fmt::Debug for World {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("World")
            .field("scene", &self.scene.name)
            .field("config", &self.config)
            .field("time", &self.time)
            .finish_non_exhaustive()
    }
}

impl World {
    /// Builds the world simulating exactly the scene's declared effects.
    pub fn new(scene: &Scene) -> World {
        World::with_effects(scene, scene.effects)
    }

    /// The effects this world simulates: the scene's declaration plus what
    /// the session's technique needs.
    pub fn effects(&self) -> EffectSet {
        self.config.effects
    }

    /// Builds the world with an explicit effect set: the scene's declaration
    /// plus whatever a technique requires, or [`EffectSet::all`] for the
    /// benchmark that measures what ignoring the declaration costs.
    pub fn with_effects(scene: &Scene, effects: EffectSet) -> World {
        let config = WorldConfig::new(scene, effects);
        let mut physics = Self::physics_for(&config);
        let env = Self::environment(scene, &config, &mut physics);
        let objects = Self::scene_objects(scene, &config, &mut physics);
        let scene_colliders = env
            .into_iter()
            .map(|h| (h, None))
            .chain(objects.iter().enumerate().map(|(i, s)| (s.collider, Some(i))))
            .map(|(h, o)| (h, o, physics.colliders[h].compute_aabb()))
            .collect();
        let mut world = World {
            physics,
            config,
            scene: scene.clone(),
            objects,
            soft: SoftBodies::default(),
            scene_colliders,
            scene_index: SceneIndex::default(),
            jammed: Vec::new(),
            pushes: Vec::new(),
            time: 0.0,
            stats: WorldStats::default(),
        };
        world.soft = SoftBodies::spawn(&world.scene.soft_bodies, &world.config, &mut world.physics);
        world.reindex();
        // Build the query structures now: a contact on the very first frame
        // must be able to ray-cast onto the scene before anything has stepped.
        world.physics.detect_collisions(&(), &());
        world
    }

    /// An empty rapier world set up as `config` says.
    fn physics_for(config: &WorldConfig) -> PhysicsWorld {
        let mut physics = PhysicsWorld::new();
        // Centimetre pieces need GJK/EPA decided at a larger scale (see `magnified`).
        physics.narrow_phase = NarrowPhase::with_query_dispatcher(MagnifiedDispatcher);
        physics.gravity = config.gravity;
        let ip = &mut physics.integration_parameters;
        ip.dt = config.dt;
        ip.num_solver_iterations = config.solver_iterations;
        ip.num_internal_pgs_iterations = config.pgs_iterations;
        ip.length_unit = config.length_unit;
        ip.max_ccd_substeps = config.ccd_substeps;
        ip.contact_softness.natural_frequency = config.contact_hz;
        // Coulomb friction at every contact point, not rapier's default
        // `Simplified` model. That one solves a manifold's friction once at its
        // centre plus a "twist" constraint whose limit (mu * sum of normal
        // impulse * distance) is independent of the sliding friction, so a box
        // sliding on the table still resists turning with its full torsional
        // friction. With `Simplified`, `surfacelab behaviours` shows a fingertip
        // circling round a pinned one barely turning a 6 cm box with Proxy and
        // Particle (their pushes translate it), and a flat hand sliding over a
        // ball with Particle not carrying it at all; per point, both do what the
        // paper expects (`pin_and_spin_*`, `ball_under_hand`). It costs about a
        // fifth more time (`surfacelab behaviours`, `surfacelab study`).
        ip.friction_model = rapier3d::dynamics::FrictionModel::Coulomb;
        physics
    }

    /// The table and, when the scene asks, its rim walls.
    fn environment(scene: &Scene, config: &WorldConfig, physics: &mut PhysicsWorld) -> Vec<ColliderHandle> {
        let friction = |mu: f32| if config.friction { mu } else { 0.0 };
        // The table: a slab whose top face is z = 0, a little larger than the
        // display so objects at the rim still rest on something.
        let t = scene.table;
        let table = ColliderBuilder::cuboid(t.width / 2.0 + 0.05, t.depth / 2.0 + 0.05, 0.025)
            .translation(Vec3::new(0.0, 0.0, -0.025))
            .friction(friction(t.friction))
            .restitution(t.restitution)
            .collision_groups(Layer::Environment.groups())
            .user_data(ENV_TAG)
            // Faces resting on it rub at their mean radius (face_friction.rs).
            .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS)
            .build();
        let mut env = vec![physics.colliders.insert(table)];
        if t.walls {
            // Invisible rim walls: the display's edge keeps objects in view.
            let h = 0.2;
            let th = 0.02;
            let walls = [
                (Vec3::new(0.0, t.depth / 2.0 + th, h / 2.0), Vec3::new(t.width / 2.0 + 2.0 * th, th, h / 2.0)),
                (Vec3::new(0.0, -t.depth / 2.0 - th, h / 2.0), Vec3::new(t.width / 2.0 + 2.0 * th, th, h / 2.0)),
                (Vec3::new(t.width / 2.0 + th, 0.0, h / 2.0), Vec3::new(th, t.depth / 2.0 + 2.0 * th, h / 2.0)),
                (Vec3::new(-t.width / 2.0 - th, 0.0, h / 2.0), Vec3::new(th, t.depth / 2.0 + 2.0 * th, h / 2.0)),
            ];
            for (c, half) in walls {
                let wall = ColliderBuilder::cuboid(half.x, half.y, half.z)
                    .translation(c)
                    .friction(friction(0.2))
                    .collision_groups(Layer::Environment.groups())
                    .user_data(ENV_TAG)
                    .build();
                env.push(physics.colliders.insert(wall));
            }
        }
        env
    }

    /// One body and collider per scene object, in scene order.
    fn scene_objects(scene: &Scene, config: &WorldConfig, physics: &mut PhysicsWorld) -> Vec<ObjectSlot> {
        let friction = |mu: f32| if config.friction { mu } else { 0.0 };
        let mut objects = Vec::with_capacity(scene.objects.len());
        for (i, o) in scene.objects.iter().enumerate() {
            let builder = match o.body {
                BodyKind::Dynamic => RigidBodyBuilder::dynamic()
                    .linear_damping(o.linear_damping)
                    .angular_damping(o.angular_damping)
                    .can_sleep(config.sleeping)
                    .ccd_enabled(config.ccd_substeps > 0),
                BodyKind::Fixed => RigidBodyBuilder::fixed(),
            };
            let body = builder.pose(Pose::from_parts(o.position, o.rotation)).user_data(i as u128).build();
            let body = physics.bodies.insert(body);
            let layer = if o.body == BodyKind::Dynamic { Layer::Object } else { Layer::Environment };
            let mut cb = collider_for(o.shape)
                .friction(friction(o.friction))
                .restitution(o.restitution)
                .collision_groups(layer.groups())
                .user_data(i as u128);
            if o.body == BodyKind::Dynamic {
                cb = cb.mass(o.mass);
            }
            let collider = physics.colliders.insert_with_parent(cb.build(), body, &mut physics.bodies);
            objects.push(ObjectSlot { body, collider, active: true });
        }
        objects
    }

    pub fn config(&self) -> &WorldConfig {
        &self.config
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Simulated seconds since the world was built.
    pub fn time(&self) -> f64 {
        self.time
    }

    pub fn dt(&self) -> f32 {
        self.config.dt
    }

    pub fn stats(&self) -> &WorldStats {
        &self.stats
    }

    /// The underlying rapier world, to read (contact pairs, soft particles).
    pub fn physics(&self) -> &PhysicsWorld {
        &self.physics
    }

    /// The declared soft bodies (read through `soft_access.rs`).
    pub(super) fn soft(&self) -> &SoftBodies {
        &self.soft
    }

    /// The soft bodies and the physics they live in, both mutable.
    pub(super) fn soft_and_physics_mut(&mut self) -> (&mut SoftBodies, &mut PhysicsWorld) {
        (&mut self.soft, &mut self.physics)
    }

    /// The rigid scene colliders with their object index and cached AABB.
    pub(super) fn scene_colliders(&self) -> &[SceneCollider] {
        &self.scene_colliders
    }

    /// The rapier world, mutable: for this module only. Techniques go
    /// through `technique_body.rs` and `object.rs`, which cannot remove or
    /// teleport a scene object.
    pub(super) fn physics_mut(&mut self) -> &mut PhysicsWorld {
        &mut self.physics
    }

    /// Fails unless the joints effect is on: a scene that declares no joints
    /// does no joint work.
    pub fn require_joints(&self, what: &str) -> Result<(), WorldError> {
        if self.config.joints {
            Ok(())
        } else {
            Err(WorldError::EffectNotDeclared {
                scene: self.scene.name.clone(),
                effect: Effect::Joints,
                what: what.to_string(),
            })
        }
    }

    /// Advances one fixed step, then caps speeds and records health figures.
    pub fn step(&mut self) {
        if self.config.sleeping && !self.physics.soft_bodies.is_empty() {
            soft::wake_touched(&mut self.physics);
        }
        let objects: Vec<ColliderHandle> =
            if self.config.give_way { self.objects.iter().map(|s| s.collider).collect() } else { Vec::new() };
        self.update_jammed(&objects);
        self.physics.step_with_events(&StepHooks { jammed: &self.jammed }, &());
        if self.config.give_way {
            self.pushes = give_way::pushes(&self.physics, &objects);
            // Hands drive objects into each other only while they push one
            // across the table, or close on a jammed pile.
            if self.pushes.iter().any(Push::touched) || self.jammed.contains(&true) {
                let slots: Vec<_> = self.objects.iter().map(|s| (s.body, s.collider)).collect();
                pile_projection::separate(&mut self.physics, &slots);
            }
        }
        self.time += f64::from(self.config.dt);
        self.stats.steps += 1;

        let cap = self.config.max_speed;
        let mut nan = false;
        for slot in &self.objects {
            let Some(b) = self.physics.bodies.get_mut(slot.body) else { continue };
            if !b.is_dynamic() || !slot.active {
                continue;
            }
            let v = b.linvel();
            let p = b.translation();
            if !v.is_finite() || !p.is_finite() {
                nan = true;
                continue;
            }
            let s = v.length();
            self.stats.max_speed_seen = self.stats.max_speed_seen.max(s);
            if s > cap {
                b.set_linvel(v * (cap / s), false);
                self.stats.speed_caps += 1;
            }
        }
        if nan || !self.physics.quarantine().is_empty() {
            self.stats.nan_count += 1;
        }
        self.refresh_scene_aabbs();
    }

    /// Finds the objects in jammed piles (see `give_way`) and gives exactly
    /// their colliders the contact-modification hook for the step: every
    /// other pair keeps rapier's contact recycling.
    /// `objects`: every object's collider, in object order.
    fn update_jammed(&mut self, objects: &[ColliderHandle]) {
        if !self.config.give_way {
            return;
        }
        let now = give_way::jammed(&self.physics, objects, &self.pushes, self.config.dt);
        if now == self.jammed {
            return;
        }
        for (i, &h) in objects.iter().enumerate() {
            let (was, is) = (self.jammed.get(i).copied().unwrap_or(false), now[i]);
            if was != is
                && let Some(c) = self.physics.colliders.get_mut(h)
            {
                c.set_active_hooks(if is { ActiveHooks::MODIFY_SOLVER_CONTACTS } else { ActiveHooks::empty() });
            }
        }
        self.jammed = now;
    }

    /// Recomputes the cached AABBs of the rigid scene colliders.
    fn refresh_scene_aabbs(&mut self) {
        for (h, _, aabb) in &mut self.scene_colliders {
            if let Some(c) = self.physics.colliders.get(*h) {
                *aabb = c.compute_aabb();
            }
        }
        self.reindex();
    }

    fn reindex(&mut self) {
        self.scene_index = SceneIndex::new(self.scene_colliders.iter().map(|(_, o, aabb)| (o.is_some(), *aabb)));
    }

    /// The rigid scene colliders that may meet `ray` within `max_toi`, in
    /// list order.
    fn scene_colliders_along(&self, ray: &Ray, max_toi: f32) -> SceneColliders<'_, SceneCollider> {
        SceneColliders::new(&self.scene_colliders, self.scene_index.along_ray(ray, max_toi))
    }

    /// Deepest current contact penetration between scene objects and the
    /// environment or each other (m, ≥ 0). Reads the narrow phase; call it
    /// after a step when a report needs it (it is not free).
    pub fn measure_penetration(&mut self) -> f32 {
        let mut deepest = 0.0f32;
        for pair in self.physics.narrow_phase.contact_pairs() {
            let (Some(c1), Some(c2)) =
                (self.physics.colliders.get(pair.collider1), self.physics.colliders.get(pair.collider2))
            else {
                continue;
            };
            let scene_pair =
                |c: &Collider| matches!(super::groups::collider_layer(c), Layer::Object | Layer::Environment);
            if !(scene_pair(c1) && scene_pair(c2)) {
                continue;
            }
            for m in pair.manifolds() {
                for p in &m.points {
                    deepest = deepest.max(-p.dist);
                }
            }
        }
        self.stats.max_penetration_seen = self.stats.max_penetration_seen.max(deepest);
        deepest
    }

    pub fn object_count(&self) -> usize {
        self.objects.len()
    }

    /// Every scene object, in the scene's order.
    pub fn object_ids(&self) -> impl Iterator<Item = ObjectId> + use<> {
        (0..self.objects.len()).map(ObjectId::new)
    }

    /// The rapier body of scene object `id`.
    pub fn object_body(&self, id: ObjectId) -> RigidBodyHandle {
        self.objects[id.index()].body
    }

    /// The rapier collider of scene object `id`.
    pub fn object_collider(&self, id: ObjectId) -> ColliderHandle {
        self.objects[id.index()].collider
    }

    /// The scene object a rapier body belongs to.
    pub fn object_of_body(&self, h: RigidBodyHandle) -> Option<ObjectId> {
        self.objects.iter().position(|s| s.body == h).map(ObjectId::new)
    }

    pub fn object_pose(&self, id: ObjectId) -> ObjectPose {
        let slot = self.objects[id.index()];
        let b = &self.physics.bodies[slot.body];
        ObjectPose {
            position: b.translation(),
            rotation: *b.rotation(),
            linvel: b.linvel(),
            angvel: b.angvel(),
            active: slot.active,
        }
    }

    /// Velocity (m/s) of scene object `id`'s material at world point `p`
    /// (its centre of mass's velocity plus its spin's at `p`); zero for a
    /// removed object.
    pub fn object_point_velocity(&self, id: ObjectId, p: Vec3) -> Vec3 {
        let slot = self.objects[id.index()];
        if !slot.active {
            return Vec3::ZERO;
        }
        self.physics.bodies.get(slot.body).map_or(Vec3::ZERO, |b| b.velocity_at_point(p))
    }

    pub fn object_poses(&self) -> Vec<ObjectPose> {
        self.object_ids().map(|id| self.object_pose(id)).collect()
    }

    pub fn is_active(&self, id: ObjectId) -> bool {
        self.objects[id.index()].active
    }

    /// Removes a scene object from the simulation (a placed positioning
    /// object vanishes). Its index stays valid; its body is disabled.
    pub fn remove_object(&mut self, id: ObjectId) {
        let slot = &mut self.objects[id.index()];
        slot.active = false;
        if let Some(b) = self.physics.bodies.get_mut(slot.body) {
            b.set_enabled(false);
        }
    }

    /// Puts every scene object back at its initial pose, at rest (soft
    /// bodies whole again).
    pub fn reset_objects(&mut self) {
        for (i, o) in self.scene.objects.iter().enumerate() {
            let slot = &mut self.objects[i];
            slot.active = true;
            if let Some(b) = self.physics.bodies.get_mut(slot.body) {
                b.set_enabled(true);
                b.set_position(Pose::from_parts(o.position, o.rotation), true);
                b.set_linvel(Vec3::ZERO, true);
                b.set_angvel(Vec3::ZERO, true);
            }
        }
        self.soft.reset(&self.config, &mut self.physics);
        self.physics.detect_collisions(&(), &());
        self.refresh_scene_aabbs();
    }

    /// Puts one object at a pose, at rest (a steering restart).
    pub fn place_object(&mut self, id: ObjectId, position: Vec3, rotation: Quat) {
        if let Some(b) = self.physics.bodies.get_mut(self.objects[id.index()].body) {
            b.set_position(Pose::from_parts(position, rotation), true);
            b.set_linvel(Vec3::ZERO, true);
            b.set_angvel(Vec3::ZERO, true);
        }
    }

    /// The eye of the camera: every contact ray starts here.
    pub fn eye(&self) -> Vec3 {
        self.scene.camera.eye()
    }

    /// The camera ray through a table-plane point (= a contact-image or
    /// screen point): from the eye towards (x, y, 0). Returns origin and unit direction.
    pub fn camera_ray(&self, table_point: Vec2) -> (Vec3, Vec3) {
        let eye = self.eye();
        let dir = (table_point.extend(0.0) - eye).normalize_or(Vec3::NEG_Z);
        (eye, dir)
    }

    /// Where a world point appears on the display (= the table plane, =
    /// the contact image): the camera ray through it meets z = 0 there.
    /// The top of a tall object far from the centre appears displaced
    /// outward, and that is where a user touches to press on it.
    pub fn screen_point(&self, p: Vec3) -> Vec2 {
        let eye = self.eye();
        let t = eye.z / (eye.z - p.z).max(1e-4);
        (eye + (p - eye) * t).truncate()
    }

    /// Casts a ray against the scene only (table, walls, objects, soft
    /// bodies; never proxies or particles).
    pub fn cast_ray(&self, origin: Vec3, dir: Vec3, max_toi: f32) -> Option<RayHit> {
        let ray = Ray::new(origin, dir);
        // Rigid scene colliders, directly (see `scene_colliders`).
        let mut best: Option<(ColliderHandle, RayIntersection)> = None;
        for (h, object, aabb) in self.scene_colliders_along(&ray, max_toi) {
            if object.is_some_and(|i| !self.objects[i].active) {
                continue;
            }
            let limit = best.as_ref().map_or(max_toi, |b| b.1.time_of_impact);
            if aabb.cast_local_ray(&ray, limit, true).is_none() {
                continue;
            }
            let Some(c) = self.physics.colliders.get(*h) else { continue };
            // parry casts rays at cylinders by GJK, whose hits land up to a
            // millimetre off the surface from the eye's distance (see
            // `ray::cylinder_hit`): solved exactly instead.
            let hit = match c.shape().as_cylinder() {
                Some(cyl) => {
                    let pose = c.position();
                    let local = Ray::new(pose.inverse_transform_point(origin), pose.rotation.inverse() * dir);
                    cylinder_hit(local.origin, local.dir, cyl.half_height, cyl.radius, limit)
                        .map(|(toi, n)| RayIntersection::new(toi, pose.rotation * n, FeatureId::Unknown))
                }
                None => c.shape().cast_ray_and_get_normal(c.position(), &ray, limit, true),
            };
            if let Some(hit) = hit {
                best = Some((*h, hit));
            }
        }
        // Soft bodies (their pieces come and go as they tear) through the
        // broad phase, only when the scene has any.
        if !self.soft.is_empty() {
            let limit = best.as_ref().map_or(max_toi, |b| b.1.time_of_impact);
            let groups = InteractionGroups::new(Group::ALL, Group::GROUP_5, InteractionTestMode::And);
            let filter = QueryFilter { groups: Some(groups), ..QueryFilter::default() };
            if let Some(soft) = self.physics.cast_ray_and_get_normal(&ray, limit, true, filter) {
                best = Some(soft);
            }
        }
        let (h, hit) = best?;
        let c = &self.physics.colliders[h];
        let point = ray.point_at(hit.time_of_impact);
        if c.user_data == SOFT_TAG {
            // A cloth is two-sided: its normal faces the ray.
            let normal = if hit.normal.dot(dir) > 0.0 { -hit.normal } else { hit.normal };
            // The ray meets the mesh through the particles' centres, but
            // bodies touch it at its contact skin (the particles' radius):
            // report that surface, or whatever is placed "on" the cloth
            // starts half its thickness inside it and is thrown off.
            let skin = c.contact_skin();
            let toi = (hit.time_of_impact - skin / normal.dot(-dir).max(0.2)).max(0.0);
            return Some(RayHit {
                object: None,
                point: ray.point_at(toi),
                normal,
                toi,
                soft: soft::hit(&self.physics, c, point),
            });
        }
        let object = if c.user_data == ENV_TAG { None } else { Some(ObjectId::new(c.user_data as usize)) };
        Some(RayHit { object, point, normal: hit.normal, toi: hit.time_of_impact, soft: None })
    }

    /// The paper's ray cast for a contact: the camera ray through the table point.
    pub fn cast_contact_ray(&self, table_point: Vec2) -> Option<RayHit> {
        let (o, d) = self.camera_ray(table_point);
        self.cast_ray(o, d, 100.0)
    }

    /// Every body's pose and velocity (and every soft particle's) as raw
    /// bits, for determinism checks.
    pub fn state_bits(&self) -> Vec<u32> {
        let mut out = Vec::new();
        let mut bodies: Vec<_> = self.physics.bodies.iter().collect();
        bodies.sort_by_key(|(h, _)| h.into_raw_parts());
        for (_, b) in bodies {
            let p = b.position();
            out.extend(p.translation.to_array().map(f32::to_bits));
            out.extend(p.rotation.to_array().map(f32::to_bits));
            out.extend(b.linvel().to_array().map(f32::to_bits));
            out.extend(b.angvel().to_array().map(f32::to_bits));
        }
        let mut soft: Vec<_> = self.physics.soft_bodies.iter().collect();
        soft.sort_by_key(|(h, _)| h.0.into_raw_parts());
        for (_, b) in soft {
            for (p, v) in b.particle_positions().zip(b.particle_velocities()) {
                out.extend(p.to_array().map(f32::to_bits));
                out.extend(v.to_array().map(f32::to_bits));
            }
        }
        out
    }
}

/// The rapier collider for a scene shape (cylinders and capsules stand on z).
pub fn collider_for(shape: Shape) -> ColliderBuilder {
    match shape {
        Shape::Box { half_extents: h } => ColliderBuilder::cuboid(h.x, h.y, h.z),
        Shape::Sphere { radius } => ColliderBuilder::ball(radius),
        Shape::Cylinder { radius, half_height } => {
            ColliderBuilder::cylinder(half_height, radius).rotation(Vec3::new(std::f32::consts::FRAC_PI_2, 0.0, 0.0))
        }
        Shape::Capsule { radius, half_height } => ColliderBuilder::capsule_z(half_height, radius),
    }
}
