//! [`GoalTracker`]: evaluates a scene goal on the world, step by step.

use super::containment::{Area, footprint};
use crate::pipeline::world::{ObjectPose, World};
use crate::scene::{Goal, ObjectId, Scene, SortingZone, SteeringGoal, Target};
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
    /// How deep each object lies inside where its goal wants it, as of the
    /// last update (see [`GoalTracker::depth`]).
    depth: Vec<Option<f32>>,
    progress: Progress,
    /// Steering start pose, for restarts.
    start: Option<(ObjectId, Vec3, Quat)>,
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
            depth: vec![None; n],
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
            let o = scene.object(g.object);
            t.start = Some((g.object, o.position, o.rotation));
            t.platform_top = g.platform.map_or(0.0, |p| {
                let po = scene.object(p);
                po.position.z + po.shape.half_z()
            });
        }
        t
    }

    pub fn progress(&self) -> Progress {
        self.progress
    }

    /// True when the object was placed (positioning) and has vanished.
    pub fn is_placed(&self, object: ObjectId) -> bool {
        self.placed[object.index()]
    }

    /// How deep object `id` lies inside the area its goal wants it in, as
    /// of the last update (m; negative: how far it sticks out): its whole
    /// footprint in the best zone of its colour (sorting), the gather
    /// circle or the region; for a positioning target, the tolerance less
    /// its centre's distance. `None` where the goal has no area for it.
    pub fn depth(&self, id: ObjectId) -> Option<f32> {
        self.depth.get(id.index()).copied().flatten()
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
            Goal::Positioning { targets, dwell_s } => self.position(world, targets, *dwell_s, &poses),
            Goal::Sorting { zones, dwell_s } => self.sort(world, zones, *dwell_s, &poses),
            Goal::Steering(g) => self.steer(world, g, &poses),
            Goal::Gather { center, radius, fraction, dwell_s } => {
                self.gather(world, (*center, *radius), *fraction, *dwell_s, &poses)
            }
            Goal::Region { object, min, max, max_height, dwell_s } => {
                let pose = &poses[object.index()];
                let area = Area::Rect { min: *min, max: *max };
                let depth = area.depth(&footprint(world.scene().object(*object).shape, pose));
                self.depth[object.index()] = depth;
                let ok = depth.is_some_and(|d| d >= 0.0) && pose.position.z <= *max_height && resting(pose);
                let done = self.dwell_step(*object, ok, dt, *dwell_s);
                self.progress.placed = usize::from(done);
                done
            }
            Goal::SoftRegion { body, min, max, max_height, dwell_s } => {
                let ok = world.soft_center(*body).is_some_and(|c| {
                    c.x >= min.x && c.x <= max.x && c.y >= min.y && c.y <= max.y && c.z <= *max_height
                }) && world.soft_max_speed(*body) < SOFT_REST_SPEED;
                self.soft_done(ok, dt, *dwell_s)
            }
            Goal::ClothFlat { body, min_area_fraction, dwell_s } => {
                let ok =
                    world.soft_max_speed(*body) < SOFT_REST_SPEED && world.soft_coverage(*body) >= *min_area_fraction;
                self.soft_done(ok, dt, *dwell_s)
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

    /// Positioning: each object that rests on its target for the dwell is
    /// placed and vanishes; done when all are.
    fn position(&mut self, world: &mut World, targets: &[Target], dwell_s: f32, poses: &[ObjectPose]) -> bool {
        let dt = world.dt();
        for t in targets {
            if self.placed[t.object.index()] {
                continue;
            }
            let p = poses[t.object.index()];
            // A target is a point with a tolerance, not an area: the
            // centre's distance is its measure.
            let depth = t.tolerance - (p.position.truncate() - t.position).length();
            self.depth[t.object.index()] = Some(depth);
            let ok = resting(&p) && depth >= 0.0;
            if self.dwell_step(t.object, ok, dt, dwell_s) {
                self.placed[t.object.index()] = true;
                world.remove_object(t.object);
            }
        }
        self.progress.placed = self.placed.iter().filter(|p| **p).count();
        self.progress.placed == targets.len()
    }

    /// Sorting: every object with a zone of its colour rests wholly inside
    /// one for the dwell; objects without a zone do not matter.
    fn sort(&mut self, world: &World, zones: &[SortingZone], dwell_s: f32, poses: &[ObjectPose]) -> bool {
        let dt = world.dt();
        let scene = world.scene();
        let oks: Vec<(ObjectId, bool)> = scene
            .object_ids()
            .filter_map(|id| {
                let o = scene.object(id);
                let p = poses[id.index()];
                let shadow = footprint(o.shape, &p);
                let depth = zones
                    .iter()
                    .filter(|z| z.color == o.color)
                    .filter_map(|z| Area::Rect { min: z.min, max: z.max }.depth(&shadow))
                    .reduce(f32::max)?;
                self.depth[id.index()] = Some(depth);
                Some((id, resting(&p) && depth >= 0.0))
            })
            .collect();
        let mut in_place = 0;
        let mut all = true;
        for (i, ok) in oks {
            if self.dwell_step(i, ok, dt, dwell_s) {
                in_place += 1;
            } else {
                all = false;
            }
        }
        self.progress.placed = in_place;
        all
    }

    /// Gather: at least `fraction` of the dynamic objects rest wholly
    /// inside the circle `(center, radius)` for the dwell.
    fn gather(
        &mut self,
        world: &World,
        (center, radius): (Vec2, f32),
        fraction: f32,
        dwell_s: f32,
        poses: &[ObjectPose],
    ) -> bool {
        let dt = world.dt();
        let scene = world.scene();
        let dynamic: Vec<ObjectId> =
            scene.object_ids().filter(|&id| scene.object(id).body == crate::scene::BodyKind::Dynamic).collect();
        let mut inside = 0;
        let area = Area::Circle { center, radius };
        for &id in &dynamic {
            let p = poses[id.index()];
            let depth = area.depth(&footprint(scene.object(id).shape, &p));
            self.depth[id.index()] = depth;
            let ok = depth.is_some_and(|d| d >= 0.0) && resting(&p);
            if self.dwell_step(id, ok, dt, dwell_s) {
                inside += 1;
            }
        }
        self.progress.placed = inside;
        !dynamic.is_empty() && inside as f32 >= fraction * dynamic.len() as f32
    }

    /// A soft goal met for the dwell counts as its one placed item.
    fn soft_done(&mut self, ok: bool, dt: f32, dwell_s: f32) -> bool {
        let done = self.soft_dwell_step(ok, dt, dwell_s);
        self.progress.placed = usize::from(done);
        done
    }

    /// Advances one object's dwell timer; true once it has held for `need` s.
    fn dwell_step(&mut self, id: ObjectId, ok: bool, dt: f32, need: f32) -> bool {
        let dwell = &mut self.dwell[id.index()];
        *dwell = if ok { *dwell + dt } else { 0.0 };
        ok && *dwell >= need
    }

    fn soft_dwell_step(&mut self, ok: bool, dt: f32, need: f32) -> bool {
        self.soft_dwell = if ok { self.soft_dwell + dt } else { 0.0 };
        ok && self.soft_dwell >= need
    }

    fn steer(&mut self, world: &mut World, g: &SteeringGoal, poses: &[ObjectPose]) -> bool {
        let p = poses[g.object.index()].position;
        if g.platform.is_some() && p.z < self.platform_top - DROP_MARGIN {
            // Dropped off the platform: the task restarts.
            self.progress.restarts += 1;
            self.progress.waypoints_passed = 0;
            if let Some((id, pos, rot)) = self.start {
                world.place_object(id, pos, rot);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::test_scenes::fixture;

    /// Steps the world and the tracker together `n` times.
    fn run(world: &mut World, tracker: &mut GoalTracker, n: usize) -> Progress {
        for _ in 0..n {
            world.step();
            tracker.update(world);
        }
        tracker.progress()
    }

    /// The world and tracker of fixture scene `name` (`tests/scenes/`).
    fn setup(name: &str) -> (World, GoalTracker) {
        let scene = fixture(name);
        (World::new(&scene), GoalTracker::new(&scene))
    }

    fn put(world: &mut World, i: usize, x: f32, y: f32) {
        let id = ObjectId::new(i);
        let z = world.scene().object(id).position.z;
        world.place_object(id, Vec3::new(x, y, z), Quat::IDENTITY);
    }

    #[test]
    fn an_object_counts_once_it_has_rested_on_its_target_for_the_dwell() {
        // A 5 cm cube and its target 20 cm away; a dwell of 0.5 s at 60 Hz
        // is 30 steps.
        let (mut world, mut tracker) = setup("cube_to_target");
        assert_eq!(tracker.progress().total, 1);
        let p = run(&mut world, &mut tracker, 60);
        assert_eq!((p.placed, p.complete), (0, false), "resting away from the target does not count");
        put(&mut world, 0, 0.2, 0.1);
        let p = run(&mut world, &mut tracker, 25);
        assert_eq!((p.placed, p.complete), (0, false), "25 steps (0.42 s) is short of the 0.5 s dwell");
        let p = run(&mut world, &mut tracker, 10);
        assert_eq!((p.placed, p.complete), (1, true), "35 steps (0.58 s) is past it");
        assert!(tracker.is_placed(ObjectId::new(0)) && !world.is_active(ObjectId::new(0)), "a placed object vanishes");
        // 60 steps away, then 30 or 31 steps of dwell (0.5 s in f32 sums of 1/60).
        let at = p.completed_at.expect("completion time");
        assert!((90.0 / 60.0..=91.5 / 60.0).contains(&at), "completed at {at} s");
    }

    #[test]
    fn leaving_the_target_restarts_the_dwell() {
        let (mut world, mut tracker) = setup("cube_to_target");
        put(&mut world, 0, 0.2, 0.1);
        run(&mut world, &mut tracker, 25);
        // Just outside the tolerance for one step: the 25 steps are lost.
        put(&mut world, 0, 0.2 + 0.03, 0.1);
        run(&mut world, &mut tracker, 1);
        put(&mut world, 0, 0.2, 0.1);
        let p = run(&mut world, &mut tracker, 25);
        assert!(!p.complete, "the dwell started again");
        let p = run(&mut world, &mut tracker, 10);
        assert!(p.complete);
    }

    #[test]
    fn sorting_counts_only_objects_in_a_zone_of_their_colour() {
        let (mut world, mut tracker) = setup("sorting_red_blue");
        assert_eq!(tracker.progress().total, 1, "only the red object has a zone");
        put(&mut world, 1, 0.2, 0.2);
        let p = run(&mut world, &mut tracker, 60);
        assert_eq!((p.placed, p.complete), (0, false), "blue in the red zone does not count");
        put(&mut world, 0, 0.15, 0.15);
        let p = run(&mut world, &mut tracker, 20);
        assert_eq!((p.placed, p.complete), (1, true));
        assert!(world.is_active(ObjectId::new(0)), "sorted objects stay on the table");
    }

    #[test]
    fn sorting_wants_the_whole_object_in_the_zone() {
        // An 8 cm cube and the sorting task's right-hand zone (x >= 0.28).
        let (mut world, mut tracker) = setup("sorting_big_box");
        // Its centre 1 cm inside the zone: 3 cm of it hang out.
        put(&mut world, 0, 0.29, 0.0);
        let p = run(&mut world, &mut tracker, 60);
        assert_eq!((p.placed, p.complete), (0, false), "a box hanging out of the zone is not sorted");
        let d = tracker.depth(ObjectId::new(0)).expect("a zone of its colour");
        assert!((d + 0.03).abs() < 1e-3, "depth {d}");
        // 5 cm inside: all of it, with 1 cm to spare.
        put(&mut world, 0, 0.33, 0.0);
        let p = run(&mut world, &mut tracker, 20);
        assert_eq!((p.placed, p.complete), (1, true));
        let d = tracker.depth(ObjectId::new(0)).expect("a zone of its colour");
        assert!((d - 0.01).abs() < 1e-3, "depth {d}");
    }

    /// The puck (object 1) on the platform's top at `(x, y)`.
    fn put_on_platform(world: &mut World, x: f32, y: f32) {
        world.place_object(ObjectId::new(1), Vec3::new(x, y, 0.061), Quat::IDENTITY);
    }

    #[test]
    fn steering_passes_waypoints_in_order_then_the_finish() {
        let (mut world, mut tracker) = setup("steering_platform");
        assert_eq!(tracker.progress().total, 3, "two waypoints and the finish");
        assert_eq!(tracker.next_waypoint(), Some(Vec2::new(0.1, 0.0)));
        // The finish before the waypoints does not count, nor does the second waypoint first.
        put_on_platform(&mut world, -0.3, 0.0);
        let p = run(&mut world, &mut tracker, 5);
        assert_eq!((p.waypoints_passed, p.complete), (0, false));
        put_on_platform(&mut world, -0.1, 0.0);
        assert_eq!(run(&mut world, &mut tracker, 5).waypoints_passed, 0);
        put_on_platform(&mut world, 0.11, 0.01);
        assert_eq!(run(&mut world, &mut tracker, 5).waypoints_passed, 1);
        assert_eq!(tracker.next_waypoint(), Some(Vec2::new(-0.1, 0.0)));
        put_on_platform(&mut world, -0.1, 0.02);
        let p = run(&mut world, &mut tracker, 5);
        assert_eq!((p.waypoints_passed, p.placed, p.complete), (2, 2, false));
        assert_eq!(tracker.next_waypoint(), Some(Vec2::new(-0.3, 0.0)));
        put_on_platform(&mut world, -0.3, 0.0);
        let p = run(&mut world, &mut tracker, 1);
        assert_eq!((p.placed, p.complete, p.restarts), (3, true, 0));
    }

    #[test]
    fn dropping_the_steered_object_restarts_from_the_start() {
        let (mut world, mut tracker) = setup("steering_platform");
        put_on_platform(&mut world, 0.1, 0.0);
        assert_eq!(run(&mut world, &mut tracker, 5).waypoints_passed, 1);
        // Off the platform's edge, on the table: 5 cm below its top.
        world.place_object(ObjectId::new(1), Vec3::new(0.45, 0.3, 0.011), Quat::IDENTITY);
        let p = run(&mut world, &mut tracker, 1);
        assert_eq!((p.restarts, p.waypoints_passed, p.complete), (1, 0, false));
        let back = world.object_pose(ObjectId::new(1)).position;
        assert!((back - Vec3::new(0.3, 0.0, 0.061)).length() < 0.01, "back at the start: {back}");
        assert_eq!(tracker.next_waypoint(), Some(Vec2::new(0.1, 0.0)));
        // Resting on the platform is no drop.
        let p = run(&mut world, &mut tracker, 60);
        assert_eq!(p.restarts, 1);
    }
}
