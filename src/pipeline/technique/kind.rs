//! The names of the interaction techniques (the study's conditions): one
//! type from the command line through the pipeline to the study's files.

use serde::{Deserialize, Serialize};
use std::fmt;

/// One of the paper's four ways of turning contacts into physics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum TechniqueKind {
    /// A force at the touched point from the contact's velocity (piloted, then dropped by the paper).
    Direct,
    /// A spring joint from the contact to an anchor on the touched object.
    Joint,
    /// One kinematically driven rigid body per contact.
    Proxy,
    /// One small body per edge pixel of the contact image, moved by flow.
    Particle,
    /// Per-frame particles plus particles that persist at the depth where
    /// they touched (the paper's suggested extension, for grasping).
    Hybrid,
}

impl TechniqueKind {
    pub const ALL: [TechniqueKind; 5] = [
        TechniqueKind::Direct,
        TechniqueKind::Joint,
        TechniqueKind::Proxy,
        TechniqueKind::Particle,
        TechniqueKind::Hybrid,
    ];

    /// The name used in files (`trials.csv`, `run.toml`) and on the command
    /// line (`joint`). A file contract: never rename.
    pub fn name(self) -> &'static str {
        match self {
            TechniqueKind::Direct => "direct",
            TechniqueKind::Joint => "joint",
            TechniqueKind::Proxy => "proxy",
            TechniqueKind::Particle => "particle",
            TechniqueKind::Hybrid => "hybrid",
        }
    }
}

impl TechniqueKind {
    /// The name used on plots and in reports (`Joint`).
    pub fn label(self) -> &'static str {
        match self {
            TechniqueKind::Direct => "Direct",
            TechniqueKind::Joint => "Joint",
            TechniqueKind::Proxy => "Proxy",
            TechniqueKind::Particle => "Particle",
            TechniqueKind::Hybrid => "Hybrid",
        }
    }
}

impl fmt::Display for TechniqueKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown technique name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown technique {0:?} (expected one of: direct, joint, proxy, particle, hybrid)")]
pub struct UnknownTechnique(pub String);

impl std::str::FromStr for TechniqueKind {
    type Err = UnknownTechnique;

    /// Case-insensitive; surrounding spaces ignored (hand-written lists
    /// such as `--techniques "joint, Proxy"`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let t = s.trim();
        TechniqueKind::ALL
            .into_iter()
            .find(|k| k.name().eq_ignore_ascii_case(t))
            .ok_or_else(|| UnknownTechnique(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_back_in_any_case() {
        for k in TechniqueKind::ALL {
            assert_eq!(k.to_string().parse::<TechniqueKind>(), Ok(k));
            assert_eq!(k.label().to_uppercase().parse::<TechniqueKind>(), Ok(k));
        }
        assert_eq!(" Particle ".parse::<TechniqueKind>(), Ok(TechniqueKind::Particle));
        assert_eq!("spring".parse::<TechniqueKind>(), Err(UnknownTechnique("spring".into())));
    }
}
