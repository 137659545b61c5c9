//! The physical effects a scene may declare. The world switches on only these.

use serde::{Deserialize, Serialize};
use std::fmt;

/// One effect a scene can ask for. Anything not declared is not simulated and
/// costs nothing: no CCD substeps, no sleeping bookkeeping, no joint set work,
/// no soft-body stepping.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    /// Gravity along −z. Without it objects float (and proxies cannot press).
    Gravity,
    /// Coulomb friction on every collider; without it all coefficients are 0.
    Friction,
    /// Continuous collision detection for fast dynamic bodies.
    Ccd,
    /// Bodies at rest fall asleep and cost nothing until touched.
    Sleeping,
    /// Impulse joints (the Joint technique, tangible hinges).
    Joints,
    /// Deformable volumes.
    SoftBodies,
    /// Cloth sheets (a soft body with bending).
    Cloth,
    /// Tearing of cloth/soft bodies under strain.
    Tearing,
}

impl Effect {
    /// Every effect, in declaration order.
    pub const ALL: [Effect; 8] = [
        Effect::Gravity,
        Effect::Friction,
        Effect::Ccd,
        Effect::Sleeping,
        Effect::Joints,
        Effect::SoftBodies,
        Effect::Cloth,
        Effect::Tearing,
    ];

    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Effect::Gravity => "gravity",
            Effect::Friction => "friction",
            Effect::Ccd => "ccd",
            Effect::Sleeping => "sleeping",
            Effect::Joints => "joints",
            Effect::SoftBodies => "soft_bodies",
            Effect::Cloth => "cloth",
            Effect::Tearing => "tearing",
        }
    }

    fn bit(self) -> u16 {
        1 << (self as u16)
    }
}

impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A small set of effects (a bit set: cheap to copy and compare).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct EffectSet(u16);

impl EffectSet {
    /// No effects at all.
    pub const fn empty() -> Self {
        EffectSet(0)
    }

    /// Every effect: what a world pays when it ignores the declaration.
    pub fn all() -> Self {
        Effect::ALL.iter().copied().collect()
    }

    pub fn contains(self, e: Effect) -> bool {
        self.0 & e.bit() != 0
    }

    pub fn insert(&mut self, e: Effect) {
        self.0 |= e.bit();
    }

    pub fn with(mut self, e: Effect) -> Self {
        self.insert(e);
        self
    }

    pub fn union(self, other: EffectSet) -> Self {
        EffectSet(self.0 | other.0)
    }

    pub fn iter(self) -> impl Iterator<Item = Effect> {
        Effect::ALL.into_iter().filter(move |e| self.contains(*e))
    }

    /// Any soft-body kind (volumes, cloth, tearing) is declared.
    pub fn any_soft(self) -> bool {
        self.contains(Effect::SoftBodies) || self.contains(Effect::Cloth) || self.contains(Effect::Tearing)
    }
}

impl FromIterator<Effect> for EffectSet {
    fn from_iter<I: IntoIterator<Item = Effect>>(iter: I) -> Self {
        let mut s = EffectSet::empty();
        for e in iter {
            s.insert(e);
        }
        s
    }
}

impl fmt::Display for EffectSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.iter().map(Effect::name).collect();
        write!(f, "[{}]", names.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_operations() {
        let s: EffectSet = [Effect::Gravity, Effect::Ccd].into_iter().collect();
        assert!(s.contains(Effect::Gravity));
        assert!(!s.contains(Effect::Sleeping));
        assert_eq!(s.to_string(), "[gravity, ccd]");
        assert_eq!(EffectSet::all().iter().count(), Effect::ALL.len());
        assert!(s.with(Effect::Cloth).any_soft());
    }
}
