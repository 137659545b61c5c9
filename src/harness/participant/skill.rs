//! Per-participant skill, drawn from the study seed.

use super::manner::Manner;
use crate::pipeline::surface::HandKind;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// How a participant prefers to touch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HandMode {
    OneFinger,
    TwoFingers,
}

impl HandMode {
    pub fn kind(self) -> HandKind {
        match self {
            HandMode::OneFinger => HandKind::Fingertips(1),
            HandMode::TwoFingers => HandKind::Fingertips(2),
        }
    }

    /// The habitual manner this preference starts from (the learner's prior).
    pub fn habit(self) -> Manner {
        match self {
            HandMode::OneFinger => Manner::Fingertips(1),
            HandMode::TwoFingers => Manner::Fingertips(2),
        }
    }
}

/// What differs between scripted participants. The same skill drives every
/// technique: differences between conditions come from the physics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Skill {
    /// Top hand speed while dragging (m/s).
    pub hand_speed: f32,
    /// Standard deviation of where the finger lands relative to where it
    /// aimed (m).
    pub aim_noise: f32,
    /// Time between looking and acting (s): the planner re-plans this often
    /// and sees the world this late.
    pub reaction_delay: f32,
    /// The habitual touch: where the learner's priors start.
    pub hand_mode: HandMode,
}

impl Skill {
    /// The manner this participant habitually starts with.
    pub fn habit(self) -> Manner {
        self.hand_mode.habit()
    }

    /// A plausible adult drawn from `seed` (Fitts-style drag speeds of
    /// 0.15–0.35 m/s, 2–5 mm aim scatter, 120–250 ms reaction).
    pub fn draw(seed: u64) -> Skill {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5ca1_ab1e);
        Skill {
            hand_speed: rng.random_range(0.15..0.35),
            aim_noise: rng.random_range(0.002..0.005),
            reaction_delay: rng.random_range(0.12..0.25),
            hand_mode: if rng.random_bool(0.7) { HandMode::OneFinger } else { HandMode::TwoFingers },
        }
    }
}
