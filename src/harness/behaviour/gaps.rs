//! Known gaps: cells of the behaviour table that miss the paper's
//! expectation today, each with what was measured and why, as far as it is
//! understood. They are issue 14's open work, listed so that the suite can
//! run in CI: a known gap is printed as `**FAIL** (known gap)` and does not
//! fail the tests, every other cell does, and a known gap that starts to
//! pass fails `tests/behaviours.rs` until it is taken off this list (the
//! list can only shrink as the physics improves).

use super::case::Metric;
use crate::pipeline::technique::TechniqueKind;

/// One known gap: a case, a technique and a measure, and why it misses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gap {
    pub case: &'static str,
    pub technique: TechniqueKind,
    pub metric: Metric,
    pub why: &'static str,
}

const TOP_FRICTION_ON_A_CYLINDER: &str = "particles on the steering cylinder's top get normal impulses swinging \
     between 0 and 6x their weight from step to step while they drag it (a same-sized box: 1.1-1.2x): parry gives a \
     cylinder's caps, for contact manifolds, as a square inscribed in them and turned towards each contact, so it \
     rocks under a push at its top; with a 24-sided convex hull instead the particles grip, and tip it over (90 \
     degrees), as Proxy's cube then does too (98): 1.5 N of press at mu = 1.5 pulls harder at the top than the 1.5 \
     N that tips a cylinder as tall as it is wide. The friction values are not the cause: its base friction on the \
     platform (0.4, the mean of 0.5 and 0.3) is below its radius over its height (0.5), so a top that sticks to the \
     finger slides it before tipping it; particles that slip over the top pull with their full friction instead \
     (1.5 x 1.5 N = 2.25 N, particles combining friction by the larger coefficient), above the 1.49 N that tips it, \
     and the rocking cap makes them slip. Since particles give way to a surface coming at them (session 12) they no \
     longer hold the rising side of the cap down with impulses their weight cannot give: the drag here tilts it 6.7 \
     degrees (14.9 before slow contacts' flow was measured over several frames, 6.3 before either), and the same \
     drag in 3 directions over 1.0, 1.5 and 2.5 s tipped it over in 4 of 9 runs (none before, Proxy 1, Joint 3). \
     Since particles are 0.4 kg and created clear of movable objects (session 13) the drag here tilts it 6.5 \
     degrees and moves it 0.2 cm; an independent audit's 9 top drags (floor, platform, steering task; 1-2 s) tip it \
     in 14 of 18 Particle and Hybrid runs (10 before; Joint 3 of 9, Proxy none). Session 14: rays are now cast at \
     cylinders exactly (parry's GJK put hits up to 1.2 mm off the surface, and a hit under the top near the rim got \
     the wall's normal, so the particle there slid down into the top and threw it); that fixed the same drag of a 3 \
     cm tall cylinder (0.0 cm and tipped over -> 20.0 cm, 0.2 degrees) and three of the audit's side pushes, but \
     this one moves it 0.9 cm, tilting 14.0 degrees. A 5 cm box of the same mass dragged the same way goes 19.6 cm \
     tilting 0.5 degrees. The cylinder's cap as parry's inscribed square (tipping about a side at 0.71 r) is part \
     of it, but with the cap as its real disc (a 12-gon of the rim over the face; README, Session 14) Particle \
     still does not drag it (0.5 cm, 15.7 degrees) and Proxy's cube rocks off its top in four of the audit's top \
     drags, so the square stays. Probed: with its tilt locked Particle drags it 19.6 cm, so it is the tipping, not \
     the grip; as it rocks onto its front rim and back the particles' press swings from a fifth of their weight to \
     six times it; one of 3.5 cm radius passes in three directions. Session 15: a hand now rests on what it landed \
     on and presses it with the flat of the finger too (pipeline/technique/rest.rs); the drag moves it 0.7 cm \
     tilting 13.8 degrees, and fails within one rock in its first 0.2 s, while the particles slip over the top and \
     pull with their full friction: the finger has slid off the top by the time the cylinder settles. Session 17, \
     probed: the particles on the top press 2-5 times their weight as soon as the drag starts (0.003-0.006 N s a \
     step each against 0.0013 at rest), the cylinder tilts 13.9 degrees within 0.15 s while the finger slides 3 cm \
     over it, and falls back once the finger has passed the top; a lower friction for particles and proxies (1.2, \
     1.0, 0.8 instead of 1.5) did not help (tilts 16.9, 90 and 16.1 degrees, 0.7, 6.5 and 0.2 cm), nor did capping \
     each particle's friction at its weight's share (the friction scaled by its weight over the last step's normal \
     impulse): it tipped over; both together, on an outside audit's 2 s drag of the cylinder standing on the floor, \
     tilted it 3.7-13.4 degrees and moved it at most 0.2 cm at every friction. Since a resting hand's skin sticks \
     to what it rests on (`particle_stick`, session 17) the drag here moves it 6.0 cm tilting 15.0 degrees (14.97, \
     at the edge of the 15 allowed); with 4 or 5 mm of stick instead of 3 it passes (20.0 cm, 1.7 degrees), but the \
     outside audit's nine top drags still move it 0.3-2.0 cm, so that is no fix and the stick stays at what a \
     fingertip's pad shears. Session 18, probed: the drag's first step pulls the top to the hand's speed at once \
     (its point moving at 0.109 m/s against the particles' 0.116), which for 150 g at 0.12 m/s in one 60 Hz step \
     takes 1.1 N beyond the base's 1.2 N of friction, over the 1.8 N that tips it about its rim while it \
     accelerates; within 1-3 steps the particles press 4-10 N instead of their 1.55 N of weight, as the rising back \
     of the top lifts their 8 kg of inertia. The cylinder's end as its real rim against a box face (four rim \
     points, the first where it leans lowest) with the platform's pairs decided afresh every step slides it, pulled \
     at its top with 0.45 of its weight, in all 24 directions tilting under 3 degrees (with rapier's recycled \
     platform pair the first to pass 3 tilted 3.8, pulled towards 105 degrees), but drags worse here: Particle 1.1 \
     cm, Proxy 19.8 -> 2.7 cm (the rim alone: 0.8 cm, 16.1 degrees; fresh pairs alone: 1.3 cm, 30.1 degrees); \
     particles of 0.1 and 0.02 kg instead of 0.4 tilt it 15.3 and 29 degrees and move it 1.4 and 0.4 cm; a skin \
     that gives (friction asked to take up half the slip a step, through the contacts' tangent velocity) moves it \
     10 cm tilting 20 degrees; the stick's slip taken up over 1.5, 2, 3 or 5 steps instead of one tilts it 17.9, \
     31.4, 16.3 and 20.0 degrees (1.4, 6.7, 2.1 and 0.4 cm), the particles' whole speed relative to the top so \
     smoothed over 2, 3 or 4 steps 14.4 (2.9 cm), 35.9 and over; particles that do not give way to a rising top \
     (normals within 25 or 45 degrees of vertical) tip it over, and so do 0.01 kg particles of friction 1.0 on the \
     rim contact above. Session 19, probed: a skin that is a spring, not a velocity (the stuck point joined to a \
     kinematic anchor carried by the hand through a force-based motor across the table, stiffness mu x press over \
     the stick, damping stiffness x 0-0.03 s, capped at mu x press, the anchor sliding along once the stretch \
     passes the stick; the contact's particles on that object frictionless, pressing only): the top keeps up with \
     the hand by tilting about the base's front rim (2.5 rad/s, the base not sliding) and the cylinder tips over \
     (94-119 degrees at a 3 mm stick, 45-100 at 1-2 cm, moving it at most 7.6 cm); with those particles also \
     holding their height against a rising top it tilts 14-40 degrees but does not slide (0.1-0.4 cm back), their \
     extra press raising the base's friction past the skin's cap at the nominal press; capped at the measured press \
     instead it tips over (39-91 degrees). Every variant also lost pin and spin on the 14 cm box (0.6-41 degrees) \
     and the flat hand's turn (15-33). A steady pull at the top slides this cylinder only between 0.4 and 0.5 of \
     its load (its base friction, 0.4, and its radius over its height, 0.5), and a coupling that sticks pulls \
     whatever keeps the top with the hand. Decomposed step by step (the outside audit's 2 s drag on the floor): in \
     the drag's first two steps the particles on the top pull 1.7 and then 4.5 N, pressing 3.3 and then 7-9 N \
     within 6 mm of the axis, while the base stands on its front rim alone at 9-11 N: driven at the hand's speed, \
     the top pivots about the rim, which takes less impulse than sliding the base. With the spring skin the hand \
     leads the top instead, and the press moves to the top's front edge, 19-23 mm ahead of the axis, over the \
     pivot, where it holds nothing back. Also measured: the press moved to where the top is highest, as a stiff \
     fingertip's would (50-100000 N/m over the pad) swings this drag between 0.4 and 11.6 cm and passes it only at \
     the stiffest (19.7 cm, 1.2 degrees), where the audit's nine drags move it 0.2-1.9 cm; the cylinder as a 24- or \
     48-sided hull tips over (101-107 degrees) and breaks Proxy's drag (3.2, 8.1 cm)";
const SLOW_TWIST_PROXY: &str = "the same twist at half the speed (3 s) turns Proxy's two cubes' box 39.2 degrees \
     against 57.2 at 1.5 s and 69.0 at 0.75 s, a coupling that loses something every step: stepped at 240 Hz \
     instead of 60 the same cubes turn it 72.5, 73.1 and 72.1 at the three speeds (a local probe with \
     `[physics] timestep_hz = 240` on a copy of small_box.toml). Traced in session 13 to rapier's contact \
     recycling: a pair whose relative pose drifts less than 0.05 x length_unit (5 mm) while neither body turns \
     more than 11 degrees keeps its contact points, normal and separation frozen, so a slowly turning box is \
     held at stale points. With recycling off, Proxy turns it 59.9 degrees, but its cube then spins a ball \
     75.9 degrees (the paper's limit: little grip of spherical objects) and carries one under a flat hand 0.76 \
     of the way (at most 0.75), so rapier's default stays (38.7 degrees). Session 17: recycling off for \
     Proxy's pairs alone does the same (59.9 degrees, ball spun 75.9, carried 0.76 and 0.77); a shorter \
     recycling distance (0.02, 0.01, 0.005 x length_unit) leaves the twist at 36.8-40.2 degrees and already \
     carries the ball 0.76; cubes free to tilt (as a dynamic cube in the paper's engine would be) turn it \
     34.2 and fail eight other cells";
use Metric::{Along as Distance, Yaw as Turn};
use TechniqueKind::{Hybrid, Particle, Proxy};

/// The known gaps, as measured by `surfacelab behaviours` on this build.
pub const GAPS: &[Gap] = &[
    Gap { case: "two_finger_twist_slow", technique: Proxy, metric: Turn, why: SLOW_TWIST_PROXY },
    Gap { case: "cylinder_top_drag", technique: Particle, metric: Distance, why: TOP_FRICTION_ON_A_CYLINDER },
    Gap { case: "cylinder_top_drag", technique: Hybrid, metric: Distance, why: TOP_FRICTION_ON_A_CYLINDER },
];

/// The known gap for this cell, if it is one.
pub fn known_gap(case: &str, technique: TechniqueKind, metric: Metric) -> Option<&'static Gap> {
    GAPS.iter().find(|g| g.case == case && g.technique == technique && g.metric == metric)
}
