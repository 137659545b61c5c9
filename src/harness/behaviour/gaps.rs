//! Known gaps: cells of the behaviour table that miss the paper's
//! expectation, each with what misses and why, as far as it is understood.
//! They are listed so that the suite can run in CI: a known gap is printed
//! as `**FAIL** (known gap)` and does not fail the tests, every other cell
//! does, and a known gap that passes fails `tests/behaviours.rs` until it
//! is taken off this list. `tests/snapshots/known_gaps.txt` records the same
//! gaps with their measured values; the tests fail when the two differ, so
//! adding a gap is an explicit change with its measurement.

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

const LONG_PUSH_SIGHT: &str = "a fingertip's line-of-sight capsules lean along their camera rays, towards the \
     table's centre as they rise; pushed from its outer side, the cylinder off the centre meets them first at its \
     top rim, a few millimetres beside the line through its base that the finger travels (the path aims at the \
     base's image). Each step then pushes it a little sideways, the offset grows, and after 20 to 25 cm of push \
     it slides off the fingertip's side. Measured on tasks/behaviours/cylinder_platform.toml, a \
     fingertip pushing along x through the base's image at 0.14 m/s: with capsules the cylinder went 2.0 cm \
     sideways over its first 12 cm, with ball particles 0.4 mm over its first 10 cm (though they then climbed \
     its rim); the capsules lost it after 16 to 25 cm, the sooner the slower the push; the sticking finger \
     contact then rolls it round the fingertip (drift = turn x radius); without fingertip friction it slides off \
     sooner. The lean is not all of it: with vertical capsules (the lean removed, \
     every other cell of the table keeping its verdict) Particle misses only 225 (22.3 cm) but Hybrid misses \
     225 and 315 (24.1 and 23.1 cm). Proxy's cube, on the base's line with a flat face, keeps it longer; a \
     pusher that holds a round object on its line over 25 cm needs a face, which a fingertip's outline of \
     independent particles is not";
const LONG_PUSH_JOINT: &str = "the cylinder leaves the fingertip's side after 15 to 21 cm of push in three of \
     the eight directions (measured, not investigated here)";

/// A known gap in how far a push moves its object.
const fn short_push(case: &'static str, technique: TechniqueKind, why: &'static str) -> Gap {
    Gap { case, technique, metric: Metric::Along, why }
}

/// The known gaps, as measured by `surfacelab behaviours` on this build.
pub const GAPS: &[Gap] = &[
    short_push("side_push_platform_wide_045", TechniqueKind::JOINT, LONG_PUSH_JOINT),
    short_push("side_push_platform_wide_045", TechniqueKind::PARTICLE, LONG_PUSH_SIGHT),
    short_push("side_push_platform_wide_045", TechniqueKind::HYBRID, LONG_PUSH_SIGHT),
    short_push("side_push_platform_wide_090", TechniqueKind::JOINT, LONG_PUSH_JOINT),
    short_push("side_push_platform_wide_225", TechniqueKind::PARTICLE, LONG_PUSH_SIGHT),
    short_push("side_push_platform_wide_270", TechniqueKind::JOINT, LONG_PUSH_JOINT),
    short_push("side_push_platform_wide_270", TechniqueKind::HYBRID, LONG_PUSH_SIGHT),
];

/// The known gap for this cell, if it is one.
pub fn known_gap(case: &str, technique: TechniqueKind, metric: Metric) -> Option<&'static Gap> {
    GAPS.iter().find(|g| g.case == case && g.technique == technique && g.metric == metric)
}
