//! The scripted participant's hands: one closed-loop skeleton for every
//! manner and every technique.
//!
//! An *episode* runs from a decision to the last hand's lift: pick the open
//! object nearest a hand (the *seed*), look at the situation (how many
//! objects share its destination nearby, its size, whether another object
//! waits elsewhere), let the [`Learner`] pick one of the manners the
//! situation allows, reach with one or two hands, then move in closed loop:
//! a hand on top of an object (*carry*) steers so that the object reaches
//! its goal; a hand behind objects (*push*) moves towards their goal,
//! staying behind the rearmost. Each reaction delay it re-plans from what it
//! sees; a hand whose objects stop following for a while, or escape it,
//! lifts (a *re-grip*, penalised); a drop ends the episode. The episode's
//! payoff teaches the learner. It never looks at which technique runs —
//! differences between conditions come from the physics alone.
//!
//! **What feedback gives it** (the same rule for every technique): with
//! feedback *on* it sees where each contact acts — the technique's feedback
//! geometry near the hand (joint line ends on the object, proxy cubes,
//! particles) — and leads a carrying hand by the lag between hand and
//! acting point. With feedback *off* it sees only the objects, as the
//! paper's participants did, with no added delay; an extra perception delay
//! can be switched on ([`PlannerOptions::perception_delay_s`]).

use super::goals::{Want, cluster, footprint, open_objects, settle_radius, want};
use super::learner::{Context, Learner, net_progress, payoff};
use super::manner::{Manner, Situation, applicable, fingers};
use super::repertoire::Repertoire;
use super::skill::Skill;
use super::usage::Usage;
use crate::pipeline::surface::{Hand, HandKind};
use crate::pipeline::technique::Feedback;
use crate::scene::{Goal, ObjectId, Scene};
use crate::session::Session;
use glam::Vec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::VecDeque;

/// Speed of a lifted hand travelling to its next touch (m/s).
const REACH_SPEED: f32 = 0.6;
/// Proportional gain of the drag: hand speed per metre of object error
/// (1/s), at most; a participant who sees late moves more carefully, so the
/// gain is also capped at `1 / (2·delay)`, which keeps the delayed loop from
/// oscillating around the goal.
const DRAG_GAIN: f32 = 3.0;
/// How long objects may stop following before a hand re-grips (s); pushes
/// get twice as long (objects bump and turn before they go).
const STUCK_AFTER: f32 = 1.0;
/// Pause after lifting before the next decision (s).
const WAIT_AFTER_LIFT: f32 = 0.6;
/// Gap between a pushing hand's rim and the object's rim (m).
const PUSH_GAP: f32 = 0.006;
/// How far the two hands of a gather turn inward (rad, ~20°): a scoop.
const GATHER_TILT: f32 = 0.35;
/// Where the hands rest between episodes (right, left), m from the centre.
const REST: [Vec2; 2] = [Vec2::new(0.2, -0.3), Vec2::new(-0.2, -0.3)];

/// Settings of the participant model that are not skill.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlannerOptions {
    /// Chance of a random manner per episode (see `learner`).
    pub explore: f32,
    /// Extra delay (s) before the participant sees the world when feedback
    /// is off. 0 by default: the paper removed only the display of where
    /// input acts; objects stayed visible at once.
    pub perception_delay_s: f32,
    /// The manners the participant may use (the study's ablation factor);
    /// the full repertoire by default.
    pub repertoire: Repertoire,
}

impl Default for PlannerOptions {
    fn default() -> Self {
        PlannerOptions {
            explore: super::learner::EXPLORE_MEASURED,
            perception_delay_s: 0.0,
            repertoire: Repertoire::FULL,
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Role {
    /// On top of (or around) one object, dragging it to its goal.
    Carry { object: ObjectId },
    /// Behind these objects, pushing them towards their common goal;
    /// `lateral` shifts the hand sideways from the group's centre line.
    Push { objects: Vec<ObjectId>, lateral: f32, standoff: f32 },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    Reach,
    Down,
    Lifted,
}

#[derive(Debug, Clone, PartialEq)]
struct HandCtl {
    /// 1 the right hand, 2 the left.
    id: u32,
    kind: HandKind,
    spread: f32,
    angle: f32,
    /// Where the hand presses (world x/y on the touched surface)...
    pos: Vec2,
    /// ...at this height: drawn where that point appears on the display.
    z: f32,
    touch: Vec2,
    /// The middle of the hand's contact relative to `pos` (a flat hand's
    /// palm centre lies 2–3 cm behind the middle of what it covers).
    centre: Vec2,
    phase: Phase,
    role: Role,
    velocity: Vec2,
    best: f32,
    best_at: f64,
}

#[derive(Debug, Clone, PartialEq)]
struct Episode {
    manner: Manner,
    context: Context,
    started: f64,
    progress: f32,
    regrips: u32,
    drops: u32,
    hands: Vec<HandCtl>,
}

/// A closed-loop scripted participant for one trial.
#[derive(Debug, Clone)]
pub struct Planner {
    skill: Skill,
    feedback: bool,
    options: PlannerOptions,
    rng: ChaCha8Rng,
    learner: Learner,
    usage: Usage,
    episode: Option<Episode>,
    idle_until: f64,
    rest: [Vec2; 2],
    next_decision: f64,
    /// Observed object positions with their time, for a delayed view.
    seen: VecDeque<(f64, Vec<Vec2>)>,
    /// Per object: the region and distance to goal at the last decision.
    last: Vec<Option<(u64, f32)>>,
    restarts: u32,
}

impl Planner {
    pub fn new(skill: Skill, feedback: bool, seed: u64, learner: Learner, options: PlannerOptions) -> Planner {
        Planner {
            skill,
            feedback,
            options,
            rng: ChaCha8Rng::seed_from_u64(seed),
            learner,
            usage: Usage::default(),
            episode: None,
            idle_until: 0.3,
            rest: REST,
            next_decision: 0.0,
            seen: VecDeque::new(),
            last: Vec::new(),
            restarts: 0,
        }
    }

    /// What the participant has learned so far.
    pub fn learner(&self) -> &Learner {
        &self.learner
    }

    /// Ends the trial: the time spent in an unfinished episode counts for
    /// its manner (and teaches nothing); returns the learner and the usage.
    pub fn finish(mut self, now: f64) -> (Learner, Usage) {
        if let Some(e) = self.episode.take() {
            self.usage.add(e.manner, (now - e.started) as f32, net_progress(e.progress, e.regrips, e.drops));
        }
        (self.learner, self.usage)
    }

    fn delay(&self) -> f32 {
        self.skill.reaction_delay + if self.feedback { 0.0 } else { self.options.perception_delay_s }
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

        let half = Vec2::new(session.scene().table.width, session.scene().table.depth) * 0.5 - Vec2::splat(0.01);
        let mut touched = false;
        let mut out = Vec::new();
        if let Some(e) = &mut self.episode {
            for h in &mut e.hands {
                match h.phase {
                    Phase::Reach => {
                        let d = h.touch - h.pos;
                        let step = REACH_SPEED * dt;
                        if d.length() <= step {
                            h.pos = h.touch;
                            h.phase = Phase::Down;
                            h.velocity = Vec2::ZERO;
                            h.best = f32::MAX;
                            h.best_at = now;
                            touched = true;
                        } else {
                            h.pos += d / d.length() * step;
                        }
                    }
                    Phase::Down => h.pos = (h.pos + h.velocity * dt).clamp(-half, half),
                    Phase::Lifted => {}
                }
                if h.phase == Phase::Down {
                    let p = session.world().screen_point(h.pos.extend(h.z));
                    out.push(
                        Hand::new(h.id, h.kind, p.x, p.y).with_angle(h.angle).with_spread(h.spread).with_pressure(0.9),
                    );
                }
            }
        }
        if touched {
            // Touch down: steer from the next frame on.
            self.next_decision = now;
        }
        out
    }

    fn decide(&mut self, session: &Session, observed: &[Vec2], now: f64) {
        let scene = session.scene();
        let world = session.world();
        let active: Vec<bool> = scene.object_ids().map(|id| world.is_active(id)).collect();
        let open = open_objects(scene, session.tracker(), &active, observed);
        let restarts = session.progress().restarts;
        let dropped = restarts > self.restarts;
        self.restarts = restarts;
        let progress = self.account(scene, session, observed, &open, dropped);

        if let Some(e) = &mut self.episode {
            e.progress += progress;
            if dropped {
                e.drops += 1;
                for h in &mut e.hands {
                    h.phase = Phase::Lifted;
                }
            }
        }
        if self.episode.is_none() {
            if now >= self.idle_until && !session.progress().complete {
                self.start_episode(session, observed, &open, now);
            }
            return;
        }
        // Feedback geometry is looked at only while a hand carries something.
        let carrying = self
            .episode
            .as_ref()
            .is_some_and(|e| e.hands.iter().any(|h| h.phase == Phase::Down && matches!(h.role, Role::Carry { .. })));
        let feedback = (self.feedback && carrying).then(|| session.feedback());
        let delay = self.delay();
        let sight = Sight {
            scene,
            open: &open,
            observed,
            now,
            gain: DRAG_GAIN.min(0.5 / delay),
            speed: self.speed(scene),
            delay,
            feedback: feedback.as_ref(),
        };
        let mut regrips = 0;
        if let Some(e) = &mut self.episode {
            for h in &mut e.hands {
                if h.phase != Phase::Down {
                    continue;
                }
                let lifted = match &h.role {
                    Role::Carry { object } => carry(h, *object, &sight),
                    Role::Push { .. } => push(h, &sight),
                };
                match lifted {
                    Step::Going => {}
                    Step::Done => h.phase = Phase::Lifted,
                    Step::Regrip => {
                        h.phase = Phase::Lifted;
                        regrips += 1;
                    }
                }
            }
            e.regrips += regrips;
            if e.manner == Manner::BimanualDrag {
                couple_hands(&mut e.hands, &open, observed);
            }
        }
        let over = self.episode.as_ref().is_some_and(|e| e.hands.iter().all(|h| h.phase == Phase::Lifted));
        if over && let Some(e) = self.episode.take() {
            let duration = (now - e.started) as f32;
            let pay = payoff(e.progress, e.regrips, e.drops, duration);
            self.learner.update(e.context, e.manner, pay);
            self.usage.add(e.manner, duration, net_progress(e.progress, e.regrips, e.drops));
            for h in &e.hands {
                self.rest[(h.id as usize).saturating_sub(1).min(1)] = h.pos;
            }
            self.idle_until = now + f64::from(WAIT_AFTER_LIFT);
        }
    }

    /// Progress since the last decision: the drop in the summed distance of
    /// open objects to their goals, counting an object that reached its
    /// region (or a waypoint) as having covered its last distance.
    fn account(
        &mut self,
        scene: &Scene,
        session: &Session,
        observed: &[Vec2],
        open: &[(ObjectId, Want)],
        dropped: bool,
    ) -> f32 {
        let n = scene.objects.len();
        let mut now: Vec<Option<(u64, f32)>> = vec![None; n];
        for (id, w) in open {
            now[id.index()] = Some((w.region, (w.point - observed[id.index()]).length()));
        }
        // Objects near enough to settle are still wanted somewhere: keep
        // their region so that leaving it is not counted twice.
        for id in scene.object_ids() {
            if now[id.index()].is_none()
                && session.world().is_active(id)
                && let Some(w) = want(scene, session.tracker(), id, observed)
            {
                now[id.index()] = Some((w.region, (w.point - observed[id.index()]).length()));
            }
        }
        let mut progress = 0.0;
        if !dropped && self.last.len() == n {
            for (before, after) in self.last.iter().zip(&now) {
                progress += match (before, after) {
                    (Some((r, e)), Some((r2, e2))) if r == r2 => e - e2,
                    (Some((_, e)), _) => *e,
                    (None, _) => 0.0,
                };
            }
        }
        self.last = now;
        progress
    }

    fn start_episode(&mut self, session: &Session, observed: &[Vec2], open: &[(ObjectId, Want)], now: f64) {
        let scene = session.scene();
        // The open object nearest a hand, and that hand.
        let Some((seed, hand)) = open.iter().flat_map(|(i, _)| (0..2).map(move |h| (*i, h))).min_by(|a, b| {
            (observed[a.0.index()] - self.rest[a.1])
                .length()
                .total_cmp(&(observed[b.0.index()] - self.rest[b.1]).length())
        }) else {
            return;
        };
        let members = cluster(open, observed, seed);
        let other = 1 - hand;
        let second = open.iter().map(|(i, _)| *i).filter(|&i| i != seed).min_by(|&a, &b| {
            (observed[a.index()] - self.rest[other])
                .length()
                .total_cmp(&(observed[b.index()] - self.rest[other]).length())
        });
        let situation =
            Situation { cluster: members.len(), footprint: footprint(scene, seed), second_object: second.is_some() };
        let context = Context::new(&scene.goal, members.len());
        let mut options = applicable(situation);
        options.retain(|&m| self.options.repertoire.allows(m));
        let Some(manner) = self.learner.choose(context, &options, self.options.explore, &mut self.rng) else {
            return;
        };
        let mut hands = Vec::new();
        let id = |h: usize| h as u32 + 1;
        match manner {
            Manner::Fingertips(_) | Manner::Pinch | Manner::FlatHand => {
                hands.push(self.carry_hand(session, id(hand), manner, seed, observed));
            }
            Manner::BimanualDrag => {
                hands.push(self.carry_hand(session, id(hand), manner, seed, observed));
                if let Some(s) = second {
                    hands.push(self.carry_hand(session, id(other), manner, s, observed));
                }
            }
            Manner::PushFingertip | Manner::PushEdge => {
                hands.push(self.push_hand(session, id(hand), manner, vec![seed], 0.0, observed));
            }
            Manner::EdgeSweep | Manner::ForearmSweep => {
                hands.push(self.push_hand(session, id(hand), manner, members.clone(), 0.0, observed));
            }
            Manner::TwoHandGather => {
                let width = spread_across(&members, observed, scene, direction(scene, session, &members, observed));
                let lateral = (width * 0.5).max(0.04);
                // The right hand takes the side to its right of the push.
                hands.push(self.push_hand(session, 1, manner, members.clone(), -lateral, observed));
                hands.push(self.push_hand(session, 2, manner, members.clone(), lateral, observed));
            }
        }
        for h in &mut hands {
            h.pos = self.rest[(h.id as usize - 1).min(1)];
        }
        self.episode = Some(Episode { manner, context, started: now, progress: 0.0, regrips: 0, drops: 0, hands });
    }

    fn carry_hand(
        &mut self,
        session: &Session,
        id: u32,
        manner: Manner,
        object: ObjectId,
        observed: &[Vec2],
    ) -> HandCtl {
        let scene = session.scene();
        let o = session.world().object_pose(object).position;
        let half_z = scene.object(object).shape.half_z();
        let r = footprint(scene, object);
        let (z, spread) = match manner {
            // Thumb and index beside the object, on the surface it stands on.
            Manner::Pinch => (o.z - half_z, ((2.0 * (r + 0.004) - 0.013) / 0.012).max(0.0)),
            _ => (o.z + half_z, 0.4),
        };
        // The middle of the contact goes on the object.
        let centre = contact_centre(manner.hand_kind(), spread);
        let touch = self.aim(observed[object.index()]) - centre;
        HandCtl {
            id,
            kind: manner.hand_kind(),
            spread,
            angle: 0.0,
            pos: touch,
            z,
            touch,
            centre,
            phase: Phase::Reach,
            role: Role::Carry { object },
            velocity: Vec2::ZERO,
            best: f32::MAX,
            best_at: 0.0,
        }
    }

    fn push_hand(
        &mut self,
        session: &Session,
        id: u32,
        manner: Manner,
        objects: Vec<ObjectId>,
        lateral: f32,
        observed: &[Vec2],
    ) -> HandCtl {
        let scene = session.scene();
        let kind = manner.hand_kind();
        let standoff = half_thickness(kind) + PUSH_GAP;
        let dir = direction(scene, session, &objects, observed);
        let target = behind(scene, &objects, observed, dir, standoff, lateral);
        let bottom = objects
            .iter()
            .map(|&i| session.world().object_pose(i).position.z - scene.object(i).shape.half_z())
            .fold(f32::MAX, f32::min);
        let touch = self.aim(target);
        HandCtl {
            id,
            kind,
            spread: 0.4,
            angle: push_angle(kind, dir, lateral),
            pos: touch,
            z: bottom.max(0.0),
            touch,
            centre: Vec2::ZERO,
            phase: Phase::Reach,
            role: Role::Push { objects, lateral, standoff },
            velocity: Vec2::ZERO,
            best: f32::MAX,
            best_at: 0.0,
        }
    }

    fn speed(&self, scene: &Scene) -> f32 {
        // Steering is slow and careful: the cylinder must not fall.
        if matches!(scene.goal, Goal::Steering(_)) { self.skill.hand_speed * 0.5 } else { self.skill.hand_speed }
    }

    /// Hands on the table now and the fingers they touch with.
    pub fn hands_down(&self) -> (u32, u32) {
        self.episode.as_ref().map_or((0, 0), |e| {
            e.hands.iter().filter(|h| h.phase == Phase::Down).fold((0, 0), |(n, f), h| (n + 1, f + fingers(h.kind)))
        })
    }

    /// The manner of the episode under way, if any.
    pub fn manner(&self) -> Option<Manner> {
        self.episode.as_ref().map(|e| e.manner)
    }
}

enum Step {
    Going,
    Done,
    Regrip,
}

/// The area-weighted middle of a hand's footprint in its own frame.
fn contact_centre(kind: HandKind, spread: f32) -> Vec2 {
    let patches = Hand::new(0, kind, 0.0, 0.0).with_spread(spread).patches();
    let (sum, area) = patches.iter().fold((Vec2::ZERO, 0.0), |(sum, area), p| {
        let [lo, hi] = p.shape.bounds();
        let a = p.shape.area();
        (sum + Vec2::new(lo[0] + hi[0], lo[1] + hi[1]) * 0.5 * a, area + a)
    });
    if area > 0.0 { sum / area } else { Vec2::ZERO }
}

/// Half the width of a hand's footprint across a push (m).
fn half_thickness(kind: HandKind) -> f32 {
    match kind {
        HandKind::Edge => 0.012,
        HandKind::Forearm => 0.035,
        HandKind::FlatHand => 0.048,
        _ => 0.0075,
    }
}

/// A pushing hand's angle: an edge or forearm (which run along the hand's
/// local y) lies across the push; a gather's two hands turn inward.
fn push_angle(kind: HandKind, dir: Vec2, lateral: f32) -> f32 {
    match kind {
        HandKind::Edge | HandKind::Forearm => {
            dir.y.atan2(dir.x) - GATHER_TILT * lateral.signum() * f32::from(lateral != 0.0)
        }
        _ => 0.0,
    }
}

/// From the objects' centre towards their goals' centre.
fn direction(scene: &Scene, session: &Session, objects: &[ObjectId], observed: &[Vec2]) -> Vec2 {
    let goals: Vec<Vec2> =
        objects.iter().filter_map(|&i| want(scene, session.tracker(), i, observed).map(|w| w.point)).collect();
    if goals.is_empty() {
        return Vec2::X;
    }
    let g = goals.iter().copied().sum::<Vec2>() / goals.len() as f32;
    let c = objects.iter().map(|&i| observed[i.index()]).sum::<Vec2>() / objects.len() as f32;
    (g - c).normalize_or(Vec2::X)
}

/// How wide the group is across `dir` (m), object rims included.
fn spread_across(objects: &[ObjectId], observed: &[Vec2], scene: &Scene, dir: Vec2) -> f32 {
    let perp = dir.perp();
    let (lo, hi) = objects.iter().fold((f32::MAX, f32::MIN), |(lo, hi), &i| {
        let s = observed[i.index()].dot(perp);
        let r = footprint(scene, i);
        (lo.min(s - r), hi.max(s + r))
    });
    (hi - lo).max(0.0)
}

/// Where a pushing hand belongs: behind the rearmost object, on the group's
/// centre line shifted by `lateral`.
fn behind(scene: &Scene, objects: &[ObjectId], observed: &[Vec2], dir: Vec2, standoff: f32, lateral: f32) -> Vec2 {
    let c = objects.iter().map(|&i| observed[i.index()]).sum::<Vec2>() / objects.len().max(1) as f32;
    let rear = objects
        .iter()
        .map(|&i| (observed[i.index()] - c).dot(dir) - footprint(scene, i))
        .fold(f32::MAX, f32::min)
        .min(0.0);
    c + dir * (rear - standoff) + dir.perp() * lateral
}

/// Where the hand's contact acts, from the technique's feedback geometry
/// near it: joint line ends on the object, proxy cubes, particles.
fn acting_point(f: &Feedback, near: Vec2) -> Option<Vec2> {
    const NEAR: f32 = 0.06;
    let mut pts: Vec<Vec2> =
        f.lines.iter().filter(|(a, _)| (a.truncate() - near).length() < NEAR).map(|(_, b)| b.truncate()).collect();
    if pts.is_empty() {
        pts = f.cubes.iter().map(|(c, _)| c.truncate()).filter(|c| (*c - near).length() < NEAR).collect();
    }
    if pts.is_empty() { None } else { Some(pts.iter().copied().sum::<Vec2>() / pts.len() as f32) }
}

/// Two hands dragging two objects at once move as one: both start together
/// and both arrive together, the hand with the shorter way to go slowing to
/// match the other (Kelso, Southard & Goodman 1979: in simultaneous
/// two-handed aiming at targets of different difficulty, "the hand moving
/// to an 'easy' target moves more slowly to accommodate its 'difficult'
/// counterpart"). Each hand's velocity is scaled by its object's error over
/// the larger error, so both errors shrink at the same rate. Once one hand
/// has lifted, the other moves on its own.
fn couple_hands(hands: &mut [HandCtl], open: &[(ObjectId, Want)], observed: &[Vec2]) {
    let error = |h: &HandCtl| match h.role {
        Role::Carry { object } if h.phase == Phase::Down => {
            open.iter().find(|(i, _)| *i == object).map(|(_, w)| (w.point - observed[object.index()]).length())
        }
        _ => None,
    };
    let errors: Vec<Option<f32>> = hands.iter().map(error).collect();
    let [Some(a), Some(b)] = errors[..] else { return };
    let longest = a.max(b);
    if longest <= 0.0 {
        return;
    }
    for (h, e) in hands.iter_mut().zip([a, b]) {
        h.velocity *= e / longest;
    }
}

/// What a hand's next move is decided from: what the participant sees this
/// decision and how fast it moves.
struct Sight<'a> {
    scene: &'a Scene,
    /// Objects not yet where they belong, with where they belong.
    open: &'a [(ObjectId, Want)],
    /// Where the participant sees each object (perceptually late).
    observed: &'a [Vec2],
    now: f64,
    /// Closed-loop gain of a drag: speed per metre of error (1/s).
    gain: f32,
    /// The hand's top speed (m/s).
    speed: f32,
    /// The participant's perceptual delay (s).
    delay: f32,
    /// The technique's feedback, when shown and looked at.
    feedback: Option<&'a Feedback>,
}

impl HandCtl {
    /// Whether progress stalled: `error` did not beat the best so far by
    /// 5 mm within `patience` seconds. A better error resets the clock.
    fn stalled(&mut self, error: f32, now: f64, patience: f64) -> bool {
        if error < self.best - 0.005 {
            self.best = error;
            self.best_at = now;
            false
        } else {
            now - self.best_at > patience
        }
    }
}

fn carry(h: &mut HandCtl, object: ObjectId, sight: &Sight) -> Step {
    let Sight { scene, open, observed, now, gain, speed, delay, feedback } = *sight;
    let Some((_, w)) = open.iter().find(|(i, _)| *i == object) else {
        return Step::Done;
    };
    let obj = observed[object.index()];
    let err = w.point - obj;
    if err.length() < settle_radius(scene) {
        return Step::Done;
    }
    // Closed loop: aim the hand so that the *object* reaches the goal; with
    // feedback, lead by the visible lag between hand and acting point.
    let mut v = err / err.length() * (gain * err.length()).min(speed);
    let pressing = h.pos + h.centre;
    if let Some(f) = feedback
        && let Some(acting) = acting_point(f, pressing)
    {
        let lag = pressing - acting;
        v -= lag.clamp_length_max(0.03) * 2.0;
    }
    // The participant sees its finger as late as the object: where the
    // finger was then, not where it is now, tells whether the object
    // escaped it (a finger moving at 0.3 m/s is 6 cm on 0.2 s later).
    let seen_pressing = pressing - h.velocity * delay;
    h.velocity = v.clamp_length_max(speed);
    let reach = footprint(scene, object) + 0.03;
    if (seen_pressing - obj).length() > reach {
        return Step::Regrip;
    }
    if h.stalled(err.length(), now, f64::from(STUCK_AFTER)) {
        return Step::Regrip;
    }
    Step::Going
}

fn push(h: &mut HandCtl, sight: &Sight) -> Step {
    let Sight { scene, open, observed, now, gain, speed, .. } = *sight;
    let Role::Push { objects, lateral, standoff } = &h.role else {
        return Step::Done;
    };
    let (lateral, standoff) = (*lateral, *standoff);
    let members: Vec<(ObjectId, Want)> = open.iter().filter(|(i, _)| objects.contains(i)).copied().collect();
    if members.is_empty() {
        return Step::Done;
    }
    let ids: Vec<ObjectId> = members.iter().map(|(i, _)| *i).collect();
    let c = ids.iter().map(|&i| observed[i.index()]).sum::<Vec2>() / ids.len() as f32;
    let g = members.iter().map(|(_, w)| w.point).sum::<Vec2>() / ids.len() as f32;
    let err = g - c;
    let dist = err.length();
    let total: f32 = members.iter().map(|(i, w)| (w.point - observed[i.index()]).length()).sum();
    if dist < settle_radius(scene) {
        // At a waypoint: the goal moves on by itself.
        h.velocity = Vec2::ZERO;
        h.best = f32::MAX;
        h.best_at = now;
        return Step::Going;
    }
    let dir = err / dist;
    let target = behind(scene, &ids, observed, dir, standoff, lateral);
    let off = target - h.pos;
    // Off the line behind the group (it turned, or slipped past): lift and
    // set the hand down behind it again.
    let lone = ids.len() == 1;
    let side = (h.pos - c).normalize_or(-dir);
    let slack = if lone { footprint(scene, ids[0]) + 0.03 } else { 0.08 };
    if (lone && lateral == 0.0 && side.dot(-dir) < 0.8) || off.length() > slack {
        return Step::Regrip;
    }
    h.angle = push_angle(h.kind, dir, lateral);
    let v = dir * (gain * dist).min(speed) + off * 2.0;
    h.velocity = v.clamp_length_max(speed);
    if h.stalled(total, now, f64::from(STUCK_AFTER) * 2.0) {
        return Step::Regrip;
    }
    Step::Going
}

#[cfg(test)]
mod tests {
    use super::*;

    fn carrying(id: u32, object: usize, velocity: Vec2) -> HandCtl {
        HandCtl {
            id,
            kind: HandKind::Fingertips(1),
            spread: 0.0,
            angle: 0.0,
            pos: Vec2::ZERO,
            z: 0.0,
            touch: Vec2::ZERO,
            centre: Vec2::ZERO,
            phase: Phase::Down,
            role: Role::Carry { object: ObjectId::new(object) },
            velocity,
            best: f32::MAX,
            best_at: 0.0,
        }
    }

    #[test]
    fn two_hands_dragging_at_once_arrive_together() {
        // Object 0 is 10 cm from its goal, object 1 is 30 cm from its own:
        // the first hand slows to a third, so both errors shrink at one rate.
        let observed = [Vec2::new(0.1, 0.0), Vec2::new(-0.3, 0.0)];
        let open = [
            (ObjectId::new(0), Want { point: Vec2::ZERO, region: 0 }),
            (ObjectId::new(1), Want { point: Vec2::ZERO, region: 1 }),
        ];
        let mut hands = [carrying(1, 0, Vec2::new(-0.3, 0.0)), carrying(2, 1, Vec2::new(0.3, 0.0))];
        couple_hands(&mut hands, &open, &observed);
        assert!((hands[0].velocity.x + 0.1).abs() < 1e-6, "{:?}", hands[0].velocity);
        assert!((hands[1].velocity.x - 0.3).abs() < 1e-6, "{:?}", hands[1].velocity);
        // One hand lifted: the other moves on its own.
        hands[1].phase = Phase::Lifted;
        hands[0].velocity = Vec2::new(-0.3, 0.0);
        couple_hands(&mut hands, &open, &observed);
        assert_eq!(hands[0].velocity, Vec2::new(-0.3, 0.0));
    }
}
