//! The scripted participant: one planner for every technique.
//!
//! It reads the scene's goal and the objects' observed poses, decides which
//! object to move and where, and drives a synthetic fingertip: reach (hand
//! lifted), touch down on the object, drag it towards the goal while
//! watching how it actually moves, lift, wait, repeat. It never looks at
//! which technique is running — differences between conditions come from
//! the physics alone.
//!
//! **What feedback gives it** (the same rule for every technique):
//! - *on*: it sees where its contact actually acts — the technique's
//!   feedback geometry (a joint line's end on the object, proxy cubes,
//!   particles) — and leads its finger by the lag between finger and acting
//!   point; it sees the world after its reaction delay.
//! - *off*: it only sees objects move, 150 ms later than with feedback (it
//!   must infer from motion that its grip slipped), and corrects no lag.
//!
//! Closed loop: every reaction delay it re-plans from what it observes; an
//! object that stops following (slip, lost grip, wedged) for 1 s makes it
//! lift and touch again at a freshly aimed point.

use super::skill::Skill;
use crate::goal::Tracker;
use crate::scene::{Goal, Scene};
use crate::session::Session;
use crate::surface::Hand;
use crate::technique::Feedback;
use glam::Vec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::VecDeque;

/// Extra perceptual delay without visual feedback (s).
const NO_FEEDBACK_DELAY: f32 = 0.15;
/// Speed of the lifted hand travelling to its next touch (m/s).
const REACH_SPEED: f32 = 0.6;
/// Proportional gain of the drag: hand speed per metre of object error
/// (1/s), at most; a participant who sees late moves more carefully, so the
/// gain is also capped at `1 / (2·delay)`, which keeps the delayed loop from
/// oscillating around the goal.
const DRAG_GAIN: f32 = 3.0;
/// How long an object may stop following before the planner re-grips (s).
const STUCK_AFTER: f32 = 1.0;
/// Pause after lifting before the next decision (s).
const WAIT_AFTER_LIFT: f32 = 0.6;

/// What the planner is doing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Intent {
    /// Hand lifted, deciding.
    Idle { until: f64 },
    /// Hand lifted, travelling to touch `object` at `touch`.
    Reach { object: usize, touch: Vec2 },
    /// Finger down on `object`, dragging it to `goal`.
    Drag { object: usize, goal: Vec2, since: f64, best: f32, best_at: f64 },
    /// Finger down on the surface behind `object`, pushing it towards the goal.
    Push { object: usize, best: f32, best_at: f64 },
}

/// How the planner moves an object; chosen by the goal, never the technique.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Manner {
    /// Press on top and drag (positioning, sorting).
    Drag,
    /// Push from behind along the way to the goal, like a puck (steering: a
    /// cylinder dragged by its top tips over).
    Push,
}

fn manner(scene: &Scene) -> Manner {
    if matches!(scene.goal, Goal::Steering(_)) { Manner::Push } else { Manner::Drag }
}

/// Gap between a pushing finger's centre and the object's rim (m).
const PUSH_GAP: f32 = 0.012;

/// A closed-loop scripted participant.
#[derive(Debug, Clone)]
pub struct Planner {
    skill: Skill,
    feedback: bool,
    rng: ChaCha8Rng,
    intent: Intent,
    /// Where the finger presses, in world x/y on the touched surface...
    finger: Vec2,
    /// ...at this height: the hand is drawn where that point appears on
    /// the display (perspective moves tall objects' tops outward).
    touch_z: f32,
    velocity: Vec2,
    next_decision: f64,
    /// Observed object positions with their time, for a delayed view.
    seen: VecDeque<(f64, Vec<Vec2>)>,
}

impl Planner {
    pub fn new(skill: Skill, feedback: bool, seed: u64) -> Planner {
        Planner {
            skill,
            feedback,
            rng: ChaCha8Rng::seed_from_u64(seed),
            intent: Intent::Idle { until: 0.3 },
            finger: Vec2::new(0.0, -0.3),
            touch_z: 0.0,
            velocity: Vec2::ZERO,
            next_decision: 0.0,
            seen: VecDeque::new(),
        }
    }

    pub fn intent(&self) -> Intent {
        self.intent
    }

    fn delay(&self) -> f32 {
        self.skill.reaction_delay + if self.feedback { 0.0 } else { NO_FEEDBACK_DELAY }
    }

    fn gauss(&mut self) -> f32 {
        // Box–Muller from two uniform draws.
        let u1: f32 = self.rng.random_range(1e-6..1.0);
        let u2: f32 = self.rng.random_range(0.0..1.0);
        (-2.0 * u1.ln()).sqrt() * (std::f32::consts::TAU * u2).cos()
    }

    fn aim(&mut self, p: Vec2) -> Vec2 {
        let n = Vec2::new(self.gauss(), self.gauss()) * self.skill.aim_noise;
        p + n
    }

    /// The hands for the next frame, given what the session shows now.
    pub fn hands(&mut self, session: &Session) -> Vec<Hand> {
        let now = session.time();
        let dt = session.world().dt();
        let positions: Vec<Vec2> = session.world().object_poses().iter().map(|p| p.position.truncate()).collect();
        self.seen.push_back((now, positions));
        let delay = f64::from(self.delay());
        while self.seen.len() > 2 && self.seen[1].0 <= now - delay {
            self.seen.pop_front();
        }
        let observed = self.seen.front().map(|(_, p)| p.clone()).unwrap_or_default();

        if now >= self.next_decision {
            self.next_decision = now + f64::from(self.skill.reaction_delay);
            self.decide(session, &observed, now);
        }

        // Move the finger.
        match self.intent {
            Intent::Idle { .. } => Vec::new(),
            Intent::Reach { touch, .. } => {
                let d = touch - self.finger;
                let step = REACH_SPEED * dt;
                if d.length() <= step {
                    self.finger = touch;
                    // Touch down: the drag starts on the next decision.
                    if let Intent::Reach { object, .. } = self.intent {
                        let goal = goal_for(session.scene(), session.tracker(), object, &observed).unwrap_or(touch);
                        let err = (goal - observed.get(object).copied().unwrap_or(touch)).length();
                        self.intent = match manner(session.scene()) {
                            Manner::Drag => Intent::Drag { object, goal, since: now, best: err, best_at: now },
                            Manner::Push => Intent::Push { object, best: err, best_at: now },
                        };
                        self.velocity = Vec2::ZERO;
                        self.next_decision = now;
                    }
                    vec![self.hand(session)]
                } else {
                    self.finger += d / d.length() * step;
                    Vec::new()
                }
            }
            Intent::Drag { .. } | Intent::Push { .. } => {
                self.finger += self.velocity * dt;
                let half =
                    Vec2::new(session.scene().table.width, session.scene().table.depth) * 0.5 - Vec2::splat(0.01);
                self.finger = self.finger.clamp(-half, half);
                vec![self.hand(session)]
            }
        }
    }

    fn hand(&self, session: &Session) -> Hand {
        let p = session.world().screen_point(self.finger.extend(self.touch_z));
        Hand::new(1, self.skill.hand_mode.kind(), p.x, p.y).with_spread(0.4).with_pressure(0.9)
    }

    fn decide(&mut self, session: &Session, observed: &[Vec2], now: f64) {
        let scene = session.scene();
        let tracker = session.tracker();
        match self.intent {
            Intent::Idle { until } => {
                if now < until || session.progress().complete {
                    return;
                }
                if let Some(object) = next_object(scene, tracker, session, observed, self.finger) {
                    let o = session.world().object_pose(object).position;
                    let half_z = scene.objects[object].shape.half_z();
                    let (touch, z) = match manner(scene) {
                        // On top of the object.
                        Manner::Drag => (observed[object], o.z + half_z),
                        // On the surface just behind it, seen from the goal.
                        Manner::Push => {
                            let goal = goal_for(scene, tracker, object, observed).unwrap_or(observed[object]);
                            let dir = (goal - observed[object]).normalize_or(Vec2::X);
                            (observed[object] - dir * (footprint(scene, object) + PUSH_GAP), o.z - half_z)
                        }
                    };
                    let touch = self.aim(touch);
                    self.touch_z = z;
                    self.intent = Intent::Reach { object, touch };
                }
            }
            Intent::Reach { object, .. } => {
                if !session.world().is_active(object) {
                    self.lift(now);
                }
            }
            Intent::Push { object, best, best_at } => self.push(session, observed, now, object, best, best_at),
            Intent::Drag { object, since, best, best_at, .. } => {
                if !session.world().is_active(object) {
                    self.lift(now);
                    return;
                }
                let Some(goal) = goal_for(scene, tracker, object, observed) else {
                    self.lift(now);
                    return;
                };
                let obj = observed[object];
                let err = goal - obj;
                let settle = settle_radius(scene);
                if err.length() < settle {
                    self.lift(now);
                    return;
                }
                // Closed loop: aim the finger so that the *object* reaches
                // the goal; with feedback, lead by the visible lag between
                // the finger and where the contact acts.
                let gain = DRAG_GAIN.min(0.5 / self.delay());
                let mut v = err / err.length() * (gain * err.length()).min(self.speed(scene));
                if self.feedback
                    && let Some(acting) = acting_point(&session.feedback())
                {
                    let lag = self.finger - acting;
                    v -= lag.clamp_length_max(0.03) * 2.0;
                }
                self.velocity = v.clamp_length_max(self.speed(scene));
                // Re-grip when the object stopped following or the finger left it.
                let reach = footprint(scene, object) + 0.03;
                let lost = (self.finger - obj).length() > reach;
                let (best, best_at) = if err.length() < best - 0.005 { (err.length(), now) } else { (best, best_at) };
                if lost || now - best_at > f64::from(STUCK_AFTER) {
                    self.lift(now);
                    return;
                }
                self.intent = Intent::Drag { object, goal, since, best, best_at };
            }
        }
    }

    fn push(&mut self, session: &Session, observed: &[Vec2], now: f64, object: usize, best: f32, best_at: f64) {
        let scene = session.scene();
        let Some(goal) = goal_for(scene, session.tracker(), object, observed) else {
            self.lift(now);
            return;
        };
        let obj = observed[object];
        let err = goal - obj;
        if err.length() < settle_radius(scene) {
            // Close enough: the goal (a waypoint) moves on by itself.
            self.velocity = Vec2::ZERO;
            self.intent = Intent::Push { object, best: f32::MAX, best_at: now };
            return;
        }
        let dir = err / err.length();
        let behind = obj - dir * (footprint(scene, object) + PUSH_GAP * 0.5);
        // Off the line behind the object (it turned, or the goal moved on):
        // lift and set the finger down behind it again.
        let off = behind - self.finger;
        let side = (self.finger - obj).normalize_or(-dir);
        if side.dot(-dir) < 0.8 || off.length() > footprint(scene, object) + 0.03 {
            self.lift(now);
            return;
        }
        let gain = DRAG_GAIN.min(0.5 / self.delay());
        let v = dir * (gain * err.length()).min(self.speed(scene)) + off * 2.0;
        self.velocity = v.clamp_length_max(self.speed(scene));
        let (best, best_at) = if err.length() < best - 0.005 { (err.length(), now) } else { (best, best_at) };
        if now - best_at > f64::from(STUCK_AFTER) * 2.0 {
            self.lift(now);
            return;
        }
        self.intent = Intent::Push { object, best, best_at };
    }

    fn speed(&self, scene: &Scene) -> f32 {
        // Steering is slow and careful: the cylinder must not fall.
        if matches!(scene.goal, Goal::Steering(_)) { self.skill.hand_speed * 0.5 } else { self.skill.hand_speed }
    }

    fn lift(&mut self, now: f64) {
        self.intent = Intent::Idle { until: now + f64::from(WAIT_AFTER_LIFT) };
        self.velocity = Vec2::ZERO;
    }
}

/// Where the contact acts, from the technique's feedback geometry: the mean
/// of the points on objects (joint line ends) or of the cubes.
fn acting_point(f: &Feedback) -> Option<Vec2> {
    let pts: Vec<Vec2> = if f.lines.is_empty() {
        f.cubes.iter().map(|(c, _)| c.truncate()).collect()
    } else {
        f.lines.iter().map(|(_, b)| b.truncate()).collect()
    };
    if pts.is_empty() { None } else { Some(pts.iter().copied().sum::<Vec2>() / pts.len() as f32) }
}

fn footprint(scene: &Scene, object: usize) -> f32 {
    scene.objects[object].shape.footprint_radius()
}

/// How close to its goal an object must get before the planner lets go.
fn settle_radius(scene: &Scene) -> f32 {
    match &scene.goal {
        Goal::Positioning { targets, .. } => targets.iter().map(|t| t.tolerance).fold(f32::MAX, f32::min) * 0.5,
        Goal::Steering(g) => g.waypoint_radius * 0.5,
        _ => 0.02,
    }
}

/// Which object to work on next: the nearest one that is not yet where the
/// goal wants it.
fn next_object(scene: &Scene, tracker: &Tracker, session: &Session, observed: &[Vec2], finger: Vec2) -> Option<usize> {
    (0..scene.objects.len())
        .filter(|&i| session.world().is_active(i))
        .filter_map(|i| {
            let goal = goal_for(scene, tracker, i, observed)?;
            let away = (goal - observed[i]).length();
            (away >= settle_radius(scene)).then_some((i, (observed[i] - finger).length()))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i)
}

/// Where the goal wants object `i` now, if anywhere.
fn goal_for(scene: &Scene, tracker: &Tracker, i: usize, observed: &[Vec2]) -> Option<Vec2> {
    match &scene.goal {
        // Soft-body goals concern no rigid object.
        Goal::None | Goal::SoftRegion { .. } | Goal::ClothFlat { .. } | Goal::Torn { .. } => None,
        Goal::Positioning { targets, .. } => {
            targets.iter().find(|t| t.object == i && !tracker.is_placed(i)).map(|t| t.position)
        }
        Goal::Sorting { zones, .. } => {
            let o = &scene.objects[i];
            let p = observed[i];
            let mine: Vec<_> = zones.iter().filter(|z| z.color_name == o.color_name).collect();
            if mine.iter().any(|z| {
                z.contains(p) && inset(z.min, z.max, 0.03).is_some_and(|(a, b)| p.cmpge(a).all() && p.cmple(b).all())
            }) {
                return None;
            }
            // The nearest point well inside the nearest zone of its colour.
            mine.iter()
                .filter_map(|z| inset(z.min, z.max, 0.06).map(|(a, b)| p.clamp(a, b)))
                .min_by(|a, b| (*a - p).length().total_cmp(&(*b - p).length()))
        }
        Goal::Steering(g) => (g.object == i).then(|| tracker.next_waypoint()).flatten(),
        Goal::Gather { center, radius, .. } => {
            let p = observed[i];
            ((p - *center).length() > radius * 0.7).then_some(*center)
        }
        Goal::Region { object, min, max, .. } => (*object == i).then(|| (*min + *max) * 0.5),
    }
}

fn inset(min: Vec2, max: Vec2, m: f32) -> Option<(Vec2, Vec2)> {
    let a = min + Vec2::splat(m);
    let b = max - Vec2::splat(m);
    (a.x <= b.x && a.y <= b.y).then_some((a, b))
}
