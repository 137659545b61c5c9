//! The names of the interaction techniques (the study's conditions).

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

impl fmt::Display for TechniqueKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for TechniqueKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        TechniqueKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown technique `{s}` (expected direct, joint, proxy, particle or hybrid)"))
    }
}
