//! The bodies and joints a technique adds to the world (proxies, particles,
//! grips, pushers, joint anchors), behind handles only the world hands out.
//!
//! A technique gets a [`TechniqueBody`] for every body it spawns and can
//! move, reshape or remove only those. Scene objects it reaches through an
//! [`ObjectId`] (see `object_push.rs`): it may push them, never remove or
//! teleport them. The type system, not a comment, keeps the two apart.

use super::groups::{Layer, collider_layer};
use super::world::World;
use crate::scene::ObjectId;
use glam::Vec3;
use rapier3d::prelude::*;

/// A rigid body a technique spawned. Only [`World`] creates these, so a
/// scene object's body can never be passed where a technique body is asked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TechniqueBody(RigidBodyHandle);

impl TechniqueBody {
    /// The rapier handle, to compare with what rapier reports (a soft
    /// particle's attachment, a contact pair). Reading only: nothing outside
    /// the world can mutate through it.
    pub fn handle(self) -> RigidBodyHandle {
        self.0
    }
}

/// A joint a technique made between one of its bodies and a scene object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TechniqueJoint(ImpulseJointHandle);

impl World {
    /// Adds a technique body with its collider. The collider must be on a
    /// technique layer ([`Layer::Proxy`], [`Layer::Particle`] or [`Layer::Sight`]): scene ray
    /// casts and the goal measures ignore exactly those.
    pub fn spawn_body(&mut self, body: impl Into<RigidBody>, collider: impl Into<Collider>) -> TechniqueBody {
        self.spawn_compound(body, vec![collider.into()])
    }

    /// Adds a technique body with several colliders, each placed by its own
    /// position relative to the body (a resting hand's pad of particles).
    /// Each collider must be on a technique layer, as for [`World::spawn_body`].
    pub fn spawn_compound(&mut self, body: impl Into<RigidBody>, colliders: Vec<Collider>) -> TechniqueBody {
        debug_assert!(
            colliders.iter().all(|c| matches!(collider_layer(c), Layer::Proxy | Layer::Particle | Layer::Sight)),
            "a technique body's colliders must be on a technique layer"
        );
        let physics = self.physics_mut();
        let body = physics.bodies.insert(body);
        for c in colliders {
            physics.colliders.insert_with_parent(c, body, &mut physics.bodies);
        }
        TechniqueBody(body)
    }

    /// Gives a technique body exactly these colliders (each placed by its
    /// builder's position relative to the body, weighed by its mass), re-using
    /// the ones it has: placed, reshaped where the shape's kind changed (a
    /// ball for a capsule; shapes of one kind are taken to be alike, as a
    /// pad's particles are) and re-weighed in place, so rapier keeps their
    /// pairs and warm-starts their contacts from step to step. Extra
    /// colliders go, missing ones are added.
    pub fn set_compound(&mut self, body: TechniqueBody, colliders: Vec<ColliderBuilder>) {
        let physics = self.physics_mut();
        let Some(have) = physics.bodies.get(body.0).map(|b| b.colliders().to_vec()) else { return };
        let mut parts = colliders.into_iter();
        for h in have {
            match parts.next() {
                Some(part) => {
                    let Some(c) = physics.colliders.get_mut(h) else { continue };
                    c.set_position_wrt_parent(part.position);
                    if c.shape().shape_type() != part.shape.shape_type() {
                        c.set_shape(part.shape);
                    }
                    if let ColliderMassProps::Mass(m) = part.mass_properties
                        && (c.mass() - m).abs() > 1e-7
                    {
                        c.set_mass(m);
                    }
                    c.set_collision_groups(part.collision_groups);
                }
                None => {
                    physics.colliders.remove(
                        h,
                        &mut physics.islands,
                        &mut physics.bodies,
                        &mut physics.soft_bodies,
                        true,
                    );
                }
            }
        }
        for part in parts {
            physics.colliders.insert_with_parent(part.build(), body.0, &mut physics.bodies);
        }
    }

    /// Adds a kinematic anchor at `at`, with no collider: the end of a
    /// joint or a soft particle's attachment that the contact drives.
    pub fn spawn_anchor(&mut self, at: Vec3) -> TechniqueBody {
        let body = RigidBodyBuilder::kinematic_position_based().translation(at).build();
        TechniqueBody(self.physics_mut().bodies.insert(body))
    }

    /// A technique body, to read; `None` once removed.
    pub fn technique_body(&self, body: TechniqueBody) -> Option<&RigidBody> {
        self.physics().bodies.get(body.0)
    }

    /// A technique body, to move: velocities, kinematic targets, pose,
    /// gravity scale, enabled. It is the technique's own.
    pub fn technique_body_mut(&mut self, body: TechniqueBody) -> Option<&mut RigidBody> {
        self.physics_mut().bodies.get_mut(body.0)
    }

    /// Drives a technique body at `velocity` this step. A body that starts
    /// to move further in a step than its CCD thickness (parry's measure of
    /// how far a shape may move before it can pass through something: a
    /// cube's half width), having moved less the step before, has its
    /// contacts this step predicted along that motion.
    ///
    /// rapier's soft CCD grows a body's broad-phase box along its motion at
    /// the end of a step, from the velocity it had then, and refreshes it
    /// before the next step only for colliders that moved. A proxy cube at
    /// rest driven at 2.9 m/s (a fingertip flicked from rest) would find
    /// nothing in its way and pass into a 6 cm box 1.8 cm ahead of it,
    /// leaving it still; predicted along its motion, it pushes the box on at
    /// nearly its own speed
    /// (`a_body_driven_suddenly_meets_what_is_in_its_way_within_the_step`).
    /// Every other step is left as rapier has it, because the alternatives
    /// cost more: soft CCD on every step of a proxy makes top drags of the
    /// steering cylinder fail; re-deciding its pairs every step stops
    /// rapier's contact recycling for them, which changes what slow hands
    /// do (`gaps.rs`, `SLOW_TWIST_PROXY`); and prediction on every step it
    /// moves fast (a cube held back by what it pushes is driven fast to
    /// catch up) puts about twice as many measured trials of the default
    /// study at the time limit (`surfacelab study`, `trials.csv`).
    pub fn drive(&mut self, body: TechniqueBody, velocity: Vec3) {
        let physics = self.physics_mut();
        let dt = physics.integration_parameters.dt;
        let (bodies, colliders) = (&mut physics.bodies, &mut physics.colliders);
        let Some(b) = bodies.get_mut(body.0) else { return };
        let thickness = b
            .colliders()
            .iter()
            .filter_map(|&h| colliders.get(h))
            .map(|c| c.shape().ccd_thickness())
            .fold(f32::INFINITY, f32::min);
        let motion = velocity.length() * dt;
        let starts = motion > thickness && b.linvel().length() * dt <= thickness;
        b.set_linvel(velocity, true);
        b.set_soft_ccd_prediction(if starts { motion } else { 0.0 });
        if !starts {
            return;
        }
        for &h in b.colliders() {
            if let Some(c) = colliders.get_mut(h)
                && let Some(&at) = c.position_wrt_parent()
            {
                // Re-attached where it is: marked as moved, so its
                // broad-phase box is grown along this motion now.
                c.set_position_wrt_parent(at);
            }
        }
    }

    /// A technique body's (first) collider, to read (feedback draws it).
    pub fn technique_collider(&self, body: TechniqueBody) -> Option<&Collider> {
        let physics = self.physics();
        let c = *physics.bodies.get(body.0)?.colliders().first()?;
        physics.colliders.get(c)
    }

    /// A technique body's (first) collider, to reshape or re-weigh.
    pub fn technique_collider_mut(&mut self, body: TechniqueBody) -> Option<&mut Collider> {
        let physics = self.physics_mut();
        let c = *physics.bodies.get(body.0)?.colliders().first()?;
        physics.colliders.get_mut(c)
    }

    /// Removes a technique body, its colliders and its joints.
    pub fn remove_body(&mut self, body: TechniqueBody) {
        let physics = self.physics_mut();
        physics.bodies.remove(
            body.0,
            &mut physics.islands,
            &mut physics.colliders,
            &mut physics.impulse_joints,
            &mut physics.multibody_joints,
            &mut physics.soft_bodies,
            true,
        );
    }

    /// Joins a technique body to a scene object (`joint`'s first anchor is
    /// on the technique body, its second on the object). `None` when the
    /// object has no body.
    pub fn attach(
        &mut self,
        body: TechniqueBody,
        object: ObjectId,
        joint: impl Into<GenericJoint>,
    ) -> Option<TechniqueJoint> {
        let h = self.object_body(object);
        let physics = self.physics_mut();
        physics.bodies.get(h)?;
        Some(TechniqueJoint(physics.impulse_joints.insert(body.0, h, joint, true)))
    }

    /// Removes a joint a technique made.
    pub fn remove_joint(&mut self, joint: TechniqueJoint) {
        self.physics_mut().impulse_joints.remove(joint.0, true);
    }

    /// Attaches particle `particle` of soft body `soft` to a technique body
    /// (rapier's point constraint). `None` when the soft body is gone.
    pub fn attach_particle(&mut self, soft: SoftBodyHandle, particle: u32, body: TechniqueBody) -> Option<()> {
        let physics = self.physics_mut();
        physics.soft_bodies.get_mut(soft)?.attach_particle(particle as usize, body.0, &physics.bodies);
        Some(())
    }

    /// Lets go of every soft particle attached to a technique body.
    pub fn detach_particles(&mut self, body: TechniqueBody) {
        for (_, b) in self.physics_mut().soft_bodies.iter_mut() {
            let held: Vec<u32> =
                b.particle_attachments().iter().filter(|a| a.body == body.0).map(|a| a.particle).collect();
            for p in held {
                b.detach_particle(p as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    /// A 6 cm box resting at the origin (the built-in `cases/small_box`),
    /// pushed by nothing.
    fn world() -> World {
        World::new(&scene::load("cases/small_box").expect("scene"))
    }

    /// A 1 cm proxy cube resting on the table at `(x, y)`.
    fn proxy(world: &mut World, x: f32, y: f32) -> TechniqueBody {
        let body = RigidBodyBuilder::dynamic().translation(Vec3::new(x, y, 0.0105)).lock_rotations().build();
        let collider = ColliderBuilder::cuboid(0.01, 0.01, 0.01).mass(0.05).collision_groups(Layer::Proxy.groups());
        world.spawn_body(body, collider)
    }

    /// `n` ball colliders 1 cm apart along x, on the particle layer.
    fn balls(n: usize, radius: f32) -> Vec<ColliderBuilder> {
        (0..n)
            .map(|i| {
                ColliderBuilder::ball(radius)
                    .translation(Vec3::new(0.01 * i as f32, 0.0, 0.0))
                    .mass(0.1)
                    .collision_groups(Layer::Particle.groups())
            })
            .collect()
    }

    #[test]
    fn a_compound_keeps_its_colliders_when_reshaped() {
        let mut w = world();
        let before = w.physics().colliders.len();
        let body = RigidBodyBuilder::dynamic().translation(Vec3::new(0.3, 0.0, 0.1)).build();
        let b = w.spawn_compound(body, balls(3, 0.003).iter().map(ColliderBuilder::build).collect());
        let handles = |w: &World| w.physics().bodies[b.handle()].colliders().to_vec();
        let first = handles(&w);
        assert_eq!(first.len(), 3);
        // Two, shifted 5 mm along y: the first two colliders stay, moved.
        let mut moved = balls(2, 0.003);
        for c in &mut moved {
            c.position.translation.y = 0.005;
        }
        w.set_compound(b, moved);
        let now = handles(&w);
        assert_eq!(now, first[..2].to_vec(), "the first two colliders are re-used");
        assert_eq!(w.physics().colliders.len(), before + 2);
        let at = w.physics().colliders[now[1]].position_wrt_parent().expect("attached").translation;
        assert!((at - Vec3::new(0.01, 0.005, 0.0)).length() < 1e-6, "{at:?}");
        // Four: two more are added; a capsule replaces a ball's shape.
        let mut four = balls(4, 0.003);
        four[0] = ColliderBuilder::capsule_z(0.05, 0.003).mass(0.2).collision_groups(Layer::Sight.groups());
        w.set_compound(b, four);
        let now = handles(&w);
        assert_eq!(now.len(), 4);
        assert_eq!(now[..2], first[..2]);
        let c0 = &w.physics().colliders[now[0]];
        assert!(c0.shape().as_capsule().is_some(), "reshaped");
        assert!((c0.mass() - 0.2).abs() < 1e-6 && c0.collision_groups() == Layer::Sight.groups());
        w.remove_body(b);
        assert_eq!(w.physics().colliders.len(), before);
    }

    #[test]
    fn a_technique_body_is_spawned_moved_and_removed() {
        let mut w = world();
        let bodies = w.physics().bodies.len();
        let colliders = w.physics().colliders.len();
        let p = proxy(&mut w, 0.3, 0.0);
        assert_eq!(w.physics().bodies.len(), bodies + 1);
        assert_eq!(w.physics().colliders.len(), colliders + 1, "the proxy's collider");
        // Driven at 0.6 m/s along -x for 10 steps (1/6 s): about 10 cm.
        for _ in 0..10 {
            let b = w.technique_body_mut(p).expect("spawned");
            b.set_linvel(Vec3::new(-0.6, 0.0, b.linvel().z), true);
            w.step();
        }
        let x = w.technique_body(p).expect("still there").translation().x;
        assert!((x - 0.2).abs() < 0.01, "moved to x = {x}, expected about 0.2");
        w.remove_body(p);
        assert!(w.technique_body(p).is_none());
        assert_eq!(w.physics().bodies.len(), bodies);
        assert_eq!(w.physics().colliders.len(), colliders, "its collider went with it");
        // The scene object is untouched: there, active, at rest at the origin.
        let boxed = w.object_pose(ObjectId::new(0));
        assert!(boxed.active);
        assert!(boxed.position.truncate().length() < 1e-3, "the box moved to {:?}", boxed.position);
    }

    /// A 1 kg, 1.6 cm cube (a proxy) at rest on the table 1.8 cm behind
    /// the 6 cm box, then driven at 2.9 m/s towards it for one step: how
    /// fast the box goes after that step, driven through `World::drive` or
    /// by setting the velocity alone.
    fn box_speed_after_a_sudden_drive(through_drive: bool) -> f32 {
        let mut w = world();
        let body = RigidBodyBuilder::dynamic().translation(Vec3::new(-0.056, 0.0, 0.0085)).lock_rotations();
        let collider = ColliderBuilder::cuboid(0.008, 0.008, 0.008).mass(1.0).collision_groups(Layer::Proxy.groups());
        let p = w.spawn_body(body, collider);
        for _ in 0..20 {
            w.step();
        }
        let v = Vec3::new(2.9, 0.0, 0.0);
        if through_drive {
            w.drive(p, v);
        } else {
            w.technique_body_mut(p).expect("spawned").set_linvel(v, true);
        }
        w.step();
        w.object_pose(ObjectId::new(0)).linvel.x
    }

    #[test]
    fn a_body_driven_suddenly_meets_what_is_in_its_way_within_the_step() {
        // 4.8 cm in the step, six times the cube's half width: set as a
        // bare velocity, rapier's broad phase still has the cube at rest
        // and the cube passes into the box; driven, it pushes the box on
        // at nearly the cube's speed.
        let (driven, bare) = (box_speed_after_a_sudden_drive(true), box_speed_after_a_sudden_drive(false));
        assert!(driven > 2.0, "driven: the box goes {driven} m/s after the step");
        assert!(bare < 0.5, "a bare velocity: the box goes {bare} m/s (the cube should pass into it)");
    }

    #[test]
    fn a_joint_pulls_the_object_and_removing_it_leaves_the_object() {
        let mut w = world();
        let box_id = ObjectId::new(0);
        let top = w.object_pose(box_id).position + Vec3::Z * 0.015;
        let anchor = w.spawn_anchor(top);
        let spring = SpringJointBuilder::new(0.0, 200.0, 5.0).local_anchor1(Vec3::ZERO).local_anchor2(Vec3::Z * 0.015);
        let joint = w.attach(anchor, box_id, spring.build()).expect("the box has a body");
        // The anchor slides 10 cm along +y over half a second; the box follows.
        for k in 1..=30u8 {
            let at = top + Vec3::Y * (0.1 * f32::from(k) / 30.0);
            w.technique_body_mut(anchor).expect("anchor").set_next_kinematic_translation(at);
            w.step();
        }
        let y = w.object_pose(box_id).position.y;
        assert!(y > 0.05, "the spring dragged the box only to y = {y}");
        w.remove_joint(joint);
        w.remove_body(anchor);
        assert_eq!(w.physics().impulse_joints.len(), 0);
        assert_eq!(w.physics().bodies.len(), 1, "the box's body stays");
        assert!(w.is_active(box_id));
        // Ids are stable: the same object, the same body, after all that.
        assert_eq!(w.object_of_body(w.object_body(box_id)), Some(box_id));
    }

    #[test]
    fn a_scene_object_can_be_pushed_but_keeps_its_place_in_the_world() {
        let mut w = world();
        let id = ObjectId::new(0);
        let mass = w.object_rigid_body(id).expect("body").mass();
        assert!((mass - 0.1).abs() < 1e-6, "mass {mass}");
        // 0.5 m/s along x, then table friction slows it (without the push
        // it would not move; without friction it would keep 0.5 m/s).
        w.push_object(id).expect("body").set_linvel(Vec3::new(0.5, 0.0, 0.0));
        for _ in 0..6 {
            w.step();
        }
        let pose = w.object_pose(id);
        let v = pose.linvel.x;
        assert!(v > 0.0 && v < 0.45, "after 0.1 s the box moves at {v} m/s");
        assert!(pose.position.x > 0.02, "the box slid only to x = {}", pose.position.x);
        w.push_object(id).expect("body").reset_forces();
        assert!(w.is_active(id));
    }
}
