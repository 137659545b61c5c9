//! [`GoalTracker`]: evaluates a scene goal on the world, step by step.

use crate::pipeline::world::{ObjectPose, World};
use crate::scene::{Goal, Scene, SteeringGoal};
use glam::{Quat, Vec2, Vec3};

/// Speed (m/s) below which an object counts as resting for a dwell.
const REST_SPEED: f32 = 0.05;
/// The same for a soft body's fastest particle: a cloth's edge flutters.
const SOFT_REST_SPEED: f32 = 0.1;
/// How far below the platform top the steered object may sink before it
/// counts as dropped (m).
const DROP_MARGIN: f32 = 0.02;

/// Where a trial stands.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Progress {
    pub complete: bool,
    /// Seconds of simulated time when the goal was met.
    pub completed_at: Option<f64>,
    /// Positioning: objects placed; sorting/gather: objects in place now.
    pub placed: usize,
    /// How many objects the goal concerns.
    pub total: usize,
    /// Steering: waypoints passed so far.
    pub waypoints_passed: usize,
    /// Steering: drops that restarted the task.
    pub restarts: u32,
}

/// Evaluates one scene's goal.
#[derive(Debug, Clone)]
pub struct GoalTracker {
    goal: Goal,
    /// Seconds each object has rested where it should (per object).
    dwell: Vec<f32>,
    placed: Vec<bool>,
    progress: Progress,
    /// Steering start pose, for restarts.
    start: Option<(usize, Vec3, Quat)>,
    platform_top: f32,
    /// Seconds the soft body of a soft goal has met it.
    soft_dwell: f32,
}

impl GoalTracker {
    pub fn new(scene: &Scene) -> GoalTracker {
        let n = scene.objects.len();
        let mut t = GoalTracker {
            goal: scene.goal.clone(),
            dwell: vec![0.0; n],
            placed: vec![false; n],
            progress: Progress::default(),
            start: None,
            platform_top: 0.0,
            soft_dwell: 0.0,
        };
        t.progress.total = match &scene.goal {
            Goal::None => 0,
            Goal::Positioning { targets, .. } => targets.len(),
            Goal::Sorting { zones, .. } => {
                scene.objects.iter().filter(|o| zones.iter().any(|z| z.color == o.color)).count()
            }
            Goal::Steering(g) => g.waypoints.len() + 1,
            Goal::Gather { .. } => scene.objects.iter().filter(|o| o.body == crate::scene::BodyKind::Dynamic).count(),
            Goal::Region { .. } | Goal::SoftRegion { .. } | Goal::ClothFlat { .. } => 1,
            Goal::Torn { pieces, .. } => *pieces,
        };
        if let Goal::Steering(g) = &scene.goal {
            let o = &scene.objects[g.object];
            t.start = Some((g.object, o.position, o.rotation));
            t.platform_top = g.platform.map_or(0.0, |p| {
                let po = &scene.objects[p];
                po.position.z + po.shape.half_z()
            });
        }
        t
    }

    pub fn progress(&self) -> Progress {
        self.progress
    }

    /// True when the object was placed (positioning) and has vanished.
    pub fn is_placed(&self, object: usize) -> bool {
        self.placed[object]
    }

    /// Call after every world step. May change the world: placed objects
    /// vanish, a dropped steering object goes back to the start.
    pub fn update(&mut self, world: &mut World) -> Progress {
        if self.progress.complete {
            return self.progress;
        }
        let dt = world.dt();
        let poses = world.object_poses();
        let goal = self.goal.clone();
        let done = match &goal {
            Goal::None => false,
            Goal::Positioning { targets, dwell_s } => {
                for t in targets {
                    if self.placed[t.object] {
                        continue;
                    }
                    let p = poses[t.object];
                    let ok = resting(&p) && (p.position.truncate() - t.position).length() <= t.tolerance;
                    if self.dwell_step(t.object, ok, dt, *dwell_s) {
                        self.placed[t.object] = true;
                        world.remove_object(t.object);
                    }
                }
                self.progress.placed = self.placed.iter().filter(|p| **p).count();
                self.progress.placed == targets.len()
            }
            Goal::Sorting { zones, dwell_s } => {
                let scene = world.scene();
                let mut in_place = 0;
                let mut all = true;
                let mut oks = Vec::new();
                for (i, o) in scene.objects.iter().enumerate() {
                    let mine: Vec<_> = zones.iter().filter(|z| z.color == o.color).collect();
                    if mine.is_empty() {
                        continue;
                    }
                    let p = poses[i];
                    let ok = resting(&p) && mine.iter().any(|z| z.contains(p.position.truncate()));
                    oks.push((i, ok));
                }
                for (i, ok) in oks {
                    let settled = self.dwell_step(i, ok, dt, *dwell_s);
                    if settled {
                        in_place += 1;
                    } else {
                        all = false;
                    }
                }
                self.progress.placed = in_place;
                all
            }
            Goal::Steering(g) => self.steer(world, g, &poses),
            Goal::Gather { center, radius, fraction, dwell_s } => {
                let dynamic: Vec<usize> = (0..poses.len())
                    .filter(|&i| world.scene().objects[i].body == crate::scene::BodyKind::Dynamic)
                    .collect();
                let mut inside = 0;
                for &i in &dynamic {
                    let ok = (poses[i].position.truncate() - *center).length() <= *radius && resting(&poses[i]);
                    if self.dwell_step(i, ok, dt, *dwell_s) {
                        inside += 1;
                    }
                }
                self.progress.placed = inside;
                !dynamic.is_empty() && inside as f32 >= fraction * dynamic.len() as f32
            }
            Goal::Region { object, min, max, max_height, dwell_s } => {
                let p = poses[*object].position;
                let ok = p.x >= min.x
                    && p.x <= max.x
                    && p.y >= min.y
                    && p.y <= max.y
                    && p.z <= *max_height
                    && resting(&poses[*object]);
                let done = self.dwell_step(*object, ok, dt, *dwell_s);
                self.progress.placed = usize::from(done);
                done
            }
            Goal::SoftRegion { body, min, max, max_height, dwell_s } => {
                let ok = world.soft_center(*body).is_some_and(|c| {
                    c.x >= min.x && c.x <= max.x && c.y >= min.y && c.y <= max.y && c.z <= *max_height
                }) && world.soft_max_speed(*body) < SOFT_REST_SPEED;
                let done = self.soft_dwell_step(ok, dt, *dwell_s);
                self.progress.placed = usize::from(done);
                done
            }
            Goal::ClothFlat { body, min_area_fraction, dwell_s } => {
                let ok =
                    world.soft_max_speed(*body) < SOFT_REST_SPEED && world.soft_coverage(*body) >= *min_area_fraction;
                let done = self.soft_dwell_step(ok, dt, *dwell_s);
                self.progress.placed = usize::from(done);
                done
            }
            Goal::Torn { body, pieces, min_piece_fraction } => {
                let masses = world.soft_piece_masses(*body);
                let total: f32 = masses.iter().sum();
                let big = masses.iter().filter(|m| **m >= min_piece_fraction * total).count();
                self.progress.placed = big.min(*pieces);
                big >= *pieces
            }
        };
        if done {
            self.progress.complete = true;
            self.progress.completed_at = Some(world.time());
        }
        self.progress
    }

    /// Advances one object's dwell timer; true once it has held for `need` s.
    fn dwell_step(&mut self, i: usize, ok: bool, dt: f32, need: f32) -> bool {
        if ok {
            self.dwell[i] += dt;
        } else {
            self.dwell[i] = 0.0;
        }
        ok && self.dwell[i] >= need
    }

    fn soft_dwell_step(&mut self, ok: bool, dt: f32, need: f32) -> bool {
        self.soft_dwell = if ok { self.soft_dwell + dt } else { 0.0 };
        ok && self.soft_dwell >= need
    }

    fn steer(&mut self, world: &mut World, g: &SteeringGoal, poses: &[ObjectPose]) -> bool {
        let p = poses[g.object].position;
        if g.platform.is_some() && p.z < self.platform_top - DROP_MARGIN {
            // Dropped off the platform: the task restarts.
            self.progress.restarts += 1;
            self.progress.waypoints_passed = 0;
            if let Some((i, pos, rot)) = self.start {
                world.place_object(i, pos, rot);
            }
            return false;
        }
        let xy = p.truncate();
        let passed = self.progress.waypoints_passed;
        if passed < g.waypoints.len() {
            if (xy - g.waypoints[passed]).length() <= g.waypoint_radius {
                self.progress.waypoints_passed += 1;
            }
            self.progress.placed = self.progress.waypoints_passed;
            return false;
        }
        let at_finish = (xy - g.finish).length() <= g.finish_radius;
        self.progress.placed = self.progress.waypoints_passed + usize::from(at_finish);
        at_finish
    }

    /// The next point the goal wants the given object at, if any (planner aid).
    pub fn next_waypoint(&self) -> Option<Vec2> {
        match &self.goal {
            Goal::Steering(g) => Some(g.waypoints.get(self.progress.waypoints_passed).copied().unwrap_or(g.finish)),
            _ => None,
        }
    }
}

fn resting(p: &ObjectPose) -> bool {
    p.active && p.linvel.length() < REST_SPEED
}
