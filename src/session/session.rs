//! [`Session`]: the frame loop. One frame = one fixed physics step: the
//! surface camera and the simulation run at the same rate (60 Hz by default),
//! which keeps replays exact.

use crate::input::Gesture;
use crate::pipeline::surface::{ContactImage, Hand, RasterParams, Sensor, rasterize_rows};
use crate::pipeline::technique::{
    ConfigError, Feedback, Technique, TechniqueConfig, TechniqueCounts, TechniqueInput, TechniqueKind,
};
use crate::pipeline::vision::{Pipeline, VisionFrame, VisionParams};
use crate::pipeline::world::{World, WorldError};
use crate::scene::Scene;
use crate::session::goal::{GoalTracker, Progress};
use crate::session::object_track::ObjectTrack;
use std::time::Instant;

/// Speed above which an object counts as moving (m/s): well above the
/// jitter of a resting body (< 1 mm/s), below the slowest deliberate push.
pub const MOVING_SPEED: f32 = 0.02;

#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    #[error(transparent)]
    Config(#[from] ConfigError),
    #[error(transparent)]
    World(#[from] WorldError),
    /// A contact image from outside (a camera, a recording) that is not the
    /// sensor's size.
    #[error("contact image is {got_w}x{got_h} pixels; this session's sensor is {want_w}x{want_h}")]
    ImageSize { got_w: usize, got_h: usize, want_w: usize, want_h: usize },
}

impl crate::error::Kind for SessionError {
    fn kind(&self) -> crate::error::ErrorKind {
        match self {
            SessionError::Config(e) => e.kind(),
            SessionError::World(e) => e.kind(),
            SessionError::ImageSize { .. } => crate::error::ErrorKind::BadInput,
        }
    }
}

/// How a session is set up beyond its scene and technique.
#[derive(Debug, Clone, PartialEq)]
pub struct SessionOptions {
    /// Technique parameters; `None` takes the defaults overridden by the
    /// scene's `[technique]` table.
    pub config: Option<TechniqueConfig>,
    /// Contact-image resolution (default 640 × 480 over the whole table).
    pub sensor_px: (u32, u32),
    pub raster: RasterParams,
    pub vision: VisionParams,
    /// Measure contact penetration after every step (for reports; it reads
    /// the narrow phase, so the study's throughput runs leave it off).
    pub measure_penetration: bool,
}

impl Default for SessionOptions {
    fn default() -> Self {
        SessionOptions {
            config: None,
            sensor_px: (640, 480),
            raster: RasterParams::default(),
            vision: VisionParams::default(),
            measure_penetration: false,
        }
    }
}

/// Time spent per stage (µs).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StageTimes {
    pub rasterize_us: f64,
    pub vision_us: f64,
    pub technique_us: f64,
    pub step_us: f64,
}

impl StageTimes {
    pub fn total_us(&self) -> f64 {
        self.rasterize_us + self.vision_us + self.technique_us + self.step_us
    }

    /// Adds another frame's (or sum's) times, stage by stage.
    pub fn add(&mut self, o: &StageTimes) {
        self.rasterize_us += o.rasterize_us;
        self.vision_us += o.vision_us;
        self.technique_us += o.technique_us;
        self.step_us += o.step_us;
    }

    /// A sum over `frames` frames as the mean a frame (zero frames: the sum).
    pub fn per_frame(&self, frames: u64) -> StageTimes {
        let n = frames.max(1) as f64;
        StageTimes {
            rasterize_us: self.rasterize_us / n,
            vision_us: self.vision_us / n,
            technique_us: self.technique_us / n,
            step_us: self.step_us / n,
        }
    }
}

/// A running scene under one technique.
pub struct Session {
    scene: Scene,
    kind: TechniqueKind,
    world: World,
    technique: Box<dyn Technique>,
    vision: Pipeline,
    sensor: Sensor,
    raster: RasterParams,
    image: ContactImage,
    /// Rows of `image` the last frame may have lit.
    lit: std::ops::Range<usize>,
    frame: VisionFrame,
    tracker: GoalTracker,
    progress: Progress,
    last: StageTimes,
    sums: StageTimes,
    frames: u64,
    max_counts: TechniqueCounts,
    measure_penetration: bool,
    /// Each scene object's start and largest tilt (see `ObjectTrack`).
    tracks: Vec<ObjectTrack>,
}

impl std::fmt::Debug for Session {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Session")
            .field("scene", &self.scene.name)
            .field("technique", &self.kind)
            .field("frames", &self.frames)
            .finish_non_exhaustive()
    }
}

impl Session {
    pub fn new(scene: &Scene, kind: TechniqueKind, options: SessionOptions) -> Result<Session, SessionError> {
        let config = match options.config {
            Some(c) => c,
            None => TechniqueConfig::from_scene(scene)?,
        };
        let effects = scene.effects.union(kind.required_effects());
        let world = World::with_effects(scene, effects);
        let tracks = world.object_poses().iter().map(ObjectTrack::new).collect();
        let sensor = Sensor::new(options.sensor_px.0, options.sensor_px.1, scene.table.width, scene.table.depth);
        let mut vision_params = options.vision;
        vision_params.stride = config.particle_stride;
        vision_params.edge_threshold = config.particle_edge_threshold;
        Ok(Session {
            scene: scene.clone(),
            kind,
            world,
            technique: kind.build(config),
            vision: Pipeline::new(vision_params),
            sensor,
            raster: options.raster,
            image: ContactImage::new(sensor.width_px as usize, sensor.height_px as usize),
            lit: 0..sensor.height_px as usize,
            frame: VisionFrame::default(),
            tracker: GoalTracker::new(scene),
            progress: Progress::default(),
            last: StageTimes::default(),
            sums: StageTimes::default(),
            frames: 0,
            max_counts: TechniqueCounts::default(),
            measure_penetration: options.measure_penetration,
            tracks,
        })
    }

    /// One frame: draw the hands, see them, act, step, judge the goal.
    pub fn step(&mut self, hands: &[Hand]) -> Result<Progress, SessionError> {
        let t0 = Instant::now();
        // Only the rows the hands light are cleared, labelled and copied
        // (see `rasterize_rows`).
        self.lit = rasterize_rows(hands, &self.sensor, &self.raster, &mut self.image, self.lit.clone());
        self.see_act_step(t0)
    }

    /// One frame from a contact image made elsewhere (a camera's rectified
    /// frame, a recording): the same frame as [`Session::step`] from its
    /// vision stage on, with no hands to draw. It must be the sensor's size.
    pub fn step_image(&mut self, image: &ContactImage) -> Result<Progress, SessionError> {
        let t0 = Instant::now();
        let (w, h) = (self.sensor.width_px as usize, self.sensor.height_px as usize);
        if image.width != w || image.height != h || image.pixels.len() != w * h {
            return Err(SessionError::ImageSize { got_w: image.width, got_h: image.height, want_w: w, want_h: h });
        }
        self.image.pixels.copy_from_slice(&image.pixels);
        // Any row may be lit: the vision stage reads them all.
        self.lit = 0..h;
        self.see_act_step(t0)
    }

    /// The frame after the contact image is ready (`t0`: when it began):
    /// vision, technique, step, goal.
    fn see_act_step(&mut self, t0: Instant) -> Result<Progress, SessionError> {
        let measure = self.measure_penetration;
        let t1 = Instant::now();
        let interest = self.technique.flow_interest(&self.world, &self.sensor, self.world.dt());
        self.frame = self.vision.process_rows(&self.image, self.lit.clone(), &interest);
        let t2 = Instant::now();
        let input = TechniqueInput { frame: &self.frame, sensor: &self.sensor, dt: self.world.dt() };
        self.technique.apply(&input, &mut self.world.for_technique())?;
        let t3 = Instant::now();
        self.world.step();
        self.technique.after_step(&mut self.world.for_technique());
        if measure {
            self.world.measure_penetration();
        }
        let t4 = Instant::now();
        // Every frame of every run: read the poses in place, no list built.
        for (track, id) in self.tracks.iter_mut().zip(self.world.object_ids()) {
            track.update(&self.world.object_pose(id));
        }
        self.progress = self.tracker.update(&mut self.world);
        self.last = StageTimes {
            rasterize_us: (t1 - t0).as_secs_f64() * 1e6,
            vision_us: (t2 - t1).as_secs_f64() * 1e6,
            technique_us: (t3 - t2).as_secs_f64() * 1e6,
            step_us: (t4 - t3).as_secs_f64() * 1e6,
        };
        self.sums.add(&self.last);
        self.frames += 1;
        let c = self.technique.counts();
        self.max_counts.contacts = self.max_counts.contacts.max(c.contacts);
        self.max_counts.bodies = self.max_counts.bodies.max(c.bodies);
        self.max_counts.joints = self.max_counts.joints.max(c.joints);
        Ok(self.progress)
    }

    /// Replays a gesture from the current time up to `until` seconds
    /// (gesture time 0 = session time 0), one frame per step.
    pub fn replay_until(&mut self, gesture: &Gesture, until: f64) -> Result<Progress, SessionError> {
        while self.time() + 0.5 * f64::from(self.world.dt()) < until {
            let hands = gesture.sample(self.time());
            self.step(&hands)?;
        }
        Ok(self.progress)
    }

    /// Removes the technique's bodies and puts every object back.
    pub fn reset(&mut self) {
        self.technique.clear(&mut self.world.for_technique());
        self.world.reset_objects();
        self.vision.reset();
        self.tracker = GoalTracker::new(&self.scene);
        self.progress = Progress::default();
        self.tracks = self.world.object_poses().iter().map(ObjectTrack::new).collect();
    }

    /// Simulated seconds.
    pub fn time(&self) -> f64 {
        self.world.time()
    }

    pub fn frames(&self) -> u64 {
        self.frames
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    pub fn technique_kind(&self) -> TechniqueKind {
        self.kind
    }

    /// Each scene object's start and largest tilt so far, by object index.
    pub fn object_tracks(&self) -> &[ObjectTrack] {
        &self.tracks
    }

    pub fn world(&self) -> &World {
        &self.world
    }

    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    pub fn sensor(&self) -> &Sensor {
        &self.sensor
    }

    pub fn image(&self) -> &ContactImage {
        &self.image
    }

    pub fn frame(&self) -> &VisionFrame {
        &self.frame
    }

    /// Objects moving faster than [`MOVING_SPEED`] now: what a run or a
    /// trial counts as still in motion.
    pub fn objects_moving(&self) -> u32 {
        self.world().object_poses().iter().filter(|p| p.active && p.linvel.length() > MOVING_SPEED).count() as u32
    }

    pub fn progress(&self) -> Progress {
        self.progress
    }

    pub fn tracker(&self) -> &GoalTracker {
        &self.tracker
    }

    pub fn feedback(&self) -> Feedback {
        self.technique.feedback(&self.world)
    }

    pub fn counts(&self) -> TechniqueCounts {
        self.technique.counts()
    }

    /// The largest counts seen over the session.
    pub fn max_counts(&self) -> TechniqueCounts {
        self.max_counts
    }

    pub fn config_mut(&mut self) -> &mut TechniqueConfig {
        self.technique.config_mut()
    }

    pub fn last_times(&self) -> StageTimes {
        self.last
    }

    /// Mean time per stage over all frames.
    pub fn mean_times(&self) -> StageTimes {
        self.sums.per_frame(self.frames)
    }
}
