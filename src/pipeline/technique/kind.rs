//! The name of an interaction technique (a study condition): one value from
//! the command line through the pipeline to the study's files.
//!
//! A [`TechniqueKind`] is a name the [registry](super::registry) knows: the
//! five built-in techniques, and any a program registers with
//! [`register`](super::register). It is `Copy`, compares by registration
//! order (the built-in ones first, in the paper's order), and prints and
//! serialises as its name, the file contract (`trials.csv`, `run.toml`).

use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// A registered technique, by name.
///
/// The built-in ones are associated constants; a registered one comes back
/// from [`register`](super::register) or from parsing its name:
///
/// ```
/// use surfacelab::pipeline::technique::TechniqueKind;
///
/// let joint: TechniqueKind = "Joint".parse().unwrap();
/// assert_eq!(joint, TechniqueKind::JOINT);
/// assert_eq!((joint.name(), joint.label()), ("joint", "Joint"));
/// assert!("magnet".parse::<TechniqueKind>().is_err()); // until a program registers it
/// ```
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TechniqueKind {
    /// Position in the registry: orders kinds in tables, menus and files.
    rank: u16,
    /// The name in files and on the command line (`joint`): a file
    /// contract, never renamed.
    name: &'static str,
}

impl TechniqueKind {
    /// A force at the touched point from the contact's velocity (piloted,
    /// then dropped by the paper).
    pub const DIRECT: TechniqueKind = TechniqueKind { rank: 0, name: "direct" };
    /// A spring joint from the contact to an anchor on the touched object.
    pub const JOINT: TechniqueKind = TechniqueKind { rank: 1, name: "joint" };
    /// One kinematically driven rigid body per contact.
    pub const PROXY: TechniqueKind = TechniqueKind { rank: 2, name: "proxy" };
    /// One small body per edge pixel of the contact image, moved by flow.
    pub const PARTICLE: TechniqueKind = TechniqueKind { rank: 3, name: "particle" };
    /// Per-frame particles plus particles that persist at the depth where
    /// they touched (the paper's suggested extension, for grasping).
    pub const HYBRID: TechniqueKind = TechniqueKind { rank: 4, name: "hybrid" };

    /// The techniques built into the crate, in the paper's order.
    pub const BUILT_IN: [TechniqueKind; 5] = [
        TechniqueKind::DIRECT,
        TechniqueKind::JOINT,
        TechniqueKind::PROXY,
        TechniqueKind::PARTICLE,
        TechniqueKind::HYBRID,
    ];

    /// Made by the registry only, so every kind names a registered technique.
    pub(super) const fn new(rank: u16, name: &'static str) -> TechniqueKind {
        TechniqueKind { rank, name }
    }

    pub(super) fn rank(self) -> usize {
        usize::from(self.rank)
    }

    /// The name used in files (`trials.csv`, `run.toml`) and on the command
    /// line (`joint`).
    pub fn name(self) -> &'static str {
        self.name
    }

    /// Every registered technique, built-in ones first, then in the order
    /// they were registered.
    pub fn registered() -> Vec<TechniqueKind> {
        super::registry::kinds()
    }
}

impl fmt::Display for TechniqueKind {
    /// The name, padded as asked (`{:<10}` lines up a table).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name)
    }
}

impl fmt::Debug for TechniqueKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "TechniqueKind({})", self.name)
    }
}

/// A technique name no registered technique has.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown technique {name:?} (registered: {})", registered.join(", "))]
pub struct UnknownTechnique {
    /// The name as given.
    pub name: String,
    /// The names registered in this program when it was asked.
    pub registered: Vec<&'static str>,
}

impl std::str::FromStr for TechniqueKind {
    type Err = UnknownTechnique;

    /// Case-insensitive; surrounding spaces ignored (hand-written lists
    /// such as `--techniques "joint, Proxy"`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let t = s.trim();
        let kinds = TechniqueKind::registered();
        kinds
            .iter()
            .copied()
            .find(|k| k.name.eq_ignore_ascii_case(t))
            .ok_or_else(|| UnknownTechnique { name: s.to_owned(), registered: kinds.iter().map(|k| k.name).collect() })
    }
}

impl Serialize for TechniqueKind {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name)
    }
}

/// Reading a name back needs the technique registered in this program: a
/// run folder written with a technique this binary lacks fails to load,
/// naming it.
impl<'de> Deserialize<'de> for TechniqueKind {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let name = String::deserialize(deserializer)?;
        name.parse().map_err(|e: UnknownTechnique| {
            serde::de::Error::custom(format!(
                "technique {:?} is not registered in this program (registered: {})",
                e.name,
                e.registered.join(", ")
            ))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_back_in_any_case() {
        for k in TechniqueKind::BUILT_IN {
            assert_eq!(k.to_string().parse::<TechniqueKind>(), Ok(k));
            assert_eq!(k.label().to_uppercase().parse::<TechniqueKind>(), Ok(k));
        }
        assert_eq!(" Particle ".parse::<TechniqueKind>(), Ok(TechniqueKind::PARTICLE));
        let err = "spring".parse::<TechniqueKind>().expect_err("not registered");
        assert_eq!(err.name, "spring");
        assert!(err.to_string().contains("registered: direct, joint, proxy, particle, hybrid"), "{err}");
    }

    #[test]
    fn built_in_kinds_order_as_the_paper_lists_them() {
        let mut shuffled =
            vec![TechniqueKind::HYBRID, TechniqueKind::JOINT, TechniqueKind::DIRECT, TechniqueKind::PARTICLE];
        shuffled.push(TechniqueKind::PROXY);
        shuffled.sort();
        assert_eq!(shuffled, TechniqueKind::BUILT_IN.to_vec());
    }

    #[test]
    fn a_run_file_names_an_unregistered_technique() {
        #[derive(Debug, Deserialize)]
        struct Row {
            #[expect(dead_code, reason = "only the error is read")]
            technique: TechniqueKind,
        }
        let err = toml::from_str::<Row>("technique = \"warp\"").expect_err("unknown");
        assert!(err.to_string().contains("technique \"warp\" is not registered in this program"), "{err}");
    }
}
